// Disk against disk (disk_disk.hpp) against the long-double references of round_reference.hpp.
#include "round_reference.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace test_disk_disk {

void disk_disk_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  disk_disk_case("coplanar overlapping", {o, z, 1}, {V3d(1, 0.5, 0), z, 1}, 0, 0);
  disk_disk_case("coplanar nested", {o, z, 2}, {V3d(0.5, 0, 0), z, 1}, 0, 0);
  disk_disk_case("coplanar disjoint", {o, z, 1}, {V3d(3, 0, 0), z, 0.5}, 1.5L, 1);
  disk_disk_case("coplanar tangent", {o, z, 1}, {V3d(0, 2, 0), z, 1}, 0, 1);
  disk_disk_case("parallel stacked", {o, z, 1}, {V3d(0, 0, 0.5), -z, 1}, 0.5L, 0);
  disk_disk_case("parallel, partly over", {o, z, 1}, {V3d(1.2, 0, 0.5), z, 0.7}, 0.5L, 0);
  disk_disk_case("parallel, beside", {o, z, 1}, {V3d(3, 0, 0.5), z, 1}, std::sqrt(1.25L), 1);
  disk_disk_case("crossing", {o, z, 1}, {V3d(0.2, 0.1, 0.1), unit(1, 0.3, 0.2), 0.8}, 0, 0);
  disk_disk_case("T touching", {o, z, 1}, {V3d(0.3, 0.2, 0.5), V3d(1, 0, 0), 0.5}, 0, 1);
  disk_disk_case("rim over the face", {o, z, 1}, {V3d(0.3, 0.2, 0.6), V3d(1, 0, 0), 0.5}, 0.1L, 1);
  {
    const double tilt = 1e-9;
    const Disk3<double> a{o, z, 1};
    const Disk3<double> b{V3d(0.5, 0.2, 1e-3), V3d(std::sin(tilt), 0, std::cos(tilt)), 1};
    disk_disk_case("near-parallel above", a, b, ref::disk_disk(a, b));
    const Disk3<double> c{V3d(0.5, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 1};
    disk_disk_case("near-coplanar crossing", a, c, 0, 0);
  }
  {
    const Disk3<double> a{V3d(0.1, 0.2, 1.9), unit(1, -2, 0.5), 1.3}, b{V3d(0.7, -0.4, 0.2), unit(0.3, 1, 2), 0.9};
    disk_disk_case("generic", a, b, ref::disk_disk(a, b));
    translated_cases(a, b, V3d(1, 0.3, -0.8), [](const char* name, const auto& at, const auto& bt) {
      disk_disk_case(name, at, bt, ref::disk_disk(at, bt));
    });
  }
}

int main() {
  disk_disk_tests();
  // The random configurations, the tangencies and the other precisions of round_reference.hpp.
  shared_round_cases([](const RoundCase& r) { disk_disk_case("random", r.da, r.db, ref::disk_disk(r.da, r.db)); },
                     [](const RoundCase& r) { disk_disk_case("tangent", r.da, r.db, ref::disk_disk(r.da, r.db)); },
                     [](const auto& s) { return precision_rows(s.da, s.db, s.dad, s.dbd, ref::disk_disk); });
  return finish_round("disk_disk");
}

}  // namespace test_disk_disk

CHECK_SUITE(test_disk_disk);
