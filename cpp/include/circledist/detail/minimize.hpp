// Candidate polishing: every candidate parameter (a polynomial root, an interval end point, a
// plane crossing) is moved to a nearby local minimum of the *exact* distance, never of the
// squared polynomial, and the smallest exact distance wins. This is what keeps tangencies
// (multiple roots known only to eps^(1/4)) and degenerate polynomials accurate.
#pragma once

#include "../primitives.hpp"
#include "../roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace circledist::detail {

template <class Real> struct Minimum {
  Real x = 0;
  Real value = std::numeric_limits<Real>::infinity();
};

// Brent's minimization (golden section + parabolic steps) of f on [a, b] starting from x, with
// fx = f(x) on entry and the minimum's value on return.
template <class Real, class F> Real brent_minimize(const F& f, Real a, Real b, Real x, Real& fx, Real abs_tol) {
  const Real golden = Real(0.3819660112501051517954131656343618822796908201942371378645513772947395371);
  const Real rel_tol = std::sqrt(std::numeric_limits<Real>::epsilon());
  Real w = x, v = x, fw = fx, fv = fx;
  Real d = 0, e = 0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Real middle = (a + b) / 2;
    const Real tol = rel_tol * std::abs(x) + abs_tol, tol2 = 2 * tol;
    if (std::abs(x - middle) <= tol2 - (b - a) / 2) break;
    bool golden_step = true;
    if (std::abs(e) > tol) {
      Real r = (x - w) * (fx - fv);
      Real q = (x - v) * (fx - fw);
      Real p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0)
        p = -p;
      else
        q = -q;
      const Real e_previous = e;
      e = d;
      if (std::abs(p) < std::abs(q * e_previous / 2) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const Real u = x + d;
        if (u - a < tol2 || b - u < tol2) d = x < middle ? tol : -tol;
        golden_step = false;
      }
    }
    if (golden_step) {
      e = (x < middle ? b : a) - x;
      d = golden * e;
    }
    const Real u = x + (std::abs(d) >= tol ? d : (d > 0 ? tol : -tol));
    const Real fu = f(u);
    if (fu <= fx) {
      if (u < x)
        b = x;
      else
        a = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      if (u < x)
        a = u;
      else
        b = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return x;
}

// Whether a minimum x found on the bracket [a, b] sits on one of its ends that is not an end of
// [lo, hi] (within Brent's tolerances): the function may still fall beyond it.
template <class Real> bool on_inner_edge(Real x, Real a, Real b, Real lo, Real hi, Real abs_tol) {
  const Real edge = 4 * (std::sqrt(std::numeric_limits<Real>::epsilon()) * std::abs(x) + abs_tol);
  return (a > lo && x - a <= edge) || (b < hi && b - x <= edge);
}

// Moves x0 to a local minimum of f on [lo, hi] (either end may be infinite). The search starts
// in [x0 - width, x0 + width] and widens while the minimum sits on an inner edge of the bracket.
template <class Real, class F>
Minimum<Real> polish_minimum(const F& f, Real x0, Real width, Real lo, Real hi, Real abs_tol) {
  Minimum<Real> m;
  m.x = std::min(std::max(x0, lo), hi);
  m.value = f(m.x);
  for (int expansion = 0; expansion < 16; ++expansion) {
    const Real a = std::max(lo, m.x - width), b = std::min(hi, m.x + width);
    if (!(b > a)) break;
    m.x = brent_minimize(f, a, b, m.x, m.value, abs_tol);
    if (!on_inner_edge(m.x, a, b, lo, hi, abs_tol)) break;
    width *= 8;
  }
  return m;
}

// The polished minima of every candidate, and the best of them. Capacity as in Candidates.
template <class Real, int Capacity = kMaxDegree + 8> struct Minima {
  std::array<Minimum<Real>, Capacity> item{};
  int count = 0;
  Minimum<Real> best;

  void add(const Minimum<Real>& m) {
    if (count < Capacity) item[count++] = m;
    if (m.value < best.value) best = m;
  }
};

template <class Real, class F, int Capacity>
Minima<Real, Capacity> polish_candidates(const F& f, const Candidates<Real, Capacity>& starts, Real width, Real lo,
                                         Real hi, Real abs_tol) {
  Minima<Real, Capacity> out;
  for (int i = 0; i < starts.count; ++i) {
    out.add(polish_minimum(f, starts.value[i], width, lo, hi, abs_tol));
  }
  return out;
}

// The squared distance and its first two derivatives along a parameter.
template <class Real> struct Jet {
  Real value, slope, curvature;
};

// On a concave stretch of the squared distance g whose features are far narrower than the
// bracket [a, b] (two rings crossing 1e-7 rad either side of a bump of height 1e-15, the octic's
// roots there lost to rounding), Brent's parabolas through the bump keep it as the best point
// and it stalls there. Walking downhill first finds the valley: steps in `direction` from m.x,
// the first g / |g'| long (where g would reach 0 at its present slope), doubled while the
// distance keeps falling. When it fell at least once, m is the lowest point and [a, b] the
// bracket of its two neighbours on the walk, for Brent to finish; otherwise nothing changes (a
// kink, or a slope of rounding noise: the whole bracket is Brent's). Stays within [a, b].
template <class Real, class F>
void downhill_bracket(const F& distance, Real step, int direction, Real& a, Real& b, Minimum<Real>& m) {
  const Real start = m.x, end = direction > 0 ? b : a;
  Real behind = m.x, ahead = end;
  for (int k = 0; k < 64 && step > 0; ++k, step *= 2) {
    Real next = m.x + direction * step;
    if (direction > 0 ? !(next < end) : !(next > end)) next = end;
    if (next == m.x) break;
    const Real value = distance(next);
    if (!(value < m.value)) {
      ahead = next;
      break;
    }
    behind = m.x;
    m = {next, value};
    if (next == end) break;
  }
  if (m.x == start) return;
  a = std::min(behind, ahead);
  b = std::max(behind, ahead);
}

// Newton steps on the exact squared distance g from x0 (g' = 0 with g'' > 0), each one kept only
// if g decreases; `distance(x)` is the exact distance. Falls back to the bracketed search when a
// step fails (a kink, a concave region) before it has converged. Never returns a worse point
// than its start. `start_value`, when the caller already has distance(x0) (the screening
// computed it), saves evaluating it again.
template <class Real, class J, class F>
Minimum<Real> polish_newton(const J& jet, const F& distance, Real x0, Real width, Real lo, Real hi, Real abs_tol,
                            Real start_value = std::numeric_limits<Real>::quiet_NaN(), bool widen = false) {
  Real x = std::min(std::max(x0, lo), hi);
  Jet<Real> g = jet(x);
  bool converged = false;
  for (int iteration = 0; iteration < 60; ++iteration) {
    if (g.slope == 0) {
      converged = true;
      break;
    }
    if (!(g.curvature > 0)) break;
    const Real step = -g.slope / g.curvature;
    const Real next = std::min(std::max(x + step, lo), hi);
    if (next == x) {  // held at an end of the interval: the minimum on it is there
      converged = true;
      break;
    }
    const Jet<Real> h = jet(next);
    if (!(h.value <= g.value)) {
      // A step below the tolerance that does not lower g is rounding noise at the minimum (about
      // one polish in four from an accurate root): converged, not a reason for the bracketed search.
      converged = std::abs(step) <= abs_tol;
      break;
    }
    x = next;
    g = h;
    if (std::abs(step) <= abs_tol) {
      converged = true;
      break;
    }
  }
  if (converged) {
    Minimum<Real> m{x, distance(x)};
    const Real start = std::min(std::max(x0, lo), hi);
    if (start != x0 || !(start_value == start_value)) start_value = distance(start);
    return start_value < m.value ? Minimum<Real>{start, start_value} : m;
  }
  // Newton could not continue: a concave stretch (an extraneous root of the squared equation,
  // a local maximum) or a kink. A short bracketed search settles it without widening.
  Minimum<Real> m{x, distance(x)};
  Real a = std::max(lo, x - width), b = std::min(hi, x + width);
  if (g.slope != 0 && g.value > 0 && std::isfinite(g.value) && std::isfinite(g.slope))
    downhill_bracket(distance, g.value / std::abs(g.slope), g.slope < 0 ? 1 : -1, a, b, m);
  if (b > a) m.x = brent_minimize(distance, a, b, m.x, m.value, abs_tol);
  // `widen`: still falling at an inner end of the search, the start lay farther than `width`
  // from its minimum (a root of an ill-conditioned polynomial: a curve with a control point 1e9
  // away puts the roots of q.q' 1e-3 off in t), and the bracketed search goes on, widening as
  // polish_minimum's does. Not for angles: their starts sample the whole circle, and on the
  // nearly flat distance of nearly coplanar concentric circles rounding makes every end look
  // lower, so that the widened search would carry each start to the same one of two tied minima.
  if (widen) {
    if (on_inner_edge(m.x, a, b, lo, hi, abs_tol)) return polish_minimum(distance, m.x, width, lo, hi, abs_tol);
  }
  return m;
}

template <class Real, class J, class F>
Minima<Real> polish_candidates_newton(const J& jet, const F& distance, const Candidates<Real>& starts, Real width,
                                      Real lo, Real hi, Real abs_tol) {
  Minima<Real> out;
  for (int i = 0; i < starts.count; ++i) out.add(polish_newton(jet, distance, starts.value[i], width, lo, hi, abs_tol));
  return out;
}

// Distances within this of the best one are a tie: the same distance up to rounding.
template <class Real> Real tie_tolerance(Real scale) { return 64 * std::numeric_limits<Real>::epsilon() * scale; }

// Two closest points farther apart than this are distinct pairs. Flat minima (tangencies) are
// only located to about eps^(1/4) * scale, so anything finer would split one pair into two.
template <class Real> Real distinct_points_tolerance(Real scale) {
  return std::max(Real(1e-3), Real(4) * std::pow(std::numeric_limits<Real>::epsilon(), Real(0.25))) * scale;
}

// Whether the polished minima hold a second closest pair: a minimum within the tie tolerance of the
// best whose point on the parametrized shape (`at(x)`) lies farther than `apart_a` from the best
// one's, `pa`, or whose closest point on the other shape (`other_point(q, ambiguous)`) lies
// farther than `apart_b` from `pb`. Every query that polishes candidates reports `unique` by it.
template <class Real, int N, class At, class OtherPoint>
bool another_closest_pair(const Minima<Real, N>& minima, Real scale, const At& at, const OtherPoint& other_point,
                          const Vec3<Real>& pa, const Vec3<Real>& pb, Real apart_a, Real apart_b) {
  const Minimum<Real>& best = minima.best;
  const Real tie = tie_tolerance(std::max(scale, best.value));
  for (int i = 0; i < minima.count; ++i) {
    const Minimum<Real>& m = minima.item[i];
    if (!(m.value <= best.value + tie)) continue;
    bool unused = false;
    const Vec3<Real> qa = at(m.x);
    const Vec3<Real> qb = other_point(qa, unused);
    if ((qa - pa).norm() > apart_a || (qb - pb).norm() > apart_b) return true;
  }
  return false;
}

}  // namespace circledist::detail
