// The angle of a point in its plane, atan2(y, x), for closest_points' circle and disk params.
//
// Why not std::atan2: glibc's costs about 27 ns a call on the machines we measure (its slow path
// for correct rounding), more than a whole point-circle distance, and a closest_points answer of
// the point kinds is little else. In double this computes the angle within 2.5 ulp of the exact
// one (2.02 is the largest error its test finds) in a fraction of the time; other types keep
// std::atan2 (long double's bar is 1e-15). cpp/tests/test_atan2.cpp measures the error against
// long double's atan2l and checks zeros, infinities and NaN against std::atan2, bit for bit.
//
// Method: the octant reduction every atan2 uses, in one division. With a = min(|x|, |y|) and
// b = max(|x|, |y|), atan(a / b) lies in [0, pi/4]; past tan(pi/8) the identity
// atan(a/b) = pi/4 + atan((a - b) / (a + b)) brings the argument back to |t| <= tan(pi/8), so one
// division serves both (its numerator and denominator chosen without a branch). On |t| <= tan(pi/8)
// atan(t) = t + t z P(z), z = t^2, with P of degree 10: the interpolant of (atan(sqrt z)/sqrt z - 1)/z
// at the Chebyshev points of [0, tan(pi/8)^2], whose error is below 0.05 ulp of atan(t)
// (tools/atan_coefficients.py derives the coefficients and prints that bound). The correction t z P
// is under 6 % of t, so its rounding shrinks by that factor; t's own (a - b, a + b and the quotient
// round once each) stays below 1.5 ulp; the angle, m pi/4 plus or minus atan(t), is summed with
// m pi/4's low part first and rounds once more: 2 ulp and a little.
#pragma once

#include "../primitives.hpp"  // CIRCLEDIST_INLINE

#include <algorithm>
#include <cmath>

namespace circledist::detail {

template <class Real> CIRCLEDIST_INLINE Real atan2(Real y, Real x) { return std::atan2(y, x); }

// Forced inline: in a unit holding many kernels the compiler kept it out of line, and the call
// cost a batch of point-circle closest_points a third of its time.
template <> CIRCLEDIST_INLINE double atan2<double>(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double a = std::min(ax, ay), b = std::max(ax, ay);
  // Zeros, infinities, NaN, magnitudes where a + b could overflow and subnormal ones (where
  // tan(pi/8) b rounds coarsely): the library's atan2, whose conventions for signed zeros and
  // infinities are the reference. Not taken by the points of a scene.
  const double sum = ax + ay;  // NaN when either is (min and max would drop it)
  if (!(sum >= 0x1p-1000 && sum < 0x1p1020)) return std::atan2(y, x);
  // Branch-free: over a batch of random directions each choice below would be mispredicted half
  // the time as a jump, which costs as much as the rest. Written as conditional expressions, GCC
  // 12 made jumps of them (22.8 ns a call in a loop over random directions); as loads from tables
  // indexed by the three comparisons' bits, and one product with 0 or 1 (exact), it cannot:
  // 13.7 ns, bit for bit the same angles (measured on this 2-core EPYC, -O3).
  constexpr double tan_pi_8 = 0.41421356237309503;  // tan(pi/8) rounded: either side is exact
  const unsigned steep = ay > ax;                   // the angle is pi/2 - atan(|x| / |y|)
  const unsigned far = a > tan_pi_8 * b;            // atan(a/b) = pi/4 + atan((a - b)/(a + b))
  const unsigned negative = std::signbit(x);
  const unsigned octant = 4 * steep + 2 * far + negative;
  // The angle is m pi/4 + sign atan(t): m = 1 past tan(pi/8); pi/2 minus that when steep; pi minus
  // that for x < 0; y's sign last. The sign of atan(t) is that of the numerator, a - b or a
  // (exact), applied by a factor off the path that waits for the division.
  static constexpr int quarters[8] = {0, 4, 1, 3, 2, 2, 1, 3};
  static constexpr double signs[8] = {1, -1, 1, -1, -1, 1, -1, 1};
  static constexpr double past_pi_8[2] = {0.0, 1.0};
  const double f = past_pi_8[far];
  const int m = quarters[octant];
  const double t = signs[octant] * (a - f * b) / (b + f * a);
  const double z = t * t;
  // P(z) by Estrin's scheme (pairs, then pairs of pairs): a shorter dependency chain than Horner's
  // rule, the same rounding (every term is under 6 % of t in the end).
  const double z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const double p01 = -0.3333333333333333 + 0.1999999999999552 * z, p23 = -0.14285714284666542 + 0.11111111015256361 * z;
  const double p45 = -0.09090904578123901 + 0.07692183190826085 * z,
               p67 = -0.06664511447381931 + 0.05858148912802064 * z;
  const double p89 = -0.05085449737939498 + 0.03923165829556517 * z, p10 = -0.019176887119035292;
  const double p = (p01 + z2 * p23) + z4 * (p45 + z2 * p67) + z8 * (p89 + z2 * p10);
  // m pi/4 as a double plus the rest, so that the sum rounds once, at the end.
  static constexpr double quarter_pi_hi[5] = {0.0, 0.7853981633974483, 1.5707963267948966, 2.356194490192345,
                                              3.141592653589793};
  static constexpr double quarter_pi_lo[5] = {0.0, 3.061616997868383e-17, 6.123233995736766e-17, 9.184850993605148e-17,
                                              1.2246467991473532e-16};
  return std::copysign(quarter_pi_hi[m] + (quarter_pi_lo[m] + (t + t * z * p)), y);
}

}  // namespace circledist::detail
