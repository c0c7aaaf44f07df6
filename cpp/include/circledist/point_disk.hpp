// Point-disk: closed form of note 001 §2.
#pragma once

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

  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Disk3<Real>& disk) {
    const Round<Real> round(disk.center, disk.normal, disk.radius);
    const Vec3<Real> local = round.local(p);
    const Vec3<Real> q = round.disk_point(local);
    Result<Real> r;
    r.distance = disk_distance_local(local, disk.radius);
    r.point_a = p;
    r.point_b = round.world(q);
    r.param_b = Round<Real>::disk_param(q);
    return r;
  }
};

}  // namespace circledist
