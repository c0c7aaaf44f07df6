// A ray's or segment's end point as a candidate against a circle or a disk: its distance from
// point-circle's or point-disk's closed form, and its closest points.
#pragma once

#include "../primitives.hpp"
#include "piece_line.hpp"
#include "planar.hpp"
#include "point_over_round.hpp"
#include "round_target.hpp"

#include <cmath>
#include <limits>

namespace circledist::detail {

// A piece's end point as a candidate: its distance to the round by point-circle's (point-disk's)
// closed form from the line's unit normal n (height z = n.(p - c), rho from the axis; over a
// disk's interior, rho <= R, the height alone), and its closest points (the distance kept the
// same, so distance() and closest() agree).
template <class Real, class R, class Target = target_t<R>>
Real end_point_distance(const Vec3<Real>& p, const R& round, const Vec3<Real>& n) {
  const Vec3<Real> d = p - round.center;
  const Real z = n.dot(d);
  const Real rho = (d - z * n).norm();
  if constexpr (Target::interior) {
    if (rho <= round.radius) return std::abs(z);
  }
  return length2d(z, rho - round.radius);
}
// Which way the distance to a ring runs at the end point p along the piece's direction D:
// 1 rising, -1 falling, 0 where rounding leaves it open (or p is on the axis, where the
// distance has a cusp). From F = z^2 + (rho - R)^2 (z = n.d, rho = |d - z n|, d = p - c):
// F' / 2 = z (n.D) + (rho - R) (d.D - z (n.D)) / rho, whose sign rho > 0 leaves to
//   E = (rho - R) (d.D) + R z (n.D).
// E's rounding: each factor carries a few eps of |d| + R (rho from d - z n: eps |d| absolute),
// so |E| is trusted above 64 eps (|d| + R) |d| |D| (1-norms: no square roots).
template <class Real>
int end_point_slope(const Vec3<Real>& p, const Circle3<Real>& ring, const Vec3<Real>& n, const Vec3<Real>& direction) {
  const Vec3<Real> d = p - ring.center;
  const Real z = n.dot(d);
  const Real rho = (d - z * n).norm();
  const Real size = d.template lpNorm<1>();
  const Real tolerance =
      64 * std::numeric_limits<Real>::epsilon() * (size + ring.radius) * size * direction.template lpNorm<1>();
  const Real e = (rho - ring.radius) * d.dot(direction) + ring.radius * z * n.dot(direction);
  return e > tolerance ? 1 : e < -tolerance ? -1 : 0;
}

template <class Piece, class Round> auto end_point_result(const Piece& piece, decltype(Round::radius) t,
                                                          const Round& round, const Vec3<decltype(Round::radius)>& n) {
  using Real = decltype(Round::radius);
  const Vec3<Real> p = piece_end(piece, t);
  Result<Real> r = PointRoundQuery<Real, std::is_same_v<Round, Disk3<Real>>>::closest(p, round);
  r.distance = end_point_distance(p, round, n);
  r.param_a = Vec2<Real>(t, 0);
  return r;
}

}  // namespace circledist::detail
