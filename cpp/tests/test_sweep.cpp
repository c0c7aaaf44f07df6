// Swept shapes (sweep.hpp): swept distances and closest points against the core queries, and a
// few known answers (a cylinder against a torus, overlaps, touching cores).
#include <circledist/sweep.hpp>

#include "check.hpp"
#include "random.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace test_sweep {

using namespace circledist;

namespace {

using V = Vec3<double>;
test_random::Random source(20261122);

template <class A, class B> void check_swept_pair(const A& a, const B& b) {
  const double ra = source.uniform(0, 0.4), rb = source.uniform(0, 0.4);
  const double d = distance(a, b);
  const double expected = std::max(0.0, d - ra - rb);
  CHECK_NEAR(distance(swept(a, ra), swept(b, rb)), expected, 1e-12);
  CHECK_NEAR(distance(swept(b, rb), swept(a, ra)), expected, 1e-12);
  CHECK_NEAR(distance(swept(a, ra), b), std::max(0.0, d - ra), 1e-12);
  CHECK_NEAR(distance(a, swept(b, rb)), std::max(0.0, d - rb), 1e-12);
  const Result<double> core_r = closest_points(a, b);
  const Result<double> r = closest_points(swept(a, ra), swept(b, rb));
  CHECK_NEAR(r.distance, expected, 1e-12);
  CHECK_NEAR((r.point_a - r.point_b).norm(), r.distance, 1e-9);
  // The swept points lie on the swept surfaces: ra from the core's closest point (when apart).
  if (d > ra + rb) {
    CHECK_NEAR((r.point_a - core_r.point_a).norm(), ra, 1e-9);
    CHECK_NEAR((r.point_b - core_r.point_b).norm(), rb, 1e-9);
    CHECK(r.unique == core_r.unique);
  } else {
    // A common point: within ra of a's core point and rb of b's.
    CHECK((r.point_a - core_r.point_a).norm() <= ra + 1e-9);
    CHECK((r.point_b - core_r.point_b).norm() <= rb + 1e-9);
    if (d < ra + rb) CHECK(!r.unique);
  }
  // Zero sweeps reproduce the core bit for bit.
  const Result<double> zero = closest_points(swept(a, 0.0), swept(b, 0.0));
  CHECK(zero.distance == core_r.distance && zero.point_a == core_r.point_a && zero.point_b == core_r.point_b);
  CHECK(distance(swept(a, 0.0), b) == d);
}

void swept_cases() {
  const Circle3<double> ring{V(0, 0, 0), V(0, 0, 1), 1.0};
  // A line 0.5 above the rim, swept by 0.2 (a cylinder) against a torus of tube radius 0.1.
  const Line3<double> line{V(-3, 1, 0.5), V(1, 0, 0)};
  CHECK_NEAR(distance(swept(line, 0.2), swept(ring, 0.1)), 0.2, 1e-14);
  const Result<double> r = closest_points(swept(line, 0.2), swept(ring, 0.1));
  CHECK_NEAR(r.point_a.z(), 0.3, 1e-12);
  CHECK_NEAR(r.point_b.z(), 0.1, 1e-12);
  // Overlapping: distance 0, one common point halfway through the overlap, not unique.
  const Result<double> o = closest_points(swept(line, 0.4), swept(ring, 0.3));
  CHECK(o.distance == 0);
  CHECK(o.point_a == o.point_b);
  CHECK_NEAR(o.point_a.z(), 0.2, 1e-12);  // overlap t in [0.2, 0.4] down from the line: t = 0.3
  CHECK(!o.unique);
  // Cores touching (d = 0): the contact point for both.
  const Segment3<double> pierce{V(0.5, 0, -1), V(0.5, 0, 1)};
  const Disk3<double> disk{V(0, 0, 0), V(0, 0, 1), 1.0};
  const Result<double> t = closest_points(swept(pierce, 0.1), disk);
  CHECK(t.distance == 0);
  CHECK_NEAR((t.point_a - V(0.5, 0, 0)).norm(), 0, 1e-12);
  // A bare point inside a torus: the point itself is the only common point.
  const Result<double> p = closest_points(V(1, 0, 0.05), swept(ring, 0.1));
  CHECK(p.distance == 0 && p.unique);
  CHECK_NEAR((p.point_a - V(1, 0, 0.05)).norm(), 0, 1e-15);

  for (int i = 0; i < 20; ++i) {
    check_swept_pair(source.line(2), source.circle(2));
    check_swept_pair(source.segment(2), source.disk(2));
    check_swept_pair(source.circle(2), source.disk(2));
    check_swept_pair(source.circle(2), source.circle(2));
    check_swept_pair(source.disk(2), source.disk(2));
    check_swept_pair(source.bezier(2), source.circle(2));
    check_swept_pair(source.vector(2), source.disk(2));
  }
}

}  // namespace

int main() {
  swept_cases();
  return check::finish("test_sweep");
}

}  // namespace test_sweep

CHECK_SUITE(test_sweep);
