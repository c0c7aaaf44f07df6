// What every query of a Bezier curve shares (curve_round_query.hpp against rings and disks, bezier_point.hpp
// and bezier_linear.hpp against points and the pieces): the polish of its candidates on the exact
// distance, the branch and bound that cuts a far-reaching curve into pieces, and its Results.
#pragma once

#include "angle_polish.hpp"
#include "local_bezier.hpp"
#include "precise_bezier.hpp"
#include "round_target.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace circledist::detail {

// As circle_round_result, for a curve parameter t in [0, 1], against a target given by its
// closest point and parameter (target_side_result, round_target.hpp: a round's, an arc's).
// A curve solved in pieces reports its point from the best piece (`where`), in local and in world
// coordinates: plain evaluation at t errs by eps times its farthest control point.
template <class Real, int N, class PointOf, class ParamOf>
Result<Real> curve_target_result(const BezierCurve3<Real>& b, const LocalBezier<Real>& c, const Round<Real>& round,
                                 const BestPiece<Real>& where, const Minima<Real, N>& minima, Real scale,
                                 const PointOf& point_of, const ParamOf& param_of) {
  const Minimum<Real>& best = minima.best;
  const Vec3<Real> pa = where.valid ? where.piece.at(where.s) : c.at(best.x);
  Result<Real> r = target_side_result(
      minima, [&](Real x) { return c.at(x); }, pa, round, scale, distinct_points_tolerance(std::min(scale, c.size)),
      point_of, param_of);
  r.point_a = where.valid ? round.world(pa) : b.at(best.x);
  r.param_a = Vec2<Real>(best.x, 0);
  return r;
}

// Against a round (Target: round_target.hpp).
template <class Target, class Real, int N>
Result<Real> curve_round_result(const BezierCurve3<Real>& b, const LocalBezier<Real>& c, const Round<Real>& round,
                                const BestPiece<Real>& where, const Minima<Real, N>& minima, Real scale) {
  return curve_target_result(
      b, c, round, where, minima, scale,
      [&](const Vec3<Real>& p, bool& ambiguous) { return Target::point(p, round.radius, scale, ambiguous); },
      [](const Vec3<Real>& q) { return Target::param(q); });
}

template <class Real> Result<Real> empty_curve_result() {
  Result<Real> r;
  r.distance = std::numeric_limits<Real>::infinity();
  r.unique = false;
  return r;
}

template <class Real> struct CurveRoundBase {
  // 2 end points + 6n-2 + 2n + n + (n-1) roots for a disk: 69 at degree 7 (a circle: 6n-2 + n + (n-1));
  // an arc, a circle's and its two ends' 2n-1 each (bezier_arc.hpp): 2 + 8n-3 + 2 (2n-1) = 81.
  using Starts = Candidates<Real, 84>;
  using Found = Minima<Real, Starts::capacity>;

  template <class Roots, class H, class J>
  static Found polish(const LocalBezier<Real>& c, const Starts& starts, Real scale, const H& h, const J& jet) {
    return polish_offsets<Roots>(jet, h, starts, Real(1e-3), Real(0), Real(1), parameter_tolerance(c.speed, scale),
                                 screening_margin(scale));
  }

  // Minima over a piece's parameter s, moved to the curve's t = t0 + s (t1 - t0) (the whole
  // curve, t0 = 0 and t1 = 1, unchanged).
  static Found on_span(const Found& piece_minima, Real t0, Real t1) {
    Found found = piece_minima;
    if (t0 == 0 && t1 == 1) return found;
    for (int i = 0; i < found.count; ++i) found.item[i].x = t0 + found.item[i].x * (t1 - t0);
    found.best.x = t0 + found.best.x * (t1 - t0);
    return found;
  }

  // A curve far larger than the round (1e5 times, or one control point 1e10 away) cannot be
  // solved as a whole: in units of its own size the round is a speck, and the polynomials'
  // roots near it are lost to rounding (a relative error of 1e-2, or the minimum missed). So the
  // curve is cut into pieces, each small next to max(radius, its distance to the round), and
  // each piece is solved in its own variable and scale. Branch and bound: a piece's control
  // points hold it (convex hull), so its ball's center's distance minus the ball's radius bounds
  // its distance from below, and pieces that cannot beat an end point already seen are dropped.
  // A curve of the round's size is one piece: the whole curve, solved as before.
  // `distance_of(p)` is the exact distance of a local point; `solve_piece(piece, scale)` the
  // minima over one piece (parameter s in [0, 1], mapped here to t = t0 + s (t1 - t0)). The
  // pieces are cut from the curve in double-double (PreciseBezier); `where` (optional) receives
  // the piece and parameter of the best minimum.
  template <class DistanceOf, class SolvePiece>
  static Found solve_pieces(const LocalBezier<Real>& c, const BezierCurve3<Real>& b, const Round<Real>& round,
                            Real scale, const DistanceOf& distance_of, const SolvePiece& solve_piece,
                            BestPiece<Real>* where) {
    const Real radius = round.radius;
    // Halving stops where t no longer splits (about 1075 levels next to t = 0: a control point
    // 1e300 times farther than the round is reached in about 1000). At most 64 pieces are
    // solved; past that every remaining piece is solved as it is.
    constexpr int kPieceRatio = 4, kMaxPieces = 64;
    struct Span {
      Real t0, t1;
    };
    const auto ball = [](const LocalBezier<Real>& p, Vec3<Real>& center) {
      Vec3<Real> lo = p.q[0], hi = p.q[0];
      for (int i = 1; i <= p.n; ++i) {
        lo = lo.cwiseMin(p.q[i]);
        hi = hi.cwiseMax(p.q[i]);
      }
      center = (lo + hi) / 2;
      Real r = 0;
      for (int i = 0; i <= p.n; ++i) r = std::max(r, (p.q[i] - center).norm());
      return r;
    };
    Vec3<Real> center;
    const Real whole = ball(c, center);
    if (!(whole > kPieceRatio * std::max(radius, distance_of(center) - whole))) return solve_piece(c, scale);
    const PreciseBezier<Real> precise(b, round);
    Found out;
    Real upper = std::min(distance_of(c.q[0]), distance_of(c.q[c.n]));
    std::vector<Span> stack{{Real(0), Real(1)}};  // on the heap: deep for extreme curves only
    int pieces = 0;
    while (!stack.empty()) {
      const Span span = stack.back();
      stack.pop_back();
      const PreciseBezier<Real> precise_piece = precise.piece(span.t0, span.t1);
      const LocalBezier<Real> piece(precise_piece.rounded(), c.n);
      const Real r = ball(piece, center);
      const Real lower = distance_of(center) - r;
      if (lower > upper + tie_tolerance(std::max(scale, upper))) continue;
      upper = std::min(upper, std::min(distance_of(piece.q[0]), distance_of(piece.q[piece.n])));
      const Real mid = (span.t0 + span.t1) / 2;
      if (r > kPieceRatio * std::max(radius, lower) && pieces < kMaxPieces && mid > span.t0 && mid < span.t1) {
        stack.push_back({mid, span.t1});
        stack.push_back({span.t0, mid});
        continue;
      }
      ++pieces;
      const Found found = solve_piece(piece, bezier_round_scale(piece, radius));
      if (found.best.value < out.best.value && where) *where = {precise_piece, found.best.x, true};
      const Found on_curve = on_span(found, span.t0, span.t1);
      for (int i = 0; i < on_curve.count; ++i) out.add(on_curve.item[i]);
      if (on_curve.best.value < out.best.value) out.best = on_curve.best;
    }
    return out;
  }
};

}  // namespace circledist::detail
