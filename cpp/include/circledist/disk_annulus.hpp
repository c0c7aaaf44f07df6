// Disk-annulus: ConvexAnnulusQuery, annulus_reduction.hpp. Derivation:
// docs/derivations/annulus.md#convex-shapes-point-line-ray-segment-disk;
// docs/derivations/annulus.md#two-annuli-and-the-false-contacts-of-diskdisk.
#pragma once

#include "annulus_reduction.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

template <class Real> struct Query<Disk3<Real>, Annulus3<Real>> : detail::ConvexAnnulusQuery<Real, Disk3<Real>> {};

}  // namespace circledist
