// Arc-annulus (Query<Arc3, Annulus3>). Derivation: docs/derivations/annulus.md#an-arc.
#pragma once

#include "annulus_reduction.hpp"
#include "detail/arc_span.hpp"
#include "point_annulus.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// An arc (docs/derivations/annulus.md, "An arc"): an arc of 2 pi is its circle, a zero radius its center.
template <class Real> struct ArcAnnulusPair {
  static constexpr bool defined = true;
  template <class Roots = DefaultRoots> static Real distance(const Arc3<Real>& arc, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_distance<Roots>(arc, a, kind);
    if (whole_arc(arc)) return detail::curve_ring_distance<Roots>(arc_circle(arc), a);
    if (!(arc.radius > 0)) return detail::point_annulus_distance(arc.center, a);
    return detail::curve_ring_distance<Roots>(arc, a);
  }
  template <class Roots = DefaultRoots> static Result<Real> closest(const Arc3<Real>& arc, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_closest<Roots>(arc, a, kind);
    if (whole_arc(arc))
      return as_arc_result(detail::curve_ring_closest<Roots>(arc_circle(arc), a), ArcSpan<Real>(arc), 0);
    if (!(arc.radius > 0)) return Query<Vec3<Real>, Annulus3<Real>>::template closest<Roots>(arc.center, a);
    return detail::curve_ring_closest<Roots>(arc, a);
  }
};

}  // namespace detail

template <class Real> struct Query<Arc3<Real>, Annulus3<Real>> : detail::ArcAnnulusPair<Real> {};

namespace detail {

// Two annuli (docs/derivations/annulus.md, "Two annuli"): an annulus that is a disk or a circle is answered

}  // namespace detail

}  // namespace circledist
