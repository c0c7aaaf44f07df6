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

// Disks whose rims are both clear of the other disk's cylinder, or one of them only
// (disk_disk.hpp, clear_rims): beside each other by -1e-3..0.5 of the scale and by 1e-12,
// parallel, tilted, steep and facing, at radius ratios 1e-6, 1 and 1e6, near the origin and 1e6 away,
// against the references in both orders; `unique` where the geometry decides it (parallel
// disks beside each other: one rim-to-rim pair).
void clear_rims_boundary() {
  const V3d z(0, 0, 1), toward(0.6, 0.8, 0), across(-0.8, 0.6, 0);
  for (const double ratio : {1e-6, 1.0, 1e6}) {
    const double rb = 1, ra = ratio * rb, reach = ra + rb;
    for (const double gap : {-1e-3, -1e-12, 0.0, 1e-12, 1e-3, 0.5}) {
      // Parallel, tilted about the line of centers, steep, and facing B's axis (rim B then
      // passes through A's cylinder while rim A stays clear of B's).
      for (const V3d& normal : {z, V3d(std::sin(0.3) * across + std::cos(0.3) * z),
                                V3d(std::sin(1.2) * across + std::cos(1.2) * z), toward}) {
        for (const double lift : {0.0, 0.4}) {
          for (const V3d& shift : {V3d(0, 0, 0), V3d(1e6, -2e6, 0.5e6)}) {
            const Disk3<double> b{shift, z, rb};
            const Disk3<double> a{shift + (reach * (1 + gap)) * toward + lift * z, normal, ra};
            const bool exact = shift.norm() == 0 || gap >= 1e-3;
            const int unique = normal == z && gap >= 1e-3 && exact ? 1 : -1;
            disk_disk_case("clear rims boundary", a, b, ref::disk_disk(a, b), unique);
          }
        }
      }
    }
  }
}

int main() {
  disk_disk_tests();
  clear_rims_boundary();
  // The random configurations, the tangencies and the other precisions of round_reference.hpp.
  shared_round_cases([](const RoundCase& r) { disk_disk_case("random", r.da, r.db, ref::disk_disk(r.da, r.db)); },
                     [](const RoundCase& r) { disk_disk_case("tangent", r.da, r.db, ref::disk_disk(r.da, r.db)); },
                     [](const auto& s) { return precision_rows(s.da, s.db, s.dad, s.dbd, ref::disk_disk); });
  return finish_round("disk_disk");
}

}  // namespace test_disk_disk

CHECK_SUITE(test_disk_disk);
