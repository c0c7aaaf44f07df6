// Bezier-point (Query<BezierCurve3, Vec3>). Derivation: docs/derivations/bezier_linear.md#point.
//
// Bezier curves (degree 1 to 7, t in [0, 1]) against a point, and the machinery the curve's
// queries against a line, ray or segment share with it (bezier_linear.hpp): docs/derivations/bezier_linear.md.
//
// Against a point (the local origin, the point subtracted from the control points first) the
// squared distance |q(t)|^2 is a polynomial of degree 2n; its stationary points are the roots of
// q . q' (degree 2n - 1), written in the power basis of w = 2t - 1 (LocalBezier::coordinate,
// detail/local_bezier.hpp). Against a line parallel to the local z axis the curve is first
// projected onto the plane z = 0 and moved so that the line passes through the origin: the
// distance to the line is the projected curve's distance to the origin, the same equation.
// Candidates: t = 0, t = 1 and the roots in [0, 1], each polished on the exact distance
// (detail/minimize.hpp); the smallest wins.
//
// A curve far larger than its distance to the target (one control point 1e10 away, the curve
// passing 1e-21 from the point at t = 5e-11) is cut into pieces by the curves' branch and bound
// (CurveRoundBase::solve_pieces in detail/curve_round_base.hpp, blossoms in double-double): the
// target is given the size of the curve's end points' distances to it, which is what the whole
// curve is solved in when it is of their size.
#pragma once

#include "detail/curve_roots.hpp"
#include "detail/curve_round_base.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// The local origin as the target of the curves' machinery (LocalBezier::jet): the
// squared distance |P|^2 and its derivatives 2 P.P', 2 (|P'|^2 + P.P'').
template <class Real> struct PointTarget {
  static constexpr bool interior = false;
  using Shape = Vec3<Real>;
  static Real distance(const Vec3<Real>& p, Real) { return std::sqrt(p.squaredNorm()); }
  static Jet<Real> jet(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2, Real) {
    return {p.squaredNorm(), 2 * p.dot(p1), 2 * (p1.squaredNorm() + p.dot(p2))};
  }
};

// What a curve is measured against, in its local frame: the origin (`line` false), or the line
// through `origin` parallel to the local z axis (`line` true; origin.z() = 0). offset(q) is the
// vector from the target's nearest point to q.
template <class Real> struct AxisTarget {
  Vec3<Real> origin = Vec3<Real>::Zero();
  bool line = false;

  Vec3<Real> offset(const Vec3<Real>& q) const {
    Vec3<Real> o = q - origin;
    if (line) o.z() = 0;
    return o;
  }
  Real distance(const Vec3<Real>& q) const { return std::sqrt(offset(q).squaredNorm()); }
  Vec3<Real> nearest(const Vec3<Real>& q) const { return line ? Vec3<Real>(origin.x(), origin.y(), q.z()) : origin; }

  // A curve's local control points moved into the target's own frame: the point query is then
  // the moved curve against the origin.
  LocalBezier<Real> moved(const LocalBezier<Real>& c) const {
    std::array<Vec3<Real>, kMaxBezierDegree + 1> q{};
    for (int i = 0; i <= c.n; ++i) q[i] = offset(c.q[i]);
    return LocalBezier<Real>(q, c.n);
  }
};

// The roots of q . q' (degree 2n - 1 in w) for a curve measured against the origin.
template <class Roots, class Real, int N>
void push_curve_point_roots(const LocalBezier<Real>& c, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> x = c.coordinate(0, scale), y = c.coordinate(1, scale), z = c.coordinate(2, scale);
  push_curve_roots<Roots>(x * x.derivative() + y * y.derivative() + z * z.derivative(), out);
}

template <class Real> struct CurveAxisSolver : CurveRoundBase<Real> {
  using Base = CurveRoundBase<Real>;
  using Found = typename Base::Found;

  // The size the branch and bound gives the target (a round's radius in detail/curve_round_query.hpp). A curve is cut
  // into pieces only when it reaches far beyond its end points (2^20 times farther than they lie
  // from each other and from the target: a control point 1e10 away, the curve back next to the
  // target): it is then halved down to pieces of that size next to the target, where the whole
  // curve's rounding would be eps times its reach. Otherwise the curve is one piece (the reach is
  // its size): its rounding is eps times its own size, and cutting it would gain nothing, while
  // a curve running along the target (a line nearly along a segment-like curve, a loop through
  // a point) would keep every piece alive in the bound and exhaust the cap on pieces next to
  // t = 0 before reaching its minimum. Ends within 2^-40 of the size of each other and of the
  // target (a closed loop through the point) count as such a curve too.
  static Real reach(const LocalBezier<Real>& c, const AxisTarget<Real>& target) {
    const Real ends =
        std::max({target.distance(c.q[0]), target.distance(c.q[c.n]), std::sqrt((c.q[c.n] - c.q[0]).squaredNorm())});
    return ends >= std::ldexp(c.size, -40) && c.size > std::ldexp(ends, 20) ? ends : c.size;
  }

  // The minima of the distance to `target` over the curve (its local control points `c` in
  // `round`'s frame; the round's radius is reach()); the scale of tolerances is a round's (bezier_round_scale).
  // `bound_of(q)`, the distance of a local point that the pieces' branch and bound prunes on:
  // the target's own (the default) or, for a ray or a segment, the piece's, whose closest pair is
  // sought among the line's minima. `every_minimum` polishes every candidate (no screening on
  // the best value so far, CurveRoundBase::polish): a ray or a segment needs the line's local minima
  // whose foot lies in the piece, not only the line's best one.
  template <class Roots> static Found solve(const LocalBezier<Real>& c, const BezierCurve3<Real>& b,
                                            const Round<Real>& round, const AxisTarget<Real>& target, Real scale,
                                            BestPiece<Real>* where = nullptr) {
    return solve<Roots>(
        c, b, round, target, scale, where, [&](const Vec3<Real>& q) { return target.distance(q); }, false);
  }

  template <class Roots, class BoundOf> static Found solve(const LocalBezier<Real>& c, const BezierCurve3<Real>& b,
                                                           const Round<Real>& round, const AxisTarget<Real>& target,
                                                           Real scale, BestPiece<Real>* where, const BoundOf& bound_of,
                                                           bool every_minimum) {
    return Base::solve_pieces(
        c, b, round, scale, bound_of,
        [&](const LocalBezier<Real>& piece, Real) {
          const LocalBezier<Real> m = target.moved(piece);
          const Real s = bezier_round_scale(m, Real(0));
          typename Base::Starts starts;
          starts.push(Real(0));
          starts.push(Real(1));
          push_curve_point_roots<Roots>(m, s, starts);
          const auto h = [&](Real t) { return PointTarget<Real>::distance(m.at(t), Real(0)); };
          const auto jet = [&](Real t) { return m.template jet<PointTarget<Real>>(t, Real(0)); };
          if (!every_minimum) return Base::template polish<Roots>(m, starts, s, h, jet);
          return polish_offsets<Roots>(jet, h, starts, Real(1e-3), Real(0), Real(1), parameter_tolerance(m.speed, s),
                                       std::numeric_limits<Real>::infinity());
        },
        where);
  }

  // The best minimum's point on the curve, local and world (from its piece when the curve was
  // cut: BestPiece, detail/precise_bezier.hpp).
  static void best_point(const BezierCurve3<Real>& b, const LocalBezier<Real>& c, const Round<Real>& round,
                         const BestPiece<Real>& where, Real t, Vec3<Real>& local, Vec3<Real>& world) {
    local = where.valid ? where.piece.at(where.s) : c.at(t);
    world = where.valid ? round.world(local) : b.at(t);
  }

  // Whether the minima hold another closest pair (detail/minimize.hpp's another_closest_pair).
  template <int N> static bool tied(const Minima<Real, N>& minima, const LocalBezier<Real>& c,
                                    const AxisTarget<Real>& target, const Vec3<Real>& pa, Real scale) {
    const auto other = [&](const Vec3<Real>& q, bool&) { return target.nearest(q); };
    return another_closest_pair(
        minima, scale, [&](Real x) { return c.at(x); }, other, pa, target.nearest(pa),
        distinct_points_tolerance(std::min(scale, c.size)), distinct_points_tolerance(scale));
  }
};

// A curve against a point: the point is the local origin (Round centered there, the frame of
// the z axis: a permutation, exact).
template <class Real> struct BezierPointPair {
  static constexpr bool defined = true;
  using Solver = CurveAxisSolver<Real>;

  struct Setup {
    Round<Real> round;
    LocalBezier<Real> c;
    AxisTarget<Real> target;
    Real scale;
    Setup(const BezierCurve3<Real>& b, const Vec3<Real>& p)
        : round(p, Vec3<Real>(0, 0, 1), Real(0)), c(b, round), target(), scale(0) {
      round.radius = Solver::reach(c, target);
      scale = bezier_round_scale(c, round.radius);
    }
  };

  template <class Roots = DefaultRoots> static Real distance(const BezierCurve3<Real>& b, const Vec3<Real>& p) {
    if (b.control.cols() == 0) return std::numeric_limits<Real>::infinity();
    const Setup s(b, p);
    return Solver::template solve<Roots>(s.c, b, s.round, s.target, s.scale).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const BezierCurve3<Real>& b, const Vec3<Real>& p) {
    if (b.control.cols() == 0) return empty_curve_result<Real>();
    const Setup s(b, p);
    BestPiece<Real> where;
    const auto minima = Solver::template solve<Roots>(s.c, b, s.round, s.target, s.scale, &where);
    Result<Real> r;
    Vec3<Real> local;
    Solver::best_point(b, s.c, s.round, where, minima.best.x, local, r.point_a);
    r.distance = minima.best.value;
    r.point_b = p;
    r.param_a = Vec2<Real>(minima.best.x, 0);
    r.param_b = Vec2<Real>::Zero();
    r.unique = !Solver::tied(minima, s.c, s.target, local, s.scale);
    return r;
  }
};

}  // namespace detail

template <class Real> struct Query<BezierCurve3<Real>, Vec3<Real>> : detail::BezierPointPair<Real> {};

}  // namespace circledist
