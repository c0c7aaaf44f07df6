// An arc as an interval of its circle's canonical angle (ArcSpan), and the search every arc
// query runs on it: the candidates of the whole circle that fall on the arc and its two ends,
// polished on the exact distance (polish_on_arc). Derivation: docs/derivations/arc.md#the-arc and
// docs/derivations/arc.md#the-arc-parametrized.
#pragma once

#include "../primitives.hpp"
#include "../roots.hpp"
#include "angle_polish.hpp"
#include "atan2.hpp"
#include "minimize.hpp"
#include "trig.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist::detail {

// The octant of (x, y), from exact comparisons of the two numbers atan2(y, x) takes: that angle,
// moved into [0, 2 pi) as the arc's sector tests move it (t < 0: t + 2 pi), lies in
// [k pi/4, (k + 1) pi/4] up to atan2's error (2.5 ulp in double, detail/atan2.hpp; std::atan2's
// in other types) and the rounding of t + 2 pi, both far below octant_slack(); [lo, hi] is that
// octant widened by the slack. y < 0 is the lower half; y = -0 the upper (atan2(-0, x) is -0 or
// -pi, t then 0 or pi). False for a NaN or infinite x or y. A comparison of t with a threshold
// is decided by the octant where [lo, hi], widened by another slack for the threshold's own
// rounding, lies wholly on one side: there t answers the same (docs/derivations/arc.md, "Cost").
template <class Real> constexpr Real octant_slack() {
  return 128 * std::numeric_limits<Real>::epsilon() * 2 * pi_v<Real>();
}
template <class Real> CIRCLEDIST_INLINE bool octant_bounds(Real x, Real y, Real& lo, Real& hi) {
  if (!(std::abs(x) + std::abs(y) < std::numeric_limits<Real>::infinity())) return false;  // NaN too
  const Real quarter = pi_v<Real>() / 4, slack = octant_slack<Real>();
  const bool lower = y < 0, left = x<0, steep = std::abs(y)> std::abs(x);
  static constexpr int octants[8] = {0, 1, 3, 2, 7, 6, 4, 5};  // by 4 lower + 2 left + steep
  const int k = octants[4 * lower + 2 * left + steep];
  lo = k * quarter - slack;
  hi = (k + 1) * quarter + slack;
  return true;
}

// The arc's circle (the same fields), and whether the arc is all of it (angle >= 2 pi).
template <class Real> Circle3<Real> arc_circle(const Arc3<Real>& a) { return {a.center, a.normal, a.radius}; }
template <class Real> bool whole_arc(const Arc3<Real>& a) { return a.angle >= 2 * pi_v<Real>(); }

// An arc's interval in its circle's canonical angle (primitives.hpp, Frame: the angle every
// circle query parametrizes by): the arc's t is theta - theta0, theta0 the canonical angle of u,
// the start's projection (u = cos theta0 U + sin theta0 V, so v = N x u = cos theta0 V -
// sin theta0 U and the arc's point at t is the circle's at theta0 + t). docs/derivations/arc.md, "The arc".
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
  // offset test of polish_on_arc, as before (docs/derivations/arc.md, "Cost").
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
  Vec3<Real> world(const Vec3<Real>& center, Real radius, Real theta) const {
    return center + from_center(radius, theta);
  }
};

// The answer of a whole arc from its circle's: the arc's parameter is its t, the circle's angle
// less theta0 (`side` 0 for param_a, 1 for param_b).
template <class Real> Result<Real> as_arc_result(Result<Real> r, const ArcSpan<Real>& span, int side) {
  Vec2<Real>& p = side == 0 ? r.param_a : r.param_b;
  p = Vec2<Real>(span.param_of(p.x()), 0);
  return r;
}

// ---------------------------------------------------------------------------------------------
// The arc parametrized against another shape (docs/derivations/arc.md, "The arc parametrized").

// Room for every query's candidates: the circle's (24 at most), two end angles, and the arc's
// two ends.
constexpr int kArcCapacity = 64;
template <class Real> using ArcCandidates = Candidates<Real, kArcCapacity>;
template <class Real> using ArcMinima = Minima<Real, kArcCapacity>;

// The least distance h reaches at the arc's ends and angles between them spaced at most pi/4
// apart (a whole circle: eight, as circle-circle samples it): a distance the arc reaches, the
// bound its circle's octic is searched under (ring_search_intervals; the tighter it is, the
// fewer intervals searched). The whole circle's own samples (sampled_distances) may lie off the
// arc. Against a disk (ArcRoundQuery). docs/derivations/arc.md, "Cost".
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
// The whole circle's best sample may lie off the arc. docs/derivations/arc.md, "Cost".
template <class Real, class H, class Sample>
Real arc_bound(const ArcSpan<Real>& span, const H& h, const Sample& sample) {
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
// arc with its ends start every basin the arc holds (docs/derivations/arc.md, "Why no samples").
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

}  // namespace circledist::detail
