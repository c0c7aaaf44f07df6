// Point-disk: closed form of note 001 §2.
#pragma once

#include "detail/point_over_round.hpp"
#include "planar.hpp"
#include "query.hpp"

namespace circledist {

template <class Real> struct Query<Vec3<Real>, Disk3<Real>> {
  static constexpr bool defined = true;

  // |z| over the disk (rho <= R), else the rim's distance, from the height z and the distance rho
  // from the axis (detail/point_over_round.hpp); closest() takes the same two numbers, so the
  // two agree to the bit.
  template <class Roots = DefaultRoots> CIRCLEDIST_INLINE static Real distance(const Vec3<Real>& p, const Disk3<Real>& disk) {
    const detail::PointOverRound<Real> seen(p, disk.center, disk.normal);
    return seen.radial <= disk.radius ? std::abs(seen.height) : length2d(seen.height, seen.radial - disk.radius);
  }

  // Over the disk, the point below P, param (rho, theta); outside, the rim point in the direction
  // of the point's in-plane part, param (R, theta); theta = atan2(y, x) in the disk's frame.
  template <class Roots = DefaultRoots> CIRCLEDIST_INLINE static Result<Real> closest(const Vec3<Real>& p, const Disk3<Real>& disk) {
    const detail::PointOverRound<Real> seen(p, disk.center, disk.normal);
    Result<Real> r;
    r.point_a = p;
    const Real theta = seen.angle();
    if (seen.radial <= disk.radius) {
      r.distance = std::abs(seen.height);
      r.point_b = seen.below(disk.center);
      r.param_b = Vec2<Real>(seen.radial, theta);
    } else {
      r.distance = length2d(seen.height, seen.radial - disk.radius);
      r.point_b = seen.on_rim(disk.center, disk.radius);  // rho > R >= 0: q has a direction
      r.param_b = Vec2<Real>(disk.radius, theta);
    }
    return r;
  }
};

}  // namespace circledist
