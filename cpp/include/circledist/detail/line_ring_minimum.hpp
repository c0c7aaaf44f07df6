// A full line's minima over a ring, seen from the ring's side (docs/derivations/line_circle.md): the global
// one by one bracketed root of the secular equation (line_ring_minimum), the other local one
// inside the astroid (other_line_minimum), whether the global one is tied with its mirror image,
// and the Result of either. A line, ray or segment against a circle, or against a disk's rim,
// is answered from here wherever the direct method applies (linear_circle.hpp, linear_disk.hpp).
#pragma once

#include "linear.hpp"
#include "minimize.hpp"
#include "../primitives.hpp"
#include "round_target.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace circledist::detail {

// A full line against a circle, seen from the circle's side. With the line's unit direction m
// and its point a closest to the center (both relative to the center, a.m = 0), the squared
// distance from the ring point R z (z a unit vector of the circle's plane) to the line is
//   |R z - a|^2 - (R z.m)^2 = R^2 (s^2 z2^2 - 2 b.z) + const,   s^2 = |m_xy|^2, b = a_xy / R,
// in the plane's basis e1 = m_xy / s, e2 = n x e1: a quadratic minimized over the unit circle,
// a trust-region subproblem. Its global minimum (More and Sorensen) is
//   z = (b1 / mu, b2 / (mu + s^2))  at the root mu >= 0 of  b1^2 / mu^2 + b2^2 / (mu + s^2)^2 = 1,
// which lies in [max(|b1|, |b| - s^2), |b|] (|z1| <= 1, |z2| <= 1, |z| = 1) and is the only
// sign change there of the quartic (note 000's quartic seen from the circle)
//   P(mu) = (mu^2 - b1^2) (mu + s^2)^2 - b2^2 mu^2.
// So one bracketed root gives the answer: no isolation, no candidates, no polish. b1 = 0 with
// |b2| < s^2 is the "hard case" mu = 0: two mirror-image closest points (unique = false).
template <class Real> struct LineRingMinimum {
  Vec3<Real> ring_point, line_point;  // relative to the center
  Real distance = 0;
  Vec3<Real> mirror;  // the ring point reflected across the plane of e2 and n: the other minimum's
                      // neighbor when b1 is small (the two minima differ by 4 R^2 |b1 z1|)
  Vec3<Real> anchor, unit_direction, unit_normal;  // a, m and n
  bool on_axis = false;                            // a line along the axis: every ring point is closest
  // The secular equation's data, for the line's other local minimum (other_line_minimum): b1,
  // b2^2, s^2 (s2 = 0 for a line parallel to the axis to within eps, whose distance has one
  // minimum), and the anchor's in-plane parts along m_xy and across it.
  Real b1 = 0, b2_squared = 0, s2 = 0;
  Vec3<Real> a_parallel = Vec3<Real>::Zero(), a_across = Vec3<Real>::Zero();
};

// The line's point closest to ring point `ring_point` (relative to the center), and their
// distance, from the anchor a and unit direction m.
template <class Real> void complete_line_minimum(LineRingMinimum<Real>& out) {
  const Vec3<Real> offset = out.ring_point - out.anchor;
  out.distance = offset.cross(out.unit_direction).norm();
  out.line_point = out.anchor + offset.dot(out.unit_direction) * out.unit_direction;
}

// What line_ring_minimum did: declined (the line is too extreme for the direct method: a zero
// or huge direction, a zero radius, non-finite input; LinearCircleQuery then answers), solved
// the root, or stopped before it because the caller's `before_root` answered.
enum class LineRingOutcome { Declined, Solved, AnsweredBeforeRoot };

// `before_root(out)` is asked once the line's data are in `out` (anchor, unit direction and
// normal, on_axis, and the secular data b1, b2^2, s^2, a_parallel, a_across) and before the
// root, the query's main cost: a ray or segment that those data already answer (an end point,
// piece_round_query.hpp) returns true there and is spared the root.
template <class Roots, class Real, class BeforeRoot>
LineRingOutcome line_ring_minimum(const Line3<Real>& line, const Circle3<Real>& circle, LineRingMinimum<Real>& out,
                                  const BeforeRoot& before_root) {
  using Outcome = LineRingOutcome;
  const Real radius = circle.radius;
  const Real normal_length = circle.normal.norm();
  const Real d2 = line.direction.squaredNorm();
  // Far from overflow and underflow (accurate_cross needs its error terms above the subnormals):
  // within 2^(+-0.3 max_exponent), 2^+-307 in double, 2^+-38 in float.
  constexpr Real bound = detail::power_of_two<Real>(std::numeric_limits<Real>::max_exponent * 3 / 10);
  const auto moderate = [bound](Real x) { return x > 1 / bound && x < bound; };
  if (!(moderate(radius) && moderate(d2) && moderate(normal_length))) return Outcome::Declined;
  // Reciprocals once: a division per component would be most of the query's time.
  const Real inverse_normal = 1 / normal_length, inverse_length = 1 / std::sqrt(d2);
  const Vec3<Real> n = circle.normal * inverse_normal;
  // The anchor from w = o x d to one rounding per component (as LocalLinear): accurate relative
  // to its own length however far along the line the origin lies.
  const Vec3<Real> m = line.direction * inverse_length;
  const Vec3<Real> a =
      m.cross(offset_cross(ExactDifference<Real>(line.origin, circle.center), line.direction)) * inverse_length;
  if (!a.allFinite()) return Outcome::Declined;
  out.anchor = a;
  out.unit_direction = m;
  out.unit_normal = n;
  // m x n from the inputs to one rounding per component: for a line nearly along the axis,
  // m - (m.n) n would carry m's rounding, eps, into a tilt of size s, and tip the ring point
  // out of the plane by eps / s.
  const Vec3<Real> tilt = accurate_cross(line.direction, circle.normal) * (inverse_length * inverse_normal);
  const Vec3<Real> a_xy = a - a.dot(n) * n, m_xy = n.cross(tilt);
  const Real s2 = tilt.squaredNorm();  // |m_xy|^2 without 1 - (m.n)^2's cancellation
  Vec3<Real> direction;                // of the closest ring point
  if (!(s2 > std::numeric_limits<Real>::epsilon() * std::numeric_limits<Real>::epsilon())) {
    // Parallel to the axis (to a tilt below eps): the ring point toward the line.
    const Real rho = a_xy.norm();
    out.on_axis = rho <= 8 * std::numeric_limits<Real>::epsilon() * std::max(radius, a.norm());
    if (before_root(static_cast<const LineRingMinimum<Real>&>(out))) return Outcome::AnsweredBeforeRoot;
    direction = rho > 0 ? a_xy : Frame<Real>(circle.normal).u;  // angle 0 when all are closest
    out.mirror = out.ring_point = radius * direction / direction.norm();
  } else {
    // a_xy.m_xy = R s b1 is -(a.n)(m.n) because a.m = 0, and a.n = a.(n - (m.n) m) for the same
    // reason. Each form matters at one extreme. Taken directly, a_xy.m_xy would carry a.m's
    // rounding, eps |a|, which swamps it for a line nearly parallel to the plane and close to it
    // (and picks the wrong one of the two crossings). And for a line nearly along the axis, a.n
    // is of size |a| s while its rounding is eps |a|: at a tilt s near eps, b1 would be noise and
    // the closest ring point anywhere on the ring. n - (m.n) m = tilt x m comes from the
    // accurate tilt, to eps relative to its length s, so (tilt x m).a is accurate at both ends.
    const Real along = -a.dot(tilt.cross(m)) * m.dot(n);
    const Real inverse_s2 = 1 / s2;
    const Vec3<Real> a_parallel = (along * inverse_s2) * m_xy, a_across = a_xy - a_parallel;
    const Real s = std::sqrt(s2);
    // The secular root in double for float scenes: with s^2 and b1 both near float's eps, the
    // quartic's low coefficients b1^2 s^4 would fall below float's smallest normal.
    using Work = std::conditional_t<std::is_same<Real, float>::value, double, Real>;
    const Work inverse_radius = 1 / Work(radius), t2 = Work(s2);
    const Work b1 = Work(along) * inverse_radius / Work(s);
    const Work b2_squared = Work(a_across.squaredNorm()) * (inverse_radius * inverse_radius);
    out.b1 = Real(b1);
    out.b2_squared = Real(b2_squared);
    out.s2 = s2;
    out.a_parallel = a_parallel;
    out.a_across = a_across;
    if (before_root(static_cast<const LineRingMinimum<Real>&>(out))) return Outcome::AnsweredBeforeRoot;
    const Work b_norm = std::sqrt(b1 * b1 + b2_squared);
    const Work lo = std::max(std::abs(b1), b_norm - t2), hi = b_norm;
    const Work c[5] = {-b1 * b1 * t2 * t2, -2 * b1 * b1 * t2, (t2 - b_norm) * (t2 + b_norm), 2 * t2, 1};
    // With |b1| <= eps^2 the b1 = 0 minimizer (the hard-case formula below, which also covers
    // |b2| > s^2) is within 2 |b1| R^2 of the minimum squared distance, so within eps R of the
    // distance; solving instead would square b1 into the subnormals and lose the root.
    const Work eps = std::numeric_limits<Real>::epsilon();
    Real mu = 0;
    if (std::abs(b1) > eps * eps) {
      // P at the ends in closed form (with b^2 = b1^2 + b2^2): -b1^2 b2^2 at |b1|,
      // b1^2 (lo^2 - b^2) at b - s^2, b2^2 s^2 (2 b + s^2) at b.
      const Work p_lo = lo == std::abs(b1) ? -b1 * b1 * b2_squared : b1 * b1 * (lo - b_norm) * (lo + b_norm);
      const Work p_hi = b2_squared * t2 * (2 * b_norm + t2);
      mu = Real(hi > lo ? Roots::bracketed_root(c, 4, lo, hi, p_lo, p_hi) : lo);
    }
    if (mu > 0) {
      direction = a_parallel * (mu + s2) + a_across * mu;  // z = (b1 / mu, b2 / (mu + s^2)), scaled
    } else {
      // The hard case: z2 = b2 / s^2 across, the rest of the unit length along m_xy.
      const Vec3<Real> across = a_across * (inverse_s2 / radius);
      const Real rest = std::sqrt(std::max(Real(0), 1 - across.squaredNorm()));
      direction = across + (along < 0 ? -rest : rest) / s * m_xy;
    }
    const Real length = direction.norm();
    if (!(length > 0) || !std::isfinite(length)) return Outcome::Declined;
    out.ring_point = (radius / length) * direction;
    out.mirror = out.ring_point - (2 * out.ring_point.dot(m_xy) * inverse_s2) * m_xy;
  }
  complete_line_minimum(out);
  return Outcome::Solved;
}

// The full line's minimum alone (false: declined).
template <class Roots, class Real>
bool line_ring_minimum(const Line3<Real>& line, const Circle3<Real>& circle, LineRingMinimum<Real>& out) {
  const auto never = [](const LineRingMinimum<Real>&) { return false; };
  return line_ring_minimum<Roots>(line, circle, out, never) == LineRingOutcome::Solved;
}

// The line's other local minimum over the ring, besides the global one m. A ray or segment is
// closest at an end point or at a local minimum of the line's distance that it holds, and those
// are local minima over the ring of the distance to the line, the quadratic
// R^2 (s^2 z2^2 - 2 b.z) above. Besides the global minimum (mu >= 0) it has at most one more on
// the circle (Martinez 1994: the local-nonglobal minimizer of a trust-region subproblem), at the
// larger root mu in (-s^2, 0) of
//   phi(mu) = b1^2 / mu^2 + b2^2 / (mu + s^2)^2 - 1,
// which is convex there, least at mu0 = -s^2 / (1 + k), k = |b2 / b1|^(2/3), where
//   phi(mu0) = (|b1|^(2/3) + |b2|^(2/3))^3 / s^4 - 1.
// So it exists only inside the astroid |b1|^(2/3) + |b2|^(2/3) < s^(4/3) (the line passing over
// the circle's evolute, near the axis), as the root of the quartic P in (mu0, -|b1|), where
// P = -phi mu^2 (mu + s^2)^2 changes sign (P(mu0) > 0 > P(-|b1|) = -b1^2 b2^2).
// Returns 0 when there is none (`second` unset), 1 when `second` holds it, and -1 where the
// rounding of b1, b2 (absolute eps (|a| / R + 1)) and s leaves the astroid test open, or |b1|
// is too small to bracket the root (the mirror-image case): the general path answers those.
// A line parallel to the axis has the distance sqrt(z(t)^2 + const), convex: no second one.
//
// `may_hold(tau_max)` says whether the piece can hold the second minimum, which lies on the
// other side of the anchor from the global one: its ring point has z1 = b1 / mu of the sign of
// -b1 (mu < 0), and its line point is a + tau m with tau = R z.m = R s z1, so tau lies in
// (0, R s] times the sign of -b1. Where the piece does not reach there, the root is not solved
// (returns 2: a second minimum exists, off the piece).
// The first half, the astroid test, is second_minimum_test: it needs only the secular data, so a
// ray or segment asks it before the global root (a line with one local minimum falls toward it
// on either side, so an end point's slope can answer: choose_from_line, linear_circle.hpp); the
// second half, other_line_minimum, solves the root where the test found one.
template <class Real> struct SecondMinimumTest {
  using Work = std::conditional_t<std::is_same<Real, float>::value, double, Real>;
  int verdict = 0;          // 0: no second minimum; 1: one, in (mu0, -|b1|); -1: undecided (the general path)
  Work one_k = 0, rho = 0;  // 1 + k and rho, for the root (verdict 1)
};

template <class Real> SecondMinimumTest<Real> second_minimum_test(const LineRingMinimum<Real>& m, Real radius) {
  using Test = SecondMinimumTest<Real>;
  using Work = typename Test::Work;
  Test test;
  if (m.s2 == 0) {
    test.verdict = m.on_axis ? -1 : 0;
    return test;
  }
  const Work eps = std::numeric_limits<Real>::epsilon();
  const Work b1 = Work(m.b1), b1_squared = b1 * b1, b2_squared = Work(m.b2_squared), t2 = Work(m.s2);
  // b's rounding, 16 eps (|a| / R + 1), bounded without square roots (x^2 + 2 > x + 1).
  const Work a_over_r = Work(m.anchor.squaredNorm()) / (Work(radius) * Work(radius));
  const Work b_error = 16 * eps * (a_over_r + 2);
  // The astroid lies in the disk |b| <= s^2 (its cusps on the circle): outside it, no cube roots
  // (2 |b| <= |b|^2 + 1 bounds the rounding of |b|^2).
  const Work b_norm_squared = b1_squared + b2_squared;
  if (b_norm_squared - t2 * t2 > Work(1e-6) * t2 * t2 + 2 * (b_norm_squared + 1) * b_error) return test;
  test.verdict = -1;
  if (!(std::abs(b1) > std::sqrt(eps) * t2)) return test;
  // rho's margin (below): rho's rounding, and b's.
  const Work x = b_error / t2;
  const Work margin = 3 * std::max(Work(1e-6), 64 * eps) + 6 * (x < 1 ? std::sqrt(x) : x);
  // Clearly outside the astroid, without a cube root: with X = b1^2, Y = b2^2 and
  // v* = (|b1|^(2/3) + |b2|^(2/3))^3 (so that rho below is v* / s^4), h(v) = (v - X - Y)^3 - 27 v X Y
  // is negative at v = X + Y, convex beyond it, and 0 at v*: so v* > S exactly where S <= X + Y
  // or h(S) < 0. Asked at S = s^4 (1 + margin + 1e-3), in units of s^4 (X and Y at most about 1
  // here): a v* at or below s^4 (1 + margin) lies 1e-3 under S, where h(S) >= 1e-9, far above h's
  // rounding (a few eps); so this answers 0 only where the test on rho below would. (An X Y that
  // underflows to 0 only makes it answer less.)
  {
    const Work unit = 1 / (t2 * t2), x_n = b1_squared * unit, y_n = b2_squared * unit;
    const Work s_far = 1 + margin + Work(1e-3);
    const Work room = s_far - (x_n + y_n);
    if (!(room > 0) || room * room * room < 27 * s_far * x_n * y_n) {
      test.verdict = 0;
      return test;
    }
  }
  // With k = |b2 / b1|^(2/3) (one cube root): phi(mu0) + 1 = (1 + k)^3 b1^2 / s^4 =: rho and
  // mu0 = -s^2 / (1 + k). rho's rounding: b2's absolute error e moves |b2|^(2/3) by at most
  // 2 e^(2/3), so rho (whose cube root is about s^(4/3) where it matters) by at most
  // 6 (e / s^2)^(2/3) <= 6 max(sqrt(x), x), x = e / s^2.
  const Work k = std::cbrt(b2_squared / b1_squared), one_k = 1 + k;
  const Work rho = b1_squared * (one_k * one_k * one_k) / (t2 * t2);
  if (rho > 1 + margin) test.verdict = 0;
  if (rho < 1 - margin) {
    test.verdict = 1;
    test.one_k = one_k;
    test.rho = rho;
  }
  return test;
}

// `test`: second_minimum_test(m, radius), asked by the caller (once per query).
template <class Roots, class Real, class MayHold>
int other_line_minimum(const LineRingMinimum<Real>& m, Real radius, LineRingMinimum<Real>& second,
                       const MayHold& may_hold, const SecondMinimumTest<Real>& test) {
  if (test.verdict != 1) return test.verdict;
  using Work = typename SecondMinimumTest<Real>::Work;
  const Work eps = std::numeric_limits<Real>::epsilon();
  const Work b1 = Work(m.b1), b1_squared = b1 * b1, b2_squared = Work(m.b2_squared), t2 = Work(m.s2);
  const Work b_norm_squared = b1_squared + b2_squared, one_k = test.one_k, rho = test.rho;
  if (!may_hold(std::copysign(radius * std::sqrt(m.s2), -m.b1))) return 2;
  const Work mu0 = -t2 / one_k, hi = -std::abs(b1);
  if (!(mu0 < hi)) return -1;
  // -P, rising through the bracket as bracketed_root asks.
  const Work q_lo = (rho - 1) * (mu0 * mu0) * ((mu0 + t2) * (mu0 + t2));
  const Work q_hi = b1_squared * b2_squared;
  const Work c[5] = {b1_squared * t2 * t2, 2 * b1_squared * t2, b_norm_squared - t2 * t2, -2 * t2, -1};
  if (!(q_lo < 0)) return -1;
  Work root = Roots::bracketed_root(c, 4, mu0, hi, q_lo, q_hi);
  // A root of P need not be one of phi. Near mu = -s^2 the terms of P are of size s^8 while P
  // itself is (mu + s^2)^2 s^4 small: where b2 is within rounding of 0 (a line whose shadow on
  // the plane crosses the center), mu0 lies within (b2 / b1)^(2/3) s^2 of -s^2, and rounding makes
  // sign changes of P there that are none of phi's (an eigenvalue of the near-double root -s^2
  // lands in the bracket, or bisection follows the noise). phi has no such cancellation, so it
  // judges the root; where it is far from 0, Newton on phi from the bracket's right end finds the
  // root instead: phi is convex and rising on (mu0, 0) and phi(-|b1|) = b2^2 / (s^2 - |b1|)^2 >= 0,
  // so Newton from there falls monotonically to the root, never past it.
  const auto phi = [&](Work mu) {
    const Work x = b1 / mu, y = b2_squared / ((mu + t2) * (mu + t2));
    return x * x + y - 1;
  };
  if (!(std::abs(phi(root)) <= 64 * eps)) {
    root = hi;
    for (int step = 0; step < 200; ++step) {
      const Work value = phi(root);
      if (!(value > 0)) break;
      const Work slope =
          -2 * b1_squared / (root * root * root) - 2 * b2_squared / ((root + t2) * (root + t2) * (root + t2));
      const Work next = root - value / slope;
      if (!(next < root && next > mu0)) break;
      root = next;
    }
  }
  const Real mu = Real(root);
  // z = (b1 / mu, b2 / (mu + s^2)), scaled by mu (mu + s^2) < 0: hence the sign.
  // a_across carries a's rounding, eps |a|, out of the plane, and this minimum exists only for a
  // line near the axis (|a_xy| within R s^2), so that rounding can be large beside the direction
  // itself for a line far above the plane: the direction is taken back into the plane (to its own
  // rounding), as the ring point must lie there.
  Vec3<Real> direction = -(m.a_parallel * (mu + m.s2) + m.a_across * mu);
  direction -= direction.dot(m.unit_normal) * m.unit_normal;
  const Real length = direction.norm();
  if (!(length > 0) || !std::isfinite(length)) return -1;
  second = m;
  second.ring_point = (radius / length) * direction;
  second.mirror = second.ring_point;  // the global minimum's mirror is not this one's
  complete_line_minimum(second);
  return 1;
}

// Whether the line's ring minimum m is tied with its mirror image (b1 near 0): which of the two
// lies on a piece, and whether a piece's closest pair is unique, is then the general path's call.
template <class Real> bool tied_with_mirror(const Circle3<Real>& c, const LineRingMinimum<Real>& m) {
  if (m.on_axis) return false;
  const Real scale = std::max(c.radius, m.anchor.norm());
  const Real mirror_distance = (m.mirror - m.anchor).cross(m.unit_direction).norm();
  return mirror_distance <= m.distance + tie_tolerance(std::max(scale, m.distance));
}

// The parameter on `line` of its `point` (relative to `center`): for a ray or segment, the piece's
// own parametrization.
template <class Real> Real line_param(const Line3<Real>& line, const Vec3<Real>& center, const Vec3<Real>& point) {
  return (point - (line.origin - center)).dot(line.direction) / line.direction.squaredNorm();
}

// The closest points of a line's minimum over the ring (line_ring_minimum). `line` is the full
// line through the piece (for a ray or a segment, the piece's own parametrization: t = param).
template <class Real>
Result<Real> line_ring_result(const Line3<Real>& line, const Circle3<Real>& c, const LineRingMinimum<Real>& m) {
  Result<Real> r;
  r.distance = m.distance;
  r.point_a = c.center + m.line_point;
  r.point_b = c.center + m.ring_point;
  r.param_a = Vec2<Real>(line_param(line, c.center, m.line_point), 0);
  const Frame<Real> frame(c.normal);
  r.param_b = RingTarget<Real>::param(frame.to_local(m.ring_point));
  // Another pair at the same distance within rounding: the whole ring (a line on the axis), the
  // mirror-image minimum when b1 is (nearly) zero (the mirror point bounds it from above), or
  // a distance flat to rounding over the ring (a line within rounding of the center's axis).
  const Real scale = std::max(c.radius, m.anchor.norm());
  r.unique =
      !m.on_axis && !(tied_with_mirror(c, m) && (m.mirror - m.ring_point).norm() > distinct_points_tolerance(scale));
  return r;
}

}  // namespace circledist::detail
