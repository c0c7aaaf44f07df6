// closest_approach(a, b, motion_a, motion_b): the least distance between two moving shapes over
// t in [0, 1], the time it happens and the closest points then. A branch and bound over t on the
// speed bound L of first_contact (motion.hpp) excludes every stretch of time that cannot come
// closer than the best distance found, then a golden-section polish in the stretches left finds
// the least. Derivation: docs/derivations/motion.md, "The closest approach".
#pragma once

#include "motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

namespace circledist {

// What closest_approach() returns: the least distance over [0, 1] and a time it happens (NaN for
// NaN input), closest_points() of the shapes at that time, and `unique`: false where another
// time is as close (within the bar: the shapes at rest relative to each other, a distance
// constant over a stretch, two separate times) or closest_points() at that time is not unique.
// `evaluations` counts the exact distances evaluated.
template <class Real> using Approach = Contact<Real>;

// The screening bar of the search, as a fraction of the query's size S: the branch and bound
// splits a stretch of time until it cannot hold a distance below best - screen; the polish then
// works on what is left (docs/derivations/motion.md, "The closest approach").
template <class Real> Real approach_screen(Real size) { return Real(1e-5) * size; }

namespace detail {

// The least of d(t) = distance_at(t) over [0, 1] (distance_at moves the shapes to t and answers
// their exact distance), d falling and rising no faster than `speed` (L), `size` the query's S.
// Returns the time and the distance there, and whether another time is as close (`several`).
template <class Real> struct Least {
  Real time = std::numeric_limits<Real>::quiet_NaN();
  Real distance = std::numeric_limits<Real>::quiet_NaN();
  bool several = false;
};

template <class Real, class Distance> Least<Real> least_over_time(Distance&& distance_at, Real speed, Real size,
                                                                  std::uint64_t& evaluations, std::uint64_t limit,
                                                                  const char* query) {
  Least<Real> out;
  const std::uint64_t start = evaluations;
  const Real delta = contact_tolerance(size), screen = std::max(delta, approach_screen(size));
  bool failed = false;
  const auto d = [&](Real t) {
    if (evaluations >= limit) throw evaluation_limit(query, limit);
    ++evaluations;
    const Real value = distance_at(t);
    if (value != value) failed = true;
    return value;
  };
  const Real d0 = d(Real(0));
  if (failed) return out;
  // At rest relative to each other: the distance is the same at every time.
  if (speed == 0) return {Real(0), d0, true};
  struct Stretch {
    Real bound, t0, d0, t1, d1;
    bool operator<(const Stretch& o) const { return bound > o.bound; }  // the least bound on top
  };
  // A stretch [t0, t1] with distances d0, d1 at its ends holds no distance below
  // (d0 + d1 - L (t1 - t0)) / 2 (the two cones of slope L from its ends meet there).
  const auto stretch = [&](Real t0, Real v0, Real t1, Real v1) {
    return Stretch{(v0 + v1 - speed * (t1 - t0)) / 2, t0, v0, t1, v1};
  };
  const Real d1 = d(Real(1));
  if (failed) return out;
  Real best = std::min(d0, d1), best_time = d1 < d0 ? Real(1) : Real(0);
  std::priority_queue<Stretch> open;
  std::vector<Stretch> left;  // the stretches not split further
  open.push(stretch(Real(0), d0, Real(1), d1));
  while (!open.empty()) {
    const Stretch s = open.top();
    // Every other stretch's bound is at least this one's; and no distance is below 0, so a
    // distance 0 found (shapes touching or crossing) ends the search at once.
    if (s.bound >= best - screen || best == 0) break;
    open.pop();
    const Real mid = s.t0 + (s.t1 - s.t0) / 2;
    if (!(mid > s.t0 && mid < s.t1)) {  // as fine as double's times
      left.push_back(s);
      continue;
    }
    const Real dm = d(mid);
    if (failed) return out;
    if (dm < best) {
      best = dm;
      best_time = mid;
    }
    open.push(stretch(s.t0, s.d0, mid, dm));
    open.push(stretch(mid, dm, s.t1, s.d1));
  }
  for (; !open.empty(); open.pop()) left.push_back(open.top());
  // The candidates: the stretches that may hold a distance below best. Every other time is at
  // least best (within the distance's rounding): the least is in the candidates, and no more
  // than `screen` below best.
  std::vector<Stretch> candidates;
  for (const Stretch& s : left)
    if (s.bound < best) candidates.push_back(s);
  std::sort(candidates.begin(), candidates.end(), [](const Stretch& x, const Stretch& y) { return x.t0 < y.t0; });
  // The sampled times of the candidates in order, and the local least samples among them (less
  // than or equal to their neighbours within a run of adjacent candidates): the dips. Each is
  // polished in the bracket of its neighbours; `bound` is the least bound (5) of the bracket's
  // stretches, below which nothing in the bracket comes.
  struct Sample {
    Real t, d, lo, hi, bound;  // the time, its distance, its bracket and the bracket's bound
  };
  std::vector<Sample> minima;
  bool flat = false;  // a run of candidates whose both ends are within the bar of the least
  for (size_t i = 0; i < candidates.size();) {
    size_t j = i;
    while (j + 1 < candidates.size() && candidates[j + 1].t0 == candidates[j].t1) ++j;
    // The run i..j: its sample times t0(i), t1(i) = t0(i + 1), ..., t1(j); sample k lies between
    // the stretches i + k - 1 and i + k.
    std::vector<std::pair<Real, Real>> run{{candidates[i].t0, candidates[i].d0}};
    for (size_t k = i; k <= j; ++k) run.push_back({candidates[k].t1, candidates[k].d1});
    if (run.size() > 2 && run.front().second <= best + delta && run.back().second <= best + delta) flat = true;
    for (size_t k = 0; k < run.size(); ++k) {
      const Real here = run[k].second;
      const bool left_ok = k == 0 || here <= run[k - 1].second;
      const bool right_ok = k + 1 == run.size() || here <= run[k + 1].second;
      if (left_ok && right_ok) {
        const Real bound =
            std::min(k == 0 ? here : candidates[i + k - 1].bound, k + 1 == run.size() ? here : candidates[i + k].bound);
        minima.push_back({run[k].first, here, k == 0 ? run[k].first : run[k - 1].first,
                          k + 1 == run.size() ? run[k].first : run[k + 1].first, bound});
      }
    }
    i = j + 1;
  }
  // Every dip is polished, the least samples first, except (a) a dip whose bound is more than
  // twice the bar above the least found so far ((5) holds to the evaluations' rounding, far
  // inside the bar): nothing in it is the answer or within the bar of it; and (b) once four dips
  // are polished and the polish has spent four times the search's evaluations, or reached the
  // evaluation limit, the dips left (dips crowded within a few hundred of the finest stretches
  // of each other: a distance flat over many stretches, where nearly every sample is a dip;
  // derivation: "Polish"). The dips past the fourth never throw at the limit.
  std::sort(minima.begin(), minima.end(),
            [](const Sample& x, const Sample& y) { return x.d < y.d || (x.d == y.d && x.t < y.t); });
  const std::uint64_t searched = evaluations - start;
  // Golden section in each bracket [lo, hi] around its least sample, until the bracket is so
  // short that L times its length is within a quarter of the bar (or as short as double's times).
  const Real golden = (std::sqrt(Real(5)) - 1) / 2;
  std::vector<Sample> polished;  // each least found, with the bracket it was found in
  // A distance 0 at two times farther apart than a tangency's own stretch within the bar
  // (about sqrt(2 delta S) / L): a stretch of contact, or two touches.
  bool zeros = false;
  const Real apart = std::sqrt(2 * delta * size) / speed;
  Real least = best;  // the least distance found so far
  for (const Sample& m : minima) {
    if (m.bound > least + 2 * delta) continue;
    const bool extra = polished.size() >= 4;
    if (extra && (evaluations - start - searched >= 4 * searched || evaluations >= limit)) break;
    Real lo = m.lo, hi = m.hi, x = m.t, fx = m.d;
    while (speed * (hi - lo) > delta / 4 && !(extra && evaluations >= limit)) {
      // The longer side of x gets the new point.
      const bool right = hi - x >= x - lo;
      const Real y = right ? x + (1 - golden) * (hi - x) : x - (1 - golden) * (x - lo);
      if (!(y > lo && y < hi) || y == x) break;
      const Real fy = d(y);
      if (failed) return out;
      zeros = zeros || (fy == 0 && fx == 0 && std::abs(y - x) > apart);
      if (fy < fx) {
        (right ? lo : hi) = x;
        x = y;
        fx = fy;
      } else {
        (right ? hi : lo) = y;
      }
    }
    polished.push_back({x, fx, m.lo, m.hi, m.bound});
    least = std::min(least, fx);
  }
  // The least of the polished, or the best sample where none improved on it (its stretches
  // had no bound below it).
  Sample won{best_time, best, best_time, best_time, best};
  for (const Sample& p : polished)
    if (p.d < won.d || (p.d == won.d && p.t < won.t)) won = p;
  out.time = won.t;
  out.distance = won.d;
  // Another time as close: a polished least within the bar whose bracket is apart from the
  // winner's, or a run of candidates within the bar at both ends (a distance flat over it).
  out.several = flat || zeros;
  for (const Sample& p : polished)
    if (p.d <= won.d + delta && (p.hi < won.lo || p.lo > won.hi)) out.several = true;
  return out;
}

}  // namespace detail

// The least distance between a(t) = moved(a, motion_a, t) and b(t) over t in [0, 1], where it
// is, and closest_points() there (docs/derivations/motion.md, "The closest approach"). The
// distance is within the bar 1e-12 S of the least (S as first_contact's size) where the least
// is a local least of a stretch the search leaves; no time outside those stretches comes closer
// (certified by the speed bound L). Shapes at rest relative to each other: time 0, unique false.
// A rotating line or ray has no speed bound: std::invalid_argument. More than `max_evaluations`
// distances: evaluation_limit (std::runtime_error).
template <class Roots = DefaultRoots, class A, class B>
Approach<scalar_t<core_t<A>>> closest_approach(const A& a, const B& b, const Motion3<scalar_t<core_t<A>>>& motion_a,
                                               const Motion3<scalar_t<core_t<A>>>& motion_b,
                                               std::uint64_t max_evaluations = kMotionEvaluationLimit) {
  using Real = scalar_t<core_t<A>>;
  static_assert(std::is_same<Real, scalar_t<core_t<B>>>::value,
                "circledist::closest_approach: shapes of one scalar type");
  Approach<Real> out;
  out.time = std::numeric_limits<Real>::quiet_NaN();
  const Real speed = detail::relative_speed(a, b, motion_a, motion_b, "closest_approach");
  const Real size = std::max(detail::motion_size(a, motion_a), detail::motion_size(b, motion_b));
  if (speed != speed || size != size) return out;
  const auto at = [&](Real t) {
    return std::make_pair(moved(a, placement(motion_a, t)), moved(b, placement(motion_b, t)));
  };
  const detail::Least<Real> least = detail::least_over_time(
      [&](Real time) {
        const auto [a_t, b_t] = at(time);
        return counted_distance<Roots>(a_t, b_t);
      },
      speed, size, out.evaluations, max_evaluations, "closest_approach");
  if (least.time != least.time) return out;
  const auto [a_t, b_t] = at(least.time);
  const Result<Real> r = counted_closest_points<Roots>(a_t, b_t);
  out.time = least.time;
  out.distance = r.distance;
  out.point_a = r.point_a;
  out.point_b = r.point_b;
  out.param_a = r.param_a;
  out.param_b = r.param_b;
  out.unique = r.unique && !least.several;
  return out;
}

}  // namespace circledist
