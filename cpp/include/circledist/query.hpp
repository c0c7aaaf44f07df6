// The symmetric front end. Each query family specializes Query<A, B> once, for one argument
// order; distance(b, a) and closest_points(b, a) reuse it and swap the result.
#pragma once

#include "primitives.hpp"
#include "roots.hpp"

#include <type_traits>

namespace circledist {

template <class A, class B, class Enable = void> struct Query {
  static constexpr bool defined = false;
};

template <class A, class B> constexpr bool has_query_v = Query<A, B>::defined;
template <class A, class B> constexpr bool has_symmetric_query_v = has_query_v<A, B> || has_query_v<B, A>;

// The distance only: no closest points are built.
template <class Roots = DefaultRoots, class A, class B> CIRCLEDIST_INLINE auto distance(const A& a, const B& b) {
  static_assert(has_symmetric_query_v<A, B>, "circledist: no query for this pair of shapes");
  if constexpr (has_query_v<A, B>) {
    return Query<A, B>::template distance<Roots>(a, b);
  } else {
    return Query<B, A>::template distance<Roots>(b, a);
  }
}

// Distance, closest points on a and b, their parameters and the `unique` flag.
template <class Roots = DefaultRoots, class A, class B> auto closest_points(const A& a, const B& b) {
  static_assert(has_symmetric_query_v<A, B>, "circledist: no query for this pair of shapes");
  if constexpr (has_query_v<A, B>) {
    return Query<A, B>::template closest<Roots>(a, b);
  } else {
    return Query<B, A>::template closest<Roots>(b, a).swapped();
  }
}

}  // namespace circledist
