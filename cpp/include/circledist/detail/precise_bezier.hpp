// A Bezier curve's local control points in double-double and its pieces cut by blossoming: the
// pieces of a curve far larger than the round it passes (curve_round_base.hpp, solve_pieces).
#pragma once

#include "planar.hpp"
#include "../primitives.hpp"
#include "double_double.hpp"

#include <algorithm>
#include <array>

namespace circledist::detail {

// The curve's local control points in double-double, and its pieces. A curve far larger than
// the round (1e5 times, or one control point 1e10 away) is solved piece by piece
// (CurveRoundBase::solve_pieces); a piece next to the round has control points of the round's
// size, but computed in plain arithmetic they would carry eps times the curve's farthest control
// point (1e-11 radii for a curve 1e5 times larger), above the bar. Here the control points are
// moved into the round's frame in double-double (the difference from the center exactly, the
// rotation with exact products) and each piece is cut from them in double-double, so a piece's
// points, and the polynomials built from them, are as accurate as a small curve's.
template <class Real> struct PreciseBezier {
  using DD = detail::DoubleDouble<Real>;
  using Point = detail::DoubleDouble3<Real>;
  int n = 0;
  std::array<Point, kMaxBezierDegree + 1> q{};

  PreciseBezier() = default;
  PreciseBezier(const BezierCurve3<Real>& b, const Round<Real>& round) : n(std::max(b.degree(), 0)) {
    const Frame<Real>& f = round.frame;
    const Vec3<Real>* axes[3] = {&f.u, &f.v, &f.n};
    for (int i = 0; i <= n; ++i) {
      const Point offset = detail::exact_difference<Real>(b.control.col(i), round.center);  // P_i - center
      for (int k = 0; k < 3; ++k) {
        DD sum;
        Real small = 0;  // the rotation of the difference's low parts: plain arithmetic suffices
        for (int j = 0; j < 3; ++j) {
          sum = sum + DD::two_product((*axes[k])[j], offset[j].hi);
          small += (*axes[k])[j] * offset[j].lo;
        }
        q[i][k] = sum + DD(small);
      }
    }
  }

  // The piece t in [t0, t1] by blossoming: its k-th control point is the polar form at
  // (t0 x (n - k), t1 x k), de Casteljau's steps with t0 then t1, each from the whole curve's
  // points (repeated halving would carry a far control point's rounding into every piece).
  PreciseBezier piece(Real t0, Real t1) const {
    PreciseBezier out;
    out.n = n;
    for (int k = 0; k <= n; ++k) {
      std::array<Point, kMaxBezierDegree + 1> p = q;
      for (int level = 0; level < n; ++level) {
        const Real t = level < n - k ? t0 : t1;
        for (int i = 0; i + level < n; ++i) p[i] = lerp(p[i], p[i + 1], t);
      }
      out.q[k] = p[0];
    }
    return out;
  }

  Vec3<Real> at(Real t) const {
    std::array<Point, kMaxBezierDegree + 1> p = q;
    for (int k = n; k > 0; --k) {
      for (int i = 0; i < k; ++i) p[i] = lerp(p[i], p[i + 1], t);
    }
    return detail::rounded(p[0]);
  }

  std::array<Vec3<Real>, kMaxBezierDegree + 1> rounded() const {
    std::array<Vec3<Real>, kMaxBezierDegree + 1> out{};
    for (int i = 0; i <= n; ++i) out[i] = detail::rounded(q[i]);
    return out;
  }

 private:
  static Point lerp(const Point& a, const Point& b, Real t) {
    Point out;
    for (int j = 0; j < 3; ++j) out[j] = a[j] + (b[j] - a[j]) * t;
    return out;
  }
};

// Where the best minimum of a curve solved in pieces lies: its piece and the piece's parameter,
// so that its point is evaluated there (at the curve's t, rounded to Real, a point 1e10 radii
// along the curve per unit of t would move by 1e-6 radii per ulp).
template <class Real> struct BestPiece {
  PreciseBezier<Real> piece;
  Real s = 0;
  bool valid = false;
};

}  // namespace circledist::detail
