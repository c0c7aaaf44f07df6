// circledist: exact 3D distances between points, lines, rays, segments, circles and disks.
// Primitives, the per-query Result, and the canonical frame of a plane.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

// The closed-form point queries are a few dozen instructions: inlined into a caller's loop, the
// latencies of consecutive queries overlap (a call per query costs about 10 % of one).
#if defined(__GNUC__) || defined(__clang__)
#define CIRCLEDIST_INLINE inline __attribute__((always_inline))
#else
#define CIRCLEDIST_INLINE inline
#endif

namespace circledist {

template <class Real> using Vec3 = Eigen::Matrix<Real, 3, 1>;
template <class Real> using Vec2 = Eigen::Matrix<Real, 2, 1>;

// A circle (the ring only). `normal` need not be unit length; `radius` >= 0.
template <class Real> struct Circle3 {
  Vec3<Real> center, normal;
  Real radius;
};

// The filled disk bounded by the circle with the same fields.
template <class Real> struct Disk3 {
  Vec3<Real> center, normal;
  Real radius;
};

// Points origin + t * direction, t in R. `direction` need not be unit length.
template <class Real> struct Line3 {
  Vec3<Real> origin, direction;
};

// Points origin + t * direction, t >= 0.
template <class Real> struct Ray3 {
  Vec3<Real> origin, direction;
};

// Points p0 + t * (p1 - p0), t in [0, 1]. p0 == p1 is allowed (a point).
template <class Real> struct Segment3 {
  Vec3<Real> p0, p1;
};

// What closest_points() returns. Parameters, per shape kind:
//   point: (0, 0); line, ray, segment: (t, 0) as in the definitions above;
//   circle: (theta, 0), the angle in the canonical frame (see Frame);
//   disk: (s, theta), the closest point being center + s (cos theta U + sin theta V).
// `unique` is false when another, distinct closest pair reaches the same distance within
// rounding (a tie between isolated pairs, or a continuum such as a line on a circle's axis).
template <class Real> struct Result {
  Real distance = std::numeric_limits<Real>::quiet_NaN();
  Vec3<Real> point_a = Vec3<Real>::Zero(), point_b = Vec3<Real>::Zero();
  Vec2<Real> param_a = Vec2<Real>::Zero(), param_b = Vec2<Real>::Zero();
  bool unique = true;

  Result swapped() const {
    Result r = *this;
    std::swap(r.point_a, r.point_b);
    std::swap(r.param_a, r.param_b);
    return r;
  }
};

// v / |v| for any finite nonzero v. |v|^2 overflows for |v| beyond about 1.3e154 (double) and
// loses digits in the subnormals below about 1e-138: such vectors are first scaled by a power of
// two (exact) to a largest component in [1, 2). The common case pays one comparison.
template <class Real> CIRCLEDIST_INLINE Vec3<Real> unit_vector(const Vec3<Real>& v) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  constexpr Real tiny = std::numeric_limits<Real>::min() / (eps * eps);
  const Real n2 = v.squaredNorm();
  if (n2 > tiny && n2 < std::numeric_limits<Real>::max()) return v / std::sqrt(n2);
  const int exponent = std::ilogb(v.cwiseAbs().maxCoeff());
  const Vec3<Real> w(std::ldexp(v.x(), -exponent), std::ldexp(v.y(), -exponent), std::ldexp(v.z(), -exponent));
  return w / w.norm();
}

// The right-handed orthonormal frame {U, V, N} of a circle or disk, built the same way everywhere
// so that angles mean the same thing in C++ and Python:
//   N = normal / |normal|;
//   U = (-N.z, 0, N.x) / |.| when |N.x| > |N.y|, else (0, N.z, -N.y) / |.|;   V = N x U.
template <class Real> struct Frame {
  Vec3<Real> u, v, n;

  explicit Frame(const Vec3<Real>& normal) {
    n = unit_vector(normal);
    // The pair holds N.z and the larger of N.x, N.y, so the largest component of the unit N:
    // its squared length is at least 1/3 and needs no hypot against underflow.
    if (std::abs(n.x()) > std::abs(n.y())) {
      u = Vec3<Real>(-n.z(), Real(0), n.x()) / std::sqrt(n.x() * n.x() + n.z() * n.z());
    } else {
      u = Vec3<Real>(Real(0), n.z(), -n.y()) / std::sqrt(n.y() * n.y() + n.z() * n.z());
    }
    v = n.cross(u);
  }

  // Coordinates (x, y, z) of a world vector in this frame (a rotation: lengths are kept).
  Vec3<Real> to_local(const Vec3<Real>& w) const { return Vec3<Real>(u.dot(w), v.dot(w), n.dot(w)); }
  Vec3<Real> to_world(const Vec3<Real>& l) const { return l.x() * u + l.y() * v + l.z() * n; }
};

}  // namespace circledist
