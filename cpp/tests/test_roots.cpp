// The root policies themselves (roots.hpp; issue 14): every policy (EigenCompanion, EigenPolished,
// EigenPolynomialSolver, Bracketing, and each wrapped in Counted<>), in double and long double (the
// precisions the policies are instantiated for: float queries are solved in double, query.hpp),
// through every entry point: roots(c, n, lo, hi, out), roots_in(c, n, intervals, out) and
// bracketed_root(c, n, lo, hi, p_lo, p_hi). The polynomials are built from known roots:
//   simple well-separated roots (degrees 1..8, with and without complex pairs, and 12, 20, 40),
//   double, triple and quadruple roots, clusters 1e-6 and 1e-9 apart, leading coefficients
//   1e-20 times the others, exactly 0 and subnormal, coefficient ranges over 1e30 (roots 1e-15
//   with 1e15, x scaled by 2^+-33: coefficients 1e-20 .. 1e20, whole polynomials scaled by
//   2^+-600), roots exactly at interval ends and one ulp (1e-17) inside or outside them,
//   bracketed_root with p(lo) = 0 and with a root 1e-30 from lo, and more roots than the output
//   buffer holds.
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

using namespace circledist;

namespace {

using LD = long double;
using CLD = std::complex<LD>;
constexpr LD kInf = std::numeric_limits<LD>::infinity();

// ---------------------------------------------------------------------------------------------
// A pair of long doubles (hi + lo): the exact expansion of prod (x - z_j).

struct DD {
  LD hi = 0, lo = 0;
};

DD two_sum(LD a, LD b) {
  const LD s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
DD fast_two_sum(LD a, LD b) {
  const LD s = a + b;
  return {s, b - (s - a)};
}
void split(LD a, LD& high, LD& low) {
  static const LD splitter = std::ldexp(LD(1), (std::numeric_limits<LD>::digits + 1) / 2) + 1;
  const LD t = splitter * a;
  high = t - (t - a);
  low = a - high;
}
DD two_prod(LD a, LD b) {
  const LD p = a * b;
  LD ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
DD add(DD a, DD b) {
  DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  s = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(s.hi, s.lo + t.lo);
}
DD mul(DD a, LD b) {
  DD p = two_prod(a.hi, b);
  return fast_two_sum(p.hi, p.lo + a.lo * b);
}
DD mul(DD a, DD b) { return add(mul(a, b.hi), mul(a, b.lo)); }

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
    for (size_t k = 0; k < cplx.size(); k += 2) v *= (x - cplx[k].real()) * (x - cplx[k].real()) + cplx[k].imag() * cplx[k].imag();
    return v;
  }
};

// lead * prod (x - real_j) * prod ((x - a)^2 + b^2) over pairs (a, b).
Truth poly(LD lead, const std::vector<LD>& real, const std::vector<std::pair<LD, LD>>& pairs = {}) {
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

std::vector<LD> repeat(LD r, int m) { return std::vector<LD>(size_t(m), r); }
std::vector<LD> join(std::vector<LD> a, const std::vector<LD>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The smallest t (to 5 %) at which Rouche's condition holds on the circle |z - center| = t (see
// the header); infinity when it never does below 1e6 (max |z_j| + 1).
LD rouche_radius(const Truth& t, CLD center, const std::vector<LD>& w, LD start) {
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
  std::vector<Real> c;    // ascending; c.size() - 1 is the degree passed
  std::vector<LD> extra;  // absolute perturbations beyond rounding: the leading terms trimming drops
  int kept = 0;           // the degree after the documented trimming (trimmed_degree)
  bool exact = true;      // c is exactly the truth's polynomial
  std::vector<LD> w_cw, w_em;                          // allowed perturbations (see the header)
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
template <class Real> Problem<Real> with_dropped_lead(const std::string& label, const Truth& t, const std::vector<Real>& lead) {
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
template <class P>
constexpr bool refined_bracket_v = std::is_same_v<unwrap_t<P>, Bracketing> || std::is_same_v<unwrap_t<P>, EigenPolished>;
// EigenCompanion::roots (and so EigenPolished) yields nothing for a degree beyond Capacity - 8.
template <class P>
constexpr bool companion_capacity_v = std::is_same_v<unwrap_t<P>, EigenCompanion> || std::is_same_v<unwrap_t<P>, EigenPolished>;

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
  std::printf("    polynomial %s, degree %d (%d after trimming), coefficients (ascending):", p.label.c_str(), p.degree(), p.kept);
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

template <class P, class Real, int Cap>
void check_candidates(const std::string& call, const Problem<Real>& p, const Region& region, const Candidates<Real, Cap>& out,
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
template <class P, class Real>
void check_bracketed(const std::string& label, const Problem<Real>& p, Real lo, Real hi, size_t root, Real sign,
                     bool lo_exact = false, Real p_lo_override = 1) {
  std::vector<Real> c = p.c;
  for (Real& v : c) v *= sign;
  const Real p_lo = p_lo_override <= 0 ? p_lo_override : Real(sign * p.truth.value(lo));
  const Real p_hi = Real(sign * p.truth.value(hi));
  const bool valid_bracket = p_lo <= 0 && p_hi >= 0 && lo <= hi;
  if (!valid_bracket)
    std::printf("test setup: bracket %s [%.21Lg, %.21Lg] with p_lo %Lg, p_hi %Lg in %s\n", label.c_str(), LD(lo), LD(hi), LD(p_lo),
                LD(p_hi), precision_name<Real>());
  CHECK(valid_bracket);  // the test's own setup
  const SolveCount<P> solves;
  const Real x = P::bracketed_root(c.data(), p.degree(), lo, hi, p_lo, p_hi);
  solves.check();
  const LD r = p.truth.real[root], bar = refined_bracket_v<P> ? p.cw_real[root] : p.em_real[root];
  const bool inside_bracket = x >= lo && x <= hi;
  const bool near_root = lo_exact ? x == lo : std::abs(LD(x) - r) <= bar;
  if (!inside_bracket || !near_root) {
    std::printf("[%s, %s] bracketed_root(%s) on [%.21Lg, %.21Lg], p_lo %.6Lg, p_hi %.6Lg: returned %.21Lg, root %.21Lg (bar %.3Lg)%s\n",
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

// ---------------------------------------------------------------------------------------------
// The cases.

template <class Real> std::vector<Problem<Real>> simple_problems() {
  std::vector<Problem<Real>> v;
  v.push_back(problem<Real>("deg1 {0.75}", poly(1, {0.75L})));
  v.push_back(problem<Real>("deg1 3x-1", poly(3, {1.0L / 3})));
  v.push_back(problem<Real>("deg2 {-1,2}", poly(1, {-1, 2})));
  v.push_back(problem<Real>("deg2 {0.1,0.3} lead -7", poly(-7, {0.1L, 0.3L})));
  v.push_back(problem<Real>("deg3 {-2,0.5,3}", poly(1, {-2, 0.5L, 3})));
  v.push_back(problem<Real>("deg4 {-3,-0.5,0.75,2}", poly(1, {-3, -0.5L, 0.75L, 2})));
  v.push_back(problem<Real>("deg5 {-4,-1.25,0.3,1.7,3.5} lead 0.01", poly(0.01L, {-4, -1.25L, 0.3L, 1.7L, 3.5L})));
  v.push_back(problem<Real>("deg6 {-2.5..2.5}", poly(1, {-2.5L, -1.5L, -0.5L, 0.5L, 1.5L, 2.5L})));
  v.push_back(problem<Real>("deg7 {-3,-2,-1,0.125,1,2,3} lead -2", poly(-2, {-3, -2, -1, 0.125L, 1, 2, 3})));
  v.push_back(problem<Real>("deg8 {1..8}", poly(1, {1, 2, 3, 4, 5, 6, 7, 8})));
  v.push_back(problem<Real>("deg8 {-3.5..3.5}", poly(1, {-3.5L, -2.5L, -1.5L, -0.5L, 0.5L, 1.5L, 2.5L, 3.5L})));
  v.push_back(problem<Real>("deg8 non-dyadic", poly(1.3L, {-2.9L, -1.7L, -0.6L, 0.2L, 0.9L, 1.6L, 2.4L, 3.1L})));
  // With complex pairs (never to be reported) and without any real root.
  v.push_back(problem<Real>("deg4 {1,-2} 0.5+-1.5i", poly(1, {1, -2}, {{0.5L, 1.5L}})));
  v.push_back(problem<Real>("deg6 {-1,3} +-i 2+-0.5i", poly(1, {-1, 3}, {{0, 1}, {2, 0.5L}})));
  v.push_back(problem<Real>("deg8 {0.25,-0.75} 3 pairs", poly(1, {0.25L, -0.75L}, {{-1, 1}, {1.5L, 2}, {0.5L, 0.75L}})));
  v.push_back(problem<Real>("deg4 no real root", poly(1, {}, {{0, 1}, {0, 2}})));
  v.push_back(problem<Real>("deg5 {2} 2 pairs", poly(1, {2}, {{-1, 0.5L}, {1, 3}})));
  return v;
}

template <class Real> std::vector<Problem<Real>> multiple_problems() {
  std::vector<Problem<Real>> v;
  v.push_back(problem<Real>("double {1,1}", poly(1, {1, 1})));
  v.push_back(problem<Real>("double {1,1,-2}", poly(1, {1, 1, -2})));
  v.push_back(problem<Real>("triple {0.5^3}", poly(1, repeat(0.5L, 3))));
  v.push_back(problem<Real>("triple {0.5^3,-2}", poly(1, join(repeat(0.5L, 3), {-2}))));
  v.push_back(problem<Real>("quadruple {1^4}", poly(1, repeat(1, 4))));
  v.push_back(problem<Real>("quadruple {2^4,-1,3}", poly(1, join(repeat(2, 4), {-1, 3}))));
  v.push_back(problem<Real>("deg8 {-0.75^4,1.5^2,3,-3}", poly(1, join(join(repeat(-0.75L, 4), repeat(1.5L, 2)), {3, -3}))));
  v.push_back(problem<Real>("deg8 {1^4,3^4}", poly(1, join(repeat(1, 4), repeat(3, 4)))));
  v.push_back(problem<Real>("non-dyadic {0.3^3,-1.1^2,2.7}", poly(1, join(join(repeat(0.3L, 3), repeat(-1.1L, 2)), {2.7L}))));
  v.push_back(problem<Real>("double {1000^2,-1,5}", poly(1, join(repeat(1000, 2), {-1, 5}))));
  v.push_back(problem<Real>("quadruple {0.1^4,-2,1.5} lead -3", poly(-3, join(repeat(0.1L, 4), {-2, 1.5L}))));
  v.push_back(problem<Real>("double with pair {0.7^2} 0+-1i", poly(1, repeat(0.7L, 2), {{0, 1}})));
  return v;
}

template <class Real> std::vector<Problem<Real>> cluster_problems() {
  std::vector<Problem<Real>> v;
  for (LD d : {1e-6L, 1e-9L}) {
    const std::string tag = d > 1e-7L ? "1e-6" : "1e-9";
    v.push_back(problem<Real>("pair " + tag, poly(1, {1, 1 + d})));
    v.push_back(problem<Real>("pair " + tag + " with {-2,3}", poly(1, {1, 1 + d, -2, 3})));
    v.push_back(problem<Real>("triple " + tag, poly(1, {0.75L, 0.75L + d, 0.75L + 2 * d, -1.5L})));
    v.push_back(problem<Real>("quadruple " + tag + " deg8",
                              poly(1, {-2, 0.5L, 0.5L + d, 0.5L + 2 * d, 0.5L + 3 * d, 3, 4, -1})));
    v.push_back(problem<Real>("two pairs " + tag, poly(1, {-1, -1 + d, 2, 2 + d, 0.3L})));
    v.push_back(problem<Real>("pair " + tag + " near 100", poly(1, {100, 100 + 100 * d, -3})));
  }
  return v;
}

template <class Real> std::vector<Problem<Real>> lead_problems() {
  std::vector<Problem<Real>> v;
  const Truth q3 = poly(1, {-2, 0.5L, 1.5L});
  const Truth q7 = poly(1, {-3, -2, -1, 0.25L, 1, 2, 3});
  for (const Truth* q : {&q3, &q7}) {
    const std::string deg = "deg" + std::to_string(q->degree()) + "+";
    Real largest = 0;
    for (const DD& d : q->coef) largest = std::max(largest, std::abs(Real(d.hi)));
    v.push_back(with_dropped_lead<Real>(deg + "1e-20 lead", *q, {Real(1e-20L) * largest}));
    v.push_back(with_dropped_lead<Real>(deg + "-1e-20 lead", *q, {-Real(1e-20L) * largest}));
    v.push_back(with_dropped_lead<Real>(deg + "0 lead", *q, {Real(0)}));
    v.push_back(with_dropped_lead<Real>(deg + "two 0 leads", *q, {Real(0), Real(0)}));
    v.push_back(with_dropped_lead<Real>(deg + "subnormal lead", *q, {std::numeric_limits<Real>::denorm_min()}));
    v.push_back(with_dropped_lead<Real>(deg + "subnormal lead 2", *q, {std::numeric_limits<Real>::min() / 1024}));
    v.push_back(with_dropped_lead<Real>(deg + "1e-20 and 0 leads", *q, {Real(0), Real(1e-20L) * largest}));
  }
  // Small but real: lead / largest about 3e-13, above trimming in both precisions; the root near
  // 1.1e12 is a root, and the search interval (Fujiwara's bound) must hold it and the small ones.
  v.push_back(problem<Real>("huge root 2^40 {-2,0.5,3}", poly(1, {-2, 0.5L, 3, std::ldexp(LD(1), 40)})));
  v.push_back(problem<Real>("huge root -2^40 {-1e-3,1}", poly(1, {-1e-3L, 1, -std::ldexp(LD(1), 40)})));
  return v;
}

template <class Real> std::vector<Problem<Real>> range_problems() {
  std::vector<Problem<Real>> v;
  const LD tiny = std::ldexp(LD(1), -50), big = std::ldexp(LD(1), 50);
  v.push_back(problem<Real>("{2^-50,2^50}", poly(1, {tiny, big})));
  v.push_back(problem<Real>("{2^-50,1,2^50}", poly(1, {tiny, 1, big})));
  v.push_back(problem<Real>("{-2^-50,3*2^-52,0.75}", poly(1, {-tiny, 3 * tiny / 4, 0.75L})));  // c0 = 9 * 2^-105
  v.push_back(problem<Real>("{-2^-50,3*2^-52,0.75,2^50,-2^49}", poly(1, {-tiny, 3 * tiny / 4, 0.75L, big, -big / 2})));
  v.push_back(problem<Real>("{1e-15,1e15}", poly(1, {1e-15L, 1e15L})));
  v.push_back(problem<Real>("{1e-15,-3,1e15,7}", poly(1, {1e-15L, -3, 1e15L, 7})));
  v.push_back(problem<Real>("{1e-15^2,1e15} lead 1e-10", poly(1e-10L, {1e-15L, 1e-15L, 1e15L, -1})));
  // x scaled by sigma with a compensating lead: coefficients from about 1e-20 to 1e20.
  const LD sigma_up = std::ldexp(LD(1), 33), sigma_down = std::ldexp(LD(1), -33);
  v.push_back(problem<Real>("sigma 2^33 {-3,-1,0.5,2} lead 2^-66",
                            poly(std::ldexp(LD(1), -66), {-3 * sigma_up, -sigma_up, sigma_up / 2, 2 * sigma_up})));
  v.push_back(problem<Real>("sigma 2^-33 {-3,-1,0.5,2} lead 2^66",
                            poly(std::ldexp(LD(1), 66), {-3 * sigma_down, -sigma_down, sigma_down / 2, 2 * sigma_down})));
  // Graded roots 1e-5 .. 1e5.
  v.push_back(problem<Real>("graded {1e-5,-1e-2,1,-1e2,1e5}", poly(1, {1e-5L, -1e-2L, 1, -1e2L, 1e5L})));
  // The whole polynomial scaled by 2^+-e (roots unchanged), e = 600 in double (coefficients near
  // 1e+-180: their squares leave the range, the values of p do not), 9600 in long double.
  const int e = std::numeric_limits<Real>::max_exponent * 600 / 1024;
  const std::string tag = "2^" + std::to_string(e);
  for (const std::vector<LD>& roots : {std::vector<LD>{0.75L}, std::vector<LD>{-1, 2}, std::vector<LD>{-2, 0.5L, 3},
                                       std::vector<LD>{-2, -1, 0.5L, 1, 3, 4}}) {
    const std::string deg = "deg" + std::to_string(roots.size());
    v.push_back(problem<Real>(deg + " lead " + tag, poly(std::ldexp(LD(1), e), roots)));
    v.push_back(problem<Real>(deg + " lead -2^-" + std::to_string(e), poly(-std::ldexp(LD(1), -e), roots)));
  }
  return v;
}

template <class P, class Real> void run_problem_set(const std::vector<Problem<Real>>& set) {
  for (const Problem<Real>& p : set) {
    if (!p.valid) {
      std::printf("test setup: %s has no finite bar in %s\n", p.label.c_str(), precision_name<Real>());
      CHECK(p.valid);
      continue;
    }
    standard_searches<P>(p);
    standard_brackets<P>(p);
  }
}

// Roots exactly at interval ends, one ulp (about 1e-17) inside and outside them.
template <class P, class Real> void interval_ends() {
  const auto up = [](Real x) { return std::nextafter(x, std::numeric_limits<Real>::infinity()); };
  const auto down = [](Real x) { return std::nextafter(x, -std::numeric_limits<Real>::infinity()); };
  struct End {
    const char* label;
    LD root;
    std::vector<LD> others;
  };
  // Exact coefficients throughout, so the roots are exactly known and exactly at (or one ulp
  // from) the ends. 1/16 (ulp 1.4e-17): p evaluates exactly there. r = 0.1 rounded to 20 bits and
  // 1 + 2^-30: the coefficients still fit, but r^3 or r^4 does not, so p(r) rounds.
  const Real tenth = std::ldexp(Real(838861), -23), off_one = Real(1 + std::ldexp(LD(1), -30));  // 0.1 to 20 bits
  const std::vector<End> ends = {{"(x-1/16)(x-3)(x+2)", 0.0625L, {3, -2}},
                                 {"(x-0.1_20)(x-3)(x+2)(x-0.625)", LD(tenth), {3, -2, 0.625L}},
                                 {"(x-(1+2^-30))(x+1)(x-2)", LD(off_one), {-1, 2}},
                                 {"(x-0.1_20)^2(x+1)(x-2)", LD(tenth), {LD(tenth), -1, 2}},
                                 {"(x-1/4)^2(x+1)(x-2)", 0.25L, {0.25L, -1, 2}},
                                 {"(x-0.5)^3(x+1)", 0.5L, {0.5L, 0.5L, -1}}};
  for (const End& e : ends) {
    const Problem<Real> p = problem<Real>(e.label, poly(1, join({e.root}, e.others)));
    if (!p.exact) std::printf("test setup: %s is not exact in %s\n", e.label, precision_name<Real>());
    CHECK(p.exact);  // the test's premise
    const Real r = Real(e.root);
    const Real a = r - Real(0.25), b = r + Real(0.25);
    for (auto [lo, hi] : std::vector<std::pair<Real, Real>>{{r, b}, {a, r}, {up(r), b}, {a, down(r)}, {down(r), b}, {a, up(r)}, {r, r}})
      check_roots<P>(p, lo, hi);
    Intervals<Real> where;
    where.add(a, r);
    where.add(up(r), b);  // the root at the end of the first piece, one ulp below the second
    check_roots_in<P>(p, where);
    Intervals<Real> pieces;
    pieces.add(a, down(r));  // the root one ulp above the first piece's end
    pieces.add(r, r);        // a degenerate piece at the root
    pieces.add(up(r), b);
    check_roots_in<P>(p, pieces);
  }
  // A root at 1e-17 next to ends at 0 and 2e-17, and a root-at-end union of pieces.
  const Real small = Real(1e-17L);
  const Problem<Real> p = problem<Real>("(x-1e-17)(x-0.5)(x+1)", poly(1, {LD(small), 0.5L, -1}));
  for (auto [lo, hi] : std::vector<std::pair<Real, Real>>{{Real(0), Real(0.25)},
                                                          {Real(2e-17L), Real(0.25)},
                                                          {small, Real(0.25)},
                                                          {Real(-0.25), small},
                                                          {Real(-0.25), Real(0)}})
    check_roots<P>(p, lo, hi);
  const Problem<Real> q = problem<Real>("{-1.5,-0.5,0.25,1,2.75}", poly(1, {-1.5L, -0.5L, 0.25L, 1, 2.75L}));
  Intervals<Real> where;
  where.add(Real(-2), Real(-1.5));
  where.add(Real(-0.5), Real(0));
  where.add(Real(0.25), Real(0.5));
  where.add(Real(1), Real(1));
  where.add(Real(2.75), std::numeric_limits<Real>::infinity());
  check_roots_in<P>(q, where);
}

// bracketed_root at the ends of its bracket and next to them.
template <class P, class Real> void bracket_ends() {
  const auto up = [](Real x) { return std::nextafter(x, std::numeric_limits<Real>::infinity()); };
  const auto down = [](Real x) { return std::nextafter(x, -std::numeric_limits<Real>::infinity()); };
  {
    // p = -(x - 1/16)(x - 3)(x + 2): increasing through 1/16.
    const Problem<Real> p = problem<Real>("(x-1/16)(x-3)(x+2)", poly(1, {0.0625L, 3, -2}));
    const Real r = Real(0.0625), s = -1;
    check_bracketed<P>("p(lo) = 0", p, r, Real(1), 0, s, true);
    check_bracketed<P>("p(lo) = -0", p, r, Real(1), 0, s, true, Real(-0.0));
    check_bracketed<P>("root at hi", p, Real(0), r, 0, s);
    check_bracketed<P>("root 1 ulp above lo", p, down(r), Real(1), 0, s);
    check_bracketed<P>("root 1 ulp below hi", p, Real(0), up(r), 0, s);
    check_bracketed<P>("2-ulp bracket", p, down(r), up(r), 0, s);
    check_bracketed<P>("wide bracket", p, Real(-1), Real(2.5), 0, s);
  }
  {
    // The same with p(root) rounding (root 0.1 rounded to 20 bits, exact coefficients).
    const Real tenth = std::ldexp(Real(838861), -23);
    const Problem<Real> p = problem<Real>("(x-0.1_20)(x-3)(x+2)", poly(1, {LD(tenth), 3, -2}));
    CHECK(p.exact);
    check_bracketed<P>("root 0.1, 1 ulp above lo", p, down(tenth), Real(1), 0, Real(-1));
    check_bracketed<P>("root 0.1, 1 ulp below hi", p, Real(0), up(tenth), 0, Real(-1));
  }
  {
    // Roots 1e-30 and 2^-100 above lo = 0, and 2 * 2^-100 above lo = 2^-100.
    const LD t100 = std::ldexp(LD(1), -100);
    for (LD r : {LD(Real(1e-30L)), t100}) {
      const Problem<Real> p = problem<Real>("root near 0 (x-r)(x+1)(x-2)", poly(1, {r, -1, 2}));
      check_bracketed<P>("root 1e-30 above lo", p, Real(0), Real(1), 0, Real(-1));
      const Problem<Real> q = problem<Real>("root near 0 (x-r)(x+1)(x+2)", poly(1, {r, -1, -2}));
      check_bracketed<P>("root 1e-30 above lo, hi 1e15", q, Real(0), Real(1e15L), 0, Real(1));
    }
    const Problem<Real> p = problem<Real>("(x-3*2^-100)(x+1)(x-2)", poly(1, {3 * t100, -1, 2}));
    check_bracketed<P>("root 2^-99 above lo", p, Real(t100), Real(1), 0, Real(-1));
  }
  {
    // Range over 1e30: both roots of (x - 1e-15)(x - 1e15)(x + 3).
    const Problem<Real> p = problem<Real>("(x-1e-15)(x-1e15)(x+3)", poly(1, {1e-15L, 1e15L, -3}));
    check_bracketed<P>("root 1e-15", p, Real(0), Real(1), 0, Real(-1));
    check_bracketed<P>("root 1e15", p, Real(1), Real(1e16L), 1, Real(1));
  }
  {
    // A triple root (a sign change), inside and at the end.
    const Problem<Real> p = problem<Real>("(x-0.5)^3(x+2)", poly(1, {0.5L, 0.5L, 0.5L, -2}));
    check_bracketed<P>("triple root", p, Real(0), Real(1), 0, Real(1));
    check_bracketed<P>("triple root at hi", p, Real(0), Real(0.5), 0, Real(1));
    check_bracketed<P>("triple root at lo", p, Real(0.5), Real(1), 0, Real(1), true);
  }
}

// More roots than the output holds: the policies must stop at its capacity, write nothing beyond
// it (the canaries after it, and AddressSanitizer), and what they did write must be roots.
template <class Real, int Cap> struct Guarded {
  Candidates<Real, Cap> out;
  Real canary[8];
  Guarded() {
    for (Real& c : canary) c = Real(12345.5);
  }
  bool intact() const {
    for (Real c : canary)
      if (c != Real(12345.5)) return false;
    return out.count >= 0 && out.count <= Cap;
  }
};

template <class P, class Real> void capacity() {
  const Problem<Real> p = problem<Real>("deg8 {-3.5..3.5}", poly(1, {-3.5L, -2.5L, -1.5L, -0.5L, 0.5L, 1.5L, 2.5L, 3.5L}));
  const Real inf = std::numeric_limits<Real>::infinity();
  const auto spurious_only = [&](const auto& out, int first) {
    // Only the spurious check applies: found roots were dropped for want of room.
    bool ok = true;
    for (int k = first; k < out.count; ++k) ok = ok && explained(p, accurate_v<P>, LD(out.value[k]));
    return ok;
  };
  {
    Guarded<Real, 3> g;
    P::roots(p.c.data(), 8, -inf, inf, g.out);
    CHECK(g.intact());
    CHECK(g.out.count == 3);
    CHECK(spurious_only(g.out, 0));
  }
  {
    Guarded<Real, 1> g;
    P::roots(p.c.data(), 8, Real(-10), Real(10), g.out);
    CHECK(g.intact());
    CHECK(g.out.count == 1);
    CHECK(spurious_only(g.out, 0));
  }
  {
    // Nine pieces (Intervals' capacity), one root in eight of them, into room for four.
    Guarded<Real, 4> g;
    Intervals<Real> where;
    for (int i = 0; i < 12; ++i) where.add(Real(-3.75 + i), Real(-3.25 + i));  // the last three dropped
    CHECK(where.count == Intervals<Real>::capacity);
    P::roots_in(p.c.data(), 8, where, g.out);
    CHECK(g.intact());
    CHECK(g.out.count == 4);
    CHECK(spurious_only(g.out, 0));
  }
  {
    // An almost full default Candidates: earlier values are kept, two more fit.
    Guarded<Real, kMaxDegree + 8> g;
    for (int i = 0; i < kMaxDegree + 6; ++i) g.out.push(Real(100 + i));
    P::roots(p.c.data(), 8, -inf, inf, g.out);
    CHECK(g.intact());
    CHECK(g.out.count == kMaxDegree + 8);
    bool kept = true;
    for (int i = 0; i < kMaxDegree + 6; ++i) kept = kept && g.out.value[i] == Real(100 + i);
    CHECK(kept);
    CHECK(spurious_only(g.out, kMaxDegree + 6));
  }
}

// Degrees above 8: the curve solves (kMaxCurveDegree + 8 capacity) and the default capacity,
// where EigenCompanion (and EigenPolished) documents that it yields no candidates.
template <class P, class Real> void high_degrees(const std::vector<Problem<Real>>& set) {
  const Real inf = std::numeric_limits<Real>::infinity();
  for (const Problem<Real>& p : set) {
    {
      Candidates<Real> out;
      P::roots(p.c.data(), p.degree(), -inf, inf, out);
      if constexpr (companion_capacity_v<P>) {
        CHECK(out.count == 0);
      } else if (p.degree() <= 12) {
        check_candidates<P>("roots (default capacity)", p, Region{{{-kInf, kInf}}}, out);
      }
    }
    {
      Guarded<Real, kMaxCurveDegree + 8> g;
      const SolveCount<P> solves;
      P::roots(p.c.data(), p.degree(), -inf, inf, g.out);
      solves.check();
      CHECK(g.intact());
      check_candidates<P>("roots (curve capacity)", p, Region{{{-kInf, kInf}}}, g.out);
    }
    {
      Candidates<Real, kMaxCurveDegree + 8> out;
      Intervals<Real> where;
      where.add(Real(-0.75), Real(0.75));
      where.add(Real(2), inf);
      P::roots_in(p.c.data(), p.degree(), where, out);
      check_candidates<P>("roots_in (curve capacity)", p, Region{{{-0.75L, 0.75L}, {2, kInf}}}, out);
    }
    standard_brackets<P>(p);
  }
}

template <class Real> std::vector<Problem<Real>> high_degree_problems() {
  std::vector<Problem<Real>> v;
  std::vector<LD> twelve, twenty, forty;
  for (int k = 0; k < 12; ++k) twelve.push_back(LD(k) / 4 - LD(1.375));  // -1.375 .. 1.375
  for (int k = 1; k <= 20; ++k) twenty.push_back(2 * std::cos((2 * k - 1) * std::acos(LD(-1)) / 40));
  for (int k = 1; k <= 40; ++k) forty.push_back(2 * std::cos((2 * k - 1) * std::acos(LD(-1)) / 80));
  v.push_back(problem<Real>("deg12 equispaced", poly(1, twelve)));
  v.push_back(problem<Real>("deg20 Chebyshev points", poly(1, twenty)));
  v.push_back(problem<Real>("deg40 Chebyshev points", poly(1, forty)));
  return v;
}

// No roots at all: constants, the zero polynomial, a point interval with no root.
template <class P, class Real> void degenerate() {
  const Real inf = std::numeric_limits<Real>::infinity();
  const Real constant[3] = {Real(2), Real(0), Real(0)}, zero[3] = {0, 0, 0};
  Candidates<Real> out;
  P::roots(constant, 0, -inf, inf, out);
  P::roots(constant, 2, -inf, inf, out);
  CHECK(out.count == 0);
  Guarded<Real, kMaxDegree + 8> g;
  P::roots(zero, 2, -inf, inf, g.out);  // every x is a root; any answer, but within bounds
  CHECK(g.intact());
  Intervals<Real> none;  // no pieces: nothing to search
  const Problem<Real> p = problem<Real>("deg3 {-2,0.5,3}", poly(1, {-2, 0.5L, 3}));
  Candidates<Real> empty;
  P::roots_in(p.c.data(), 3, none, empty);
  if constexpr (accurate_v<P>) CHECK(empty.count == 0);
  check_candidates<P>("roots_in (no pieces)", p, Region{}, empty);
}

// A polynomial whose balanced companion matrix Eigen's real Schur iteration does not reduce
// (NoConvergence: no eigenvalues at all): the octic of circle-circle (detail/local_circle.hpp) for
// a circle through the other ring's axis at two opposite angles, (9 u^8 - 40 u^6 + 62 u^4 -
// 40 u^2 + 9) / 729 = (u^2 - 1)^2 (9 u^4 - 22 u^2 + 9) / 729, with these exact double coefficients
// (a circle of radius 1/2 in x = 0 about the origin against the ring of radius 1/2 about
// (0, 3/2, 0) in y = 3/2). Its simple roots u^2 = (11 +- 2 sqrt 10) / 9 are the minima; the
// eigenvalue policies returned none (the arc-circle differential finding of 2026-11-26). Every
// policy must return all four to 1e-12, whichever way it finds them (roots.hpp:
// roots_without_eigenvalues); in long double the same coefficients do not stall, and must agree.
template <class P, class Real> void stalling_companion() {
  const Real c[9] = {Real(1.0 / 81), 0, Real(-40.0 / 729), 0, Real(62.0 / 729), 0, Real(-40.0 / 729), 0, Real(1.0 / 81)};
  const Real inf = std::numeric_limits<Real>::infinity();
  Candidates<Real> out;
  P::roots(c, 8, -inf, inf, out);
  for (const LD v : {(11 + 2 * std::sqrt(10.0L)) / 9, (11 - 2 * std::sqrt(10.0L)) / 9})
    for (const LD sign : {-1.0L, 1.0L}) {
      const LD root = sign * std::sqrt(v);
      bool found = false;
      for (int i = 0; i < out.count; ++i) found = found || std::abs(LD(out.value[i]) - root) <= 1e-12L;
      if (!found) std::printf("[%s, %s] stalling companion: root %.17Lg not found\n", policy_name<P>().c_str(),
                              precision_name<Real>(), root);
      CHECK(found);
    }
}

template <class Real> struct Sets {
  std::vector<Problem<Real>> simple = simple_problems<Real>(), multiple = multiple_problems<Real>(),
                             clusters = cluster_problems<Real>(), leads = lead_problems<Real>(),
                             ranges = range_problems<Real>(), high = high_degree_problems<Real>();
};

template <class P, class Real> void run_policy(const Sets<Real>& sets) {
  run_problem_set<P>(sets.simple);
  run_problem_set<P>(sets.multiple);
  run_problem_set<P>(sets.clusters);
  run_problem_set<P>(sets.leads);
  run_problem_set<P>(sets.ranges);
  interval_ends<P, Real>();
  bracket_ends<P, Real>();
  capacity<P, Real>();
  high_degrees<P>(sets.high);
  degenerate<P, Real>();
  stalling_companion<P, Real>();
}

// SelectedEigenPolicy (the Python module's one unit for the three eigenvalue policies) is the
// chosen policy to the bit: the same candidates, the same bracketed roots, the same polish.
template <class Fixed, class Real> void selected_matches(SelectedEigenPolicy::Which which, const Sets<Real>& sets) {
  const SelectedEigenPolicy::Use use(which);
  CHECK(SelectedEigenPolicy::polish() == Fixed::polish());
  for (const auto* set : {&sets.simple, &sets.multiple, &sets.clusters, &sets.leads, &sets.ranges}) {
    for (const Problem<Real>& problem : *set) {
      const int degree = int(problem.c.size()) - 1;
      const Real inf = std::numeric_limits<Real>::infinity();
      Candidates<Real> fixed, selected, counted;
      Fixed::roots(problem.c.data(), degree, -inf, inf, fixed);
      SelectedEigenPolicy::roots(problem.c.data(), degree, -inf, inf, selected);
      const SolveCount<Counted<SelectedEigenPolicy>> solves;
      Counted<SelectedEigenPolicy>::roots(problem.c.data(), degree, -inf, inf, counted);
      solves.check();
      bool same = fixed.count == selected.count && fixed.count == counted.count;
      for (int i = 0; same && i < fixed.count; ++i)
        same = fixed.value[i] == selected.value[i] && fixed.value[i] == counted.value[i];
      CHECK(same);
    }
  }
  // -(x - 1)(x - 2)(x - 3): the one root in [1.5, 2.5], rising from p(1.5) < 0 to p(2.5) > 0.
  const Real c[4] = {6, -11, 6, -1};
  const Real root = SelectedEigenPolicy::bracketed_root(c, 3, Real(1.5), Real(2.5), Real(-0.375), Real(0.375));
  CHECK(root == Fixed::bracketed_root(c, 3, Real(1.5), Real(2.5), Real(-0.375), Real(0.375)));
  CHECK_NEAR(root, 2, 1e-12);
}

template <class Real> void run_precision() {
  const Sets<Real> sets;
  selected_matches<EigenCompanion>(SelectedEigenPolicy::Which::Companion, sets);
  selected_matches<EigenPolished>(SelectedEigenPolicy::Which::Polished, sets);
  selected_matches<EigenPolynomialSolver>(SelectedEigenPolicy::Which::PolynomialSolver, sets);
  CHECK(SelectedEigenPolicy::selected() == SelectedEigenPolicy::Which::Companion);  // the guards restored it
  run_policy<EigenCompanion>(sets);
  run_policy<EigenPolished>(sets);
  run_policy<EigenPolynomialSolver>(sets);
  run_policy<Bracketing>(sets);
  run_policy<Counted<EigenCompanion>>(sets);
  run_policy<Counted<EigenPolished>>(sets);
  run_policy<Counted<EigenPolynomialSolver>>(sets);
  run_policy<Counted<Bracketing>>(sets);
}

// Coefficients (lowest first) of (x - r0)(x - r1)(x - r2)(x - r3).
void quartic_from_roots(const double r[4], double c[5]) {
  c[0] = 1;
  for (int k = 1; k <= 4; ++k) c[k] = 0;
  for (int i = 0; i < 4; ++i) {
    for (int k = i + 1; k >= 1; --k) c[k] = c[k - 1] - r[i] * c[k];
    c[0] = -r[i] * c[0];
  }
}

// Policy::bracketed_root, the line-circle quartic's solver: a root inside, a root many orders of
// magnitude below the bracket's top, and a non-negative p(lo) returning lo itself.
template <class Policy> void bracketed_root_cases(bool refined) {
  const double eps = std::numeric_limits<double>::epsilon();
  {
    const double r[4] = {0.3, -2, -3, -5}, lo = 0, hi = 1;
    double c[5];
    quartic_from_roots(r, c);
    const double x = Policy::bracketed_root(c, 4, lo, hi, detail::horner(c, 4, lo), detail::horner(c, 4, hi));
    CHECK_NEAR(x, 0.3, 8 * eps);
  }
  {
    const double r[4] = {1e-30, -1, -2, -3}, lo = 0, hi = 1;
    double c[5];
    quartic_from_roots(r, c);
    const double x = Policy::bracketed_root(c, 4, lo, hi, detail::horner(c, 4, lo), detail::horner(c, 4, hi));
    // The companion matrix finds it to eps of the largest root; refining policies to eps of itself.
    CHECK_NEAR(x, 1e-30, refined ? 8 * eps * 1e-30 : 8 * eps);
  }
  {
    const double r[4] = {0.25, -1, -2, -3};
    double c[5];
    quartic_from_roots(r, c);
    CHECK(Policy::bracketed_root(c, 4, 0.25, 1.0, 0.0, detail::horner(c, 4, 1.0)) == 0.25);
  }
}

// Policy::roots_in: every root of one polynomial inside a union of intervals; one solve for the
// statistics however many intervals. Bracketing searches the intervals only and returns those
// roots alone; the eigenvalue policies return every root (theirs can err by more than an
// interval is wide, roots.hpp roots_kept_in), a superset, as a policy may.
template <class Policy> void roots_in_cases() {
  const double r[4] = {-3, -0.5, 0.75, 2};
  double c[5];
  quartic_from_roots(r, c);
  Intervals<double> where;
  where.add(-std::numeric_limits<double>::infinity(), -1);
  where.add(0.5, 1);
  Candidates<double> out;
  stats() = Stats{};
  Counted<Policy>::roots_in(c, 4, where, out);
  CHECK(stats().solves == 1);
  const bool only_inside = has_accurate_roots<Policy>::value;
  CHECK(out.count == (only_inside ? 2 : 4));
  const auto has_root = [&](double x) {
    for (int i = 0; i < out.count; ++i)
      if (std::abs(out.value[i] - x) <= 1e-12) return true;
    return false;
  };
  CHECK(has_root(-3));
  CHECK(has_root(0.75));
  CHECK(where.contains(-1e300) && where.contains(0.5) && !where.contains(0) && !where.contains(2));
}

}  // namespace

int main() {
  static_assert(has_accurate_roots<Counted<Bracketing>>::value && !has_accurate_roots<Counted<EigenCompanion>>::value);
  roots_in_cases<EigenCompanion>();
  roots_in_cases<EigenPolished>();
  roots_in_cases<Bracketing>();
  bracketed_root_cases<EigenCompanion>(false);
  bracketed_root_cases<EigenPolished>(true);
  bracketed_root_cases<Bracketing>(true);
  run_precision<double>();
  run_precision<long double>();
  return check::finish("roots");
}
