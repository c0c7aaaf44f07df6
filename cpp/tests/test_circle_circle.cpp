// Circle against circle (circle_circle.hpp) against the long-double references of
// round_reference.hpp, and the octic's pruning (ring_search_intervals, detail/local_circle.hpp).
#include "round_reference.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace test_circle_circle {

void circle_circle_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  circle_circle_case("coplanar overlapping", {o, z, 1}, {V3d(1, 0, 0), z, 1}, 0, 0);
  circle_circle_case("coplanar nested", {o, z, 3}, {V3d(0.5, 0, 0), z, 1}, 1.5L, 1);
  circle_circle_case("coplanar disjoint", {o, z, 1}, {V3d(3, 0, 0), z, 0.5}, 1.5L, 1);
  circle_circle_case("concentric coplanar", {V3d(0.3, -0.2, 0.7), unit(1, 2, 3), 1},
                     {V3d(0.3, -0.2, 0.7), unit(1, 2, 3), 2}, 1, 0);
  circle_circle_case("coaxial parallel planes", {o, z, 1}, {V3d(0, 0, 0.5), z, 2}, std::sqrt(1.25L), 0);
  {
    const V3d n = unit(1, 2, 3);
    circle_circle_case("coaxial tilted", {V3d(1, 1, 1), n, 1}, {V3d(1, 1, 1) + 0.5 * n, -n, 2}, std::sqrt(1.25L), 0);
  }
  // B crosses A's plane at (1,0,0), on A, and at the origin, inside A: one common point.
  circle_circle_case("linked, touching (distance 0)", {o, z, 1}, {V3d(0.5, 0, 0), V3d(0, 1, 0), 0.5}, 0, 1);
  {
    const Circle3<double> a{o, z, 1}, b{V3d(0.6, 0.05, 0.1), unit(0, 1, 0.2), 0.9};
    circle_circle_case("linked", a, b, ref::circle_circle(a, b));
  }
  // Every point of B = (1 + cos s, 0, sin s) is at distance 1 from A (and vice versa).
  circle_circle_case("through the other's center, orthogonal normals", {o, z, 1}, {V3d(1, 0, 0), V3d(0, 1, 0), 1}, 1,
                     0);
  circle_circle_case("touching, orthogonal planes", {o, z, 1}, {V3d(2, 0, 0), V3d(0, 1, 0), 1}, 0, 1);
  circle_circle_case("touching, coplanar outside", {o, z, 1}, {V3d(2, 0, 0), z, 1}, 0, 1);
  circle_circle_case("touching, coplanar inside", {o, z, 2}, {V3d(1, 0, 0), z, 1}, 0, 1);
  {
    const double tilt = 1e-9;
    const Circle3<double> a{o, z, 1};
    const Circle3<double> b{V3d(0.3, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 0.8};
    circle_circle_case("near-coplanar crossing", a, b, ref::circle_circle(a, b));
    const Circle3<double> c{V3d(3, 0.5, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 1};
    circle_circle_case("near-coplanar disjoint", a, c, ref::circle_circle(a, c));
    const Circle3<double> d{V3d(0.2, 0.1, 0), V3d(std::sin(tilt), 0, std::cos(tilt)), 0.5};
    circle_circle_case("near-coplanar nested", a, d, ref::circle_circle(a, d));
  }
  {
    const auto check = [](const char* name, const Circle3<double>& a, const Circle3<double>& b) {
      circle_circle_case(name, a, b, ref::circle_circle(a, b));
    };
    circle_round_shared_cases<Circle3<double>>(check);
    translated_cases(generic_circle(), generic_round<Circle3<double>>(), V3d(1, -0.7, 0.3), check);
  }
  {
    const Circle3<double> big{o, z, 1};
    const Circle3<double> onrim{V3d(0.6, 0.8, 2e-6), unit(1, 0.3, 0.2), 1e-6};
    circle_circle_case("radius ratio 1e-6 at the rim", onrim, big, ref::circle_circle(onrim, big));
    const Circle3<double> coax{V3d(0, 0, 0.5), z, 1e-6};
    circle_circle_case("radius ratio 1e-6 coaxial", coax, big, std::sqrt(0.25L + (1 - 1e-6L) * (1 - 1e-6L)), 0);
  }
  {
    // Same center, orthogonal tilted normals: A's points have rho <= 1 from B's axis, so the
    // distance 1 + 4 - 4 rho is least at A's two crossings of B's plane.
    const V3d n1 = unit(1, 2, 3), n2 = n1.cross(V3d(0, 0, 1)).normalized();
    const V3d c(0.4, -1.1, 2.3);
    circle_circle_case("same center, orthogonal normals", {c, n2, 1}, {c, n1, 2}, 1, 0);
    circle_circle_case("same center, orthogonal normals, equal radii", {c, n2, 1.5}, {c, n1, 1.5}, 0, 0);
  }
}

// ring_search_intervals (the octic's pruning): for random, touching and linked pairs, the angle
// at which A comes closest to B's ring, found by the reference minimizer on the library's own
// parametrization of A, lies in the intervals kept for the sampled bound. So does every angle
// whose distance ties with it (two-sample check: the second-best local minimum when it ties).
void pruning_tests() {
  std::mt19937_64 rng(20261123);
  std::normal_distribution<double> normal;
  auto vec = [&] { return V3d(normal(rng), normal(rng), normal(rng)); };
  auto radius = [&] { return std::exp(0.7 * normal(rng)); };
  int pruned = 0, total = 0;
  for (int k = 0; k < check::scaled(300); ++k) {
    Circle3<double> a{vec(), vec(), radius()}, b{vec(), vec(), radius()};
    if (k % 3 == 1) b.center = a.center + a.radius * Frame<double>(a.normal).u + 1e-9 * vec();  // touching
    if (k % 3 == 2)
      b = {a.center + a.radius * Frame<double>(a.normal).u, Frame<double>(a.normal).u, a.radius};  // linked
    const circledist::Round<double> round(b.center, b.normal, b.radius);
    const LocalCircle<double> c(a, round);
    const double scale = circle_round_scale(c, b.radius);
    const V3 o = c.center.cast<LD>(), e1 = c.e1.cast<LD>(), e2 = c.e2.cast<LD>();
    LD best_t = 0, best_h = std::numeric_limits<LD>::infinity();
    const auto h = [&](LD t) {
      const V3 p = o + std::cos(t) * e1 + std::sin(t) * e2;
      const LD rho = std::sqrt(p.x() * p.x() + p.y() * p.y());
      const LD value = std::sqrt(p.z() * p.z() + (rho - LD(b.radius)) * (rho - LD(b.radius)));
      if (value < best_h) {
        best_h = value;
        best_t = t;
      }
      return value;
    };
    ref::minimize(h, -ref::kPi, ref::kPi, true);
    const double bound =
        sampled_distance(c, [&](const V3d& p) { return RingTarget<double>::distance_squared(p, b.radius); });
    CHECK(bound >= double(best_h) - 1e-15 * scale);
    const Intervals<double> kept = ring_search_intervals(c, b.radius, bound + 1e-4 * scale);
    const double u = std::tan(double(best_t) / 2);
    CHECK(kept.contains(u));
    if (!kept.contains(u)) std::printf("pruning case %d: u* = %.17g outside the kept intervals\n", k, u);
    ++total;
    if (!(kept.count == 1 && kept.lo[0] == -std::numeric_limits<double>::infinity() &&
          kept.hi[0] == std::numeric_limits<double>::infinity()))
      ++pruned;
  }
  // Not a requirement, but pruning that never prunes would be a defect worth seeing.
  CHECK(pruned > total / 2);
  std::printf("pruning: %d of %d pairs searched on part of the circle only\n", pruned, total);
}

int main() {
  circle_circle_tests();
  pruning_tests();
  // The random configurations, the tangencies and the other precisions of round_reference.hpp.
  shared_round_cases([](const RoundCase& r) { circle_circle_case("random", r.a, r.b, ref::circle_circle(r.a, r.b)); },
                     [](const RoundCase& r) { circle_circle_case("tangent", r.a, r.b, ref::circle_circle(r.a, r.b)); },
                     [](const auto& s) { return precision_rows(s.a, s.b, s.ad, s.bd, ref::circle_circle); });
  return finish_round("circle_circle");
}

}  // namespace test_circle_circle

CHECK_SUITE(test_circle_circle);
