// Circle against disk: note 001 §4 (details in docs/circle_disk.md). The circle A is written in
// the disk's local frame, P(t) = O + E1 cos t + E2 sin t with t A's canonical angle, and its
// angle range is cut where the projection crosses the rim (§4.1). Inside the rim the distance is
// the height |z(t)|, minimal where z = 0 or z' = 0 (§4.2); outside it is the distance to the rim
// circle, stationary at the roots of the octic of §4.3, which is the circle-circle equation
// (circle_circle.hpp). All equations are taken through the half-angle substitution
// u = tan(t/2) (one root <-> one angle, no extraneous sign of sin t, no acos near +-1); the
// cut points, t = 0 and t = pi join the candidates and the exact point-disk distance judges.
#pragma once

#include "circle_circle.hpp"

namespace circledist {

// §4.1: x(t)^2 + y(t)^2 - R^2 = 0, trigonometric degree 2 (a quartic in u).
template <class Roots, class Real, int N>
void push_rim_partition(const LocalCircle<Real>& c, Real radius, Real scale, Candidates<Real, N>& out) {
  const Trig<Real, 1> x = c.coordinate(0, scale), y = c.coordinate(1, scale);
  Trig<Real, 2> g = x * x + y * y;
  const Real r = radius / scale;
  g.c[0] -= r * r;
  push_trig_roots<Roots>(g, out);
}

// §4.2: z(t) = c0 + c1 cos t + c2 sin t = 0 and z'(t) = c2 cos t - c1 sin t = 0 (quadratics in u).
template <class Roots, class Real, int N>
void push_height_roots(const LocalCircle<Real>& c, Real scale, Candidates<Real, N>& out) {
  const Trig<Real, 1> z = c.coordinate(2, scale);
  push_trig_roots<Roots>(z, out);
  push_trig_roots<Roots>(z.derivative(), out);
}

template <class Real> struct Query<Circle3<Real>, Disk3<Real>> {
  static constexpr bool defined = true;
  // 2 fixed + 8 (octic) + 4 (rim quartic) + 2 + 2 (height quadratics) = 18 at most.
  using Starts = Candidates<Real, 24>;

  template <class Roots> static Minima<Real, Starts::capacity> solve(const LocalCircle<Real>& c, Real radius, Real scale) {
    Starts starts;
    push_circle_candidates(starts);
    push_rim_partition<Roots>(c, radius, scale, starts);
    push_height_roots<Roots>(c, scale, starts);
    // The octic's roots matter outside the cylinder only, where the disk distance is the ring's:
    // there the minimum is at most any disk distance A reaches (ring_search_intervals).
    const auto squared = [&](const Vec3<Real>& p) { return disk_distance_squared(p, radius); };
    push_circle_ring_roots<Roots>(c, radius, scale, sampled_distance(c, squared), starts);
    const auto h = [&](Real t) { return disk_distance_local(c.at(t), radius); };
    const auto jet = [&](Real t) { return c.jet(t, radius, &disk_jet_of<Real>); };
    return polish_angles<Roots>(jet, h, starts, parameter_tolerance(c.radius, scale), screening_margin(scale));
  }

  // The distance alone needs neither the rim partition nor, often, the octic (docs/circle_disk.md,
  // "The distance alone"): it is the smaller of the circle-ring distance and |z| at the points
  // over the disk where z = 0 or z' = 0. Those few points come first; where the best of them is
  // as low as |z| gets anywhere on the circle (the circle crosses the disk, or its lowest point is
  // over it), no ring point can be closer and the octic is skipped.
  template <class Roots = DefaultRoots> static Real distance(const Circle3<Real>& a, const Disk3<Real>& disk) {
    const Round<Real> round(disk.center, disk.normal, disk.radius);
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, disk.radius);
    Candidates<Real, 8> heights;
    push_circle_candidates(heights);  // z' = 0 everywhere (a parallel circle) has no roots to push
    push_height_roots<Roots>(c, scale, heights);
    Real best = std::numeric_limits<Real>::infinity(), lowest = best;
    for (int i = 0; i < heights.count; ++i) {
      const Vec3<Real> p = c.at(heights.value[i]);
      best = std::min(best, disk_distance_local(p, disk.radius));
      lowest = std::min(lowest, std::abs(p.z()));
    }
    if (best <= lowest + tie_tolerance(scale)) return best;
    // Only rim points closer than `best` matter: the octic is searched where they can be.
    return std::min(best,
                    Query<Circle3<Real>, Circle3<Real>>::template solve<Roots>(c, disk.radius, scale, best).best.value);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Circle3<Real>& a, const Disk3<Real>& disk) {
    const Round<Real> round(disk.center, disk.normal, disk.radius);
    const LocalCircle<Real> c(a, round);
    const Real scale = circle_round_scale(c, disk.radius);
    const auto minima = solve<Roots>(c, disk.radius, scale);
    return circle_round_result(
        a, c, round, minima, scale, [&](const Vec3<Real>& p, bool&) { return round.disk_point(p); },
        &Round<Real>::disk_param);
  }
};

}  // namespace circledist
