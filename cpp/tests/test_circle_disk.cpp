// Circle against disk (circle_disk.hpp) against the long-double references of round_reference.hpp.
#include "round_reference.hpp"

#include <circledist/effects.hpp>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace test_circle_disk {

void circle_disk_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  circle_disk_case("in the disk's plane, inside", {V3d(0.2, 0.1, 0), z, 0.5}, {o, z, 1}, 0, 0);
  circle_disk_case("in the disk's plane, inside, tilted", {V3d(0.2, 0.1, 0), unit(1, 1, 1), 0.5},
                   {V3d(0.2, 0.1, 0), unit(1, 1, 1), 1}, 0, 0);
  circle_disk_case("crossing the disk twice", {V3d(0.1, 0, 0), V3d(0, 1, 0), 0.5}, {o, z, 1}, 0, 0);
  circle_disk_case("parallel above, projection inside", {V3d(0.1, 0.2, 0.3), z, 0.4}, {o, z, 1}, 0.3L, 0);
  circle_disk_case("coaxial, wider than the disk", {V3d(0, 0, 0.5), z, 2}, {o, z, 1}, std::sqrt(1.25L), 0);
  // In the disk frame the circle is (2 cos, 0, 2 sin): sqrt(5 - 4 |cos|) outside, least at the rim.
  circle_disk_case("same center, orthogonal, radius 2 vs 1", {o, V3d(0, 1, 0), 2}, {o, z, 1}, 1, 0);
  circle_disk_case("same center, orthogonal, radius 1 vs 2", {o, V3d(0, 1, 0), 1}, {o, z, 2}, 0, 0);
  circle_disk_case("touching the rim", {V3d(2, 0, 0), V3d(0, 1, 0), 1}, {o, z, 1}, 0, 1);
  circle_disk_case("resting on the disk", {V3d(0.2, 0, 0.5), V3d(0, 1, 0), 0.5}, {o, z, 1}, 0, 1);
  {
    const Circle3<double> a{V3d(2, 0, 0.3), V3d(0, 1, 0), 1};
    circle_disk_case("beside the rim", a, {o, z, 1}, ref::circle_disk(a, {o, z, 1}), 1);
  }
  {
    const double tilt = 1e-9;
    const Circle3<double> a{V3d(0.3, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 0.5};
    const Disk3<double> d{o, z, 1};
    circle_disk_case("near-coplanar inside", a, d, ref::circle_disk(a, d));
    const Circle3<double> b{V3d(0.3, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 1.5};
    circle_disk_case("near-coplanar around", b, d, ref::circle_disk(b, d));
    const Circle3<double> c{V3d(3, 0.2, 1e-3), V3d(std::sin(tilt), 0, std::cos(tilt)), 1.5};
    circle_disk_case("near-coplanar outside", c, d, ref::circle_disk(c, d));
  }
  {
    const auto check = [](const char* name, const Circle3<double>& a, const Disk3<double>& d) {
      circle_disk_case(name, a, d, ref::circle_disk(a, d));
    };
    circle_round_shared_cases<Disk3<double>>(check);
    const Circle3<double> lifted{V3d(0.1, 0.2, 1.9), unit(1, -2, 0.5), 1.3};
    check("generic lifted", lifted, generic_round<Disk3<double>>());
    translated_cases(lifted, generic_round<Disk3<double>>(), V3d(-0.4, 1, 0.9), check);
  }
  {
    const Disk3<double> big{o, z, 1};
    const Circle3<double> over{V3d(0.3, 0.3, 1e-3), unit(0.2, 1, 0.4), 1e-6};
    circle_disk_case("radius ratio 1e-6 over the disk", over, big, ref::circle_disk(over, big));
    const Disk3<double> tiny{V3d(0.3, 0.1, 0.2), unit(0.1, 0.2, 1), 1e-6};
    const Circle3<double> unit_circle{o, unit(1, 0.5, 0.2), 1};
    circle_disk_case("disk radius ratio 1e-6", unit_circle, tiny, ref::circle_disk(unit_circle, tiny));
  }
}

// distance<EigenX> and closest_points<EigenX> are SelectedEigenPolicy's answers with X selected
// for the call (query.hpp), to the bit, whatever the thread had selected, which they leave as it
// was; Counted<EigenX> (the effects' wrapper) alike.
void eigen_policies_run_as_selected() {
  using Which = SelectedEigenPolicy::Which;
  ShapeDraw d(41);
  for (int k = 0; k < 50; ++k) {
    const Circle3<double> a{d.vec(), d.vec(), d.radius()};
    const Disk3<double> b{d.vec(), d.vec(), d.radius()};
    const auto as_selected = [&](Which which) {
      const SelectedEigenPolicy::Use use(which);
      return std::pair(distance<SelectedEigenPolicy>(a, b), closest_points<SelectedEigenPolicy>(b, a));
    };
    const auto same = [](const auto& x, const auto& y) {
      return x.first == y.first && x.second.distance == y.second.distance && x.second.point_a == y.second.point_a &&
             x.second.point_b == y.second.point_b && x.second.unique == y.second.unique;
    };
    const SelectedEigenPolicy::Use outer(Which::PolynomialSolver);  // another selection around the calls
    CHECK(same(std::pair(distance<EigenCompanion>(a, b), closest_points<EigenCompanion>(b, a)),
               as_selected(Which::Companion)));
    CHECK(same(std::pair(distance<EigenPolished>(a, b), closest_points<EigenPolished>(b, a)),
               as_selected(Which::Polished)));
    CHECK(SelectedEigenPolicy::selected() == Which::PolynomialSolver);
    CHECK(same(std::pair(distance<Counted<EigenPolished>>(a, b), closest_points<Counted<EigenPolished>>(b, a)),
               as_selected(Which::Polished)));
    CHECK(SelectedEigenPolicy::selected() == Which::PolynomialSolver);
  }
}

int main() {
  circle_disk_tests();
  eigen_policies_run_as_selected();
  // The random configurations, the tangencies and the other precisions of round_reference.hpp.
  shared_round_cases([](const RoundCase& r) { circle_disk_case("random", r.a, r.db, ref::circle_disk(r.a, r.db)); },
                     [](const RoundCase& r) { circle_disk_case("tangent", r.b, r.da, ref::circle_disk(r.b, r.da)); },
                     [](const auto& s) { return precision_rows(s.a, s.db, s.ad, s.dbd, ref::circle_disk); });
  return finish_round("circle_disk");
}

}  // namespace test_circle_disk

CHECK_SUITE(test_circle_disk);
