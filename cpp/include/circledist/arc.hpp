// Arcs (issue 19; derivation in docs/arc.md). An arc is a circle whose candidates are restricted
// to its angles, with its two end points added. Against a point: point-circle's closed form
// (note 000 §1) where the point's angle falls on the arc, else the nearer end. Against a line,
// ray, segment, circle, disk or arc: the arc is parametrized by its circle's canonical angle theta
// on [theta0, theta0 + angle] (ArcSpan) and the other shape's exact distance from the arc's point
// is minimized there (polish_on_arc): the whole circle's stationary angles that fall on the arc
// (the circle machinery's own candidates, Query<Circle3, Circle3>::candidates and
// Query<Circle3, Disk3>::candidates; for a piece, the quartic of its line's distance), the arc's
// ends and, where the other shape's closest point is one of its own ends (a ray's or segment's,
// another arc's), that end's stationary angle; each polished on the interval (polish_offsets,
// detail/angle_polish.hpp). A piece is first asked the fast way (piece_arc_fast): the line's
// minima over the ring (line_ring_minimum, other_line_minimum) on the arc, the arc's ends and the
// piece's ends, no quartic. An arc of angle 2 pi is its circle, answered by the circle's query.
#pragma once

#include "circle_circle.hpp"
#include "circle_disk.hpp"
#include "detail/point_over_round.hpp"
#include "line_circle.hpp"
#include "linear.hpp"
#include "linear_linear.hpp"
#include "point_circle.hpp"
#include "point_disk.hpp"
#include "detail/trig.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {
// The octant of (x, y), from exact comparisons of the two numbers atan2(y, x) takes: that angle,
// moved into [0, 2 pi) as the arc's sector tests move it (t < 0: t + 2 pi), lies in
// [k pi/4, (k + 1) pi/4] up to atan2's error (2.5 ulp in double, detail/atan2.hpp; std::atan2's
// in other types) and the rounding of t + 2 pi, both far below octant_slack(); [lo, hi] is that
// octant widened by the slack. y < 0 is the lower half; y = -0 the upper (atan2(-0, x) is -0 or
// -pi, t then 0 or pi). False for a NaN or infinite x or y. A comparison of t with a threshold
// is decided by the octant where [lo, hi], widened by another slack for the threshold's own
// rounding, lies wholly on one side: there t answers the same (docs/arc.md, "Cost").
template <class Real> constexpr Real octant_slack() { return 128 * std::numeric_limits<Real>::epsilon() * 2 * pi_v<Real>(); }
template <class Real> CIRCLEDIST_INLINE bool octant_bounds(Real x, Real y, Real& lo, Real& hi) {
  if (!(std::abs(x) + std::abs(y) < std::numeric_limits<Real>::infinity())) return false;  // NaN too
  const Real quarter = pi_v<Real>() / 4, slack = octant_slack<Real>();
  const bool lower = y < 0, left = x < 0, steep = std::abs(y) > std::abs(x);
  static constexpr int octants[8] = {0, 1, 3, 2, 7, 6, 4, 5};  // by 4 lower + 2 left + steep
  const int k = octants[4 * lower + 2 * left + steep];
  lo = k * quarter - slack;
  hi = (k + 1) * quarter + slack;
  return true;
}
}  // namespace detail

// The arc's circle (the same fields), and whether the arc is all of it (angle >= 2 pi).
template <class Real> Circle3<Real> arc_circle(const Arc3<Real>& a) { return {a.center, a.normal, a.radius}; }
template <class Real> bool whole_arc(const Arc3<Real>& a) { return a.angle >= 2 * pi_v<Real>(); }

// An arc's interval in its circle's canonical angle (primitives.hpp, Frame: the angle every
// circle query parametrizes by): the arc's t is theta - theta0, theta0 the canonical angle of u,
// the start's projection (u = cos theta0 U + sin theta0 V, so v = N x u = cos theta0 V -
// sin theta0 U and the arc's point at t is the circle's at theta0 + t). docs/arc.md, "The arc".
template <class Real> struct ArcSpan {
  Frame<Real> frame;
  Real theta0 = 0, angle;

  explicit ArcSpan(const Arc3<Real>& a) : frame(a.normal), angle(std::max(a.angle, Real(0))) {
    const Vec3<Real> start = detail::moderate_start(a.start);
    const Real x = frame.u.dot(start), y = frame.v.dot(start);
    if (x != 0 || y != 0) theta0 = detail::atan2(y, x);  // no projection: U's angle, 0
  }
  // A circle as the arc of all its angles from its own angle 0 (its canonical parameter).
  explicit ArcSpan(const Circle3<Real>& c) : frame(c.normal), angle(2 * pi_v<Real>()) {}

  Real lo() const { return theta0; }
  Real hi() const { return theta0 + angle; }

  // The arc's t of a canonical angle, in [0, 2 pi).
  Real offset(Real theta) const {
    const Real turn = 2 * pi_v<Real>();
    Real t = theta - theta0;
    if (!(t >= 0 && t < turn)) t -= turn * std::floor(t / turn);
    return t;
  }
  // The arc's parameter of a circle point's canonical angle: t when it lies on the arc, else the
  // nearer end (a point rounded past an end).
  Real param_of(Real theta) const {
    const Real t = offset(theta);
    if (t <= angle) return t;
    return t - angle < 2 * pi_v<Real>() - t ? angle : Real(0);
  }
  bool holds(Real theta) const { return offset(theta) <= angle; }
  // The arc's angles, widened by 2^-20 rad at each end, as intervals of u = tan(theta / 2) (the
  // octic's variable): one, or two where the arc passes theta = pi (u = +-infinity); everywhere
  // for an arc within 2^-19 of the whole turn. Roots in the widening are dropped by the exact
  // offset test of polish_on_arc, as before (docs/arc.md, "Cost").
  Intervals<Real> half_angle_range() const {
    const Real pi = pi_v<Real>(), margin = Real(1) / (1 << 20);
    Real a = theta0 - margin;
    const Real width = angle + 2 * margin;
    if (!(width < 2 * pi)) return Intervals<Real>::everywhere();
    if (a < -pi) a += 2 * pi;  // theta0 in (-pi, pi]: a into [-pi, pi)
    if (a >= pi) a -= 2 * pi;
    const Real b = a + width;  // below a + 2 pi: the two pieces below stay apart
    Intervals<Real> out;
    const Real inf = std::numeric_limits<Real>::infinity();
    if (b < pi) {
      out.add(std::tan(a / 2), std::tan(b / 2));
    } else {
      out.add(-inf, std::tan((b - 2 * pi) / 2));
      out.add(std::tan(a / 2), inf);
    }
    return out;
  }
  // The parameter (t, 0) of an angle polished on [lo, hi].
  Vec2<Real> param(Real theta) const { return Vec2<Real>(std::min(std::max(theta - theta0, Real(0)), angle), 0); }

  // The point of the circle of `radius` at canonical angle theta: in the circle's own frame
  // (center at the origin), and in the world.
  static Vec3<Real> local(Real radius, Real theta) {
    return Vec3<Real>(radius * std::cos(theta), radius * std::sin(theta), Real(0));
  }
  Vec3<Real> from_center(Real radius, Real theta) const {
    return radius * (std::cos(theta) * frame.u + std::sin(theta) * frame.v);
  }
  Vec3<Real> world(const Vec3<Real>& center, Real radius, Real theta) const { return center + from_center(radius, theta); }
};

// The answer of a whole arc from its circle's: the arc's parameter is its t, the circle's angle
// less theta0 (`side` 0 for param_a, 1 for param_b).
template <class Real> Result<Real> as_arc_result(Result<Real> r, const ArcSpan<Real>& span, int side) {
  Vec2<Real>& p = side == 0 ? r.param_a : r.param_b;
  p = Vec2<Real>(span.param_of(p.x()), 0);
  return r;
}

// ---------------------------------------------------------------------------------------------
// Point against arc: closed form (docs/arc.md, "A point"). The distance from P to the circle's
// point at angle theta is sqrt(z^2 + rho^2 + R^2 - 2 R rho cos(theta - phi)), phi the angle of P's
// projection: least at phi and rising on both sides to its greatest at phi + pi. So over the arc
// it is least at phi when phi lies on the arc (point-circle's answer), otherwise at the end
// nearer in angle. On the axis (rho = 0) every arc point is as close.
// The angle is taken from the arc's own start direction u' (the start's in-plane part), not from
// the canonical frame: no Frame, no theta0, one atan2 (docs/arc.md, "A point": the cost).
template <class Real> struct Query<Vec3<Real>, Arc3<Real>> {
  static constexpr bool defined = true;
  using Whole = detail::PointRoundQuery<Real, false>;

  template <class Roots = DefaultRoots> static Real distance(const Vec3<Real>& p, const Arc3<Real>& arc) {
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
  // (piece_arc_fast; docs/arc.md, "Before the root").
  template <bool Points>
  CIRCLEDIST_INLINE static Result<Real> solve(const Vec3<Real>& p, const Arc3<Real>& arc, bool& on_ring) {
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
    const Real ring = length2d(seen.height, seen.radial - radius);
    // u' = |W|^2 S - (S.W) W, the start's in-plane part times |W|^2 (seen's W, rescaled if it
    // had to be: no division), and v' = W x u' (|v'| = s |u'|): the arc's u and v up to their
    // lengths.
    const Vec3<Real> start = detail::moderate_start(arc.start);
    const Real k = seen.wx * start.x() + seen.wy * start.y() + seen.wz * start.z();
    const Vec3<Real> u(seen.norm2 * start.x() - k * seen.wx, seen.norm2 * start.y() - k * seen.wy,
                       seen.norm2 * start.z() - k * seen.wz);
    // |u'| = sqrt(|u'|^2) (Eigen's norm()): zero exactly where its square is, so the test needs
    // no square root; the length itself only where an end point is formed.
    if (!(u.squaredNorm() > 0)) return cold_solve(p, arc, on_ring);  // no projection: Frame's U (the definition's fallback)
    const Vec3<Real> v(seen.wy * u.z() - seen.wz * u.y(), seen.wz * u.x() - seen.wx * u.z(),
                       seen.wx * u.y() - seen.wy * u.x());
    if (seen.on_axis(radius)) {  // every arc point as close: the start
      on_ring = true;
      r.distance = ring;
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
    if constexpr (!Points) where = sector_without_angle(x, y, angle, margin);
    if (where < 0) {
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
      r.distance = ring;
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
    const Real to_v = to_u / seen.s;
    const Vec3<Real> e1 = (std::cos(angle) * to_u) * u + (std::sin(angle) * to_v) * v;
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

 private:
  // distance()'s sector test without the atan2 (docs/arc.md, "Cost"): the answer's place (0
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
  static Result<Real> cold_solve(const Vec3<Real>& p, const Arc3<Real>& arc, bool& on_ring) {
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

// ---------------------------------------------------------------------------------------------
// The arc parametrized against another shape (docs/arc.md, "The arc parametrized").

// Room for every query's candidates: the circle's (24 at most), two end angles, and the arc's
// two ends.
constexpr int kArcCapacity = 64;
template <class Real> using ArcCandidates = Candidates<Real, kArcCapacity>;
template <class Real> using ArcMinima = Minima<Real, kArcCapacity>;

// The least distance h reaches at the arc's ends and angles between them spaced at most pi/4
// apart (a whole circle: eight, as circle-circle samples it): a distance the arc reaches, the
// bound its circle's octic is searched under (ring_search_intervals; the tighter it is, the
// fewer intervals searched). The whole circle's own samples (sampled_distances) may lie off the
// arc. Against a disk (ArcRoundQuery). docs/arc.md, "Cost".
template <class Real, class H> Real arc_bound(const ArcSpan<Real>& span, const H& h) {
  const int pieces = std::min(8, std::max(1, int(std::ceil(span.angle * (4 / pi_v<Real>())))));
  Real best = std::numeric_limits<Real>::infinity();
  for (int k = 0; k <= pieces; ++k) best = std::min(best, h(span.lo() + span.angle * k / pieces));
  return best;
}

// h with its values at the arc's two ends kept: arc_bound takes h there, and polish_on_arc's
// screening takes it there again (the ends are starts). The same numbers (h is a function of
// t alone), each computed once.
template <class Real, class H> auto with_end_values(const ArcSpan<Real>& span, const H& h) {
  const Real lo = span.lo(), hi = span.hi(), at_lo = h(lo), at_hi = h(hi);
  return [=, &h](Real t) { return t == lo ? at_lo : (t == hi ? at_hi : h(t)); };
}

// The same bound against a ring or an arc, without the interior evaluations: the least of h at
// the arc's two ends and of `sample(i)`, the distance at the circle's sample angle i pi/4
// (sampled_squared_distances: exact cosines and sines), over the samples the arc holds. Ends and
// samples are at most pi/4 apart along the arc, as the whole circle's eight are; the samples cost
// no sine or cosine, and against a ring they are the ones the circle query takes anyway.
// The whole circle's best sample may lie off the arc. docs/arc.md, "Cost".
template <class Real, class H, class Sample> Real arc_bound(const ArcSpan<Real>& span, const H& h, const Sample& sample) {
  Real best = std::min(h(span.lo()), h(span.hi()));
  for (int i = 0; i < 8; ++i)
    if (span.holds(i * (pi_v<Real>() / 4))) best = std::min(best, sample(i));
  return best;
}

// The candidates of the whole circle that fall on the arc (moved to the turn that holds them)
// and the arc's two ends, polished on [lo, hi] on the exact distance h (jet: its square's
// derivatives), as polish_angles does on the whole circle. The ends are exact candidates (the
// minimum on an interval can sit at an end). No samples of the arc's own: where the circle's
// roots say nothing (a circle nearly coincident with the other round, whose octic is rounding
// noise) the circle's candidates already carry circle-circle's eight samples, and those on the
// arc with its ends start every basin the arc holds (docs/arc.md, "Why no samples").
template <class Roots, class Real, int N, class J, class H>
ArcMinima<Real> polish_on_arc(const ArcSpan<Real>& span, const Candidates<Real, N>& candidates, const J& jet,
                              const H& h, Real radius, Real scale) {
  ArcCandidates<Real> starts;
  if (!(span.angle >= 0) || !std::isfinite(span.lo())) {  // a NaN angle or normal: no answer, NaN
    ArcMinima<Real> none;
    none.best = Minimum<Real>{span.lo(), std::numeric_limits<Real>::quiet_NaN()};
    return none;
  }
  starts.push(span.lo());
  starts.push(span.hi());
  for (int i = 0; i < candidates.count; ++i) {
    const Real t = span.offset(candidates.value[i]);
    if (t <= span.angle) starts.push(span.lo() + t);
  }
  return polish_offsets<Roots>(jet, h, starts, Real(1e-3), span.lo(), span.hi(), parameter_tolerance(radius, scale),
                               screening_margin(scale), pi_v<Real>());
}

// closest(): the arc's ends as minima of their own (at their distance `distance_at(t)`), for
// `unique` only (another_closest_pair), not for the best, which the polished minima hold. Where
// the distance is flat along the arc (an arc coaxial and coplanar with a round: every point as
// close), polishing can take every start to one point (a Newton step on rounding noise runs to
// the interval's end), so the polished minima alone showed one pair; an end as close at a
// distinct point is a second closest pair. (A whole circle's starts hold eight samples; an arc's
// hold its ends, which the polish may move.)
template <class Real, class DistanceAt>
void add_ends_for_ties(ArcMinima<Real>& minima, const ArcSpan<Real>& span, const DistanceAt& distance_at) {
  for (const Real end : {span.lo(), span.hi()})
    if (minima.count < kArcCapacity) minima.item[minima.count++] = Minimum<Real>{end, distance_at(end)};
}

// An arc (or a circle, ArcSpan(Circle3)) against a ring or a disk (Target, round_target.hpp):
// the arc's circle seen from the round (LocalCircle, CircleOverRound: the distance and jet that
// circle-circle and circle-disk polish on), the whole circle's candidates from those queries,
// searched under the arc's own bound.
template <class Real, class Target> struct ArcRoundQuery {
  using Shape = typename Target::Shape;

  using CircleDisk = Query<Circle3<Real>, Disk3<Real>>;
  using Heights = typename CircleDisk::Heights;

  template <class Roots>
  static ArcMinima<Real> solve(const ArcSpan<Real>& span, const LocalCircle<Real>& c, Real radius, Real scale) {
    if constexpr (Target::interior) {
      return solve<Roots>(span, c, radius, scale, CircleDisk::template height_candidates<Roots>(c, scale));
    } else {
      return solve<Roots>(span, c, radius, scale, Heights());
    }
  }

  // `heights`: against a disk, circle-disk's height candidates (computed once for the verdict
  // and the solve); unused against a ring.
  template <class Roots>
  static ArcMinima<Real> solve(const ArcSpan<Real>& span, const LocalCircle<Real>& c, Real radius, Real scale,
                               const Heights& heights) {
    const CircleOverRound<Real> view(c, radius);
    const auto distance = [&](Real t) { return view.template distance<Target>(t); };
    const auto h = with_end_values(span, distance);
    const auto jet = [&](Real t) { return view.template jet<Target>(t); };
    if constexpr (Target::interior) {
      // Against a disk, as before: the bound from h itself, the octic searched on the whole
      // circle. Restricted to the arc's angles (as against a ring, below), the octic's roots over a
      // disk parallel to the arc's plane (rounding noise there: the distance is the planes' gap
      // over the disk) came out differently, and the continuum's `unique` with them, wrong in 4
      // of 6 changed cases (docs/arc.md, "Cost").
      return polish_on_arc<Roots>(span, CircleDisk::template candidates<Roots>(view, scale, heights, arc_bound(span, h)),
                                  jet, h, c.radius, scale);
    } else {
      (void)heights;
      using CircleCircle = Query<Circle3<Real>, Circle3<Real>>;
      const auto squared = [&](const Vec3<Real>& p) { return RingTarget<Real>::distance_squared(p, radius); };
      const std::array<Real, 8> samples = sampled_squared_distances(c, squared);
      const Real bound = arc_bound(span, h, [&](int i) { return std::sqrt(samples[i]); });
      const Intervals<Real> within = span.half_angle_range();
      return polish_on_arc<Roots>(
          span, CircleCircle::template candidates<Roots>(view, scale, bound, sampled_distances(samples), &within), jet,
          h, c.radius, scale);
    }
  }

  // Against a disk, distance()'s early answer (circle-disk's height verdict restricted to the
  // arc; docs/arc.md, "Cost"): the disk's distance is at least the height |z| everywhere, and
  // over the arc |z| is least at an end, at a root of z (z = 0) or at a root of z' (an interior
  // local extremum of z): the arc's points among circle-disk's height candidates (z = 0, z' = 0,
  // t = 0, pi) and its two ends hold the arc's least |z|, `lowest`. Where the least disk
  // distance among those same points, `best`, is no more than that (within circle-disk's tie
  // tolerance, the rounding of z at the rounded roots), no point of the arc is closer than
  // `best`, an arc point's distance: the answer, without the octic. A root rounded just off the
  // arc is dropped, but |z| at the arc's end next to it is then within rounding of its value.
  struct HeightVerdict {
    Real best;
    bool decided;
  };
  template <class Roots>
  static HeightVerdict height_verdict(const ArcSpan<Real>& span, const LocalCircle<Real>& c, Real radius, Real scale,
                                      const Heights& heights) {
    // One sine and cosine per point: |z| at each, then the disk's distance only at the points
    // whose |z| is within the tolerance of the lowest (elsewhere it is at least |z|, above
    // lowest + tolerance: such a point can neither decide nor be the decided best).
    const CircleOverRound<Real> view(c, radius);
    Real cs[Heights::capacity + 2], sn[Heights::capacity + 2], z[Heights::capacity + 2];
    int n = 0;
    Real lowest = std::numeric_limits<Real>::infinity();
    const auto take = [&](Real t) {
      cs[n] = std::cos(t);
      sn[n] = std::sin(t);
      z[n] = std::abs(c.center.z() + cs[n] * c.e1.z() + sn[n] * c.e2.z());
      lowest = std::min(lowest, z[n]);
      ++n;
    };
    take(span.lo());
    take(span.hi());
    for (int i = 0; i < heights.count; ++i) {
      const Real t = span.offset(heights.value[i]);
      if (t <= span.angle) take(span.lo() + t);
    }
    const Real level = lowest + tie_tolerance(scale);
    Real best = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < n; ++i)
      if (z[i] <= level) best = std::min(best, view.template distance<Target>(cs[i], sn[i]));
    if (!(best <= level)) return {best, false};
    // Decided. The answer is then polished as the full solve would polish it: those same starts
    // (each polished alone, polish_offsets, on the same h and jet over the same interval), which
    // the full solve holds too and, being within rounding of the least |z|, polishes too (its
    // screening margin is 16 sqrt(eps) scale). So the decided answer is the full solve's (the
    // least over a superset of these starts) wherever its best comes from one of them, and a
    // crossing of the disk, where an unpolished root of z leaves |z| at rounding noise, reaches
    // what the polish reaches.
    ArcCandidates<Real> starts;
    const auto keep = [&](int i, Real t) {
      if (z[i] <= level) starts.push(t);
    };
    int i = 0;
    keep(i++, span.lo());
    keep(i++, span.hi());
    for (int k = 0; k < heights.count; ++k) {
      const Real t = span.offset(heights.value[k]);
      if (t <= span.angle) keep(i++, span.lo() + t);
    }
    const auto h = [&](Real t) { return view.template distance<Target>(t); };
    const auto jet = [&](Real t) { return view.template jet<Target>(t); };
    const ArcMinima<Real> polished =
        polish_offsets<Roots>(jet, h, starts, Real(1e-3), span.lo(), span.hi(), parameter_tolerance(c.radius, scale),
                              screening_margin(scale), pi_v<Real>());
    return {std::min(best, polished.best.value), true};
  }

  // The arc first.
  template <class Roots> static Real distance(const Arc3<Real>& arc, const Shape& shape) {
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const LocalCircle<Real> c(arc_circle(arc), round);
    const ArcSpan<Real> span(arc);
    const Real scale = circle_round_scale(c, shape.radius);
    if constexpr (Target::interior) {
      const Heights heights = CircleDisk::template height_candidates<Roots>(c, scale);
      const HeightVerdict early = height_verdict<Roots>(span, c, shape.radius, scale, heights);
      if (early.decided) return early.best;
      return std::min(early.best, solve<Roots>(span, c, shape.radius, scale, heights).best.value);
    } else {
      return solve<Roots>(span, c, shape.radius, scale).best.value;
    }
  }

  // Against a disk the distance is distance()'s (the verdict's where it decides), as circle-disk
  // reports it: the two agree to the bit.
  template <class Roots> static Result<Real> closest(const Arc3<Real>& arc, const Shape& shape) {
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const LocalCircle<Real> c(arc_circle(arc), round);
    const ArcSpan<Real> span(arc);
    const Real scale = circle_round_scale(c, shape.radius);
    Heights heights;
    if constexpr (Target::interior) heights = CircleDisk::template height_candidates<Roots>(c, scale);
    ArcMinima<Real> minima = solve<Roots>(span, c, shape.radius, scale, heights);
    add_ends_for_ties(minima, span, [&](Real t) {
      bool unused = false;
      const Vec3<Real> p = c.at(t);
      return (p - Target::point(p, shape.radius, scale, unused)).norm();
    });
    Result<Real> r = circle_round_result<Target>(arc_circle(arc), c, round, minima, scale);
    r.param_a = span.param(minima.best.x);
    if constexpr (Target::interior) {
      const HeightVerdict early = height_verdict<Roots>(span, c, shape.radius, scale, heights);
      r.distance = early.decided ? early.best : std::min(early.best, minima.best.value);
    }
    return r;
  }
};

// ---------------------------------------------------------------------------------------------
// Arc B as the target of a moving point, in B's round frame (center at the origin, normal
// along z): its distance is point-arc's (above), the ring's where the point's angle falls on the
// arc, else the nearer end's. Against arc B, A is parametrized (an arc, or a circle as the arc of
// all its angles) and its candidates are circle-circle's against B's ring and B's ends' own
// stationary angles on A. (Where A's point crosses from the ring's form to an end's, the distance
// is C^1, both forms having the gradient (P - E) / |P - E|: a minimum there is a root of the ring's
// octic too, docs/arc.md.)
template <class Real> struct ArcTarget {
  ArcSpan<Real> span;
  Real radius;
  Vec3<Real> end[2];

  bool sectors;  // whether sector() may decide (a finite angle in [0, 2 pi), radius and start)

  explicit ArcTarget(const Arc3<Real>& b)
      : span(b), radius(b.radius), end{ArcSpan<Real>::local(b.radius, span.lo()), ArcSpan<Real>::local(b.radius, span.hi())} {
    sectors = span.angle >= 0 && span.angle < 2 * pi_v<Real>() && radius > 0 && radius < std::numeric_limits<Real>::infinity() &&
              std::isfinite(span.lo());
  }

  // -1 where the ring's point is on the arc, else the nearer end's index. The sector test of
  // the canonical angle (an atan2 per call: every h and jet of arc-arc and circle-arc evaluates
  // it) is first decided by the signs of the cross products with the ends (sector()), and taken
  // in full only where those do not decide.
  int nearest_end(const Vec3<Real>& p) const {
    const int fast = sector(p);
    if (fast > 0 || (fast < 0 && span.holds(detail::atan2(p.y(), p.x())))) return -1;
    return (p - end[0]).squaredNorm() <= (p - end[1]).squaredNorm() ? 0 : 1;
  }

  // Whether p's angle lies on the arc, decided without an atan2: 1 on it, 0 off it, -1
  // undecided (then span.holds(atan2) decides, as it always did). With c0 = end0 x p and
  // c1 = p x end1 (z components; |end| = R): for an angle <= pi the arc is where both are
  // >= 0, for an angle > pi where either is (its gap, the complement, is then under pi). A sign
  // counts only beyond tol = 1e-9 R (|x| + |y|) >= 1e-9 |end| |p|, that is where p's direction
  // is more than about 1e-9 rad from the line through either end: the rounding of c0 and c1
  // (2 eps R (|x| + |y|)), of the ends' cosines and sines and of holds()'s atan2, theta0 and
  // offset (a few ulps of 2 pi) are all below 1e-14 rad, so beyond tol holds() gives the same
  // answer, and where either sign is within tol (p near an end's line, on the axis, NaN) this
  // answers -1. A NaN or out-of-range angle, radius or theta0: -1 always (`sectors`).
  int sector(const Vec3<Real>& p) const {
    if (!sectors) return -1;
    const Real x = p.x(), y = p.y();
    const Real tol = Real(1e-9) * radius * (std::abs(x) + std::abs(y));
    const Real c0 = end[0].x() * y - end[0].y() * x, c1 = x * end[1].y() - y * end[1].x();
    if (span.angle <= pi_v<Real>()) {
      if (c0 > tol && c1 > tol) return 1;
      if (c0 < -tol || c1 < -tol) return 0;  // offset in (pi, 2 pi) or in (angle, angle + pi)
    } else {
      if (c0 > tol || c1 > tol) return 1;  // offset in (0, pi) or in (angle - pi, angle)
      if (c0 < -tol && c1 < -tol) return 0;  // offset in (pi, 2 pi) and in (angle, 2 pi)
    }
    return -1;
  }

  // The arc's point closest to p. On the axis (within rounding, at the scene's `scale`) every
  // point is as close: the start, and `ambiguous`.
  Vec3<Real> point(const Vec3<Real>& p, Real scale, bool& ambiguous) const {
    if (length2d(p.x(), p.y()) <= 8 * std::numeric_limits<Real>::epsilon() * scale) {
      ambiguous = ambiguous || radius > 0;
      return end[0];
    }
    const int e = nearest_end(p);
    return e < 0 ? RingTarget<Real>::point(p, radius, scale, ambiguous) : end[e];
  }
  // The parameter (t, 0) of one of its points.
  Vec2<Real> param(const Vec3<Real>& q) const { return Vec2<Real>(span.param_of(detail::atan2(q.y(), q.x())), 0); }
};

// The squared distance from a moving point P to a fixed point E and its derivatives.
template <class Real>
Jet<Real> point_jet(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2, const Vec3<Real>& e) {
  const Vec3<Real> d = p - e;
  return {d.squaredNorm(), 2 * d.dot(p1), 2 * (p1.squaredNorm() + d.dot(p2))};
}

// The angle on circle c (LocalCircle: P(t) = O + E1 cos t + E2 sin t, |E1| = |E2|, E1.E2 = 0) of the
// point nearest a point q: the angle of q - O in the basis E1, E2 (none when q is on the axis).
template <class Real, int N> void push_nearest_angle(const LocalCircle<Real>& c, const Vec3<Real>& q, Candidates<Real, N>& out) {
  const Vec3<Real> d = q - c.center;
  const Real x = d.dot(c.e1), y = d.dot(c.e2);
  if (x != 0 || y != 0) out.push(std::atan2(y, x));
}

template <class Real> struct ArcArcQuery {
  // A (span: an arc, or a circle whole) parametrized against arc B.
  template <class Roots>
  static ArcMinima<Real> solve(const ArcSpan<Real>& span, const LocalCircle<Real>& c, const ArcTarget<Real>& target,
                               Real scale) {
    const CircleOverRound<Real> view(c, target.radius);
    // One sine and cosine per evaluation: the point for the sector test and the ring's form
    // from the same cos t and sin t (CircleOverRound's overloads: the values of the angle forms
    // to the bit; c.at(t) is c.center + cos t e1 + sin t e2, as here).
    const auto distance = [&](Real t) {
      const Real cs = std::cos(t), sn = std::sin(t);
      const Vec3<Real> p = c.center + cs * c.e1 + sn * c.e2;
      const int e = target.nearest_end(p);
      return e < 0 ? view.template distance<RingTarget<Real>>(cs, sn) : (p - target.end[e]).norm();
    };
    const auto h = with_end_values(span, distance);
    const auto jet = [&](Real t) {
      const Real cs = std::cos(t), sn = std::sin(t);
      const Vec3<Real> w = cs * c.e1 + sn * c.e2, p = c.center + w;
      const int e = target.nearest_end(p);
      return e < 0 ? view.template jet<RingTarget<Real>>(cs, sn) : point_jet(p, Vec3<Real>(cs * c.e2 - sn * c.e1), Vec3<Real>(-w), target.end[e]);
    };
    const auto squared = [&](const Vec3<Real>& p) { return RingTarget<Real>::distance_squared(p, target.radius); };
    // The ring's octic under a distance A's arc reaches (the arc's distance is at least the
    // ring's, so every closest pair with B's point inside B lies under it).
    const Intervals<Real> within = span.half_angle_range();
    // At the samples: the point from the exact cosines and sines, B's distance as h takes it.
    const auto sample = [&](int i) {
      const Vec3<Real> p = c.center + SampleAngles<Real>::cs[i][0] * c.e1 + SampleAngles<Real>::cs[i][1] * c.e2;
      const int e = target.nearest_end(p);
      return e < 0 ? std::sqrt(squared(p)) : (p - target.end[e]).norm();
    };
    const auto circle = Query<Circle3<Real>, Circle3<Real>>::template candidates<Roots>(
        view, scale, arc_bound(span, h, sample), sampled_distances(c, squared), &within);
    ArcCandidates<Real> candidates;
    for (int i = 0; i < circle.count; ++i) candidates.push(circle.value[i]);
    for (const Vec3<Real>& e : target.end) push_nearest_angle(c, e, candidates);
    return polish_on_arc<Roots>(span, candidates, jet, h, c.radius, scale);
  }

  // A (an arc or a circle: `a` its circle, `span` its angles) against arc b.
  template <class Roots> static Real distance(const Circle3<Real>& a, const ArcSpan<Real>& span, const Arc3<Real>& b) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const LocalCircle<Real> c(a, round);
    return solve<Roots>(span, c, ArcTarget<Real>(b), circle_round_scale(c, b.radius)).best.value;
  }

  // The same with its closest points; A's parameter is its span's (an arc's t; a circle's angle).
  template <class Roots>
  static Result<Real> closest(const Circle3<Real>& a, const ArcSpan<Real>& span, const Arc3<Real>& b, bool a_is_arc) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const LocalCircle<Real> c(a, round);
    const ArcTarget<Real> target(b);
    const Real scale = circle_round_scale(c, b.radius);
    ArcMinima<Real> minima = solve<Roots>(span, c, target, scale);
    const Real best = minima.best.x;
    const auto at = [&](Real t) { return c.at(t); };
    const auto arc_point = [&](const Vec3<Real>& q, bool& ambiguous) { return target.point(q, scale, ambiguous); };
    const auto distance_at = [&](Real t) {
      bool unused = false;
      return (at(t) - arc_point(at(t), unused)).norm();
    };
    if (a_is_arc) add_ends_for_ties(minima, span, distance_at);
    // B's ends' nearest angles on A too: over an A coaxial with B the distance is flat across B's
    // span, whose bounds on A these are, so where polishing took every start to one point (a
    // whole circle has no ends of its own to show the continuum) they are a second pair.
    ArcCandidates<Real> ends_of_b;
    for (const Vec3<Real>& e : target.end) push_nearest_angle(c, e, ends_of_b);
    for (int i = 0; i < ends_of_b.count; ++i) {
      const Real t = span.offset(ends_of_b.value[i]);
      if (t <= span.angle && minima.count < kArcCapacity)
        minima.item[minima.count++] = Minimum<Real>{span.lo() + t, distance_at(span.lo() + t)};
    }
    const Vec3<Real> pa = c.at(best);
    bool ambiguous = false;
    const Vec3<Real> pb = arc_point(pa, ambiguous);
    ambiguous = ambiguous || another_closest_pair(minima, scale, at, arc_point, pa, pb,
                                                  distinct_points_tolerance(std::min(scale, c.radius)),
                                                  distinct_points_tolerance(scale));
    Result<Real> r;
    r.distance = minima.best.value;
    r.point_a = span.world(a.center, a.radius, best);
    r.param_a = a_is_arc ? span.param(best) : Vec2<Real>(wrap_angle(best), 0);
    r.point_b = round.world(pb);
    r.param_b = target.param(pb);
    r.unique = !ambiguous;
    return r;
  }
};

// ---------------------------------------------------------------------------------------------
// Lines, rays and segments against an arc: the arc parametrized, the piece's exact distance
// (docs/arc.md, "A line, ray or segment").

// The piece seen from the arc's circle's frame (LocalLinear: anchored at its point nearest the
// center, a unit direction m, tau in [lo, hi]): the distance from a local point (|w x m| for
// w = p - a when p's foot lies on the piece, else the distance to the nearer end), its square's
// jet along the arc, and the piece's closest point.
template <class Real> struct PieceOverArc {
  const LocalLinear<Real>& line;

  Real clamped(Real tau) const { return std::min(std::max(tau, line.lo), line.hi); }
  bool inside(Real tau) const { return !line.is_point && tau >= line.lo && tau <= line.hi; }
  Real tau_of(const Vec3<Real>& p) const { return line.is_point ? Real(0) : clamped((p - line.anchor).dot(line.dir)); }
  Vec3<Real> point(const Vec3<Real>& p) const { return line.anchor + tau_of(p) * line.dir; }

  Real distance(const Vec3<Real>& p) const {
    const Vec3<Real> w = p - line.anchor;
    const Real tau = w.dot(line.dir);
    if (inside(tau)) return w.cross(line.dir).norm();
    return (w - clamped(tau) * line.dir).norm();
  }
  Jet<Real> jet(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2) const {
    const Vec3<Real> w = p - line.anchor;
    const Real tau = w.dot(line.dir);
    if (!inside(tau)) return point_jet(p, p1, p2, Vec3<Real>(line.anchor + clamped(tau) * line.dir));
    const Vec3<Real> q = w.cross(line.dir), q1 = p1.cross(line.dir), q2 = p2.cross(line.dir);
    return {q.squaredNorm(), 2 * q.dot(q1), 2 * (q1.squaredNorm() + q.dot(q2))};
  }
};

// The candidate angles of a piece against the arc's circle (radius R, its frame: P = R (cos, sin, 0)):
// with w = P - a and L = w.m = R (m_x cos + m_y sin) - a.m, the squared distance to the full line
// f = |w|^2 - L^2 has f' / 2 = R (a_x sin - a_y cos) - L L', trigonometric of degree 2 (a quartic
// in tan(theta / 2)); beyond an end (the foot L past lo or hi) the distance is the end's, least at
// the end's own angle (where it changes form the distance is C^1: a minimum there is a root of
// f' too, docs/arc.md). Plus t = 0 and pi (the half-angle substitution's blind spot). In units
// of `scale`.
template <class Roots, class Real, int N>
void push_piece_arc_candidates(const LocalLinear<Real>& line, Real radius, Real scale, Candidates<Real, N>& out) {
  push_circle_candidates(out);
  const auto push_end = [&](Real tau) {
    const Vec3<Real> e = line.at(tau);
    if (e.x() != 0 || e.y() != 0) out.push(std::atan2(e.y(), e.x()));
  };
  if (line.is_point) {
    push_end(Real(0));
    return;
  }
  const Vec3<Real> a = line.anchor / scale;
  const Vec3<Real>& m = line.dir;
  const Real r = radius / scale;
  Trig<Real, 1> along;
  along.c[0] = -a.dot(m);
  along.c[1] = r * m.x();
  along.s[1] = r * m.y();
  Trig<Real, 2> slope = Real(-1) * (along * along.derivative());
  slope.c[1] -= r * a.y();
  slope.s[1] += r * a.x();
  push_trig_roots<Roots>(slope, out);
  for (const Real tau : {line.lo, line.hi})
    if (std::isfinite(tau)) push_end(tau);
}

// The fast path (docs/arc.md, "A line, ray or segment: the fast path"). Over the whole circle the
// squared distance to the full line has at most two local minima, the global one
// (line_ring_minimum) and, inside the astroid, the other (other_line_minimum). The arc's
// distance to the piece is least at an arc end, or at an interior angle where it is a local
// minimum over the whole circle of the distance to the piece: there the piece's closest point is
// inside the piece (a local minimum of the line's distance, with its foot on the piece) or one of
// its ends E (the angle of E's projection, point-arc's answer for E). Every candidate value is the
// distance between a point of the arc and a point of the piece, so the least is the distance.
// The arc's unit u and v and its end points, relative to its center (u from |W|^2 S - (S.W) W, as
// point-arc takes it).
template <class Real> struct ArcEnds {
  Vec3<Real> u, v;  // |W|^2 times the start's in-plane part (u'), and W x u' (|v| = |W| |u|)
  Vec3<Real> end[2];
  Real angle = 0, s = 0, length = 0;  // |W|, |u|
  bool usable = false;  // false: a start along the normal, a zero or huge normal, a NaN angle

  // Unnormalized (no division: the sector test is an angle, scale-free; find_ends scales).
  // W is first scaled by a power of two (exact: only its direction counts) to |W|^2 in
  // [2^-100, 2^100], as PointOverRound takes it: u' is |W|^2 |S| and v' |W|^3 |S|, and |u'|^2
  // |W|^4 |S|^2, in the subnormals for a normal of 1e-80 and a unit start (its rounding moves the
  // ends' points off their circle by up to a fifth of the radius, and a line's distance as much).
  explicit ArcEnds(const Arc3<Real>& a) {
    constexpr Real lo = detail::power_of_two<Real>(-100), hi = detail::power_of_two<Real>(100);
    Vec3<Real> w = a.normal;
    Real n2 = w.squaredNorm();
    if (!detail::strictly_between(n2, lo, hi)) {
      w = detail::ldexp3(w, -detail::direction_exponent(w));
      n2 = w.squaredNorm();
    }
    const Vec3<Real> start = detail::moderate_start(a.start);
    u = n2 * start - w.dot(start) * w;
    length = u.norm();
    usable = length > 0 && std::isfinite(length) && n2 > 0 && std::isfinite(n2) && !std::isnan(a.angle);
    if (!usable) return;
    s = std::sqrt(n2);
    v = w.cross(u);
    angle = std::max(a.angle, Real(0));
  }
  // The end points (a sine and cosine: only where the ends are candidates).
  void find_ends(Real radius) {
    const Real to_u = radius / length, to_v = to_u / s;
    end[0] = to_u * u;
    end[1] = (std::cos(angle) * to_u) * u + (std::sin(angle) * to_v) * v;
  }
  // The arc's t of a point relative to the center (its angle from u toward v), in [0, 2 pi).
  Real offset(const Vec3<Real>& p) const {
    const Real t = detail::atan2(p.dot(v), s * p.dot(u));
    return t < 0 ? t + 2 * pi_v<Real>() : t;
  }
  // offset(p) <= angle, the atan2 only where the octant of the same two numbers does not decide
  // (detail::octant_bounds: where it does, offset answers the same).
  bool holds(const Vec3<Real>& p) const {
    Real lo, hi;
    if (detail::octant_bounds(s * p.dot(u), p.dot(v), lo, hi)) {
      if (hi < angle) return true;
      if (lo > angle) return false;
    }
    return offset(p) <= angle;
  }
};

// The piece relative to the arc's center c along its line's anchor a (its point nearest c, from
// line_ring_minimum, to one rounding) and unit direction m: tau in [lo, hi] from a, the ends'
// tau taken as (E - c).m (rounding along the line only). A point's distance |w - clamp(w.m) m|,
// w = p - a, stays accurate however far the piece's origin lies, where the point-ray closed form
// from a far origin would carry eps |origin - c| across the line into every distance.
template <class Real> struct AnchoredPiece {
  Vec3<Real> anchor, dir;
  Real lo, hi;

  template <class Piece>
  AnchoredPiece(const Piece& piece, const Linear<Real>& linear, const LineRingMinimum<Real>& m, const Vec3<Real>& c)
      : anchor(m.anchor), dir(m.unit_direction), lo(linear.lo), hi(linear.hi) {
    if (std::isfinite(lo)) lo = (piece_end(piece, lo) - c).dot(dir);
    if (std::isfinite(hi)) hi = (piece_end(piece, hi) - c).dot(dir);
  }
  Vec3<Real> point(const Vec3<Real>& p) const {
    const Real tau = std::min(std::max((p - anchor).dot(dir), lo), hi);
    return anchor + tau * dir;
  }
  Real distance(const Vec3<Real>& p) const { return (p - point(p)).norm(); }
};

// The fast path's answer: the least candidate, and whether another lies within the tie
// tolerance at distinct points (closest() then takes the pair and `unique` from the general path).
template <class Real> struct PieceArcPick {
  Real value = std::numeric_limits<Real>::infinity();
  Vec3<Real> piece_point = Vec3<Real>::Zero(), arc_point = Vec3<Real>::Zero();  // world
  Real piece_param = 0, arc_param = 0;
  bool unique = true, tied = false;
};

// False where the fast path does not decide (the general path answers): the line declined by
// line_ring_minimum or along the axis, the second minimum undecided, a segment too long for its
// line (piece_line).
template <class Roots, bool for_closest, class Real, class Piece>
bool piece_arc_fast(const Piece& piece, const Arc3<Real>& arc, PieceArcPick<Real>& out) {
  ArcEnds<Real> ends(arc);
  if (!ends.usable) return false;
  const Circle3<Real> c = arc_circle(arc);
  const PieceLine<Real> pl = piece_line(piece, arc.radius);
  if (!pl.usable) return false;
  const Linear<Real> linear = as_linear(piece);
  using PointArc = Query<Vec3<Real>, Arc3<Real>>;
  // Before the root (docs/arc.md, "Before the root"): where the line has one local minimum over
  // the ring, an end at which the ring's distance rises along the piece (p0, a ray's origin) or
  // falls toward the piece's end (p1) is the piece's closest point to the circle, as for a circle
  // (choose_from_line, line_circle.hpp); it is the arc's answer too where that end's nearest ring
  // point lies on the arc (point-arc's `on_ring`): the arc is no nearer than its circle anywhere,
  // and as near at that end. The answer is the end's point-arc candidate the rest of this path
  // would have found, by the same call.
  SecondMinimumTest<Real> test;
  const auto before_root = [&](const LineRingMinimum<Real>& line_data) {
    test = second_minimum_test(line_data, arc.radius);
    if (test.verdict != 0 || line_data.on_axis) return false;
    const Vec3<Real>& direction = pl.line.direction;
    Real tau;
    if (std::isfinite(linear.lo) && end_point_slope(piece_end(piece, linear.lo), c, line_data.unit_normal, direction) > 0)
      tau = linear.lo;
    else if (std::isfinite(linear.hi) &&
             end_point_slope(piece_end(piece, linear.hi), c, line_data.unit_normal, direction) < 0)
      tau = linear.hi;
    else
      return false;
    const Vec3<Real> end = piece_end(piece, tau);
    bool on_ring;
    const Result<Real> r = PointArc::template solve<for_closest>(end, arc, on_ring);
    if (!on_ring) return false;
    out.value = r.distance;
    if constexpr (for_closest) {
      out.piece_point = end;
      out.piece_param = tau;
      out.arc_point = r.point_b;
      out.arc_param = r.param_b.x();
      out.tied = !r.unique;
    }
    return true;
  };
  LineRingMinimum<Real> m;
  const LineRingOutcome outcome = line_ring_minimum<Roots>(pl.line, c, m, before_root);
  if (outcome == LineRingOutcome::AnsweredBeforeRoot) return out.value == out.value;
  if (outcome == LineRingOutcome::Declined || m.on_axis) return false;
  // The line's global minimum over the whole circle on the arc, its foot on the piece: no point of
  // the arc is nearer the line, so none nearer the piece, and this pair is the answer. It is the
  // only pair at that distance unless it is tied with its mirror image (the trust-region
  // subproblem's global minimizer is unique outside its hard case, b1 = 0, which the mirror
  // bounds: line_ring_minimum.hpp), where closest() asks the general path.
  // distance() needs only whether a ring point is on the arc (ArcEnds::holds), closest() its t.
  const auto on_arc_at = [&](const Vec3<Real>& ring_point, Real& t) {
    if constexpr (for_closest) {
      t = ends.offset(ring_point);
      return t <= ends.angle;
    } else {
      return ends.holds(ring_point);
    }
  };
  Real global_t = 0;
  const bool on_arc = on_arc_at(m.ring_point, global_t);
  if (on_arc && on_piece(pl.line, c.center, m.line_point, linear)) {
    out.value = m.distance;
    if constexpr (for_closest) {
      out.piece_point = c.center + m.line_point;
      out.arc_point = c.center + m.ring_point;
      out.piece_param = line_param(pl.line, c.center, m.line_point);
      out.arc_param = global_t;
      out.tied = tied_with_mirror(c, m);
    }
    return out.value == out.value;
  }
  LineRingMinimum<Real> second;
  const int other = other_line_minimum<Roots>(m, arc.radius, second, [](Real) { return true; }, test);
  if (other < 0) return false;
  // Closest points keep every candidate (for the tie test); the distance keeps the least value.
  PieceArcPick<Real> list[for_closest ? 6 : 1];
  int count = 0;
  Real least = std::numeric_limits<Real>::infinity();
  if (other == 1) {  // the global minimum is off the arc or the piece (above)
    Real t = 0;
    if (on_arc_at(second.ring_point, t) && on_piece(pl.line, c.center, second.line_point, linear)) {
      least = second.distance;
      if constexpr (for_closest) {
        PieceArcPick<Real>& k = list[count++];
        k.value = second.distance;
        k.piece_point = c.center + second.line_point;
        k.arc_point = c.center + second.ring_point;
        k.piece_param = line_param(pl.line, c.center, second.line_point);
        k.arc_param = t;
      }
    }
  }
  const AnchoredPiece<Real> local(piece, linear, m, c.center);
  ends.find_ends(arc.radius);
  for (int e = 0; e < 2; ++e) {
    if constexpr (for_closest) {
      const Vec3<Real> q = local.point(ends.end[e]);
      PieceArcPick<Real>& k = list[count++];
      k.value = (ends.end[e] - q).norm();
      k.piece_point = c.center + q;
      k.piece_param = line_param(pl.line, c.center, q);  // the piece's own parameter
      k.arc_point = c.center + ends.end[e];
      k.arc_param = e == 0 ? Real(0) : ends.angle;
    } else {
      least = std::min(least, local.distance(ends.end[e]));
    }
  }
  for (const Real tau : {linear.lo, linear.hi}) {
    if (!std::isfinite(tau)) continue;
    const Vec3<Real> end = piece_end(piece, tau);
    if constexpr (for_closest) {
      const Result<Real> r = PointArc::template closest<Roots>(end, arc);
      PieceArcPick<Real>& k = list[count++];
      k.value = r.distance;
      k.piece_point = end;
      k.piece_param = tau;
      k.arc_point = r.point_b;
      k.arc_param = r.param_b.x();
      k.unique = r.unique;
    } else {
      least = std::min(least, PointArc::template distance<Roots>(end, arc));
    }
  }
  if constexpr (!for_closest) {
    out.value = least;
  } else {
    int best = 0;
    for (int i = 1; i < count; ++i)
      if (list[i].value < list[best].value) best = i;
    out = list[best];
    const Real scale = std::max(arc.radius, out.value);
    const Real tie = tie_tolerance(scale), apart = distinct_points_tolerance(scale);
    for (int i = 0; i < count; ++i)
      if (i != best && list[i].value <= out.value + tie &&
          ((list[i].arc_point - out.arc_point).norm() > apart || (list[i].piece_point - out.piece_point).norm() > apart))
        out.tied = true;
    if (!out.unique) out.tied = true;
  }
  // Non-finite input is declined above (line_ring_minimum, ArcEnds); a NaN least all the same
  // goes to the general path.
  return out.value == out.value;
}

template <class Real, class Piece> struct PieceArcQuery {
  static constexpr bool defined = true;
  using Circle = Query<Piece, Circle3<Real>>;
  using Point = Query<Vec3<Real>, Piece>;

  template <class Roots>
  static ArcMinima<Real> solve(const ArcSpan<Real>& span, const LocalLinear<Real>& line, Real radius, Real scale) {
    const PieceOverArc<Real> piece{line};
    const auto h = [&](Real t) { return piece.distance(ArcSpan<Real>::local(radius, t)); };
    const auto jet = [&](Real t) {
      const Real cs = std::cos(t), sn = std::sin(t);
      const Vec3<Real> p(radius * cs, radius * sn, 0);
      return piece.jet(p, Vec3<Real>(-radius * sn, radius * cs, 0), Vec3<Real>(-p));
    };
    Candidates<Real, 24> candidates;
    push_piece_arc_candidates<Roots>(line, radius, scale, candidates);
    return polish_on_arc<Roots>(span, candidates, jet, h, radius, scale);
  }

  template <class Roots = DefaultRoots> static Real distance(const Piece& piece, const Arc3<Real>& arc) {
    if (whole_arc(arc)) return Circle::template distance<Roots>(piece, arc_circle(arc));
    if (!(arc.radius > 0)) return Point::template distance<Roots>(arc.center, piece);
    PieceArcPick<Real> pick;
    if (piece_arc_fast<Roots, false>(piece, arc, pick)) return pick.value;
    const Round<Real> round(arc.center, arc.normal, arc.radius);
    const LocalLinear<Real> line(as_linear(piece), round);
    return solve<Roots>(ArcSpan<Real>(arc), line, arc.radius, linear_round_scale(line, arc.radius)).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Piece& piece, const Arc3<Real>& arc) {
    const ArcSpan<Real> span(arc);
    if (whole_arc(arc)) return as_arc_result(Circle::template closest<Roots>(piece, arc_circle(arc)), span, 1);
    if (!(arc.radius > 0)) return Point::template closest<Roots>(arc.center, piece).swapped();
    PieceArcPick<Real> pick;
    const bool fast = piece_arc_fast<Roots, true>(piece, arc, pick);
    if (fast && !pick.tied) {
      Result<Real> r;
      r.distance = pick.value;
      r.point_a = pick.piece_point;
      r.param_a = Vec2<Real>(pick.piece_param, 0);
      r.point_b = pick.arc_point;
      r.param_b = Vec2<Real>(pick.arc_param, 0);
      return r;
    }
    const Round<Real> round(arc.center, arc.normal, arc.radius);
    const Linear<Real> linear = as_linear(piece);
    const LocalLinear<Real> line(linear, round);
    const Real scale = linear_round_scale(line, arc.radius);
    ArcMinima<Real> minima = solve<Roots>(span, line, arc.radius, scale);
    const PieceOverArc<Real> over{line};
    const Real best = minima.best.x;
    const auto at = [&](Real t) { return ArcSpan<Real>::local(arc.radius, t); };
    const auto piece_point_of = [&](const Vec3<Real>& q, bool&) { return over.point(q); };
    add_ends_for_ties(minima, span, [&](Real t) { return (at(t) - over.point(at(t))).norm(); });
    const Vec3<Real> pa = at(best);
    const Vec3<Real> pb = over.point(pa);
    Result<Real> r;
    // A tie the fast path saw: the general path's pair and `unique`, the fast path's distance
    // (as distance() answers it).
    r.distance = fast ? pick.value : minima.best.value;
    Real t;
    r.point_a = piece_point(linear, line, round, over.tau_of(pa), t);
    r.param_a = Vec2<Real>(t, 0);
    r.point_b = span.world(arc.center, arc.radius, best);
    r.param_b = span.param(best);
    r.unique = !another_closest_pair(minima, scale, at, piece_point_of, pa, pb,
                                     distinct_points_tolerance(std::min(scale, arc.radius)),
                                     distinct_points_tolerance(scale));
    return r;
  }
};

template <class Real> struct Query<Line3<Real>, Arc3<Real>> : PieceArcQuery<Real, Line3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Arc3<Real>> : PieceArcQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Arc3<Real>> : PieceArcQuery<Real, Segment3<Real>> {};

// ---------------------------------------------------------------------------------------------
// Circle and disk against an arc. A disk: the arc parametrized against it (circle-disk's
// candidates on the arc). A circle: the smaller of the two parametrized, as circle-circle does
// (its angle features are then never narrower than the other's): the arc against the ring, or
// the circle, whole, against the arc (ArcArcQuery).
template <class Real, class Round3> struct RoundArcQuery {
  static constexpr bool defined = true;
  using Target = target_t<Round3>;
  using Whole = Query<Circle3<Real>, Round3>;  // the arc whole: its circle against the round

  static bool round_parametrized(const Round3& round, const Arc3<Real>& arc) {
    return !Target::interior && round.radius < arc.radius;
  }

  template <class Roots = DefaultRoots> static Real distance(const Round3& round, const Arc3<Real>& arc) {
    if (whole_arc(arc)) return Whole::template distance<Roots>(arc_circle(arc), round);
    if (!(arc.radius > 0)) return Query<Vec3<Real>, Round3>::template distance<Roots>(arc.center, round);
    if (round_parametrized(round, arc)) {
      const Circle3<Real> c{round.center, round.normal, round.radius};
      return ArcArcQuery<Real>::template distance<Roots>(c, ArcSpan<Real>(c), arc);
    }
    return ArcRoundQuery<Real, Target>::template distance<Roots>(arc, round);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Round3& round, const Arc3<Real>& arc) {
    if (whole_arc(arc))
      return as_arc_result(Whole::template closest<Roots>(arc_circle(arc), round), ArcSpan<Real>(arc), 0).swapped();
    if (!(arc.radius > 0)) return Query<Vec3<Real>, Round3>::template closest<Roots>(arc.center, round).swapped();
    if (round_parametrized(round, arc)) {
      const Circle3<Real> c{round.center, round.normal, round.radius};
      return ArcArcQuery<Real>::template closest<Roots>(c, ArcSpan<Real>(c), arc, false);
    }
    return ArcRoundQuery<Real, Target>::template closest<Roots>(arc, round).swapped();
  }
};

template <class Real> struct Query<Circle3<Real>, Arc3<Real>> : RoundArcQuery<Real, Circle3<Real>> {};
template <class Real> struct Query<Disk3<Real>, Arc3<Real>> : RoundArcQuery<Real, Disk3<Real>> {};

// ---------------------------------------------------------------------------------------------
// Arc against arc: the smaller parametrized against the other (ArcArcQuery); an arc that is
// whole is a circle (Query<Circle3, Arc3>), a zero radius a point.
template <class Real> struct Query<Arc3<Real>, Arc3<Real>> {
  static constexpr bool defined = true;
  using CircleArc = Query<Circle3<Real>, Arc3<Real>>;

  static bool first_parametrized(const Arc3<Real>& a, const Arc3<Real>& b) { return a.radius <= b.radius; }

  template <class Roots = DefaultRoots> static Real distance(const Arc3<Real>& a, const Arc3<Real>& b) {
    if (whole_arc(a)) return CircleArc::template distance<Roots>(arc_circle(a), b);
    if (whole_arc(b)) return CircleArc::template distance<Roots>(arc_circle(b), a);
    if (!(a.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template distance<Roots>(a.center, b);
    if (!(b.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template distance<Roots>(b.center, a);
    return first_parametrized(a, b) ? ArcArcQuery<Real>::template distance<Roots>(arc_circle(a), ArcSpan<Real>(a), b)
                                    : ArcArcQuery<Real>::template distance<Roots>(arc_circle(b), ArcSpan<Real>(b), a);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Arc3<Real>& a, const Arc3<Real>& b) {
    if (whole_arc(a)) return as_arc_result(CircleArc::template closest<Roots>(arc_circle(a), b), ArcSpan<Real>(a), 0);
    if (whole_arc(b))
      return as_arc_result(CircleArc::template closest<Roots>(arc_circle(b), a), ArcSpan<Real>(b), 0).swapped();
    if (!(a.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template closest<Roots>(a.center, b);
    if (!(b.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template closest<Roots>(b.center, a).swapped();
    return first_parametrized(a, b)
               ? ArcArcQuery<Real>::template closest<Roots>(arc_circle(a), ArcSpan<Real>(a), b, true)
               : ArcArcQuery<Real>::template closest<Roots>(arc_circle(b), ArcSpan<Real>(b), a, true).swapped();
  }
};

}  // namespace circledist
