// The machinery of test_roots.cpp: polynomials from known roots, the bar every reported root is
// held to, and the checks of one search.
//
// The truth. A polynomial is lead * prod (x - z_j) for chosen roots z_j (long double values, so
// any double is exact); its coefficients are expanded in a pair of long doubles (about 128 bits,
// far below either precision's rounding) and rounded once to the precision under test. So the
// polynomial a policy sees has coefficients within eps |c_i| of those of the known-root polynomial
// (exactly those where they fit: the interval-end cases rely on it).
//
// The bar: a backward-stability radius, by Rouche's theorem. A policy may answer with the exact
// roots of a polynomial whose coefficients are perturbed by at most w_i (below); every root of the
// perturbed polynomial then lies within t_j of a true root z_j, t_j the smallest t with
//     |lead| prod_k | t - |z_j - z_k| |  >  sum_i w_i (|z_j| + t)^i
// (the left side bounds |P| from below on the circle |z - z_j| = t, the right side bounds the
// perturbation there; where it holds, the disc holds as many perturbed roots as true ones, and
// the union of the discs holds all of them). This one radius is the conditioning bound of every
// case: eps S(z) / |P'(z)| (S(x) = sum |c_i| |x|^i) for a simple root, (eps S / |P^(m) / m!|)^(1/m)
// -- "about eps^(1/m)" -- for a root of multiplicity m, and for a cluster the smaller of the
// linear estimate and the radius of the whole cluster seen as one multiple root (two roots 1e-9
// apart in double: about sqrt(eps), as for a double root). The checks:
//   found:    every true real root in the search region has a reported value within its t_j;
//             for Bracketing, which searches the region only, where the root of the given
//             (rounded) polynomial is in the region for sure (t_j for the rounding alone, 0 for
//             exact coefficients: a root exactly at an end is required);
//   spurious: every reported value lies within t_j of a true root, or is itself an exact root of
//             a polynomial within the allowed perturbation (|P(x)| <= sum w_i |x|^i);
//   inside:   Bracketing (accurate_roots) reports values inside the search region only;
//   dropped:  where trimming drops leading terms, nothing beyond the trimmed polynomial's root
//             bound comes back (the degree drops; the search interval does not explode).
// The allowed perturbation (n the degree after trimming, eps the precision's epsilon):
//   w_i = eps |c_i|  (the coefficients' own rounding)  +
//     K |c_i|         for the policies declaring accurate_roots (Bracketing: "every root to
//                     rounding"), coefficientwise, with K = 128 (n + 1) eps: twice the library's
//                     own bound on the rounding of p(x) (rounding_bound, 64 (n + 1) eps S(x)):
//                     Bracketing keeps the critical points where |p| is within that bound, and
//                     evaluating p there rounds by about as much again;
//     K |c_n| (1 + A)^2, A = max |c_i / c_n|, for the eigenvalue policies, which do not declare
//                     it: the proven normwise backward error of roots from companion-matrix
//                     eigenvalues, O(eps ||a||^2) for the monic coefficients a (Edelman & Murakami
//                     1995; balancing, which Eigen does, usually does far better, but nothing
//                     guarantees it). Roots whose bar this makes infinite are not required.
//   + the leading terms the documented trimming drops (trimmed_degree: up to 16 eps times the
//     largest coefficient), in full: the roots they carry may be lost (infinite bars) and are not
//     required; the test's 1e-20, 0 and subnormal leading coefficients are such terms.
// bracketed_root: Bracketing and EigenPolished refine by safeguarded Halley to a relative 2 eps
// (roots.hpp), so they get the coefficientwise bar; EigenCompanion and EigenPolynomialSolver
// return an eigenvalue inside the bracket when there is one: the companion bar. Every answer must
// lie in [lo, hi]; with p_lo not below zero it must be lo itself.
#pragma once

#include <circledist/effects.hpp>
#include <circledist/roots.hpp>

#include "check.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace roots_problem {

using namespace circledist;

using LD = long double;
using CLD = std::complex<LD>;
constexpr LD kInf = std::numeric_limits<LD>::infinity();

// ---------------------------------------------------------------------------------------------
// A pair of long doubles (hi + lo): the exact expansion of prod (x - z_j).

struct DD {
  LD hi = 0, lo = 0;
};

inline DD two_sum(LD a, LD b) {
  const LD s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
inline DD fast_two_sum(LD a, LD b) {
  const LD s = a + b;
  return {s, b - (s - a)};
}
inline void split(LD a, LD& high, LD& low) {
  static const LD splitter = std::ldexp(LD(1), (std::numeric_limits<LD>::digits + 1) / 2) + 1;
  const LD t = splitter * a;
  high = t - (t - a);
  low = a - high;
}
inline DD two_prod(LD a, LD b) {
  const LD p = a * b;
  LD ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
inline DD add(DD a, DD b) {
  DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  s = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(s.hi, s.lo + t.lo);
}
inline DD mul(DD a, LD b) {
  DD p = two_prod(a.hi, b);
  return fast_two_sum(p.hi, p.lo + a.lo * b);
}
inline DD mul(DD a, DD b) { return add(mul(a, b.hi), mul(a, b.lo)); }

// ---------------------------------------------------------------------------------------------
// Polynomials from known roots.

struct Truth {
  LD lead = 1;
  std::vector<LD> real;   // real roots, with multiplicity
  std::vector<CLD> cplx;  // complex roots, both of each conjugate pair
  std::vector<DD> coef;   // lead * prod (x - z_j), ascending

  int degree() const { return int(coef.size()) - 1; }
  // P(x) from the factors: a few long double ulps relative, whatever the cancellation.
  LD value(LD x) const {
    LD v = lead;
    for (LD r : real) v *= x - r;
    for (size_t k = 0; k < cplx.size(); k += 2)
      v *= (x - cplx[k].real()) * (x - cplx[k].real()) + cplx[k].imag() * cplx[k].imag();
    return v;
  }
};

// lead * prod (x - real_j) * prod ((x - a)^2 + b^2) over pairs (a, b).
inline Truth poly(LD lead, const std::vector<LD>& real, const std::vector<std::pair<LD, LD>>& pairs = {}) {
  Truth t;
  t.lead = lead;
  t.real = real;
  t.coef = {DD{lead, 0}};
  for (LD r : real) {
    std::vector<DD> next(t.coef.size() + 1);
    for (size_t k = 0; k < next.size(); ++k) {
      if (k >= 1) next[k] = add(next[k], t.coef[k - 1]);
      if (k < t.coef.size()) next[k] = add(next[k], mul(t.coef[k], -r));
    }
    t.coef = next;
  }
  for (auto [a, b] : pairs) {
    t.cplx.push_back(CLD(a, b));
    t.cplx.push_back(CLD(a, -b));
    const DD q = add(two_prod(a, a), two_prod(b, b));  // x^2 - 2a x + (a^2 + b^2)
    std::vector<DD> next(t.coef.size() + 2);
    for (size_t k = 0; k < next.size(); ++k) {
      if (k >= 2) next[k] = add(next[k], t.coef[k - 2]);
      if (k >= 1 && k - 1 < t.coef.size()) next[k] = add(next[k], mul(t.coef[k - 1], -2 * a));
      if (k < t.coef.size()) next[k] = add(next[k], mul(t.coef[k], q));
    }
    t.coef = next;
  }
  return t;
}

inline std::vector<LD> repeat(LD r, int m) { return std::vector<LD>(size_t(m), r); }
inline std::vector<LD> join(std::vector<LD> a, const std::vector<LD>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The smallest t (to 5 %) at which Rouche's condition holds on the circle |z - center| = t (see
// the header); infinity when it never does below 1e6 (max |z_j| + 1).
inline LD rouche_radius(const Truth& t, CLD center, const std::vector<LD>& w, LD start) {
  std::vector<LD> d;
  for (LD r : t.real) d.push_back(std::abs(center - r));
  for (CLD z : t.cplx) d.push_back(std::abs(center - z));
  LD largest = 0;
  for (LD r : t.real) largest = std::max(largest, std::abs(r));
  for (CLD z : t.cplx) largest = std::max(largest, std::abs(z));
  const LD a = std::abs(t.lead), rc = std::abs(center);
  const auto holds = [&](LD s) {
    LD f = a;
    for (LD dk : d) f *= std::abs(s - dk);
    LD bound = 0;
    for (int i = int(w.size()) - 1; i >= 0; --i) bound = bound * (rc + s) + w[i];
    return f > bound;
  };
  for (LD s = std::max(start, std::numeric_limits<LD>::min()); s < 1e6L * (largest + 1); s *= LD(1.05))
    if (holds(s)) return s;
  return kInf;
}

template <class Real> const char* precision_name() { return std::is_same_v<Real, double> ? "double" : "long double"; }

// A case: the truth, the coefficients the policy gets, the allowed perturbations and the bars.
template <class Real> struct Problem {
  std::string label;
  Truth truth;
  std::vector<Real> c;         // ascending; c.size() - 1 is the degree passed
  std::vector<LD> extra;       // absolute perturbations beyond rounding: the leading terms trimming drops
  int kept = 0;                // the degree after the documented trimming (trimmed_degree)
  bool exact = true;           // c is exactly the truth's polynomial
  std::vector<LD> w_cw, w_em;  // allowed perturbations (see the header)
  std::vector<LD> cw_real, cw_cplx, em_real, em_cplx;  // Rouche radii for them
  std::vector<LD> rho;  // Rouche radii for the rounding alone: where the given polynomial's root is
  bool valid = true;

  int degree() const { return int(c.size()) - 1; }
  // sum_i w_i |x|^i
  static LD bound(const std::vector<LD>& w, LD x) {
    LD b = 0;
    for (int i = int(w.size()) - 1; i >= 0; --i) b = b * std::abs(x) + w[i];
    return b;
  }
};

// The trimming every policy applies first (roots.hpp, trimmed_degree): leading coefficients up
// to 16 eps times the largest are dropped. Those roots are not required; the perturbation allowed
// includes the dropped terms in full.
template <class Real> void apply_trimming(Problem<Real>& p) {
  Real largest = 0;
  for (Real v : p.c) largest = std::max(largest, std::abs(v));
  int n = p.degree();
  while (n > 0 && std::abs(p.c[n]) <= 16 * std::numeric_limits<Real>::epsilon() * largest) --n;
  p.kept = n;
  p.extra.resize(p.c.size(), 0);
  for (int i = n + 1; i <= p.degree(); ++i) p.extra[i] = std::max(p.extra[i], std::abs(LD(p.c[i])));
}

template <class Real> void compute_bars(Problem<Real>& p) {
  const LD eps = std::numeric_limits<Real>::epsilon();
  const LD K = 128 * (p.kept + 1) * eps;
  const size_t m = std::max(p.c.size(), p.truth.coef.size());
  // Edelman & Murakami: the companion matrix of the monic trimmed polynomial has norm about
  // 1 + A, A = max |c_i / c_n|, and a backward-stable eigensolver's eps ||C|| maps to coefficient
  // perturbations up to about eps ||C|| (1 + A) |c_n|, about eps (1 + A)^2 |c_n|. Balancing usually does far better,
  // but nothing guarantees it.
  const LD lead = std::abs(LD(p.c[p.kept]));
  LD A = 0;
  for (int i = 0; i < p.kept; ++i) A = std::max(A, std::abs(LD(p.c[i])) / lead);
  std::vector<LD> rounding(m, 0);
  p.w_cw.assign(m, 0);
  p.w_em.assign(m, 0);
  for (size_t i = 0; i < m; ++i) {
    const LD ci = i < p.truth.coef.size() ? std::abs(p.truth.coef[i].hi) : 0;
    const LD dropped = i < p.extra.size() ? p.extra[i] : 0;
    rounding[i] = eps * ci + dropped;
    p.w_cw[i] = rounding[i] + K * ci;
    p.w_em[i] = rounding[i] + (int(i) <= p.kept ? K * lead * (1 + A) * (1 + A) : 0);
  }
  for (size_t i = 0; i < p.truth.coef.size(); ++i) {
    const DD& d = p.truth.coef[i];
    p.exact = p.exact && d.lo == 0 && LD(p.c[i]) == d.hi;
  }
  for (size_t i = 0; i < p.extra.size(); ++i) p.exact = p.exact && p.extra[i] == 0;
  for (LD r : p.truth.real) {
    const LD start = std::abs(r) * eps / 8;
    p.cw_real.push_back(rouche_radius(p.truth, CLD(r), p.w_cw, start));
    p.em_real.push_back(rouche_radius(p.truth, CLD(r), p.w_em, start));
    p.rho.push_back(p.exact ? 0 : rouche_radius(p.truth, CLD(r), rounding, start));
  }
  for (CLD z : p.truth.cplx) {
    p.cw_cplx.push_back(rouche_radius(p.truth, z, p.w_cw, std::abs(z) * eps / 8));
    p.em_cplx.push_back(rouche_radius(p.truth, z, p.w_em, std::abs(z) * eps / 8));
  }
  // Infinite bars only where the trimming drops terms (it may remove or move several roots).
  for (LD b : p.cw_real) p.valid = p.valid && (std::isfinite(b) || p.kept < p.degree());
  for (LD b : p.cw_cplx) p.valid = p.valid && (std::isfinite(b) || p.kept < p.degree());
  for (Real v : p.c) p.valid = p.valid && std::isfinite(v);
}

template <class Real> Problem<Real> problem(const std::string& label, const Truth& t) {
  Problem<Real> p;
  p.label = label;
  p.truth = t;
  for (const DD& d : t.coef) p.c.push_back(Real(d.hi));
  apply_trimming(p);
  compute_bars(p);
  return p;
}

// The truth's polynomial with leading coefficients appended that the trimming must drop.
template <class Real>
Problem<Real> with_dropped_lead(const std::string& label, const Truth& t, const std::vector<Real>& lead) {
  Problem<Real> p;
  p.label = label;
  p.truth = t;
  for (const DD& d : t.coef) p.c.push_back(Real(d.hi));
  for (Real v : lead) p.c.push_back(v);
  apply_trimming(p);
  p.valid = p.kept == t.degree();  // the test's premise: these leads are below the trimming
  compute_bars(p);
  return p;
}

// ---------------------------------------------------------------------------------------------
// Policies.

template <class P> struct unwrap {
  using type = P;
};
template <class P> struct unwrap<Counted<P>> {
  using type = P;
};
template <class P> using unwrap_t = typename unwrap<P>::type;
template <class P> constexpr bool is_counted_v = !std::is_same_v<unwrap_t<P>, P>;
// roots() and roots_in(): the coefficientwise bar and values inside the region only.
template <class P> constexpr bool accurate_v = has_accurate_roots<P>::value;
// bracketed_root() refined by Halley to 2 eps (roots.hpp).
template <class P> constexpr bool refined_bracket_v =
    std::is_same_v<unwrap_t<P>, Bracketing> || std::is_same_v<unwrap_t<P>, EigenPolished>;
// EigenCompanion::roots (and so EigenPolished) yields nothing for a degree beyond Capacity - 8.
template <class P> constexpr bool companion_capacity_v =
    std::is_same_v<unwrap_t<P>, EigenCompanion> || std::is_same_v<unwrap_t<P>, EigenPolished>;

template <class P> std::string policy_name() {
  using I = unwrap_t<P>;
  std::string inner = std::is_same_v<I, EigenCompanion>          ? "EigenCompanion"
                      : std::is_same_v<I, EigenPolished>         ? "EigenPolished"
                      : std::is_same_v<I, EigenPolynomialSolver> ? "EigenPolynomialSolver"
                                                                 : "Bracketing";
  return is_counted_v<P> ? "Counted<" + inner + ">" : inner;
}

// Counted<> counts exactly one solve per call.
template <class P> struct SolveCount {
  std::uint64_t before = stats().solves;
  void check() const {
    if constexpr (is_counted_v<P>) CHECK(stats().solves == before + 1);
  }
};

// ---------------------------------------------------------------------------------------------
// Checks.

struct Region {
  std::vector<std::pair<LD, LD>> pieces;
  bool contains(LD x) const {
    for (auto [a, b] : pieces)
      if (x >= a && x <= b) return true;
    return false;
  }
  std::string text() const {
    std::string s;
    char buf[96];
    for (auto [a, b] : pieces) {
      std::snprintf(buf, sizeof buf, "%s[%.21Lg, %.21Lg]", s.empty() ? "" : " u ", a, b);
      s += buf;
    }
    return s;
  }
};

template <class Real> void print_problem(const Problem<Real>& p) {
  std::printf("    polynomial %s, degree %d (%d after trimming), coefficients (ascending):", p.label.c_str(),
              p.degree(), p.kept);
  for (Real v : p.c) std::printf(" %.21Lg", LD(v));
  std::printf("\n    true real roots (bar coefficientwise / companion):");
  for (size_t i = 0; i < p.truth.real.size(); ++i)
    std::printf(" %.21Lg (%.3Lg / %.3Lg)", p.truth.real[i], p.cw_real[i], p.em_real[i]);
  std::printf("\n");
}

// Whether x is explained by the truth: within the Rouche radius of a true root, or an exact root
// of a polynomial within the allowed perturbation (|P(x)| <= sum w_i |x|^i: the only way a
// reported value may sit where the trimming removed roots).
template <class Real> bool explained(const Problem<Real>& p, bool cw, LD x) {
  const auto& br = cw ? p.cw_real : p.em_real;
  const auto& bc = cw ? p.cw_cplx : p.em_cplx;
  for (size_t i = 0; i < p.truth.real.size(); ++i)
    if (std::isfinite(br[i]) && std::abs(x - p.truth.real[i]) <= br[i]) return true;
  for (size_t i = 0; i < p.truth.cplx.size(); ++i)
    if (std::isfinite(bc[i]) && std::abs(CLD(x) - p.truth.cplx[i]) <= bc[i]) return true;
  return std::abs(p.truth.value(x)) <= Problem<Real>::bound(cw ? p.w_cw : p.w_em, x);
}

// Whether a true root must be reported: any root in the region for the policies that return
// every root anyway; for Bracketing (searching the region only) where the root of the given,
// rounded polynomial is in the region for sure (rho: 0 for exact coefficients). Roots the
// trimming may remove (infinite bars) are not required.
template <class Real> bool required(const Problem<Real>& p, bool region_only, size_t i, const Region& region) {
  const LD r = p.truth.real[i], bar = region_only ? p.cw_real[i] : p.em_real[i];
  if (!std::isfinite(bar)) return false;
  if (!region_only) return region.contains(r);
  for (auto [a, b] : region.pieces)
    if (r - p.rho[i] >= a && r + p.rho[i] <= b) return true;
  return false;
}

template <class P, class Real, int Cap> void check_candidates(const std::string& call, const Problem<Real>& p,
                                                              const Region& region, const Candidates<Real, Cap>& out,
                                                              int first = 0) {
  const bool cw = accurate_v<P>;
  const auto& br = cw ? p.cw_real : p.em_real;
  bool found_every_root = true, no_spurious_root = true, all_inside = true;
  std::string problems;
  char buf[256];
  for (size_t i = 0; i < p.truth.real.size(); ++i) {
    if (!required(p, cw, i, region)) continue;
    const LD r = p.truth.real[i];
    bool found = false;
    for (int k = first; k < out.count; ++k) found = found || std::abs(LD(out.value[k]) - r) <= br[i];
    if (!found) {
      found_every_root = false;
      std::snprintf(buf, sizeof buf, "    root %.21Lg not found (bar %.3Lg)\n", r, br[i]);
      problems += buf;
    }
  }
  for (int k = first; k < out.count; ++k) {
    const LD x = out.value[k];
    if (!explained(p, cw, x)) {
      no_spurious_root = false;
      std::snprintf(buf, sizeof buf, "    reported %.21Lg is no root\n", x);
      problems += buf;
    }
    if (cw && !region.contains(x)) {
      all_inside = false;
      std::snprintf(buf, sizeof buf, "    reported %.21Lg is outside the region\n", x);
      problems += buf;
    }
  }
  // Where leading coefficients are trimmed, the degree drops: nothing beyond Cauchy's bound for
  // the trimmed polynomial (1 + max |c_i / c_kept|) may come back (no exploded search interval).
  bool degree_dropped = true;
  if (p.kept < p.degree()) {
    LD bound = 0;
    for (int i = 0; i < p.kept; ++i) bound = std::max(bound, std::abs(LD(p.c[i]) / LD(p.c[p.kept])));
    for (int k = first; k < out.count; ++k) {
      if (std::abs(LD(out.value[k])) > 1 + bound) {
        degree_dropped = false;
        std::snprintf(buf, sizeof buf, "    reported %.21Lg is beyond the trimmed polynomial's root bound %.3Lg\n",
                      LD(out.value[k]), 1 + bound);
        problems += buf;
      }
    }
  }
  if (!problems.empty()) {
    std::printf("[%s, %s] %s on %s:\n%s", policy_name<P>().c_str(), precision_name<Real>(), call.c_str(),
                region.text().c_str(), problems.c_str());
    std::printf("    reported (%d):", out.count - first);
    for (int k = first; k < out.count; ++k) std::printf(" %.21Lg", LD(out.value[k]));
    std::printf("\n");
    print_problem(p);
  }
  CHECK(found_every_root);
  CHECK(no_spurious_root);
  CHECK(degree_dropped);
  if (cw) CHECK(all_inside);
}

template <class P, class Real> void check_roots(const Problem<Real>& p, Real lo, Real hi) {
  Candidates<Real> out;
  const SolveCount<P> solves;
  P::roots(p.c.data(), p.degree(), lo, hi, out);
  solves.check();
  check_candidates<P>("roots", p, Region{{{LD(lo), LD(hi)}}}, out);
}

template <class P, class Real> void check_roots_in(const Problem<Real>& p, const Intervals<Real>& where) {
  Candidates<Real> out;
  const SolveCount<P> solves;
  P::roots_in(p.c.data(), p.degree(), where, out);
  solves.check();
  Region region;
  for (int i = 0; i < where.count; ++i) region.pieces.push_back({LD(where.lo[i]), LD(where.hi[i])});
  check_candidates<P>("roots_in", p, region, out);
}

// bracketed_root on [lo, hi] around `root` (index into truth.real), p oriented by `sign` so that
// p(lo) <= 0 <= p(hi); p_lo and p_hi from the factored form (the closed form a caller has).
// With `lo_exact`, p(lo) is 0 and the answer must be lo itself.
template <class P, class Real> void check_bracketed(const std::string& label, const Problem<Real>& p, Real lo, Real hi,
                                                    size_t root, Real sign, bool lo_exact = false,
                                                    Real p_lo_override = 1) {
  std::vector<Real> c = p.c;
  for (Real& v : c) v *= sign;
  const Real p_lo = p_lo_override <= 0 ? p_lo_override : Real(sign * p.truth.value(lo));
  const Real p_hi = Real(sign * p.truth.value(hi));
  const bool valid_bracket = p_lo <= 0 && p_hi >= 0 && lo <= hi;
  if (!valid_bracket)
    std::printf("test setup: bracket %s [%.21Lg, %.21Lg] with p_lo %Lg, p_hi %Lg in %s\n", label.c_str(), LD(lo),
                LD(hi), LD(p_lo), LD(p_hi), precision_name<Real>());
  CHECK(valid_bracket);  // the test's own setup
  const SolveCount<P> solves;
  const Real x = P::bracketed_root(c.data(), p.degree(), lo, hi, p_lo, p_hi);
  solves.check();
  const LD r = p.truth.real[root], bar = refined_bracket_v<P> ? p.cw_real[root] : p.em_real[root];
  const bool inside_bracket = x >= lo && x <= hi;
  const bool near_root = lo_exact ? x == lo : std::abs(LD(x) - r) <= bar;
  if (!inside_bracket || !near_root) {
    std::printf(
        "[%s, %s] bracketed_root(%s) on [%.21Lg, %.21Lg], p_lo %.6Lg, p_hi %.6Lg: returned %.21Lg, root %.21Lg (bar %.3Lg)%s\n",
        policy_name<P>().c_str(), precision_name<Real>(), label.c_str(), LD(lo), LD(hi), LD(p_lo), LD(p_hi), LD(x), r,
        bar, lo_exact ? ", lo expected exactly" : "");
    std::printf("    (coefficients below times %g)\n", double(sign));
    print_problem(p);
  }
  CHECK(inside_bracket);
  CHECK(near_root);
}

// ---------------------------------------------------------------------------------------------
// The standard searches of a problem: everywhere, the hull of its real roots, half-lines, and
// roots_in on pieces around every other root and on everywhere(); bracketed_root around every
// real root of odd multiplicity whose bracket is a valid one for the rounded polynomial.

template <class Real> std::vector<LD> distinct_sorted(const std::vector<LD>& v) {
  std::vector<LD> s = v;
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

template <class P, class Real> void standard_searches(const Problem<Real>& p) {
  const Real inf = std::numeric_limits<Real>::infinity();
  check_roots<P>(p, -inf, inf);
  check_roots_in<P>(p, Intervals<Real>::everywhere());
  const std::vector<LD> s = distinct_sorted<Real>(p.truth.real);
  if (s.empty()) {
    check_roots<P>(p, Real(-4), Real(4));
    return;
  }
  const LD span = std::max(LD(1), s.back() - s.front());
  check_roots<P>(p, Real(s.front() - span / 8), Real(s.back() + span / 8));
  if (s.size() >= 2) {
    const size_t mid = s.size() / 2;
    const Real m = Real((s[mid - 1] + s[mid]) / 2);
    check_roots<P>(p, -inf, m);
    check_roots<P>(p, m, inf);
  }
  // Pieces around every other distinct root (at most Intervals::capacity of them).
  Intervals<Real> where;
  for (size_t j = 0; j < s.size(); j += 2) {
    LD gap = span;
    if (j > 0) gap = std::min(gap, s[j] - s[j - 1]);
    if (j + 1 < s.size()) gap = std::min(gap, s[j + 1] - s[j]);
    where.add(Real(s[j] - gap / 3), Real(s[j] + gap / 3));
  }
  check_roots_in<P>(p, where);
}

template <class P, class Real> void standard_brackets(const Problem<Real>& p) {
  const LD eps = std::numeric_limits<Real>::epsilon();
  const std::vector<LD> s = distinct_sorted<Real>(p.truth.real);
  for (size_t j = 0; j < s.size(); ++j) {
    const int multiplicity = int(std::count(p.truth.real.begin(), p.truth.real.end(), s[j]));
    if (multiplicity % 2 == 0) continue;
    const size_t root = size_t(std::find(p.truth.real.begin(), p.truth.real.end(), s[j]) - p.truth.real.begin());
    const LD scale = std::max(LD(1), std::abs(s[j]));
    const LD gap_lo = j > 0 ? s[j] - s[j - 1] : scale, gap_hi = j + 1 < s.size() ? s[j + 1] - s[j] : scale;
    const Real lo = Real(s[j] - LD(0.37) * gap_lo), hi = Real(s[j] + LD(0.61) * gap_hi);
    // A valid bracket for the rounded polynomial: its root stays inside (the bar is the radius
    // for a far larger perturbation than the rounding), and the signs at both ends are beyond
    // any perturbation the bars allow.
    const LD bar = p.cw_real[root];
    if (!(LD(lo) < s[j] - 2 * bar && LD(hi) > s[j] + 2 * bar)) continue;
    const auto margin = [&](LD x) {
      LD size = 0;
      for (int i = int(p.truth.coef.size()) - 1; i >= 0; --i) size = size * std::abs(x) + std::abs(p.truth.coef[i].hi);
      LD dropped = 0;
      for (size_t i = 0; i < p.extra.size(); ++i) dropped += p.extra[i] * std::pow(std::abs(x), LD(i));
      return 4 * (128 * (p.kept + 1) + 1) * eps * size + dropped;
    };
    if (!(std::abs(p.truth.value(lo)) > margin(lo) && std::abs(p.truth.value(hi)) > margin(hi))) continue;
    const Real sign = p.truth.value(hi) > 0 ? Real(1) : Real(-1);
    check_bracketed<P>(p.label, p, lo, hi, root, sign);
  }
}

}  // namespace roots_problem
