// A circle or disk seen from its own frame: local coordinates (x, y, z) with the center at the
// origin and the normal along z. What differs between the two (the distances of a local point,
// the closest point, its parameter) is the target policy of detail/round_target.hpp.
#pragma once

#include "../primitives.hpp"

#include <cmath>

namespace circledist::detail {

template <class Real> Real length2d(Real x, Real y) { return std::sqrt(x * x + y * y); }

template <class Real> struct Round {
  Vec3<Real> center;
  Frame<Real> frame;
  Real radius;

  Round(const Vec3<Real>& c, const Vec3<Real>& normal, Real r) : center(c), frame(normal), radius(r) {}

  // Subtracting the center first is exact for nearby coordinates (scenes far from the origin).
  Vec3<Real> local(const Vec3<Real>& world) const { return frame.to_local(world - center); }
  Vec3<Real> world(const Vec3<Real>& local_point) const { return center + frame.to_world(local_point); }
};

}  // namespace circledist::detail
