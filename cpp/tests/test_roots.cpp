// The root policies themselves (roots.hpp): every policy (EigenCompanion, EigenPolished,
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
// The truth, the bars and the checks: roots_problem.hpp.

#include "roots_problem.hpp"

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

namespace test_roots {

using namespace circledist;
using namespace roots_problem;

namespace {

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
  v.push_back(
      problem<Real>("deg8 {0.25,-0.75} 3 pairs", poly(1, {0.25L, -0.75L}, {{-1, 1}, {1.5L, 2}, {0.5L, 0.75L}})));
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
  v.push_back(
      problem<Real>("deg8 {-0.75^4,1.5^2,3,-3}", poly(1, join(join(repeat(-0.75L, 4), repeat(1.5L, 2)), {3, -3}))));
  v.push_back(problem<Real>("deg8 {1^4,3^4}", poly(1, join(repeat(1, 4), repeat(3, 4)))));
  v.push_back(
      problem<Real>("non-dyadic {0.3^3,-1.1^2,2.7}", poly(1, join(join(repeat(0.3L, 3), repeat(-1.1L, 2)), {2.7L}))));
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
  v.push_back(
      problem<Real>("sigma 2^-33 {-3,-1,0.5,2} lead 2^66",
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
  const std::vector<End> ends = {
      {"(x-1/16)(x-3)(x+2)", 0.0625L, {3, -2}},          {"(x-0.1_20)(x-3)(x+2)(x-0.625)", LD(tenth), {3, -2, 0.625L}},
      {"(x-(1+2^-30))(x+1)(x-2)", LD(off_one), {-1, 2}}, {"(x-0.1_20)^2(x+1)(x-2)", LD(tenth), {LD(tenth), -1, 2}},
      {"(x-1/4)^2(x+1)(x-2)", 0.25L, {0.25L, -1, 2}},    {"(x-0.5)^3(x+1)", 0.5L, {0.5L, 0.5L, -1}}};
  for (const End& e : ends) {
    const Problem<Real> p = problem<Real>(e.label, poly(1, join({e.root}, e.others)));
    if (!p.exact) std::printf("test setup: %s is not exact in %s\n", e.label, precision_name<Real>());
    CHECK(p.exact);  // the test's premise
    const Real r = Real(e.root);
    const Real a = r - Real(0.25), b = r + Real(0.25);
    for (auto [lo, hi] :
         std::vector<std::pair<Real, Real>>{{r, b}, {a, r}, {up(r), b}, {a, down(r)}, {down(r), b}, {a, up(r)}, {r, r}})
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
  const Problem<Real> p =
      problem<Real>("deg8 {-3.5..3.5}", poly(1, {-3.5L, -2.5L, -1.5L, -0.5L, 0.5L, 1.5L, 2.5L, 3.5L}));
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
// eigenvalue policies returned none (an arc-circle finding of the differential test). Every
// policy must return all four to 1e-12, whichever way it finds them (roots.hpp:
// roots_without_eigenvalues); in long double the same coefficients do not stall, and must agree.
template <class P, class Real> void stalling_companion() {
  const Real c[9] = {Real(1.0 / 81),    0, Real(-40.0 / 729), 0, Real(62.0 / 729), 0,
                     Real(-40.0 / 729), 0, Real(1.0 / 81)};
  const Real inf = std::numeric_limits<Real>::infinity();
  Candidates<Real> out;
  P::roots(c, 8, -inf, inf, out);
  for (const LD v : {(11 + 2 * std::sqrt(10.0L)) / 9, (11 - 2 * std::sqrt(10.0L)) / 9})
    for (const LD sign : {-1.0L, 1.0L}) {
      const LD root = sign * std::sqrt(v);
      bool found = false;
      for (int i = 0; i < out.count; ++i) found = found || std::abs(LD(out.value[i]) - root) <= 1e-12L;
      if (!found)
        std::printf("[%s, %s] stalling companion: root %.17Lg not found\n", policy_name<P>().c_str(),
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

}  // namespace test_roots

CHECK_SUITE(test_roots);
