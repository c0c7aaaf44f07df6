// detail/atan2.hpp: the double atan2 against long double's atan2l (64-bit significand, an
// independent implementation whose own error is 2^-11 of a double's ulp), in units of the double
// result's ulp; std::atan2's conventions for zeros, infinities and NaN, bit for bit.
#include <circledist/detail/atan2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

#include "check.hpp"

namespace test_atan2 {

namespace {

double worst_ulps = 0;
double worst_y = 0, worst_x = 0;

// |detail::atan2(y, x) - atan2l(y, x)| in ulps of the exact angle rounded to double.
double ulps(double y, double x) {
  const long double exact = std::atan2((long double)y, (long double)x);
  const double rounded = double(exact);
  const double ulp = std::nextafter(std::abs(rounded), std::numeric_limits<double>::infinity()) - std::abs(rounded);
  const double error = double(std::abs((long double)circledist::detail::atan2(y, x) - exact) / ulp);
  if (error > worst_ulps) {
    worst_ulps = error;
    worst_y = y;
    worst_x = x;
  }
  return error;
}

bool same_bits(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  std::uint64_t ba, bb;
  std::memcpy(&ba, &a, sizeof a);
  std::memcpy(&bb, &b, sizeof b);
  return ba == bb;
}

}  // namespace

int main() {
  constexpr double kBound = 2.5;  // the header's stated bound, in ulps
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60), wide_exponent(-1060, 1015);

  // Random directions at every scale the points of a scene have, and at extreme ones (a tenth of
  // them under the sanitizers, check.hpp).
  double random_worst = 0;
  for (int i = 0; i < check::scaled(1000000); ++i) {
    const double scale = std::ldexp(1.0, i % 10 == 0 ? wide_exponent(rng) : exponent(rng));
    random_worst = std::max(random_worst, ulps(scale * unit(rng), scale * unit(rng)));
  }
  CHECK(random_worst <= kBound);

  // Where the reduction switches: the octant boundaries |y| = |x| and |y| = tan(pi/8) |x| (and
  // their mirror images), a few ulps either side, in all four quadrants; and the axes.
  double boundary_worst = 0;
  const double tan_pi_8 = 0.41421356237309503, tan_3pi_8 = 2.4142135623730949;
  for (double ratio : {1.0, tan_pi_8, tan_3pi_8}) {
    for (int k = -64; k <= 64; ++k) {
      for (int quadrant = 0; quadrant < 4; ++quadrant) {
        const double x = (quadrant & 1 ? -1 : 1) * (1 + unit(rng) / 4);
        double y = ratio * std::abs(x);
        for (int step = 0; step < std::abs(k); ++step) y = std::nextafter(y, k < 0 ? 0.0 : 10.0);
        boundary_worst = std::max(boundary_worst, ulps(quadrant & 2 ? -y : y, x));
      }
    }
  }
  for (double tiny : {1e-300, 1e-200, 1e-17, 1e-9, 4.9e-324}) {
    for (double sign_x : {1.0, -1.0}) {
      for (double sign_y : {1.0, -1.0}) {
        boundary_worst = std::max(boundary_worst, ulps(sign_y * tiny, sign_x * 1.5));
        boundary_worst = std::max(boundary_worst, ulps(sign_y * 1.5, sign_x * tiny));
      }
    }
  }
  CHECK(boundary_worst <= kBound);

  // Subnormal, huge and mixed magnitudes (the huge ones take std::atan2's path).
  double extreme_worst = 0;
  const double max = std::numeric_limits<double>::max(), denorm = std::numeric_limits<double>::denorm_min();
  for (double y : {denorm, 3 * denorm, 1e-310, 1e-300, 1.0, 1e300, 0.5 * max, max}) {
    for (double x : {denorm, 7 * denorm, 1e-310, 1e-300, 1.0, 1e300, 0.5 * max, max}) {
      extreme_worst = std::max({extreme_worst, ulps(y, x), ulps(-y, x), ulps(y, -x), ulps(-y, -x)});
    }
  }
  CHECK(extreme_worst <= kBound);

  // Zeros, infinities and NaN: exactly std::atan2's answers, signs of zero included.
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  int special_mismatches = 0;
  for (double y : {0.0, -0.0, 1.0, -1.0, inf, -inf, nan, max}) {
    for (double x : {0.0, -0.0, 1.0, -1.0, inf, -inf, nan, max}) {
      if (!same_bits(circledist::detail::atan2(y, x), std::atan2(y, x))) {
        ++special_mismatches;
        std::printf("special case differs: atan2(%g, %g) = %.17g, std::atan2 %.17g\n", y, x,
                    circledist::detail::atan2(y, x), std::atan2(y, x));
      }
    }
  }
  CHECK(special_mismatches == 0);

  // Other types are std::atan2 itself.
  CHECK(circledist::detail::atan2(0.3L, -0.7L) == std::atan2(0.3L, -0.7L));
  CHECK(circledist::detail::atan2(0.3f, -0.7f) == std::atan2(0.3f, -0.7f));

  std::printf("largest error %.3f ulp (random %.3f, boundaries %.3f, extremes %.3f), at atan2(%.17g, %.17g)\n",
              worst_ulps, random_worst, boundary_worst, extreme_worst, worst_y, worst_x);
  return check::finish("test_atan2");
}

}  // namespace test_atan2

CHECK_SUITE(test_atan2);
