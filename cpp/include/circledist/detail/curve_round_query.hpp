// A Bezier curve (degree 1 to 7, t in [0, 1]) against a disk or a circle, CurveRoundQuery: note 001
// §3 with polynomial curves. In the round's local frame (center subtracted from the control points
// first, exact for translated scenes) the curve is converted to the power basis in w = 2t - 1, the
// variable whose roots of interest lie in [-1, 1], where the power basis is best conditioned.
// Against a disk, [0, 1] is cut where x^2 + y^2 = r^2 (degree 2n); inside pieces minimize |z| (z =
// 0 or z' = 0, degrees n and n-1); outside pieces use note 001 eq. (2) squared, degree 6n - 2 (28
// for a quintic). Against a circle only the last equation is needed. Squaring adds extraneous
// roots; they are harmless because every candidate is judged (and polished) on the exact
// point-round distance, never on the polynomial. Derivation: docs/derivations/bezier.md.
#pragma once

#include "curve_roots.hpp"
#include "curve_round_base.hpp"

#include <limits>

namespace circledist::detail {

// Note 001 eq. (2) squared, in w: (P.P')^2 (x^2 + y^2) - R^2 (x x' + y y')^2 = 0, degree 6n - 2.
// Both sides carry P' twice, so d/dw in place of d/dt changes nothing.
template <class Roots, class Real, int N>
void push_curve_ring_roots(const LocalBezier<Real>& c, Real radius, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> x = c.coordinate(0, scale), y = c.coordinate(1, scale), z = c.coordinate(2, scale);
  const CurvePoly<Real> h = x * x.derivative() + y * y.derivative();
  const CurvePoly<Real> dot = h + z * z.derivative();
  const Real r = radius / scale;
  push_curve_roots<Roots>((dot * dot) * (x * x + y * y) - (r * r) * (h * h), out);
}

// Where the height over the round's plane has z z' = 0 (degrees n and n - 1): the stationary
// points of |z|, a disk's inside pieces (note 001 §3), a ring's curve along its axis (below) and
// an annulus's interior candidates (annulus_reduction.hpp, docs/derivations/annulus.md "A Bezier curve").
template <class Roots, class Real, int N>
void push_curve_height_roots(const LocalBezier<Real>& c, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> z = c.coordinate(2, scale);
  push_curve_roots<Roots>(z, out);
  push_curve_roots<Roots>(z.derivative(), out);
}

// The same candidates, each refined on the curve itself (an annulus's interior candidates,
// annulus_reduction.hpp), where no polish on the exact distance follows: Newton steps on the height z
// (de Casteljau) from each root of z, on its slope z' from each root of z', clamped to [0, 1]
// and kept only while they lower |z| or |z'|. The eigenvalue policies' roots of a curve whose
// height is nearly of lower degree (a degree-elevated arch: its high coefficients rounding noise,
// hence roots near 1e5 and, from the QR's backward error eps |C|, the small ones off by 1e-14)
// put a crossing of the plane at |z| = 2e-14 in long double (7e-15 x the outer radius,
// tests/accuracy/test_regressions.py); the disk's candidates are polished on the exact distance and
// land on the crossing. A simple root takes a step or two; a double one (the curve touching the
// plane) halves its error per step, and its z' root is the accurate candidate there. The root as
// it came is kept too where the steps moved it (a step that left for another root's basin loses
// nothing): every candidate is a curve point at its true |z|, so the interior answer and its
// verdict are never worse than the unrefined roots'. `out` holds up to 2 (2n - 1) of them.
template <class Roots, class Real, int N>
void push_refined_curve_height_roots(const LocalBezier<Real>& c, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> z = c.coordinate(2, scale);
  // f(t) and its slope: the height (order 0) or its slope (order 1) along the curve.
  const auto value = [&](int order, Real t, Real& slope) {
    const Vec3<Real> p1 = LocalBezier<Real>::casteljau(c.d1, c.n - 1, t);
    const Vec3<Real> p2 = c.n >= 2 ? LocalBezier<Real>::casteljau(c.d2, c.n - 2, t) : Vec3<Real>::Zero();
    slope = order == 0 ? p1.z() : p2.z();
    return order == 0 ? c.at(t).z() : p1.z();
  };
  const auto refine = [&](int order, Real t) {
    Real slope = 0;
    Real v = value(order, t, slope);
    for (int iteration = 0; iteration < 16 && v != 0 && slope != 0; ++iteration) {
      const Real next = std::min(std::max(t - v / slope, Real(0)), Real(1));
      if (!(next != t)) break;
      Real next_slope = 0;
      const Real next_v = value(order, next, next_slope);
      if (!(std::abs(next_v) < std::abs(v))) break;
      t = next;
      v = next_v;
      slope = next_slope;
    }
    return t;
  };
  for (int order = 0; order < 2; ++order) {
    Candidates<Real, N> roots;
    push_curve_roots<Roots>(order == 0 ? z : z.derivative(), roots);
    for (int i = 0; i < roots.count; ++i) {
      const Real refined = refine(order, roots.value[i]);
      out.push(refined);
      if (refined != roots.value[i]) out.push(roots.value[i]);
    }
  }
}

// Note 001 §3: where x^2 + y^2 = R^2 (the pieces' ends), and z z' = 0 (the inside pieces).
template <class Roots, class Real, int N>
void push_curve_disk_roots(const LocalBezier<Real>& c, Real radius, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> x = c.coordinate(0, scale), y = c.coordinate(1, scale);
  CurvePoly<Real> g = x * x + y * y;
  const Real r = radius / scale;
  g.c[0] -= r * r;
  push_curve_roots<Roots>(g, out);
  push_curve_height_roots<Roots>(c, scale, out);
}

// A piece's candidates against a ring or a disk (Target): its end points; the roots of note 001
// eq. (2) squared (the ring's stationary points); for a disk, the rim crossings and z z' = 0
// (note 001 §3); for a ring, z z' = 0 as well: eq. (2) squared carries the factor x^2 + y^2, so
// on a curve lying along the axis it vanishes identically and has no roots, while the distance
// sqrt(R^2 + z^2) is smallest where z z' = 0; those roots seed the polish there and near it.
// Also an arc's circle's candidates (bezier_arc.hpp).
template <class Roots, class Target, class Real, int N>
void push_curve_round_candidates(const LocalBezier<Real>& piece, Real radius, Real scale, Candidates<Real, N>& out) {
  out.push(Real(0));
  out.push(Real(1));
  if constexpr (Target::interior) push_curve_disk_roots<Roots>(piece, radius, scale, out);
  push_curve_ring_roots<Roots>(piece, radius, scale, out);
  if constexpr (!Target::interior) push_curve_height_roots<Roots>(piece, scale, out);
}

// A curve against a ring or a disk: its candidates (push_curve_round_candidates), polished on
// the target's exact distance.
template <class Real, class Target> struct CurveRoundQuery : CurveRoundBase<Real> {
  static constexpr bool defined = true;
  using Base = CurveRoundBase<Real>;
  using Shape = typename Target::Shape;

  template <class Roots> static auto solve(const LocalBezier<Real>& c, const BezierCurve3<Real>& b,
                                           const Round<Real>& round, Real scale, BestPiece<Real>* where = nullptr) {
    const Real radius = round.radius;
    const auto distance_of = [&](const Vec3<Real>& p) { return Target::distance(p, radius); };
    return Base::solve_pieces(
        c, b, round, scale, distance_of,
        [&](const LocalBezier<Real>& piece, Real s) {
          typename Base::Starts starts;
          push_curve_round_candidates<Roots, Target>(piece, radius, s, starts);
          const auto h = [&](Real t) { return Target::distance(piece.at(t), radius); };
          const auto jet = [&](Real t) { return piece.template jet<Target>(t, radius); };
          return Base::template polish<Roots>(piece, starts, s, h, jet);
        },
        where);
  }

  template <class Roots = DefaultRoots> static Real distance(const BezierCurve3<Real>& b, const Shape& shape) {
    if (b.control.cols() == 0) return std::numeric_limits<Real>::infinity();
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const LocalBezier<Real> c(b, round);
    return solve<Roots>(c, b, round, bezier_round_scale(c, shape.radius)).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const BezierCurve3<Real>& b, const Shape& shape) {
    if (b.control.cols() == 0) return empty_curve_result<Real>();
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const LocalBezier<Real> c(b, round);
    const Real scale = bezier_round_scale(c, shape.radius);
    BestPiece<Real> where;
    const auto minima = solve<Roots>(c, b, round, scale, &where);
    return curve_round_result<Target>(b, c, round, where, minima, scale);
  }
};

}  // namespace circledist::detail
