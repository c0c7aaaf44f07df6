// Point-circle: closed form (note 000 §1, the point-circle distance F).
#pragma once

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

  template <class Roots = DefaultRoots> static Result<Real> closest(const Vec3<Real>& p, const Circle3<Real>& c) {
    const Round<Real> round(c.center, c.normal, c.radius);
    const Vec3<Real> local = round.local(p);
    Result<Real> r;
    const Real scale = std::max(c.radius, local.norm());
    bool ambiguous = false;
    const Vec3<Real> q = round.ring_point(local, scale, ambiguous);
    r.distance = ring_distance_local(local, c.radius);
    r.point_a = p;
    r.point_b = round.world(q);
    r.param_b = Round<Real>::ring_param(q);
    r.unique = !ambiguous;
    return r;
  }
};

}  // namespace circledist
