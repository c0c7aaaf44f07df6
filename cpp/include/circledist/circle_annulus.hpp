// Circle-annulus: CurveAnnulusQuery, annulus_reduction.hpp. Derivation:
// docs/derivations/annulus.md#a-circle.
#pragma once

#include "annulus_reduction.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

template <class Real> struct Query<Circle3<Real>, Annulus3<Real>> : detail::CurveAnnulusQuery<Real, Circle3<Real>> {};

}  // namespace circledist
