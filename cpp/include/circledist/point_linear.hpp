// Point against a line, ray or segment (Query<Vec3, Line3 | Ray3 | Segment3>). Derivation: the
// closed form below (no derivation page; the scaled pieces are linear_linear.hpp's).
#pragma once

#include "linear_linear.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// A point against a line, ray or segment: its projection, clamped to the interval.
template <class Real, class Piece> struct PointLinearQuery {
  static constexpr bool defined = true;

  // The projection's parameter on the piece with its direction scaled to components in [1, 2)
  // (`exponent` returns the scaling: t = ldexp(t', -exponent)), so |d|^2 neither overflows
  // (1e283) nor underflows; the closest point is origin + t' d'.
  static Real parameter(const Vec3<Real>& offset, const Linear<Real>& l, Linear<Real>& scaled, int& exponent) {
    scaled = unit_scaled(l, exponent);
    const Real aa = scaled.direction.squaredNorm();
    return aa > 0 ? clamp_to(offset.dot(scaled.direction) / aa, scaled.lo, scaled.hi)
                  : clamp_to(Real(0), scaled.lo, scaled.hi);
  }

  // The closest point's offset from p, from p's offset from the origin (subtracted first, exact
  // for nearby coordinates): t d - (p - o), not (o + t d) - p, which in a scene 1e6 from the
  // world's origin carries eps 1e6. A segment's far end is its own p1 (d = p1 - p0 is rounded).
  static Vec3<Real> separation(const Vec3<Real>& p, const Vec3<Real>& offset, const Linear<Real>& scaled, Real t) {
    if (scaled.has_end && t == scaled.hi) return scaled.end - p;
    return t * scaled.direction - offset;
  }

  // The answer as a LinearPair (t, the distance, the closest point of the piece): the projection
  // in plain arithmetic, or, where the offsets' rounding (at most about 4 eps of their size, as in
  // linear_pair_scaled) may exceed 1024 eps of the distance (an origin or segment end far from p,
  // or p on the piece), from the exact inputs (detail::point_to_exact_piece). distance() leaves
  // the closest point out.
  template <bool WithPoint> static LinearPair<Real> solve(const Vec3<Real>& p, const Piece& piece) {
    Linear<Real> scaled;
    int exponent = 0;
    const Linear<Real> l = as_linear(piece);
    const Vec3<Real> offset = p - l.origin;
    LinearPair<Real> out;
    out.t = parameter(offset, l, scaled, exponent);
    out.distance = separation(p, offset, scaled, out.t).norm();
    const Real size = offset.cwiseAbs().sum() + std::abs(out.t) * scaled.direction.cwiseAbs().sum();
    // (an infinite distance too: the plain offset's rounding, eps times an origin 1e306 away,
    // squares past the largest double, where the exact offsets do not)
    if (!(size <= detail::kExactPassRatio * out.distance) || !(out.distance < std::numeric_limits<Real>::infinity())) {
      const LinearPair<Real> exact = detail::point_to_exact_piece(p, detail::ExactPiece<Real>(scaled, l, exponent));
      if (std::isfinite(exact.distance) && exact.point_b.allFinite()) {
        out = exact;
        out.t = std::ldexp(out.t, -exponent);
        return out;
      }
    }
    if constexpr (WithPoint)
      out.point_b =
          scaled.has_end && out.t == scaled.hi ? scaled.end : Vec3<Real>(scaled.origin + out.t * scaled.direction);
    out.t = std::ldexp(out.t, -exponent);
    return out;
  }

  template <class Roots = DefaultRoots> static Real distance(const Vec3<Real>& p, const Piece& piece) {
    return solve<false>(p, piece).distance;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Piece& piece) {
    const LinearPair<Real> answer = solve<true>(p, piece);
    Result<Real> r;
    r.point_a = p;
    r.point_b = answer.point_b;
    r.distance = answer.distance;
    r.param_b = Vec2<Real>(answer.t, 0);
    return r;
  }
};

}  // namespace detail

template <class Real> struct Query<Vec3<Real>, Line3<Real>> : detail::PointLinearQuery<Real, Line3<Real>> {};
template <class Real> struct Query<Vec3<Real>, Ray3<Real>> : detail::PointLinearQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Vec3<Real>, Segment3<Real>> : detail::PointLinearQuery<Real, Segment3<Real>> {};

}  // namespace circledist
