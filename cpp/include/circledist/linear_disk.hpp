// Line, ray and segment against a disk (Query<Line3 | Ray3 | Segment3, Disk3>). Derivation:
// docs/derivations/line_disk.md.
//
// Line, ray and segment against a disk: note 000 §2, completed (derivation in docs/derivations/line_disk.md).
// The piece's projection enters and leaves the disk at the rim crossings tau1 <= tau2. Inside
// [tau1, tau2] the distance is the height |z(tau)|, linear in tau, so its minimum is at tau1,
// tau2 or the plane crossing. Outside, the disk distance is the circle distance, whose
// stationary points are roots of the note-000 quartic. The end points of the piece's own
// interval are candidates too. The exact disk distance judges every candidate.
#pragma once

#include "detail/end_point.hpp"
#include "detail/line_ring_minimum.hpp"
#include "detail/piece_line.hpp"
#include "detail/piece_round_query.hpp"
#include "detail/linear.hpp"
#include "query.hpp"

#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// The general path (LinearRoundQuery, detail/linear.hpp) on the disk target.
template <class Real, class Piece> using LinearDiskQuery = LinearRoundQuery<Real, Piece, DiskTarget<Real>>;

// The disk's rim, the circle line_ring_minimum answers a line against.
template <class Real> Circle3<Real> disk_rim(const Disk3<Real>& disk) {
  return {disk.center, disk.normal, disk.radius};
}

// A full line's distance to a disk: zero where it crosses the disk's plane inside the rim, and
// otherwise its distance to the rim circle. The distance to the line is convex over the plane and
// vanishes at the crossing, so with the crossing outside the disk (or none) its minimum over the
// disk lies on the rim; a line parallel to the plane over the disk is as close to the rim points
// under it as to any. So the line-circle solver from the circle's side answers it (one bracketed
// root). A ray or segment takes the line's answer where it holds the line's point of it (the
// crossing, or the line's closest point to the rim when the line does not cross the disk), as
// against a circle (PieceRoundQuery, detail/piece_round_query.hpp); elsewhere the general path
// answers (returns false). For closest points, a line within sqrt(eps) of parallel to the plane
// (which may touch a continuum) or a rim minimum tied with its mirror image marks the answer
// `tied`: its pair and `unique` are the general path's to judge.
// The line's distance to the disk is convex (the distance to a convex set, along a line), so a
// ray or segment that does not hold the line's minimum is closest at its end nearer that
// minimum: point-disk's closed form there (strictly closest: a convex function falls strictly
// toward its minimum, so the pair is unique).
template <class Roots, class Real, class Piece>
bool choose_from_line(const Piece& piece, const Disk3<Real>& disk, PieceChoice<Real>& out, bool for_closest) {
  using Choice = PieceChoice<Real>;
  const PieceLine<Real> pl = piece_line(piece, disk.radius);
  out.line = pl.line;
  if (!pl.usable || !line_ring_minimum<Roots>(out.line, disk_rim(disk), out.global)) return false;
  const LineRingMinimum<Real>& m = out.global;
  const Real height = m.anchor.dot(m.unit_normal), slope = m.unit_direction.dot(m.unit_normal);
  bool crosses = false;  // the line crosses the plane inside the rim, at out.crossing
  if (slope != 0) {
    out.crossing = m.anchor - (height / slope) * m.unit_direction;
    crosses = out.crossing.squaredNorm() <= disk.radius * disk.radius;
  }
  // A line within sqrt(eps) of parallel to the plane may touch the disk along a chord, or be as
  // close to a stretch of the rim as to its closest point: `tied`, the general path judges `unique`.
  if (for_closest && !(std::abs(slope) > std::sqrt(std::numeric_limits<Real>::epsilon()))) out.tied = true;
  // The line's minimum (the crossing, or the line's point closest to the rim) as a parameter of
  // the piece: inside [lo, hi] the line's answer holds; outside, the nearer end answers.
  const Linear<Real> linear = as_linear(piece);
  const int side = piece_side(out.line, disk.center, crosses ? out.crossing : m.line_point, linear);
  if (side != 0) {
    out.winner = Choice::kEnd;
    out.t = side < 0 ? linear.lo : linear.hi;
    out.value = end_point_distance(piece_end(piece, out.t), disk, m.unit_normal);
    return true;
  }
  if (crosses) {
    out.winner = Choice::kCrossing;
    out.value = 0;
    return true;
  }
  if (for_closest && tied_with_mirror(disk_rim(disk), m)) out.tied = true;
  out.value = m.distance;
  return true;
}

template <class Real> Result<Real> line_minimum_result(const PieceChoice<Real>& choice, const Disk3<Real>& disk) {
  if (choice.winner == PieceChoice<Real>::kCrossing) {
    // One common point: the line meets the plane once.
    Result<Real> r;
    r.distance = 0;
    r.point_a = r.point_b = disk.center + choice.crossing;
    r.param_a = Vec2<Real>(line_param(choice.line, disk.center, choice.crossing), 0);
    r.param_b = DiskTarget<Real>::param(Frame<Real>(disk.normal).to_local(choice.crossing));
    return r;
  }
  // A rim point: (s, theta) = (R, theta).
  Result<Real> r = line_ring_result(choice.line, disk_rim(disk), choice.global);
  r.param_b = Vec2<Real>(disk.radius, r.param_b.x());
  return r;
}

template <class Real, class Piece> using PieceDiskQuery = PieceRoundQuery<Real, Piece, DiskTarget<Real>>;

}  // namespace detail

template <class Real> struct Query<Line3<Real>, Disk3<Real>> : detail::PieceDiskQuery<Real, Line3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Disk3<Real>> : detail::PieceDiskQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Disk3<Real>> : detail::PieceDiskQuery<Real, Segment3<Real>> {};

}  // namespace circledist
