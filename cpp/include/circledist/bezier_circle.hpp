// Bezier-circle (Query<BezierCurve3, Circle3>): CurveRoundQuery, detail/curve_round_query.hpp.
// Derivation: docs/derivations/bezier.md.
#pragma once

#include "detail/curve_round_query.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

template <class Real> struct Query<BezierCurve3<Real>, Circle3<Real>>
    : detail::CurveRoundQuery<Real, detail::RingTarget<Real>> {};

}  // namespace circledist
