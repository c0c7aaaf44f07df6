// Point-annulus (Query<Vec3, Annulus3>). Derivation: docs/derivations/annulus.md#a-point.
#pragma once

#include "annulus_reduction.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// A point: closed form (docs/derivations/annulus.md, "A point").
template <class Real> struct PointAnnulusPair {
  static constexpr bool defined = true;
  template <class Roots = DefaultRoots> static Real distance(const Vec3<Real>& p, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_distance<Roots>(p, a, kind);
    return detail::point_annulus_distance(p, a);
  }
  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_closest<Roots>(p, a, kind);
    return detail::PointRingQuery<Real>::closest(p, a.center, a.normal, a.inner_radius, a.outer_radius);
  }
};

}  // namespace detail

template <class Real> struct Query<Vec3<Real>, Annulus3<Real>> : detail::PointAnnulusPair<Real> {};

}  // namespace circledist
