// Line, ray and segment against each other (Query<Line3 | Ray3 | Segment3, ...>). Derivation: the
// closed forms below (no derivation page).
//
// Points, lines, rays and segments against each other: closed forms, no polynomial. They let
// swept points (balls) and swept segments (capsules) meet each other, and a scene mix every kind.
//
// Two pieces P(s) = p + s u, s in [lo_a, hi_a], and Q(t) = q + t v, t in [lo_b, hi_b] (either end
// may be infinite): the squared distance f(s, t) = |w + s u - t v|^2, w = p - q, is convex, so its
// minimum over the box of parameters is the interior stationary point when that lies in the box,
// and otherwise lies on an edge of the box, where one parameter sits at a finite end and the
// other minimizes a convex quadratic: its stationary value clamped to its interval. The exact
// distance judges those few candidates. Parallel pieces (u x v = 0) have no interior point; their
// distance is constant along the overlap of their projections, which contains an end point of one
// of them unless both are full lines (then any pair at s = 0 does). `unique` is false when that
// overlap is longer than the distinct-points tolerance (a continuum of closest pairs).
// Where the pieces' defining points lie far from where they pass, the candidates are evaluated
// again from the exact inputs (detail/exact_linear.hpp).
#pragma once

#include "detail/exact_linear.hpp"
#include "linear.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// The piece with its direction scaled by a power of two (exact) to a largest component in
// [1, 2), its parameter interval scaled inversely: the same points, P(s) = p + s u for s in the
// returned interval, with s = ldexp(s', -exponent). Products of directions (|u|^2 |v|^2, and
// |u x v|^2 of lines with |u| = 1e80) would otherwise overflow or underflow.
template <class Real> Linear<Real> unit_scaled(const Linear<Real>& piece, int& exponent) {
  // Components within 2^(+-max_exponent / 5) need no scaling: products of four of them stay off
  // overflow and the subnormals (the common case pays two comparisons).
  constexpr Real lo = detail::power_of_two<Real>(std::numeric_limits<Real>::min_exponent / 5);
  constexpr Real hi = detail::power_of_two<Real>(std::numeric_limits<Real>::max_exponent / 5);
  const Real largest = piece.direction.cwiseAbs().maxCoeff();
  exponent = 0;
  if (largest >= lo && largest <= hi) return piece;
  exponent = largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
  Linear<Real> out = piece;
  for (int i = 0; i < 3; ++i) out.direction[i] = std::ldexp(piece.direction[i], -exponent);
  out.lo = std::ldexp(piece.lo, exponent);
  out.hi = std::ldexp(piece.hi, exponent);
  return out;
}

// `exact` is set to the candidates that may be the least (within their rounding of the best) when
// the rounding of the pieces' offsets may exceed about 1e3 eps of the answer; else 0.
template <class Real>
LinearPair<Real> linear_pair_scaled(const Linear<Real>& a, const Linear<Real>& b, unsigned& exact);

template <class Real> LinearPair<Real> linear_pair(const Linear<Real>& a, const Linear<Real>& b) {
  int ea = 0, eb = 0;
  const Linear<Real> sa = unit_scaled(a, ea), sb = unit_scaled(b, eb);
  unsigned contenders = 0;
  LinearPair<Real> p = linear_pair_scaled(sa, sb, contenders);
  p.point_a = sa.origin + p.s * sa.direction;
  p.point_b = sb.origin + p.t * sb.direction;
  if (contenders) {
    LinearPair<Real> exact =
        detail::exact_pair(detail::ExactPiece<Real>(sa, a, ea), detail::ExactPiece<Real>(sb, b, eb), contenders);
    // Not finite only where products of the offsets overflow (scenes near the largest doubles,
    // which the front end scales back first): the plain answer stands there.
    if (std::isfinite(exact.distance) && exact.point_a.allFinite() && exact.point_b.allFinite()) {
      exact.unique = p.unique;
      p = exact;
    }
  }
  p.s = std::ldexp(p.s, -ea);
  p.t = std::ldexp(p.t, -eb);
  return p;
}

template <class Real>
LinearPair<Real> linear_pair_scaled(const Linear<Real>& a, const Linear<Real>& b, unsigned& exact) {
  const Vec3<Real>& u = a.direction;
  const Vec3<Real>& v = b.direction;
  const Vec3<Real> w = a.origin - b.origin;
  const Real aa = u.squaredNorm(), bb = u.dot(v), cc = v.squaredNorm(), dd = u.dot(w), ee = v.dot(w);
  const bool a_point = !(aa > 0), b_point = !(cc > 0);
  LinearPair<Real> best;
  // Each candidate's value and the size of the offsets it was computed from (1-norms: an upper
  // bound, no square root), whose rounding it carries: w's, s u's, t v's and their sum's, each
  // within eps / 2 of its own size per component, at most about 4 eps of the size in all (for the interior
  // point's |w.n| / |n|, w's and the cross product's, about 2 eps of |w|; its points' as well).
  // Only the largest size is kept: the rare pairs it marks evaluate their candidates again (kept
  // in an array, the candidates cost 12 ns more on every pair).
  Real largest_size = 0, best_size = 0;
  const Real w_size = w.cwiseAbs().sum(), u_size = u.cwiseAbs().sum(), v_size = v.cwiseAbs().sum();
  const auto evaluate = [&](Real s, Real t, Real& size) {
    size = w_size + std::abs(s) * u_size + std::abs(t) * v_size;
    return (w + s * u - t * v).norm();
  };
  const auto consider = [&](Real s, Real t, unsigned) {
    Real size;
    const Real dist = evaluate(s, t, size);
    largest_size = std::max(largest_size, size);
    if (dist < best.distance) {
      best = {dist, s, t, true};
      best_size = size;
    }
  };
  // The stationary value of one parameter with the other fixed, clamped.
  const auto t_for = [&](Real s) {
    return b_point ? clamp_to(Real(0), b.lo, b.hi) : clamp_to((bb * s + ee) / cc, b.lo, b.hi);
  };
  const auto s_for = [&](Real t) {
    return a_point ? clamp_to(Real(0), a.lo, a.hi) : clamp_to((bb * t - dd) / aa, a.lo, a.hi);
  };
  // The candidates on the box's edges: a finite end of one piece, the other parameter its
  // stationary value clamped.
  const auto for_each_end = [&](const auto& visit) {
    if (std::isfinite(a.lo)) visit(a.lo, t_for(a.lo), detail::kEndALo);
    if (std::isfinite(a.hi)) visit(a.hi, t_for(a.hi), detail::kEndAHi);
    if (std::isfinite(b.lo)) visit(s_for(b.lo), b.lo, detail::kEndBLo);
    if (std::isfinite(b.hi)) visit(s_for(b.hi), b.hi, detail::kEndBHi);
  };
  // n = u x v with each component rounded once (accurate_cross): for nearly parallel pieces the
  // plain cross product cancels, and its error, eps |u| |v| per component, tilts n by
  // eps / sin(angle), which |w.n| / |n| turns into eps |w| / sin(angle) (1.5e-11 for a true 6e-18
  // between two crossing segments 1e-5 rad apart).
  const Vec3<Real> n = accurate_cross(u, v);
  const Real cross2 = n.squaredNorm();
  const Real parallel = 64 * std::numeric_limits<Real>::epsilon() * aa * cc;
  if (!a_point && !b_point && cross2 > 0) {
    // The interior stationary point; its distance by the closed form |w.n| / |n|, which stays
    // accurate for nearly parallel pieces. s and t there are ill-conditioned: from the dot
    // products, (bb ee - cc dd) / |n|^2 carries eps |w| |u|^2 |v|^2 / |n|^2, a shift along the
    // pieces of eps |w| / sin^2(angle) each, and the two shifts, independent, part the points by
    // as much. Below about 6 degrees they come from the Binet-Cauchy forms
    // s = -(w x v).n / |n|^2, t = -(w x u).n / |n|^2 with accurate cross products: eps |w| / sin
    // each, which parts the points by eps |w| only (a shift along a piece moves it off the other
    // by sin times the shift).
    Real s = (bb * ee - cc * dd) / cross2, t = (aa * ee - bb * dd) / cross2;
    if (cross2 < Real(1e-2) * aa * cc) {
      const Real s_accurate = -accurate_cross(w, v).dot(n) / cross2, t_accurate = -accurate_cross(w, u).dot(n) / cross2;
      // Kept where the stationary point lies within 1 / eps scene sizes of the scene. Farther,
      // the pieces are parallel within the scene's rounding (and the front end, which scales
      // scenes beyond the moderate range back by up to 2^1023, could not even represent the
      // points): the dot-product values stand, as before, with `unique` false from the
      // parallel test below.
      const Real scene =
          std::max({w.cwiseAbs().maxCoeff(), a.origin.cwiseAbs().maxCoeff(), b.origin.cwiseAbs().maxCoeff()});
      const Real far = scene / std::numeric_limits<Real>::epsilon();
      if (std::abs(s_accurate) * std::sqrt(aa) <= far && std::abs(t_accurate) * std::sqrt(cc) <= far) {
        s = s_accurate;
        t = t_accurate;
      }
    }
    if (s >= a.lo && s <= a.hi && t >= b.lo && t <= b.hi) {
      best = {std::abs(w.dot(n)) / std::sqrt(cross2), s, t, true};
      // (its size counts s u and t v too: the closest points p + s u and q + t v carry their
      // rounding, 2e-10 for pieces 1e-8 rad apart passing 1e6 from both origins)
      best_size = largest_size = w_size + std::abs(s) * u_size + std::abs(t) * v_size;
    }
  }
  const Real interior_distance = best.distance, interior_size = best_size;  // inf, 0: none
  for_each_end(consider);
  const bool any_point = !(best.distance < std::numeric_limits<Real>::infinity());
  // Two full lines, parallel: any s gives the distance; a full line and a degenerate one (a zero
  // direction): that one's point, and its projection on the other.
  const Real any_t = clamp_to(Real(0), b.lo, b.hi);
  const Real any_s = b_point ? s_for(any_t) : clamp_to(Real(0), a.lo, a.hi);
  const Real any_t_for_s = b_point ? any_t : t_for(any_s);
  if (any_point) consider(any_s, any_t_for_s, detail::kAnyPoint);
  if (!a_point && !b_point && !(cross2 > parallel)) {
    // Parallel: the overlap of b's projection onto a's parameter with a's interval.
    const Real t0 = std::isfinite(b.lo) ? b.lo : -std::numeric_limits<Real>::infinity();
    const Real t1 = std::isfinite(b.hi) ? b.hi : std::numeric_limits<Real>::infinity();
    Real p0 = (bb * t0 - dd) / aa, p1 = (bb * t1 - dd) / aa;
    if (!(p0 == p0)) p0 = bb > 0 ? -std::numeric_limits<Real>::infinity() : std::numeric_limits<Real>::infinity();
    if (!(p1 == p1)) p1 = bb > 0 ? std::numeric_limits<Real>::infinity() : -std::numeric_limits<Real>::infinity();
    const Real lo = std::max(a.lo, std::min(p0, p1)), hi = std::min(a.hi, std::max(p0, p1));
    const Real scale = std::max({w.norm(), best.distance, Real(1e-300)});
    if (hi > lo && (hi - lo) * std::sqrt(aa) > distinct_points_tolerance(scale)) best.unique = false;
  }
  // Any candidate that may be the least (within four times its rounding of the best) and whose
  // rounding may exceed 1024 eps of the best (sizes above detail::kExactPassRatio, 256, times
  // the distance) asks for the exact evaluation of all that may be the least: a plain answer is
  // then good to about 2e-13 of itself in double (1e-16 in long double), as the bars ask, and an
  // exact one to about eps^2 times the offsets (detail/exact_linear.hpp). (Segments with
  // normally distributed ends take the exact pass about once in 120 pairs, at about 2.5 us.)
  exact = 0;
  if (largest_size <= detail::kExactPassRatio * best.distance) return best;
  constexpr Real rounding = 16 * std::numeric_limits<Real>::epsilon();
  unsigned contenders = 0;
  bool cancels = false;
  const auto judge = [&](Real dist, Real size, unsigned candidate) {
    if (!(dist - rounding * size <= best.distance + rounding * best_size)) return;
    contenders |= candidate;
    if (!(size <= detail::kExactPassRatio * best.distance)) cancels = true;
  };
  judge(interior_distance, interior_size, 0u);
  const auto judge_end = [&](Real s, Real t, unsigned candidate) {
    Real size;
    const Real dist = evaluate(s, t, size);
    judge(dist, size, candidate);
  };
  for_each_end(judge_end);
  if (any_point) judge_end(any_s, any_t_for_s, detail::kAnyPoint);
  exact = cancels ? (contenders | detail::kExactPass) : 0u;
  return best;
}

template <class Real, class PieceA, class PieceB> struct LinearLinearQuery {
  static constexpr bool defined = true;

  template <class Roots = DefaultRoots> static Real distance(const PieceA& a, const PieceB& b) {
    return linear_pair(as_linear(a), as_linear(b)).distance;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const PieceA& a, const PieceB& b) {
    const Linear<Real> la = as_linear(a), lb = as_linear(b);
    const LinearPair<Real> p = linear_pair(la, lb);
    Result<Real> r;
    r.distance = p.distance;
    r.point_a = p.point_a;
    r.point_b = p.point_b;
    r.param_a = Vec2<Real>(p.s, 0);
    r.param_b = Vec2<Real>(p.t, 0);
    r.unique = p.unique;
    return r;
  }
};

}  // namespace detail

template <class Real> struct Query<Line3<Real>, Line3<Real>>
    : detail::LinearLinearQuery<Real, Line3<Real>, Line3<Real>> {};
template <class Real> struct Query<Line3<Real>, Ray3<Real>> : detail::LinearLinearQuery<Real, Line3<Real>, Ray3<Real>> {
};
template <class Real> struct Query<Line3<Real>, Segment3<Real>>
    : detail::LinearLinearQuery<Real, Line3<Real>, Segment3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Ray3<Real>> : detail::LinearLinearQuery<Real, Ray3<Real>, Ray3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Segment3<Real>>
    : detail::LinearLinearQuery<Real, Ray3<Real>, Segment3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Segment3<Real>>
    : detail::LinearLinearQuery<Real, Segment3<Real>, Segment3<Real>> {};

}  // namespace circledist
