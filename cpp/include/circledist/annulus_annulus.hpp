// Annulus-annulus (Query<Annulus3, Annulus3>). Derivation:
// docs/derivations/annulus.md#two-annuli-and-the-false-contacts-of-diskdisk.
#pragma once

#include "annulus_reduction.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// other ring.
template <class Real> struct AnnulusAnnulusPair {
  static constexpr bool defined = true;

  template <class Roots = DefaultRoots> static Real distance(const Annulus3<Real>& a, const Annulus3<Real>& b) {
    using namespace detail;
    const AnnulusKind ka = annulus_kind(a), kb = annulus_kind(b);
    if (ka == AnnulusKind::kDisk) return circledist::distance<Roots>(annulus_disk(a), b);
    if (ka == AnnulusKind::kCircle) return circledist::distance<Roots>(outer_rim(a), b);
    if (ka != AnnulusKind::kRing) return degenerate_annulus_result<Real>(ka).distance;
    if (kb != AnnulusKind::kRing) return distance<Roots>(b, a);  // b as its disk or circle
    // Where the outer disks' closest pair lies in both rings it is the annuli's; distance()
    // needs that pair, so it runs closest() (the same number).
    return closest<Roots>(a, b).distance;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Annulus3<Real>& a, const Annulus3<Real>& b) {
    using namespace detail;
    const AnnulusKind ka = annulus_kind(a), kb = annulus_kind(b);
    if (ka == AnnulusKind::kDisk) return circledist::closest_points<Roots>(annulus_disk(a), b);
    if (ka == AnnulusKind::kCircle)
      return rim_as_annulus(circledist::closest_points<Roots>(outer_rim(a), b).swapped(), a.outer_radius).swapped();
    if (ka != AnnulusKind::kRing) return degenerate_annulus_result<Real>(ka);
    if (kb != AnnulusKind::kRing) return closest<Roots>(b, a).swapped();
    // The outer disks first (docs/derivations/annulus.md, "Two annuli"): A and B lie in them, so a closest
    // pair of the disks with both points in the rings (s >= inner on each) is one of the annuli,
    // and the disks' `unique` is theirs. A contact of the disks in a hole is no contact of the
    // annuli (the false contacts): the rims answer then.
    const Result<Real> disks = circledist::closest_points<Roots>(annulus_disk(a), annulus_disk(b));
    if (disks.param_a.x() >= a.inner_radius && disks.param_b.x() >= b.inner_radius) return disks;
    CircleAnnulusCandidates<Real> candidates;
    // a's rims against b: a's side a rim point, (radius, theta) on a.
    const auto from_a = [](Result<Real> r, Real radius) {
      r.param_a = Vec2<Real>(radius, r.param_a.x());
      return r;
    };
    candidates.add(from_a(curve_ring_closest<Roots>(outer_rim(a), b), a.outer_radius));
    candidates.add(from_a(curve_ring_closest<Roots>(inner_rim(a), b), a.inner_radius));
    candidates.add(from_a(curve_ring_closest<Roots>(outer_rim(b), a), b.outer_radius).swapped());
    candidates.add(from_a(curve_ring_closest<Roots>(inner_rim(b), a), b.inner_radius).swapped());
    const Real scale = std::max({a.outer_radius, b.outer_radius, (a.center - b.center).norm()});
    return best_of(candidates, scale > 0 ? scale : Real(1));
  }
};

}  // namespace detail

template <class Real> struct Query<Annulus3<Real>, Annulus3<Real>> : detail::AnnulusAnnulusPair<Real> {};

}  // namespace circledist
