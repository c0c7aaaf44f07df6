// Disk-arc (Query<Disk3, Arc3>): RoundArcQuery, circle_arc.hpp. Derivation:
// docs/derivations/arc.md#a-circle-or-a-disk.
#pragma once

#include "circle_arc.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

template <class Real> struct Query<Disk3<Real>, Arc3<Real>> : detail::RoundArcQuery<Real, Disk3<Real>> {};

}  // namespace circledist
