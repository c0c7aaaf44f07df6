// What a round shape is as the target of a query: a ring (Circle3: the rim only) or a disk
// (Disk3: the rim and the interior it bounds). Every query against a round is written once,
// templated on the target; the target holds what differs: the distance of a local point and its
// square, the squared distance's jets along a curve, the closest point and its parameter. Over
// the interior (a disk's, rho <= R) the distance is the height |z|; everywhere else it is the
// ring's. All of it is static and resolved at compile time (`if constexpr` on `interior`).
#pragma once

#include "minimize.hpp"
#include "planar.hpp"
#include "atan2.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace circledist::detail {

// The interior's squared distance z^2 and its derivatives along a curve, from the height z and
// its first two derivatives.
template <class Real> Jet<Real> height_jet(Real z, Real z1, Real z2) {
  return {z * z, 2 * z * z1, 2 * (z1 * z1 + z * z2)};
}

template <class Real, bool Interior> struct RoundTarget {
  static constexpr bool interior = Interior;
  using Shape = std::conditional_t<Interior, Disk3<Real>, Circle3<Real>>;

  // The ring: squared distance of note 000 §1, F = R^2 + |C-P|^2 - 2R W.(P-C), written in the
  // form that does not cancel: |P - K| with z the height and rho the distance from the axis.
  // The disk: note 001 §2, delta^2 = z^2 inside the cylinder, the ring distance outside it.
  static Real distance(const Vec3<Real>& p, Real radius) {
    const Real rho = length2d(p.x(), p.y());
    if constexpr (Interior) {
      if (rho <= radius) return std::abs(p.z());
    }
    return length2d(p.z(), rho - radius);
  }

  // The same distance squared, without the last square root (for bounds: an underflow to 0 only
  // loosens them).
  static Real distance_squared(const Vec3<Real>& p, Real radius) {
    Real off = length2d(p.x(), p.y()) - radius;
    if constexpr (Interior) off = std::max(off, Real(0));
    return p.z() * p.z() + off * off;
  }

  // The exact squared distance from P(t) and its t-derivatives, from P, P' and P''. Over the
  // interior, the height squared (height_jet); on the ring:
  // g = z^2 + (rho - R)^2 = |P|^2 + R^2 - 2 R rho, g' = 2 (P.P' - R rho'),
  // g'' = 2 (|P'|^2 + P.P'' - R rho''), rho' = (x x' + y y') / rho,
  // rho'' = (x'^2 + y'^2 + x x'' + y y'' - rho'^2) / rho. On the axis (rho = 0) the ring distance
  // has a cone point: the curvature is NaN and the polish falls back to the bracketed search.
  static Jet<Real> jet(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2, Real radius) {
    const Real rho = length2d(p.x(), p.y());
    if constexpr (Interior) {
      if (rho <= radius) return height_jet(p.z(), p1.z(), p2.z());
    }
    const Real value = p.z() * p.z() + (rho - radius) * (rho - radius);
    if (!(rho > 0)) return {value, 2 * p.dot(p1), std::numeric_limits<Real>::quiet_NaN()};
    const Real rho1 = (p.x() * p1.x() + p.y() * p1.y()) / rho;
    const Real rho2 = (p1.x() * p1.x() + p1.y() * p1.y() + p.x() * p2.x() + p.y() * p2.y() - rho1 * rho1) / rho;
    return {value, 2 * (p.dot(p1) - radius * rho1), 2 * (p1.squaredNorm() + p.dot(p2) - radius * rho2)};
  }

  // The same along a line P = anchor + tau m with |m| = 1 (P'' = 0): on the ring the squared
  // distance |P|^2 + R^2 - 2 R rho with rho' = (P.m)_xy / rho,
  // rho'' = |m_xy|^2 / rho - (P.m)_xy^2 / rho^3; over the interior the height squared.
  static Jet<Real> line_jet(const Vec3<Real>& p, const Vec3<Real>& m, Real radius) {
    const Real rho = length2d(p.x(), p.y());
    if constexpr (Interior) {
      if (rho <= radius) {
        const Real mz = m.z();
        return {p.z() * p.z(), 2 * p.z() * mz, 2 * mz * mz};
      }
    }
    const Real along = p.x() * m.x() + p.y() * m.y();
    const Real value = p.z() * p.z() + (rho - radius) * (rho - radius);
    if (!(rho > 0)) return {value, p.dot(m), std::numeric_limits<Real>::quiet_NaN()};
    const Real rho1 = along / rho;
    const Real rho2 = (m.x() * m.x() + m.y() * m.y() - rho1 * rho1) / rho;
    return {value, 2 * (p.dot(m) - radius * rho1), 2 * (1 - radius * rho2)};
  }

  // The target's point closest to a local point p. Over a disk's interior, p's projection. On
  // the ring, a point on the axis (rho within rounding of 0, for a scene of size `scale`) is
  // equidistant from every ring point: `ambiguous` is set and the point at angle 0 is returned.
  static Vec3<Real> point(const Vec3<Real>& p, Real radius, Real scale, bool& ambiguous) {
    const Real rho = length2d(p.x(), p.y());
    if constexpr (Interior) {
      if (rho <= radius) return Vec3<Real>(p.x(), p.y(), 0);
    } else {
      if (rho <= 8 * std::numeric_limits<Real>::epsilon() * scale) {
        ambiguous = ambiguous || radius > 0;
        return Vec3<Real>(radius, 0, 0);
      }
    }
    return Vec3<Real>(radius * p.x() / rho, radius * p.y() / rho, 0);
  }

  // The parameter of a local point of the target: (theta, 0) on a ring, (s, theta) on a disk.
  static Vec2<Real> param(const Vec3<Real>& q) {
    if constexpr (Interior) {
      return Vec2<Real>(length2d(q.x(), q.y()), detail::atan2(q.y(), q.x()));
    } else {
      return Vec2<Real>(detail::atan2(q.y(), q.x()), 0);
    }
  }
};

template <class Real> using RingTarget = RoundTarget<Real, false>;
template <class Real> using DiskTarget = RoundTarget<Real, true>;

// The target of a round shape: target_t<Circle3<Real>> is RingTarget<Real>, target_t<Disk3<Real>>
// DiskTarget<Real>. Other shapes have none (no `type`), so that `class = target_t<R>` limits a
// template to circles and disks.
template <class Shape> struct target_of {};
template <class Real> struct target_of<Circle3<Real>> {
  using type = RingTarget<Real>;
};
template <class Real> struct target_of<Disk3<Real>> {
  using type = DiskTarget<Real>;
};
template <class Shape> using target_t = typename target_of<Shape>::type;

// The other side's Result of a shape A against a target given by its closest point to a local
// point, `point_of(p, ambiguous)`, and that point's parameter, `param_of(q)`, from the polished
// minima (the caller adds A's point and parameter): the distance, the target's point closest to
// `pa` (A's local point at the best minimum), with its parameter, and `unique`. That is false
// when the target's point is not the only one (`point_of` sets `ambiguous`: a point on a ring's
// or an arc's axis) or when another tied minimum gives a distinct pair (another_closest_pair:
// points of A, `at(x)`, told apart at `apart_a`, points of the target at the scene's scale).
// A round (round_side_result below) and an arc (bezier_arc.hpp) are such targets.
template <class Real, int N, class At, class PointOf, class ParamOf>
Result<Real> target_side_result(const Minima<Real, N>& minima, const At& at, const Vec3<Real>& pa,
                                const Round<Real>& round, Real scale, Real apart_a, const PointOf& point_of,
                                const ParamOf& param_of) {
  bool ambiguous = false;
  const Vec3<Real> pb = point_of(pa, ambiguous);
  ambiguous =
      ambiguous || another_closest_pair(minima, scale, at, point_of, pa, pb, apart_a, distinct_points_tolerance(scale));
  Result<Real> r;
  r.distance = minima.best.value;
  r.point_b = round.world(pb);
  r.param_b = param_of(pb);
  r.unique = !ambiguous;
  return r;
}

// The round's side: Target::point and Target::param.
template <class Target, class Real, int N, class At>
Result<Real> round_side_result(const Minima<Real, N>& minima, const At& at, const Vec3<Real>& pa,
                               const Round<Real>& round, Real scale, Real apart_a) {
  return target_side_result(
      minima, at, pa, round, scale, apart_a,
      [&](const Vec3<Real>& p, bool& ambiguous) { return Target::point(p, round.radius, scale, ambiguous); },
      [](const Vec3<Real>& q) { return Target::param(q); });
}

}  // namespace circledist::detail
