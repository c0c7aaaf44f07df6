// The requested effects (effects.hpp): within / intersects / distance_if_within against
// `distance <= d`, and the counters that show the work done (no polynomial solve where the
// bounds decide), in double, float and long double.
#include <circledist/annulus.hpp>
#include <circledist/effects.hpp>

#include "check.hpp"
#include "random.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace test_effects {

using namespace circledist;

namespace {

using V = Vec3<double>;
test_random::Random source(20261122);

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
  const double ra = source.uniform(0, 0.3), rb = source.uniform(0, 0.3);
  CHECK(intersects(swept(a, ra), swept(b, rb)) == (d <= ra + rb + 1e-9) || std::abs(d - ra - rb) < 1e-9);
}

void laziness_cases() {
  const Disk3<double> disk{V(0, 0, 0), V(0, 0, 1), 1.0};
  const Circle3<double> ring{V(0, 0, 0), V(0, 0, 1), 1.0};
  reset_stats();
  // Well separated.
  CHECK(!intersects(Circle3<double>{V(10, 0, 0), V(0, 1, 0), 1.0}, disk));
  CHECK(!intersects(Line3<double>{V(0, 5, 0), V(1, 0, 0)}, ring));
  CHECK(!within(Segment3<double>{V(0, 0, 2), V(1, 1, 3)}, disk, 1.5));  // above the plane
  CHECK(!within(swept(source.bezier(0.5), 0.1), Disk3<double>{V(0, 0, 9), V(1, 1, 1), 1.0}, 1.0));
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
  const Circle3<double> a = source.circle(1), b = source.circle(1);
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
    check_within_pair(source.line(4), source.circle(4), decided);
    check_within_pair(source.segment(4), source.disk(4), decided);
    check_within_pair(source.circle(4), source.disk(4), decided);
    check_within_pair(source.disk(4), source.disk(4), decided);
    check_within_pair(source.circle(4), source.circle(4), decided);
    check_within_pair(source.bezier(4), source.disk(4), decided);
  }
  CHECK(decided > 30 * 6 * 5 / 3);
  std::printf("within decided by bounds: %d of %d\n", decided, 30 * 6 * 5);
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

// A round's center on another's axis, in small integers (bounds.hpp, sample_points: a round's
// point toward the other's center is built orthogonal to its normal, so that it lies on the
// round whatever the rounding; from q - (m.q) m it would be the rounding's direction, a point on
// the axis, and within() would say yes at a quarter of the distance). Every round against a circle and a
// disk, both orders, plain and swept: within() at fractions of the distance and intersects()
// equal their definition on distance().
template <class A, class B> void definition_pair(const A& a, const B& b, int& pairs) {
  const double d = distance(a, b);
  const double s = plain_scale(a, b) + d + 1;
  for (const double f : {0.0, 0.25, 0.5, 0.9, 0.999999, 1.0, 1.000001, 1.1, 2.0}) {
    const double limit = f * d;
    const bool want = d <= limit + touch_tolerance(s + limit);
    if (std::abs(d - limit) > 1e-9 * s) {
      CHECK(within(a, b, limit) == want);
      CHECK(within(b, a, limit) == want);
    }
  }
  if (d > 1e-9 * s) CHECK(!intersects(a, b) && !intersects(b, a));
  ++pairs;
}

template <class R> void definition_against(const R& b, const V& axis_point, const V& na, int& pairs) {
  for (const double ra : {0.0, 1.0, 2.0}) {
    const Circle3<double> circle{axis_point, na, ra};
    const Disk3<double> disk{axis_point, na, ra};
    definition_pair(circle, b, pairs);
    definition_pair(disk, b, pairs);
    definition_pair(swept(circle, 0.5), b, pairs);
    for (const double inner : {0.0, 1.0, 2.0}) {
      if (inner > ra) continue;
      const Annulus3<double> annulus{axis_point, na, inner, ra};
      definition_pair(annulus, b, pairs);
      definition_pair(swept(annulus, 0.5), swept(b, 0.25), pairs);
    }
  }
}

void center_on_axis_cases() {
  int pairs = 0;
  const auto small = [](int i) { return double(i % 5 - 2); };
  for (int i = 0; i < 125; ++i) {
    const V center(small(i), small(i / 5), small(i / 25));
    const V nb(small(i * 7 + 1), small(i * 3 + 2), small(i + 3));
    const V na(small(i * 11 + 4), small(i * 13), small(i * 2 + 1));
    if (nb.squaredNorm() == 0 || na.squaredNorm() == 0) continue;
    for (const double rb : {0.0, 1.0, 2.0}) {
      const Circle3<double> circle{center, nb, rb};
      const Disk3<double> disk{center, nb, rb};
      for (const double k : {-2.0, -1.0, 1.0, 2.0}) {
        // A's center on B's axis, and B's center on A's axis
        definition_against(circle, V(center + k * nb), na, pairs);
        definition_against(disk, V(center + k * nb), na, pairs);
        definition_against(circle, V(center - k * na), na, pairs);
        definition_against(disk, V(center - k * na), na, pairs);
      }
    }
  }
  std::printf("center on an axis: %d pairs\n", pairs);
}

}  // namespace

int main() {
  center_on_axis_cases();
  laziness_cases();
  precisions<float>();
  precisions<long double>();
  return check::finish("test_effects");
}

}  // namespace test_effects

CHECK_SUITE(test_effects);
