// Swept shapes: a shape grown by a sweep radius r >= 0, the set of points within r of it (its
// Minkowski sum with a ball). A point becomes a ball, a segment a capsule, a ray a half-infinite
// capsule, a line an infinite cylinder, a circle a solid torus, a disk a rounded disk, a Bezier
// curve or an arc a tube, an annulus a rounded washer.
//
// With d the distance between the cores, the distance between swept shapes is
//   max(0, d - r_a - r_b),
// and, when the swept shapes are apart (d > r_a + r_b), their closest points are the cores'
// closest points moved towards each other along the connecting direction u = (p_b - p_a) / d:
//   p_a + r_a u  and  p_b - r_b u.
// When they touch or overlap (d <= r_a + r_b) the distance is 0 and both returned points are one
// common point: the point on the cores' connecting segment halfway through the stretch that lies
// in both swept shapes, p_a + t u with t the middle of [max(0, d - r_b), min(d, r_a)]. When d == 0
// the direction u is undefined and not needed: that point is the cores' contact point p_a, returned
// as both points (p_b equals it up to rounding).
// Parameters (param_a, param_b) are always those of the cores' closest points. `unique` is the
// cores' flag while the swept shapes are apart or touch at exactly d == r_a + r_b; overlapping
// swept shapes (d < r_a + r_b) share a whole region of points, so `unique` is then false (unless
// one side is a bare point, which is the only common point).
// Sweeps of zero give back the core's result bit for bit.
#pragma once

#include "all_pairs.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <utility>

namespace circledist {

// The scalar type of a primitive.
template <class Real> Real scalar_tag(const Vec3<Real>&);
template <class Real> Real scalar_tag(const Line3<Real>&);
template <class Real> Real scalar_tag(const Ray3<Real>&);
template <class Real> Real scalar_tag(const Segment3<Real>&);
template <class Real> Real scalar_tag(const Circle3<Real>&);
template <class Real> Real scalar_tag(const Disk3<Real>&);
template <class Real> Real scalar_tag(const BezierCurve3<Real>&);
template <class Real> Real scalar_tag(const Arc3<Real>&);
template <class Real> Real scalar_tag(const Annulus3<Real>&);
template <class S> using scalar_t = decltype(scalar_tag(std::declval<const S&>()));

// A primitive S grown by `sweep` (>= 0).
template <class S> struct Swept {
  using Shape = S;
  S shape;
  scalar_t<S> sweep = 0;
};

template <class S> Swept<S> swept(const S& shape, scalar_t<S> sweep) { return Swept<S>{shape, sweep}; }

template <class S> Swept<S> swept(const Swept<S>& s, scalar_t<S> more) { return Swept<S>{s.shape, s.sweep + more}; }

// The order of same-kind queries (primitives.hpp): by the shape, then by the sweep.
template <class S> bool precedes(const Swept<S>& x, const Swept<S>& y) {
  return precedes(x.shape, y.shape) || (!precedes(y.shape, x.shape) && x.sweep < y.sweep);
}

template <class T> struct is_swept : std::false_type {};
template <class S> struct is_swept<Swept<S>> : std::true_type {};
template <class T> constexpr bool is_swept_v = is_swept<T>::value;

template <class T> struct core_type {
  using type = T;
};
template <class S> struct core_type<Swept<S>> {
  using type = S;
};
template <class T> using core_t = typename core_type<T>::type;

// The core of a shape (itself when not swept) and its sweep (0 when not swept).
template <class T> const T& core(const T& shape) { return shape; }
template <class S> const S& core(const Swept<S>& s) { return s.shape; }
template <class T> scalar_t<core_t<T>> sweep_of(const T&) { return 0; }
template <class S> scalar_t<S> sweep_of(const Swept<S>& s) { return s.sweep; }

// max(0, d - ra - rb), with a NaN core distance passed on.
template <class Real> Real swept_distance(Real d, Real ra, Real rb) {
  // The larger radius first: as accurate as either order, and the same whichever shape is a.
  const Real gap = (d - std::max(ra, rb)) - std::min(ra, rb);
  return gap > 0 || gap != gap ? gap : Real(0);
}

// The swept result from the cores' result (see the header comment). `point_only` is true when a
// side is a bare point (a point with sweep 0): a single common point then.
template <class Real> Result<Real> swept_result(const Result<Real>& core, Real ra, Real rb, bool point_only) {
  Result<Real> r = core;
  if (ra == 0 && rb == 0) return r;
  const Real d = r.distance;
  if (d != d) return r;
  const Vec3<Real> w = r.point_b - r.point_a;
  const Real length = w.norm();
  // The connecting direction; undefined when the cores touch (or their points round together).
  const bool has_direction = d > 0 && length > 0;
  const Vec3<Real> u = has_direction ? Vec3<Real>(w / length) : Vec3<Real>::Zero();
  r.distance = swept_distance(d, ra, rb);
  if (d > ra + rb) {
    if (has_direction) {
      r.point_a = r.point_a + ra * u;
      r.point_b = r.point_b - rb * u;
    }
    return r;
  }
  if (d > 0) {
    const Real lo = std::max(Real(0), d - rb), hi = std::min(d, ra);
    const Real t = (lo + hi) / 2;
    const Vec3<Real> common = has_direction ? Vec3<Real>(r.point_a + t * u) : r.point_a;
    r.point_a = common;
    r.point_b = common;
  }
  // d == 0: the cores' contact point p_a lies in both swept shapes (p_b equals it up to
  // rounding); both returned points are that one common point.
  if (d == 0) r.point_b = r.point_a;
  if (d < ra + rb && !point_only) r.unique = false;
  return r;
}

template <class T> constexpr bool is_bare_point_type_v = std::is_same_v<core_t<T>, Vec3<scalar_t<core_t<T>>>>;

// Lazy forms of the traits (std::conjunction instantiates the query test only for swept pairs).
template <class A, class B> struct has_core_query : std::bool_constant<has_symmetric_query_v<core_t<A>, core_t<B>>> {};
template <class A, class B> struct either_swept : std::bool_constant<is_swept_v<A> || is_swept_v<B>> {};

// Every pair of shapes with a query gets the same pair with either or both sides swept.
template <class A, class B>
struct Query<A, B, std::enable_if_t<std::conjunction_v<either_swept<A, B>, has_core_query<A, B>>>> {
  static constexpr bool defined = true;
  using Real = scalar_t<core_t<A>>;

  template <class Roots = DefaultRoots> static Real distance(const A& a, const B& b) {
    return swept_distance(circledist::distance<Roots>(core(a), core(b)), Real(sweep_of(a)), Real(sweep_of(b)));
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const A& a, const B& b) {
    const Real ra = sweep_of(a), rb = sweep_of(b);
    const bool point_only = (is_bare_point_type_v<A> && ra == 0) || (is_bare_point_type_v<B> && rb == 0);
    return swept_result(circledist::closest_points<Roots>(core(a), core(b)), ra, rb, point_only);
  }
};

}  // namespace circledist
