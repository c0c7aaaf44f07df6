// Line, ray and segment against a circle (Query<Line3 | Ray3 | Segment3, Circle3>). Derivation:
// docs/derivations/line_circle.md.
//
// Line, ray and segment against a circle (docs/derivations/line_circle.md). A full line is answered from the
// circle's side, by one bracketed root (detail/line_ring_minimum.hpp); a ray or segment by its
// full line's local minima and its end points where they decide (detail/piece_round_query.hpp).
// Elsewhere, the general path: note 000 §1 (the quartic), restricted to the piece's interval with
// its end points added for rays and segments (LinearRoundQuery, detail/linear.hpp).
#pragma once

#include "detail/end_point.hpp"
#include "detail/line_ring_minimum.hpp"
#include "detail/piece_line.hpp"
#include "detail/piece_round_query.hpp"
#include "detail/linear.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// The general path (LinearRoundQuery, detail/linear.hpp) on the ring target.
template <class Real, class Piece> using LinearCircleQuery = LinearRoundQuery<Real, Piece, RingTarget<Real>>;

// A full line: its minimum over the ring (line_ring_minimum); the general path where the direct
// method declines (a zero or huge direction, a zero radius, non-finite input).
template <class Real> struct LineCirclePair {
  static constexpr bool defined = true;
  using General = LinearCircleQuery<Real, Line3<Real>>;

  template <class Roots = DefaultRoots> static Real distance(const Line3<Real>& line, const Circle3<Real>& c) {
    LineRingMinimum<Real> m;
    if (!line_ring_minimum<Roots>(line, c, m)) return General::template distance<Roots>(line, c);
    return m.distance;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Line3<Real>& line, const Circle3<Real>& c) {
    LineRingMinimum<Real> m;
    if (!line_ring_minimum<Roots>(line, c, m)) return General::template closest<Roots>(line, c);
    return line_ring_result(line, c, m);
  }
};

}  // namespace detail

template <class Real> struct Query<Line3<Real>, Circle3<Real>> : detail::LineCirclePair<Real> {};

namespace detail {

// Rays and segments. A ray's or segment's distance is the least of its end points' and of the
// line's local minima that it holds: the global one m (line_ring_minimum) and, inside the
// astroid, the other (other_line_minimum). End points by point-circle's closed form. Where the
// other minimum is undecided, or where a segment is too long for the line through it
// (piece_line), the general path answers (returns false). For closest points, a minimum tied
// with its mirror image, or an end tied with another candidate, marks the answer `tied`: its
// pair and `unique` are the general path's to judge (PieceRoundQuery).
template <class Roots, class Real, class Piece>
bool choose_from_line(const Piece& piece, const Circle3<Real>& c, PieceChoice<Real>& out, bool for_closest) {
  using Choice = PieceChoice<Real>;
  const PieceLine<Real> pl = piece_line(piece, c.radius);
  out.line = pl.line;
  const LineRingMinimum<Real>& m = out.global;
  if (!pl.usable) return false;
  const Linear<Real> linear = as_linear(piece);
  // Before the root: where the line has one local minimum (the astroid test), its distance falls
  // toward that minimum on either side, so an end at which it rises along the piece is the
  // closest point of the rest (p0 of a segment, a ray's origin), and so is an end at which it
  // falls toward the piece's end (p1): those pieces need no root (docs/derivations/line_circle.md).
  SecondMinimumTest<Real> second_test;
  const auto before_root = [&](const LineRingMinimum<Real>& line_data) {
    second_test = second_minimum_test(line_data, c.radius);
    if (second_test.verdict != 0) return false;
    const Vec3<Real>& direction = out.line.direction;
    if (std::isfinite(linear.lo) &&
        end_point_slope(piece_end(piece, linear.lo), c, line_data.unit_normal, direction) > 0) {
      out.t = linear.lo;
    } else if (std::isfinite(linear.hi) &&
               end_point_slope(piece_end(piece, linear.hi), c, line_data.unit_normal, direction) < 0) {
      out.t = linear.hi;
    } else {
      return false;
    }
    out.winner = Choice::kEnd;
    out.value = end_point_distance(piece_end(piece, out.t), c, line_data.unit_normal);
    return true;
  };
  const LineRingOutcome outcome = line_ring_minimum<Roots>(out.line, c, out.global, before_root);
  if (outcome == LineRingOutcome::AnsweredBeforeRoot) return true;
  if (outcome == LineRingOutcome::Declined) return false;
  const int side = piece_side(out.line, c.center, m.line_point, linear);
  if (side == 0) {
    // The global minimum on the piece answers (tied where its mirror image is as close).
    if (for_closest) out.tied = tied_with_mirror(c, m);
    out.value = m.distance;
    return true;
  }
  // The piece's extent along the line as offsets tau from the anchor (a.m = 0), and whether it
  // reaches the second minimum's side, (0, tau_max] or [tau_max, 0) (other_line_minimum).
  const auto tau_of = [&](Real t) {
    return std::isfinite(t) ? (piece_end(piece, t) - c.center).dot(m.unit_direction) : t;
  };
  const auto may_hold = [&](Real tau_max) {
    const Real lo = tau_of(linear.lo), hi = tau_of(linear.hi);
    const Real slack = 64 * std::numeric_limits<Real>::epsilon() *
                       (std::abs(tau_max) + m.anchor.norm() + (std::isfinite(lo) ? std::abs(lo) : Real(0)) +
                        (std::isfinite(hi) ? std::abs(hi) : Real(0)));
    return tau_max > 0 ? hi >= -slack && lo <= tau_max + slack : lo <= slack && hi >= tau_max - slack;
  };
  const int other = other_line_minimum<Roots>(m, c.radius, out.second, may_hold, second_test);
  if (other < 0) return false;
  out.winner = Choice::kEnd;
  if (other == 0) {
    // One minimum, off the piece: the distance falls toward it, so the nearer end answers.
    out.t = side < 0 ? linear.lo : linear.hi;
    out.value = end_point_distance(piece_end(piece, out.t), c, m.unit_normal);
    return true;
  }
  if (other == 1 && on_piece(out.line, c.center, out.second.line_point, linear)) {
    out.winner = Choice::kSecond;
    out.value = out.second.distance;
  }
  for (const Real t : {linear.lo, linear.hi}) {
    if (!std::isfinite(t)) continue;
    const Real value = end_point_distance(piece_end(piece, t), c, m.unit_normal);
    // A tie between an end and a line minimum, or between both ends (a segment symmetric about
    // the axis), is two distinct closest pairs: `tied`, for the general path to judge `unique`.
    if (for_closest && std::abs(value - out.value) <= tie_tolerance(std::max(c.radius, value))) out.tied = true;
    if (value < out.value) {
      out.value = value;
      out.t = t;
      out.winner = Choice::kEnd;
    }
  }
  return true;
}

template <class Real> Result<Real> line_minimum_result(const PieceChoice<Real>& choice, const Circle3<Real>& c) {
  return line_ring_result(choice.line, c, choice.winner == PieceChoice<Real>::kSecond ? choice.second : choice.global);
}

template <class Real, class Piece> using PieceCircleQuery = PieceRoundQuery<Real, Piece, RingTarget<Real>>;

}  // namespace detail

template <class Real> struct Query<Ray3<Real>, Circle3<Real>> : detail::PieceCircleQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Circle3<Real>> : detail::PieceCircleQuery<Real, Segment3<Real>> {};

}  // namespace circledist
