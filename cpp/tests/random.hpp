// Seeded random numbers, vectors and directions for the C++ tests (one engine per test program,
// so that each test draws the same sequence on every run).
#pragma once

#include <circledist/primitives.hpp>

#include <random>

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
    do v = vector(1); while (v.norm() < 0.1);
    return v;
  }
};

}  // namespace test_random
