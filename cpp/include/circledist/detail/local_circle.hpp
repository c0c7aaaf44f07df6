// A circle A seen from the local frame of a round shape B, P(t) = O + E1 cos t + E2 sin t: its
// length scale, the distances at eight exact angles, the angle intervals where the distance can
// be small, and the octic whose roots are the stationary points of the distance from P(t) to B's
// ring (note 001 eq. (2) with the simplification of eq. (3); docs/derivations/circle_circle.md).
#pragma once

#include "minimize.hpp"
#include "planar.hpp"
#include "trig.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace circledist::detail {

// Circle A (radius rho, canonical frame {U_A, V_A, M}) in the local frame of round B:
//   P(t) = O + E1 cos t + E2 sin t,  O = local(T), E1 = rho local(U_A), E2 = rho local(V_A),
// t being A's canonical angle: the same t gives A's world point T + rho (cos t U_A + sin t V_A).
template <class Real> struct LocalCircle {
  Frame<Real> frame;  // A's own frame (for world points and parameters)
  Vec3<Real> center, e1, e2;
  Real radius;

  LocalCircle(const Circle3<Real>& a, const Round<Real>& round) : frame(a.normal), radius(a.radius) {
    center = round.local(a.center);
    e1 = a.radius * round.frame.to_local(frame.u);
    e2 = a.radius * round.frame.to_local(frame.v);
  }

  Vec3<Real> at(Real t) const { return center + std::cos(t) * e1 + std::sin(t) * e2; }

  // P(t), P'(t), P''(t) = O - P(t), for the Newton polish.
  // The target's (round_target.hpp) squared distance and its derivatives there.
  template <class Target> Jet<Real> jet(Real t, Real radius) const {
    return jet<Target>(std::cos(t), std::sin(t), radius);
  }
  // The same from c = cos t and s = sin t.
  template <class Target> Jet<Real> jet(Real c, Real s, Real radius) const {
    const Vec3<Real> w = c * e1 + s * e2;
    return Target::jet(Vec3<Real>(center + w), Vec3<Real>(c * e2 - s * e1), Vec3<Real>(-w), radius);
  }

  // One coordinate as a trigonometric polynomial of degree 1, in units of `scale`.
  Trig<Real, 1> coordinate(int i, Real scale) const {
    Trig<Real, 1> f;
    f.c[0] = center[i] / scale;
    f.c[1] = e1[i] / scale;
    f.s[1] = e2[i] / scale;
    return f;
  }
};

// Length scale of a circle-vs-round query: tolerances and coefficients follow it.
template <class Real> Real circle_round_scale(const LocalCircle<Real>& c, Real radius) {
  const Real s = std::max(std::max(radius, c.radius), c.center.norm());
  return s > 0 ? s : Real(1);
}

// The smallest and largest distances over the eight angles t = k pi/4 (exact cosines and sines,
// no trigonometric calls), from `squared(P)`, the squared distance of a local point: the smallest
// is a distance that A reaches, an upper bound on its minimum to prune with (one square root, not
// sixteen); the largest tells nearly coincident circles (circle-circle's solve).
template <class Real> struct SampledDistances {
  Real best, worst;
};
// The eight squared distances themselves, k = 0..7 at t = k pi/4 (an arc keeps those of the
// angles it holds: arc_span.hpp, arc_bound).
template <class Real> struct SampleAngles {
  static constexpr Real k = Real(0.7071067811865475244008443621048490392848359376884740365883398689953662L);
  static constexpr Real cs[8][2] = {{1, 0}, {k, k}, {0, 1}, {-k, k}, {-1, 0}, {-k, -k}, {0, -1}, {k, -k}};
};
template <class Real, class Squared>
std::array<Real, 8> sampled_squared_distances(const LocalCircle<Real>& c, const Squared& squared) {
  std::array<Real, 8> q;
  for (int i = 0; i < 8; ++i)
    q[i] = squared(Vec3<Real>(c.center + SampleAngles<Real>::cs[i][0] * c.e1 + SampleAngles<Real>::cs[i][1] * c.e2));
  return q;
}
template <class Real> SampledDistances<Real> sampled_distances(const std::array<Real, 8>& squared) {
  Real best = std::numeric_limits<Real>::infinity(), worst = 0;
  for (const Real q : squared) {
    best = std::min(best, q);
    worst = std::max(worst, q);
  }
  return {std::sqrt(best), std::sqrt(worst)};
}
template <class Real, class Squared>
SampledDistances<Real> sampled_distances(const LocalCircle<Real>& c, const Squared& squared) {
  return sampled_distances(sampled_squared_distances(c, squared));
}
template <class Real, class Squared> Real sampled_distance(const LocalCircle<Real>& c, const Squared& squared) {
  return sampled_distances(c, squared).best;
}

// Where on A the distance h to the ring can be at most `bound`, as intervals of u = tan(t/2)
// (docs/derivations/circle_circle.md, "Pruning"). Every ring point Q has z = 0 and |Q| = R, so
// h(t) >= |z(t)| and h(t) >= ||P(t)| - R|: h <= bound needs -bound <= z <= bound and
// (R - bound)^2 <= |P|^2 <= (R + bound)^2. z and |P|^2 = |O|^2 + rho^2 + 2 O.E1 cos t + 2 O.E2 sin t
// are trigonometric of degree 1, so each condition is a quadratic inequality in u; the
// intervals are where all four hold, between the sorted roots of the quadratics. Exact for the
// minimum: a bound that some point reaches keeps the minimizer and every tie with it.
template <class Real> Intervals<Real> ring_search_intervals(const LocalCircle<Real>& c, Real radius, Real bound) {
  // (1 + u^2) (v0 + v1 cos t + v2 sin t - limit) = a u^2 + b u + c0, to be <= 0 (sign 1) or >= 0 (-1).
  struct Condition {
    Real a, b, c0, sign;
    Real at(Real u) const { return sign * ((a * u + b) * u + c0); }
  };
  const auto condition = [](Real v0, Real v1, Real v2, Real limit, Real sign) {
    return Condition{v0 - limit - v1, 2 * v2, v0 - limit + v1, sign};
  };
  const Real z0 = c.center.z(), z1 = c.e1.z(), z2 = c.e2.z();
  const Real q0 = c.center.squaredNorm() + c.radius * c.radius, q1 = 2 * c.center.dot(c.e1),
             q2 = 2 * c.center.dot(c.e2);
  // A condition that holds on the whole circle is left out: v0 + v1 cos t + v2 sin t ranges over
  // v0 -+ sqrt(v1^2 + v2^2), compared squared.
  const auto always_below = [](Real v0, Real v1, Real v2, Real limit) {
    return limit - v0 >= 0 && (limit - v0) * (limit - v0) >= v1 * v1 + v2 * v2;
  };
  Condition conditions[4];
  int n = 0;
  if (!always_below(z0, z1, z2, bound)) conditions[n++] = condition(z0, z1, z2, bound, 1);
  if (!always_below(-z0, -z1, -z2, bound)) conditions[n++] = condition(z0, z1, z2, -bound, -1);
  const Real outer = (radius + bound) * (radius + bound), inner = (radius - bound) * (radius - bound);
  if (!always_below(q0, q1, q2, outer)) conditions[n++] = condition(q0, q1, q2, outer, 1);
  if (radius > bound && !always_below(-q0, -q1, -q2, -inner)) conditions[n++] = condition(q0, q1, q2, inner, -1);
  if (n == 0) return Intervals<Real>::everywhere();
  // The quadratics' real roots split the line into pieces on which every condition keeps its sign.
  Real cuts[8];
  int cut_count = 0;
  for (int i = 0; i < n; ++i) {
    const Condition& q = conditions[i];
    if (q.a == 0) {
      if (q.b != 0) cuts[cut_count++] = -q.c0 / q.b;
      continue;
    }
    const Real disc = q.b * q.b - 4 * q.a * q.c0;
    if (!(disc >= 0)) continue;
    detail::stable_quadratic_roots(q.c0, q.b, q.a, disc, cuts + cut_count);
    cut_count += 2;
  }
  for (int i = 1; i < cut_count; ++i)  // insertion sort: at most eight
    for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
  const Real inf = std::numeric_limits<Real>::infinity();
  Intervals<Real> out;
  for (int i = 0; i <= cut_count; ++i) {
    const Real lo = i == 0 ? -inf : cuts[i - 1], hi = i == cut_count ? inf : cuts[i];
    if (!(lo <= hi)) continue;  // a NaN cut
    const Real inside = cut_count == 0   ? Real(0)
                        : i == 0         ? hi - std::max(Real(1), std::abs(hi))
                        : i == cut_count ? lo + std::max(Real(1), std::abs(lo))
                                         : (lo + hi) / 2;
    bool kept = true;
    for (int k = 0; k < n && kept; ++k) kept = !(conditions[k].at(inside) > 0);
    if (kept) out.add(lo, hi);
  }
  // The sample that set the bound satisfies every condition: nothing kept means the pieces
  // went wrong (NaN), and the whole line is searched.
  return out.count > 0 ? out : Intervals<Real>::everywhere();
}

// The stationary points of the distance from P(t) to the ring of radius R (note 001 eq. (2)):
//   P.P' sqrt(x^2 + y^2) = R (x x' + y y'),  squared:  (P.P')^2 (x^2 + y^2) - R^2 (x x' + y y')^2 = 0.
// By eq. (3), P.P' = (O.E2) cos t - (O.E1) sin t: the second harmonic cancels because
// |E1| = |E2| and E1.E2 = 0, so the left side has trigonometric degree 4, an octic in u.
// x x' + y y' = G'/2 with G = x^2 + y^2. Coefficients in units of `scale` (all O(1)).
//
// The octic is built in u directly (the half-angle form of that equation, which half_angle()
// would give from the Trig products, in a third of the operations): (1 + u^2) times a first
// harmonic v0 + v1 cos t + v2 sin t is the quadratic (v0 + v1) + 2 v2 u + (v0 - v1) u^2, so with
//   X, Y, X', Y', D = (1 + u^2) x, y, x', y', P.P'        (quadratics)
//   G = X^2 + Y^2 = (1 + u^2)^2 (x^2 + y^2),   H = X X' + Y Y' = (1 + u^2)^2 (x x' + y y'),
//   p(u) = D^2 G - R^2 H^2 = (1 + u^2)^4 [ (P.P')^2 (x^2 + y^2) - R^2 (x x' + y y')^2 ].
template <class Real, std::size_t A, std::size_t B>
std::array<Real, A + B - 1> product(const std::array<Real, A>& a, const std::array<Real, B>& b) {
  std::array<Real, A + B - 1> out{};
  for (std::size_t i = 0; i < A; ++i)
    for (std::size_t j = 0; j < B; ++j) out[i + j] += a[i] * b[j];
  return out;
}

// (1 + u^2) times the first harmonic v0 + v1 cos t + v2 sin t, a quadratic in u = tan(t/2).
template <class Real> std::array<Real, 3> harmonic_quadratic(Real v0, Real v1, Real v2) {
  return {v0 + v1, 2 * v2, v0 - v1};
}

// p / 2^k with 2^k the largest coefficient's binade: exact, and the same roots.
template <class Real, std::size_t N> std::array<Real, N> normalized(const std::array<Real, N>& coefficients) {
  std::array<Real, N> p = coefficients;
  Real largest = 0;
  for (const Real& x : p) largest = std::max(largest, std::abs(x));
  if (!(largest > 0) || !std::isfinite(largest)) return p;
  scale_by_power_of_two(p.data(), int(N), -binade(largest));
  return p;
}

template <class Real>
std::array<Real, 9> circle_ring_octic_from_coordinates(const LocalCircle<Real>& c, Real radius, Real scale) {
  const Real inv = 1 / scale;
  const Real x0 = c.center.x() * inv, x1 = c.e1.x() * inv, x2 = c.e2.x() * inv;
  const Real y0 = c.center.y() * inv, y1 = c.e1.y() * inv, y2 = c.e2.y() * inv;
  const std::array<Real, 3> x = harmonic_quadratic(x0, x1, x2), y = harmonic_quadratic(y0, y1, y2);
  const std::array<Real, 3> dx = harmonic_quadratic(Real(0), x2, -x1), dy = harmonic_quadratic(Real(0), y2, -y1);
  const std::array<Real, 3> d =
      harmonic_quadratic(Real(0), c.center.dot(c.e2) * inv * inv, -c.center.dot(c.e1) * inv * inv);
  std::array<Real, 5> g = product(x, x), h = product(x, dx);
  const std::array<Real, 5> yy = product(y, y), ydy = product(y, dy);
  for (int i = 0; i < 5; ++i) {
    g[i] += yy[i];
    h[i] += ydy[i];
  }
  const Real r = radius * inv;
  std::array<Real, 9> p = product(product(d, d), g);
  const std::array<Real, 9> hh = product(h, h);
  for (int i = 0; i < 9; ++i) p[i] -= r * r * hh[i];
  return p;
}

// Candidates every circle query shares: t = pi (the half-angle substitution's blind spot) and
// t = 0, so that a circle whose every point is closest (coaxial circles, a circle in the disk)
// always yields two distinct tied minima.
template <class Real, int N> void push_circle_candidates(Candidates<Real, N>& out) {
  out.push(Real(0));
  out.push(pi_v<Real>());
}

}  // namespace circledist::detail
