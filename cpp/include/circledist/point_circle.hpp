// Point-circle: closed form (note 000 §1, the point-circle distance F).
#pragma once

#include "detail/atan2.hpp"
#include "planar.hpp"
#include "query.hpp"

namespace circledist {

template <class Real> struct Query<Vec3<Real>, Circle3<Real>> {
  static constexpr bool defined = true;

  // Needs only the unit normal, not the full frame: height z and distance rho from the axis.
  template <class Roots = DefaultRoots> CIRCLEDIST_INLINE static Real distance(const Vec3<Real>& p, const Circle3<Real>& c) {
    const Vec3<Real> d = p - c.center;
    const Vec3<Real> n = unit_vector(c.normal);
    const Real z = n.dot(d);
    const Real rho = (d - z * n).norm();
    return length2d(z, rho - c.radius);
  }

  // The distance from the same height and radial offset as distance() (so the two agree to the
  // bit); the ring point from the in-plane coordinates (x, y) = (u.d, v.d), so that it lies in
  // the plane (scaling d - z n by R / rho would carry its rounding, eps |z|, out of the plane
  // R / rho times over for a point high above the axis); the angle atan2(y, x).
  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Circle3<Real>& c) {
    const Frame<Real> frame(c.normal);
    const Vec3<Real> d = p - c.center;
    const Real z = frame.n.dot(d);
    Result<Real> r;
    r.distance = length2d(z, (d - z * frame.n).norm() - c.radius);
    r.point_a = p;
    const Real x = frame.u.dot(d), y = frame.v.dot(d);
    const Real rho = length2d(x, y);
    // A point on the axis (rho within rounding of 0) is as close to every ring point: the one at
    // angle 0, and `unique` false.
    if (rho <= 8 * std::numeric_limits<Real>::epsilon() * std::max(c.radius, d.norm())) {
      r.point_b = c.center + c.radius * frame.u;
      r.unique = !(c.radius > 0);
      return r;
    }
    const Real scale = c.radius / rho;
    r.point_b = c.center + (scale * x) * frame.u + (scale * y) * frame.v;
    r.param_b = Vec2<Real>(detail::atan2(y, x), 0);
    return r;
  }
};

}  // namespace circledist
