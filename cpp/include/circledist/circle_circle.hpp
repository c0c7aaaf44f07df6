// Circle-circle (Query<Circle3, Circle3>). Derivation: docs/derivations/circle_circle.md.
//
// Circle against circle (derivation in docs/derivations/circle_circle.md). The machinery every query that
// parametrizes a circle by its angle shares lives in detail/: trigonometric polynomials and the
// half-angle substitution (trig.hpp), the circle seen from a round's frame and its octic
// (local_circle.hpp), polishing on the exact distance (angle_polish.hpp), and the circle against
// a round's plane, cylinder and ring with the Result it gives (circle_over_round.hpp).
#pragma once

#include "detail/circle_over_round.hpp"
#include "detail/minimize.hpp"
#include "detail/planar.hpp"
#include "query.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace circledist {

namespace detail {

// The distance h(t) and its jet for the polish (angle_polish.hpp), keeping cos t and sin t of
// the last few angles: the polish asks for both at one angle (every start's value, then the jet
// at the ones it polishes; Newton's last jet, then the value there), and each would take its
// own sine and cosine. The same values to the bit as CircleOverRound's, which take them from
// the same cos t and sin t; an angle is a kept one only with the same sign (sin(-0) is -0).
template <class Real> class RecentAngles {
 public:
  template <class Target> Real distance(const CircleOverRound<Real>& view, Real t) {
    const int i = at(t);
    return view.template distance<Target>(cs_[i], sn_[i]);
  }
  template <class Target> Jet<Real> jet(const CircleOverRound<Real>& view, Real t) {
    const int i = at(t);
    return view.template jet<Target>(cs_[i], sn_[i]);
  }

 private:
  static constexpr int kKept = 8;
  int at(Real t) {
    for (int i = 0; i < count_; ++i)
      if (t_[i] == t && std::signbit(t_[i]) == std::signbit(t)) return i;
    const int i = next_;
    next_ = (next_ + 1) % kKept;
    count_ = std::max(count_, next_ == 0 ? kKept : next_);
    t_[i] = t;
    cs_[i] = std::cos(t);
    sn_[i] = std::sin(t);
    return i;
  }
  Real t_[kKept], cs_[kKept], sn_[kKept];
  int count_ = 0, next_ = 0;
};

// Circle-circle: the smaller circle is parametrized (its angle features are then never narrower
// than the other's), its candidates are the octic's roots plus t = 0 and t = pi; the exact
// point-circle distance judges them. The octic is searched only where the distance can beat the
// best of eight samples (or the caller's `bound`, a distance some point is known to reach).
template <class Real> struct CircleCirclePair {
  static constexpr bool defined = true;
  using Starts = Candidates<Real, kMaxDegree + 16>;

  // The candidate angles of the parametrized circle: t = 0 and t = pi, the octic's roots where
  // the distance can be at most `bound` (a distance the circle reaches: the best of its eight
  // samples or the caller's; an arc passes one its own points reach, detail/arc_span.hpp), and the extra
  // starts below. `samples` are the full circle's (sampled_distances).
  // `within`: an arc's angles, where alone its octic is searched (push_circle_ring_roots).
  template <class Roots> static Starts candidates(const CircleOverRound<Real>& view, Real scale, Real bound,
                                                  const SampledDistances<Real>& samples,
                                                  const Intervals<Real>* within = nullptr) {
    Starts starts;
    push_circle_candidates(starts);
    push_circle_ring_roots<Roots>(view, scale, bound, starts, within);
    // Where the circle crosses the ring's plane (z = 0, the height roots of circle_disk.hpp):
    // rings that cross lie there. For rings of equal radius whose centers are 1e-14 apart, the
    // octic is so ill-conditioned that the eigenvalue policies' roots led the polish to 0.505
    // for a distance of 1e-14 (tests/accuracy/test_regressions.py, near-concentric crossing rings).
    // Policies that refine every root to rounding find them from the octic (and skip these
    // starts' cost: 18 % of a circle-circle query).
    if constexpr (!has_accurate_roots<Roots>::value) push_trig_roots<Roots>(view.c.coordinate(2, scale), starts);
    // Nearly coincident circles (every sample within 1e-3 scale of the ring): the distance is a
    // trigonometric function of low degree in t with few, wide minima; the eight sample angles,
    // polished on the exact distance, reach them too, whatever the roots policy makes of the
    // octic there.
    if (samples.worst <= Real(1e-3) * scale)
      for (int k = -3; k <= 4; ++k) starts.push(k * pi_v<Real>() / 4);
    return starts;
  }

  template <class Roots>
  static Minima<Real, Starts::capacity> solve(const LocalCircle<Real>& c, Real radius, Real scale,
                                              Real bound = std::numeric_limits<Real>::infinity()) {
    const CircleOverRound<Real> view(c, radius);
    const auto squared = [&](const Vec3<Real>& p) { return RingTarget<Real>::distance_squared(p, radius); };
    const SampledDistances<Real> samples = sampled_distances(c, squared);
    const Starts starts = candidates<Roots>(view, scale, std::min(bound, samples.best), samples);
    RecentAngles<Real> angles;
    const auto h = [&](Real t) { return angles.template distance<RingTarget<Real>>(view, t); };
    const auto jet = [&](Real t) { return angles.template jet<RingTarget<Real>>(view, t); };
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

  // a is parametrized, b is the ring. `bound`: as for solve().
  template <class Roots> static Real distance_ordered(const Circle3<Real>& a, const Circle3<Real>& b,
                                                      Real bound = std::numeric_limits<Real>::infinity()) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const LocalCircle<Real> c(a, round);
    return solve<Roots>(c, b.radius, circle_round_scale(c, b.radius), bound).best.value;
  }

  template <class Roots> static Result<Real> closest_ordered(const Circle3<Real>& a, const Circle3<Real>& b,
                                                             Real bound = std::numeric_limits<Real>::infinity()) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, b.radius);
    const auto minima = solve<Roots>(c, b.radius, scale, bound);
    return circle_round_result<RingTarget<Real>>(a, c, round, minima, scale);
  }

  template <class Roots = DefaultRoots> static Real distance(const Circle3<Real>& a, const Circle3<Real>& b) {
    return parametrized_first(a, b) ? distance_ordered<Roots>(a, b) : distance_ordered<Roots>(b, a);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Circle3<Real>& a, const Circle3<Real>& b) {
    return parametrized_first(a, b) ? closest_ordered<Roots>(a, b) : closest_ordered<Roots>(b, a).swapped();
  }

  // The same where only a distance at most `bound` matters (circle-disk's rim part): the octic
  // is searched only where the distance can be at most that (or the samples' best); a minimum
  // above it may be missed, one at or below it is found as distance() finds it.
  template <class Roots = DefaultRoots>
  static Real distance_below(const Circle3<Real>& a, const Circle3<Real>& b, Real bound) {
    return parametrized_first(a, b) ? distance_ordered<Roots>(a, b, bound) : distance_ordered<Roots>(b, a, bound);
  }

  template <class Roots = DefaultRoots>
  static Result<Real> closest_below(const Circle3<Real>& a, const Circle3<Real>& b, Real bound) {
    return parametrized_first(a, b) ? closest_ordered<Roots>(a, b, bound)
                                    : closest_ordered<Roots>(b, a, bound).swapped();
  }
};

}  // namespace detail

template <class Real> struct Query<Circle3<Real>, Circle3<Real>> : detail::CircleCirclePair<Real> {};

// The circle machinery the C++ tests (test_circle_circle.cpp) reach in the public namespace, as
// before it moved to detail/.
using detail::circle_round_scale;
using detail::LocalCircle;
using detail::ring_search_intervals;
using detail::RingTarget;
using detail::Round;
using detail::sampled_distance;

}  // namespace circledist
