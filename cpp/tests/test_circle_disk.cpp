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

// Neither clear of the cylinder nor decided by its heights, a circle's distance is the
// circle-rim distance (docs/derivations/circle_disk.md, "The distance alone, and the rim part").
// Parallel circles crossing the rim, whose t = 0 and t = pi (their frame's +-y) lie off the disk:
// the closest set is the arc over the disk (distance h, not unique), or, where the disk lies
// inside the circle's projection, one pair. And tilted circles over the rim, their lowest point
// just inside or outside it (the heights decide or the rim part does), against the references.
void rim_part_boundary() {
  const V3d z(0, 0, 1);
  for (const V3d& shift : {V3d(0, 0, 0), V3d(1e6, -2e6, 0.5e6)}) {
    const Disk3<double> d{shift, z, 1};
    for (const double r : {1.0, 2.0}) {
      for (const double offset : {0.9, 1.0, 1.5}) {
        for (const double h : {2.0, 0.3, 1e-6}) {
          const Circle3<double> a{shift + V3d(offset, 0, h), z, r};
          const bool crossing = std::abs(offset - r) < 1 && 1 < offset + r;
          // Crossing: the distance is the height as the inputs hold it (1e6 away, h rounds).
          const LD height = LD(a.center.z()) - LD(d.center.z());
          circle_disk_case("rim part, parallel", a, d, crossing ? height : ref::circle_disk(a, d), crossing ? 0 : 1);
        }
      }
    }
    for (const double r : {0.5, 2.0}) {
      for (const double tilt : {0.2, 0.7, 1.3}) {
        for (const double lift : {0.2, 1.0}) {
          for (const double edge : {-0.5, -1e-3, 0.0, 1e-3, 0.5}) {
            // The lowest point of the circle, (x + r cos(tilt), 0, lift), at 1 + edge from the axis.
            const double x = 1 + edge - r * std::cos(tilt);
            const Circle3<double> a{shift + V3d(x, 0, lift + r * std::sin(tilt)),
                                    V3d(std::sin(tilt), 0, std::cos(tilt)), r};
            circle_disk_case("rim part, tilted over the rim", a, d, ref::circle_disk(a, d));
          }
        }
      }
    }
  }
}

// A circle clear of the disk's cylinder is answered as circle-circle against the rim
// (docs/derivations/circle_disk.md, "A circle clear of the cylinder"). Its boundary: circles
// whose projection misses the rim by -1e-3..1e-3 of the scale and by a few ulps, touches it, or
// crosses it; parallel (their lowest point beside the rim) and tilted; radius ratios 1e-6, 1 and
// 1e6; near the origin and 1e6 away. The distance, the closest points and their parameters
// against the references; `unique` where the geometry decides it.
void clear_of_cylinder_boundary() {
  const double eps = std::numeric_limits<double>::epsilon();
  const V3d z(0, 0, 1);
  for (const double ratio : {1e-6, 1.0, 1e6}) {
    const double big_r = 1, r = ratio * big_r, reach = r + big_r;
    for (const double gap : {-1e-3, -1e-12, -8 * eps, 0.0, 8 * eps, 1e-12, 1e-3}) {
      for (const double lift : {0.0, 0.5}) {
        for (const V3d& shift : {V3d(0, 0, 0), V3d(1e6, -2e6, 0.5e6)}) {
          const Disk3<double> d{shift, z, big_r};
          // Parallel to the disk, beside it along (0.6, 0.8): its projection's nearest point is
          // gap * reach from the rim.
          const V3d toward(0.6, 0.8, 0);
          const Circle3<double> parallel{shift + (reach * (1 + gap)) * toward + V3d(0, 0, lift), z, r};
          // In the plane through the axis and the center, standing: its nearest point to the axis
          // is the same, at height `lift`.
          const Circle3<double> standing{shift + (reach * (1 + gap)) * toward + V3d(0, 0, lift), V3d(-0.8, 0.6, 0), r};
          // Tilted about that direction's normal: its projection reaches r cos(0.3) toward the axis.
          const Circle3<double> tilted{shift + (reach * (1 + gap)) * toward + V3d(0, 0, lift),
                                       V3d(0.6 * std::sin(0.3), 0.8 * std::sin(0.3), std::cos(0.3)), r};
          // Unique, where the gap is what it says (near the origin, or larger than the far
          // coordinates' rounding): one closest pair where the parallel circle passes beside the
          // rim or touches it, or (radius ratio 1e6) passes around the disk; a closest arc where
          // it passes over the disk.
          const bool exact = shift.norm() == 0 || std::abs(gap) >= 1e-3;
          const int parallel_unique = !exact ? -1 : gap >= 0 ? 1 : gap <= -1e-3 ? (ratio > 1 ? 1 : 0) : -1;
          circle_disk_case("clear boundary, parallel", parallel, d, ref::circle_disk(parallel, d), parallel_unique);
          circle_disk_case("clear boundary, standing", standing, d, ref::circle_disk(standing, d));
          circle_disk_case("clear boundary, tilted", tilted, d, ref::circle_disk(tilted, d));
        }
      }
    }
  }
}

// The test's rounding margin: a circle parallel to a tilted disk, its center (r + R)(1 + j eps)
// from the axis along a random direction, j = -12..12, so that its projection misses or meets the
// rim by a few ulps either way. Where the test clears a circle, its projection must miss the
// disk (its distance from the axis, computed in long double from the same doubles, exceeds
// R + r: the exact condition for a parallel circle); and far clear of the rim, it clears it.
void clear_of_cylinder_margin() {
  using Pair = Query<Circle3<double>, Disk3<double>>;
  const double eps = std::numeric_limits<double>::epsilon();
  ShapeDraw draw(4040);
  int wrong = 0;
  for (int k = 0; k < check::scaled(400); ++k) {
    const V3d n = draw.vec().normalized();
    const double big_r = draw.radius(), r = k % 3 == 0 ? 1e-6 * big_r : (k % 3 == 1 ? big_r : 1e6 * big_r);
    const V3d center = k % 2 == 0 ? draw.vec() : V3d(1e6 * draw.vec());
    const V3d w = n.cross(draw.vec()).normalized();
    const double lift = draw.normal(draw.rng);
    const Disk3<double> d{center, n, big_r};
    const detail::Round<double> round(d.center, d.normal, d.radius);
    for (int j = -12; j <= 12; ++j) {
      const Circle3<double> a{center + ((r + big_r) * (1 + j * eps)) * w + lift * n, n, r};
      // Long double: the center's distance from the axis, with the unit normal of the same doubles.
      const V3 nl = n.cast<LD>() / n.cast<LD>().norm();
      const V3 offset = a.center.cast<LD>() - d.center.cast<LD>();
      const LD rho = (offset - offset.dot(nl) * nl).norm();
      if (Pair::clear_of_cylinder(a, round) && !(rho - LD(r) > LD(big_r))) {
        ++wrong;
        std::printf("  cleared a circle over the disk: rho - r - R = %.3Lg\n", rho - LD(r) - LD(big_r));
      }
      const Circle3<double> far{a.center + (1e-6 * (r + big_r)) * w, n, r};
      CHECK(Pair::clear_of_cylinder(far, round));
    }
  }
  CHECK(wrong == 0);
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
  clear_of_cylinder_boundary();
  clear_of_cylinder_margin();
  rim_part_boundary();
  eigen_policies_run_as_selected();
  // The random configurations, the tangencies and the other precisions of round_reference.hpp.
  shared_round_cases([](const RoundCase& r) { circle_disk_case("random", r.a, r.db, ref::circle_disk(r.a, r.db)); },
                     [](const RoundCase& r) { circle_disk_case("tangent", r.b, r.da, ref::circle_disk(r.b, r.da)); },
                     [](const auto& s) { return precision_rows(s.a, s.db, s.ad, s.dbd, ref::circle_disk); });
  return finish_round("circle_disk");
}

}  // namespace test_circle_disk

CHECK_SUITE(test_circle_disk);
