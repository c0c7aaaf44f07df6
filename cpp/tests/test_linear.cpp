// Point, line, ray and segment against circles and disks, on cases whose answer is known in
// closed form (tangencies, the axis, the plane, translations), in float, double and long double.
#include <circledist/circledist.hpp>
#include <circledist/effects.hpp>

#include "check.hpp"

#include <cmath>
#include <limits>
#include <utility>

using namespace circledist;

template <class Real> Real tol(Real scale) { return Real(1e-12) * scale; }

template <class Real> void analytic_cases() {
  using V = Vec3<Real>;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real bar = std::max(Real(1e-12), Real(64) * eps);  // 1e-12 in double, rounding-limited otherwise
  const Circle3<Real> ring{V(0, 0, 0), V(0, 0, 3), Real(1)};
  const Disk3<Real> disk{V(0, 0, 0), V(0, 0, 3), Real(1)};

  // A line parallel to the plane whose projection is tangent to the circle: distance = height.
  for (Real h : {Real(1e-3), Real(1e-6), Real(1e-9), Real(0)}) {
    const Line3<Real> line{V(5, 1, h), V(2, 0, 0)};
    CHECK_NEAR(distance(line, ring), h, bar);
    CHECK_NEAR(distance(ring, line), h, bar);
    const Result<Real> r = closest_points(line, ring);
    CHECK_NEAR((r.point_a - r.point_b).norm(), r.distance, bar);
    CHECK_NEAR(r.point_b.y(), Real(1), Real(1e-5));
  }

  // The axis: every rim point is at distance R from the crossing point.
  const Result<Real> axis = closest_points(Line3<Real>{V(0, 0, 7), V(0, 0, -2)}, ring);
  CHECK_NEAR(axis.distance, Real(1), bar);
  CHECK(!axis.unique);
  // Parallel to the axis, off by e: R - e.
  for (Real e : {Real(1e-8), Real(1e-12), Real(0.25)}) {
    CHECK_NEAR(distance(Line3<Real>{V(e, 0, 3), V(0, 0, 1)}, ring), 1 - e, bar);
  }
  // In the plane: through the center (two touching points, not unique), outside, across.
  const Result<Real> across = closest_points(Line3<Real>{V(-4, 0, 0), V(1, 0, 0)}, ring);
  CHECK_NEAR(across.distance, Real(0), bar);
  CHECK(!across.unique);
  CHECK_NEAR(distance(Line3<Real>{V(0, 3, 0), V(1, 1e-30, 0)}, ring), Real(2), bar);
  // A ray pointing away and a zero-length segment reduce to the point-circle distance.
  const V p(0, 3, 4);
  const Real point_circle = std::sqrt(Real(4) + Real(16));
  CHECK_NEAR(distance(Ray3<Real>{p, V(0, 1, 1)}, ring), point_circle, bar * 5);
  CHECK_NEAR(distance(Segment3<Real>{p, p}, ring), point_circle, bar * 5);
  CHECK_NEAR(distance(p, ring), point_circle, bar * 5);
  CHECK_NEAR(distance(ring, p), point_circle, bar * 5);

  // Disk: parallel above the interior (continuum), piercing (0, unique), in the plane.
  const Result<Real> above = closest_points(Line3<Real>{V(0, Real(0.5), 2), V(1, 0, 0)}, disk);
  CHECK_NEAR(above.distance, Real(2), bar * 2);
  CHECK(!above.unique);
  const Result<Real> pierce = closest_points(Segment3<Real>{V(Real(0.5), 0, -1), V(Real(0.5), 0, 1)}, disk);
  CHECK_NEAR(pierce.distance, Real(0), bar);
  CHECK(pierce.unique);
  CHECK_NEAR(pierce.point_a.x(), Real(0.5), bar);
  CHECK_NEAR(distance(Segment3<Real>{V(Real(0.2), 0, 0), V(Real(0.3), 0, 0)}, disk), Real(0), bar);
  CHECK_NEAR(distance(Line3<Real>{V(3, 0, 1), V(0, 1, 0)}, disk), std::sqrt(Real(5)), bar * 3);
  CHECK_NEAR(distance(V(Real(0.5), 0, -2), disk), Real(2), bar * 2);
  CHECK_NEAR(distance(V(3, 0, -2), disk), std::sqrt(Real(8)), bar * 3);
  // A segment ending exactly on the rim, from above.
  CHECK_NEAR(distance(Segment3<Real>{V(1, 0, 0), V(1, 0, 5)}, disk), Real(0), bar);
  CHECK_NEAR(distance(Segment3<Real>{V(0, 1, 1), V(0, 2, 1)}, disk), Real(1), bar);
  // A ray starting beyond the disk's cylinder and pointing away: its rim crossings lie behind
  // its origin and must not count; the origin is the closest point.
  CHECK_NEAR(distance(Ray3<Real>{V(3, 0, 1), V(1, 0, 0)}, disk), std::sqrt(Real(5)), bar * 3);
  CHECK_NEAR(distance(Ray3<Real>{V(3, 0, 1), V(1, 0, 0)}, ring), std::sqrt(Real(5)), bar * 3);
}

// A scene translated far from the origin keeps an absolute error of 1e-12 for a unit radius:
// the solvers subtract nearby coordinates first.
void translated_cases() {
  using V = Vec3<double>;
  for (double offset : {1e6, 1e8}) {
    const V o(offset, -offset, offset);
    const Circle3<double> ring{o, V(0, 0, 1), 1.0};
    for (double h : {1e-3, 1e-9}) {
      // The input's height is what o.z + h rounds to, less o.z (an exact subtraction).
      const double height = (o.z() + h) - o.z();
      CHECK_NEAR(distance(Line3<double>{o + V(5, 1, h), V(1, 0, 0)}, ring), height, 1e-12);
      CHECK_NEAR(distance(Segment3<double>{o + V(-5, 1, h), o + V(5, 1, h)}, ring), height, 1e-12);
    }
    CHECK_NEAR(distance(Line3<double>{o + V(0, 0, 2), V(0, 0, 1)}, ring), 1.0, 1e-12);
  }
}

// Radius 0 (a point), and tiny or huge radii with the scene scaled alike.
void radius_cases() {
  using V = Vec3<double>;
  const Circle3<double> dot{V(0, 0, 0), V(0, 0, 1), 0.0};
  CHECK_NEAR(distance(Line3<double>{V(0, 3, 4), V(1, 0, 0)}, dot), 5.0, 1e-12 * 5);
  for (double r : {1e-9, 1e9}) {
    const Circle3<double> ring{V(0, 0, 0), V(0, 0, 1), r};
    CHECK_NEAR(distance(Line3<double>{V(5 * r, r, 1e-6 * r), V(1, 0, 0)}, ring), 1e-6 * r, 1e-12 * r);
  }
}

// Coefficients (lowest first) of (x - r0)(x - r1)(x - r2)(x - r3).
inline void quartic_from_roots(const double r[4], double c[5]) {
  c[0] = 1;
  for (int k = 1; k <= 4; ++k) c[k] = 0;
  for (int i = 0; i < 4; ++i) {
    for (int k = i + 1; k >= 1; --k) c[k] = c[k - 1] - r[i] * c[k];
    c[0] = -r[i] * c[0];
  }
}

// Policy::bracketed_root, the line-circle quartic's solver: a root inside, a root many orders of
// magnitude below the bracket's top, and a non-negative p(lo) returning lo itself.
template <class Policy> void bracketed_root_cases(bool refined) {
  const double eps = std::numeric_limits<double>::epsilon();
  {
    const double r[4] = {0.3, -2, -3, -5}, lo = 0, hi = 1;
    double c[5];
    quartic_from_roots(r, c);
    const double x = Policy::bracketed_root(c, 4, lo, hi, detail::horner(c, 4, lo), detail::horner(c, 4, hi));
    CHECK_NEAR(x, 0.3, 8 * eps);
  }
  {
    const double r[4] = {1e-30, -1, -2, -3}, lo = 0, hi = 1;
    double c[5];
    quartic_from_roots(r, c);
    const double x = Policy::bracketed_root(c, 4, lo, hi, detail::horner(c, 4, lo), detail::horner(c, 4, hi));
    // The companion matrix finds it to eps of the largest root; refining policies to eps of itself.
    CHECK_NEAR(x, 1e-30, refined ? 8 * eps * 1e-30 : 8 * eps);
  }
  {
    const double r[4] = {0.25, -1, -2, -3};
    double c[5];
    quartic_from_roots(r, c);
    CHECK(Policy::bracketed_root(c, 4, 0.25, 1.0, 0.0, detail::horner(c, 4, 1.0)) == 0.25);
  }
}

// Policy::roots_in: every root of one polynomial inside a union of intervals; one solve for the
// statistics however many intervals. Bracketing searches the intervals only and returns those
// roots alone; the eigenvalue policies return every root (theirs can err by more than an
// interval is wide, roots.hpp roots_kept_in), a superset, as a policy may.
template <class Policy> void roots_in_cases() {
  const double r[4] = {-3, -0.5, 0.75, 2};
  double c[5];
  quartic_from_roots(r, c);
  Intervals<double> where;
  where.add(-std::numeric_limits<double>::infinity(), -1);
  where.add(0.5, 1);
  Candidates<double> out;
  stats() = Stats{};
  Counted<Policy>::roots_in(c, 4, where, out);
  CHECK(stats().solves == 1);
  const bool only_inside = has_accurate_roots<Policy>::value;
  CHECK(out.count == (only_inside ? 2 : 4));
  const auto has_root = [&](double x) {
    for (int i = 0; i < out.count; ++i)
      if (std::abs(out.value[i] - x) <= 1e-12) return true;
    return false;
  };
  CHECK(has_root(-3));
  CHECK(has_root(0.75));
  CHECK(where.contains(-1e300) && where.contains(0.5) && !where.contains(0) && !where.contains(2));
}

int main() {
  roots_in_cases<EigenCompanion>();
  roots_in_cases<EigenPolished>();
  roots_in_cases<Bracketing>();
  bracketed_root_cases<EigenCompanion>(false);
  bracketed_root_cases<EigenPolished>(true);
  bracketed_root_cases<Bracketing>(true);
  analytic_cases<float>();
  analytic_cases<double>();
  analytic_cases<long double>();
  translated_cases();
  radius_cases();
  return check::finish("linear");
}
