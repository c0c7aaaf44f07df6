// Lines, rays and segments whose defining points (origins, segment ends) lie far from where they
// pass each other: their candidates evaluated from exact differences of the inputs in
// double-double (linear_linear.hpp takes this pass where its closed forms' rounding could exceed
// about 1e3 eps of the answer).
#pragma once

#include "linear.hpp"
#include "double_double.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace circledist::detail {

// The closed forms of linear_linear.hpp lose eps times the pieces' own offsets: w = p - q rounds
// by eps |w|, and w + s u - t v by eps (|w| + |s u| + |t v|). Where a line's origin, a ray's
// origin or a segment's ends lie far (1e10) from where the pieces pass each other, that is far
// more than a small distance between them (a point 6e-9 from a segment whose ends are 1e11 and
// 1e8 away came out 1.7e-5). The pieces themselves are exact (their defining points and
// directions are the inputs), so the answer is not ill-posed: here the candidates that may be the
// least are evaluated from exact differences of the inputs in double-double. What is left is
// about eps^2 times the offsets (absolute: 1e-21 for an origin 1e11 away), not eps times them.

// The candidates of linear_pair_scaled (linear_linear.hpp), as bits of `contenders`; the interior
// point has none (exact_pair always weighs it), and kExactPass marks a request for the pass even
// where the interior point alone contends.
enum LinearCandidate : unsigned { kEndALo = 1, kEndAHi = 2, kEndBLo = 4, kEndBHi = 8, kAnyPoint = 16, kExactPass = 32 };

// Past this ratio of a candidate's offsets (their 1-norms) to the distance, the closed forms'
// rounding (about 4 eps of the offsets) may exceed 1024 eps of the distance, and the candidates
// that may be the least are evaluated by this pass.
constexpr int kExactPassRatio = 256;

// A piece with its direction held exactly: a segment's p1 - p0 (rounded in Linear::direction)
// as a double-double, scaled by the same power of two as the piece (unit_scaled).
template <class Real> struct ExactPiece {
  using DD = DoubleDouble<Real>;
  const Linear<Real>& piece;
  std::array<DD, 3> dir;
  ExactPiece(const Linear<Real>& scaled, const Linear<Real>& original, int exponent) : piece(scaled) {
    for (int i = 0; i < 3; ++i) {
      const DD d = original.has_end ? DD::two_sum(original.end[i], -original.origin[i]) : DD(original.direction[i]);
      dir[i] = DD(std::ldexp(d.hi, -exponent), std::ldexp(d.lo, -exponent));
    }
  }
  bool is_point() const { return !(dir[0].hi != 0 || dir[1].hi != 0 || dir[2].hi != 0); }
  Real dir_size() const { return std::abs(dir[0].hi) + std::abs(dir[1].hi) + std::abs(dir[2].hi); }
  // origin + s dir, to about eps^2 of the coordinates, for a parameter held as a double-double
  // (a quotient): rounding s first would move the point by eps |s dir| along the piece (1e-10 at
  // 1e6), which a small distance to it turns into (eps |s dir|)^2 / 2d more.
  DoubleDouble3<Real> exact_at(const DD& s) const {
    return {DD(piece.origin[0]) + dir[0] * s, DD(piece.origin[1]) + dir[1] * s, DD(piece.origin[2]) + dir[2] * s};
  }
  // The point at a parameter of Real, rounded once (a segment's far end is its own p1).
  Vec3<Real> at(Real s) const { return piece.has_end && s == piece.hi ? piece.end : rounded(exact_at(DD(s))); }
};

// The length of a rounded offset, without squares that underflow or overflow: in a scene the
// front end scaled down from near the largest doubles (a point 1 from a ray whose origin lies
// 1.5e308 away), the offset between the pieces is subnormal (1e-308), and its square would be 0.
template <class Real> Real rounded_norm(const DoubleDouble3<Real>& x) { return rounded(x).stableNorm(); }

// The point x against a piece: the projection's parameter compared with the interval's ends in
// double-double ((x - o).d against lo |d|^2: the sign of a small difference of large terms), the
// distance as |(x - o) x d| / |d| (to about eps^2 of |x - o|, however far o lies along the piece), or
// the end's exact offset.
template <class Real>
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline, cold))  // rare: kept out of the plain path's code
#endif
LinearPair<Real>
point_to_exact_piece(const Vec3<Real>& x, const ExactPiece<Real>& b) {
  using DD = DoubleDouble<Real>;
  const Linear<Real>& l = b.piece;
  LinearPair<Real> out;
  out.point_a = x;
  const DoubleDouble3<Real> e = exact_difference<Real>(x, l.origin);
  const auto at_end = [&](Real t, const Vec3<Real>& end) {
    out.t = t;
    out.point_b = end;
    out.distance = rounded_norm(exact_difference<Real>(x, end));
    return out;
  };
  if (b.is_point()) return at_end(clamp_to(Real(0), l.lo, l.hi), l.origin);
  const DD along = dot(e, b.dir), length2 = dot(b.dir, b.dir);
  if (std::isfinite(l.lo) && !((along - length2 * l.lo).hi > 0)) return at_end(l.lo, b.at(l.lo));
  if (std::isfinite(l.hi) && !((along - length2 * l.hi).hi < 0)) return at_end(l.hi, b.at(l.hi));
  const DD t = along / length2;
  out.t = t.value();
  out.point_b = rounded(b.exact_at(t));
  out.distance = rounded_norm(cross(e, b.dir)) / std::sqrt(length2.value());
  return out;
}

// Two pieces (unit_scaled, as linear_pair_scaled takes them): the least of the interior
// stationary point, when it lies in both intervals (decided in double-double), and the finite
// ends against the other piece that `contenders` names (the others lost by more than their
// rounding: each costs about 0.5 us here). `unique` is the caller's (the parallel test does not
// cancel).
template <class Real>
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline, cold))  // rare: kept out of the plain path's code
#endif
LinearPair<Real>
exact_pair(const ExactPiece<Real>& a, const ExactPiece<Real>& b, unsigned contenders) {
  using DD = DoubleDouble<Real>;
  LinearPair<Real> best;
  const auto take = [&](const LinearPair<Real>& c) {
    if (c.distance < best.distance) best = c;
  };
  const auto swapped = [](LinearPair<Real> c) {
    std::swap(c.s, c.t);
    std::swap(c.point_a, c.point_b);
    return c;
  };
  const Linear<Real>&la = a.piece, &lb = b.piece;
  if (!a.is_point() && !b.is_point()) {
    const DoubleDouble3<Real> w = exact_difference<Real>(la.origin, lb.origin), n = cross(a.dir, b.dir);
    const DD n2 = dot(n, n);
    if (n2.hi > 0) {
      // s = -((w x v).n) / |n|^2, t = -((w x u).n) / |n|^2 (the Binet-Cauchy forms above).
      const DD s_num = -dot(cross(w, b.dir), n), t_num = -dot(cross(w, a.dir), n);
      const auto inside = [&](const DD& num, const Linear<Real>& l) {
        return !(std::isfinite(l.lo) && (num - n2 * l.lo).hi < 0) && !(std::isfinite(l.hi) && (num - n2 * l.hi).hi > 0);
      };
      if (inside(s_num, la) && inside(t_num, lb)) {
        // The distance |X.n| / |n| from the nearer of two offsets between points of the lines:
        // n carries about eps^2 |u| |v| per component (eps^2 / sin(angle) of itself, 1e-16 for
        // pieces 5e-17 rad apart), which an offset X turns into |X| times that. w, between the
        // origins, is exact; W, between the pieces' points at s and t, is small (near the
        // distance) but carries eps^2 of their coordinates: where the stationary point lies far
        // from both origins (lines 1e-16 rad apart passing 1e-9 apart, s = 1e16), w answers.
        // The point of b is the foot of a's point on b's line, not b's own stationary value: for
        // pieces 5e-17 rad apart the two stationary values carry independent errors along the
        // pieces (1e-6 at 3e10 from the origins), which would part the points by as much.
        LinearPair<Real> c;
        const DD s = s_num / n2;
        const DoubleDouble3<Real> pa = a.exact_at(s);
        const DoubleDouble3<Real> origin_b{DD(lb.origin[0]), DD(lb.origin[1]), DD(lb.origin[2])};
        DD t = dot(pa - origin_b, b.dir) / dot(b.dir, b.dir);
        if (t.hi < lb.lo) t = DD(lb.lo);
        if (t.hi > lb.hi) t = DD(lb.hi);
        c.s = s.value();
        c.t = t.value();
        const DoubleDouble3<Real> pb = b.exact_at(t);
        const DoubleDouble3<Real> near = pa - pb;
        const Real n_norm = rounded(n).norm();
        const Real n_error = n_norm > 0 ? a.dir_size() * b.dir_size() / n_norm : Real(0);
        const Real w_error = rounded(w).cwiseAbs().sum() * n_error;
        const Real near_error =
            rounded(near).cwiseAbs().sum() * n_error + rounded(pa).cwiseAbs().sum() + rounded(pb).cwiseAbs().sum();
        c.point_a = rounded(pa);
        c.point_b = rounded(pb);
        c.distance = std::abs(dot(near_error < w_error ? near : w, n).value()) / std::sqrt(n2.value());
        take(c);
      }
    }
  }
  for (const ExactPiece<Real>* p : {&a, &b}) {
    const ExactPiece<Real>& other = p == &a ? b : a;
    for (const bool high : {false, true}) {
      const Real end = high ? p->piece.hi : p->piece.lo;
      const unsigned bit = p == &a ? (high ? kEndAHi : kEndALo) : (high ? kEndBHi : kEndBLo);
      if (!(contenders & bit) || !std::isfinite(end)) continue;
      LinearPair<Real> c = point_to_exact_piece(p->at(end), other);
      c.s = end;
      take(p == &a ? c : swapped(c));
    }
  }
  if (!(best.distance < std::numeric_limits<Real>::infinity()) || (contenders & kAnyPoint)) {
    // Two full lines without a crossing (parallel): any point of one; a full line and a
    // degenerate one (a zero direction): that one's point.
    if (b.is_point()) {
      LinearPair<Real> c = point_to_exact_piece(lb.origin, a);
      c.s = clamp_to(Real(0), lb.lo, lb.hi);
      take(swapped(c));
    } else {
      LinearPair<Real> c = point_to_exact_piece(la.origin, b);
      c.s = clamp_to(Real(0), la.lo, la.hi);
      take(c);
    }
  }
  return best;
}

}  // namespace circledist::detail
