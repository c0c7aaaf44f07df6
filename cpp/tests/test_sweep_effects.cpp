// Swept shapes (sweep.hpp) and the requested effects (effects.hpp): swept distances and closest
// points against the core queries, within / intersects against `distance <= d`, and the counters
// that show the work done (no polynomial solve where the bounds decide).
#include <circledist/effects.hpp>

#include "check.hpp"
#include "random.hpp"

#include <cmath>
#include <random>

using namespace circledist;

namespace {

using V = Vec3<double>;
test_random::Random source(20261122);
double uniform(double a, double b) { return source.uniform(a, b); }
V random_vector(double scale) { return source.vector(scale); }
V random_direction() { return source.direction(); }

Circle3<double> random_circle(double spread) { return {random_vector(spread), random_direction(), uniform(0.2, 1.5)}; }
Disk3<double> random_disk(double spread) { return {random_vector(spread), random_direction(), uniform(0.2, 1.5)}; }
Segment3<double> random_segment(double spread) {
  const V p = random_vector(spread);
  return {p, p + random_vector(1.5)};
}
Line3<double> random_line(double spread) { return {random_vector(spread), random_direction()}; }
BezierCurve3<double> random_bezier(double spread) {
  BezierCurve3<double> b;
  b.control.resize(3, 4);
  const V p = random_vector(spread);
  for (int i = 0; i < 4; ++i) b.control.col(i) = p + random_vector(1.2);
  return b;
}

template <class A, class B> void check_swept_pair(const A& a, const B& b) {
  const double ra = uniform(0, 0.4), rb = uniform(0, 0.4);
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

template <class A, class B> void check_within_pair(const A& a, const B& b, int& decided) {
  const double d = distance(a, b);
  for (double limit : {0.0, 0.5 * d, 0.9 * d, 1.1 * d, 2 * d + 0.1}) {
    const Stats before = stats();
    const bool w = within(a, b, limit);
    const Stats after = stats();
    if (after.decided_by_bounds > before.decided_by_bounds) {
      ++decided;
      CHECK(after.solves == before.solves);
    }
    CHECK(w == (d <= limit + 1e-9 * (1 + limit)) || std::abs(d - limit) < 1e-9);
    CHECK(w == within(b, a, limit));
    const double bounded = distance_if_within(a, b, limit);
    CHECK(w ? bounded == d : std::isinf(bounded));
  }
  const double ra = uniform(0, 0.3), rb = uniform(0, 0.3);
  CHECK(intersects(swept(a, ra), swept(b, rb)) == (d <= ra + rb + 1e-9) || std::abs(d - ra - rb) < 1e-9);
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
    check_swept_pair(random_line(2), random_circle(2));
    check_swept_pair(random_segment(2), random_disk(2));
    check_swept_pair(random_circle(2), random_disk(2));
    check_swept_pair(random_circle(2), random_circle(2));
    check_swept_pair(random_disk(2), random_disk(2));
    check_swept_pair(random_bezier(2), random_circle(2));
    check_swept_pair(random_vector(2), random_disk(2));
  }
}

void laziness_cases() {
  const Disk3<double> disk{V(0, 0, 0), V(0, 0, 1), 1.0};
  const Circle3<double> ring{V(0, 0, 0), V(0, 0, 1), 1.0};
  reset_stats();
  // Well separated.
  CHECK(!intersects(Circle3<double>{V(10, 0, 0), V(0, 1, 0), 1.0}, disk));
  CHECK(!intersects(Line3<double>{V(0, 5, 0), V(1, 0, 0)}, ring));
  CHECK(!within(Segment3<double>{V(0, 0, 2), V(1, 1, 3)}, disk, 1.5));  // above the plane
  CHECK(!within(swept(random_bezier(0.5), 0.1), Disk3<double>{V(0, 0, 9), V(1, 1, 1), 1.0}, 1.0));
  // Clearly overlapping.
  CHECK(intersects(Segment3<double>{V(0.5, 0, -1), V(0.5, 0, 1)}, disk));
  CHECK(intersects(Circle3<double>{V(0.5, 0, 0), V(1, 0, 0), 0.7}, disk));  // a circle through the disk
  CHECK(intersects(Disk3<double>{V(0.5, 0, 0), V(1, 0, 0), 1.0}, disk));
  CHECK(intersects(swept(Circle3<double>{V(1, 0, 0), V(0, 1, 0), 1.0}, 0.6), swept(ring, 0.5)));  // tori
  CHECK(within(Line3<double>{V(-3, 1, 0.5), V(1, 0, 0)}, ring, 0.6));
  CHECK(intersects(swept(Line3<double>{V(-3, 1, 0.5), V(1, 0, 0)}, 0.3), swept(ring, 0.25)));
  CHECK(stats().solves == 0);
  CHECK(stats().distances == 0);
  CHECK(stats().within == 10 && stats().decided_by_bounds == 10);

  // The distance never builds closest points; both solve the same polynomials.
  const Circle3<double> a = random_circle(1), b = random_circle(1);
  reset_stats();
  const double d = counted_distance(a, b);
  const Stats after_distance = stats();
  CHECK(after_distance.closest_points == 0 && after_distance.distances == 1 && after_distance.solves > 0);
  const Result<double> r = counted_closest_points(a, b);
  CHECK(stats().closest_points == 1);
  CHECK(stats().solves == 2 * after_distance.solves);
  CHECK(r.distance == d);

  // Random pairs: within agrees with the distance; the bounds decide most of them.
  int decided = 0;
  for (int i = 0; i < 30; ++i) {
    check_within_pair(random_line(4), random_circle(4), decided);
    check_within_pair(random_segment(4), random_disk(4), decided);
    check_within_pair(random_circle(4), random_disk(4), decided);
    check_within_pair(random_disk(4), random_disk(4), decided);
    check_within_pair(random_circle(4), random_circle(4), decided);
    check_within_pair(random_bezier(4), random_disk(4), decided);
  }
  CHECK(decided > 30 * 6 * 5 / 3);
  std::printf("within decided by bounds: %d of %d\n", decided, 30 * 6 * 5);
}

// Points, lines, rays and segments against each other (linear_linear.hpp): closed forms checked
// against dense sampling, the parallel continuum, and capsules.
void linear_cases() {
  for (int i = 0; i < 40; ++i) {
    const Segment3<double> a = random_segment(2), b = random_segment(2);
    const double d = distance(a, b);
    double sampled = std::numeric_limits<double>::infinity();
    for (int j = 0; j <= 200; ++j) {
      for (int k = 0; k <= 200; ++k) {
        const V p = a.p0 + (j / 200.0) * (a.p1 - a.p0), q = b.p0 + (k / 200.0) * (b.p1 - b.p0);
        sampled = std::min(sampled, (p - q).norm());
      }
    }
    CHECK(d <= sampled + 1e-12);
    CHECK(sampled - d < 0.02);
    const Result<double> r = closest_points(a, b);
    CHECK_NEAR((r.point_a - r.point_b).norm(), d, 1e-12);
    CHECK_NEAR(distance(b, a), d, 1e-15);
  }
  CHECK_NEAR(distance(Line3<double>{V(0, 0, 0), V(1, 0, 0)}, Line3<double>{V(5, 7, 2), V(0, 1, 0)}), 2.0, 1e-15);
  // Nearly parallel lines far out: the closed form |w.n| / |n| keeps the distance exact.
  CHECK_NEAR(distance(Line3<double>{V(0, 0, 0), V(1, 0, 0)}, Line3<double>{V(0, 0, 1), V(1, 1e-9, 0)}), 1.0, 1e-12);
  const Result<double> parallel =
      closest_points(Segment3<double>{V(0, 0, 0), V(1, 0, 0)}, Segment3<double>{V(0.5, 1, 0), V(2, 1, 0)});
  CHECK_NEAR(parallel.distance, 1.0, 1e-15);
  CHECK(!parallel.unique);
  CHECK_NEAR(distance(Ray3<double>{V(0, 0, 0), V(1, 0, 0)}, Ray3<double>{V(-1, 1, 0), V(-1, 0, 0)}), std::sqrt(2.0),
             1e-15);
  CHECK_NEAR(distance(V(-2, 1, 0), Ray3<double>{V(0, 0, 0), V(1, 0, 0)}), std::sqrt(5.0), 1e-15);
  CHECK_NEAR(distance(V(1, 2, 2), V(0, 0, 0)), 3.0, 1e-15);
  // Capsules.
  const auto capsule_a = swept(Segment3<double>{V(0, 0, 0), V(1, 0, 0)}, 0.3);
  const auto capsule_b = swept(Segment3<double>{V(0.5, 1, -1), V(0.5, 1, 1)}, 0.3);
  CHECK_NEAR(distance(capsule_a, capsule_b), 0.4, 1e-15);
  reset_stats();
  CHECK(!intersects(capsule_a, capsule_b));
  CHECK(within(capsule_a, capsule_b, 0.5));
  CHECK(stats().solves == 0);
}

template <class Real> void precisions() {
  using W = Vec3<Real>;
  const Circle3<Real> ring{W(0, 0, 0), W(0, 0, 1), Real(1)};
  const Line3<Real> line{W(-3, 1, Real(0.5)), W(1, 0, 0)};
  CHECK_NEAR(distance(swept(line, Real(0.2)), ring), Real(0.3), Real(1e-5));
  CHECK(within(line, ring, Real(0.6)));
  CHECK(!intersects(line, swept(ring, Real(0.4))));
  CHECK(intersects(line, swept(ring, Real(0.6))));
}

}  // namespace

int main() {
  swept_cases();
  laziness_cases();
  linear_cases();
  precisions<float>();
  precisions<long double>();
  return check::finish("test_sweep_effects");
}
