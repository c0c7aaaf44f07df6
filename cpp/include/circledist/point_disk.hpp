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
    // Both cases' numbers are computed and one is selected, without a jump: over a batch of
    // points on both sides of the rim a branch is mispredicted about as often as not (measured
    // 34.6 against 29.9 ns a query).
    using Seen = detail::PointOverRound<Real>;
    const bool over = seen.radial <= disk.radius;
    const typename Seen::InPlane q = seen.in_plane();
    const Real to_plane = Real(1) / seen.norm2, to_rim = Seen::to_rim(q, disk.radius);
    const Real above = std::abs(seen.height), off_rim = length2d(seen.height, seen.radial - disk.radius);
    r.distance = over ? above : off_rim;
    r.point_b = Seen::at(disk.center, q, over ? to_plane : to_rim);  // rho > R >= 0 for the rim: q has a direction
    r.param_b = Vec2<Real>(over ? seen.radial : disk.radius, seen.angle());
    return r;
  }
};

}  // namespace circledist
