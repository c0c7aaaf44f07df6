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

#include "circle_circle.hpp"
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
    const Heights heights = height_candidates<Roots>(c, scale);
    return solve<Roots>(c, radius, scale, heights, height_verdict(CircleOverRound<Real>(c, radius), scale, heights));
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

  // distance()'s shortcut: the disk distance at each height candidate, their best, and whether
  // that is decided: as low as |z| gets anywhere on the circle (one sine and cosine a point).
  struct HeightVerdict {
    std::array<Real, Heights::capacity> value{};
    Real best = std::numeric_limits<Real>::infinity();
    bool decided = false;
  };
  static HeightVerdict height_verdict(const CircleOverRound<Real>& view, Real scale, const Heights& heights) {
    const LocalCircle<Real>& c = view.c;
    HeightVerdict out;
    Real lowest = out.best;
    for (int i = 0; i < heights.count; ++i) {
      const Real cs = std::cos(heights.value[i]), sn = std::sin(heights.value[i]);
      out.value[i] = view.template distance<DiskTarget<Real>>(cs, sn);
      out.best = std::min(out.best, out.value[i]);
      lowest = std::min(lowest, std::abs(c.center.z() + cs * c.e1.z() + sn * c.e2.z()));  // c.at(t).z()
    }
    out.decided = out.best <= lowest + tie_tolerance(scale);
    return out;
  }

  // The heights come first among the starts, and the verdict has their values already.
  template <class Roots> static Minima<Real, Starts::capacity> solve(const LocalCircle<Real>& c, Real radius,
                                                                     Real scale, const Heights& heights,
                                                                     const HeightVerdict& verdict) {
    const CircleOverRound<Real> view(c, radius);
    const auto squared = [&](const Vec3<Real>& p) { return DiskTarget<Real>::distance_squared(p, radius); };
    const Starts starts = candidates<Roots>(view, scale, heights, sampled_distance(c, squared));
    RecentAngles<Real> angles;
    const auto h = [&](Real t) { return angles.template distance<DiskTarget<Real>>(view, t); };
    const auto jet = [&](Real t) { return angles.template jet<DiskTarget<Real>>(view, t); };
    return polish_angles<Roots>(jet, h, starts, parameter_tolerance(c.radius, scale), screening_margin(scale),
                                verdict.value.data(), heights.count);
  }

  // The distance alone often needs no octic (docs/derivations/circle_disk.md, "The distance
  // alone, and the rim part"): the points over the disk where z = 0 or z' = 0 come first; where
  // the best of them is as low as |z| gets anywhere on the circle (the circle crosses the disk,
  // or its lowest point is over it), no other point can be closer.
  template <class Roots = DefaultRoots> static Real distance(const Circle3<Real>& a, const Disk3<Real>& disk) {
    const Round<Real> round(disk.center, disk.normal, disk.radius);
    if (clear_of_cylinder(a, round)) return Rim::template distance<Roots>(a, rim(disk));
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, disk.radius);
    const Heights heights = height_candidates<Roots>(c, scale);
    const HeightVerdict early = height_verdict(CircleOverRound<Real>(c, disk.radius), scale, heights);
    if (early.decided) return early.best;
    // Then the rim part (the same section): circle-circle against the rim, the answer where it
    // lies below every height candidate; otherwise the full solve, as closest() runs it. (The
    // octic in A's own angle is not enough for the rim part: for a circle 1e5 times larger than
    // the disk its roots near the disk are a cluster 1e-5 wide that rounding blurs, and a minimum
    // was missed, 0.084 for 0.0138; circle-circle parametrizes the smaller circle, the rim.)
    // Its octic is searched only where the rim distance can be at most early.best: a rim part
    // above that never decides (the same section).
    const Real rim_part = Rim::template distance_below<Roots>(a, rim(disk), early.best);
    if (rim_part_decides(rim_part, early, scale)) return rim_part;
    return std::min(early.best, solve<Roots>(c, disk.radius, scale, heights, early).best.value);
  }

  // The same decisions as distance(): the clear circle's and the rim part's answers are
  // circle-circle's; otherwise the closest pair of the full solve, reporting the distance
  // distance() returns (the two never disagree: the best height candidate, unpolished, may lie
  // an ulp above the polished minimum).
  template <class Roots = DefaultRoots> static Result<Real> closest(const Circle3<Real>& a, const Disk3<Real>& disk) {
    const Round<Real> round(disk.center, disk.normal, disk.radius);
    if (clear_of_cylinder(a, round)) {
      // The rim's parameter (theta, 0) is the disk's (radius, theta): the same frame.
      Result<Real> r = Rim::template closest<Roots>(a, rim(disk));
      r.param_b = Vec2<Real>(disk.radius, r.param_b.x());
      return r;
    }
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, disk.radius);
    const Heights heights = height_candidates<Roots>(c, scale);
    const HeightVerdict early = height_verdict(CircleOverRound<Real>(c, disk.radius), scale, heights);
    if (!early.decided) {
      Result<Real> r = Rim::template closest_below<Roots>(a, rim(disk), early.best);
      if (rim_part_decides(r.distance, early, scale)) {
        r.param_b = Vec2<Real>(disk.radius, r.param_b.x());  // as for a circle clear of the cylinder
        return r;
      }
    }
    const auto minima = solve<Roots>(c, disk.radius, scale, heights, early);
    Result<Real> r = circle_round_result<DiskTarget<Real>>(a, c, round, minima, scale);
    r.distance = early.decided ? early.best : std::min(early.best, minima.best.value);
    return r;
  }

  // Whether every point of A lies outside the disk's cylinder (docs/derivations/circle_disk.md,
  // "A circle clear of the cylinder"): A's points lie within its radius r of its center, so their
  // distances from the axis are at least rho - r, rho its center's; where that exceeds the
  // disk's radius R, the disk's distance is its rim's at every point of A, and the query is
  // circle-circle against the rim (the smaller circle parametrized, as circle-circle chooses).
  // The margin covers the rounding of rho (the center's local coordinates err by a few eps
  // |O|); NaN fields fail the test.
  static bool clear_of_cylinder(const Circle3<Real>& a, const Round<Real>& round) {
    const Vec3<Real> o = round.local(a.center);
    const Real margin = 16 * std::numeric_limits<Real>::epsilon() * (o.norm() + a.radius + round.radius);
    return length2d(o.x(), o.y()) - a.radius - round.radius > margin;
  }

  // Whether the circle-rim distance is the answer: below every height candidate's disk distance
  // by more than the tie tolerance. Then no point over the disk comes as close (the least |z| on
  // an arc over the disk is at a height candidate or at an end on the rim, where the disk's
  // distance is the rim's), the closest pairs are the rim's and none of them ties with a point
  // over the disk.
  static bool rim_part_decides(Real rim_part, const HeightVerdict& early, Real scale) {
    return rim_part + tie_tolerance(scale) < early.best;
  }

 private:
  using Rim = Query<Circle3<Real>, Circle3<Real>>;
  static Circle3<Real> rim(const Disk3<Real>& d) { return {d.center, d.normal, d.radius}; }
};

}  // namespace detail

template <class Real> struct Query<Circle3<Real>, Disk3<Real>> : detail::CircleDiskPair<Real> {};

}  // namespace circledist
