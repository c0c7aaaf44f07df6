// A ray or segment (or a full line) against a circle or a disk through its full line's minimum
// over the round (line_ring_minimum.hpp), the general path wherever that declines: the shared
// skeleton PieceRoundQuery, and PieceChoice, what a round's hook hands it.
#pragma once

#include "linear.hpp"
#include "../primitives.hpp"
#include "../roots.hpp"
#include "end_point.hpp"
#include "line_ring_minimum.hpp"

#include <limits>

namespace circledist::detail {

// The answer of a piece from its full line's minimum over the round (line_ring_minimum): the
// candidates and the winner. Which candidates there are is the round's own (choose_from_line:
// the line's two local minima over a ring, the plane crossing of a disk); the rest is shared
// (PieceRoundQuery).
template <class Real> struct PieceChoice {
  Line3<Real> line;                          // the full line through the piece
  LineRingMinimum<Real> global, second;      // the line's minima over the ring (second: the other local one)
  Vec3<Real> crossing = Vec3<Real>::Zero();  // a disk's: where the line meets its plane inside the rim
  enum Winner { kGlobal, kSecond, kCrossing, kEnd } winner = kGlobal;
  Real t = 0, value = std::numeric_limits<Real>::infinity();  // the end's parameter; the winner's distance
  // For closest points: another candidate as close to rounding (a mirror image, an end, a
  // continuum), so that which pair is reported and whether it is unique are the general path's
  // call. `value` is still the answer distance() gives.
  bool tied = false;
};

// Each round's hook, defined by its public header (linear_circle.hpp, linear_disk.hpp). Declared
// here because C++17 reads choose_from_line<Roots>(...) in PieceRoundQuery as a call only where
// a function template of that name is visible; the call is resolved when a query is instantiated.
template <class Roots, class Real, class Piece>
bool choose_from_line(const Piece& piece, const Circle3<Real>& c, PieceChoice<Real>& out, bool for_closest);
template <class Roots, class Real, class Piece>
bool choose_from_line(const Piece& piece, const Disk3<Real>& disk, PieceChoice<Real>& out, bool for_closest);

// A piece against a round through its full line (one bracketed root), the general path
// (LinearRoundQuery) wherever choose_from_line declines: distance() and closest() pick the same
// candidate with the same formulas. The round's hooks, overloaded on its shape:
// choose_from_line<Roots>(piece, round, choice, for_closest) (false: the general path answers;
// for_closest: mark ties, which distance() need not look for)
// and line_minimum_result(choice, round) (the Result of a winner on the line's side, not an end).
// Where the choice is `tied`, the general path reports the pair and `unique`, with the distance
// the choice found: distance() returns that value, and the two must not differ (the general
// path's own distance is as exact, but may differ in the last bits).
template <class Real, class Piece, class Target> struct PieceRoundQuery : LinearRoundQuery<Real, Piece, Target> {
  using General = LinearRoundQuery<Real, Piece, Target>;
  using Round = typename Target::Shape;

  template <class Roots = DefaultRoots> static Real distance(const Piece& piece, const Round& round) {
    PieceChoice<Real> choice;
    if (choose_from_line<Roots>(piece, round, choice, false)) return choice.value;
    return General::template distance<Roots>(piece, round);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Piece& piece, const Round& round) {
    PieceChoice<Real> choice;
    if (!choose_from_line<Roots>(piece, round, choice, true)) return General::template closest<Roots>(piece, round);
    if (choice.tied) {
      Result<Real> r = General::template closest<Roots>(piece, round);
      r.distance = choice.value;
      return r;
    }
    if (choice.winner == PieceChoice<Real>::kEnd)
      return end_point_result(piece, choice.t, round, choice.global.unit_normal);
    return line_minimum_result(choice, round);
  }
};

}  // namespace circledist::detail
