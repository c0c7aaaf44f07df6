// Point-circle: closed form (note 000 §1, the point-circle distance F).
#pragma once

#include "detail/point_over_round.hpp"
#include "planar.hpp"
#include "query.hpp"

namespace circledist {

template <class Real> struct Query<Vec3<Real>, Circle3<Real>> {
  static constexpr bool defined = true;

  // F = sqrt(z^2 + (rho - R)^2) from the height z and the distance rho from the axis
  // (detail/point_over_round.hpp); closest() takes the same two numbers, so the two agree to the bit.
  template <class Roots = DefaultRoots> CIRCLEDIST_INLINE static Real distance(const Vec3<Real>& p, const Circle3<Real>& c) {
    const detail::PointOverRound<Real> seen(p, c.center, c.normal);
    return length2d(seen.height, seen.radial - c.radius);
  }

  // The ring point in the direction of the point's in-plane part, at angle atan2(y, x) in the
  // circle's frame.
  template <class Roots = DefaultRoots> CIRCLEDIST_INLINE static Result<Real> closest(const Vec3<Real>& p, const Circle3<Real>& c) {
    const detail::PointOverRound<Real> seen(p, c.center, c.normal);
    Result<Real> r;
    r.distance = length2d(seen.height, seen.radial - c.radius);
    r.point_a = p;
    // A point on the axis (rho within rounding of 0) is as close to every ring point: the one at
    // angle 0, and `unique` false.
    if (seen.on_axis(c.radius)) {
      r.point_b = seen.rim_at_zero(c.center, c.radius);
      r.unique = !(c.radius > 0);
      return r;
    }
    r.point_b = seen.on_rim(c.center, c.radius);
    r.param_b = Vec2<Real>(seen.angle(), 0);
    return r;
  }
};

}  // namespace circledist
