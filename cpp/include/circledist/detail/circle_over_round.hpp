// Circle A against the plane, cylinder and ring of a round B, written with the small quantities
// that decide near-degenerate pairs (docs/derivations/circle_circle.md, "Nearly coincident circles"): the
// quartics and octic whose roots are A's candidate angles, their search, and the Result built
// from the polished minima with its `unique` flag.
#pragma once

#include "angle_polish.hpp"
#include "local_circle.hpp"
#include "round_target.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace circledist::detail {

// Circle A against the plane, cylinder and ring of round B (radius R), written with the small
// quantities that decide near-degenerate pairs (docs/derivations/circle_circle.md, "Nearly coincident
// circles"): the height z(t) and the radial excess s(t) = x^2 + y^2 - R^2 = rho^2 - R^2.
// Both follow from first harmonics: z = z0 + z1 cos t + z2 sin t, and, as |E1| = |E2| = r (A's
// radius) and E1.E2 = 0,
//   |P|^2 - R^2 = q0 + q1 cos t + q2 sin t,  q0 = |O|^2 + (r - R)(r + R),  q1 = 2 O.E1,  q2 = 2 O.E2,
// so s = q - z^2. The ring distance is then h^2 = z^2 + w^2 with w = rho - R = s / (rho + R).
// For two circles nearly coincident (centers 1e-12 apart, normals 1e-9 apart, radii equal to
// 1e-10) every one of these terms is small and computed to its own relative precision, where
// x^2 + y^2 - R^2 from the coordinates cancels to noise of eps R^2: the octic built from them
// was rounding noise and Newton's slopes pointed anywhere. For other pairs (a circle much larger
// than the ring, far from it) the terms of the expansion are the larger ones, and the distance
// from the coordinates is the accurate form: each query takes the form whose rounding bound is
// the smaller (`expanded`), the expansion only for a circle near the ring all along.
template <class Real> struct CircleOverRound {
  const LocalCircle<Real>& c;
  Real radius;  // R
  Real z0, z1, z2, q0, q1, q2;
  bool expanded;

  CircleOverRound(const LocalCircle<Real>& circle, Real ring_radius) : c(circle), radius(ring_radius) {
    z0 = c.center.z(), z1 = c.e1.z(), z2 = c.e2.z();
    const Real r = c.radius;
    q0 = c.center.squaredNorm() + (r - radius) * (r + radius);
    q1 = 2 * c.center.dot(c.e1);
    q2 = 2 * c.center.dot(c.e2);
    // Rounding bounds of s near the cylinder (rho ~ R, where it decides), in units of eps: from
    // the coordinates, x and y err by eps times the sizes of their terms and s = x^2 + y^2 - R^2
    // by 2 rho (that) + R^2; the expansion errs by the sizes of its own terms. (A circle of
    // radius 1e6 passing a ring of radius 1: terms of 1e12 in the expansion, 1e6 R from the
    // coordinates.)
    const auto size = [](Real v0, Real v1, Real v2) { return std::abs(v0) + std::abs(v1) + std::abs(v2); };
    const Real x = size(c.center.x(), c.e1.x(), c.e2.x()), y = size(c.center.y(), c.e1.y(), c.e2.y());
    const Real z = size(z0, z1, z2);
    const Real from_coordinates = 2 * radius * (x + y) + radius * radius;
    const Real from_harmonics =
        c.center.squaredNorm() + std::abs((r - radius) * (r + radius)) + std::abs(q1) + std::abs(q2) + z * z;
    // And only where |s| <= R^2 / 4 on the whole circle: rho = sqrt(R^2 + s) must not cancel (a
    // small circle near the center of a ring of radius 4e8 has s = -R^2 + O(1), and rho from it
    // erred by sqrt(eps) R).
    expanded = from_harmonics < from_coordinates && 4 * from_harmonics <= radius * radius;
  }

  // z, s and their first two t-derivatives at t (harmonics: f'' = -(f - f0)).
  struct Terms {
    Real z, z1, z2, s, s1, s2;
  };
  Terms terms(Real t) const { return terms(std::cos(t), std::sin(t)); }
  // The same from cos t and sin t.
  Terms terms(Real cs, Real sn) const {
    Terms out;
    const Real zw = z1 * cs + z2 * sn, qw = q1 * cs + q2 * sn;
    out.z = z0 + zw;
    out.z1 = z2 * cs - z1 * sn;
    out.z2 = -zw;
    const Real q = q0 + qw, dq = q2 * cs - q1 * sn;
    out.s = q - out.z * out.z;
    out.s1 = dq - 2 * out.z * out.z1;
    out.s2 = -qw - 2 * (out.z1 * out.z1 + out.z * out.z2);
    return out;
  }

  // The target's distance from P(t): on the ring h = sqrt(z^2 + w^2), over a disk's interior
  // (s <= 0) the height |z|.
  template <class Target> Real distance(Real t) const { return distance<Target>(std::cos(t), std::sin(t)); }
  // The same from cos t and sin t (the same value to the bit).
  template <class Target> Real distance(Real cs, Real sn) const {
    if (!expanded) return Target::distance(Vec3<Real>(c.center + cs * c.e1 + sn * c.e2), radius);
    const Terms v = terms(cs, sn);
    if constexpr (Target::interior) {
      if (v.s <= 0) return std::abs(v.z);
    }
    return length2d(v.z, excess(v.s));
  }

  // The target's squared distance and its derivatives. On the ring g = z^2 + w^2, from
  // w (rho + R) = s:
  // w' (rho + R) + w rho' = s',  w'' (rho + R) + 2 w' rho' + w rho'' = s'',  2 rho rho' = s',
  // rho'' = (s''/2 - rho'^2) / rho. On the axis (rho = 0) the curvature is NaN, as in
  // RoundTarget::jet. Over a disk's interior (s <= 0), the height squared (height_jet).
  template <class Target> Jet<Real> jet(Real t) const { return jet<Target>(std::cos(t), std::sin(t)); }
  // The same from cos t and sin t (the same value to the bit).
  template <class Target> Jet<Real> jet(Real cs, Real sn) const {
    if (!expanded) return c.template jet<Target>(cs, sn, radius);
    const Terms v = terms(cs, sn);
    if constexpr (Target::interior) {
      if (v.s <= 0) return height_jet(v.z, v.z1, v.z2);
    }
    return ring_jet_from(v);
  }

 private:
  Real rho(Real s) const { return std::sqrt(std::max(Real(0), (radius * radius + s))); }
  Real excess(Real s) const {  // w = rho - R
    const Real sum = rho(s) + radius;
    return sum > 0 ? s / sum : Real(0);
  }
  Jet<Real> ring_jet_from(const Terms& v) const {
    const Real p = rho(v.s), sum = p + radius;
    const Real w = sum > 0 ? v.s / sum : Real(0);
    const Real value = v.z * v.z + w * w;
    if (!(p > 0)) return {value, 2 * v.z * v.z1, std::numeric_limits<Real>::quiet_NaN()};
    const Real p1 = v.s1 / (2 * p), p2 = (v.s2 / 2 - p1 * p1) / p;
    const Real w1 = (v.s1 - w * p1) / sum, w2 = (v.s2 - 2 * w1 * p1 - w * p2) / sum;
    return {value, 2 * (v.z * v.z1 + w * w1), 2 * (v.z1 * v.z1 + v.z * v.z2 + w1 * w1 + w * w2)};
  }
};

// (1 + u^2)^2 s(t) = (1 + u^2) Q - Z^2 from the harmonics (Q, Z: the quadratics of q and z), in
// units of `scale`: the radial excess that the octic and the rim quartic share.
template <class Real> std::array<Real, 5> excess_quartic(const CircleOverRound<Real>& v, Real scale) {
  const Real inv = 1 / scale, inv2 = inv * inv;
  std::array<Real, 5> s =
      product(std::array<Real, 3>{1, 0, 1}, harmonic_quadratic(v.q0 * inv2, v.q1 * inv2, v.q2 * inv2));
  const std::array<Real, 3> z = harmonic_quadratic(v.z0 * inv, v.z1 * inv, v.z2 * inv);
  const std::array<Real, 5> zz = product(z, z);
  for (int i = 0; i < 5; ++i) s[i] -= zz[i];
  return s;
}

// The octic of circle_ring_octic_from_coordinates from the harmonics of CircleOverRound. With
// D = P.P' = q'/2, G = x^2 + y^2 = R^2 + s and H = x x' + y y' = s'/2 (s' = q' - 2 z z'),
//   4 (D^2 G - R^2 H^2) = q'^2 s + 4 R^2 z z' (q' - z z'),
// the same polynomial with the cancelling R^2 q'^2 terms taken out symbolically. In u, with
// Q, Q', Z, Z' the quadratics (1 + u^2) q, ... and (1 + u^2)^2 s = (1 + u^2) Q - Z^2:
//   p(u) = Q'^2 ((1 + u^2) Q - Z^2) + 4 R^2 Z Z' ((1 + u^2) Q' - Z Z').
// Scaled by a power of two so that its largest coefficient is about 1 (its terms can be 1e-36).
template <class Real> std::array<Real, 9> circle_ring_octic(const CircleOverRound<Real>& v, Real scale) {
  if (!v.expanded) return circle_ring_octic_from_coordinates(v.c, v.radius, scale);
  const Real inv = 1 / scale, inv2 = inv * inv, r = v.radius * inv;
  const std::array<Real, 3> z = harmonic_quadratic(v.z0 * inv, v.z1 * inv, v.z2 * inv),
                            dz = harmonic_quadratic(Real(0), v.z2 * inv, -v.z1 * inv);
  const std::array<Real, 3> dq = harmonic_quadratic(Real(0), v.q2 * inv2, -v.q1 * inv2);
  const std::array<Real, 5> s = excess_quartic(v, scale);
  std::array<Real, 5> t = product(std::array<Real, 3>{1, 0, 1}, dq);
  const std::array<Real, 5> zdz = product(z, dz);
  for (int i = 0; i < 5; ++i) t[i] -= zdz[i];
  std::array<Real, 9> p = product(product(dq, dq), s);
  const std::array<Real, 9> second = product(zdz, t);
  for (int i = 0; i < 9; ++i) p[i] += 4 * r * r * second[i];
  return normalized(p);
}

// (1 + u^2)^2 s(t), s = x^2 + y^2 - R^2: where A's projection crosses the rim (circle_disk.hpp);
// from the harmonics (excess_quartic) when they are the accurate form, else from x and y.
template <class Real> std::array<Real, 5> circle_rim_quartic(const CircleOverRound<Real>& v, Real scale) {
  const Real inv = 1 / scale;
  std::array<Real, 5> s;
  if (v.expanded) {
    s = excess_quartic(v, scale);
  } else {
    const LocalCircle<Real>& c = v.c;
    const std::array<Real, 3> x = harmonic_quadratic(c.center.x() * inv, c.e1.x() * inv, c.e2.x() * inv),
                              y = harmonic_quadratic(c.center.y() * inv, c.e1.y() * inv, c.e2.y() * inv);
    s = product(x, x);
    const std::array<Real, 5> yy = product(y, y);
    const Real r = v.radius * inv;
    const std::array<Real, 5> rr = product(std::array<Real, 3>{r, 0, r}, std::array<Real, 3>{r, 0, r});
    for (int i = 0; i < 5; ++i) s[i] += yy[i] - rr[i];
  }
  return normalized(s);
}

// Its roots are searched only where the distance can be at most `bound`, a distance A reaches
// (ring_search_intervals, which searches everywhere for an infinite bound; the margin of
// 1e-4 scale dwarfs the rounding of its quadratics), and, for an arc, only on its angles
// (`within`, in u = tan(t/2): ArcSpan::half_angle_range, docs/derivations/arc.md "Cost"; null for a circle).
template <class Roots, class Real, int N> void push_circle_ring_roots(const CircleOverRound<Real>& v, Real scale,
                                                                      Real bound, Candidates<Real, N>& out,
                                                                      const Intervals<Real>* within = nullptr) {
  const std::array<Real, 9> p = circle_ring_octic(v, scale);
  const Intervals<Real> where = ring_search_intervals(v.c, v.radius, bound + Real(1e-4) * scale);
  push_half_angle_roots<Roots>(p.data(), 8, within ? where.within(*within) : where, out);
}

// Builds the Result for circle A against round B from the polished minima, as
// linear_round_result does: B's side from round_side_result (round_target.hpp; distinct tied
// pairs make `unique` false), A's point here. Points on A are told apart at A's own size (a tiny
// circle coaxial with a big one is still a continuum), points on B at the scene's scale.
template <class Target, class Real, int N>
Result<Real> circle_round_result(const Circle3<Real>& a, const LocalCircle<Real>& c, const Round<Real>& round,
                                 const Minima<Real, N>& minima, Real scale) {
  const Minimum<Real>& best = minima.best;
  Result<Real> r = round_side_result<Target>(
      minima, [&](Real x) { return c.at(x); }, c.at(best.x), round, scale,
      distinct_points_tolerance(std::min(scale, c.radius)));
  r.point_a = a.center + c.radius * (std::cos(best.x) * c.frame.u + std::sin(best.x) * c.frame.v);
  r.param_a = Vec2<Real>(best.x, 0);
  return r;
}

}  // namespace circledist::detail
