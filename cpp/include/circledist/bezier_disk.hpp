// Bezier-disk (Query<BezierCurve3, Disk3>): CurveRoundQuery, detail/curve_round_query.hpp.
// Derivation: docs/derivations/bezier.md.
#pragma once

#include "detail/curve_round_query.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

template <class Real> struct Query<BezierCurve3<Real>, Disk3<Real>>
    : detail::CurveRoundQuery<Real, detail::DiskTarget<Real>> {};

}  // namespace circledist
