// A Bezier curve in a round's local frame: its control points and those of its derivatives,
// evaluation and the target's jet along it, its coordinates in the power basis of w = 2t - 1 (the
// polynomials of curve_round_query.hpp and bezier_point.hpp), and the length scale of a curve and a round.
#pragma once

#include "minimize.hpp"
#include "planar.hpp"
#include "../primitives.hpp"
#include "curve_poly.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace circledist::detail {

static_assert(6 * kMaxBezierDegree - 2 <= kMaxCurveDegree, "circledist: curve polynomials exceed kMaxCurveDegree");

// The curve in a round's local frame: control points q_i = frame(P_i - center), and the control
// points of its first and second derivatives in t.
template <class Real> struct LocalBezier {
  int n = 0;
  std::array<Vec3<Real>, kMaxBezierDegree + 1> q{}, d1{}, d2{};
  Real speed = 0;  // max |P'(t)|, bounded by the largest hodograph control point
  Real size = 0;   // max |q_i - q_0|, the curve's extent

  LocalBezier(const BezierCurve3<Real>& b, const Round<Real>& round) : n(std::max(b.degree(), 0)) {
    for (int i = 0; i <= n && i < int(b.control.cols()); ++i) q[i] = round.local(b.control.col(i));
    derive();
  }

  // A curve from its local control points (a piece of another, piece_of below).
  LocalBezier(const std::array<Vec3<Real>, kMaxBezierDegree + 1>& local, int degree) : n(degree), q(local) { derive(); }

  void derive() {
    for (int i = 0; i <= n; ++i) size = std::max(size, (q[i] - q[0]).norm());
    for (int i = 0; i < n; ++i) {
      d1[i] = Real(n) * (q[i + 1] - q[i]);
      speed = std::max(speed, d1[i].norm());
    }
    for (int i = 0; i + 1 < n; ++i) d2[i] = Real(n - 1) * (d1[i + 1] - d1[i]);
  }

  static Vec3<Real> casteljau(std::array<Vec3<Real>, kMaxBezierDegree + 1> p, int m, Real t) {
    for (int k = m; k > 0; --k) {
      for (int i = 0; i < k; ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
    }
    return p[0];
  }

  Vec3<Real> at(Real t) const { return casteljau(q, n, t); }

  // A squared distance's jet at t, `of(P, P', P'')`: a target's with state (an arc's ends,
  // bezier_arc.hpp) as well as a round's (jet below).
  template <class Of> Jet<Real> jet_of(Real t, const Of& of) const {
    const Vec3<Real> p1 = n >= 1 ? casteljau(d1, n - 1, t) : Vec3<Real>::Zero();
    const Vec3<Real> p2 = n >= 2 ? casteljau(d2, n - 2, t) : Vec3<Real>::Zero();
    return of(at(t), p1, p2);
  }

  // The target's (round_target.hpp) squared distance and its derivatives at t.
  template <class Target> Jet<Real> jet(Real t, Real radius) const {
    return jet_of(t, [&](const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2) {
      return Target::jet(p, p1, p2, radius);
    });
  }

  // Coordinate i in the power basis of w = 2t - 1, in units of `scale`:
  // C(n, k) t^k (1-t)^(n-k) = C(n, k) 2^-n (1 + w)^k (1 - w)^(n-k).
  CurvePoly<Real> coordinate(int i, Real scale) const {
    CurvePoly<Real> out;
    out.degree = n;
    Real binomial = 1;  // C(n, k)
    for (int k = 0; k <= n; ++k) {
      std::array<Real, kMaxBezierDegree + 1> basis{};
      basis[0] = 1;
      for (int m = 0; m < n; ++m) {  // times (1 + w) for m < k, then (1 - w)
        const Real sign = m < k ? Real(1) : Real(-1);
        for (int j = m + 1; j > 0; --j) basis[j] = basis[j] + sign * basis[j - 1];
      }
      const Real weight = binomial * std::ldexp(q[k][i] / scale, -n);
      for (int j = 0; j <= n; ++j) out.c[j] += weight * basis[j];
      binomial = binomial * Real(n - k) / Real(k + 1);
    }
    return out;
  }
};

template <class Real> Real bezier_round_scale(const LocalBezier<Real>& c, Real radius) {
  Real s = radius;
  for (int i = 0; i <= c.n; ++i) s = std::max(s, c.q[i].norm());
  return s > 0 ? s : Real(1);
}

}  // namespace circledist::detail
