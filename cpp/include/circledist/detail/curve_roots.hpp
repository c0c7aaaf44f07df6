// The roots of a curve's polynomial (curve_poly.hpp) in w in [-1, 1], as curve parameters
// t = (1 + w) / 2: the root policy that takes its degree, and the far root that the eigenvalue
// policies need divided out first.
#pragma once

#include "../roots.hpp"
#include "curve_poly.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace circledist::detail {

// A root policy that can solve the curve degrees: the asked one when it accepts a large
// Candidates, EigenCompanion otherwise.
template <class Roots, class Real, class = void> struct CurveRoots {
  using type = EigenCompanion;
};
template <class Roots, class Real>
struct CurveRoots<Roots, Real,
                  std::void_t<decltype(Roots::roots(std::declval<const Real*>(), 0, Real(0), Real(0),
                                                    std::declval<Candidates<Real, kMaxCurveDegree + 8>&>()))>> {
  using type = Roots;
};

// p without the roots far outside [-1, 1] that a nearly vanishing leading coefficient makes,
// for the policies whose roots are eigenvalues. A curve whose highest power of w
// nearly cancels (nearly point-symmetric about the round's center with even degree, its even
// powers only the float32 rounding of its control points; or nearly of lower degree) gives a
// polynomial whose leading coefficient is 1e-9 of the others, hence one root near 1e7; Eigen's
// real Schur QR on the balanced companion matrix then returned the roots in [-1, 1] as complex
// pairs 0.1 to 0.5 off (LAPACK's QR on the same matrix does not), and EigenCompanion answered
// 0.1713 for a curve 0.1601 from a circle. Such a root is divided out exactly, as long as there
// is one. Where |c_{d-1}| r^(d-1) exceeds the sum of the other |c_i| r^i (here by a third at
// least) for r = |c_{d-1} / c_d| / 4 > 64, p has d - 1 roots inside |w| = r and one beyond
// (Pellet's theorem), real: nothing near [-1, 1] is removed. Its reciprocal v is the small root
// of the reversed polynomial, found by Newton from -c_d / c_{d-1}, and p = (1 - v w) s is
// divided from the constant term, s_i = c_i + v s_{i-1}, where errors shrink by |v| at every
// step (from the leading coefficient they would grow by 1 / |v|). Not a truncation: s has the
// other roots of p (dropping the small leading terms, a change of sqrt(eps) of the coefficients,
// lost a cluster of roots at the end of a piece of a larger curve). Bracketing searches
// [-1, 1] alone and needs none of this.
template <class Real> CurvePoly<Real> without_far_roots(const CurvePoly<Real>& polynomial) {
  CurvePoly<Real> p = polynomial;
  const int trimmed = trimmed_degree(p.c.data(), p.degree);
  if (trimmed < 0) return p;
  p.degree = trimmed;
  while (p.degree >= 3) {
    const int d = p.degree;
    const Real* c = p.c.data();
    const Real r = std::abs(c[d - 1] / c[d]) / 4;
    if (!(r > 64) || !std::isfinite(r)) break;
    Real rest = 0, power = 1;  // sum over i < d - 1 of |c_i| r^(i - (d - 1)), against |c_{d-1}|
    for (int i = d - 2; i >= 0; --i) {
      power /= r;
      rest += std::abs(c[i]) * power;
    }
    if (!(rest < std::abs(c[d - 1]) / 2)) break;
    Real v = -c[d] / c[d - 1];
    for (int iteration = 0; iteration < 16; ++iteration) {
      Real value = 0, slope = 0;  // the reversed polynomial c_d + c_{d-1} v + ... + c_0 v^d
      for (int i = 0; i <= d; ++i) {
        slope = slope * v + value;
        value = value * v + c[i];
      }
      if (!(slope != 0)) break;
      const Real step = value / slope;
      v -= step;
      if (!(std::abs(step) > std::numeric_limits<Real>::epsilon() * std::abs(v))) break;
    }
    if (!(std::abs(v) * r < 1)) break;  // Newton did not reach the root beyond r (or is NaN): p as it is
    CurvePoly<Real> s;
    s.degree = d - 1;
    s.c[0] = c[0];
    for (int i = 1; i < d; ++i) s.c[i] = c[i] + v * s.c[i - 1];
    p = s;
  }
  return p;
}

// Appends t = (1 + w) / 2 for the near-real roots w of p in [-1, 1] (a little slack, clamped:
// a root pushed just outside by rounding still seeds the polish at the end point).
template <class Roots, class Real, int N> void push_curve_roots(const CurvePoly<Real>& p, Candidates<Real, N>& out) {
  Candidates<Real, kMaxCurveDegree + 8> roots;
  const Real slack = Real(1e-3);
  using Policy = typename CurveRoots<Roots, Real>::type;
  if constexpr (!has_accurate_roots<Policy>::value) {
    const CurvePoly<Real> q = without_far_roots(p);
    Policy::roots(q.c.data(), q.degree, -1 - slack, 1 + slack, roots);
  } else {
    Policy::roots(p.c.data(), p.degree, -1 - slack, 1 + slack, roots);
  }
  for (int i = 0; i < roots.count; ++i) {
    const Real w = roots.value[i];
    if (w >= -1 - slack && w <= 1 + slack) out.push(std::min(std::max((1 + w) / 2, Real(0)), Real(1)));
  }
}

}  // namespace circledist::detail
