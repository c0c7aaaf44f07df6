// Circle-arc (Query<Circle3, Arc3>), and the arc parametrized against a round that disk-arc shares.
// Derivation: docs/derivations/arc.md#a-circle-or-a-disk; docs/derivations/arc.md#an-arc.
//
// Arcs. An arc is a circle whose candidates are restricted
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
#include "detail/arc_span.hpp"
#include "detail/arc_target.hpp"
#include "detail/trig.hpp"
#include "point_arc.hpp"
#include "point_circle.hpp"
#include "point_disk.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

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
  template <class Roots> static ArcMinima<Real> solve(const ArcSpan<Real>& span, const LocalCircle<Real>& c,
                                                      Real radius, Real scale, const Heights& heights) {
    const CircleOverRound<Real> view(c, radius);
    const auto distance = [&](Real t) { return view.template distance<Target>(t); };
    const auto h = with_end_values(span, distance);
    const auto jet = [&](Real t) { return view.template jet<Target>(t); };
    if constexpr (Target::interior) {
      // Against a disk, as before: the bound from h itself, the octic searched on the whole
      // circle. Restricted to the arc's angles (as against a ring, below), the octic's roots over a
      // disk parallel to the arc's plane (rounding noise there: the distance is the planes' gap
      // over the disk) came out differently, and the continuum's `unique` with them, wrong in 4
      // of 6 changed cases (docs/derivations/arc.md, "Cost").
      return polish_on_arc<Roots>(span,
                                  CircleDisk::template candidates<Roots>(view, scale, heights, arc_bound(span, h)), jet,
                                  h, c.radius, scale);
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
  // arc; docs/derivations/arc.md, "Cost"): the disk's distance is at least the height |z| everywhere, and
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
  template <class Roots> static HeightVerdict height_verdict(const ArcSpan<Real>& span, const LocalCircle<Real>& c,
                                                             Real radius, Real scale, const Heights& heights) {
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

template <class Real> struct ArcArcQuery {
  // A (span: an arc, or a circle whole) parametrized against arc B.
  template <class Roots> static ArcMinima<Real> solve(const ArcSpan<Real>& span, const LocalCircle<Real>& c,
                                                      const ArcTarget<Real>& target, Real scale) {
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
      return e < 0 ? view.template jet<RingTarget<Real>>(cs, sn)
                   : point_jet(p, Vec3<Real>(cs * c.e2 - sn * c.e1), Vec3<Real>(-w), target.end[e]);
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

}  // namespace detail

template <class Real> struct Query<Circle3<Real>, Arc3<Real>> : detail::RoundArcQuery<Real, Circle3<Real>> {};

}  // namespace circledist
