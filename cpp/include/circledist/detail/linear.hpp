// Lines, rays and segments as one "linear piece" origin + t * direction, t in [lo, hi], the
// machinery shared by every linear-vs-round query (linear_circle.hpp, linear_disk.hpp), and their
// general path, LinearRoundQuery, written once for the ring and the disk target
// (detail/round_target.hpp).
#pragma once

#include "double_double.hpp"
#include "round_target.hpp"
#include "minimize.hpp"
#include "planar.hpp"

#include <cmath>
#include <limits>

namespace circledist::detail {

template <class Real> struct Linear {
  Vec3<Real> origin, direction;
  Real lo, hi;  // parameter interval; either end may be infinite
  // A segment keeps its second end point: direction = p1 - p0 is rounded, and the line through
  // the rounded direction can miss the true one by more than a tiny offset it must keep.
  Vec3<Real> end = Vec3<Real>::Zero();
  bool has_end = false;
};

template <class Real> Linear<Real> as_linear(const Line3<Real>& l) {
  const Real inf = std::numeric_limits<Real>::infinity();
  return {l.origin, l.direction, -inf, inf};
}
template <class Real> Linear<Real> as_linear(const Ray3<Real>& r) {
  return {r.origin, r.direction, Real(0), std::numeric_limits<Real>::infinity()};
}
template <class Real> Linear<Real> as_linear(const Segment3<Real>& s) {
  return {s.p0, s.p1 - s.p0, Real(0), Real(1), s.p1, true};
}

// The answer between two linear pieces (linear_linear.hpp): their parameters and closest points.
template <class Real> struct LinearPair {
  Real distance = std::numeric_limits<Real>::infinity();
  Real s = 0, t = 0;
  bool unique = true;
  // The closest points, from the pieces with scaled directions: finite even where s or t is not
  // representable (a direction of 1e-295 with the closest point 1e38 away: t = 1e333).
  Vec3<Real> point_a = Vec3<Real>::Zero(), point_b = Vec3<Real>::Zero();
};

template <class Real> Real clamp_to(Real x, Real lo, Real hi) { return std::min(std::max(x, lo), hi); }

// a * b - c * d with a single rounding error (Kahan's algorithm with fused multiply-adds).
template <class Real> Real difference_of_products(Real a, Real b, Real c, Real d) {
  const Real cd = c * d;
  const Real error = std::fma(-c, d, cd);
  return std::fma(a, b, -cd) + error;
}

// x cross y, each component to within about one rounding of its own value, however much the
// two products cancel.
template <class Real> Vec3<Real> accurate_cross(const Vec3<Real>& x, const Vec3<Real>& y) {
  return Vec3<Real>(difference_of_products(x.y(), y.z(), x.z(), y.y()),
                    difference_of_products(x.z(), y.x(), x.x(), y.z()),
                    difference_of_products(x.x(), y.y(), x.y(), y.x()));
}

// x - y as an unevaluated sum hi + lo, exactly (Knuth's TwoSum per component). A line's origin
// far from a round's center (1e10 away for a radius of 1) loses eps |x| in x - y, far more
// than the offset of the line from the center that the answer depends on.
template <class Real> struct ExactDifference {
  Vec3<Real> hi, lo;
  ExactDifference(const Vec3<Real>& x, const Vec3<Real>& y) {
    const detail::DoubleDouble3<Real> d = detail::exact_difference<Real>(x, y);
    for (int i = 0; i < 3; ++i) {
      hi[i] = d[i].hi;
      lo[i] = d[i].lo;
    }
  }
};

// (x - y) cross d to about one rounding per component of the result, however far x lies from y
// along d: the cross product of the rounded difference by accurate_cross, plus what the
// difference's rounding contributes (small: plain arithmetic is accurate enough for it).
template <class Real> Vec3<Real> offset_cross(const ExactDifference<Real>& x, const Vec3<Real>& d) {
  return accurate_cross(x.hi, d) + x.lo.cross(d);
}

// (x - c) cross (y - c) the same way, for a segment through two far end points.
template <class Real> Vec3<Real> offset_cross(const ExactDifference<Real>& x, const ExactDifference<Real>& y) {
  return accurate_cross(x.hi, y.hi) + (x.hi.cross(y.lo) + x.lo.cross(y.hi));
}

// The piece in a round's local frame, re-anchored at its point closest to the round's center and
// with a unit direction: P(tau) = anchor + tau * dir, and t = (tau + shift) / length. Anchoring
// keeps the polynomial's variable small and its coefficients free of the along-line offset.
template <class Real> struct LocalLinear {
  Vec3<Real> anchor, dir;
  Vec3<Real> anchor_world, dir_world;  // the same, on world axes (the anchor relative to the center)
  Real length = 1, shift = 0, lo = 0, hi = 0;
  bool is_point = false;  // zero-length direction (a degenerate segment)

  //
  // The anchor is computed in world coordinates before any rotation: rotating the origin (at a
  // distance |o - c| from the center) into the frame would err by eps |o - c|, far more than the
  // offset of a line passing 1e-17 from the center of a circle of radius 1e-9. With w = (o - c) x d
  // (through both end points for a segment) to one rounding per component, the anchor
  // d x w / |d|^2 is accurate relative to its own length.
  LocalLinear(const Linear<Real>& piece, const Round<Real>& round) {
    const ExactDifference<Real> exact_origin(piece.origin, round.center);
    const Vec3<Real>& origin = exact_origin.hi;
    const Real largest = piece.direction.cwiseAbs().maxCoeff();
    if (!(largest > 0)) {
      is_point = true;
      anchor_world = origin;
      dir_world.setZero();
      anchor = round.frame.to_local(origin);
      dir.setZero();
      length = 1;
      return;
    }
    // The direction scaled by a power of two (exact) to components of order 1: its squared
    // length neither overflows (|d| = 1e200) nor underflows (1e-200); `length` is |d| itself.
    const int exponent = std::ilogb(largest);
    const Vec3<Real> direction = piece.direction.unaryExpr([&](Real x) { return Real(std::ldexp(x, -exponent)); });
    const Vec3<Real> m = round.frame.to_local(direction);
    const Real scaled_length = m.norm();
    length = std::ldexp(scaled_length, exponent);
    dir = m / scaled_length;
    const ExactDifference<Real> exact_end(piece.has_end ? piece.end : piece.origin, round.center);
    Vec3<Real> w;
    if (piece.has_end) {
      w = offset_cross(exact_origin, exact_end);
      for (int i = 0; i < 3; ++i) w[i] = std::ldexp(w[i], -exponent);
    } else {
      w = offset_cross(exact_origin, direction);
    }
    anchor_world = direction.cross(w) / direction.squaredNorm();
    dir_world = direction / direction.norm();
    anchor = round.frame.to_local(anchor_world);
    // A point's tau is its offset from the center along the line, (x - c).dir, from the exact
    // difference: accurate relative to the point's own distance from the center. (A segment's
    // near end as length - shift, with its far end 1e9 away, erred by 1e9 eps = 1e-7 along the
    // line.)
    const auto tau_of = [&](const ExactDifference<Real>& x) { return x.hi.dot(dir_world) + x.lo.dot(dir_world); };
    shift = -tau_of(exact_origin);
    lo = std::isfinite(piece.lo) ? piece.lo * length - shift : piece.lo;
    hi = piece.has_end ? tau_of(exact_end) : std::isfinite(piece.hi) ? piece.hi * length - shift : piece.hi;
  }

  Vec3<Real> at(Real tau) const { return anchor + tau * dir; }
  Real t_of(Real tau) const { return (tau + shift) / length; }
};

// Exact candidates every linear-vs-round query evaluates as they are, clamped to the interval
// (they are not estimates of a stationary point, so they are not polished): the anchor, the plane crossing (where the
// disk's height kinks; for a circle, the closest point of a line along the axis, where the quartic vanishes
// identically), and the finite interval ends (the note's "ray origin" rule).
template <class Real> void push_linear_candidates(const LocalLinear<Real>& line, Candidates<Real>& out) {
  out.push(Real(0));
  if (line.is_point) return;
  if (line.dir.z() != 0) out.push(-line.anchor.z() / line.dir.z());
  if (std::isfinite(line.lo)) out.push(line.lo);
  if (std::isfinite(line.hi)) out.push(line.hi);
}

// Note 000 §1: the zero-derivative condition squared,
//   (a0 + a1 t)^2 (c0 + 2 c1 t + c2 t^2) = R^2 (b0 + b1 t)^2,
// expanded into d0 + d1 t + ... + d4 t^4. Here in the circle's frame (b1 = mx^2 + my^2 without
// the cancellation of M.M - (N.M)^2), with a1 = |M| = 1 and t scaled by `scale` so that the
// coefficients are O(1). Appends the near-real roots (as tau) to `out`.
template <class Roots, class Real>
void push_line_circle_roots(const LocalLinear<Real>& line, Real radius, Real scale, Candidates<Real>& out) {
  if (line.is_point) return;
  const Vec3<Real> a = line.anchor / scale;
  const Vec3<Real>& m = line.dir;
  const Real r2 = (radius / scale) * (radius / scale);
  const Real a0 = a.dot(m);
  const Real b0 = m.x() * a.x() + m.y() * a.y(), b1 = m.x() * m.x() + m.y() * m.y();
  const Real c0 = a.x() * a.x() + a.y() * a.y(), c1 = b0, c2 = b1;
  const Real d[5] = {
      a0 * a0 * c0 - b0 * b0 * r2,
      2 * (a0 * c0 + a0 * a0 * c1 - b0 * b1 * r2),
      c0 + 4 * a0 * c1 + a0 * a0 * c2 - b1 * b1 * r2,
      2 * (c1 + a0 * c2),
      c2,
  };
  // Only |tau| <= |a| + R can hold a root: beyond it |P.m| = |a0 + tau| > R while
  // |P_xy . m_xy| <= |P_xy|, so the left side exceeds the right unless P_xy = 0 (the line
  // crossing the axis: a local maximum of the ring distance, never a minimum). A 1 % margin
  // covers the coefficients' rounding; the piece's own interval bounds the search too (its
  // ends are exact candidates).
  const Real reach = Real(1.01) * (a.norm() + radius / scale);
  const Real lo = std::max(-reach, line.lo / scale), hi = std::min(reach, line.hi / scale);
  Candidates<Real> roots;
  Roots::roots(d, 4, lo, hi, roots);
  for (int i = 0; i < roots.count; ++i) out.push(roots.value[i] * scale);
}

// The length scale of a linear-vs-round query: tolerances and the polish width follow it.
template <class Real> Real linear_round_scale(const LocalLinear<Real>& line, Real radius) {
  const Real s = std::max(radius, line.anchor.norm());
  return s > 0 ? s : Real(1);
}

// Polishes the `stationary` candidates (polynomial roots) on the exact distance `h(tau)` over the
// piece's interval, as the root policy asks (Newton on the squared distance `jet`, or a
// bracketed search), and evaluates the `exact` candidates as they are.
template <class Roots, class Real, class J, class H>
Minima<Real> minimize_linear(const J& jet, const H& h, const LocalLinear<Real>& line, Real radius,
                             const Candidates<Real>& stationary, const Candidates<Real>& exact, Real scale) {
  const Real width = Real(1e-3) * scale;
  const Real abs_tol = Real(0.1) * std::sqrt(std::numeric_limits<Real>::epsilon()) * scale;
  Minima<Real> out;
  if (Roots::polish() == Polish::Newton) {
    // Squaring note 000's condition (P.M) = R (Q-C).M / |Q-C| let in the roots of the other
    // branch, (P.M) = -R (...): those are no stationary points of the distance, so they are
    // evaluated but not polished (Newton would fail on them and fall back to a slow search).
    Candidates<Real> genuine;
    for (int i = 0; i < stationary.count; ++i) {
      const Real tau = std::min(std::max(stationary.value[i], line.lo), line.hi);
      const Vec3<Real> p = line.at(tau);
      const Real rho = length2d(p.x(), p.y());
      const Real along = p.dot(line.dir);
      const Real pull = rho > 0 ? radius * (p.x() * line.dir.x() + p.y() * line.dir.y()) / rho : Real(0);
      // A genuine root where the squared distance is concave is a local maximum: the minima
      // beside it have roots of their own, so it is evaluated, not polished (Newton would stop
      // at once and hand it to the slow bracketed search).
      if (std::abs(along - pull) > 4 * std::abs(along + pull) + abs_tol || jet(tau).curvature < 0) {
        out.add(Minimum<Real>{tau, h(tau)});
      } else {
        genuine.push(tau);
      }
    }
    const Minima<Real> polished = polish_candidates_newton(jet, h, genuine, width, line.lo, line.hi, abs_tol);
    for (int i = 0; i < polished.count; ++i) out.add(polished.item[i]);
  } else {
    out = polish_candidates(h, stationary, width, line.lo, line.hi, abs_tol);
  }
  for (int i = 0; i < exact.count; ++i) {
    const Real tau = std::min(std::max(exact.value[i], line.lo), line.hi);
    out.add(Minimum<Real>{tau, h(tau)});
  }
  return out;
}

// The world point of the piece at `tau` of its local line, and its parameter t: an end point
// exactly when tau sits there; otherwise from the world anchor (accurate relative to its distance
// from the center, where origin + t direction would err by eps |origin - center| across the line).
template <class Real> Vec3<Real> piece_point(const Linear<Real>& piece, const LocalLinear<Real>& line,
                                             const Round<Real>& round, Real tau, Real& t) {
  t = line.is_point ? Real(0) : line.t_of(tau);
  t = std::min(std::max(t, piece.lo), piece.hi);
  if (line.is_point || tau <= line.lo) {
    t = line.is_point ? Real(0) : piece.lo;
    return piece.origin;
  }
  if (tau >= line.hi) {
    t = piece.hi;
    return piece.has_end ? piece.end : Vec3<Real>(piece.origin + t * piece.direction);
  }
  return round.center + (line.anchor_world + tau * line.dir_world);
}

// Builds the Result from the polished minima: the round's side from round_side_result
// (round_target.hpp; distinct tied pairs make `unique` false), the piece's point here.
template <class Target, class Real>
Result<Real> linear_round_result(const Linear<Real>& piece, const LocalLinear<Real>& line, const Round<Real>& round,
                                 const Minima<Real>& minima, Real scale) {
  const Minimum<Real>& best = minima.best;
  Result<Real> r = round_side_result<Target>(
      minima, [&](Real x) { return line.at(x); }, line.at(best.x), round, scale, distinct_points_tolerance(scale));
  Real t;
  r.point_a = piece_point(piece, line, round, best.x, t);
  r.param_a = Vec2<Real>(t, 0);
  return r;
}

// Where the projection of the piece crosses the rim: b1 tau^2 + 2 b0 tau + (rho0^2 - R^2) = 0.
template <class Real> void push_rim_crossings(const LocalLinear<Real>& line, Real radius, Candidates<Real>& out) {
  if (line.is_point) return;
  const Vec3<Real>& a = line.anchor;
  const Vec3<Real>& m = line.dir;
  const Real b1 = m.x() * m.x() + m.y() * m.y();
  if (!(b1 > 0)) return;
  const Real b0 = m.x() * a.x() + m.y() * a.y();
  const Real rho0 = length2d(a.x(), a.y());
  const Real c = (rho0 - radius) * (rho0 + radius);
  const Real disc = b0 * b0 - b1 * c;
  if (disc < 0) return;
  const Real q = -(b0 + std::copysign(std::sqrt(disc), b0));
  if (q != 0) {
    out.push(q / b1);
    out.push(c / q);
  } else {
    out.push(Real(0));
  }
}

// Line, ray and segment against a ring or a disk, on the general path: note 000 §1's quartic
// (the ring's stationary points), the exact candidates and, for a disk, the rim crossings
// (note 000 §2, docs/derivations/line_disk.md), judged by the target's exact distance.
template <class Real, class Piece, class Target> struct LinearRoundQuery {
  static constexpr bool defined = true;
  using Shape = typename Target::Shape;

  template <class Roots> static Minima<Real> solve(const LocalLinear<Real>& line, Real radius, Real scale) {
    Candidates<Real> stationary, exact;
    push_line_circle_roots<Roots>(line, radius, scale, stationary);
    push_linear_candidates(line, exact);
    if constexpr (Target::interior) push_rim_crossings(line, radius, exact);
    const auto h = [&](Real tau) { return Target::distance(line.at(tau), radius); };
    const auto jet = [&](Real tau) { return Target::line_jet(line.at(tau), line.dir, radius); };
    return minimize_linear<Roots>(jet, h, line, radius, stationary, exact, scale);
  }

  template <class Roots = DefaultRoots> static Real distance(const Piece& piece, const Shape& shape) {
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const LocalLinear<Real> line(as_linear(piece), round);
    return solve<Roots>(line, shape.radius, linear_round_scale(line, shape.radius)).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Piece& piece, const Shape& shape) {
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const Linear<Real> linear = as_linear(piece);
    const LocalLinear<Real> line(linear, round);
    const Real scale = linear_round_scale(line, shape.radius);
    const Minima<Real> minima = solve<Roots>(line, shape.radius, scale);
    return linear_round_result<Target>(linear, line, round, minima, scale);
  }
};

}  // namespace circledist::detail
