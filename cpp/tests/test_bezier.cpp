// Bezier curves against disks and circles (bezier.hpp) against the long-double references of
// round_reference.hpp. (The curve-center cases are test_bezier_center.cpp.)
#include "round_reference.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace test_bezier {

void bezier_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  const Disk3<double> disk{o, z, 1};
  const Circle3<double> ring{o, z, 1};
  {
    // Collinear, evenly spaced control points: the segment itself, with the same parameter.
    const V3d p(-1.5, 0.7, 0.4), q(2.1, -0.3, -0.2);
    const BezierCurve3<double> line = bezier({p, (2 * p + q) / 3, (p + 2 * q) / 3, q});
    const Segment3<double> seg{p, q};
    const double expected = distance(seg, disk);
    bezier_case("bezier-disk", "straight = segment", line, disk, ref::bezier_disk(line, disk));
    check::record(std::abs(distance(line, disk) - expected) <= 1e-12, "straight vs segment-disk", __FILE__, __LINE__);
    const BezierCurve3<double> high = bezier({V3d(-2, 0.5, 0.3), V3d(2, -0.5, -0.1)});
    bezier_case("bezier-disk", "degree 1 over the disk", high, disk, ref::bezier_disk(high, disk));
    check::record(std::abs(distance(high, disk) -
                           distance(Segment3<double>{V3d(-2, 0.5, 0.3), V3d(2, -0.5, -0.1)}, disk)) <= 1e-12,
                  "degree 1 vs segment-disk", __FILE__, __LINE__);
  }
  {
    // y = 1 + (2t - 1)^2, x = 2t - 1 in the disk's plane: touches the rim at (0, 1, 0).
    const BezierCurve3<double> touch = bezier({V3d(-1, 2, 0), V3d(0, 0, 0), V3d(1, 2, 0)});
    bezier_case("bezier-disk", "tangent to the rim", touch, disk, 0, 1);
    bezier_case("bezier-circle", "tangent to the circle", touch, ring, 0, 1);
    const BezierCurve3<double> lifted = bezier({V3d(-1, 2, 1e-3), V3d(0, 0, 1e-3), V3d(1, 2, 1e-3)});
    bezier_case("bezier-disk", "tangent to the rim, lifted", lifted, disk, 1e-3L, 1);
    bezier_case("bezier-circle", "tangent to the circle, lifted", lifted, ring, 1e-3L, 1);
  }
  {
    const BezierCurve3<double> flat = bezier({V3d(-2, 0.1, 0), V3d(-0.5, 0.8, 0), V3d(0.5, -0.6, 0), V3d(2, 0.2, 0)});
    bezier_case("bezier-disk", "in the disk's plane, across", flat, disk, 0, 0);
    bezier_case("bezier-circle", "in the circle's plane, across", flat, ring, ref::bezier_circle(flat, ring));
    const BezierCurve3<double> outside = bezier({V3d(1.5, -1, 0), V3d(2.5, 0, 0), V3d(1.5, 1, 0)});
    bezier_case("bezier-disk", "in the disk's plane, outside", outside, disk, ref::bezier_disk(outside, disk));
  }
  {
    const BezierCurve3<double> rim =
        bezier({V3d(0.2, 0.1, 0.5), V3d(0.8, 0.3, 0.4), V3d(1.6, 0.4, 0.1), V3d(2.2, -0.2, 0.3)});
    bezier_case("bezier-disk", "crossing the rim", rim, disk, ref::bezier_disk(rim, disk));
    bezier_case("bezier-circle", "crossing the rim", rim, ring, ref::bezier_circle(rim, ring));
  }
  {
    // A quintic with four local minima of the distance to the disk and to the circle (at
    // 0.110, 0.121, 0.381 and 0.442: the two lowest are close competitors).
    const BezierCurve3<double> four = bezier({V3d(1.9, -1.2, 0.7), V3d(-0.1, 0.9, -1.6), V3d(-1.2, 0, 0.5),
                                              V3d(-1.1, -3.2, -0.6), V3d(-1.1, 0.9, -0.8), V3d(1.4, 0, 0)});
    bezier_case("bezier-disk", "degree 5, four local minima", four, disk, ref::bezier_disk(four, disk), 1);
    bezier_case("bezier-circle", "degree 5, four local minima", four, ring, ref::bezier_circle(four, ring), 1);
    // A quintic waving over the disk and around the circle.
    const BezierCurve3<double> wave = bezier({V3d(-1.6, -0.2, 0.4), V3d(-1.0, 1.4, -0.3), V3d(-0.3, -1.5, 0.9),
                                              V3d(0.4, 1.6, -0.6), V3d(1.0, -1.2, 0.7), V3d(1.7, 0.3, 0.2)});
    bezier_case("bezier-disk", "degree 5 waving", wave, disk, ref::bezier_disk(wave, disk));
    bezier_case("bezier-circle", "degree 5 waving", wave, ring, ref::bezier_circle(wave, ring));
    const Disk3<double> tilted{V3d(0.1, 0.2, 0.6), unit(0.3, 0.4, 1), 0.8};
    bezier_case("bezier-disk", "degree 5 waving, tilted disk", wave, tilted, ref::bezier_disk(wave, tilted));
    translated_cases(wave, tilted, V3d(0.6, -1, 0.2), [](const char* name, const auto& moved, const auto& dt) {
      bezier_case("bezier-disk", name, moved, dt, ref::bezier_disk(moved, dt));
    });
  }
}

int main() {
  bezier_tests();
  // The random configurations, the tangencies and the other precisions of round_reference.hpp.
  shared_round_cases(
      [](const RoundCase& r) {
        bezier_case("bezier-disk", "random", r.c, r.db, ref::bezier_disk(r.c, r.db));
        bezier_case("bezier-circle", "random", r.c, r.b, ref::bezier_circle(r.c, r.b));
      },
      [](const RoundCase& r) {
        bezier_case("bezier-disk", "tangent", r.c, r.da, ref::bezier_disk(r.c, r.da));
        bezier_case("bezier-circle", "tangent", r.c, r.a, ref::bezier_circle(r.c, r.a));
      },
      [](const auto& s) {
        std::vector<std::array<double, 2>> rows = precision_rows(s.c, s.db, s.cd, s.dbd, ref::bezier_disk);
        const std::vector<std::array<double, 2>> circle = precision_rows(s.c, s.b, s.cd, s.bd, ref::bezier_circle);
        rows.insert(rows.end(), circle.begin(), circle.end());
        return rows;
      });
  return finish_round("bezier");
}

}  // namespace test_bezier

CHECK_SUITE(test_bezier);
