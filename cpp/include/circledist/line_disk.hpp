// Line, ray and segment against a disk: note 000 §2, completed (derivation in docs/line_disk.md).
// The piece's projection enters and leaves the disk at the rim crossings tau1 <= tau2. Inside
// [tau1, tau2] the distance is the height |z(tau)|, linear in tau, so its minimum is at tau1,
// tau2 or the plane crossing. Outside, the disk distance is the circle distance, whose
// stationary points are roots of the note-000 quartic. The end points of the piece's own
// interval are candidates too. The exact disk distance judges every candidate.
#pragma once

#include "line_circle.hpp"
#include "linear.hpp"
#include "query.hpp"

namespace circledist {

// The general path (LinearRoundQuery, linear.hpp) on the disk target.
template <class Real, class Piece> using LinearDiskQuery = LinearRoundQuery<Real, Piece, DiskTarget<Real>>;

// A full line's distance to a disk: zero where it crosses the disk's plane inside the rim, and
// otherwise its distance to the rim circle. The distance to the line is convex over the plane and
// vanishes at the crossing, so with the crossing outside the disk (or none) its minimum over the
// disk lies on the rim; a line parallel to the plane over the disk is as close to the rim points
// under it as to any. So the line-circle solver from the circle's side answers it (one bracketed
// root). A ray or segment takes the line's answer where it holds the line's point of it (the
// crossing, or the line's closest point to the rim when the line does not cross the disk), as in
// PieceCircleQuery; elsewhere, and for closest points of a line within sqrt(eps) of parallel to
// the plane (which may touch a continuum), the general path answers.
template <class Real> struct LineDiskMinimum {
  Line3<Real> line;  // the full line through the piece
  LineRingMinimum<Real> ring;
  bool crosses = false;  // the line crosses the plane inside the rim, at `crossing`
  bool parallel = false;
  Vec3<Real> crossing = Vec3<Real>::Zero();  // relative to the center
};

template <class Roots, class Piece, class Real>
bool line_disk_minimum(const Piece& piece, const Disk3<Real>& disk, LineDiskMinimum<Real>& out) {
  const PieceLine<Real> pl = piece_line(piece, disk.radius);
  out.line = pl.line;
  if (!pl.usable || !line_ring_minimum<Roots>(out.line, Circle3<Real>{disk.center, disk.normal, disk.radius}, out.ring))
    return false;
  const LineRingMinimum<Real>& m = out.ring;
  const Real height = m.anchor.dot(m.unit_normal), slope = m.unit_direction.dot(m.unit_normal);
  out.parallel = slope == 0;
  if (!out.parallel) {
    out.crossing = m.anchor - (height / slope) * m.unit_direction;
    out.crosses = out.crossing.squaredNorm() <= disk.radius * disk.radius;
  }
  return true;
}

// The line's distance to the disk is convex (the distance to a convex set, along a line), so a
// ray or segment that does not hold the line's minimum is closest at its end nearer that
// minimum: point-disk's closed form there (strictly closest: a convex function falls strictly
// toward its minimum, so the pair is unique).
template <class Real, class Piece> struct PieceDiskQuery : LinearDiskQuery<Real, Piece> {
  using General = LinearDiskQuery<Real, Piece>;

  // The line's minimum (the crossing, or the line's point closest to the rim) as a parameter of
  // the piece: inside [lo, hi] the line's answer holds; outside, the end at `t` answers.
  static bool end_answers(const LineDiskMinimum<Real>& m, const Disk3<Real>& disk, const Linear<Real>& linear,
                          Real& t) {
    const int side = piece_side(m.line, disk.center, m.crosses ? m.crossing : m.ring.line_point, linear);
    if (side == 0) return false;
    t = side < 0 ? linear.lo : linear.hi;
    return true;
  }

  template <class Roots = DefaultRoots> static Real distance(const Piece& piece, const Disk3<Real>& disk) {
    LineDiskMinimum<Real> m;
    if (line_disk_minimum<Roots>(piece, disk, m)) {
      const Linear<Real> linear = as_linear(piece);
      Real t = 0;
      if (end_answers(m, disk, linear, t)) return end_point_distance(piece_end(piece, t), disk, m.ring.unit_normal);
      return m.crosses ? Real(0) : m.ring.distance;
    }
    return General::template distance<Roots>(piece, disk);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Piece& piece, const Disk3<Real>& disk) {
    LineDiskMinimum<Real> m;
    const Circle3<Real> rim{disk.center, disk.normal, disk.radius};
    // A line within sqrt(eps) of parallel to the plane may touch the disk along a chord, or be as
    // close to a stretch of the rim as to its closest point: the general path judges `unique`.
    if (line_disk_minimum<Roots>(piece, disk, m) &&
        std::abs(m.ring.unit_direction.dot(m.ring.unit_normal)) > std::sqrt(std::numeric_limits<Real>::epsilon())) {
      const Linear<Real> linear = as_linear(piece);
      Real t = 0;
      if (end_answers(m, disk, linear, t)) return end_point_result(piece, t, disk, m.ring.unit_normal);
      if (m.crosses) {
        // One common point: the line meets the plane once.
        Result<Real> r;
        r.distance = 0;
        r.point_a = r.point_b = disk.center + m.crossing;
        r.param_a = Vec2<Real>(line_param(m.line, disk.center, m.crossing), 0);
        r.param_b = DiskTarget<Real>::param(Frame<Real>(disk.normal).to_local(m.crossing));
        return r;
      }
      if (!tied_with_mirror(rim, m.ring)) {
        Result<Real> r = line_ring_result(m.line, rim, m.ring);
        r.param_b = Vec2<Real>(disk.radius, r.param_b.x());
        return r;
      }
    }
    return General::template closest<Roots>(piece, disk);
  }
};
template <class Real> struct Query<Line3<Real>, Disk3<Real>> : PieceDiskQuery<Real, Line3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Disk3<Real>> : PieceDiskQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Disk3<Real>> : PieceDiskQuery<Real, Segment3<Real>> {};

}  // namespace circledist
