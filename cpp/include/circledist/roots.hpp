// Polynomial root policies. Every solver builds a polynomial whose real roots are *candidates*
// for a closest parameter; a policy turns coefficients into candidate parameters. Candidates are
// then polished and judged on the exact distance (see minimize.hpp), so a policy may return a
// superset of the true roots but must never lose a real root, including multiple ones.
#pragma once

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <complex>
#include <limits>

namespace circledist {

// Degree 8 covers the line and circle queries (the circle-disk and circle-circle octics);
// coefficients ascending. Curves need more: a Bezier curve of degree n against a circle gives
// degree 6n - 2, hence kMaxCurveDegree for degree 7.
constexpr int kMaxDegree = 8;
constexpr int kMaxCurveDegree = 40;

// The default capacity holds the roots of one degree-8 polynomial plus a few extra candidates.
// A larger Capacity also lets EigenCompanion solve degrees up to Capacity - 8 (see roots()).
template <class Real, int Capacity = kMaxDegree + 8> struct Candidates {
  static constexpr int capacity = Capacity;
  std::array<Real, Capacity> value{};
  int count = 0;
  void push(Real x) {
    if (count < int(value.size()) && std::isfinite(x)) value[count++] = x;
  }
};

// The degree after dropping leading coefficients that are rounding noise relative to the
// largest one; -1 when the polynomial is identically zero. Eigen's PolynomialSolver asserts on
// a zero leading coefficient, so no solver passes an untrimmed polynomial on.
template <class Real> int trimmed_degree(const Real* c, int degree) {
  Real largest = 0;
  for (int i = 0; i <= degree; ++i) largest = std::max(largest, std::abs(c[i]));
  if (!(largest > 0) || !std::isfinite(largest)) return -1;
  const Real noise = 16 * std::numeric_limits<Real>::epsilon() * largest;
  while (degree > 0 && std::abs(c[degree]) <= noise) --degree;
  return degree;
}

namespace detail {

// Diagonal similarity scaling by powers of two (Parlett-Reinsch): the eigenvalues are
// unchanged and the QR iteration becomes far more accurate for unbalanced companions.
template <class Matrix> void balance(Matrix& a) {
  using Real = typename Matrix::Scalar;
  const Real radix = 2, radix2 = 4;
  const int n = int(a.rows());
  for (bool done = false; !done;) {
    done = true;
    for (int i = 0; i < n; ++i) {
      Real col = 0, row = 0;
      for (int j = 0; j < n; ++j) {
        if (j == i) continue;
        col += std::abs(a(j, i));
        row += std::abs(a(i, j));
      }
      if (col == 0 || row == 0) continue;
      Real g = row / radix, f = 1;
      const Real s = col + row;
      while (col < g) { f *= radix; col *= radix2; }
      g = row * radix;
      while (col > g) { f /= radix; col /= radix2; }
      if ((col + row) / f < Real(0.95) * s) {
        done = false;
        a.row(i) /= f;
        a.col(i) *= f;
      }
    }
  }
}

template <class Real> bool near_real(const std::complex<Real>& z, Real tolerance) {
  return std::abs(z.imag()) <= tolerance * (1 + std::abs(z.real()));
}

// The near-real eigenvalues of the balanced companion matrix of a trimmed polynomial of degree
// >= 3. `Matrix` fixes the storage: the degree-8 one every line/circle query instantiates, or a
// dynamic one for the curve degrees (instantiated only where a large Candidates asks for it).
template <class Matrix, class Real, int Capacity>
void companion_roots(const Real* c, int degree, Real tol, Candidates<Real, Capacity>& out) {
  Matrix companion = Matrix::Zero(degree, degree);
  for (int i = 0; i + 1 < degree; ++i) companion(i + 1, i) = 1;
  for (int i = 0; i < degree; ++i) companion(i, degree - 1) = -c[i] / c[degree];
  balance(companion);
  Eigen::EigenSolver<Matrix> solver(companion, /*computeEigenvectors=*/false);
  if (solver.info() != Eigen::Success) return;
  const auto& eigenvalues = solver.eigenvalues();
  for (int i = 0; i < degree; ++i) {
    const std::complex<Real> z = eigenvalues[i];
    if (near_real(z, tol)) out.push(z.real());
  }
}

}  // namespace detail

// Eigen's polynomial solver scheme (balanced companion matrix, real Schur form by QR), without
// the eigenvectors Eigen's PolynomialSolver computes and never uses. A root is kept when it is
// near-real: a quadruple root (a line whose projection is tangent to the circle) comes back as
// two complex pairs with imaginary parts around eps^(1/4), and `realRoots()` would drop them.
struct EigenCompanion {
  // Relative imaginary part still taken as a real root (covers multiplicity up to 4 in double).
  template <class Real> static Real near_real_tolerance() {
    return std::max(Real(1e-2), Real(8) * std::pow(std::numeric_limits<Real>::epsilon(), Real(0.25)));
  }

  // Appends the real parts of the near-real roots of c[0] + c[1] x + ... + c[degree] x^degree.
  // Degrees up to kMaxDegree always; up to Capacity - 8 when `out` is a larger Candidates (the
  // default Candidates never instantiates the large solver, so line/circle builds do not pay
  // for it). A degree beyond what `out` supports yields no candidates.
  template <class Real, int Capacity>
  static void roots(const Real* coefficients, int degree, Candidates<Real, Capacity>& out) {
    degree = trimmed_degree(coefficients, degree);
    if (degree <= 0) return;
    const Real* c = coefficients;
    const Real tol = near_real_tolerance<Real>();
    if (degree == 1) {
      out.push(-c[0] / c[1]);
      return;
    }
    if (degree == 2) {
      // Stable quadratic formula; a complex pair contributes its real part when near-real.
      const Real disc = c[1] * c[1] - 4 * c[2] * c[0];
      if (disc >= 0) {
        const Real q = -(c[1] + std::copysign(std::sqrt(disc), c[1])) / 2;
        out.push(q / c[2]);
        if (q != 0) out.push(c[0] / q);
        else out.push(Real(0));
      } else {
        const std::complex<Real> z(-c[1] / (2 * c[2]), std::sqrt(-disc) / (2 * std::abs(c[2])));
        if (detail::near_real(z, tol)) out.push(z.real());
      }
      return;
    }
    using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDegree, kMaxDegree>;
    if (degree <= kMaxDegree) {
      detail::companion_roots<Matrix>(c, degree, tol, out);
    } else if constexpr (Capacity > kMaxDegree + 8) {
      if (degree <= Capacity - 8) {
        detail::companion_roots<Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>>(c, degree, tol, out);
      }
    }
  }
};

using DefaultRoots = EigenCompanion;

}  // namespace circledist
