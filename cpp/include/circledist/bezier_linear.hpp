// Bezier against a line, ray or segment (Query<BezierCurve3, Line3 | Ray3 | Segment3>). Derivation:
// docs/derivations/bezier_linear.md#line; docs/derivations/bezier_linear.md#ray-and-segment.
//
// Bezier curves against lines, rays and segments: docs/derivations/bezier_linear.md.
//
// A line: in the frame whose z axis is the line's direction, centered at the curve's control
// point nearest the line (the control points' differences from it exact in the pieces,
// detail/precise_bezier.hpp), the line's parameter is eliminated by dropping z: the squared
// distance to the line is that of the curve projected onto z = 0 from the line's trace (x0, y0),
// a polynomial of degree 2n, and the curve against the line is bezier_point.hpp's curve against
// a point for the projected curve (roots of degree 2n - 1, end points, polish on the exact
// distance, pieces for far curves).
//
// A ray or a segment: a closest pair (t, s) has s inside the piece (then t is a stationary point
// of the distance to the whole line whose foot lies inside: the line's minima with the foot's
// parameter in the interval), or s at an end of the piece (the curve against that end point,
// bezier_point.hpp), or t at an end of the curve (t = 0 or 1 against the piece, in closed form,
// linear_linear.hpp). The smallest of those candidates wins; distinct tied ones make `unique`
// false (a curve lying along the piece).
#pragma once

#include "bezier_point.hpp"
#include "detail/linear.hpp"
#include "linear_linear.hpp"
#include "query.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// The curve in the frame of a line (the piece's supporting line, direction nonzero): `round`'s
// center is the control point nearest the line, its normal the line's direction; `line` the
// line there (anchor: its point nearest the center, accurate relative to its length, detail/linear.hpp);
// `target` the line as bezier_point.hpp's AxisTarget (the anchor's trace on z = 0).
template <class Real> struct CurveLineFrame {
  Round<Real> round;
  LocalLinear<Real> line;
  LocalBezier<Real> c;
  AxisTarget<Real> target;
  Real scale = 1;

  static Vec3<Real> nearest_control_point(const BezierCurve3<Real>& b, const Linear<Real>& piece) {
    const Vec3<Real> d = unit_vector(piece.direction);
    int best = 0;
    Real best_distance = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < int(b.control.cols()); ++i) {
      const Real distance = (Vec3<Real>(b.control.col(i)) - piece.origin).cross(d).squaredNorm();
      if (distance < best_distance) {
        best_distance = distance;
        best = i;
      }
    }
    return b.control.col(best);
  }

  CurveLineFrame(const BezierCurve3<Real>& b, const Linear<Real>& piece)
      : round(nearest_control_point(b, piece), piece.direction, Real(0)), line(piece, round), c(b, round) {
    target.origin = Vec3<Real>(line.anchor.x(), line.anchor.y(), 0);
    target.line = true;
    round.radius = CurveAxisSolver<Real>::reach(c, target);
    scale = std::max(bezier_round_scale(c, round.radius), std::sqrt(line.anchor.squaredNorm()));
  }

  // The foot on the line of a local point: its tau (detail/linear.hpp), and its world point.
  Real tau_of(const Vec3<Real>& local) const { return (local - line.anchor).dot(line.dir); }
  Vec3<Real> foot(Real tau) const { return round.center + (line.anchor_world + tau * line.dir_world); }
};

// A curve against a whole line.
template <class Real> struct BezierLinePair {
  static constexpr bool defined = true;
  using Solver = CurveAxisSolver<Real>;

  template <class Roots = DefaultRoots> static Real distance(const BezierCurve3<Real>& b, const Line3<Real>& l) {
    if (b.control.cols() == 0) return std::numeric_limits<Real>::infinity();
    const CurveLineFrame<Real> f(b, as_linear(l));
    return Solver::template solve<Roots>(f.c, b, f.round, f.target, f.scale).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const BezierCurve3<Real>& b, const Line3<Real>& l) {
    if (b.control.cols() == 0) return empty_curve_result<Real>();
    const CurveLineFrame<Real> f(b, as_linear(l));
    BestPiece<Real> where;
    const auto minima = Solver::template solve<Roots>(f.c, b, f.round, f.target, f.scale, &where);
    Result<Real> r;
    Vec3<Real> local;
    Solver::best_point(b, f.c, f.round, where, minima.best.x, local, r.point_a);
    const Real tau = f.tau_of(local);
    r.distance = minima.best.value;
    r.point_b = f.foot(tau);
    r.param_a = Vec2<Real>(minima.best.x, 0);
    r.param_b = Vec2<Real>(f.line.t_of(tau), 0);
    r.unique = !Solver::tied(minima, f.c, f.target, local, f.scale);
    return r;
  }
};

}  // namespace detail

template <class Real> struct Query<BezierCurve3<Real>, Line3<Real>> : detail::BezierLinePair<Real> {};

namespace detail {

// A ray or a segment moved by -p (its points only: the ray's direction stays).
template <class Real> Ray3<Real> piece_moved_by(const Ray3<Real>& r, const Vec3<Real>& p) {
  return {r.origin - p, r.direction};
}
template <class Real> Segment3<Real> piece_moved_by(const Segment3<Real>& s, const Vec3<Real>& p) {
  return {s.p0 - p, s.p1 - p};
}

// A curve against a ray or a segment: the candidates of the header comment.
template <class Real, class Piece> struct CurvePieceQuery {
  static constexpr bool defined = true;
  using Solver = CurveAxisSolver<Real>;

  struct Found {
    std::array<Result<Real>, 5> item;
    int count = 0;
    Real scale = 0;
    void add(const Result<Real>& r) { item[count++] = r; }
  };

  // The interior candidate: the best minimum of the distance to the whole line whose foot lies in
  // the piece; `unique` false when another such minimum ties with it at another point.
  template <class Roots> static void interior(const BezierCurve3<Real>& b, const Linear<Real>& linear, Found& out) {
    const CurveLineFrame<Real> f(b, linear);
    out.scale = std::max(out.scale, f.scale);
    BestPiece<Real> where;
    // Pieces of the curve are pruned on their distance to the ray or segment (clamped foot).
    const auto piece_distance = [&](const Vec3<Real>& q) {
      const Real tau = std::min(std::max(f.tau_of(q), f.line.lo), f.line.hi);
      return std::sqrt((q - f.line.at(tau)).squaredNorm());
    };
    const auto minima = Solver::template solve<Roots>(f.c, b, f.round, f.target, f.scale, &where, piece_distance, true);
    using Inside = std::decay_t<decltype(minima)>;
    Inside inside;
    for (int i = 0; i < minima.count; ++i) {
      const Real tau = f.tau_of(f.c.at(minima.item[i].x));
      if (tau >= f.line.lo && tau <= f.line.hi) inside.add(minima.item[i]);
    }
    if (inside.count == 0) return;
    Result<Real> r;
    Vec3<Real> local;
    // The piece's point where the best minimum is the whole line's (BestPiece, detail/precise_bezier.hpp).
    const bool same = where.valid && inside.best.x == minima.best.x && inside.best.value == minima.best.value;
    BestPiece<Real> none;
    Solver::best_point(b, f.c, f.round, same ? where : none, inside.best.x, local, r.point_a);
    const Real tau = std::min(std::max(f.tau_of(local), f.line.lo), f.line.hi);
    r.distance = inside.best.value;
    r.point_b = f.foot(tau);
    r.param_a = Vec2<Real>(inside.best.x, 0);
    r.param_b = Vec2<Real>(std::min(std::max(f.line.t_of(tau), linear.lo), linear.hi), 0);
    r.unique = !Solver::tied(inside, f.c, f.target, local, f.scale);
    out.add(r);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const BezierCurve3<Real>& b, const Piece& piece) {
    if (b.control.cols() == 0) return empty_curve_result<Real>();
    const Linear<Real> linear = as_linear(piece);
    Found found;
    if (linear.direction.cwiseAbs().maxCoeff() > 0) interior<Roots>(b, linear, found);
    // The curve's end points against the piece, each with the piece moved by minus the end point
    // (in world coordinates 1e6 away, the closed form's rounding of eps x 1e6 was 1e-12 of a
    // query of size 6).
    const int n = int(b.control.cols()) - 1;
    for (const int i : {0, n}) {
      const Vec3<Real> p = b.control.col(i);
      Result<Real> r =
          Query<Vec3<Real>, Piece>::template closest<Roots>(Vec3<Real>::Zero(), detail::piece_moved_by(piece, p));
      r.point_a = p;
      r.point_b = p + r.point_b;
      r.param_a = Vec2<Real>(Real(i == 0 ? 0 : 1), 0);
      found.add(r);
    }
    Real scale = found.scale;
    for (int i = 0; i <= n; ++i) scale = std::max(scale, (Vec3<Real>(b.control.col(i)) - linear.origin).norm());
    if (!(scale > 0)) scale = 1;
    const Real tie = tie_tolerance(scale), apart = distinct_points_tolerance(scale);
    const auto smallest = [&] {
      int best = 0;
      for (int i = 1; i < found.count; ++i)
        if (found.item[i].distance < found.item[best].distance) best = i;
      return best;
    };
    // The piece's end points against the curve, unless the control points' ball shows the end
    // farther than the best candidate so far (and than a tie with it).
    Vec3<Real> lo = b.control.col(0), hi = lo;
    for (int i = 1; i <= n; ++i) {
      lo = lo.cwiseMin(Vec3<Real>(b.control.col(i)));
      hi = hi.cwiseMax(Vec3<Real>(b.control.col(i)));
    }
    const Vec3<Real> center = (lo + hi) / 2;
    Real radius = 0;
    for (int i = 0; i <= n; ++i) radius = std::max(radius, (Vec3<Real>(b.control.col(i)) - center).norm());
    const auto end = [&](const Vec3<Real>& p, Real s) {
      const Real lower = (p - center).norm() - radius;
      if (lower > found.item[smallest()].distance + 2 * tie + std::numeric_limits<Real>::epsilon() * scale) return;
      Result<Real> r = Query<BezierCurve3<Real>, Vec3<Real>>::template closest<Roots>(b, p);
      r.param_b = Vec2<Real>(s, 0);
      found.add(r);
    };
    end(linear.origin, Real(0));
    if (linear.has_end) end(linear.end, Real(1));
    const int best = smallest();
    Result<Real> r = found.item[best];
    scale = std::max(scale, r.distance);
    for (int i = 0; i < found.count; ++i) {
      const Result<Real>& o = found.item[i];
      if (i == best || !(o.distance <= r.distance + tie)) continue;
      if ((o.point_a - r.point_a).norm() > apart || (o.point_b - r.point_b).norm() > apart) r.unique = false;
    }
    return r;
  }

  template <class Roots = DefaultRoots> static Real distance(const BezierCurve3<Real>& b, const Piece& piece) {
    return closest<Roots>(b, piece).distance;
  }
};

}  // namespace detail

template <class Real> struct Query<BezierCurve3<Real>, Ray3<Real>> : detail::CurvePieceQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<BezierCurve3<Real>, Segment3<Real>> : detail::CurvePieceQuery<Real, Segment3<Real>> {
};

}  // namespace circledist
