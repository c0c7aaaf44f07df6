// Bezier curves (degree 1 to 7, t in [0, 1]) against disks and circles: note 001 §3 with
// polynomial curves. In the round's local frame (center subtracted from the control points
// first, exact for translated scenes) the curve is converted to the power basis in w = 2t - 1,
// the variable whose roots of interest lie in [-1, 1], where the power basis is best
// conditioned. Against a disk, [0, 1] is cut where x^2 + y^2 = r^2 (degree 2n); inside pieces
// minimize |z| (z = 0 or z' = 0, degrees n and n-1); outside pieces use note 001 eq. (2)
// squared, degree 6n - 2 (28 for a quintic). Against a circle only the last equation is needed.
// Squaring adds extraneous roots; they are harmless because every candidate is judged (and
// polished) on the exact point-round distance, never on the polynomial.
#pragma once

#include "detail/curve_roots.hpp"
#include "detail/curve_round_base.hpp"
#include "query.hpp"

#include <limits>

namespace circledist {

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
// an annulus's interior candidates (annulus.hpp, docs/annulus.md "A Bezier curve").
template <class Roots, class Real, int N>
void push_curve_height_roots(const LocalBezier<Real>& c, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> z = c.coordinate(2, scale);
  push_curve_roots<Roots>(z, out);
  push_curve_roots<Roots>(z.derivative(), out);
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

  template <class Roots>
  static auto solve(const LocalBezier<Real>& c, const BezierCurve3<Real>& b, const Round<Real>& round, Real scale,
                    BestPiece<Real>* where = nullptr) {
    const Real radius = round.radius;
    const auto distance_of = [&](const Vec3<Real>& p) { return Target::distance(p, radius); };
    return Base::solve_pieces(c, b, round, scale, distance_of, [&](const LocalBezier<Real>& piece, Real s) {
      typename Base::Starts starts;
      push_curve_round_candidates<Roots, Target>(piece, radius, s, starts);
      const auto h = [&](Real t) { return Target::distance(piece.at(t), radius); };
      const auto jet = [&](Real t) { return piece.template jet<Target>(t, radius); };
      return Base::template polish<Roots>(piece, starts, s, h, jet);
    }, where);
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

template <class Real> struct Query<BezierCurve3<Real>, Disk3<Real>> : CurveRoundQuery<Real, DiskTarget<Real>> {};
template <class Real> struct Query<BezierCurve3<Real>, Circle3<Real>> : CurveRoundQuery<Real, RingTarget<Real>> {};

}  // namespace circledist
