// Points, lines, rays and segments against each other (linear_linear.hpp): closed forms checked
// against dense sampling, the parallel continuum, far origins and ends (exact configurations), and
// capsules (swept segments, effects.hpp).
#include <circledist/effects.hpp>
#include <circledist/linear_linear.hpp>
#include <circledist/sweep.hpp>

#include "check.hpp"
#include "random.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace test_linear_linear {

using namespace circledist;

namespace {

using V = Vec3<double>;
test_random::Random source(20261122);

void linear_cases() {
  for (int i = 0; i < check::scaled(40); ++i) {
    const Segment3<double> a = source.segment(2), b = source.segment(2);
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

// Origins and segment ends 2^36 directions away from where the pieces pass, in configurations
// built exactly in binary (integer directions, power-of-two offsets), so the distances are known
// in closed form: the offsets between the origins round by eps |w| ~ 1e-4 in plain arithmetic.
// Scenes near the largest doubles, in exact binary configurations (review finding): a point 1
// from a ray along the x axis, 1.5e308 from its origin, answered 0. The plain offset's rounding
// (eps times an origin 1e306 away) squared past the largest double, and the scene scaled down
// by the front end put the distance among the subnormals, whose square is 0.
void near_largest_cases() {
  for (const double x : {1e300, 1e306, 1e307, 1.5e308, 1.7e308}) {
    const V p(x, 0, 1), o(0, 0, 0), along(1.9, 0, 0);
    const Line3<double> line{o, along}, across{p, V(0, 1, 0)};
    const Ray3<double> ray{o, along};
    const Segment3<double> to_max{o, V(1.79e308, 0, 0)}, both_sides{V(-x, 0, 0), V(x, 0, 0)};
    CHECK_NEAR(distance(p, ray), 1.0, 1e-12);
    CHECK_NEAR(closest_points(p, ray).distance, 1.0, 1e-12);
    CHECK_NEAR(distance(ray, p), 1.0, 1e-12);
    CHECK_NEAR(distance(p, line), 1.0, 1e-12);
    CHECK_NEAR(distance(p, to_max), 1.0, 1e-12);
    CHECK_NEAR(closest_points(p, to_max).distance, 1.0, 1e-12);
    CHECK_NEAR(distance(p, both_sides), 1.0, 1e-12);
    CHECK_NEAR(distance(line, across), 1.0, 1e-12);
    CHECK_NEAR(distance(ray, across), 1.0, 1e-12);
    CHECK_NEAR(distance(to_max, across), 1.0, 1e-12);
  }
  // Origins 2^1016 .. 2^1020 along d = (3, 4, 12) from a point h m off the line through 0.
  const V d(3, 4, 12), m(4, -3, 0);  // d.m = 0, |m| = 5
  for (const int k : {1016, 1018, 1019, 1020}) {
    const double far = std::ldexp(1.0, k);
    for (const int e : {-30, 0, 30}) {
      const double h = std::ldexp(1.0, e), gap = 5 * h;
      const V p = h * m;
      const Line3<double> line{-far * d, d};
      const Ray3<double> ray{-far * d, d};
      const Segment3<double> both_far{-far * d, (far / 2) * d}, one_far{-far * d, 0.25 * d};
      CHECK_NEAR(distance(p, line), gap, 1e-12 * gap);
      CHECK_NEAR(distance(p, ray), gap, 1e-12 * gap);
      CHECK_NEAR(closest_points(p, ray).distance, gap, 1e-12 * gap);
      CHECK_NEAR(distance(p, both_far), gap, 1e-12 * gap);
      CHECK_NEAR(distance(p, one_far), gap, 1e-12 * gap);
      CHECK_NEAR(distance(both_far, Segment3<double>{p, p + m}), gap, 1e-12 * gap);
    }
  }
}

void far_origin_cases() {
  const double far = std::ldexp(1.0, 36), h = std::ldexp(1.0, -30);
  const V d(3, 4, 12), m(4, -3, 0);            // d.m = 0, |m| = 5
  const V x(0.5, 0.25, 0.125), p = x + h * m;  // p lies 5 h from the line through x along d
  const double gap = 5 * h;
  for (const double sign : {1.0, -1.0}) {
    const Line3<double> line{x - sign * far * d, d};
    CHECK_NEAR(distance(p, line), gap, 1e-12 * gap);
    CHECK_NEAR(closest_points(p, line).distance, gap, 1e-12 * gap);
    CHECK_NEAR(distance(line, p), gap, 1e-12 * gap);
  }
  const Ray3<double> ray{x - far * d, d};
  CHECK_NEAR(distance(p, ray), gap, 1e-12 * gap);
  const Segment3<double> both_far{x - far * d, x + (far / 2) * d}, one_far{x - far * d, x + 0.25 * d};
  CHECK_NEAR(distance(p, both_far), gap, 1e-12 * gap);
  CHECK_NEAR(distance(p, one_far), gap, 1e-12 * gap);
  CHECK_NEAR(distance(both_far, Segment3<double>{p, p + m}), gap, 1e-12 * gap);
  // Two crossing lines, both origins far: the distance is h |d x e| = 65 h for e = m.
  const double h2 = std::ldexp(1.0, -10);
  const V normal = d.cross(m);  // (36, 48, -25), |normal| = 65
  const Line3<double> a{-far * d, d}, b{h2 * normal + far * m, m};
  CHECK_NEAR(distance(a, b), 65 * h2, 1e-12 * 65 * h2);
  CHECK_NEAR(distance(b, a), 65 * h2, 1e-12 * 65 * h2);
  const Result<double> r = closest_points(a, b);
  CHECK_NEAR(r.distance, 65 * h2, 1e-12 * 65 * h2);
  CHECK((r.point_a - V(0, 0, 0)).norm() < 1e-3 && (r.point_b - h2 * normal).norm() < 1e-3);
  const Ray3<double> ray_a{-far * d, d};
  const Segment3<double> segment_b{h2 * normal + far * m, h2 * normal - far * m};
  CHECK_NEAR(distance(ray_a, segment_b), 65 * h2, 1e-12 * 65 * h2);
  CHECK_NEAR(distance(segment_b, ray_a), 65 * h2, 1e-12 * 65 * h2);
}

// Found by review: lines one ulp of direction apart, passing 9e-10 apart where the stationary
// point lies 1.8e16 from both origins (the exact pass must not take the offset between the far
// points there), and a full line against a degenerate one (a zero direction) given second.
void review_cases() {
  const Line3<double> a{V(0, 0, 0), V(1, 0.5, 0.25)}, b{V(0, 1e-9, 1), V(1, 0.5, 0.25 + std::ldexp(1.0, -54))};
  // Reference: |w.n| / |n| in exact arithmetic, n = (2^-55, -2^-54, 0) exactly, w = (0, 1e-9, 1).
  const double truth = 8.9442719099991593e-10;  // mpmath, 50 digits
  CHECK_NEAR(distance(a, b), truth, 1e-12 * truth);
  CHECK_NEAR(distance(b, a), truth, 1e-12 * truth);
  CHECK_NEAR(closest_points(a, b).distance, truth, 1e-12 * truth);
  const Line3<double> far_line{V(-1e10, 0, 0), V(1, 0, 0)}, degenerate{V(5, 3e-9, 0), V(0, 0, 0)};
  CHECK_NEAR(distance(far_line, degenerate), 3e-9, 1e-12 * 3e-9);
  CHECK_NEAR(distance(degenerate, far_line), 3e-9, 1e-12 * 3e-9);
}

}  // namespace

int main() {
  review_cases();
  linear_cases();
  far_origin_cases();
  near_largest_cases();
  return check::finish("test_linear_linear");
}

}  // namespace test_linear_linear

CHECK_SUITE(test_linear_linear);
