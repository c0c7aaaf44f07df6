// Point-disk (Query<Vec3, Disk3>). Derivation:
// docs/derivations/line_disk.md#1-the-disk-its-frame-and-the-distance-from-a-point.
//
// Point-disk: closed form (note 001 §2), detail/point_over_round.hpp.
#pragma once

#include "detail/point_over_round.hpp"
#include "query.hpp"

namespace circledist {

template <class Real> struct Query<Vec3<Real>, Disk3<Real>> : detail::PointRoundQuery<Real, true> {};

}  // namespace circledist
