// An arc as the target of a moving point (ArcTarget): the ring's distance where the point's
// angle falls on the arc, else the nearer end's; and the jets of a point target. Derivation:
// docs/derivations/arc.md#an-arc.
#pragma once

#include "../primitives.hpp"
#include "arc_span.hpp"
#include "atan2.hpp"
#include "local_circle.hpp"
#include "minimize.hpp"
#include "planar.hpp"
#include "round_target.hpp"

#include <cmath>
#include <limits>

namespace circledist::detail {

// Arc B as the target of a moving point, in B's round frame (center at the origin, normal
// along z): its distance is point-arc's (above), the ring's where the point's angle falls on the
// arc, else the nearer end's. Against arc B, A is parametrized (an arc, or a circle as the arc of
// all its angles) and its candidates are circle-circle's against B's ring and B's ends' own
// stationary angles on A. (Where A's point crosses from the ring's form to an end's, the distance
// is C^1, both forms having the gradient (P - E) / |P - E|: a minimum there is a root of the ring's
// octic too, docs/derivations/arc.md.)
template <class Real> struct ArcTarget {
  ArcSpan<Real> span;
  Real radius;
  Vec3<Real> end[2];

  bool sectors;  // whether sector() may decide (a finite angle in [0, 2 pi), radius and start)

  explicit ArcTarget(const Arc3<Real>& b)
      : span(b),
        radius(b.radius),
        end{ArcSpan<Real>::local(b.radius, span.lo()), ArcSpan<Real>::local(b.radius, span.hi())} {
    sectors = span.angle >= 0 && span.angle < 2 * pi_v<Real>() && radius > 0 &&
              radius < std::numeric_limits<Real>::infinity() && std::isfinite(span.lo());
  }

  // -1 where the ring's point is on the arc, else the nearer end's index. The sector test of
  // the canonical angle (an atan2 per call: every h and jet of arc-arc and circle-arc evaluates
  // it) is first decided by the signs of the cross products with the ends (sector()), and taken
  // in full only where those do not decide.
  int nearest_end(const Vec3<Real>& p) const {
    const int fast = sector(p);
    if (fast > 0 || (fast < 0 && span.holds(detail::atan2(p.y(), p.x())))) return -1;
    return (p - end[0]).squaredNorm() <= (p - end[1]).squaredNorm() ? 0 : 1;
  }

  // Whether p's angle lies on the arc, decided without an atan2: 1 on it, 0 off it, -1
  // undecided (then span.holds(atan2) decides, as it always did). With c0 = end0 x p and
  // c1 = p x end1 (z components; |end| = R): for an angle <= pi the arc is where both are
  // >= 0, for an angle > pi where either is (its gap, the complement, is then under pi). A sign
  // counts only beyond tol = 1e-9 R (|x| + |y|) >= 1e-9 |end| |p|, that is where p's direction
  // is more than about 1e-9 rad from the line through either end: the rounding of c0 and c1
  // (2 eps R (|x| + |y|)), of the ends' cosines and sines and of holds()'s atan2, theta0 and
  // offset (a few ulps of 2 pi) are all below 1e-14 rad, so beyond tol holds() gives the same
  // answer, and where either sign is within tol (p near an end's line, on the axis, NaN) this
  // answers -1. A NaN or out-of-range angle, radius or theta0: -1 always (`sectors`).
  int sector(const Vec3<Real>& p) const {
    if (!sectors) return -1;
    const Real x = p.x(), y = p.y();
    const Real tol = Real(1e-9) * radius * (std::abs(x) + std::abs(y));
    const Real c0 = end[0].x() * y - end[0].y() * x, c1 = x * end[1].y() - y * end[1].x();
    if (span.angle <= pi_v<Real>()) {
      if (c0 > tol && c1 > tol) return 1;
      if (c0 < -tol || c1 < -tol) return 0;  // offset in (pi, 2 pi) or in (angle, angle + pi)
    } else {
      if (c0 > tol || c1 > tol) return 1;    // offset in (0, pi) or in (angle - pi, angle)
      if (c0 < -tol && c1 < -tol) return 0;  // offset in (pi, 2 pi) and in (angle, 2 pi)
    }
    return -1;
  }

  // The arc's point closest to p. On the axis (within rounding, at the scene's `scale`) every
  // point is as close: the start, and `ambiguous`.
  Vec3<Real> point(const Vec3<Real>& p, Real scale, bool& ambiguous) const {
    if (length2d(p.x(), p.y()) <= 8 * std::numeric_limits<Real>::epsilon() * scale) {
      ambiguous = ambiguous || radius > 0;
      return end[0];
    }
    const int e = nearest_end(p);
    return e < 0 ? RingTarget<Real>::point(p, radius, scale, ambiguous) : end[e];
  }
  // The parameter (t, 0) of one of its points.
  Vec2<Real> param(const Vec3<Real>& q) const { return Vec2<Real>(span.param_of(detail::atan2(q.y(), q.x())), 0); }
};

// The squared distance from a moving point P to a fixed point E and its derivatives.
template <class Real>
Jet<Real> point_jet(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2, const Vec3<Real>& e) {
  const Vec3<Real> d = p - e;
  return {d.squaredNorm(), 2 * d.dot(p1), 2 * (p1.squaredNorm() + d.dot(p2))};
}

// The angle on circle c (LocalCircle: P(t) = O + E1 cos t + E2 sin t, |E1| = |E2|, E1.E2 = 0) of the
// point nearest a point q: the angle of q - O in the basis E1, E2 (none when q is on the axis).
template <class Real, int N>
void push_nearest_angle(const LocalCircle<Real>& c, const Vec3<Real>& q, Candidates<Real, N>& out) {
  const Vec3<Real> d = q - c.center;
  const Real x = d.dot(c.e1), y = d.dot(c.e2);
  if (x != 0 || y != 0) out.push(std::atan2(y, x));
}

}  // namespace circledist::detail
