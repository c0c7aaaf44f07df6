// Point-arc (Query<Vec3, Arc3>). Derivation: docs/derivations/arc.md#a-point-closed-form.
#pragma once

#include "detail/arc_span.hpp"
#include "detail/point_over_round.hpp"
#include "point_circle.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// Point against arc: closed form (docs/derivations/arc.md, "A point"). The distance from P to the circle's
// point at angle theta is sqrt(z^2 + rho^2 + R^2 - 2 R rho cos(theta - phi)), phi the angle of P's
// projection: least at phi and rising on both sides to its greatest at phi + pi. So over the arc
// it is least at phi when phi lies on the arc (point-circle's answer), otherwise at the end
// nearer in angle. On the axis (rho = 0) every arc point is as close.
// The angle is taken from the arc's own start direction u' (the start's in-plane part), not from
// the canonical frame: no Frame, no theta0; and the place of the answer (the ring, an end) from
// signs against the ends' directions, with the trigonometry the arc carries (Arc3::trig): no
// atan2 (docs/derivations/arc.md, "A point": the ends' directions).
template <class Real> struct PointArcPair {
  static constexpr bool defined = true;
  using Whole = detail::PointRoundQuery<Real, false>;

  template <class Roots = DefaultRoots>
  CIRCLEDIST_INLINE static Real distance(const Vec3<Real>& p, const Arc3<Real>& arc) {
    if (whole_arc(arc)) return Whole::distance(p, arc_circle(arc));
    bool on_ring;
    return solve<false>(p, arc, on_ring).distance;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Arc3<Real>& arc) {
    if (whole_arc(arc)) return as_arc_result(Whole::closest(p, arc_circle(arc)), ArcSpan<Real>(arc), 1);
    bool on_ring;
    return solve<true>(p, arc, on_ring);
  }

  // The one computation behind distance() (Points false: the points and parameters are not
  // formed) and closest(): the same distance to the bit. An arc that is not whole; `on_ring`
  // says whether the answer is the ring's (point-circle's distance: the point's angle on the arc,
  // or the point on the axis), which a piece's end answered before the root needs
  // (piece_arc_fast; docs/derivations/arc.md, "Before the root").
  template <bool Points>
  CIRCLEDIST_INLINE static Result<Real> solve(const Vec3<Real>& p, const Arc3<Real>& arc, bool& on_ring) {
    if (arc.trig.angle == arc.angle) return solve_with<Points, true>(p, arc, on_ring);
    return solve_uncached<Points>(p, arc, on_ring);
  }

 private:
  // An arc without its trigonometry (Arc3::trig), or a point whose place the ends do not
  // decide: the general path, out of line (the common one stays small enough to be inlined
  // into a caller's loop).
  template <bool Points>
#if defined(__GNUC__) || defined(__clang__)
  __attribute__((noinline))
#endif
  static Result<Real>
  solve_uncached(const Vec3<Real>& p, const Arc3<Real>& arc, bool& on_ring) {
    return solve_with<Points, false>(p, arc, on_ring);
  }

  // solve()'s computation; Cached: the arc carries its angle's trigonometry.
  template <bool Points, bool Cached>
  CIRCLEDIST_INLINE static Result<Real> solve_with(const Vec3<Real>& p, const Arc3<Real>& arc, bool& on_ring) {
    constexpr Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real turn = 2 * pi_v<Real>();
    Result<Real> r;
    r.point_a = p;
    on_ring = false;
    if (!(arc.radius > 0)) {  // the center alone
      r.distance = (p - arc.center).norm();
      r.point_b = arc.center;
      return r;
    }
    const detail::PointOverRound<Real> seen(p, arc.center, arc.normal);
    const Real radius = arc.radius;
    const Real angle = arc.angle > 0 ? arc.angle : (arc.angle <= 0 ? Real(0) : nan);  // NaN stays NaN
    // The ring's distance (point-circle's), formed only where it is the answer.
    const auto ring = [&] { return length2d(seen.height, seen.radial - radius); };
    // u' = |W|^2 S - (S.W) W, the start's in-plane part times |W|^2 (seen's W, rescaled if it
    // had to be: no division), and v' = W x u' (|v'| = s |u'|): the arc's u and v up to their
    // lengths.
    const Vec3<Real> start = detail::moderate_start(arc.start);
    const Real k = seen.wx * start.x() + seen.wy * start.y() + seen.wz * start.z();
    const Vec3<Real> u(seen.norm2 * start.x() - k * seen.wx, seen.norm2 * start.y() - k * seen.wy,
                       seen.norm2 * start.z() - k * seen.wz);
    // |u'| = sqrt(|u'|^2) (Eigen's norm()): zero exactly where its square is, so the test needs
    // no square root; the length itself only where an end point is formed.
    if (!(u.squaredNorm() > 0))
      return cold_solve(p, arc, on_ring);  // no projection: Frame's U (the definition's fallback)
    const Vec3<Real> v(seen.wy * u.z() - seen.wz * u.y(), seen.wz * u.x() - seen.wx * u.z(),
                       seen.wx * u.y() - seen.wy * u.x());
    if (seen.on_axis(radius)) {  // every arc point as close: the start
      on_ring = true;
      r.distance = ring();
      r.point_b = arc.center + (radius / u.norm()) * u;
      r.unique = false;
      return r;
    }
    // The point's angle from u toward v, in [0, 2 pi): q = s^2 (d - z N) against u' and v' / s.
    const typename detail::PointOverRound<Real>::InPlane q = seen.in_plane();
    const Real y = q.x * v.x() + q.y * v.y() + q.z * v.z(), x = seen.s * (q.x * u.x() + q.y * u.y() + q.z * u.z());
    // Off the arc: the end nearer in angle is the nearer (the distance rises with the angular
    // gap, up to pi). Where the gaps are within `margin` of each other (P near the plane through
    // the axis that bisects the arc's gap) both ends are measured: the nearer, or two closest
    // pairs when they tie.
    constexpr Real margin = Real(1) / (1 << 20);
    // Where the answer is: 0 the ring (t <= angle), 1 the start, 2 the far end, 3 both ends.
    int where = -1;
    Real t = 0;
    if constexpr (Cached) {
      where = sector_from_ends(x, y, arc.trig);
      if (where < 0) return solve_uncached<Points>(p, arc, on_ring);  // x or y not finite
      if constexpr (Points) {
        if (where == 0) {
          t = detail::atan2(y, x);
          t = detail::select(t < 0, t + turn, t);
        }
      }
    } else if constexpr (!Points) {
      where = sector_without_angle(x, y, angle, margin);
    }
    if (!Cached && where < 0) {
      t = detail::atan2(y, x);
      t = detail::select(t < 0, t + turn, t);
      if (!(t == t) || !(angle == angle)) {  // a NaN normal or angle (out of line in effect: rare)
        r.distance = nan;
        return r;
      }
      const Real to_end = t - angle, to_start = turn - t;
      where = t <= angle ? 0 : (to_start < to_end - margin ? 1 : (to_end < to_start - margin ? 2 : 3));
    }
    if (where == 0) {
      on_ring = true;
      r.distance = ring();
      if constexpr (Points) {
        r.point_b = seen.on_rim(arc.center, radius);
        r.param_b = Vec2<Real>(t, 0);
      }
      return r;
    }
    // From the center (p - c exact for nearby coordinates): the world end points round by an
    // ulp of their coordinates, 1e-10 at 1e6.
    const Vec3<Real> d = p - arc.center;
    const Real to_u = radius / u.norm();
    const Vec3<Real> e0 = to_u * u;
    const Real d0 = (d - e0).norm();
    if (where == 1) {  // the start: no trigonometry
      r.distance = d0;
      if constexpr (Points) r.point_b = arc.center + e0;
      return r;
    }
    // The far end, radius (cos a u' / |u'| + sin a v' / (s |u'|)).
    const Real to_v = to_u * seen.inv_s;
    const Real cos_a = Cached ? arc.trig.cos_angle : std::cos(angle),
               sin_a = Cached ? arc.trig.sin_angle : std::sin(angle);
    const Vec3<Real> e1 = (cos_a * to_u) * u + (sin_a * to_v) * v;
    const Real d1 = (d - e1).norm();
    if (where == 2) {
      r.distance = d1;
      if constexpr (Points) {
        r.point_b = arc.center + e1;
        r.param_b = Vec2<Real>(angle, 0);
      }
      return r;
    }
    const bool first = d0 <= d1;
    r.distance = first ? d0 : d1;
    r.point_b = arc.center + (first ? e0 : e1);
    r.param_b = Vec2<Real>(first ? Real(0) : angle, 0);
    r.unique = !(std::abs(d0 - d1) <= tie_tolerance(std::max(radius, r.distance)) &&
                 (e0 - e1).norm() > distinct_points_tolerance(radius));
    return r;
  }

  // The answer's place (0 the ring, 1 the start, 2 the far end, 3 both ends) from the arc's
  // end directions (docs/derivations/arc.md, "A point": the ends' directions): (x, y) is the
  // point's in-plane part, |q| (cos t, sin t) with t its angle from the start. With the end at
  // angle a, y cos a - x sin a = |q| sin(t - a): for a <= pi the point is on the arc where
  // y >= 0 and that is <= 0; for a > pi it is off the arc where y < 0 and that is > 0. Off the
  // arc, the gap's bisector b = pi + a/2 parts the points nearer the start (t > b) from those
  // nearer the far end: x sin(a/2) - y cos(a/2) = |q| sin(t - b), t - b in (-pi, pi). Both ends
  // are measured where |t - b| <= margin / 2 (solve()'s band), |sin(t - b)| <= sin(margin / 2).
  // -1 (the general path decides) where x or y is not finite.
  CIRCLEDIST_INLINE static int sector_from_ends(Real x, Real y, const detail::ArcTrig<Real>& e) {
    const Real ax = std::abs(x), ay = std::abs(y);
    if (!(ax + ay < std::numeric_limits<Real>::infinity())) return -1;  // NaN too
    const Real past_end = y * e.cos_angle - x * e.sin_angle;
    const bool on_arc = e.cos_half >= 0 ? (y >= 0 && past_end <= 0) : !(y < 0 && past_end > 0);
    if (on_arc) return 0;
    const Real side = x * e.sin_half - y * e.cos_half, gap = std::abs(side);
    // sin(margin / 2) to the last bit is not needed: the band's edge is a choice, not a bound.
    constexpr Real band = Real(1) / (1 << 21);
    const Real big = std::max(ax, ay);
    if (gap > band * (ax + ay)) return side > 0 ? 1 : 2;  // |q| <= |x| + |y|
    if (gap <= band * big) return 3;                      // |q| >= max(|x|, |y|)
    const Real small = std::min(ax, ay) / big;
    return gap > band * (big * std::sqrt(1 + small * small)) ? (side > 0 ? 1 : 2) : 3;
  }

  // distance()'s sector test without the atan2 (docs/derivations/arc.md, "Cost"): the answer's place (0
  // the ring, 1 the start, 2 the far end, 3 both ends, as solve() derives them from t) where the
  // octant of (x, y) decides it, else -1 (then t decides). The octant comes from exact
  // comparisons of x and y, the very numbers atan2 takes: t = atan2(y, x), moved into [0, 2 pi),
  // lies in [k pi/4, (k + 1) pi/4] up to atan2's error (2.5 ulp in double, detail/atan2.hpp;
  // std::atan2's in other types) and the rounding of t + 2 pi, both far below
  // slack = 64 eps 2 pi. Each of solve()'s comparisons, t <= angle, to_start < to_end - margin
  // (t beyond (2 pi + angle + margin) / 2, each difference rounding by an ulp of 2 pi) and
  // to_end < to_start - margin, is taken here only where the octant, widened by 2 slack on
  // each side, lies wholly on one side of its threshold: there t gives the same answer.
  // A NaN or infinite x, y or angle: -1.
  CIRCLEDIST_INLINE static int sector_without_angle(Real x, Real y, Real angle, Real margin) {
    Real lo, hi;
    if (!(angle < std::numeric_limits<Real>::infinity()) || !detail::octant_bounds(x, y, lo, hi)) return -1;  // NaN too
    const Real turn = 2 * pi_v<Real>(), slack = detail::octant_slack<Real>();
    if (hi < angle) return 0;
    if (!(lo > angle)) return -1;
    const Real start_side = (turn + angle + margin) / 2, end_side = (turn + angle - margin) / 2;
    if (lo > start_side + slack) return 1;  // to_start < to_end - margin
    if (!(hi < start_side - slack)) return -1;
    if (hi < end_side - slack) return 2;  // to_end < to_start - margin
    if (lo > end_side + slack) return 3;  // neither
    return -1;
  }

  // A start with no in-plane part: the arc starts at Frame's U (ArcSpan's theta0 = 0); the
  // general form through the canonical angle, out of line (rare).
#if defined(__GNUC__) || defined(__clang__)
  __attribute__((noinline, cold))
#endif
  static Result<Real>
  cold_solve(const Vec3<Real>& p, const Arc3<Real>& arc, bool& on_ring) {
    Arc3<Real> a = arc;
    a.start = Frame<Real>(arc.normal).u;
    if (!(a.start.squaredNorm() > 0)) {  // a zero or NaN normal: no answer
      Result<Real> r;
      r.point_a = p;
      r.distance = std::numeric_limits<Real>::quiet_NaN();
      return r;
    }
    return solve<true>(p, a, on_ring);
  }
};

}  // namespace detail

template <class Real> struct Query<Vec3<Real>, Arc3<Real>> : detail::PointArcPair<Real> {};

}  // namespace circledist
