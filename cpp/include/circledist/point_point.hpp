// Point-point (Query<Vec3, Vec3>). Derivation: |q - p|, no derivation page.
#pragma once

#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

template <class Real> struct PointPointPair {
  static constexpr bool defined = true;
  template <class Roots = DefaultRoots> static Real distance(const Vec3<Real>& p, const Vec3<Real>& q) {
    return (q - p).norm();
  }
  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Vec3<Real>& q) {
    Result<Real> r;
    r.distance = (q - p).norm();
    r.point_a = p;
    r.point_b = q;
    return r;
  }
};

}  // namespace detail

template <class Real> struct Query<Vec3<Real>, Vec3<Real>> : detail::PointPointPair<Real> {};

}  // namespace circledist
