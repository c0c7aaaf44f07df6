// Trigonometric polynomials of a circle's angle t and the tangent half-angle substitution
// u = tan(t/2), which turns one of degree K into an ordinary polynomial of degree 2K whose real
// roots give the stationary angles (docs/derivations/circle_circle.md). Shared by every query that
// parametrizes a circle by its angle: circle_circle.hpp, circle_disk.hpp, disk_disk.hpp.
#pragma once

#include "../primitives.hpp"
#include "../roots.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace circledist::detail {

// f(t) = c[0] + sum_{k=1..K} (c[k] cos kt + s[k] sin kt). s[0] is always 0.
template <class Real, int K> struct Trig {
  std::array<Real, K + 1> c{}, s{};

  Trig derivative() const {
    Trig d;
    for (int k = 1; k <= K; ++k) {
      d.c[k] = k * s[k];
      d.s[k] = -k * c[k];
    }
    return d;
  }
};

// The product, by cos j cos k = (cos(j+k) + cos(j-k))/2 and the three similar identities.
template <class Real, int J, int K> Trig<Real, J + K> operator*(const Trig<Real, J>& f, const Trig<Real, K>& g) {
  Trig<Real, J + K> h;
  for (int j = 0; j <= J; ++j) {
    for (int k = 0; k <= K; ++k) {
      const Real cc = f.c[j] * g.c[k], ss = f.s[j] * g.s[k], sc = f.s[j] * g.c[k], cs = f.c[j] * g.s[k];
      const int sum = j + k, diff = j >= k ? j - k : k - j;
      const Real sign = j >= k ? Real(1) : Real(-1);  // sin((j-k)t) = sign * sin(diff t)
      h.c[sum] += (cc - ss) / 2;
      h.c[diff] += (cc + ss) / 2;
      h.s[sum] += (sc + cs) / 2;
      h.s[diff] += sign * (sc - cs) / 2;
    }
  }
  h.s[0] = 0;
  return h;
}

template <class Real, int K> Trig<Real, K> operator+(const Trig<Real, K>& f_in, const Trig<Real, K>& g) {
  Trig<Real, K> f = f_in;  // a copy, not a changed by-value parameter (cpp/tests/lto_aggregates.cpp)
  for (int k = 0; k <= K; ++k) {
    f.c[k] += g.c[k];
    f.s[k] += g.s[k];
  }
  return f;
}

template <class Real, int K> Trig<Real, K> operator-(const Trig<Real, K>& f_in, const Trig<Real, K>& g) {
  Trig<Real, K> f = f_in;  // a copy, not a changed by-value parameter (cpp/tests/lto_aggregates.cpp)
  for (int k = 0; k <= K; ++k) {
    f.c[k] -= g.c[k];
    f.s[k] -= g.s[k];
  }
  return f;
}

template <class Real, int K> Trig<Real, K> operator*(Real a, const Trig<Real, K>& g) {
  Trig<Real, K> f = g;
  for (int k = 0; k <= K; ++k) {
    f.c[k] *= a;
    f.s[k] *= a;
  }
  return f;
}

// The tangent half-angle substitution: with u = tan(t/2), cos t = (1-u^2)/(1+u^2) and
// sin t = 2u/(1+u^2), so p(u) = (1+u^2)^K f(t) is a polynomial of degree 2K (ascending
// coefficients) whose real roots are exactly the roots t of f in (-pi, pi). Its leading
// coefficient is f(pi): when t = pi is a root the degree drops, so t = pi is always a candidate.
// (1+u^2)^K cos kt and (1+u^2)^K sin kt are the real and imaginary parts of
// (1 + iu)^(2k) (1+u^2)^(K-k): polynomials with integer coefficients, tabulated at compile time,
// so that the substitution is one small matrix product.
template <int K> struct HalfAngleTable {
  long long cos_part[K + 1][2 * K + 1] = {}, sin_part[K + 1][2 * K + 1] = {};

  constexpr HalfAngleTable() {
    long long re[2 * K + 1] = {}, im[2 * K + 1] = {};  // (1 + iu)^(2k), degree 2k
    re[0] = 1;
    for (int k = 0; k <= K; ++k) {
      // times (1 + u^2)^(K-k), by its binomial coefficients
      long long binomial = 1;
      for (int j = 0, m = K - k; j <= m; ++j) {
        for (int i = 0; i <= 2 * k; ++i) {
          cos_part[k][i + 2 * j] += binomial * re[i];
          sin_part[k][i + 2 * j] += binomial * im[i];
        }
        binomial = binomial * (m - j) / (j + 1);
      }
      long long next_re[2 * K + 1] = {}, next_im[2 * K + 1] = {};  // times (1 - u^2) + i 2u
      for (int i = 0; i <= 2 * k && i + 2 <= 2 * K; ++i) {
        next_re[i] += re[i];
        next_re[i + 2] -= re[i];
        next_re[i + 1] -= 2 * im[i];
        next_im[i] += im[i];
        next_im[i + 2] -= im[i];
        next_im[i + 1] += 2 * re[i];
      }
      for (int i = 0; i <= 2 * K; ++i) {
        re[i] = next_re[i];
        im[i] = next_im[i];
      }
    }
  }
};

template <class Real, int K> std::array<Real, 2 * K + 1> half_angle(const Trig<Real, K>& f) {
  static constexpr HalfAngleTable<K> table{};
  std::array<Real, 2 * K + 1> out{};
  for (int i = 0; i <= 2 * K; ++i) {
    Real sum = 0;
    for (int k = 0; k <= K; ++k) sum += Real(table.cos_part[k][i]) * f.c[k] + Real(table.sin_part[k][i]) * f.s[k];
    out[i] = sum;
  }
  return out;
}

// Appends the angles t = 2 atan(u) of the near-real roots u of a half-angle polynomial p of
// degree <= kMaxDegree, where the caller's intervals of u say they can matter.
template <class Roots, class Real, int N>
void push_half_angle_roots(const Real* p, int degree, const Intervals<Real>& where, Candidates<Real, N>& out) {
  Candidates<Real> roots;
  Roots::roots_in(p, degree, where, roots);
  for (int i = 0; i < roots.count; ++i) out.push(2 * std::atan(roots.value[i]));
}

// The same for the roots of a trigonometric polynomial f, through its half-angle polynomial.
template <class Roots, class Real, int K, int N>
void push_trig_roots(const Trig<Real, K>& f, Candidates<Real, N>& out) {
  static_assert(2 * K <= kMaxDegree, "circledist: trigonometric degree too high for the default root policy");
  const std::array<Real, 2 * K + 1> p = half_angle(f);
  push_half_angle_roots<Roots>(p.data(), 2 * K, Intervals<Real>::everywhere(), out);
}

// The angle in (-pi, pi], the range of atan2 that RingTarget::param uses too.
template <class Real> Real wrap_angle(Real t) {
  const Real pi = pi_v<Real>();
  if (t > -pi && t <= pi) return t;  // the usual case: a polished angle stays near its start
  t = std::remainder(t, 2 * pi);
  return t <= -pi ? t + 2 * pi : t;
}

}  // namespace circledist::detail
