// Requested effects, from cheapest to dearest: intersects(a, b) and within(a, b, d) (booleans),
// distance(a, b) (query.hpp: never builds closest points), closest_points(a, b). The booleans
// first try the cheap exact bounds of bounds.hpp and run the polynomial solver only when the
// bounds cannot decide. Every shape may be swept (sweep.hpp).
//
// Definitions. With D the library's distance(a, b) and s the pair's length scale,
//   within(a, b, d)   is   D <= d + tol,   tol = 64 eps (s + d)   (d >= 0; false for d < 0),
//   intersects(a, b)  is   within(a, b, 0).
// The tolerance absorbs the rounding of D itself: a segment through a disk computes its height at
// the crossing as ~1e-17, not 0. The bounds decide only with a margin of sqrt(eps) (s + d) to
// spare (far above the solvers' error), so a decision by bounds always agrees with the solver;
// the answer is the same as `distance(a, b) <= d + tol` computed for every pair.
//
// Counters (Stats, one set per thread) let callers and tests see the work done:
//   solves             polynomial solves (calls of a root policy wrapped in Counted<>)
//   distances          exact distance evaluations (one per pair, including within()'s fallbacks)
//   closest_points     closest-point evaluations
//   within             within() / intersects() / distance_if_within() pair tests
//   decided_by_bounds  of those, the ones the bounds decided (no exact distance evaluated)
//   culled             pairs a broadphase (a scene's bounding-volume hierarchy) skipped unseen
// within() and friends always count; circledist::distance() / closest_points() count solves only
// when given a Counted<> root policy (the Python module always does).
#pragma once

#include "bounds.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace circledist {

struct Stats {
  std::uint64_t solves = 0;
  std::uint64_t distances = 0;
  std::uint64_t closest_points = 0;
  std::uint64_t within = 0;
  std::uint64_t decided_by_bounds = 0;
  std::uint64_t culled = 0;
};

// Counters add up: a program that answers on several threads adds each thread's counts (the
// difference of its stats() after and before) to the caller's.
inline Stats& operator+=(Stats& a, const Stats& b) {
  a.solves += b.solves;
  a.distances += b.distances;
  a.closest_points += b.closest_points;
  a.within += b.within;
  a.decided_by_bounds += b.decided_by_bounds;
  a.culled += b.culled;
  return a;
}
inline Stats operator-(Stats a, const Stats& b) {
  a.solves -= b.solves;
  a.distances -= b.distances;
  a.closest_points -= b.closest_points;
  a.within -= b.within;
  a.decided_by_bounds -= b.decided_by_bounds;
  a.culled -= b.culled;
  return a;
}

// The calling thread's counters.
inline Stats& stats() {
  static thread_local Stats s;
  return s;
}
inline void reset_stats() { stats() = Stats{}; }

// A root policy that counts its calls in stats().solves and otherwise is `Roots`.
template <class Roots> struct Counted {
  static constexpr Polish polish() { return Roots::polish(); }
  static constexpr bool accurate_roots = has_accurate_roots<Roots>::value;
  using Inner = Roots;

  template <class Real, int Capacity>
  static auto roots(const Real* coefficients, int degree, Real lo, Real hi, Candidates<Real, Capacity>& out)
      -> decltype(Roots::roots(coefficients, degree, lo, hi, out)) {
    ++stats().solves;
    return Roots::roots(coefficients, degree, lo, hi, out);
  }

  template <class Real, int Capacity> static void roots_in(const Real* coefficients, int degree,
                                                           const Intervals<Real>& intervals,
                                                           Candidates<Real, Capacity>& out) {
    ++stats().solves;
    Roots::roots_in(coefficients, degree, intervals, out);
  }

  template <class Real>
  static Real bracketed_root(const Real* coefficients, int degree, Real lo, Real hi, Real p_lo, Real p_hi) {
    ++stats().solves;
    return Roots::bracketed_root(coefficients, degree, lo, hi, p_lo, p_hi);
  }
};

template <class Roots> struct counted_policy {
  using type = Counted<Roots>;
};
template <class Roots> struct counted_policy<Counted<Roots>> {
  using type = Counted<Roots>;
};
template <class Roots> using counted_t = typename counted_policy<Roots>::type;

// The tolerance of within(): see the header comment.
template <class Real> Real touch_tolerance(Real scale) { return 64 * std::numeric_limits<Real>::epsilon() * scale; }
template <class Real> Real bounds_margin(Real scale) { return std::sqrt(std::numeric_limits<Real>::epsilon()) * scale; }

// What the bounds say about `distance <= limit (+ tol)`: decided true, decided false, or unknown.
enum class Verdict { No, Yes, Unknown };

template <class Real> Verdict judge(const DistanceBounds<Real>& b, Real limit) {
  const Real scale = b.scale + limit;
  const Real tol = touch_tolerance(scale), margin = bounds_margin(scale) + b.rounding;
  if (b.lower > limit + tol + margin) return Verdict::No;
  if (b.upper + margin <= limit || b.upper <= tol / 2) return Verdict::Yes;
  return Verdict::Unknown;
}

// The pair's length scale when no bounds were computed (closed-form pairs).
template <class A, class B> scalar_t<core_t<A>> plain_scale(const A& a, const B& b) {
  return pair_scale(bounding_ball(a), a, bounding_ball(b), b);
}

template <class A, class B> constexpr bool pair_has_bounds_v = has_bounds_v<core_t<A>, core_t<B>>;

namespace detail {

// What distance_if_within() and within() answer: whether distance <= d (+ tol), and the distance
// then (+inf otherwise, or when it was not computed).
template <class Real> struct WithinAnswer {
  bool within;
  Real distance;
};

// distance_if_within() (NeedDistance) and within() on shapes in double or wider, of a moderate
// scene size: the bounds first; within() stops at either of their verdicts, distance_if_within()
// only at a No (it needs the distance of a Yes).
template <class Roots, bool NeedDistance, class A, class B>
WithinAnswer<scalar_t<core_t<A>>> moderate_within(const A& a, const B& b, scalar_t<core_t<A>> d) {
  using Real = scalar_t<core_t<A>>;
  Stats& st = stats();
  ++st.within;
  const Real inf = std::numeric_limits<Real>::infinity();
  if (!(d >= 0)) {
    ++st.decided_by_bounds;
    return {false, inf};
  }
  Real scale;
  if constexpr (pair_has_bounds_v<A, B>) {
    const DistanceBounds<Real> bounds = distance_bounds(a, b);
    const Verdict v = judge(bounds, d);
    if (v == Verdict::No || (v == Verdict::Yes && !NeedDistance)) {
      ++st.decided_by_bounds;
      return {v == Verdict::Yes, inf};
    }
    scale = bounds.scale;
  } else {
    scale = plain_scale(a, b);
  }
  ++st.distances;
  const Real D = circledist::distance<counted_t<Roots>>(a, b);
  const bool within = D <= d + touch_tolerance(scale + d);
  return {within, within ? D : inf};
}

// The effects' front end, as query.hpp's is distance()'s: float shapes are decided in double, and
// a scene out of the moderate size range (the bounds square coordinates: at 1e155 a scale of inf
// made every pair "within") is scaled by a power of two first. within() is invariant under the
// scaling: D, d and the tolerance scale alike.
template <class S> auto promoted_shape(const S& s) { return promoted(s); }
template <class S> auto promoted_shape(const Swept<S>& s) { return swept(promoted(s.shape), double(s.sweep)); }
template <class S> S scaled_shape(const S& s, int e) { return scaled(s, e); }
template <class S> Swept<S> scaled_shape(const Swept<S>& s, int e) {
  return {scaled(s.shape, e), std::ldexp(s.sweep, e)};
}
template <class A, class B> constexpr bool promotable_pair_v =
    promotable<core_t<A>>::value && promotable<core_t<B>>::value;
template <class A, class B> constexpr bool scalable_pair_v = scalable<core_t<A>>::value && scalable<core_t<B>>::value;

}  // namespace detail

// The distance when it is at most d (+ tol), +inf otherwise: the exact distance is evaluated
// only when the bounds cannot show it exceeds d. (What a nearest-neighbour search asks.)
template <class Roots = DefaultRoots, class A, class B>
scalar_t<core_t<A>> distance_if_within(const A& a, const B& b, scalar_t<core_t<A>> d) {
  using Real = scalar_t<core_t<A>>;
  if constexpr (detail::ordered_v<A, B>) {  // one order for shapes of one kind (query.hpp)
    if (precedes(b, a)) return distance_if_within<Roots>(b, a, d);
  }
  if constexpr (detail::promotable_pair_v<A, B>) {
    return Real(distance_if_within<Roots>(detail::promoted_shape(a), detail::promoted_shape(b), double(d)));
  } else {
    if constexpr (detail::scalable_pair_v<A, B>) {
      const int e = detail::scene_exponent(core(a), core(b));
      if (e != 0)
        return std::ldexp(detail::moderate_within<Roots, true>(detail::scaled_shape(a, e), detail::scaled_shape(b, e),
                                                               std::ldexp(d, e))
                              .distance,
                          -e);
    }
    return detail::moderate_within<Roots, true>(a, b, d).distance;
  }
}

// distance(a, b) <= d + tol, deciding by bounds where they suffice.
template <class Roots = DefaultRoots, class A, class B> bool within(const A& a, const B& b, scalar_t<core_t<A>> d) {
  if constexpr (detail::ordered_v<A, B>) {  // one order for shapes of one kind (query.hpp)
    if (precedes(b, a)) return within<Roots>(b, a, d);
  }
  if constexpr (detail::promotable_pair_v<A, B>) {
    return within<Roots>(detail::promoted_shape(a), detail::promoted_shape(b), double(d));
  } else {
    if constexpr (detail::scalable_pair_v<A, B>) {
      const int e = detail::scene_exponent(core(a), core(b));
      if (e != 0)
        return detail::moderate_within<Roots, false>(detail::scaled_shape(a, e), detail::scaled_shape(b, e),
                                                     std::ldexp(d, e))
            .within;
    }
    return detail::moderate_within<Roots, false>(a, b, d).within;
  }
}

// Whether the shapes touch or overlap: within(a, b, 0).
template <class Roots = DefaultRoots, class A, class B> bool intersects(const A& a, const B& b) {
  return within<Roots>(a, b, scalar_t<core_t<A>>(0));
}

// distance() and closest_points() that count their evaluations and solves in stats().
template <class Roots = DefaultRoots, class A, class B> auto counted_distance(const A& a, const B& b) {
  ++stats().distances;
  return circledist::distance<counted_t<Roots>>(a, b);
}
template <class Roots = DefaultRoots, class A, class B> auto counted_closest_points(const A& a, const B& b) {
  ++stats().closest_points;
  return circledist::closest_points<counted_t<Roots>>(a, b);
}

}  // namespace circledist
