// Bezier-annulus: CurveAnnulusQuery, annulus_reduction.hpp. Derivation:
// docs/derivations/annulus.md#a-bezier-curve.
#pragma once

#include "annulus_reduction.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

template <class Real> struct Query<BezierCurve3<Real>, Annulus3<Real>>
    : detail::CurveAnnulusQuery<Real, BezierCurve3<Real>> {};

}  // namespace circledist
