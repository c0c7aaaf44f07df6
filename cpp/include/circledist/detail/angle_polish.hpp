// Candidates polished on the exact distance: the parameter tolerances, which candidates are worth
// polishing (the screening) and the polish itself (periodic for angles). The exact squared
// distances with their derivatives (jets) from a moving point to a ring or a disk are the
// targets' (round_target.hpp).
#pragma once

#include "minimize.hpp"
#include "trig.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist::detail {

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

  // `known`: h at the first `known_count` starts, where the caller has it already.
  template <class H>
  ScreenedStarts(const H& h, const Candidates<Real, N>& starts, const Real* known = nullptr, int known_count = 0)
      : count(starts.count) {
    for (int i = 0; i < count; ++i) {
      value[i] = i < known_count ? known[i] : h(starts.value[i]);
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
// `known`, `known_count`: h at the first starts, where the caller has it (ScreenedStarts).
template <class Roots, class Real, int N, class J, class H>
Minima<Real, N> polish_offsets(const J& jet, const H& h, const Candidates<Real, N>& starts, Real width, Real lo,
                               Real hi, Real abs_tol, Real margin, Real reach = std::numeric_limits<Real>::infinity(),
                               const Real* known = nullptr, int known_count = 0) {
  Minima<Real, N> out;
  const ScreenedStarts<Real, N> screened(h, starts, known, known_count);
  for (int k = 0; k < screened.count; ++k) {
    const int i = screened.order[k];
    if (has_accurate_roots<Roots>::value && out.count > 0 && !(screened.value[i] <= out.best.value + margin)) break;
    const Real t0 = starts.value[i];
    const auto f = [&](Real d) { return h(t0 + d); };
    const Real below = std::max(lo - t0, -reach), above = std::min(hi - t0, reach);
    Minimum<Real> m;
    if (Roots::polish() == Polish::Newton) {
      const auto g = [&](Real d) { return jet(t0 + d); };
      // A parameter without a period (a curve's t: `reach` infinite) widens its search where
      // its start was far from the minimum (minimize.hpp, polish_newton).
      m = polish_newton(g, f, Real(0), width, below, above, abs_tol, screened.value[i],
                        !(reach < std::numeric_limits<Real>::infinity()));
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
Minima<Real, N> polish_angles(const J& jet, const H& h, const Candidates<Real, N>& starts, Real abs_tol, Real margin,
                              const Real* known = nullptr, int known_count = 0) {
  const Real inf = std::numeric_limits<Real>::infinity();
  Minima<Real, N> out =
      polish_offsets<Roots>(jet, h, starts, Real(1e-3), -inf, inf, abs_tol, margin, pi_v<Real>(), known, known_count);
  for (int i = 0; i < out.count; ++i) out.item[i].x = wrap_angle(out.item[i].x);
  out.best.x = wrap_angle(out.best.x);
  return out;
}

}  // namespace circledist::detail
