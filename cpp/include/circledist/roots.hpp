// Polynomial root policies. Every solver builds a polynomial whose real roots are *candidates*
// for a closest parameter; a policy turns coefficients into candidate parameters. Candidates are
// then polished and judged on the exact distance (see detail/minimize.hpp), so a policy may return a
// superset of the true roots but must never lose a real root, including multiple ones.
//
// The two entry points of a policy:
//   Policy::roots(c, degree, lo, hi, out)
// appends candidates for the real roots of c[0] + c[1] x + ... + c[degree] x^degree in [lo, hi]
// (either end may be infinite). The interval is the caller's promise that no root outside it
// matters: bracketing searches only there, the companion policies find every root anyway.
//   Policy::bracketed_root(c, degree, lo, hi, p_lo, p_hi)
// returns the one root in the finite [lo, hi], where the caller knows that p changes sign
// nowhere else in between and gives p(lo) <= 0 <= p(hi) (from a closed form: more accurate than
// Horner there, and free; a line's minima over a ring, detail/line_ring_minimum.hpp). Where p_lo
// is not below zero, lo is the root and is returned as it is.
//   Policy::roots_in(c, degree, intervals, out)
// is roots() for a union of disjoint intervals (one polynomial solve, however many pieces):
// bracketing searches each piece, the companion policies solve once and keep the roots inside.
#pragma once

#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace circledist {

// How candidates are moved to a local minimum of the exact distance (detail/minimize.hpp):
//   Newton: Newton steps on the exact squared distance, a bracketed search only where they fail;
//   Bracketed: a bracketed (Brent) minimization of the exact distance around every candidate,
//     finished by the Newton steps that lower it (a crossing, distance 0, is a V in the distance).
// A policy says which by `Policy::polish()`, a constant for every policy but
// SelectedEigenPolicy, which reads the calling thread's choice.
enum class Polish { Newton, Bracketed };

// Whether a policy returns every root to rounding (Roots::accurate_roots = true), so that a
// candidate's start value tells how low it can lead (screening_margin, detail/angle_polish.hpp).
// Policies that do not say are taken as not accurate.
template <class Roots, class = void> struct has_accurate_roots : std::false_type {};
template <class Roots> struct has_accurate_roots<Roots, std::enable_if_t<Roots::accurate_roots>> : std::true_type {};

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

// Disjoint intervals [lo[i], hi[i]] in increasing order; the outer ends may be infinite.
template <class Real> struct Intervals {
  static constexpr int capacity = 9;
  std::array<Real, capacity> lo{}, hi{};
  int count = 0;

  static Intervals everywhere() {
    Intervals all;
    all.add(-std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::infinity());
    return all;
  }
  // Appends [a, b] (a >= the last hi), merged with the last interval where they touch.
  void add(Real a, Real b) {
    if (count > 0 && hi[count - 1] >= a) {
      hi[count - 1] = std::max(hi[count - 1], b);
    } else if (count < capacity) {
      lo[count] = a;
      hi[count] = b;
      ++count;
    }
  }
  bool contains(Real x) const {
    for (int i = 0; i < count; ++i)
      if (x >= lo[i] && x <= hi[i]) return true;
    return false;
  }
  // The parts of these intervals that lie in `other`'s (both sorted and disjoint); these whole
  // where the parts would not fit (a superset: searching more is never wrong).
  Intervals within(const Intervals& other) const {
    Intervals out;
    int i = 0, j = 0, pieces = 0;
    while (i < count && j < other.count) {
      const Real a = std::max(lo[i], other.lo[j]), b = std::min(hi[i], other.hi[j]);
      if (a <= b) {
        if (++pieces > capacity) return *this;
        out.add(a, b);
      }
      if (hi[i] < other.hi[j])
        ++i;
      else
        ++j;
    }
    return out;
  }
};

// roots_in for the policies that find every root anyway: one solve, every root kept. Their
// roots of an ill-conditioned polynomial can err by more than the intervals are wide (a circle
// 1e4 times larger than the disk it passes: roots 4e-5 apart in u, found 1e-4 off), so keeping
// only the roots inside would drop the one that leads to the minimum; every root is a candidate
// judged on the exact distance anyway, and the intervals are the Bracketing policy's saving.
template <class Roots, class Real, int Capacity>
void roots_kept_in(const Real* c, int degree, const Intervals<Real>&, Candidates<Real, Capacity>& out) {
  const Real inf = std::numeric_limits<Real>::infinity();
  Roots::roots(c, degree, -inf, inf, out);
}

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

// std::ilogb(x), read from the bits for a normal IEEE double (the same value without a library
// call: root bounds and polynomial scaling take one per coefficient).
template <class Real> int binade(Real x) {
  if constexpr (std::numeric_limits<Real>::is_iec559 && sizeof(Real) == sizeof(std::uint64_t) &&
                std::numeric_limits<Real>::digits == 53) {
    const Real magnitude = std::abs(x);
    if (magnitude >= std::numeric_limits<Real>::min() && magnitude <= std::numeric_limits<Real>::max()) {
      std::uint64_t bits;
      std::memcpy(&bits, &magnitude, sizeof bits);
      return int((bits >> 52) & 0x7ff) - 1023;
    }
  }
  return std::ilogb(x);
}

// x 2^e (std::ldexp) for every x of p, by one multiplication where 2^e is a normal number (the
// same values: a product with a power of two is rounded once, as ldexp's result is).
template <class Real> void scale_by_power_of_two(Real* p, int n, int e) {
  if (e > std::numeric_limits<Real>::min_exponent && e < std::numeric_limits<Real>::max_exponent - 1) {
    const Real factor = std::ldexp(Real(1), e);
    for (int i = 0; i < n; ++i) p[i] *= factor;
  } else {
    for (int i = 0; i < n; ++i) p[i] = std::ldexp(p[i], e);
  }
}

template <class Real>
Real halley_bisection(const Real* c, int n, Real a, Real b, Real pa, Real x, Real rel_tol, Real abs_tol);

// The two real roots of c0 + c1 x + c2 x^2 (c2 != 0, discriminant `disc` >= 0) by the stable
// formula: q = -(c1 + sign(c1) sqrt(disc)) / 2, roots q / c2 and c0 / q (0 when q is 0, a double
// root at 0).
// c0, c1, c2 scaled by one power of two (exact; the roots do not change) to a largest magnitude
// in [1, 2): the discriminant c1^2 - 4 c2 c0 would overflow for coefficients past 1e154 and
// vanish into the subnormals below 1e-154. Returns the discriminant of the scaled coefficients.
template <class Real> Real balanced_quadratic(const Real* c, Real out[3]) {
  const Real largest = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
  const int e = largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
  for (int i = 0; i < 3; ++i) out[i] = e != 0 ? std::ldexp(c[i], -e) : c[i];
  return out[1] * out[1] - 4 * out[2] * out[0];
}

template <class Real> void stable_quadratic_roots(Real c0, Real c1, Real c2, Real disc, Real r[2]) {
  const Real q = -(c1 + std::copysign(std::sqrt(disc), c1)) / 2;
  r[0] = q / c2;
  r[1] = q != 0 ? c0 / q : Real(0);
}

// p(x) by Horner's scheme, with p'(x) in `slope` from the same pass.
template <class Real> Real horner_with_slope(const Real* c, int n, Real x, Real& slope) {
  Real v = c[n];
  slope = 0;
  for (int i = n - 1; i >= 0; --i) {
    slope = slope * x + v;
    v = v * x + c[i];
  }
  return v;
}

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
      while (col < g) {
        f *= radix;
        col *= radix2;
      }
      g = row * radix;
      while (col > g) {
        f /= radix;
        col /= radix2;
      }
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
// False when Eigen's real Schur iteration did not converge: then it has no eigenvalues at all.
template <class Matrix, class Real, int Capacity>
bool companion_roots(const Real* c, int degree, Real tol, Candidates<Real, Capacity>& out) {
  Matrix companion = Matrix::Zero(degree, degree);
  for (int i = 0; i + 1 < degree; ++i) companion(i + 1, i) = 1;
  for (int i = 0; i < degree; ++i) companion(i, degree - 1) = -c[i] / c[degree];
  balance(companion);
  Eigen::EigenSolver<Matrix> solver(companion, /*computeEigenvectors=*/false);
  if (solver.info() != Eigen::Success) return false;
  const auto& eigenvalues = solver.eigenvalues();
  for (int i = 0; i < degree; ++i) {
    const std::complex<Real> z = eigenvalues[i];
    if (near_real(z, tol)) out.push(z.real());
  }
  return true;
}

// The real roots of a trimmed polynomial (degree >= 1) whose companion matrix the QR iteration
// could not reduce (below): found without eigenvalues, by the bracketing policy's isolation over
// the root bound, or none where that finds more values than a polynomial of this degree has
// roots (rounding noise) or the degree is beyond its buffers. Defined after isolate_roots.
template <class Real, int Capacity>
void roots_without_eigenvalues(const Real* c, int degree, Candidates<Real, Capacity>& out);

// A few Newton steps on p from x, kept only while |p| decreases (multiple roots converge slowly
// and are left to the distance polish).
template <class Real> Real newton_on_polynomial(const Real* c, int n, Real x) {
  Real slope = 0;
  Real v = horner_with_slope(c, n, x, slope);
  for (int iteration = 0; iteration < 8 && v != 0 && slope != 0; ++iteration) {
    const Real next = x - v / slope;
    Real next_slope = 0;
    const Real next_v = horner_with_slope(c, n, next, next_slope);
    if (!(std::abs(next_v) < std::abs(v))) break;
    x = next;
    v = next_v;
    slope = next_slope;
  }
  return x;
}

}  // namespace detail

// Eigen's polynomial solver scheme (balanced companion matrix, real Schur form by QR), without
// the eigenvectors Eigen's PolynomialSolver computes and never uses. A root is kept when it is
// near-real: a quadruple root (a line whose projection is tangent to the circle) comes back as
// two complex pairs with imaginary parts around eps^(1/4), and `realRoots()` would drop them.
struct EigenCompanion {
  static constexpr Polish polish() { return Polish::Newton; }

  // Relative imaginary part still taken as a real root (covers multiplicity up to 4 in double).
  template <class Real> static Real near_real_tolerance() {
    return std::max(Real(1e-2), Real(8) * std::pow(std::numeric_limits<Real>::epsilon(), Real(0.25)));
  }

  // Appends the real parts of the near-real roots of c[0] + c[1] x + ... + c[degree] x^degree.
  // Degrees up to kMaxDegree always; up to Capacity - 8 when `out` is a larger Candidates (the
  // default Candidates never instantiates the large solver, so line/circle builds do not pay
  // for it). A degree beyond what `out` supports yields no candidates.
  template <class Real, int Capacity>
  static void roots(const Real* coefficients, int degree, Real /*lo*/, Real /*hi*/, Candidates<Real, Capacity>& out) {
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
      Real q[3];
      const Real disc = detail::balanced_quadratic(c, q);
      if (disc >= 0) {
        Real r[2];
        detail::stable_quadratic_roots(q[0], q[1], q[2], disc, r);
        out.push(r[0]);
        out.push(r[1]);
      } else {
        const std::complex<Real> z(-q[1] / (2 * q[2]), std::sqrt(-disc) / (2 * std::abs(q[2])));
        if (detail::near_real(z, tol)) out.push(z.real());
      }
      return;
    }
    // Eigen's real Schur iteration can stall: the balanced companion of the even, palindromic
    // octic of a circle through the other ring's axis at two opposite angles (double roots at
    // u = +-1, simple ones at u and -u) gave NoConvergence after its iteration limit, and no
    // roots at all (tests/accuracy/test_regressions.py, circle through a ring's axis). Such a polynomial's
    // roots come from detail::roots_without_eigenvalues.
    using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDegree, kMaxDegree>;
    bool converged = true;
    if (degree <= kMaxDegree) {
      converged = detail::companion_roots<Matrix>(c, degree, tol, out);
    } else if constexpr (Capacity > kMaxDegree + 8) {
      if (degree <= Capacity - 8) {
        converged = detail::companion_roots<Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>>(c, degree, tol, out);
      }
    }
    if (!converged) detail::roots_without_eigenvalues(c, degree, out);
  }

  template <class Real, int Capacity>
  static void roots_in(const Real* c, int degree, const Intervals<Real>& intervals, Candidates<Real, Capacity>& out) {
    roots_kept_in<EigenCompanion>(c, degree, intervals, out);
  }

  template <class Real> static Real bracketed_root(const Real* c, int degree, Real lo, Real hi, Real p_lo, Real p_hi) {
    return eigenvalue_bracketed_root<EigenCompanion>(c, degree, lo, hi, p_lo, p_hi);
  }

  // For the policies whose roots are eigenvalues: a near-real root inside [lo, hi]. Where the
  // eigenvalues put none there (a root at the bracket's end, 1e-17 from lo, computed a little
  // outside it), the sign change the caller guarantees is searched by safeguarded Halley instead:
  // a clamped or midpoint answer would be no root at all.
  template <class Policy, class Real>
  static Real eigenvalue_bracketed_root(const Real* c, int degree, Real lo, Real hi, Real p_lo, Real p_hi) {
    if (!(p_lo < 0)) return lo;
    Candidates<Real> all;
    Policy::roots(c, degree, lo, hi, all);
    for (int i = 0; i < all.count; ++i)
      if (all.value[i] >= lo && all.value[i] <= hi) return all.value[i];
    Real x = lo - p_lo * (hi - lo) / (p_hi - p_lo);
    if (!(x > lo && x < hi)) x = lo;
    return detail::halley_bisection(c, degree, lo, hi, p_lo, x, 2 * std::numeric_limits<Real>::epsilon(), Real(0));
  }
};

// Eigen's own solver, Eigen::PolynomialSolver (unsupported/Eigen/Polynomials), called as it is:
// the design card's solver. EigenCompanion is the same scheme without the eigenvectors and the
// dynamic allocations, about 3x faster for the same roots (docs/reports/accuracy_vs_time.md). Eigen
// asserts on a zero leading coefficient, so the polynomial is trimmed first. Its realRoots()
// keeps roots whose imaginary part is below an absolute 1e-12: a tangency's quadruple root
// comes back with imaginary parts near eps^(1/4) = 1e-4 and would be lost, so the near-real
// filter of EigenCompanion (relative, up to multiplicity 4) is applied to roots() instead.
struct EigenPolynomialSolver {
  static constexpr Polish polish() { return Polish::Newton; }

  template <class Real, int Capacity>
  static void roots(const Real* coefficients, int degree, Real /*lo*/, Real /*hi*/, Candidates<Real, Capacity>& out) {
    degree = trimmed_degree(coefficients, degree);
    if (degree <= 0) return;
    const Eigen::Matrix<Real, Eigen::Dynamic, 1> polynomial =
        Eigen::Map<const Eigen::Matrix<Real, Eigen::Dynamic, 1>>(coefficients, degree + 1);
    const Eigen::PolynomialSolver<Real, Eigen::Dynamic> solver(polynomial);
    // Eigen's solver does not report an iteration that did not converge (EigenCompanion above):
    // its eigenvalue solver then leaves the roots unset, none instead of `degree` of them.
    if (solver.roots().size() != degree || !solver.roots().allFinite()) {
      detail::roots_without_eigenvalues(coefficients, degree, out);
      return;
    }
    const Real tol = EigenCompanion::near_real_tolerance<Real>();
    for (Eigen::Index i = 0; i < solver.roots().size(); ++i)
      if (detail::near_real(std::complex<Real>(solver.roots()[i]), tol)) out.push(solver.roots()[i].real());
  }

  template <class Real, int Capacity>
  static void roots_in(const Real* c, int degree, const Intervals<Real>& intervals, Candidates<Real, Capacity>& out) {
    roots_kept_in<EigenPolynomialSolver>(c, degree, intervals, out);
  }

  template <class Real> static Real bracketed_root(const Real* c, int degree, Real lo, Real hi, Real p_lo, Real p_hi) {
    return EigenCompanion::eigenvalue_bracketed_root<EigenPolynomialSolver>(c, degree, lo, hi, p_lo, p_hi);
  }
};

// EigenCompanion's roots, each refined by Newton steps on the polynomial, then polished by a
// bracketed minimization of the exact distance: the most careful, and the slowest.
struct EigenPolished {
  static constexpr Polish polish() { return Polish::Bracketed; }

  template <class Real, int Capacity>
  static void roots(const Real* coefficients, int degree, Real lo, Real hi, Candidates<Real, Capacity>& out) {
    const int first = out.count;
    EigenCompanion::roots(coefficients, degree, lo, hi, out);
    degree = trimmed_degree(coefficients, degree);
    for (int i = first; i < out.count; ++i)
      out.value[i] = detail::newton_on_polynomial(coefficients, degree, out.value[i]);
  }

  template <class Real, int Capacity>
  static void roots_in(const Real* c, int degree, const Intervals<Real>& intervals, Candidates<Real, Capacity>& out) {
    roots_kept_in<EigenPolished>(c, degree, intervals, out);
  }

  // EigenCompanion's root, refined by safeguarded Halley in the bracket.
  template <class Real> static Real bracketed_root(const Real* c, int degree, Real lo, Real hi, Real p_lo, Real p_hi) {
    if (!(p_lo < 0)) return lo;
    const Real x = EigenCompanion::bracketed_root(c, degree, lo, hi, p_lo, p_hi);
    const Real eps = std::numeric_limits<Real>::epsilon();
    return detail::halley_bisection(c, degree, lo, hi, p_lo, x, 2 * eps, Real(0));
  }
};

namespace detail {

template <class Real> Real horner(const Real* c, int n, Real x) {
  Real v = c[n];
  for (int i = n - 1; i >= 0; --i) v = v * x + c[i];
  return v;
}

// A bound on the rounding error of evaluating p (degree n) at x, from size = sum |c_i| |x|^i,
// generously inflated to cover the rounding already in the coefficients.
template <class Real> Real rounding_bound(int n, Real size) {
  return Real(64) * (n + 1) * std::numeric_limits<Real>::epsilon() * size;
}

// That bound for Horner's scheme.
template <class Real> Real horner_error(const Real* c, int n, Real x) {
  Real v = std::abs(c[n]);
  const Real ax = std::abs(x);
  for (int i = n - 1; i >= 0; --i) v = v * ax + std::abs(c[i]);
  return rounding_bound(n, v);
}

// What one pass of the root search needs at x: p(x), p'(x), p''(x) / 2, and sum |c_i| |x|^i,
// which bounds the rounding of p(x).
template <class Real> struct PassValues {
  Real value, slope, half_curvature, size;
};

// Horner's scheme, any degree: the four values from one pass over the coefficients.
template <class Real> struct HornerPass {
  const Real* c;
  int n;

  PassValues<Real> operator()(Real x) const {
    Real value = c[n], slope = 0, half_curvature = 0, size = std::abs(c[n]);
    const Real ax = std::abs(x);
    for (int i = n - 1; i >= 0; --i) {
      half_curvature = half_curvature * x + slope;
      slope = slope * x + value;
      value = value * x + c[i];
      size = size * ax + std::abs(c[i]);
    }
    return {value, slope, half_curvature, size};
  }
};

// c[0] + c[1] x + ... + c[N] x^N by Estrin's scheme (x2 = x^2, x4 = x^4): pairs, then pairs of
// pairs. Horner's chain of N multiply-adds is latency-bound (no FMA without -mfma); this one is
// log2(N) deep, and its rounding obeys the same kind of bound, a small multiple of
// eps sum |c_i| |x|^i.
template <int N, class Real> Real estrin(const Real* c, Real x, Real x2, Real x4) {
  if constexpr (N == 0) {
    return c[0];
  } else if constexpr (N == 1) {
    return c[0] + c[1] * x;
  } else if constexpr (N <= 3) {
    return (c[0] + c[1] * x) + x2 * estrin<N - 2>(c + 2, x, x2, x4);
  } else if constexpr (N <= 7) {
    return estrin<3>(c, x, x2, x4) + x4 * estrin<N - 4>(c + 4, x, x2, x4);
  } else {
    return estrin<7>(c, x, x2, x4) + (x4 * x4) * estrin<N - 8>(c + 8, x, x2, x4);
  }
}

// The same four values for a fixed degree N (3..8, every line and circle query), by Estrin's
// scheme on the coefficients of p, p' and p''/2 (formed once per search) and of |p|: about a
// third faster per pass than Horner.
template <int N, class Real> struct EstrinPass {
  const Real* c;
  Real d1[N], d2[N - 1], magnitude[N + 1];

  explicit EstrinPass(const Real* coefficients) : c(coefficients) {
    for (int i = 0; i <= N; ++i) magnitude[i] = std::abs(c[i]);
    for (int i = 0; i < N; ++i) d1[i] = Real(i + 1) * c[i + 1];
    for (int i = 0; i + 1 < N; ++i) d2[i] = Real((i + 1) * (i + 2) / 2) * c[i + 2];
  }

  PassValues<Real> operator()(Real x) const {
    const Real x2 = x * x, x4 = x2 * x2, ax = std::abs(x);
    return {estrin<N>(c, x, x2, x4), estrin<N - 1>(d1, x, x2, x4), estrin<N - 2>(d2, x, x2, x4),
            estrin<N>(magnitude, ax, x2, x4)};
  }
};

// p(x) and horner_error's bound on its rounding, by Estrin's scheme for the degrees 3..8.
template <int N, class Real> Real estrin_with_error(const Real* c, Real x, Real& error) {
  Real magnitude[N + 1];
  for (int i = 0; i <= N; ++i) magnitude[i] = std::abs(c[i]);
  const Real x2 = x * x, x4 = x2 * x2;
  error = rounding_bound(N, estrin<N>(magnitude, std::abs(x), x2, x4));
  return estrin<N>(c, x, x2, x4);
}

// p(x) by Estrin's scheme for the degrees 1..8, Horner's beyond.
template <class Real> Real polynomial_value(const Real* c, int n, Real x) {
  const Real x2 = x * x, x4 = x2 * x2;
  switch (n) {
    case 1:
      return estrin<1>(c, x, x2, x4);
    case 2:
      return estrin<2>(c, x, x2, x4);
    case 3:
      return estrin<3>(c, x, x2, x4);
    case 4:
      return estrin<4>(c, x, x2, x4);
    case 5:
      return estrin<5>(c, x, x2, x4);
    case 6:
      return estrin<6>(c, x, x2, x4);
    case 7:
      return estrin<7>(c, x, x2, x4);
    case 8:
      return estrin<8>(c, x, x2, x4);
    default:
      return horner(c, n, x);
  }
}

template <class Real> Real value_with_error(const Real* c, int n, Real x, Real& error) {
  switch (n) {
    case 3:
      return estrin_with_error<3>(c, x, error);
    case 4:
      return estrin_with_error<4>(c, x, error);
    case 5:
      return estrin_with_error<5>(c, x, error);
    case 6:
      return estrin_with_error<6>(c, x, error);
    case 7:
      return estrin_with_error<7>(c, x, error);
    case 8:
      return estrin_with_error<8>(c, x, error);
    default:
      error = horner_error(c, n, x);
      return horner(c, n, x);
  }
}

// The root of p in (a, b), from x in (a, b), where p(a) and p(b) have opposite signs and p is
// monotonic, to a relative accuracy of `rel_tol`, an absolute one of `abs_tol` (roots near 0
// would otherwise take bisection steps down to the smallest numbers), or until p(x) is zero
// within its rounding (closer than that, the steps are rounding noise and the bracket shrinks
// one side only). Halley steps (cubic convergence; p'' comes from the same pass, so a step
// costs little more than Newton's and about one pass in four is saved), Newton's where
// Halley's denominator is not positive and finite. `pass(x)` gives PassValues for degree n.
template <class Real, class Pass>
Real halley_search(const Pass& pass, int n, Real a, Real b, Real pa, Real x, Real rel_tol, Real abs_tol) {
  const Real eps = std::numeric_limits<Real>::epsilon();
  // A step that leaves the bracket is replaced by the bracket's midpoint, which halves it.
  for (int iteration = 0; iteration < 100; ++iteration) {
    const PassValues<Real> v = pass(x);
    const Real px = v.value, slope = v.slope, half_curvature = v.half_curvature;
    if (std::abs(px) <= 2 * n * eps * v.size) return x;
    if ((px < 0) == (pa < 0)) {
      a = x;
      pa = px;
    } else {
      b = x;
    }
    const Real tol = rel_tol * std::abs(x) + abs_tol;
    const Real denominator = slope * slope - px * half_curvature;
    Real next = (a + b) / 2;
    if (denominator > 0 && denominator < std::numeric_limits<Real>::infinity()) {
      next = x - px * slope / denominator;
    } else if (slope != 0) {
      next = x - px / slope;
    }
    // Converged: the last step may land just past the end the iterate became.
    if (std::abs(next - x) <= tol) return std::min(std::max(next, a), b);
    // Newton's next error would be (p'' / 2p') step^2, Halley's is smaller still: once that is
    // below tol the step is the answer, without another pass to confirm it (taken only for small
    // steps, where the model holds).
    const Real step = next - x;
    if (next > a && next < b && std::abs(step) <= Real(1e-4) * (std::abs(x) + abs_tol) &&
        std::abs(half_curvature) * step * step <= tol * std::abs(slope))
      return next;
    if (!(next > a && next < b)) next = (a + b) / 2;
    if (b - a <= 2 * tol) return next;
    x = next;
  }
  return x;
}

// halley_search with Estrin passes for the degrees of the line and circle queries, Horner's
// for the rest (curves).
template <class Real>
Real halley_bisection(const Real* c, int n, Real a, Real b, Real pa, Real x, Real rel_tol, Real abs_tol) {
  switch (n) {
    case 3:
      return halley_search(EstrinPass<3, Real>(c), n, a, b, pa, x, rel_tol, abs_tol);
    case 4:
      return halley_search(EstrinPass<4, Real>(c), n, a, b, pa, x, rel_tol, abs_tol);
    case 5:
      return halley_search(EstrinPass<5, Real>(c), n, a, b, pa, x, rel_tol, abs_tol);
    case 6:
      return halley_search(EstrinPass<6, Real>(c), n, a, b, pa, x, rel_tol, abs_tol);
    case 7:
      return halley_search(EstrinPass<7, Real>(c), n, a, b, pa, x, rel_tol, abs_tol);
    case 8:
      return halley_search(EstrinPass<8, Real>(c), n, a, b, pa, x, rel_tol, abs_tol);
    default:
      return halley_search(HornerPass<Real>{c, n}, n, a, b, pa, x, rel_tol, abs_tol);
  }
}

// Room for what isolate_roots returns at one level: the roots and the critical points where p
// vanishes within rounding. In exact arithmetic that is at most 2n - 1 values, but rounding
// noise (a polynomial dominated by one huge coefficient) can show more sign changes than roots.
constexpr int kIsolateCapacity = 2 * kMaxCurveDegree + 8;

// Appends the real roots of c (degree n >= 1, c[n] != 0) in [lo, hi] in increasing order, and
// the critical points there at which p vanishes within rounding; roots to a relative accuracy
// `rel_tol` (2 eps for the answer) and an absolute one of rel_tol * min(1, (hi - lo) / 2): the
// callers' variables are O(1) where roots cluster (a half angle, a line parameter in units of
// the scene, a curve's [-1, 1]), and an interval widened by a root bound (up to 1e9 for a
// nearly vanishing leading coefficient) must not widen the tolerance with it, or close roots
// merge. The critical points only need sqrt(eps): an error delta in one changes p there by
// p'' delta^2 / 2, within the rounding its sign test allows for. `out` holds `capacity` values;
// false when more were found (noise): the caller then finds the roots another way.
template <class Real>
bool isolate_roots(const Real* c, int n, Real lo, Real hi, Real rel_tol, Real* out, int& count, int capacity) {
  bool room = true;
  const auto push = [&](Real x) {
    if (count < capacity) {
      out[count++] = x;
    } else {
      room = false;
    }
  };
  if (n == 1) {
    const Real x = -c[0] / c[1];
    if (x >= lo && x <= hi) push(x);
    return room;
  }
  if (n == 2) {
    // Closed form: the stable quadratic formula, or the vertex when p nearly touches zero there.
    Real q[3];
    const Real disc = balanced_quadratic(c, q);
    Real r[2];
    int k = 0;
    if (disc > 0) {
      stable_quadratic_roots(q[0], q[1], q[2], disc, r);
      if (r[0] > r[1]) std::swap(r[0], r[1]);
      k = 2;
    } else {
      const Real vertex = -q[1] / (2 * q[2]);
      if (std::abs(horner(q, 2, vertex)) <= horner_error(q, 2, vertex)) r[k++] = vertex;
    }
    for (int i = 0; i < k; ++i)
      if (r[i] >= lo && r[i] <= hi) push(r[i]);
    return room;
  }
  Real dc[kMaxCurveDegree];
  for (int i = 0; i < n; ++i) dc[i] = (i + 1) * c[i + 1];
  Real critical[kIsolateCapacity];
  int critical_count = 0;
  const Real coarse = std::sqrt(std::numeric_limits<Real>::epsilon());
  if (!isolate_roots(dc, n - 1, lo, hi, coarse, critical, critical_count, kIsolateCapacity)) return false;

  // Where to start Newton in [a, b]. Next to a critical end c the false-position point sits
  // where p' is nearly 0, and the first Newton step flies far off (then the steps only halve the
  // distance back). The quadratic model there, p(c) + p''(c) (x - c)^2 / 2, vanishes at
  // c +- sqrt(-2 p(c) / p''(c)): a start close to the root. From the critical end with the
  // smaller |p|, else (the model has no root there: NaN or outside) false position.
  Real ddc[kMaxCurveDegree];  // p''
  for (int i = 0; i + 1 < n && critical_count > 0; ++i) ddc[i] = (i + 1) * dc[i + 1];
  const auto start = [&](Real a, Real b, Real pa, Real pb, bool a_critical, bool b_critical) {
    const bool from_a = a_critical && (!b_critical || std::abs(pa) <= std::abs(pb));
    if (from_a || b_critical) {
      const Real e = from_a ? a : b, pe = from_a ? pa : pb;
      const Real curvature = polynomial_value(ddc, n - 2, e);
      const Real step = std::sqrt(-2 * pe / curvature);
      const Real x = from_a ? e + step : e - step;
      if (x > a && x < b) return x;
    }
    const Real x = a - pa * (b - a) / (pb - pa);
    return x > a && x < b ? x : (a + b) / 2;
  };
  // Relative accuracy down to the smallest normal numbers (a root of 6.7e-16 is wanted to its
  // own digits, not to eps); the search also stops where p is zero within rounding.
  const Real abs_tol = std::numeric_limits<Real>::min();
  Real error = 0;
  Real a = lo, pa = value_with_error(c, n, lo, error);
  // An end where p vanishes within rounding may be a root whose value did not round to 0.
  if (std::abs(pa) <= error) push(lo);
  for (int k = 0; k <= critical_count; ++k) {
    const Real b = k < critical_count ? critical[k] : hi;
    const Real pb = value_with_error(c, n, b, error);
    if ((pa < 0 && pb > 0) || (pa > 0 && pb < 0)) {
      const Real x = start(a, b, pa, pb, k > 0, k < critical_count);
      push(halley_bisection(c, n, a, b, pa, x, rel_tol, abs_tol));
    }
    if (k < critical_count && std::abs(pb) <= error) {
      if (count == 0 || out[count - 1] != b) push(b);
    } else if (k == critical_count && std::abs(pb) <= error && (count == 0 || out[count - 1] != b)) {
      push(b);
    }
    a = b;
    pa = pb;
  }
  return room;
}

// Fujiwara's bound, 2 max |c_i / c_n|^(1 / (n - i)) (the i = 0 term halved), rounded up to a
// power of two through the exponents alone (no pow): every root lies in [-bound, bound]. Far
// tighter than Cauchy's when the coefficients are unbalanced.
template <class Real> Real root_bound(const Real* c, int n) {
  int exponent = std::numeric_limits<int>::min();
  for (int i = 0; i < n; ++i) {
    const Real ratio = std::abs(c[i] / c[n]) / (i == 0 ? 2 : 1);
    if (!(ratio > 0)) continue;
    const int e = binade(ratio) + 1, k = n - i;  // ratio < 2^e, so ratio^(1/k) < 2^ceil(e/k)
    exponent = std::max(exponent, e >= 0 ? (e + k - 1) / k : -((-e) / k));
  }
  return exponent == std::numeric_limits<int>::min() ? Real(1) : std::ldexp(Real(2), exponent);
}

// The roots of a trimmed polynomial in [lo, hi] to a relative 2 eps, and its critical points
// there where it vanishes within rounding (isolate_roots), into `found` (kIsolateCapacity
// values); false where the degree is beyond isolate_roots' buffers or it found more values than
// they hold (rounding noise). The Bracketing policy's search, and the eigenvalue policies'
// fallback (roots_without_eigenvalues).
template <class Real> bool isolated_roots(const Real* c, int degree, Real lo, Real hi, Real* found, int& count) {
  return degree <= kMaxCurveDegree &&
         isolate_roots(c, degree, lo, hi, 2 * std::numeric_limits<Real>::epsilon(), found, count, kIsolateCapacity);
}

template <class Real, int Capacity>
void roots_without_eigenvalues(const Real* c, int degree, Candidates<Real, Capacity>& out) {
  if (degree < 1) return;
  const Real bound = root_bound(c, degree);
  Real found[kIsolateCapacity];
  int count = 0;
  if (isolated_roots(c, degree, -bound, bound, found, count))
    for (int i = 0; i < count; ++i) out.push(found[i]);
}

}  // namespace detail

// The Bracketing root policy: real roots without eigenvalues. The roots of p' split the real
// line into intervals on which p is monotonic; each sign change holds exactly one root, found by
// safeguarded Halley-bisection; the roots of p' come from p'' the same way, down to degree 1.
// An even-multiplicity root (a tangency) shows no sign change, but it is a critical point where
// p vanishes within rounding: such critical points are kept, so a double root is never missed.
struct Bracketing {
  static constexpr Polish polish() { return Polish::Newton; }
  // Every root to rounding (a relative 2 eps): candidates can be screened by their start values.
  static constexpr bool accurate_roots = true;

  template <class Real, int Capacity>
  static void roots(const Real* coefficients, int degree, Real lo, Real hi, Candidates<Real, Capacity>& out) {
    degree = trimmed_degree(coefficients, degree);
    if (degree <= 0 || !(lo <= hi)) return;
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      const Real bound = detail::root_bound(coefficients, degree);
      lo = std::max(lo, -bound);
      hi = std::min(hi, bound);
    }
    // isolate_roots' buffers hold degrees up to kMaxCurveDegree (the septic curve's).
    Real found[detail::kIsolateCapacity];
    int count = 0;
    if (detail::isolated_roots(coefficients, degree, lo, hi, found, count) && count <= Capacity - out.count) {
      for (int i = 0; i < count; ++i) out.push(found[i]);
      return;
    }
    // More sign changes than a polynomial of this degree has roots (rounding noise), more values
    // than `out` has room for (noise-level critical points of a degree-40 polynomial), or a
    // degree beyond the buffers: the companion matrix finds every root however noisy the values;
    // its roots are refined by Newton and clamped into [lo, hi] (candidates, judged on the
    // exact distance afterwards).
    Candidates<Real, Capacity> all;
    EigenCompanion::roots(coefficients, degree, lo, hi, all);
    for (int i = 0; i < all.count; ++i) {
      const Real x = detail::newton_on_polynomial(coefficients, degree, all.value[i]);
      out.push(std::min(std::max(x, lo), hi));
    }
  }

  // Each piece is searched on its own: the derivative chain only has its critical points there.
  template <class Real, int Capacity>
  static void roots_in(const Real* c, int degree, const Intervals<Real>& intervals, Candidates<Real, Capacity>& out) {
    for (int i = 0; i < intervals.count; ++i) roots(c, degree, intervals.lo[i], intervals.hi[i], out);
  }

  // One sign change and nothing else in the bracket: safeguarded Halley from the false-position
  // point, no isolation. Where that point rounds onto lo (a root many orders of magnitude below
  // hi), Halley starts at lo itself: the midpoint would take a halving per order of magnitude.
  template <class Real> static Real bracketed_root(const Real* c, int degree, Real lo, Real hi, Real p_lo, Real p_hi) {
    if (!(p_lo < 0)) return lo;
    Real x = lo - p_lo * (hi - lo) / (p_hi - p_lo);
    if (!(x > lo && x < hi)) x = lo;
    return detail::halley_bisection(c, degree, lo, hi, p_lo, x, 2 * std::numeric_limits<Real>::epsilon(), Real(0));
  }
};
// The three eigenvalue policies behind one switch read at run time. Every solver is a template
// on its policy, and these three differ only in roots() and polish(), so a program that offers
// all of them (the Python module) compiles each solver once for the three instead of three
// times, at the price of a switch per polynomial solve. None of them has accurate roots, so the
// solvers take the same branches for each. The choice belongs to the calling thread (`Use`, an
// RAII guard; EigenCompanion until one is made): a thread that answers queries for another must
// make the caller's choice its own.
struct SelectedEigenPolicy {
  enum class Which { Companion, Polished, PolynomialSolver };

  static Which& selected() {
    static thread_local Which which = Which::Companion;
    return which;
  }

  // The calling thread's choice for the guard's lifetime.
  class Use {
   public:
    explicit Use(Which which) : previous_(selected()) { selected() = which; }
    ~Use() { selected() = previous_; }
    Use(const Use&) = delete;
    Use& operator=(const Use&) = delete;

   private:
    Which previous_;
  };

  static Polish polish() { return selected() == Which::Polished ? Polish::Bracketed : Polish::Newton; }

  template <class Real, int Capacity>
  static void roots(const Real* coefficients, int degree, Real lo, Real hi, Candidates<Real, Capacity>& out) {
    switch (selected()) {
      case Which::Polished:
        return EigenPolished::roots(coefficients, degree, lo, hi, out);
      case Which::PolynomialSolver:
        return EigenPolynomialSolver::roots(coefficients, degree, lo, hi, out);
      default:
        return EigenCompanion::roots(coefficients, degree, lo, hi, out);
    }
  }

  template <class Real, int Capacity>
  static void roots_in(const Real* c, int degree, const Intervals<Real>& intervals, Candidates<Real, Capacity>& out) {
    switch (selected()) {
      case Which::Polished:
        return EigenPolished::roots_in(c, degree, intervals, out);
      case Which::PolynomialSolver:
        return EigenPolynomialSolver::roots_in(c, degree, intervals, out);
      default:
        return EigenCompanion::roots_in(c, degree, intervals, out);
    }
  }

  template <class Real> static Real bracketed_root(const Real* c, int degree, Real lo, Real hi, Real p_lo, Real p_hi) {
    switch (selected()) {
      case Which::Polished:
        return EigenPolished::bracketed_root(c, degree, lo, hi, p_lo, p_hi);
      case Which::PolynomialSolver:
        return EigenPolynomialSolver::bracketed_root(c, degree, lo, hi, p_lo, p_hi);
      default:
        return EigenCompanion::bracketed_root(c, degree, lo, hi, p_lo, p_hi);
    }
  }
};

template <class Roots> struct Counted;  // effects.hpp

namespace detail {

// The other way round: the choice each of the three stands for, which the front end
// (query.hpp) makes for a call of distance<P> or closest_points<P> with P one of them (or
// Counted<> of one), answering through SelectedEigenPolicy: the three differ only in roots()
// and polish(), so a program that uses several of them compiles each solver once, and the
// answers are the same bits.
template <class Roots> struct selected_eigen {
  static constexpr bool value = false;
};
template <SelectedEigenPolicy::Which Choice> struct selected_as {
  static constexpr bool value = true;
  static constexpr SelectedEigenPolicy::Which which = Choice;
  using type = SelectedEigenPolicy;
};
template <> struct selected_eigen<EigenCompanion> : selected_as<SelectedEigenPolicy::Which::Companion> {};
template <> struct selected_eigen<EigenPolished> : selected_as<SelectedEigenPolicy::Which::Polished> {};
template <> struct selected_eigen<EigenPolynomialSolver> : selected_as<SelectedEigenPolicy::Which::PolynomialSolver> {};
template <class Roots> struct selected_eigen<Counted<Roots>> : selected_eigen<Roots> {
  using type = Counted<SelectedEigenPolicy>;
};

}  // namespace detail

// The default policy of every solver, chosen by bench/accuracy_vs_time.py (see the README):
// Bracketing and EigenCompanion are equally accurate on every hard case in every precision, and
// Bracketing is the faster (about 3x on the geometric mean of the kinds).
using DefaultRoots = Bracketing;

}  // namespace circledist
