// An annulus's parts: its outer disk, its rims, and what kind of set it is (a true ring, a disk,
// a circle, empty or NaN). Derivation: docs/derivations/annulus.md#the-annulus.
#pragma once

#include "../primitives.hpp"

#include <cmath>
#include <limits>

namespace circledist::detail {

template <class Real> Disk3<Real> annulus_disk(const Annulus3<Real>& a) { return {a.center, a.normal, a.outer_radius}; }
template <class Real> Circle3<Real> outer_rim(const Annulus3<Real>& a) { return {a.center, a.normal, a.outer_radius}; }
template <class Real> Circle3<Real> inner_rim(const Annulus3<Real>& a) { return {a.center, a.normal, a.inner_radius}; }

// What an annulus is (Annulus3's definition, primitives.hpp): the disk, the circle, a true ring,
// the empty set or NaN.
enum class AnnulusKind { kRing, kDisk, kCircle, kEmpty, kNaN };
template <class Real> AnnulusKind annulus_kind(const Annulus3<Real>& a) {
  if (std::isnan(a.inner_radius) || std::isnan(a.outer_radius)) return AnnulusKind::kNaN;
  if (a.inner_radius > a.outer_radius) return AnnulusKind::kEmpty;
  if (!(a.inner_radius > 0)) return AnnulusKind::kDisk;
  if (a.inner_radius == a.outer_radius) return AnnulusKind::kCircle;
  return AnnulusKind::kRing;
}

// The Result of the empty set or a NaN annulus (b's side).
template <class Real> Result<Real> degenerate_annulus_result(AnnulusKind kind) {
  Result<Real> r;
  r.distance =
      kind == AnnulusKind::kEmpty ? std::numeric_limits<Real>::infinity() : std::numeric_limits<Real>::quiet_NaN();
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  r.point_a = r.point_b = Vec3<Real>::Constant(nan);
  r.param_a = r.param_b = Vec2<Real>::Constant(nan);
  return r;
}

// A rim's Result (b's side a circle's (theta, 0)) as the annulus's (radius, theta).
template <class Real> Result<Real> rim_as_annulus(Result<Real> r, Real radius) {
  r.param_b = Vec2<Real>(radius, r.param_b.x());
  return r;
}

// The front end's answer of x against the annulus's disk or circle (its kinds kDisk, kCircle,
// kEmpty, kNaN), b's side in the annulus's parameter. (The front end orders two disks as

}  // namespace circledist::detail
