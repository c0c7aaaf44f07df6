// Circle-disk (Query<Circle3, Disk3>). Derivation: docs/derivations/circle_disk.md.
//
// Circle against disk: note 001 §4 (details in docs/derivations/circle_disk.md). The circle A is written in
// the disk's local frame, P(t) = O + E1 cos t + E2 sin t with t A's canonical angle, and its
// angle range is cut where the projection crosses the rim (§4.1). Inside the rim the distance is
// the height |z(t)|, minimal where z = 0 or z' = 0 (§4.2); outside it is the distance to the rim
// circle, stationary at the roots of the octic of §4.3, which is the circle-circle equation
// (detail/local_circle.hpp). All equations are taken through the half-angle substitution
// u = tan(t/2) (one root <-> one angle, no extraneous sign of sin t, no acos near +-1); the
// cut points, t = 0 and t = pi join the candidates and the exact point-disk distance judges.
#pragma once

#include "detail/circle_over_round.hpp"
#include "query.hpp"

namespace circledist {

namespace detail {

// §4.1: x(t)^2 + y(t)^2 - R^2 = 0, trigonometric degree 2 (a quartic in u; circle_rim_quartic).
template <class Roots, class Real, int N>
void push_rim_partition(const CircleOverRound<Real>& v, Real scale, Candidates<Real, N>& out) {
  const std::array<Real, 5> p = circle_rim_quartic(v, scale);
  push_half_angle_roots<Roots>(p.data(), 4, Intervals<Real>::everywhere(), out);
}

// §4.2: z(t) = c0 + c1 cos t + c2 sin t = 0 and z'(t) = c2 cos t - c1 sin t = 0 (quadratics in u).
template <class Roots, class Real, int N>
void push_height_roots(const LocalCircle<Real>& c, Real scale, Candidates<Real, N>& out) {
  const Trig<Real, 1> z = c.coordinate(2, scale);
  push_trig_roots<Roots>(z, out);
  push_trig_roots<Roots>(z.derivative(), out);
}

template <class Real> struct CircleDiskPair {
  static constexpr bool defined = true;
  // 2 fixed + 8 (octic) + 4 (rim quartic) + 2 + 2 (height quadratics) = 18 at most.
  using Starts = Candidates<Real, 24>;

  // The candidates every solve starts from: t = 0, t = pi and the height roots of §4.2.
  using Heights = Candidates<Real, 8>;
  template <class Roots> static Heights height_candidates(const LocalCircle<Real>& c, Real scale) {
    Heights heights;
    push_circle_candidates(heights);  // z' = 0 everywhere (a parallel circle) has no roots to push
    push_height_roots<Roots>(c, scale, heights);
    return heights;
  }

  template <class Roots>
  static Minima<Real, Starts::capacity> solve(const LocalCircle<Real>& c, Real radius, Real scale) {
    return solve<Roots>(c, radius, scale, height_candidates<Roots>(c, scale));
  }

  // The candidate angles: the height candidates, the rim partition (§4.1) and the octic's roots
  // (§4.3). The octic's roots matter outside the cylinder only, where the disk distance is the
  // ring's: there the minimum is at most `bound`, any disk distance the circle reaches (its best
  // sample; an arc passes one its own points reach, detail/arc_span.hpp) (ring_search_intervals).
  // `within`: an arc's angles, where alone its octic is searched (push_circle_ring_roots).
  template <class Roots> static Starts candidates(const CircleOverRound<Real>& view, Real scale, const Heights& heights,
                                                  Real bound, const Intervals<Real>* within = nullptr) {
    Starts starts;
    for (int i = 0; i < heights.count; ++i) starts.push(heights.value[i]);
    push_rim_partition<Roots>(view, scale, starts);
    push_circle_ring_roots<Roots>(view, scale, bound, starts, within);
    return starts;
  }

  template <class Roots> static Minima<Real, Starts::capacity> solve(const LocalCircle<Real>& c, Real radius,
                                                                     Real scale, const Heights& heights) {
    const CircleOverRound<Real> view(c, radius);
    const auto squared = [&](const Vec3<Real>& p) { return DiskTarget<Real>::distance_squared(p, radius); };
    const Starts starts = candidates<Roots>(view, scale, heights, sampled_distance(c, squared));
    const auto h = [&](Real t) { return view.template distance<DiskTarget<Real>>(t); };
    const auto jet = [&](Real t) { return view.template jet<DiskTarget<Real>>(t); };
    return polish_angles<Roots>(jet, h, starts, parameter_tolerance(c.radius, scale), screening_margin(scale));
  }

  // The distance alone often needs no octic (docs/derivations/circle_disk.md, "The distance alone"): the
  // points over the disk where z = 0 or z' = 0 come first; where the best of them is as low as
  // |z| gets anywhere on the circle (the circle crosses the disk, or its lowest point is over
  // it), no other point can be closer.
  template <class Roots = DefaultRoots> static Real distance(const Circle3<Real>& a, const Disk3<Real>& disk) {
    const Round<Real> round(disk.center, disk.normal, disk.radius);
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, disk.radius);
    const Heights heights = height_candidates<Roots>(c, scale);
    const HeightVerdict early = height_verdict(c, disk.radius, scale, heights);
    if (early.decided) return early.best;
    // Otherwise the full solve, as closest() runs it: the ring's octic alone is not enough. For
    // a circle 1e5 times larger than the disk its roots near the disk are a cluster 1e-5 wide
    // that rounding blurs, and the minimum was missed (0.084 for 0.0138) where the rim crossings
    // of the full solve start next to it.
    return std::min(early.best, solve<Roots>(c, disk.radius, scale, heights).best.value);
  }

  // The closest pair of the full solve, reporting the distance distance() returns (the two never
  // disagree: the best height candidate, unpolished, may lie an ulp above the polished minimum).
  template <class Roots = DefaultRoots> static Result<Real> closest(const Circle3<Real>& a, const Disk3<Real>& disk) {
    const Round<Real> round(disk.center, disk.normal, disk.radius);
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, disk.radius);
    const Heights heights = height_candidates<Roots>(c, scale);
    const auto minima = solve<Roots>(c, disk.radius, scale, heights);
    Result<Real> r = circle_round_result<DiskTarget<Real>>(a, c, round, minima, scale);
    const HeightVerdict early = height_verdict(c, disk.radius, scale, heights);
    r.distance = early.decided ? early.best : std::min(early.best, minima.best.value);
    return r;
  }

 private:
  // distance()'s shortcut: the best of the points over the disk where z = 0 or z' = 0, decided
  // when it is as low as |z| gets anywhere on the circle.
  struct HeightVerdict {
    Real best;
    bool decided;
  };
  static HeightVerdict height_verdict(const LocalCircle<Real>& c, Real radius, Real scale, const Heights& heights) {
    const CircleOverRound<Real> view(c, radius);
    Real best = std::numeric_limits<Real>::infinity(), lowest = best;
    for (int i = 0; i < heights.count; ++i) {
      best = std::min(best, view.template distance<DiskTarget<Real>>(heights.value[i]));
      lowest = std::min(lowest, std::abs(c.at(heights.value[i]).z()));
    }
    return {best, best <= lowest + tie_tolerance(scale)};
  }
};

}  // namespace detail

template <class Real> struct Query<Circle3<Real>, Disk3<Real>> : detail::CircleDiskPair<Real> {};

}  // namespace circledist
