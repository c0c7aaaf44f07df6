// closest_points of four point-round pairs at once, in the lanes of an AVX register: the batched
// query of the point kinds (src/pairs.hpp), so that closest_points costs at most twice distance.
//
// Why: a point-circle distance is about 35 floating-point operations and three square roots;
// its closest points about 120, a third of them the angle (atan2.hpp). One at a time, the closest
// points cost three distances (measured 19.8 against 6.5 ns a pair in a C++ loop shaped like the
// batch kernel, on a 2-core AMD EPYC), and neither memory nor the divider is the limit: the count
// of operations is. Four pairs a register take it to 10.6 ns (1.65x the distance; two lanes of
// SSE2 gave 17.5 ns, the loads and stores around the lanes then costing as much as they saved).
//
// Exactness: every lane runs the operations of PointRoundQuery::closest and detail::atan2<double>
// (point_over_round.hpp, atan2.hpp) in the same order, each an IEEE operation rounded once
// (additions, products, quotients, square roots; selections and sign copies are exact), so each
// lane's answer is the scalar query's to the bit; cpp/tests/test_point_round_lanes.cpp and
// tests/pairs/test_point_round_lanes.py hold the two to the bit. The code is a mirror of the scalar
// code, not a template shared with it: it is compiled for AVX (target attribute) in any x86 build,
// and a function compiled for AVX cannot be inlined into code that must run without it. Not FMA,
// which could fuse a product and a sum the scalar code rounds apart. Where the processor has no
// AVX (has_lanes()), off x86, and for every block where a lane leaves the common path (a normal
// out of [2^-50, 2^50], a point on a circle's axis, an angle's arguments out of atan2's fast
// range, a distance out of the front end's moderate range, anything not finite), the scalar query
// answers: the answers are the scalar query's in every case.
#pragma once

#include "point_over_round.hpp"

#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#define CIRCLEDIST_POINT_ROUND_LANES 1
#include <immintrin.h>
#else
#define CIRCLEDIST_POINT_ROUND_LANES 0
#endif

#include <limits>

namespace circledist::detail {

#if CIRCLEDIST_POINT_ROUND_LANES

// Compiled for AVX (four doubles a register) whatever the build's flags: the module is built for
// any x86-64 processor, and the caller asks the processor first (has_lanes()). Not FMA: the
// lanes must round as the scalar code does, one operation at a time.
#define CIRCLEDIST_LANES_FN inline __attribute__((always_inline, target("avx")))
#define CIRCLEDIST_LANES_FN_LAMBDA __attribute__((always_inline, target("avx")))

constexpr int kLanes = 4;

// True where the processor runs AVX.
inline bool has_lanes() {
  static const bool avx = __builtin_cpu_supports("avx");
  return avx;
}

// Four doubles, with the scalar operators: the code below reads as the scalar code it mirrors.
struct Lanes {
  __m256d v;
  static CIRCLEDIST_LANES_FN Lanes of(double x0, double x1, double x2, double x3) {
    return {_mm256_set_pd(x3, x2, x1, x0)};
  }
  static CIRCLEDIST_LANES_FN Lanes both(double x) { return {_mm256_set1_pd(x)}; }
  CIRCLEDIST_LANES_FN void to(double* out) const { _mm256_storeu_pd(out, v); }
};
// Stores the lanes of a and b interleaved: a0 b0 a1 b1 a2 b2 a3 b3 (a param's two numbers).
CIRCLEDIST_LANES_FN void store_pairs(Lanes a, Lanes b, double* out) {
  const __m256d low = _mm256_unpacklo_pd(a.v, b.v), high = _mm256_unpackhi_pd(a.v, b.v);  // a0 b0 a2 b2, a1 b1 a3 b3
  _mm256_storeu_pd(out, _mm256_permute2f128_pd(low, high, 0x20));
  _mm256_storeu_pd(out + 4, _mm256_permute2f128_pd(low, high, 0x31));
}
// Twelve consecutive numbers x0 y0 z0 x1 ... z3 (four 3-vectors) as the lanes x, y, z, and back:
// a transpose by 128-bit halves and shuffles, where loading lane by lane costs twice the operations.
CIRCLEDIST_LANES_FN void load_triples(const double* p, Lanes& x, Lanes& y, Lanes& z) {
  const __m256d xy02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p)), _mm_loadu_pd(p + 6), 1);
  const __m256d zx02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 2)), _mm_loadu_pd(p + 8), 1);
  const __m256d yz13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 4)), _mm_loadu_pd(p + 10), 1);
  x = {_mm256_shuffle_pd(xy02, zx02, 0b1010)};
  y = {_mm256_shuffle_pd(xy02, yz13, 0b0101)};
  z = {_mm256_shuffle_pd(zx02, yz13, 0b1010)};
}
CIRCLEDIST_LANES_FN void store_triples(Lanes x, Lanes y, Lanes z, double* p) {
  const __m256d xy02 = _mm256_shuffle_pd(x.v, y.v, 0b0000), zx02 = _mm256_shuffle_pd(z.v, x.v, 0b1010);
  const __m256d yz13 = _mm256_shuffle_pd(y.v, z.v, 0b1111);
  _mm_storeu_pd(p, _mm256_castpd256_pd128(xy02));
  _mm_storeu_pd(p + 2, _mm256_castpd256_pd128(zx02));
  _mm_storeu_pd(p + 4, _mm256_castpd256_pd128(yz13));
  _mm_storeu_pd(p + 6, _mm256_extractf128_pd(xy02, 1));
  _mm_storeu_pd(p + 8, _mm256_extractf128_pd(zx02, 1));
  _mm_storeu_pd(p + 10, _mm256_extractf128_pd(yz13, 1));
}
// The lanes x[0], x[stride], x[2 stride], x[3 stride].
CIRCLEDIST_LANES_FN Lanes strided_lanes(const double* x, std::ptrdiff_t stride) {
  return {_mm256_set_pd(x[3 * stride], x[2 * stride], x[stride], x[0])};
}
CIRCLEDIST_LANES_FN Lanes operator+(Lanes a, Lanes b) { return {_mm256_add_pd(a.v, b.v)}; }
CIRCLEDIST_LANES_FN Lanes operator-(Lanes a, Lanes b) { return {_mm256_sub_pd(a.v, b.v)}; }
CIRCLEDIST_LANES_FN Lanes operator*(Lanes a, Lanes b) { return {_mm256_mul_pd(a.v, b.v)}; }
CIRCLEDIST_LANES_FN Lanes operator/(Lanes a, Lanes b) { return {_mm256_div_pd(a.v, b.v)}; }
CIRCLEDIST_LANES_FN Lanes sqrt(Lanes a) { return {_mm256_sqrt_pd(a.v)}; }
CIRCLEDIST_LANES_FN Lanes abs(Lanes a) { return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)}; }
CIRCLEDIST_LANES_FN Lanes min(Lanes a, Lanes b) { return {_mm256_min_pd(a.v, b.v)}; }
CIRCLEDIST_LANES_FN Lanes max(Lanes a, Lanes b) { return {_mm256_max_pd(a.v, b.v)}; }
// Comparisons give masks (all bits of a lane set where true, none where false or NaN: ordered,
// quiet, as the scalar operators).
CIRCLEDIST_LANES_FN Lanes operator<(Lanes a, Lanes b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
CIRCLEDIST_LANES_FN Lanes operator<=(Lanes a, Lanes b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)}; }
CIRCLEDIST_LANES_FN Lanes operator>(Lanes a, Lanes b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
CIRCLEDIST_LANES_FN Lanes operator>=(Lanes a, Lanes b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)}; }
CIRCLEDIST_LANES_FN Lanes operator&(Lanes a, Lanes b) { return {_mm256_and_pd(a.v, b.v)}; }
// mask ? if_true : if_false, lane by lane (select.hpp's, exact).
CIRCLEDIST_LANES_FN Lanes select(Lanes mask, Lanes if_true, Lanes if_false) {
  return {_mm256_blendv_pd(if_false.v, if_true.v, mask.v)};
}
// Each lane's magnitude with the sign of the other operand's lane (std::copysign's).
CIRCLEDIST_LANES_FN Lanes copysign(Lanes magnitude, Lanes sign) {
  const __m256d bit = _mm256_set1_pd(-0.0);
  return {_mm256_or_pd(_mm256_andnot_pd(bit, magnitude.v), _mm256_and_pd(bit, sign.v))};
}
// Bit k for lane k: the lanes whose mask (or sign bit) is set.
CIRCLEDIST_LANES_FN int lanes_set(Lanes mask) { return _mm256_movemask_pd(mask.v); }
constexpr int kAllLanes = (1 << kLanes) - 1;

// detail::atan2<double> (atan2.hpp) in lanes, operation for operation; false (and nothing
// computed) where a lane's arguments leave its fast range, which the scalar function hands to
// std::atan2.
CIRCLEDIST_LANES_FN bool atan2_lanes(Lanes y, Lanes x, Lanes& angle) {
  const Lanes ax = abs(x), ay = abs(y);
  const Lanes a = min(ax, ay), b = max(ax, ay);
  const Lanes sum = ax + ay;
  if (lanes_set((sum >= Lanes::both(0x1p-1000)) & (sum < Lanes::both(0x1p1020))) != kAllLanes) return false;
  constexpr double tan_pi_8 = 0.41421356237309503;
  const int steep = lanes_set(ay > ax), far = lanes_set(a > Lanes::both(tan_pi_8) * b);
  const int negative = lanes_set(x);  // the sign bits
  static constexpr int quarters[8] = {0, 4, 1, 3, 2, 2, 1, 3};
  static constexpr double signs[8] = {1, -1, 1, -1, -1, 1, -1, 1};
  static constexpr double past_pi_8[2] = {0.0, 1.0};
  static constexpr double quarter_pi_hi[5] = {0.0, 0.7853981633974483, 1.5707963267948966, 2.356194490192345,
                                              3.141592653589793};
  static constexpr double quarter_pi_lo[5] = {0.0, 3.061616997868383e-17, 6.123233995736766e-17, 9.184850993605148e-17,
                                              1.2246467991473532e-16};
  alignas(32) double sign[kLanes], f[kLanes], hi[kLanes], lo[kLanes];
  for (int k = 0; k < kLanes; ++k) {
    const int octant = 4 * ((steep >> k) & 1) + 2 * ((far >> k) & 1) + ((negative >> k) & 1);
    sign[k] = signs[octant];
    f[k] = past_pi_8[(far >> k) & 1];
    hi[k] = quarter_pi_hi[quarters[octant]];
    lo[k] = quarter_pi_lo[quarters[octant]];
  }
  const Lanes fl = {_mm256_load_pd(f)};
  const Lanes t = Lanes{_mm256_load_pd(sign)} * (a - fl * b) / (b + fl * a);
  const Lanes z = t * t;
  const Lanes z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const Lanes p01 = Lanes::both(-0.3333333333333333) + Lanes::both(0.1999999999999552) * z;
  const Lanes p23 = Lanes::both(-0.14285714284666542) + Lanes::both(0.11111111015256361) * z;
  const Lanes p45 = Lanes::both(-0.09090904578123901) + Lanes::both(0.07692183190826085) * z;
  const Lanes p67 = Lanes::both(-0.06664511447381931) + Lanes::both(0.05858148912802064) * z;
  const Lanes p89 = Lanes::both(-0.05085449737939498) + Lanes::both(0.03923165829556517) * z,
              p10 = Lanes::both(-0.019176887119035292);
  const Lanes p = (p01 + z2 * p23) + z4 * (p45 + z2 * p67) + z8 * (p89 + z2 * p10);
  angle = copysign(Lanes{_mm256_load_pd(hi)} + (Lanes{_mm256_load_pd(lo)} + (t + t * z * p)), y);
  return true;
}

// What the lanes' points are measured against: circles, disks, or true rings (annuli with
// 0 < inner < outer, PointRingQuery).
enum class LaneTarget { kCircle, kDisk, kRing };

// A point and a round (circle, disk or ring) per lane, and closest_points' answer per lane; the
// caller moves them from and to its own layout.
struct PointRoundLanes {
  Lanes px, py, pz;  // the point
  Lanes cx, cy, cz;  // the round's center
  Lanes wx, wy, wz;  // its normal, as given
  Lanes radius;      // its radius (a ring's outer one)
  Lanes inner;       // a ring's inner radius (unused for circles and disks)
};
struct PointRoundAnswerLanes {
  Lanes distance;
  Lanes bx, by, bz;      // the closest point of the round (the point itself is the other)
  Lanes param0, param1;  // the round's param: (theta, 0) on a circle, (rho, theta) on a disk or ring
};

// PointRoundQuery<double, Target == kDisk>::closest (PointRingQuery::closest for rings) in every
// lane, as the front end's closest_points answers it (no promotion for double; the moderate-range
// check): the point's param is (0, 0) and `unique` true. False, with `out` untouched, where a lane
// leaves the common path (the caller then asks the scalar query for every lane).
template <LaneTarget Target>
CIRCLEDIST_LANES_FN bool point_round_closest_lanes(const PointRoundLanes& in, PointRoundAnswerLanes& out) {
  constexpr bool circle = Target == LaneTarget::kCircle, ring = Target == LaneTarget::kRing;
  const Lanes wx = in.wx, wy = in.wy, wz = in.wz, radius = in.radius;
  // A ring in every lane, else the annulus's other kinds (annulus_kind) answer.
  if constexpr (ring) {
    if (lanes_set((in.inner > Lanes::both(0)) & (in.inner < radius)) != kAllLanes) return false;
  }
  // PointOverRound's constructor.
  const Lanes dx = in.px - in.cx, dy = in.py - in.cy, dz = in.pz - in.cz;
  const Lanes norm2 = wx * wx + wy * wy + wz * wz;
  constexpr double lo = power_of_two<double>(-100), hi = power_of_two<double>(100);
  if (lanes_set((norm2 > Lanes::both(lo)) & (norm2 < Lanes::both(hi))) != kAllLanes) return false;  // rescale_normal
  const Lanes s = sqrt(norm2);
  const Lanes inv_s = Lanes::both(1) / s;
  const Lanes mx = wy * dz - wz * dy, my = wz * dx - wx * dz, mz = wx * dy - wy * dx;
  const Lanes cross = sqrt(mx * mx + my * my + mz * mz);
  const Lanes height = (wx * dx + wy * dy + wz * dz) * inv_s;
  const Lanes radial = cross * inv_s;
  // on_axis() of a rim the answer is on (a circle's; a ring's inner one over its hole): the
  // scalar query's own branch.
  constexpr double tol = 8 * std::numeric_limits<double>::epsilon();
  const auto on_axis = [&](Lanes rim_radius) CIRCLEDIST_LANES_FN_LAMBDA {
    return cross <= Lanes::both(tol) * s * (rim_radius + (abs(dx) + abs(dy) + abs(dz)));
  };
  Lanes hole;  // a ring's lanes over its hole (rho < inner)
  if constexpr (circle) {
    if (lanes_set(on_axis(radius))) return false;
  } else if constexpr (ring) {
    hole = radial < in.inner;
    if (lanes_set(hole & on_axis(in.inner))) return false;
  }
  // in_plane() and to_rim().
  const Lanes qx = my * wz - mz * wy, qy = mz * wx - mx * wz, qz = mx * wy - my * wx;
  const Lanes length = sqrt(qx * qx + qy * qy + qz * qz);
  const auto to_rim = [&](Lanes rim_radius) CIRCLEDIST_LANES_FN_LAMBDA {
    return select(length > Lanes::both(0), rim_radius / length, Lanes::both(0));
  };
  // angle().
  const Lanes x_major = abs(wx) > abs(wy);
  const Lanes along_u = select(x_major, wx * dz - wz * dx, wz * dy - wy * dz) + Lanes::both(0);
  const Lanes along_v = select(x_major, wz * mx - wx * mz, wy * mz - wz * my) + Lanes::both(0);
  Lanes theta;
  if (!atan2_lanes(along_v, s * along_u, theta)) return false;
  const auto from_rim = [&](Lanes rim_radius) CIRCLEDIST_LANES_FN_LAMBDA {  // length2d
    const Lanes off = radial - rim_radius;
    return sqrt(height * height + off * off);
  };
  Lanes distance, scale, param0, param1;
  if constexpr (circle) {  // PointRoundAnswers::on_rim
    distance = from_rim(radius);
    scale = to_rim(radius);
    param0 = theta;
    param1 = Lanes::both(0);
  } else {  // PointRoundAnswers::over_disk
    const Lanes over = radial <= radius;
    const Lanes to_plane = Lanes::both(1) / norm2;
    distance = select(over, abs(height), from_rim(radius));
    scale = select(over, to_plane, to_rim(radius));
    param0 = select(over, radial, radius);
    param1 = theta;
  }
  if constexpr (ring) {  // PointRingQuery: the inner rim over the hole, param (inner, theta)
    distance = select(hole, from_rim(in.inner), distance);
    scale = select(hole, to_rim(in.inner), scale);
    param0 = select(hole, in.inner, param0);
  }
  // ranged_closest_points: a distance out of the moderate range is the scalar path's.
  constexpr double lowest = power_of_two<double>(std::numeric_limits<double>::min_exponent / 4);
  constexpr double highest = power_of_two<double>(std::numeric_limits<double>::max_exponent / 4);
  if (lanes_set((distance > Lanes::both(lowest)) & (distance < Lanes::both(highest))) != kAllLanes) return false;
  out.distance = distance;
  out.bx = in.cx + scale * qx;  // at()
  out.by = in.cy + scale * qy;
  out.bz = in.cz + scale * qz;
  out.param0 = param0;
  out.param1 = param1;
  return true;
}

#endif  // CIRCLEDIST_POINT_ROUND_LANES

}  // namespace circledist::detail
