// Circle against circle (derivation in docs/circle_circle.md), and the machinery every query
// that parametrizes a circle by its angle shares (circle_disk.hpp, disk_disk.hpp):
//   - trigonometric polynomials and the tangent half-angle substitution u = tan(t/2), which turns
//     a trigonometric polynomial of degree K into an ordinary polynomial of degree 2K;
//   - the circle A seen from the local frame of a round B, P(t) = O + E1 cos t + E2 sin t;
//   - the octic whose roots are the stationary points of the distance from P(t) to B's ring
//     (note 001 eq. (2) with the simplification of eq. (3));
//   - polishing of angle candidates on the exact distance, and the Result with its `unique` flag.
#pragma once

#include "minimize.hpp"
#include "planar.hpp"
#include "query.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace circledist {

template <class Real> constexpr Real pi_v() {
  return Real(3.141592653589793238462643383279502884197169399375105820974944592307816406L);
}

// f(t) = c[0] + sum_{k=1..K} (c[k] cos kt + s[k] sin kt). s[0] is always 0.
template <class Real, int K> struct Trig {
  std::array<Real, K + 1> c{}, s{};

  Trig derivative() const {
    Trig d;
    for (int k = 1; k <= K; ++k) {
      d.c[k] = k * s[k];
      d.s[k] = -k * c[k];
    }
    return d;
  }
};

// The product, by cos j cos k = (cos(j+k) + cos(j-k))/2 and the three similar identities.
template <class Real, int J, int K> Trig<Real, J + K> operator*(const Trig<Real, J>& f, const Trig<Real, K>& g) {
  Trig<Real, J + K> h;
  for (int j = 0; j <= J; ++j) {
    for (int k = 0; k <= K; ++k) {
      const Real cc = f.c[j] * g.c[k], ss = f.s[j] * g.s[k], sc = f.s[j] * g.c[k], cs = f.c[j] * g.s[k];
      const int sum = j + k, diff = j >= k ? j - k : k - j;
      const Real sign = j >= k ? Real(1) : Real(-1);  // sin((j-k)t) = sign * sin(diff t)
      h.c[sum] += (cc - ss) / 2;
      h.c[diff] += (cc + ss) / 2;
      h.s[sum] += (sc + cs) / 2;
      h.s[diff] += sign * (sc - cs) / 2;
    }
  }
  h.s[0] = 0;
  return h;
}

template <class Real, int K> Trig<Real, K> operator+(Trig<Real, K> f, const Trig<Real, K>& g) {
  for (int k = 0; k <= K; ++k) {
    f.c[k] += g.c[k];
    f.s[k] += g.s[k];
  }
  return f;
}

template <class Real, int K> Trig<Real, K> operator-(Trig<Real, K> f, const Trig<Real, K>& g) {
  for (int k = 0; k <= K; ++k) {
    f.c[k] -= g.c[k];
    f.s[k] -= g.s[k];
  }
  return f;
}

template <class Real, int K> Trig<Real, K> operator*(Real a, Trig<Real, K> f) {
  for (int k = 0; k <= K; ++k) {
    f.c[k] *= a;
    f.s[k] *= a;
  }
  return f;
}

// The tangent half-angle substitution: with u = tan(t/2), cos t = (1-u^2)/(1+u^2) and
// sin t = 2u/(1+u^2), so p(u) = (1+u^2)^K f(t) is a polynomial of degree 2K (ascending
// coefficients) whose real roots are exactly the roots t of f in (-pi, pi). Its leading
// coefficient is f(pi): when t = pi is a root the degree drops, so t = pi is always a candidate.
// (1+u^2)^K cos kt and (1+u^2)^K sin kt are the real and imaginary parts of
// (1 + iu)^(2k) (1+u^2)^(K-k): polynomials with integer coefficients, tabulated at compile time,
// so that the substitution is one small matrix product.
template <int K> struct HalfAngleTable {
  long long cos_part[K + 1][2 * K + 1] = {}, sin_part[K + 1][2 * K + 1] = {};

  constexpr HalfAngleTable() {
    long long re[2 * K + 1] = {}, im[2 * K + 1] = {};  // (1 + iu)^(2k), degree 2k
    re[0] = 1;
    for (int k = 0; k <= K; ++k) {
      // times (1 + u^2)^(K-k), by its binomial coefficients
      long long binomial = 1;
      for (int j = 0, m = K - k; j <= m; ++j) {
        for (int i = 0; i <= 2 * k; ++i) {
          cos_part[k][i + 2 * j] += binomial * re[i];
          sin_part[k][i + 2 * j] += binomial * im[i];
        }
        binomial = binomial * (m - j) / (j + 1);
      }
      long long next_re[2 * K + 1] = {}, next_im[2 * K + 1] = {};  // times (1 - u^2) + i 2u
      for (int i = 0; i <= 2 * k && i + 2 <= 2 * K; ++i) {
        next_re[i] += re[i];
        next_re[i + 2] -= re[i];
        next_re[i + 1] -= 2 * im[i];
        next_im[i] += im[i];
        next_im[i + 2] -= im[i];
        next_im[i + 1] += 2 * re[i];
      }
      for (int i = 0; i <= 2 * K; ++i) {
        re[i] = next_re[i];
        im[i] = next_im[i];
      }
    }
  }
};

template <class Real, int K> std::array<Real, 2 * K + 1> half_angle(const Trig<Real, K>& f) {
  static constexpr HalfAngleTable<K> table{};
  std::array<Real, 2 * K + 1> out{};
  for (int i = 0; i <= 2 * K; ++i) {
    Real sum = 0;
    for (int k = 0; k <= K; ++k) sum += Real(table.cos_part[k][i]) * f.c[k] + Real(table.sin_part[k][i]) * f.s[k];
    out[i] = sum;
  }
  return out;
}

// Appends the angles t = 2 atan(u) of the near-real roots u of a half-angle polynomial p of
// degree <= kMaxDegree, where the caller's intervals of u say they can matter.
template <class Roots, class Real, int N>
void push_half_angle_roots(const Real* p, int degree, const Intervals<Real>& where, Candidates<Real, N>& out) {
  Candidates<Real> roots;
  Roots::roots_in(p, degree, where, roots);
  for (int i = 0; i < roots.count; ++i) out.push(2 * std::atan(roots.value[i]));
}

// The same for the roots of a trigonometric polynomial f, through its half-angle polynomial.
template <class Roots, class Real, int K, int N> void push_trig_roots(const Trig<Real, K>& f, Candidates<Real, N>& out) {
  static_assert(2 * K <= kMaxDegree, "circledist: trigonometric degree too high for the default root policy");
  const std::array<Real, 2 * K + 1> p = half_angle(f);
  push_half_angle_roots<Roots>(p.data(), 2 * K, Intervals<Real>::everywhere(), out);
}

// The angle in (-pi, pi], the range of atan2 that Round::ring_param uses too.
template <class Real> Real wrap_angle(Real t) {
  const Real pi = pi_v<Real>();
  if (t > -pi && t <= pi) return t;  // the usual case: a polished angle stays near its start
  t = std::remainder(t, 2 * pi);
  return t <= -pi ? t + 2 * pi : t;
}

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
  template <class JetOf> Jet<Real> jet(Real t, Real radius, const JetOf& jet_of) const {
    const Real c = std::cos(t), s = std::sin(t);
    const Vec3<Real> w = c * e1 + s * e2;
    return jet_of(Vec3<Real>(center + w), Vec3<Real>(c * e2 - s * e1), Vec3<Real>(-w), radius);
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
template <class Real, class Squared>
SampledDistances<Real> sampled_distances(const LocalCircle<Real>& c, const Squared& squared) {
  const Real k = Real(0.7071067811865475244008443621048490392848359376884740365883398689953662L);
  const Real angle[8][2] = {{1, 0}, {k, k}, {0, 1}, {-k, k}, {-1, 0}, {-k, -k}, {0, -1}, {k, -k}};
  Real best = std::numeric_limits<Real>::infinity(), worst = 0;
  for (const auto& cs : angle) {
    const Real q = squared(Vec3<Real>(c.center + cs[0] * c.e1 + cs[1] * c.e2));
    best = std::min(best, q);
    worst = std::max(worst, q);
  }
  return {std::sqrt(best), std::sqrt(worst)};
}
template <class Real, class Squared> Real sampled_distance(const LocalCircle<Real>& c, const Squared& squared) {
  return sampled_distances(c, squared).best;
}

// Where on A the distance h to the ring can be at most `bound`, as intervals of u = tan(t/2)
// (docs/circle_circle.md, "Pruning"). Every ring point Q has z = 0 and |Q| = R, so
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
    const Real inside = cut_count == 0 ? Real(0)
                        : i == 0       ? hi - std::max(Real(1), std::abs(hi))
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
template <class Real, std::size_t N> std::array<Real, N> normalized(std::array<Real, N> p) {
  Real largest = 0;
  for (const Real& x : p) largest = std::max(largest, std::abs(x));
  if (!(largest > 0) || !std::isfinite(largest)) return p;
  const int e = std::ilogb(largest);
  for (Real& x : p) x = std::ldexp(x, -e);
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

// The absolute polishing tolerance for a parameter along which points move at most `speed`
// per unit (a circle's radius for its angle, the hodograph bound for a curve's t), in a scene
// of length `scale`: about 1e-4 sqrt(eps) in the parameter, finer when a unit of parameter is
// longer than the scene, so that the arc-length step stays below 1e-4 sqrt(eps) scale. The
// parameter is polished as an offset from its start (polish_offsets), so Brent's relative
// tolerance does not cap it.
template <class Real> Real parameter_tolerance(Real speed, Real scale) {
  const Real t = Real(1e-4) * std::sqrt(std::numeric_limits<Real>::epsilon());
  return speed > scale ? t * scale / speed : t;
}

// Which candidates are worth polishing. Polishing only lowers a value, and every local minimum
// of h has an accurate candidate next to it (a root of its stationary equation, or a cut/end
// point), whose start value exceeds the minimum by at most `margin` (h'' delta^2 / 2 for a root
// known to delta ~ eps^(1/4) rad, far less for simple roots). So a candidate starting more than
// `margin` above the best polished value cannot lead to the minimum, or to a tie with it, that
// another candidate does not reach: it is skipped. Those are mostly local maxima and extraneous
// roots of the squared equations, which would otherwise slide across the whole circle (about
// 125 exact evaluations per candidate against about 40 for a start at a minimum). The sorted
// order polishes the most promising start first; the first one is always polished.
// The premise, accurate roots, holds for the policies that refine every root to rounding
// (Roots::accurate_roots, Bracketing). The eigenvalue policies' roots of a clustered octic (a
// circle 1e4 times larger than the disk it passes, whose closest stretch spans 1e-5 rad) err by
// 1e-4 in u, so their starts lie far above the minimum they lead to: every one is polished.
template <class Real> Real screening_margin(Real scale) {
  return 16 * std::sqrt(std::numeric_limits<Real>::epsilon()) * scale;
}

template <class Real, int N> struct ScreenedStarts {
  std::array<Real, N> value{};
  std::array<int, N> order{};
  int count = 0;

  template <class H> ScreenedStarts(const H& h, const Candidates<Real, N>& starts) : count(starts.count) {
    for (int i = 0; i < count; ++i) {
      value[i] = h(starts.value[i]);
      if (!(value[i] == value[i])) value[i] = std::numeric_limits<Real>::infinity();
      // Insertion sort by start value (N is small).
      int j = i;
      for (; j > 0 && value[order[j - 1]] > value[i]; --j) order[j] = order[j - 1];
      order[j] = i;
    }
  }
};

// Every candidate that passes the screening is moved to a local minimum of the exact distance
// h on [lo, hi] (infinite for a periodic angle), as the root policy asks: Newton steps on the
// exact squared distance `jet` (falling back to the bracketed search where they fail), or the
// bracketed search alone. Each start t0 is polished as an offset d, h(t0 + d), so that Brent's
// relative tolerance (sqrt(eps) |x|) never limits the parameter's absolute accuracy.
// `reach` bounds the offset itself: half a turn for a periodic angle, where a flat distance (a
// circle parallel to a disk) would otherwise let Newton's steps run to t = 5e16.
template <class Roots, class Real, int N, class J, class H>
Minima<Real, N> polish_offsets(const J& jet, const H& h, const Candidates<Real, N>& starts, Real width, Real lo,
                               Real hi, Real abs_tol, Real margin,
                               Real reach = std::numeric_limits<Real>::infinity()) {
  Minima<Real, N> out;
  const ScreenedStarts<Real, N> screened(h, starts);
  for (int k = 0; k < screened.count; ++k) {
    const int i = screened.order[k];
    if (has_accurate_roots<Roots>::value && out.count > 0 && !(screened.value[i] <= out.best.value + margin)) break;
    const Real t0 = starts.value[i];
    const auto f = [&](Real d) { return h(t0 + d); };
    const Real below = std::max(lo - t0, -reach), above = std::min(hi - t0, reach);
    Minimum<Real> m;
    if (Roots::polish() == Polish::Newton) {
      const auto g = [&](Real d) { return jet(t0 + d); };
      m = polish_newton(g, f, Real(0), width, below, above, abs_tol, screened.value[i]);
    } else {
      m = polish_minimum(f, Real(0), width, below, above, abs_tol);
      // Where the shapes cross (h = 0), h is a V whose bottom the bracket locates only to its
      // tolerance, and the value keeps slope x tolerance (3e-14 in long double); the squared
      // distance is a smooth parabola there, and Newton steps on it, kept only while they lower
      // h, land on the crossing.
      for (int step = 0; step < 4; ++step) {
        const Jet<Real> g = jet(t0 + m.x);
        if (!(g.curvature > 0) || g.slope == 0) break;
        const Real next = std::min(std::max(m.x - g.slope / g.curvature, below), above);
        const Real value = f(next);
        if (!(value < m.value)) break;
        m.x = next;
        m.value = value;
      }
    }
    m.x = t0 + m.x;
    out.item[out.count++] = m;
    if (m.value < out.best.value) out.best = m;
  }
  return out;
}

// Angles: periodic, polished with the note's width of 1e-3 rad, then wrapped to (-pi, pi].
template <class Roots, class Real, int N, class J, class H>
Minima<Real, N> polish_angles(const J& jet, const H& h, const Candidates<Real, N>& starts, Real abs_tol, Real margin) {
  const Real inf = std::numeric_limits<Real>::infinity();
  Minima<Real, N> out = polish_offsets<Roots>(jet, h, starts, Real(1e-3), -inf, inf, abs_tol, margin, pi_v<Real>());
  for (int i = 0; i < out.count; ++i) out.item[i].x = wrap_angle(out.item[i].x);
  out.best.x = wrap_angle(out.best.x);
  return out;
}

// The exact squared distance from P(t) to the ring of radius R and its t-derivatives:
// g = z^2 + (rho - R)^2 = |P|^2 + R^2 - 2 R rho, g' = 2 (P.P' - R rho'),
// g'' = 2 (|P'|^2 + P.P'' - R rho''), rho' = (x x' + y y') / rho,
// rho'' = (x'^2 + y'^2 + x x'' + y y'' - rho'^2) / rho. On the axis (rho = 0) the ring distance
// has a cone point: the curvature is NaN and the polish falls back to the bracketed search.
template <class Real> Jet<Real> ring_jet_of(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2, Real radius) {
  const Real rho = length2d(p.x(), p.y());
  const Real value = p.z() * p.z() + (rho - radius) * (rho - radius);
  if (!(rho > 0)) return {value, 2 * p.dot(p1), std::numeric_limits<Real>::quiet_NaN()};
  const Real rho1 = (p.x() * p1.x() + p.y() * p1.y()) / rho;
  const Real rho2 = (p1.x() * p1.x() + p1.y() * p1.y() + p.x() * p2.x() + p.y() * p2.y() - rho1 * rho1) / rho;
  return {value, 2 * (p.dot(p1) - radius * rho1), 2 * (p1.squaredNorm() + p.dot(p2) - radius * rho2)};
}

// The exact squared disk distance: the height squared over the disk, the ring's outside it.
template <class Real> Jet<Real> disk_jet_of(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2, Real radius) {
  if (length2d(p.x(), p.y()) <= radius) {
    return {p.z() * p.z(), 2 * p.z() * p1.z(), 2 * (p1.z() * p1.z() + p.z() * p2.z())};
  }
  return ring_jet_of(p, p1, p2, radius);
}

// Circle A against the plane, cylinder and ring of round B (radius R), written with the small
// quantities that decide near-degenerate pairs (docs/circle_circle.md, "Nearly coincident
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
    const Real from_harmonics = c.center.squaredNorm() + std::abs((r - radius) * (r + radius)) + std::abs(q1) +
                                std::abs(q2) + z * z;
    // And only where |s| <= R^2 / 4 on the whole circle: rho = sqrt(R^2 + s) must not cancel (a
    // small circle near the center of a ring of radius 4e8 has s = -R^2 + O(1), and rho from it
    // erred by sqrt(eps) R).
    expanded = from_harmonics < from_coordinates && 4 * from_harmonics <= radius * radius;
  }

  // z, s and their first two t-derivatives at t (harmonics: f'' = -(f - f0)).
  struct Terms {
    Real z, z1, z2, s, s1, s2;
  };
  Terms terms(Real t) const {
    const Real cs = std::cos(t), sn = std::sin(t);
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

  Real ring_distance(Real t) const {
    if (!expanded) return ring_distance_local(c.at(t), radius);
    const Terms v = terms(t);
    return length2d(v.z, excess(v.s));
  }

  Real disk_distance(Real t) const {
    if (!expanded) return disk_distance_local(c.at(t), radius);
    const Terms v = terms(t);
    return v.s <= 0 ? std::abs(v.z) : length2d(v.z, excess(v.s));
  }

  // The squared ring distance g = z^2 + w^2 and its derivatives, from w (rho + R) = s:
  // w' (rho + R) + w rho' = s',  w'' (rho + R) + 2 w' rho' + w rho'' = s'',  2 rho rho' = s',
  // rho'' = (s''/2 - rho'^2) / rho. On the axis (rho = 0) the curvature is NaN, as in ring_jet_of.
  Jet<Real> ring_jet(Real t) const {
    if (!expanded) return c.jet(t, radius, &ring_jet_of<Real>);
    return ring_jet_from(terms(t));
  }

  Jet<Real> disk_jet(Real t) const {
    if (!expanded) return c.jet(t, radius, &disk_jet_of<Real>);
    const Terms v = terms(t);
    if (v.s <= 0) return {v.z * v.z, 2 * v.z * v.z1, 2 * (v.z1 * v.z1 + v.z * v.z2)};
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
// 1e-4 scale dwarfs the rounding of its quadratics).
template <class Roots, class Real, int N>
void push_circle_ring_roots(const CircleOverRound<Real>& v, Real scale, Real bound, Candidates<Real, N>& out) {
  const std::array<Real, 9> p = circle_ring_octic(v, scale);
  push_half_angle_roots<Roots>(p.data(), 8, ring_search_intervals(v.c, v.radius, bound + Real(1e-4) * scale), out);
}

// Builds the Result for circle A against round B from the polished minima, as
// linear_round_result does: `round_point(p, ambiguous)` maps a local point of A to its closest
// local point of B. Distinct tied pairs make `unique` false. Points on A are told apart at A's
// own size (a tiny circle coaxial with a big one is still a continuum), points on B at the
// scene's scale.
template <class Real, int N, class RoundPoint, class RoundParam>
Result<Real> circle_round_result(const Circle3<Real>& a, const LocalCircle<Real>& c, const Round<Real>& round,
                                 const Minima<Real, N>& minima, Real scale, const RoundPoint& round_point,
                                 const RoundParam& round_param) {
  Result<Real> r;
  const Minimum<Real>& best = minima.best;
  bool ambiguous = false;
  const Vec3<Real> pa = c.at(best.x);
  const Vec3<Real> pb = round_point(pa, ambiguous);
  const Real tie = tie_tolerance(std::max(scale, best.value));
  const Real apart_a = distinct_points_tolerance(std::min(scale, c.radius));
  const Real apart_b = distinct_points_tolerance(scale);
  for (int i = 0; i < minima.count && !ambiguous; ++i) {
    const Minimum<Real>& m = minima.item[i];
    if (!(m.value <= best.value + tie)) continue;
    bool unused = false;
    const Vec3<Real> qa = c.at(m.x);
    const Vec3<Real> qb = round_point(qa, unused);
    if ((qa - pa).norm() > apart_a || (qb - pb).norm() > apart_b) ambiguous = true;
  }
  r.distance = best.value;
  r.point_a = a.center + c.radius * (std::cos(best.x) * c.frame.u + std::sin(best.x) * c.frame.v);
  r.point_b = round.world(pb);
  r.param_a = Vec2<Real>(best.x, 0);
  r.param_b = round_param(pb);
  r.unique = !ambiguous;
  return r;
}

// Circle-circle: the smaller circle is parametrized (its angle features are then never narrower
// than the other's), its candidates are the octic's roots plus t = 0 and t = pi; the exact
// point-circle distance judges them. The octic is searched only where the distance can beat the
// best of eight samples (or the caller's `bound`, a distance some point is known to reach).
template <class Real> struct Query<Circle3<Real>, Circle3<Real>> {
  static constexpr bool defined = true;
  using Starts = Candidates<Real, kMaxDegree + 16>;

  template <class Roots>
  static Minima<Real, Starts::capacity> solve(const LocalCircle<Real>& c, Real radius, Real scale,
                                              Real bound = std::numeric_limits<Real>::infinity()) {
    const CircleOverRound<Real> view(c, radius);
    Starts starts;
    push_circle_candidates(starts);
    const auto squared = [&](const Vec3<Real>& p) { return ring_distance_squared(p, radius); };
    const SampledDistances<Real> samples = sampled_distances(c, squared);
    push_circle_ring_roots<Roots>(view, scale, std::min(bound, samples.best), starts);
    // Where the circle crosses the ring's plane (z = 0, the height roots of circle_disk.hpp):
    // rings that cross lie there. For rings of equal radius whose centers are 1e-14 apart, the
    // octic is so ill-conditioned that the eigenvalue policies' roots led the polish to 0.505
    // for a distance of 1e-14 (tests/test_regressions.py, near-concentric crossing rings).
    // Policies that refine every root to rounding find them from the octic (and skip these
    // starts' cost: 18 % of a circle-circle query).
    if constexpr (!has_accurate_roots<Roots>::value) push_trig_roots<Roots>(c.coordinate(2, scale), starts);
    // Nearly coincident circles (every sample within 1e-3 scale of the ring): the distance is a
    // trigonometric function of low degree in t with few, wide minima; the eight sample angles,
    // polished on the exact distance, reach them too, whatever the roots policy makes of the
    // octic there.
    if (samples.worst <= Real(1e-3) * scale)
      for (int k = -3; k <= 4; ++k) starts.push(k * pi_v<Real>() / 4);
    const auto h = [&](Real t) { return view.ring_distance(t); };
    const auto jet = [&](Real t) { return view.ring_jet(t); };
    return polish_angles<Roots>(jet, h, starts, parameter_tolerance(c.radius, scale), screening_margin(scale));
  }

  // Whether a is the circle to parametrize: the smaller one, and between equal radii the first in
  // a fixed order of the fields, so that (a, b) and (b, a) run the same computation and give
  // the same distance to the last bit.
  static bool parametrized_first(const Circle3<Real>& a, const Circle3<Real>& b) {
    if (a.radius != b.radius) return a.radius < b.radius;
    for (int i = 0; i < 3; ++i)
      if (a.center[i] != b.center[i]) return a.center[i] < b.center[i];
    for (int i = 0; i < 3; ++i)
      if (a.normal[i] != b.normal[i]) return a.normal[i] < b.normal[i];
    return true;
  }

  // a is parametrized, b is the ring.
  template <class Roots> static Real distance_ordered(const Circle3<Real>& a, const Circle3<Real>& b) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const LocalCircle<Real> c(a, round);
    return solve<Roots>(c, b.radius, circle_round_scale(c, b.radius)).best.value;
  }

  template <class Roots> static Result<Real> closest_ordered(const Circle3<Real>& a, const Circle3<Real>& b) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, b.radius);
    const auto minima = solve<Roots>(c, b.radius, scale);
    return circle_round_result(
        a, c, round, minima, scale,
        [&](const Vec3<Real>& p, bool& ambiguous) { return round.ring_point(p, scale, ambiguous); },
        &Round<Real>::ring_param);
  }

  template <class Roots = DefaultRoots> static Real distance(const Circle3<Real>& a, const Circle3<Real>& b) {
    return parametrized_first(a, b) ? distance_ordered<Roots>(a, b) : distance_ordered<Roots>(b, a);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Circle3<Real>& a, const Circle3<Real>& b) {
    return parametrized_first(a, b) ? closest_ordered<Roots>(a, b) : closest_ordered<Roots>(b, a).swapped();
  }
};

}  // namespace circledist
