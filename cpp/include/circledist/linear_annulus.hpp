// Line, ray and segment against an annulus: ConvexAnnulusQuery, annulus_reduction.hpp. Derivation:
// docs/derivations/annulus.md#convex-shapes-point-line-ray-segment-disk.
#pragma once

#include "annulus_reduction.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

template <class Real> struct Query<Line3<Real>, Annulus3<Real>> : detail::ConvexAnnulusQuery<Real, Line3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Annulus3<Real>> : detail::ConvexAnnulusQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Annulus3<Real>> : detail::ConvexAnnulusQuery<Real, Segment3<Real>> {
};

}  // namespace circledist
