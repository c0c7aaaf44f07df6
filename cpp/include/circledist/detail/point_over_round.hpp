// A point seen from a circle's or disk's plane: its height, its distance from the axis, and, for
// closest_points, the plane point below it and its angle; and the point queries of both rounds
// on it (PointRoundQuery: point_circle.hpp, point_disk.hpp; note 000 §1, note 001 §2), which
// differ only in what they make of these.
#pragma once

#include "planar.hpp"
#include "../primitives.hpp"
#include "../roots.hpp"
#include "atan2.hpp"
#include "select.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace circledist::detail {

// With d = P - C and W the normal as given (|W| = s), the identities
//   z   = (W . d) / s                 (the height)
//   rho = |W x d| / s                 (the distance from the axis)
//   q   = (W x d) x W = s^2 (d - z N) (the in-plane part of d, times s^2)
// need one square root of |W|^2 and one reciprocal, not a unit normal (three divisions) and then
// a projection: the cheap path of every point query. The angle of q in the round's frame
// (primitives.hpp, Frame: U' = (-W.z, 0, W.x) or (0, W.z, -W.y), U = U' / |U'|, V = N x U) is
//   atan2(V . q, U . q) = atan2((W x U') . d, s (U' . d)) = atan2(-U' . (W x d), s (U' . d)),
// since U' and W x U' are orthogonal to W (U' . W is 0 exactly), with no |U'| at all, and the
// triple product reuses W x d.
// Rounding: W x d carries eps |W| |d|, so rho carries eps |d|, as d - z N would; the angle
// carries eps |d| / rho, the conditioning of the angle of a point near the axis.
//
// Written on scalars, not Eigen's fixed vectors: the packets Eigen forms for a 3-vector are
// stored by one width and read back by another, and the stalls cost a batch of point queries as
// much as the arithmetic (measured 52 against 34 ns per point-circle closest_points).
template <class Real> struct PointOverRound {
  Real dx, dy, dz;  // d = P - C (subtracted first: exact for nearby coordinates)
  Real wx, wy, wz;  // W, scaled by a power of two into a range where W x d x W cannot overflow
  Real norm2;       // |W|^2
  Real s, inv_s;    // |W| and 1 / |W|
  Real mx, my, mz;  // W x d
  Real cross;       // |W x d| = s rho
  Real height;      // z
  Real radial;      // rho

  CIRCLEDIST_INLINE PointOverRound(const Vec3<Real>& p, const Vec3<Real>& center, const Vec3<Real>& normal)
      : dx(p.x() - center.x()),
        dy(p.y() - center.y()),
        dz(p.z() - center.z()),
        wx(normal.x()),
        wy(normal.y()),
        wz(normal.z()) {
    // |W| in [2^-50, 2^50] keeps (W x d) x W, |W|^2 |d|, as far from overflow and the subnormals
    // as d itself is (the front end scales scenes whose distances leave the moderate range).
    constexpr Real lo = power_of_two<Real>(-100), hi = power_of_two<Real>(100);
    norm2 = wx * wx + wy * wy + wz * wz;
    if (!strictly_between(norm2, lo, hi)) rescale_normal();
    s = std::sqrt(norm2);
    inv_s = Real(1) / s;
    mx = wy * dz - wz * dy;
    my = wz * dx - wx * dz;
    mz = wx * dy - wy * dx;
    cross = std::sqrt(mx * mx + my * my + mz * mz);
    height = (wx * dx + wy * dy + wz * dz) * inv_s;
    radial = cross * inv_s;
  }

  // True when the point is within rounding of the axis, rho <= 8 eps (R + |d|_1) (|d|_1, the sum
  // of |d|'s components, is |d| within a factor sqrt(3)): every rim point is then as close, and
  // q has no direction.
  CIRCLEDIST_INLINE bool on_axis(Real radius) const {
    constexpr Real tol = 8 * std::numeric_limits<Real>::epsilon();
    return cross <= tol * s * (radius + (std::abs(dx) + std::abs(dy) + std::abs(dz)));
  }

  // q = (W x d) x W, in the plane to rounding (eps |W x d| |W|, whatever the error of W x d).
  struct InPlane {
    Real x, y, z;
  };
  CIRCLEDIST_INLINE InPlane in_plane() const { return {my * wz - mz * wy, mz * wx - mx * wz, mx * wy - my * wx}; }
  // The rim point at `radius` in the direction of q (not on the axis), scaled by q's own length:
  // W x d's component along W (its rounding, up to eps |W| |d|, large beside |W x d| = s rho near
  // the axis) counts in `cross` but not in q.
  CIRCLEDIST_INLINE static Real to_rim(const InPlane& q, Real radius) {
    const Real length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    return length > 0 ? radius / length : Real(0);  // 0: a zero radius on the axis
  }
  // The plane point C + scale q: on the rim at scale to_rim(q, R), below P at 1 / s^2.
  CIRCLEDIST_INLINE static Vec3<Real> at(const Vec3<Real>& center, const InPlane& q, Real scale) {
    return Vec3<Real>(center.x() + scale * q.x, center.y() + scale * q.y, center.z() + scale * q.z);
  }
  CIRCLEDIST_INLINE Vec3<Real> on_rim(const Vec3<Real>& center, Real radius) const {
    const InPlane q = in_plane();
    return at(center, q, to_rim(q, radius));
  }

  // The angle of q in the round's frame (see above); 0 on the axis.
  CIRCLEDIST_INLINE Real angle() const {
    const bool x_major = std::abs(wx) > std::abs(wy);  // Frame's choice, on W (scaling keeps it)
    // + 0 turns a -0 into +0 (a point on the axis of a disk facing -z gave -0, and atan2(0, -0)
    // is pi): the angle on the axis is 0, as the three-term dot products gave it.
    // (select: the axis is as often one as the other over a batch, and a jump would be mispredicted.)
    const Real along_u = select(x_major, wx * dz - wz * dx, wz * dy - wy * dz) + Real(0);
    const Real along_v = select(x_major, wz * mx - wx * mz, wy * mz - wz * my) + Real(0);
    return atan2(along_v, s * along_u);
  }

  // The rim point of angle 0, C + radius U: the answer for a point on the axis (out of line: rare).
#if defined(__GNUC__) || defined(__clang__)
  __attribute__((noinline, cold))
#endif
  Vec3<Real>
  rim_at_zero(const Vec3<Real>& center, Real radius) const {
    return center + radius * Frame<Real>(Vec3<Real>(wx, wy, wz)).u;
  }

 private:
  // Out of line: normals of moderate length never come here.
#if defined(__GNUC__) || defined(__clang__)
  __attribute__((noinline, cold))
#endif
  void
  rescale_normal() {
    const int exponent = std::ilogb(std::max({std::abs(wx), std::abs(wy), std::abs(wz)}));
    wx = std::ldexp(wx, -exponent);
    wy = std::ldexp(wy, -exponent);
    wz = std::ldexp(wz, -exponent);
    norm2 = wx * wx + wy * wy + wz * wz;
  }
};

// The answers of a point seen from a round's plane, one per region of the plane its projection
// falls in: on a rim (the round's own circle, or an annulus's inner one over its hole) and over a
// disk's or an annulus's face. Each fills the round's side of r (b's); distance() and closest()
// below take the same numbers, so the two agree to the bit.
template <class Real> struct PointRoundAnswers {
  using Seen = PointOverRound<Real>;

  // The rim point in the direction of the point's in-plane part, param (theta, 0), or (radius,
  // theta) with `as_ring_param` (an annulus's rim); a point on the axis (rho within rounding of
  // 0) is as close to every rim point: the one at angle 0, and `unique` false.
  CIRCLEDIST_INLINE static void on_rim(const Seen& seen, const Vec3<Real>& center, Real radius, bool as_ring_param,
                                       Result<Real>& r) {
    r.distance = length2d(seen.height, seen.radial - radius);
    if (seen.on_axis(radius)) {
      r.point_b = seen.rim_at_zero(center, radius);
      r.param_b = as_ring_param ? Vec2<Real>(radius, 0) : Vec2<Real>(0, 0);
      r.unique = !(radius > 0);
      return;
    }
    r.point_b = seen.on_rim(center, radius);
    const Real theta = seen.angle();
    r.param_b = as_ring_param ? Vec2<Real>(radius, theta) : Vec2<Real>(theta, 0);
  }

  // Over a disk of `radius` (or beyond it): the point below P, param (rho, theta), or the rim
  // point, param (radius, theta). Both cases' numbers are computed and one is selected, without
  // a jump (detail/select.hpp: GCC 12 had made jumps of the conditional expressions): over a
  // batch of points on both sides of the rim a jump is mispredicted about as often as not
  // (measured 43.6 against 36.5 ns a query in a C++ loop). A point on the axis over the disk has
  // q = 0 and takes the point below it (rho <= R); the rim's q has a direction (rho > R >= 0).
  CIRCLEDIST_INLINE static void over_disk(const Seen& seen, const Vec3<Real>& center, Real radius, Result<Real>& r) {
    const bool over = seen.radial <= radius;
    const typename Seen::InPlane q = seen.in_plane();
    const Real to_plane = Real(1) / seen.norm2, to_rim = Seen::to_rim(q, radius);
    const Real above = std::abs(seen.height), off_rim = length2d(seen.height, seen.radial - radius);
    r.distance = select(over, above, off_rim);
    r.point_b = Seen::at(center, q, select(over, to_plane, to_rim));
    r.param_b = Vec2<Real>(select(over, seen.radial, radius), seen.angle());
  }

  // The distance over a disk: |z| over it (rho <= R, note 001 §2), from the rim beyond. Both
  // numbers and a selection, not a jump, as in over_disk(): over a batch of points on both sides
  // of the rim the jump was mispredicted about half the time (measured 17.5 against 11.5 ns a
  // query in a C++ loop over random pairs).
  CIRCLEDIST_INLINE static Real over_disk_distance(const Seen& seen, Real radius) {
    return select(seen.radial <= radius, std::abs(seen.height), length2d(seen.height, seen.radial - radius));
  }
};

// The queries of a point against a round (point_circle.hpp, point_disk.hpp): Interior false for
// a circle (the rim), true for a disk (the rim and the interior it bounds), the one difference.
template <class Real, bool Interior> struct PointRoundQuery {
  static constexpr bool defined = true;
  using Round = std::conditional_t<Interior, Disk3<Real>, Circle3<Real>>;
  using Answers = PointRoundAnswers<Real>;

  // F = sqrt(z^2 + (rho - R)^2) from the rim (note 000 §1), |z| over a disk (rho <= R, note 001
  // §2).
  template <class Roots = DefaultRoots>
  CIRCLEDIST_INLINE static Real distance(const Vec3<Real>& p, const Round& round) {
    const PointOverRound<Real> seen(p, round.center, round.normal);
    if constexpr (Interior) return Answers::over_disk_distance(seen, round.radius);
    return length2d(seen.height, seen.radial - round.radius);
  }

  // The rim point in the direction of the point's in-plane part, param (theta, 0) on a circle and
  // (R, theta) on a disk; over a disk, the point below P, param (rho, theta); theta = atan2(y, x)
  // in the round's frame.
  template <class Roots = DefaultRoots>
  CIRCLEDIST_INLINE static Result<Real> closest(const Vec3<Real>& p, const Round& round) {
    const PointOverRound<Real> seen(p, round.center, round.normal);
    Result<Real> r;
    r.point_a = p;
    if constexpr (Interior) {
      Answers::over_disk(seen, round.center, round.radius, r);
    } else {
      Answers::on_rim(seen, round.center, round.radius, false, r);
    }
    return r;
  }
};

// A point against a true ring, an annulus with 0 < inner < outer (annulus_reduction.hpp): the inner
// circle's answer over the hole (rho < inner), the disk's over the ring and beyond
// (docs/derivations/annulus.md), from one PointOverRound; param (rho, theta) over the ring, (R, theta) on a
// rim.
template <class Real> struct PointRingQuery {
  using Answers = PointRoundAnswers<Real>;

  CIRCLEDIST_INLINE static Real distance(const Vec3<Real>& p, const Vec3<Real>& center, const Vec3<Real>& normal,
                                         Real inner, Real outer) {
    const PointOverRound<Real> seen(p, center, normal);
    if (seen.radial < inner) return length2d(seen.height, seen.radial - inner);
    return Answers::over_disk_distance(seen, outer);
  }

  CIRCLEDIST_INLINE static Result<Real> closest(const Vec3<Real>& p, const Vec3<Real>& center, const Vec3<Real>& normal,
                                                Real inner, Real outer) {
    const PointOverRound<Real> seen(p, center, normal);
    Result<Real> r;
    r.point_a = p;
    if (seen.radial < inner) {
      Answers::on_rim(seen, center, inner, true, r);
    } else {
      Answers::over_disk(seen, center, outer, r);
    }
    return r;
  }
};

}  // namespace circledist::detail
