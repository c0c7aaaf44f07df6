// Double-double arithmetic: a value as an unevaluated sum hi + lo of two Reals, |lo| <= ulp(hi)/2,
// about twice Real's precision (Dekker 1971; Shewchuk 1997 for the error-free transformations).
// Used where a quantity is a small difference of large terms that plain arithmetic cannot hold:
// the pieces of a Bezier curve 1e5 times larger than the round it passes, cut from control
// points 1e5 radii away (precise_bezier.hpp), a line's origin far from a round's center
// (linear.hpp, ExactDifference), and the distance between lines, rays and segments whose defining
// points lie far from where they pass each other (exact_linear.hpp, exact_pair).
#pragma once

#include "../primitives.hpp"

#include <array>
#include <cmath>

namespace circledist::detail {

template <class Real> struct DoubleDouble {
  Real hi = 0, lo = 0;

  DoubleDouble() = default;
  DoubleDouble(Real h, Real l = 0) : hi(h), lo(l) {}

  // a + b exactly, as s + e (Knuth's TwoSum: no assumption on the magnitudes).
  static DoubleDouble two_sum(Real a, Real b) {
    const Real s = a + b;
    const Real bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
  }
  // a + b exactly when |a| >= |b| (Dekker's FastTwoSum), to renormalize.
  static DoubleDouble fast_two_sum(Real a, Real b) {
    const Real s = a + b;
    return {s, b - (s - a)};
  }
  // a * b exactly (the fused multiply-add gives the product's rounding error).
  static DoubleDouble two_product(Real a, Real b) {
    const Real p = a * b;
    return {p, std::fma(a, b, -p)};
  }

  Real value() const { return hi + lo; }

  friend DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
    DoubleDouble s = two_sum(a.hi, b.hi);
    s.lo += a.lo + b.lo;
    return fast_two_sum(s.hi, s.lo);
  }
  friend DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi, -a.lo}; }
  friend DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) { return a + (-b); }
  friend DoubleDouble operator*(const DoubleDouble& a, Real b) {
    DoubleDouble p = two_product(a.hi, b);
    p.lo += a.lo * b;
    return fast_two_sum(p.hi, p.lo);
  }
  // The quotient to about eps^2 relative: the rounded quotient and one correction.
  friend DoubleDouble operator/(const DoubleDouble& a, const DoubleDouble& b) {
    const Real q = a.hi / b.hi;
    const DoubleDouble r = a - b * q;
    return fast_two_sum(q, (r.hi + r.lo) / b.hi);
  }
  // The product to about eps^2 relative: lo * lo is below that and left out.
  friend DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
    DoubleDouble p = two_product(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return fast_two_sum(p.hi, p.lo);
  }
};

// A 3-vector of double-doubles, and the operations every user of one needs (the exact offsets of
// exact_linear.hpp, the local control points of precise_bezier.hpp, linear.hpp's ExactDifference).
template <class Real> using DoubleDouble3 = std::array<DoubleDouble<Real>, 3>;

// x - y exactly, per component (TwoSum): for any type with x[i] and y[i] (Eigen's vectors too).
template <class Real, class X, class Y> DoubleDouble3<Real> exact_difference(const X& x, const Y& y) {
  return {DoubleDouble<Real>::two_sum(x[0], -y[0]), DoubleDouble<Real>::two_sum(x[1], -y[1]),
          DoubleDouble<Real>::two_sum(x[2], -y[2])};
}
template <class Real> DoubleDouble<Real> dot(const DoubleDouble3<Real>& x, const DoubleDouble3<Real>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}
template <class Real> DoubleDouble3<Real> cross(const DoubleDouble3<Real>& x, const DoubleDouble3<Real>& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}
template <class Real> DoubleDouble3<Real> operator-(const DoubleDouble3<Real>& x, const DoubleDouble3<Real>& y) {
  return {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
}
// Each component rounded once to Real.
template <class Real> Vec3<Real> rounded(const DoubleDouble3<Real>& x) {
  return Vec3<Real>(x[0].value(), x[1].value(), x[2].value());
}

}  // namespace circledist::detail
