// Point-disk: closed form of note 001 §2.
#pragma once

#include "detail/atan2.hpp"
#include "planar.hpp"
#include "query.hpp"

namespace circledist {

template <class Real> struct Query<Vec3<Real>, Disk3<Real>> {
  static constexpr bool defined = true;

  template <class Roots = DefaultRoots> CIRCLEDIST_INLINE static Real distance(const Vec3<Real>& p, const Disk3<Real>& disk) {
    const Vec3<Real> d = p - disk.center;
    const Vec3<Real> n = unit_vector(disk.normal);
    const Real z = n.dot(d);
    const Real rho = (d - z * n).norm();
    return rho <= disk.radius ? std::abs(z) : length2d(z, rho - disk.radius);
  }

  // The distance from the same height and radial offset as distance() (so the two agree to the
  // bit); the disk point from the in-plane coordinates (x, y) = (u.d, v.d), so that it lies in
  // the plane (see point-circle); the angle atan2(y, x).
  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Disk3<Real>& disk) {
    const Frame<Real> frame(disk.normal);
    const Vec3<Real> d = p - disk.center;
    const Real z = frame.n.dot(d);
    const Real radial = (d - z * frame.n).norm();
    Result<Real> r;
    r.point_a = p;
    const Real x = frame.u.dot(d), y = frame.v.dot(d);
    const Real theta = detail::atan2(y, x);
    if (radial <= disk.radius) {
      r.distance = std::abs(z);
      r.point_b = disk.center + x * frame.u + y * frame.v;
      r.param_b = Vec2<Real>(length2d(x, y), theta);
    } else {
      r.distance = length2d(z, radial - disk.radius);
      const Real planar = length2d(x, y);  // 0 only for a zero radius within rounding of the axis
      const Real scale = planar > 0 ? disk.radius / planar : Real(0);
      r.point_b = disk.center + (scale * x) * frame.u + (scale * y) * frame.v;
      r.param_b = Vec2<Real>(disk.radius, theta);
    }
    return r;
  }
};

}  // namespace circledist
