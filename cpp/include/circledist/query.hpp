// The symmetric front end. Each query family specializes Query<A, B> once, for one argument
// order; distance(b, a) and closest_points(b, a) reuse it and swap the result.
#pragma once

#include "primitives.hpp"
#include "roots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace circledist {

template <class A, class B, class Enable = void> struct Query {
  static constexpr bool defined = false;
};

template <class A, class B> constexpr bool has_query_v = Query<A, B>::defined;
template <class A, class B> constexpr bool has_symmetric_query_v = has_query_v<A, B> || has_query_v<B, A>;

namespace detail {

template <class Roots, class A, class B> CIRCLEDIST_INLINE auto direct_distance(const A& a, const B& b) {
  if constexpr (has_query_v<A, B>) {
    return Query<A, B>::template distance<Roots>(a, b);
  } else {
    return Query<B, A>::template distance<Roots>(b, a);
  }
}

template <class Roots, class A, class B> CIRCLEDIST_INLINE auto direct_closest_points(const A& a, const B& b) {
  if constexpr (has_query_v<A, B>) {
    return Query<A, B>::template closest<Roots>(a, b);
  } else {
    return Query<B, A>::template closest<Roots>(b, a).swapped();
  }
}

// Two shapes of one kind, which the front end answers in the order `precedes` gives
// (primitives.hpp): both argument orders then agree to the bit. Two points need no order:
// |a - b| is the same number computed either way round.
template <class A> struct needs_order : std::true_type {};
template <class Real> struct needs_order<Vec3<Real>> : std::false_type {};
template <class A, class B, class = void> struct ordered : std::false_type {};
template <class A>
struct ordered<A, A,
               std::enable_if_t<needs_order<A>::value,
                                std::void_t<decltype(precedes(std::declval<const A&>(), std::declval<const A&>()))>>>
    : std::true_type {};
template <class A, class B> constexpr bool ordered_v = ordered<A, B>::value;

// Shapes the front end can promote to double (float primitives) and scale (every primitive):
// found by argument-dependent lookup where the shape is defined (primitives.hpp).
template <class A, class = void> struct promotable : std::false_type {};
template <class A> struct promotable<A, std::void_t<decltype(promoted(std::declval<const A&>()))>> : std::true_type {};
template <class A, class = void> struct scalable : std::false_type {};
template <class A>
struct scalable<A,
                std::void_t<decltype(scaled(std::declval<const A&>(), 0)), decltype(extent(std::declval<const A&>()))>>
    : std::true_type {};

// Distances between 2^(min_exponent / 4) and 2^(max_exponent / 4) (1e-77 .. 1e77 in double) are
// trusted as computed: the solvers square coordinates and differences of coordinates (and the
// octics their fourth powers in units of the scene), which neither overflows nor reaches the
// subnormals there. Outside it (inf or NaN from an overflow, 0 from an underflow, or simply a
// huge or tiny answer) the scene's own size decides: a scene out of that range is scaled by a
// power of two to a largest coordinate in [1, 2), solved, and scaled back, as hypot does.
template <class Real> CIRCLEDIST_INLINE bool moderate(Real x) {
  constexpr Real lo = power_of_two<Real>(std::numeric_limits<Real>::min_exponent / 4);
  constexpr Real hi = power_of_two<Real>(std::numeric_limits<Real>::max_exponent / 4);
  return strictly_between(x, lo, hi);
}

// The exponent to scale a and b by, or 0 when their coordinates are moderate already.
template <class A, class B> int scene_exponent(const A& a, const B& b) {
  const auto largest = std::max(extent(a), extent(b));
  if (!(largest > 0) || !(largest < std::numeric_limits<decltype(largest)>::infinity()) || moderate(largest)) return 0;
  return -std::ilogb(largest);
}

// A scene whose coordinates reach 2^(max_exponent - 3) (2.2e307 in double) can overflow in a
// difference or a short sum of them (a segment from -1.5e308 to 1.5e308: p1 - p0
// is inf), where the query itself would be fine. Before the scene is scaled down to [1, 2), which
// would take its small features (a unit circle beside it, a height of 0.5) into the subnormals,
// it is scaled by 1/4 only: -2 for such a scene, else 0.
template <class A, class B> int overflow_exponent(const A& a, const B& b) {
  using Real = std::decay_t<decltype(extent(a))>;
  const Real largest = std::max(extent(a), extent(b));
  constexpr Real top = power_of_two<Real>(std::numeric_limits<Real>::max_exponent - 3);
  return largest >= top && largest < std::numeric_limits<Real>::infinity() ? -2 : 0;
}

// The answer of the scene scaled when its size asks for it, and the exponent `e` it was scaled
// by (0: no scaling helps, and nothing is solved): by 1/4 first where its coordinates reach the top
// of the range (overflow_exponent), kept if that distance is moderate; else to [1, 2)
// (scene_exponent). distance() and closest_points() both choose through it, so they agree.
template <class A, class B, class Solve, class DistanceOf>
auto solve_rescaled(const A& a, const B& b, const Solve& solve, const DistanceOf& distance_of, int& e) {
  e = overflow_exponent(a, b);
  if (e != 0) {
    const auto quarter = solve(scaled(a, e), scaled(b, e));
    if (moderate(distance_of(quarter))) return quarter;
  }
  e = scene_exponent(a, b);
  return e != 0 ? solve(scaled(a, e), scaled(b, e)) : decltype(solve(a, b)){};
}

// The distance of the scene scaled when its size asks for it (else d, as computed): out of line,
// so that the common path of ranged_distance stays one comparison.
template <class Roots, class A, class B, class Real>
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline, cold))
#endif
Real rescaled_distance(const A& a, const B& b, Real d) {
  int e = 0;
  const Real r = solve_rescaled(
      a, b, [](const auto& x, const auto& y) { return direct_distance<Roots>(x, y); }, [](Real v) { return v; }, e);
  return e != 0 ? Real(std::ldexp(r, -e)) : d;
}

// direct_distance, checked for range (`moderate`) and recomputed on the scaled scene.
template <class Roots, class A, class B> CIRCLEDIST_INLINE auto ranged_distance(const A& a, const B& b) {
  const auto d = direct_distance<Roots>(a, b);
  if constexpr (scalable<A>::value && scalable<B>::value) {
    if (!moderate(d)) return rescaled_distance<Roots>(a, b, d);
  }
  return d;
}

// closest_points of the scene scaled when its size asks for it (else r, as computed): out of
// line, as rescaled_distance is.
template <class Roots, class A, class B, class R>
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline, cold))
#endif
R rescaled_closest_points(const A& a, const B& b, const R& computed) {
  int e = 0;
  R r = solve_rescaled(
      a, b, [](const auto& x, const auto& y) { return direct_closest_points<Roots>(x, y); },
      [](const R& answer) { return answer.distance; }, e);
  if (e == 0) return computed;
  r.distance = std::ldexp(r.distance, -e);
  r.point_a = ldexp3(r.point_a, -e);
  r.point_b = ldexp3(r.point_b, -e);
  r.param_a = unscaled_param(r.param_a, a, e);
  r.param_b = unscaled_param(r.param_b, b, e);
  return r;
}

template <class Roots, class A, class B> CIRCLEDIST_INLINE auto ranged_closest_points(const A& a, const B& b) {
  auto r = direct_closest_points<Roots>(a, b);
  if constexpr (scalable<A>::value && scalable<B>::value) {
    if (!moderate(r.distance)) r = rescaled_closest_points<Roots>(a, b, r);
  }
  return r;
}

}  // namespace detail

namespace detail {

// The front end's own steps: float shapes are solved in double and the answer rounded
// (primitives.hpp, promoted()); scenes out of the moderate range are scaled.
template <class Roots, class A, class B> CIRCLEDIST_INLINE auto promoted_distance(const A& a, const B& b) {
  if constexpr (promotable<A>::value && promotable<B>::value) {
    return float(ranged_distance<Roots>(promoted(a), promoted(b)));
  } else {
    return ranged_distance<Roots>(a, b);
  }
}

// The answer's parameters moved into the shapes' domains (param_in_domain, primitives.hpp), in
// place: a copy of the whole answer per kernel, inlined everywhere, cost the module tens of kB.
template <class R, class A, class B> inline void keep_params_in_domain(R& r, const A& a, const B& b) {
  r.param_a = param_in_domain(r.param_a, a);
  r.param_b = param_in_domain(r.param_b, b);
}

template <class Roots, class A, class B> CIRCLEDIST_INLINE auto promoted_closest_points(const A& a, const B& b) {
  if constexpr (promotable<A>::value && promotable<B>::value) {
    const auto pa = promoted(a);
    const auto pb = promoted(b);
    auto r = ranged_closest_points<Roots>(pa, pb);
    keep_params_in_domain(r, pa, pb);
    return r.template cast<float>();
  } else {
    auto r = ranged_closest_points<Roots>(a, b);
    keep_params_in_domain(r, a, b);
    return r;
  }
}

}  // namespace detail

// The distance only: no closest points are built. Two shapes of one kind are answered in one
// order whichever way they are given (detail::ordered_v). An eigenvalue policy is answered
// through SelectedEigenPolicy, with it chosen for the call (roots.hpp, detail::selected_eigen).
template <class Roots = DefaultRoots, class A, class B> CIRCLEDIST_INLINE auto distance(const A& a, const B& b) {
  static_assert(has_symmetric_query_v<A, B>, "circledist: no query for this pair of shapes");
  if constexpr (detail::selected_eigen<Roots>::value) {
    const SelectedEigenPolicy::Use use(detail::selected_eigen<Roots>::which);
    return distance<typename detail::selected_eigen<Roots>::type>(a, b);
  } else {
    if constexpr (detail::ordered_v<A, B>) {
      if (precedes(b, a)) return detail::promoted_distance<Roots>(b, a);
    }
    return detail::promoted_distance<Roots>(a, b);
  }
}

// Distance, closest points on a and b, their parameters and the `unique` flag.
template <class Roots = DefaultRoots, class A, class B> CIRCLEDIST_INLINE auto closest_points(const A& a, const B& b) {
  static_assert(has_symmetric_query_v<A, B>, "circledist: no query for this pair of shapes");
  if constexpr (detail::selected_eigen<Roots>::value) {
    const SelectedEigenPolicy::Use use(detail::selected_eigen<Roots>::which);
    return closest_points<typename detail::selected_eigen<Roots>::type>(a, b);
  } else {
    if constexpr (detail::ordered_v<A, B>) {
      if (precedes(b, a)) return detail::promoted_closest_points<Roots>(b, a).swapped();
    }
    return detail::promoted_closest_points<Roots>(a, b);
  }
}

}  // namespace circledist
