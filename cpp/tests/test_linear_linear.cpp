// Points, lines, rays and segments against each other (linear_linear.hpp): closed forms checked
// against dense sampling, the parallel continuum, and capsules (swept segments, effects.hpp).
#include <circledist/effects.hpp>
#include <circledist/linear_linear.hpp>
#include <circledist/sweep.hpp>

#include "check.hpp"
#include "random.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace circledist;

namespace {

using V = Vec3<double>;
test_random::Random source(20261122);

void linear_cases() {
  for (int i = 0; i < 40; ++i) {
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

}  // namespace

int main() {
  linear_cases();
  return check::finish("test_linear_linear");
}
