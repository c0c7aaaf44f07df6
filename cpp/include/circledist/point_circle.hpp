// Point-circle (Query<Vec3, Circle3>). Derivation:
// docs/derivations/line_disk.md#1-the-disk-its-frame-and-the-distance-from-a-point.
//
// Point-circle: closed form (note 000 §1, the point-circle distance F),
// detail/point_over_round.hpp.
#pragma once

#include "detail/point_over_round.hpp"
#include "query.hpp"

namespace circledist {

template <class Real> struct Query<Vec3<Real>, Circle3<Real>> : detail::PointRoundQuery<Real, false> {};

}  // namespace circledist
