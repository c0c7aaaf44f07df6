// Bezier-arc (Query<BezierCurve3, Arc3>). Derivation: docs/derivations/arc.md#a-bezier-curve.
//
// Bezier curves against arcs. The curve is parametrized against the arc as the target of a moving
// point (ArcTarget, detail/arc_target.hpp), in the arc's circle's frame: its distance from a point
// is the ring's where the point's angle falls on the arc, else the nearer end's. So a minimum of
// the curve's distance to the arc is an end of the curve, a stationary point of the ring distance
// (the Bezier-circle candidates: note 001 eq. (2) squared and z z' = 0, detail/curve_round_query.hpp), or a
// stationary point of the distance to one of the arc's ends E ((q - E).q' = 0, degree 2n - 1,
// bezier_point.hpp); where the two forms meet the distance is C^1 (both have the gradient (P - E) /
// |P - E|), so a minimum there is a root of the ring's equation too. Every candidate is polished on
// the exact arc distance, and the far-reaching curve is cut into pieces by the curves' branch and
// bound (CurveRoundBase), as against a circle. An arc of angle 2 pi is its circle (Bezier-circle's
// answer, to the bit), a zero radius its center (Bezier-point's).
#pragma once

#include "bezier_circle.hpp"
#include "bezier_point.hpp"
#include "detail/arc_span.hpp"
#include "detail/arc_target.hpp"
#include "point_arc.hpp"
#include "query.hpp"

#include <limits>

namespace circledist {

namespace detail {

// The arc's exact distance from a local point and its square's jet along a curve (docs/derivations/arc.md,
// "A Bezier curve"): the ring's form where the point's angle lies on the arc, else the nearer
// end's (point_jet).
template <class Real> Real arc_target_distance(const ArcTarget<Real>& target, const Vec3<Real>& p) {
  const int e = target.nearest_end(p);
  return e < 0 ? RingTarget<Real>::distance(p, target.radius) : (p - target.end[e]).norm();
}
template <class Real> Jet<Real> arc_target_jet(const ArcTarget<Real>& target, const Vec3<Real>& p, const Vec3<Real>& p1,
                                               const Vec3<Real>& p2) {
  const int e = target.nearest_end(p);
  return e < 0 ? RingTarget<Real>::jet(p, p1, p2, target.radius) : point_jet(p, p1, p2, target.end[e]);
}

template <class Real> struct BezierArcPair : CurveRoundBase<Real> {
  static constexpr bool defined = true;
  using Base = CurveRoundBase<Real>;
  using CurveCircle = Query<BezierCurve3<Real>, Circle3<Real>>;
  using CurvePoint = Query<BezierCurve3<Real>, Vec3<Real>>;

  // The minima over the curve (its local control points `c` in the arc's circle's frame `round`).
  // Each piece's candidates: the circle's (push_curve_round_candidates, the ends t = 0 and 1
  // among them) and each arc end's stationary points (its point query's equation on the piece
  // moved to the end: AxisTarget).
  template <class Roots> static typename Base::Found solve(const LocalBezier<Real>& c, const BezierCurve3<Real>& b,
                                                           const Round<Real>& round, const ArcTarget<Real>& target,
                                                           Real scale, BestPiece<Real>* where = nullptr) {
    const auto distance_of = [&](const Vec3<Real>& p) { return arc_target_distance(target, p); };
    return Base::solve_pieces(
        c, b, round, scale, distance_of,
        [&](const LocalBezier<Real>& piece, Real s) {
          typename Base::Starts starts;
          push_curve_round_candidates<Roots, RingTarget<Real>>(piece, target.radius, s, starts);
          for (const Vec3<Real>& e : target.end) {
            AxisTarget<Real> end;
            end.origin = e;
            push_curve_point_roots<Roots>(end.moved(piece), s, starts);
          }
          const auto h = [&](Real t) { return distance_of(piece.at(t)); };
          const auto jet = [&](Real t) {
            return piece.jet_of(t, [&](const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2) {
              return arc_target_jet(target, p, p1, p2);
            });
          };
          return Base::template polish<Roots>(piece, starts, s, h, jet);
        },
        where);
  }

  template <class Roots = DefaultRoots> static Real distance(const BezierCurve3<Real>& b, const Arc3<Real>& arc) {
    if (whole_arc(arc)) return CurveCircle::template distance<Roots>(b, arc_circle(arc));
    if (!(arc.radius > 0)) return CurvePoint::template distance<Roots>(b, arc.center);
    if (b.control.cols() == 0) return std::numeric_limits<Real>::infinity();
    const Round<Real> round(arc.center, arc.normal, arc.radius);
    const LocalBezier<Real> c(b, round);
    return solve<Roots>(c, b, round, ArcTarget<Real>(arc), bezier_round_scale(c, arc.radius)).best.value;
  }

  template <class Roots = DefaultRoots>
  static Result<Real> closest(const BezierCurve3<Real>& b, const Arc3<Real>& arc) {
    if (whole_arc(arc))
      return as_arc_result(CurveCircle::template closest<Roots>(b, arc_circle(arc)), ArcSpan<Real>(arc), 1);
    if (!(arc.radius > 0)) return CurvePoint::template closest<Roots>(b, arc.center);
    if (b.control.cols() == 0) return empty_curve_result<Real>();
    const Round<Real> round(arc.center, arc.normal, arc.radius);
    const LocalBezier<Real> c(b, round);
    const ArcTarget<Real> target(arc);
    const Real scale = bezier_round_scale(c, arc.radius);
    BestPiece<Real> where;
    const auto minima = solve<Roots>(c, b, round, target, scale, &where);
    return curve_target_result(
        b, c, round, where, minima, scale,
        [&](const Vec3<Real>& p, bool& ambiguous) { return target.point(p, scale, ambiguous); },
        [&](const Vec3<Real>& q) { return target.param(q); });
  }
};

}  // namespace detail

template <class Real> struct Query<BezierCurve3<Real>, Arc3<Real>> : detail::BezierArcPair<Real> {};

}  // namespace circledist
