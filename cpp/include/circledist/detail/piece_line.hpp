// A ray or segment as part of its full line: the line the fast path solves (PieceLine), where a
// point of that line lies against the piece (piece_side, on_piece), and the piece's end points.
#pragma once

#include "linear.hpp"
#include "../primitives.hpp"

namespace circledist::detail {

// A ray or segment whose full line has its minimum over the ring on the piece has that minimum
// too: the piece is part of the line, so it is no closer, and it holds the line's closest point.
// Then one bracketed root answers it, as for a full line; otherwise (or where the line's minimum
// is tied with its mirror image, either of which might be the piece's) the general path does.
// A segment's line is taken through p0 along the rounded p1 - p0, which misses p1 by about eps
// times its length: only segments shorter than 64 radii (an error below 64 eps R) take it.
template <class Real> struct PieceLine {
  Line3<Real> line;
  bool usable = true;
};
template <class Real> PieceLine<Real> piece_line(const Line3<Real>& l, Real) { return {l}; }
template <class Real> PieceLine<Real> piece_line(const Ray3<Real>& r, Real) { return {{r.origin, r.direction}}; }
template <class Real> PieceLine<Real> piece_line(const Segment3<Real>& s, Real radius) {
  const Vec3<Real> d = s.p1 - s.p0;
  return {{s.p0, d}, d.squaredNorm() <= 4096 * radius * radius};
}

// Where `point` (relative to `center`) of `line` lies against the piece: -1 before lo, 0 on
// [lo, hi], 1 after hi (its parameter compared as t |d|^2, without the division).
template <class Real>
int piece_side(const Line3<Real>& line, const Vec3<Real>& center, const Vec3<Real>& point, const Linear<Real>& piece) {
  const Real d2 = line.direction.squaredNorm();
  const Real scaled = (point - (line.origin - center)).dot(line.direction);
  return scaled < piece.lo * d2 ? -1 : scaled > piece.hi * d2 ? 1 : 0;
}
template <class Real>
bool on_piece(const Line3<Real>& line, const Vec3<Real>& center, const Vec3<Real>& point, const Linear<Real>& piece) {
  return piece_side(line, center, point, piece) == 0;
}

// A ray's or segment's end point at parameter t (the origin of a ray; p0 or p1 exactly, not
// p0 + (p1 - p0)), for the end-point answers of the pieces.
template <class Real> Vec3<Real> piece_end(const Line3<Real>& l, Real) { return l.origin; }  // never asked
template <class Real> Vec3<Real> piece_end(const Ray3<Real>& r, Real) { return r.origin; }
template <class Real> Vec3<Real> piece_end(const Segment3<Real>& s, Real t) { return t > 0 ? s.p1 : s.p0; }

}  // namespace circledist::detail
