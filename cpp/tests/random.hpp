// Seeded random numbers, vectors, directions and shapes for the C++ tests (one engine per test
// program, so that each test draws the same sequence on every run).
#pragma once

#include <circledist/bezier.hpp>
#include <circledist/primitives.hpp>

#include <random>
#include <vector>

namespace test_random {

using V = circledist::Vec3<double>;

struct Random {
  std::mt19937_64 engine;
  explicit Random(std::uint64_t seed) : engine(seed) {}

  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(engine); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }  // [lo, hi]
  V vector(double scale) { return V(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale)); }
  // A direction of length 0.1 to sqrt(3), not normalized (queries take any nonzero length).
  V direction() {
    V v;
    do v = vector(1);
    while (v.norm() < 0.1);
    return v;
  }

  // Shapes near the origin: their points within `spread` of it in each coordinate, radii in
  // [0.2, 1.5), segments up to 1.5 and cubic curves' control points up to 1.2 per coordinate from
  // their first point.
  circledist::Line3<double> line(double spread) { return {vector(spread), direction()}; }
  circledist::Segment3<double> segment(double spread) {
    const V p = vector(spread);
    return {p, p + vector(1.5)};
  }
  circledist::Circle3<double> circle(double spread) { return {vector(spread), direction(), uniform(0.2, 1.5)}; }
  circledist::Disk3<double> disk(double spread) { return {vector(spread), direction(), uniform(0.2, 1.5)}; }
  circledist::BezierCurve3<double> bezier(double spread) {
    circledist::BezierCurve3<double> b;
    b.control.resize(3, 4);
    const V p = vector(spread);
    for (int i = 0; i < 4; ++i) b.control.col(i) = p + vector(1.2);
    return b;
  }
};

// The control points of the same curve raised to `degree` (degree elevation: q_i = i/(m+1) p_{i-1}
// + (1 - i/(m+1)) p_i, once per degree): a curve of lower degree whose power-basis coefficients
// above it are rounding noise, the input the root policies find hardest.
inline std::vector<V> elevated(std::vector<V> p, int degree) {
  while (int(p.size()) - 1 < degree) {
    const int m = int(p.size()) - 1;
    std::vector<V> raised(m + 2);
    raised[0] = p[0];
    raised[m + 1] = p[m];
    for (int i = 1; i <= m; ++i) raised[i] = (double(i) / (m + 1)) * p[i - 1] + (1 - double(i) / (m + 1)) * p[i];
    p = raised;
  }
  return p;
}

}  // namespace test_random
