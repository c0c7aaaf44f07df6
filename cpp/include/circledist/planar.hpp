// A circle or disk seen from its own frame: local coordinates (x, y, z) with the center at the
// origin and the normal along z, and the closed-form point distances of note 001 §2.
#pragma once

#include "detail/atan2.hpp"
#include "primitives.hpp"

#include <algorithm>
#include <cmath>

namespace circledist {

template <class Real> Real length2d(Real x, Real y) { return std::sqrt(x * x + y * y); }

// Squared distance of note 000 §1, F = R^2 + |C-P|^2 - 2R W.(P-C), written in the form that does
// not cancel: |P - K| with z the height and rho the distance from the axis.
template <class Real> Real ring_distance_local(const Vec3<Real>& p, Real radius) {
  return length2d(p.z(), length2d(p.x(), p.y()) - radius);
}

// Note 001 §2: delta^2 = z^2 inside the cylinder, the ring distance outside it.
template <class Real> Real disk_distance_local(const Vec3<Real>& p, Real radius) {
  const Real rho = length2d(p.x(), p.y());
  return rho <= radius ? std::abs(p.z()) : length2d(p.z(), rho - radius);
}

// The same two distances squared, without the last square root (for bounds: an underflow to 0
// only loosens them).
template <class Real> Real ring_distance_squared(const Vec3<Real>& p, Real radius) {
  const Real off = length2d(p.x(), p.y()) - radius;
  return p.z() * p.z() + off * off;
}
template <class Real> Real disk_distance_squared(const Vec3<Real>& p, Real radius) {
  const Real off = std::max(length2d(p.x(), p.y()) - radius, Real(0));
  return p.z() * p.z() + off * off;
}

template <class Real> struct Round {
  Vec3<Real> center;
  Frame<Real> frame;
  Real radius;

  Round(const Vec3<Real>& c, const Vec3<Real>& normal, Real r) : center(c), frame(normal), radius(r) {}

  // Subtracting the center first is exact for nearby coordinates (scenes far from the origin).
  Vec3<Real> local(const Vec3<Real>& world) const { return frame.to_local(world - center); }
  Vec3<Real> world(const Vec3<Real>& local_point) const { return center + frame.to_world(local_point); }

  // The ring point closest to a local point. A point on the axis (rho within rounding of 0) is
  // equidistant from every ring point: `ambiguous` is set and the point at angle 0 is returned.
  Vec3<Real> ring_point(const Vec3<Real>& p, Real scale, bool& ambiguous) const {
    const Real rho = length2d(p.x(), p.y());
    if (rho <= 8 * std::numeric_limits<Real>::epsilon() * scale) {
      ambiguous = ambiguous || radius > 0;
      return Vec3<Real>(radius, 0, 0);
    }
    return Vec3<Real>(radius * p.x() / rho, radius * p.y() / rho, 0);
  }

  Vec3<Real> disk_point(const Vec3<Real>& p) const {
    const Real rho = length2d(p.x(), p.y());
    if (rho <= radius) return Vec3<Real>(p.x(), p.y(), 0);
    return Vec3<Real>(radius * p.x() / rho, radius * p.y() / rho, 0);
  }

  // (theta, 0) on a ring, (s, theta) on a disk, from a local point of the shape.
  static Vec2<Real> ring_param(const Vec3<Real>& q) { return Vec2<Real>(detail::atan2(q.y(), q.x()), 0); }
  static Vec2<Real> disk_param(const Vec3<Real>& q) {
    return Vec2<Real>(length2d(q.x(), q.y()), detail::atan2(q.y(), q.x()));
  }
};

}  // namespace circledist
