// A polynomial in one real parameter whose degree follows a Bezier curve's (its coordinates,
// their products and derivatives, up to kMaxCurveDegree): power-basis coefficients, ascending,
// and the arithmetic that builds the curve's equations from its coordinates (local_bezier.hpp).
#pragma once

#include "../roots.hpp"

#include <algorithm>
#include <array>

namespace circledist::detail {

// A polynomial of degree <= kMaxCurveDegree, coefficients ascending.
template <class Real> struct CurvePoly {
  std::array<Real, kMaxCurveDegree + 1> c{};
  int degree = 0;

  CurvePoly derivative() const {
    CurvePoly d;
    d.degree = std::max(degree - 1, 0);
    for (int i = 1; i <= degree; ++i) d.c[i - 1] = i * c[i];
    return d;
  }
};

template <class Real> CurvePoly<Real> operator*(const CurvePoly<Real>& a, const CurvePoly<Real>& b) {
  CurvePoly<Real> p;
  p.degree = a.degree + b.degree;
  for (int i = 0; i <= a.degree; ++i) {
    for (int j = 0; j <= b.degree; ++j) p.c[i + j] += a.c[i] * b.c[j];
  }
  return p;
}

template <class Real> CurvePoly<Real> operator+(const CurvePoly<Real>& a, const CurvePoly<Real>& b) {
  CurvePoly<Real> p;
  p.degree = std::max(a.degree, b.degree);
  for (int i = 0; i <= p.degree; ++i) p.c[i] = a.c[i] + b.c[i];
  return p;
}

// (A const reference and a local copy, here and wherever a function changes a copy of an
// aggregate: built by GCC 12 with -flto, functions that changed an aggregate parameter passed by
// value gave wrong answers, hidden by -fno-ipa-modref; cpp/tests/lto_aggregates.cpp.)
template <class Real> CurvePoly<Real> operator*(Real s, const CurvePoly<Real>& a) {
  CurvePoly<Real> p = a;
  for (int i = 0; i <= p.degree; ++i) p.c[i] *= s;
  return p;
}

template <class Real> CurvePoly<Real> operator-(const CurvePoly<Real>& a, const CurvePoly<Real>& b) {
  return a + Real(-1) * b;
}

}  // namespace circledist::detail
