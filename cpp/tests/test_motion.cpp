// Rigid motions (motion.hpp): the rotation R(w) against the quaternion formula and exact quarter
// turns, moved shapes (radii, angles and sweeps kept; a point of a shape moves onto the moved
// shape at the same parameter), reach() against sampled points, first_contact() against
// analytic contact times and a dense-sampling-plus-bisection reference, the evaluation limit of
// both queries, and closest_approach() against analytic least distances and a dense-sampling-
// plus-golden-section reference (many near-equal dips included).
#include <circledist/closest_approach.hpp>
#include <circledist/motion.hpp>

#include "check.hpp"
#include "random.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace test_motion {

using namespace circledist;

namespace {

using V = Vec3<double>;
using M = Mat3<double>;
using Motion = Motion3<double>;
test_random::Random source(20261129);
const double pi = pi_v<double>();
const double inf = std::numeric_limits<double>::infinity();

// The rotation by |w| about w / |w| from the unit quaternion q = (cos(theta / 2), sin(theta / 2) k),
// as I + 2 q_w [q]x + 2 [q]x^2: an independent formula, and one whose R - I keeps its digits at
// tiny angles (no 1 - cos). Returns R - I.
M quaternion_rotation_minus_identity(const V& w) {
  const double theta = w.stableNorm();  // no underflow for the tiniest rotations
  if (theta == 0) return M::Zero();
  const V q = std::sin(theta / 2) * (w / theta);
  const double qw = std::cos(theta / 2);
  M cross;
  cross << 0, -q.z(), q.y(), q.z(), 0, -q.x(), -q.y(), q.x(), 0;
  return 2 * qw * cross + 2 * cross * cross;
}

// A quarter turn about axis i (exact integer entries).
M quarter_turn(int axis) {
  M r = M::Zero();
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;
  r(axis, axis) = 1;
  r(k, j) = 1;   // e_j -> e_k
  r(j, k) = -1;  // e_k -> -e_j
  return r;
}

void rotations() {
  // Quarter turns composed: R(n pi/2 e_i) = Q_i^n, up to n = 9 (two full turns and a quarter).
  for (int axis = 0; axis < 3; ++axis) {
    M power = M::Identity();
    for (int n = 0; n <= 9; ++n) {
      V w = V::Zero();
      w(axis) = n * pi / 2;
      CHECK((rotation_matrix(w) - power).cwiseAbs().maxCoeff() <= 4e-16 * (n + 1));
      power = quarter_turn(axis) * power;
    }
  }
  // Right-handed: a quarter turn about z takes x to y.
  CHECK((rotation_matrix(V(0, 0, pi / 2)) * V(1, 0, 0) - V(0, 1, 0)).norm() <= 1e-16);
  // Random axes and angles (up to ten turns) against the quaternion formula; orthonormal, det 1.
  for (int i = 0; i < 200; ++i) {
    const V w = source.direction().normalized() * source.uniform(0, 20 * pi);
    const M r = rotation_matrix(w);
    // The angle |w| itself carries a rounding of eps |w|.
    const double tol = 2e-15 + 4 * std::numeric_limits<double>::epsilon() * w.norm();
    CHECK(((r - M::Identity()) - quaternion_rotation_minus_identity(w)).cwiseAbs().maxCoeff() <= tol);
    CHECK((r.transpose() * r - M::Identity()).cwiseAbs().maxCoeff() <= 1e-15);
    CHECK(std::abs(r.determinant() - 1) <= 1e-15);
  }
  // Tiny angles: R - I relative to the angle, where a 1 - cos form would lose every digit.
  for (const double scale : {1e-5, 1e-9, 1e-20, 1e-200, 1e-310}) {
    const V w = source.direction().normalized() * scale;
    const M r = rotation_matrix(w);
    const M minus = quaternion_rotation_minus_identity(w);
    // Off the diagonal R - I is the cross-product matrix of w to first order: compare it relative to |w|.
    M off = r - minus;
    off.diagonal().setZero();
    const double subnormal = 8 * std::numeric_limits<double>::denorm_min();
    CHECK(off.cwiseAbs().maxCoeff() <= 2e-15 * scale + subnormal);
    CHECK(std::abs(r(1, 0) - w.z()) <= 2e-15 * scale + scale * scale + subnormal);
    CHECK(!r.hasNaN());
  }
  // Many turns: the same rotation as the angle less whole turns, to the rounding of the angle.
  for (const int turns : {1, 10, 1000, 1000000}) {
    const V k = source.direction().normalized();
    const double alpha = source.uniform(0, 2 * pi);
    const double theta = alpha + 2 * pi * turns;
    const M r = rotation_matrix(V(theta * k)), reduced = rotation_matrix(V(alpha * k));
    CHECK((r - reduced).cwiseAbs().maxCoeff() <= 8 * std::numeric_limits<double>::epsilon() * theta);
    CHECK((r.transpose() * r - M::Identity()).cwiseAbs().maxCoeff() <= 1e-15);
  }
  // Huge rotation vectors stay finite and orthonormal; a zero one is the identity exactly.
  const M huge = rotation_matrix(V(3e200, -1e200, 2e200));
  CHECK(!huge.hasNaN() && (huge.transpose() * huge - M::Identity()).cwiseAbs().maxCoeff() <= 1e-15);
  CHECK(rotation_matrix(V(0, 0, 0)) == M::Identity());
  CHECK(rotation_matrix(V(inf, 0, 0)).hasNaN());
}

Motion random_motion() {
  Motion m;
  m.translation = source.vector(3);
  m.rotation = source.direction().normalized() * source.uniform(0, 6 * pi);
  m.center = source.vector(2);
  return m;
}

// The point x moved by m at t, from the quaternion rotation (independent of placement()).
V moved_point_reference(const V& x, const Motion& m, double t) {
  const V w = t * m.rotation;
  return m.center + (x - m.center) + quaternion_rotation_minus_identity(w) * (x - m.center) + t * m.translation;
}

Arc3<double> random_arc(double spread) {
  const Circle3<double> c = source.circle(spread);
  return {c.center, c.normal, c.radius, source.direction(), source.uniform(0.1, 2 * pi)};
}
Annulus3<double> random_annulus(double spread) {
  const Disk3<double> d = source.disk(spread);
  return {d.center, d.normal, d.radius * source.uniform(0.1, 0.9), d.radius};
}

// Points of the shapes by their parameters (the definitions in primitives.hpp).
V circle_point(const V& center, const V& normal, double s, double theta) {
  const Frame<double> f(normal);
  return center + s * (std::cos(theta) * f.u + std::sin(theta) * f.v);
}
V arc_point(const Arc3<double>& a, double t) {
  const detail::ArcSpan<double> span(a);
  return span.world(a.center, a.radius, span.lo() + t);
}

void moved_shapes() {
  for (int i = 0; i < 100; ++i) {
    const Motion m = random_motion();
    const double t = source.uniform(0, 1);
    const double tol = 1e-14 * 20;  // coordinates up to ~20 here
    // Points move as the reference moves them.
    const V p = source.vector(2);
    CHECK((moved(p, m, t) - moved_point_reference(p, m, t)).norm() <= tol);
    // Lines, rays, segments and curves: the point at parameter s moves to the moved shape's point
    // at s.
    const double s = source.uniform(-2, 2);
    const Line3<double> line = source.line(2);
    const Line3<double> ml = moved(line, m, t);
    CHECK((ml.origin + s * ml.direction - moved_point_reference(V(line.origin + s * line.direction), m, t)).norm() <=
          tol);
    CHECK(std::abs(ml.direction.norm() - line.direction.norm()) <= 1e-15 * line.direction.norm());
    const Ray3<double> ray{line.origin, line.direction};
    const Ray3<double> mr = moved(ray, m, t);
    CHECK(mr.origin == ml.origin && mr.direction == ml.direction);
    const Segment3<double> seg = source.segment(2);
    const Segment3<double> ms = moved(seg, m, t);
    const double u = source.uniform(0, 1);
    CHECK((ms.p0 + u * (ms.p1 - ms.p0) - moved_point_reference(V(seg.p0 + u * (seg.p1 - seg.p0)), m, t)).norm() <= tol);
    const BezierCurve3<double> curve = source.bezier(2);
    const BezierCurve3<double> mc = moved(curve, m, t);
    CHECK(mc.degree() == curve.degree());
    CHECK((mc.at(u) - moved_point_reference(curve.at(u), m, t)).norm() <= tol);
    // Circles, disks, annuli: radii kept to the bit; a point of the shape lies on the moved shape.
    const Circle3<double> circle = source.circle(2);
    const Circle3<double> mcirc = moved(circle, m, t);
    CHECK(mcirc.radius == circle.radius);
    const double theta = source.uniform(-pi, pi);
    CHECK(distance(moved_point_reference(circle_point(circle.center, circle.normal, circle.radius, theta), m, t),
                   mcirc) <= tol);
    const Disk3<double> disk = source.disk(2);
    const Disk3<double> md = moved(disk, m, t);
    CHECK(md.radius == disk.radius);
    const V inside = circle_point(disk.center, disk.normal, disk.radius * u, theta);
    CHECK(distance(moved_point_reference(inside, m, t), md) <= tol);
    const Annulus3<double> ring = random_annulus(2);
    const Annulus3<double> mring = moved(ring, m, t);
    CHECK(mring.inner_radius == ring.inner_radius && mring.outer_radius == ring.outer_radius);
    const V on_ring =
        circle_point(ring.center, ring.normal, ring.inner_radius + u * (ring.outer_radius - ring.inner_radius), theta);
    CHECK(distance(moved_point_reference(on_ring, m, t), mring) <= tol);
    // Arcs: radius and angle kept; the point at the arc's parameter t moves to the moved arc's
    // point at the same parameter (the start rotates with the arc).
    const Arc3<double> arc = random_arc(2);
    const Arc3<double> marc = moved(arc, m, t);
    CHECK(marc.radius == arc.radius && marc.angle == arc.angle);
    const double along = u * arc.angle;
    CHECK((arc_point(marc, along) - moved_point_reference(arc_point(arc, along), m, t)).norm() <= tol);
    // Sweeps kept, cores moved.
    const auto swept_circle = swept(circle, 0.3);
    const auto msw = moved(swept_circle, m, t);
    CHECK(msw.sweep == 0.3 && msw.shape.center == mcirc.center && msw.shape.normal == mcirc.normal);
  }
  // An arc whose start leans out of its plane, or lies along its normal (no projection: it starts
  // at the frame's U), keeps its start point through rotations of any axis.
  for (int i = 0; i < 50; ++i) {
    const Motion m = random_motion();
    const double t = source.uniform(0, 1);
    const Circle3<double> c = source.circle(1);
    const Frame<double> f(c.normal);
    for (const V& start : {V(f.n), V(3 * f.n + 1e-3 * f.v), V(V::Zero()), V(1e-200 * f.u + 1e-200 * f.v)}) {
      const Arc3<double> arc{c.center, c.normal, c.radius, start, 1.0};
      for (const double along : {0.0, 0.5, 1.0}) {
        CHECK((arc_point(moved(arc, m, t), along) - moved_point_reference(arc_point(arc, along), m, t)).norm() <=
              1e-13);
      }
    }
  }
  // At rest: every point where it was (the center subtracted and added back: to rounding).
  const Circle3<double> c{V(1, 2, 3), V(0, 1, 1), 0.5};
  const Circle3<double> still = moved(c, Motion{}, 0.7);
  CHECK(still.center == c.center && still.normal == c.normal && still.radius == c.radius);
  // Directions of any length rotate without overflow.
  const Line3<double> long_line{V(0, 0, 0), V(1e300, 1e300, 0)};
  const Line3<double> turned = moved(long_line, Motion{V::Zero(), V(0, 0, pi / 2), V::Zero()}, 1.0);
  CHECK(std::abs(turned.direction.x() + 1e300) <= 1e285 && std::abs(turned.direction.y() - 1e300) <= 1e285);
}

// Sampled points of each shape.
template <class F> double sampled_reach(const V& c, int n, const F& point) {
  double out = 0;
  for (int i = 0; i <= n; ++i) out = std::max(out, (point(double(i) / n) - c).norm());
  return out;
}

void reaches() {
  for (int i = 0; i < 60; ++i) {
    const V c = source.vector(3);
    const int n = 2000;
    const auto check_reach = [&](double bound, double sampled, bool tight) {
      CHECK(sampled <= bound * (1 + 1e-14));
      if (tight) CHECK(sampled >= bound * (1 - 1e-5));
    };
    const V p = source.vector(2);
    CHECK(reach(p, c) == (p - c).norm());
    const Segment3<double> seg = source.segment(2);
    check_reach(reach(seg, c), sampled_reach(c, n, [&](double u) { return V(seg.p0 + u * (seg.p1 - seg.p0)); }), true);
    const Circle3<double> circle = source.circle(2);
    check_reach(
        reach(circle, c),
        sampled_reach(c, n,
                      [&](double u) { return circle_point(circle.center, circle.normal, circle.radius, 2 * pi * u); }),
        true);
    const Disk3<double> disk = source.disk(2);
    // The disk sampled on a grid of radii and angles.
    double disk_sampled = 0;
    for (int j = 0; j <= 20; ++j)
      disk_sampled = std::max(disk_sampled, sampled_reach(c, n, [&](double u) {
                                return circle_point(disk.center, disk.normal, disk.radius * j / 20, 2 * pi * u);
                              }));
    check_reach(reach(disk, c), disk_sampled, true);
    const Annulus3<double> ring = random_annulus(2);
    check_reach(
        reach(ring, c),
        sampled_reach(c, n,
                      [&](double u) { return circle_point(ring.center, ring.normal, ring.outer_radius, 2 * pi * u); }),
        true);
    const Arc3<double> arc = random_arc(2);
    check_reach(reach(arc, c), sampled_reach(c, n, [&](double u) { return arc_point(arc, u * arc.angle); }), false);
    const BezierCurve3<double> curve = source.bezier(2);
    check_reach(reach(curve, c), sampled_reach(c, n, [&](double u) { return curve.at(u); }), false);
    CHECK(reach(swept(circle, 0.25), c) == reach(circle, c) + 0.25);
  }
  CHECK(reach(source.line(1), V(0, 0, 0)) == inf);
  CHECK(reach(Ray3<double>{V(0, 0, 0), V(1, 0, 0)}, V(0, 0, 0)) == inf);
  CHECK(reach(BezierCurve3<double>{}, V(1, 1, 1)) == 0);
}

// The analytic cases: |t - expected| within the bar's width in time, delta / |slope| (the
// distance crosses `within` at `slope` per unit time), and the reported distance within delta.
template <class A, class B> void check_contact(const A& a, const B& b, const Motion& ma, const Motion& mb,
                                               double within, double expected, double slope) {
  const Contact<double> c = first_contact(a, b, ma, mb, within);
  const double size = std::max(detail::motion_size(a, ma), detail::motion_size(b, mb));
  const double delta = contact_tolerance(size);
  CHECK(std::abs(c.time - expected) <= delta / slope + 4e-16);
  CHECK(std::abs(c.distance - within) <= delta);
  CHECK(std::abs((c.point_a - c.point_b).norm() - c.distance) <= 1e-12 * size);
  // The points lie on the shapes at that time.
  CHECK(distance(c.point_a, moved(a, ma, c.time)) <= 1e-12 * size);
  CHECK(distance(c.point_b, moved(b, mb, c.time)) <= 1e-12 * size);
  CHECK(c.evaluations > 0 && c.evaluations < 10000);
}

void analytic_contacts() {
  const Circle3<double> unit{V(0, 0, 0), V(0, 0, 1), 1.0};
  // The size S of the bar: coordinates and radii at both ends, travel, and a rotating shape's swing.
  CHECK(detail::motion_size(V(-5, 0, 0.3), Motion{V(10, 0, 0)}) == 10);
  CHECK(detail::motion_size(unit, Motion{V::Zero(), V(pi, 0, 0)}) == 1);
  CHECK(detail::motion_size(swept(unit, 0.5), Motion{V::Zero(), V(pi, 0, 0), V(3, 0, 0)}) == 3 + 4.5);
  // A point moving straight at a circle, 0.3 off its plane: distance sqrt((|x| - 1)^2 + 0.09),
  // 0.5 at |x| = 1.4, x = -5 + 10 t: t = 0.36, where the distance falls at 8 per unit time.
  check_contact(V(-5, 0, 0.3), unit, Motion{V(10, 0, 0)}, Motion{}, 0.5, 0.36, 8.0);
  // The same from the circle's side (the circle moves, the point stays).
  check_contact(unit, V(-5, 0, 0.3), Motion{V(-10, 0, 0)}, Motion{}, 0.5, 0.36, 8.0);
  // A ring turning about a diameter (the x axis) through a point of its sphere, at angle alpha
  // from its plane: it passes through the point at the one instant t = alpha / pi, the distance
  // falling at pi to 0 and rising again.
  for (const double alpha : {0.3, 1.0, 2.5}) {
    const V p(0, std::cos(alpha), std::sin(alpha));
    check_contact(unit, p, Motion{V::Zero(), V(pi, 0, 0)}, Motion{}, 0.0, alpha / pi, pi);
    // Many turns: 20 turns over [0, 1], the first pass at alpha / (40 pi).
    check_contact(unit, p, Motion{V::Zero(), V(40 * pi, 0, 0)}, Motion{}, 0.0, alpha / (40 * pi), 40 * pi);
  }
  // A clock hand (a segment from the center) turning twice about z through a point at radius 0.5
  // and angle beta; the center of rotation off the origin, everything shifted by 1e6 (a far scene).
  for (const V& shift : {V(0, 0, 0), V(1e6, -1e6, 1e6)}) {
    const double beta = 2.0;
    const Segment3<double> hand{shift, V(shift + V(1, 0, 0))};
    const V p = shift + 0.5 * V(std::cos(beta), std::sin(beta), 0);
    check_contact(hand, p, Motion{V::Zero(), V(0, 0, 4 * pi), shift}, Motion{}, 0.0, beta / (4 * pi), 4 * pi * 0.5);
  }
  // A brief contact: a point flying at 2000 per unit time through a disk of radius 1e-3 (facing
  // it) 0.9e-3 off its center: in contact at one instant only, which no sampling would find.
  {
    const Disk3<double> small{V(0, 0, 0), V(1, 0, 0), 1e-3};
    const double x0 = -1e3 + 0.123;
    check_contact(V(x0, 0.9e-3, 0), small, Motion{V(2e3, 0, 0)}, Motion{}, 0.0, -x0 / 2e3, 2e3);
  }
  // A line translating onto a circle (translation of unbounded shapes is fine): x = -3 + 6 t
  // reaches the circle at x = -1, t = 1/3.
  const Line3<double> line{V(-3, 0, 0), V(0, 1, 0)};
  check_contact(line, unit, Motion{V(6, 0, 0)}, Motion{}, 0.0, 1.0 / 3, 6.0);
  // Swept shapes: a ball of radius 0.2 at the same point: contact 0.2 earlier in distance.
  check_contact(swept(V(-5, 0, 0.3), 0.2), unit, Motion{V(10, 0, 0)}, Motion{}, 0.3, 0.36, 8.0);

  // float and long double: the same contact, to their bars (64 eps S in float, 1e-12 S).
  {
    using F = Vec3<float>;
    const Contact<float> c = first_contact(F(-5, 0, 0.3f), Circle3<float>{F(0, 0, 0), F(0, 0, 1), 1.0f},
                                           Motion3<float>{F(10, 0, 0)}, Motion3<float>{}, 0.5f);
    CHECK(std::abs(double(c.time) - 0.36) <= double(contact_tolerance(10.0f)) / 8 + 1e-7);
    using L = Vec3<long double>;
    const Contact<long double> w = first_contact(L(-5, 0, 0.3L), Circle3<long double>{L(0, 0, 0), L(0, 0, 1), 1.0L},
                                                 Motion3<long double>{L(10, 0, 0)}, Motion3<long double>{}, 0.5L);
    CHECK(std::abs(w.time - 0.36L) <= contact_tolerance(10.0L) / 8 + 1e-18L);
  }
  // Already within at t = 0: time 0.
  const Contact<double> now = first_contact(V(1, 0, 0.1), unit, Motion{V(5, 0, 0)}, Motion{}, 0.2);
  CHECK(now.time == 0 && now.evaluations == 1);
  // Never: a point passing 0.5 above the circle with within 0.4: +inf, NaN points.
  const Contact<double> never = first_contact(V(-5, 0, 0.5), unit, Motion{V(10, 0, 0)}, Motion{}, 0.4);
  CHECK(never.time == inf && std::isnan(never.distance) && never.point_a.hasNaN() && never.param_b.hasNaN());
  // A ring turning about its own axis never changes: a point 0.5 off it is never reached (and
  // the advancement takes steps of 0.5 / (4 pi)).
  const Contact<double> spin = first_contact(unit, V(1.5, 0, 0), Motion{V::Zero(), V(0, 0, 4 * pi)}, Motion{}, 0.0);
  CHECK(spin.time == inf && spin.evaluations <= 30);
  // Both at rest, apart: one evaluation, never.
  const Contact<double> rest = first_contact(unit, V(3, 0, 0), Motion{}, Motion{}, 0.0);
  CHECK(rest.time == inf && rest.evaluations == 1);
  // Moving together (the same translation): the distance cannot change.
  const Contact<double> together = first_contact(unit, V(3, 0, 0), Motion{V(1, 2, 3)}, Motion{V(1, 2, 3)}, 0.0);
  CHECK(together.time == inf && together.evaluations == 1);
  // A tangential near miss: a point passing 1e-6 outside the circle, in its plane (the distance
  // falls quadratically to 1e-6): no contact, in a few thousand steps (about pi sqrt(r / gap)).
  const Contact<double> graze = first_contact(V(-5, 1 + 1e-6, 0), unit, Motion{V(10, 0, 0)}, Motion{}, 0.0);
  CHECK(graze.time == inf && graze.evaluations < 20000);
  // ... a tangency with within = 1e-9: the distance x^2 / 2 + O(x^4) reaches it at
  // x = -sqrt(2e-9), falling at 10 sqrt(2e-9) per unit time there ...
  const double delta = contact_tolerance(10.0);
  const Contact<double> tangent = first_contact(V(-5, 1, 0), unit, Motion{V(10, 0, 0)}, Motion{}, 1e-9);
  CHECK(std::abs(tangent.time - (0.5 - std::sqrt(2e-9) / 10)) <= delta / (10 * std::sqrt(2e-9)));
  CHECK(std::abs(tangent.distance - 1e-9) <= delta);
  // ... and the exact tangency (within 0, the distance touching 0 at t = 0.5 only): reached where
  // the distance is delta / 2, x = -sqrt(delta), in about 2 sqrt(r / delta) = 6e5 steps.
  const Contact<double> touch = first_contact(V(-5, 1, 0), unit, Motion{V(10, 0, 0)}, Motion{}, 0.0);
  CHECK(touch.time <= 0.5 && touch.time >= 0.5 - 1.01 * std::sqrt(delta) / 10);
  CHECK(touch.distance <= delta);
  CHECK(touch.evaluations < 1000000);
  // NaN in, NaN out; a rotating line refused, a translating one fine.
  CHECK(std::isnan(first_contact(V(0, 0, std::nan("")), unit, Motion{}, Motion{}, 0.0).time));
  CHECK(std::isnan(first_contact(V(5, 0, 0), unit, Motion{V(std::nan(""), 0, 0)}, Motion{}, 0.0).time));
  bool refused = false;
  try {
    first_contact(line, unit, Motion{V::Zero(), V(0, 0, 1)}, Motion{}, 0.0);
  } catch (const std::invalid_argument&) {
    refused = true;
  }
  CHECK(refused);
  refused = false;
  try {
    first_contact(unit, Ray3<double>{V(0, 0, 0), V(1, 0, 0)}, Motion{}, Motion{V::Zero(), V(0, 1, 0)}, 0.0);
  } catch (const std::invalid_argument&) {
    refused = true;
  }
  CHECK(refused);
}

// The reference: d(t) sampled at n + 1 times, the first sample with d <= within, and the time of
// the crossing bisected between it and the sample before (to the last bit of t). Returns +inf
// when no sample is within.
template <class A, class B> double sampled_first_contact(const A& a, const B& b, const Motion& ma, const Motion& mb,
                                                         double within, int n, std::vector<double>& samples) {
  const auto gap = [&](double t) { return distance(moved(a, ma, t), moved(b, mb, t)) - within; };
  samples.assign(n + 1, 0);
  for (int i = 0; i <= n; ++i) samples[i] = gap(double(i) / n);
  for (int i = 0; i <= n; ++i) {
    if (samples[i] > 0) continue;
    if (i == 0) return 0;
    double lo = double(i - 1) / n, hi = double(i) / n;
    while (true) {
      const double mid = lo + (hi - lo) / 2;
      if (mid <= lo || mid >= hi) break;
      (gap(mid) > 0 ? lo : hi) = mid;
    }
    return hi;
  }
  return inf;
}

template <class A, class B> void check_against_sampling(const A& a, const B& b, int& crossings) {
  const Motion ma = random_motion(), mb = random_motion();
  const int n = 400;
  std::vector<double> samples;
  sampled_first_contact(a, b, ma, mb, 0.0, n, samples);
  // within between the least and the largest sampled distance: a crossing, mostly.
  const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
  const double within = std::max(0.0, *lo + source.uniform(-0.1, 0.6) * (*hi - *lo));
  const double reference = sampled_first_contact(a, b, ma, mb, within, n, samples);
  const Contact<double> c = first_contact(a, b, ma, mb, within);
  const double size = std::max(detail::motion_size(a, ma), detail::motion_size(b, mb));
  const double delta = contact_tolerance(size);
  // Never a missed contact: no sampled time before the reported one comes within - delta.
  for (int i = 0; i <= n && double(i) / n < c.time; ++i) CHECK(samples[i] + within >= within - delta);
  if (c.time < inf) {
    // A real contact: within + delta at the time reported (a fresh evaluation).
    CHECK(distance(moved(a, ma, c.time), moved(b, mb, c.time)) <= within + delta);
    CHECK(c.distance <= within + delta);
  }
  if (reference < inf) {
    ++crossings;
    // Not later than the sampled crossing, beyond the bar's width in time there (the slope of
    // the distance at the crossing, by a difference over 1e-6).
    const double h = 1e-6;
    const double t0 = std::max(0.0, reference - h);
    const double slope =
        (distance(moved(a, ma, t0), moved(b, mb, t0)) - distance(moved(a, ma, reference), moved(b, mb, reference))) /
        (reference - t0 > 0 ? reference - t0 : 1.0);
    CHECK(c.time <= reference + (slope > 0 ? 2 * delta / slope : 1e-3) + 1e-15);
  } else {
    // No sample within: the advancement agrees (never) or found a contact between samples.
    CHECK(c.time == inf || distance(moved(a, ma, c.time), moved(b, mb, c.time)) <= within + delta);
  }
}

void random_contacts() {
  int crossings = 0, cases = 0;
  for (int i = 0; i < check::scaled(8); ++i) {
    check_against_sampling(source.vector(2), source.circle(2), crossings);
    check_against_sampling(source.segment(2), source.disk(2), crossings);
    check_against_sampling(source.circle(2), source.circle(2), crossings);
    check_against_sampling(random_arc(2), source.segment(2), crossings);
    check_against_sampling(swept(source.segment(2), 0.1), random_annulus(2), crossings);
    check_against_sampling(source.bezier(2), source.circle(2), crossings);
    cases += 6;
  }
  // Most cases cross (the check above is not vacuous).
  CHECK(crossings >= cases / 2);
}

// The analytic least distances: value to the bar, the time to the bar's width in time.
template <class A, class B> Approach<double> check_approach(const A& a, const B& b, const Motion& ma, const Motion& mb,
                                                            double expected, bool unique) {
  const Approach<double> c = closest_approach(a, b, ma, mb);
  const double size = std::max(detail::motion_size(a, ma), detail::motion_size(b, mb));
  const double delta = contact_tolerance(size);
  CHECK(std::abs(c.distance - expected) <= delta);
  CHECK(c.unique == unique);
  CHECK(c.time >= 0 && c.time <= 1);
  // The points lie on the shapes at that time, as far apart as the distance.
  CHECK(distance(c.point_a, moved(a, ma, c.time)) <= delta);
  CHECK(distance(c.point_b, moved(b, mb, c.time)) <= delta);
  CHECK(std::abs((c.point_a - c.point_b).norm() - c.distance) <= delta);
  CHECK(c.distance == distance(moved(a, ma, c.time), moved(b, mb, c.time)));
  return c;
}

void analytic_approaches() {
  const Circle3<double> unit{V(0, 0, 0), V(0, 0, 1), 1.0};
  // A point passing over the ring, 2 off its axis and 1 above: least sqrt(2) at t = 0.5.
  const Approach<double> over = check_approach(V(-3, 2, 1), unit, Motion{V(6, 0, 0)}, Motion{}, std::sqrt(2.0), true);
  CHECK(std::abs(over.time - 0.5) <= 1e-6);
  // 0.5 off the axis and 2 above: the least 2 twice, where the point is over the rim (x = -+sqrt(0.75)).
  const Approach<double> twice = check_approach(V(-3, 0.5, 2), unit, Motion{V(6, 0, 0)}, Motion{}, 2.0, false);
  CHECK(std::min(std::abs(twice.time - (3 - std::sqrt(0.75)) / 6), std::abs(twice.time - (3 + std::sqrt(0.75)) / 6)) <=
        1e-6);
  // The least at the start (moving away) and at the end (coming closer).
  CHECK(check_approach(V(2, 0, 0), unit, Motion{V(3, 1, 0)}, Motion{}, 1.0, true).time == 0);
  CHECK(check_approach(V(5, 0, 0), unit, Motion{V(-2, 0, 1)}, Motion{}, std::sqrt(5.0), true).time == 1);
  // A tangential graze: a point along a tangent of the ring touches it at t = 0.5 only.
  const Approach<double> graze = check_approach(V(-5, 1, 0), unit, Motion{V(10, 0, 0)}, Motion{}, 0.0, true);
  CHECK(std::abs(graze.time - 0.5) <= 1e-6);
  // Spinning about its own axis: at rest relative to the point (time 0, not unique).
  const Approach<double> spin =
      check_approach(unit, V(2.5, 0, 0), Motion{V::Zero(), V(0, 0, 8 * pi)}, Motion{}, 1.5, false);
  CHECK(spin.time == 0 && spin.evaluations == 1);
  // The same motion for both: at rest relative to each other.
  const Motion both{V(1, 2, 3), V(0.4, 2, -1), V(0.5, 0, 0)};
  CHECK(check_approach(unit, V(0, 3, 0), both, both, 2.0, false).evaluations == 1);
  // A point at the center of a ring tumbling about a diameter: the distance 1 at every time.
  check_approach(unit, V(0, 0, 0), Motion{V::Zero(), V(2 * pi, 0, 0)}, Motion{}, 1.0, false);
  // Coaxial rings (every rim point at once): the smaller one rising past the larger's plane to
  // 0.5 below... least where they are level, sqrt((1 - 0.5)^2) = 0.5, at t = 0.5.
  const Circle3<double> small{V(0, 0, -1), V(0, 0, 1), 0.5};
  const Approach<double> coaxial = check_approach(small, unit, Motion{V(0, 0, 2)}, Motion{}, 0.5, false);
  CHECK(std::abs(coaxial.time - 0.5) <= 1e-6);
  // A ring of radius 0.3 through the hole of an annulus of radii 0.5 and 1 (coaxial): least 0.2.
  const Annulus3<double> washer{V(0, 0, 0), V(0, 0, 1), 0.5, 1.0};
  const Circle3<double> thread{V(0, 0, -2), V(0, 0, 1), 0.3};
  check_approach(thread, washer, Motion{V(0, 0, 4)}, Motion{}, 0.2, false);
  // Off center by 0.1 through the hole, tilted: it still passes the hole without touching.
  const Approach<double> through =
      closest_approach(Circle3<double>{V(0.1, 0, -2), V(0, 0.1, 1), 0.3}, washer, Motion{V(0, 0, 4)}, Motion{});
  CHECK(through.distance > 0.05 && through.distance < 0.2);
  // Many turns: a ring tumbling 20 times about x past a point at radius sqrt(1.17): the least
  // |p| - 1 whenever its plane holds the point, 40 times.
  const V p(0, 0.6, 0.9);
  check_approach(unit, p, Motion{V::Zero(), V(40 * pi, 0, 0)}, Motion{}, p.norm() - 1, false);
  // 1e6 from the origin: a clock hand turning once about z past a point at radius 1.5 and
  // height 0.25 above its plane: least sqrt(0.25 + 0.0625) at the hand's tip.
  for (const V& shift : {V(0, 0, 0), V(1e6, -1e6, 1e6)}) {
    const Segment3<double> hand{shift, V(shift + V(1, 0, 0))};
    const V q = shift + V(1.5 * std::cos(2.0), 1.5 * std::sin(2.0), 0.25);
    const Approach<double> c =
        check_approach(hand, q, Motion{V::Zero(), V(0, 0, 2 * pi), shift}, Motion{}, std::sqrt(0.3125), true);
    CHECK(std::abs(c.time - 2.0 / (2 * pi)) <= 1e-5);
  }
  // Coplanar disks passing through each other: distance 0 over a stretch (not unique), found
  // without refining the stretch (a distance 0 ends the search).
  const Approach<double> crossing =
      check_approach(Disk3<double>{V(-3, 0, 0), V(0, 0, 1), 1.0}, Disk3<double>{V(0, 0.5, 0), V(0, 0, 1), 1.0},
                     Motion{V(6, 0, 0)}, Motion{}, 0.0, false);
  CHECK(crossing.evaluations < 200);
  // NaN in, NaN out; a rotating line refused.
  CHECK(std::isnan(closest_approach(V(0, 0, std::nan("")), unit, Motion{V(1, 0, 0)}, Motion{}).time));
  bool refused = false;
  try {
    closest_approach(Line3<double>{V(0, 0, 3), V(1, 0, 0)}, unit, Motion{V::Zero(), V(0, 0, 1)}, Motion{});
  } catch (const std::invalid_argument& e) {
    refused = std::string(e.what()).find("closest_approach") != std::string::npos;
  }
  CHECK(refused);
  // A translating line is fine: a line falling onto the ring's plane, least 0 (touching it).
  check_approach(Line3<double>{V(0, 0.5, 2), V(1, 0, 0)}, unit, Motion{V(0, 0, -4)}, Motion{}, 0.0, false);
}

// The reference: d(t) sampled at n + 1 times, and golden section (to the last bit of t) about
// each of the three least local minima of the samples; the least found.
template <class A, class B> double sampled_least(const A& a, const B& b, const Motion& ma, const Motion& mb, int n) {
  const auto d = [&](double t) { return distance(moved(a, ma, t), moved(b, mb, t)); };
  std::vector<double> samples(n + 1);
  for (int i = 0; i <= n; ++i) samples[i] = d(double(i) / n);
  std::vector<int> minima;
  for (int i = 0; i <= n; ++i)
    if ((i == 0 || samples[i] <= samples[i - 1]) && (i == n || samples[i] <= samples[i + 1])) minima.push_back(i);
  std::sort(minima.begin(), minima.end(), [&](int x, int y) { return samples[x] < samples[y]; });
  double least = *std::min_element(samples.begin(), samples.end());
  for (size_t k = 0; k < std::min<size_t>(3, minima.size()); ++k) {
    double lo = std::max(0, minima[k] - 1) / double(n), hi = std::min(n, minima[k] + 1) / double(n);
    const double g = (std::sqrt(5.0) - 1) / 2;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = d(x1), f2 = d(x2);
    for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
      if (f1 <= f2) {
        hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = d(x1);
      } else {
        lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = d(x2);
      }
    }
    least = std::min({least, f1, f2});
  }
  return least;
}

template <class A, class B>
void check_approach_against_sampling(const A& a, const B& b, const Motion& ma, const Motion& mb, double& worst) {
  const Approach<double> c = closest_approach(a, b, ma, mb);
  const double size = std::max(detail::motion_size(a, ma), detail::motion_size(b, mb));
  const double delta = contact_tolerance(size);
  const double reference = sampled_least(a, b, ma, mb, 2000);
  CHECK(std::abs(c.distance - reference) <= delta);
  CHECK(c.distance == distance(moved(a, ma, c.time), moved(b, mb, c.time)));
  worst = std::max(worst, std::abs(c.distance - reference) / size);
}

// The evaluation limit: a query past it throws evaluation_limit, never answers "no contact".
void evaluation_limits() {
  const Circle3<double> unit{V(0, 0, 0), V(0, 0, 1), 1.0};
  // The near miss of analytic_contacts takes some 4400 steps: with a limit of 1000 it throws.
  bool thrown = false;
  try {
    first_contact(V(-5, 1 + 1e-6, 0), unit, Motion{V(10, 0, 0)}, Motion{}, 0.0, 1000);
  } catch (const evaluation_limit&) {
    thrown = true;
  }
  CHECK(thrown);
  // With the default limit it completes.
  CHECK(first_contact(V(-5, 1 + 1e-6, 0), unit, Motion{V(10, 0, 0)}, Motion{}, 0.0).time == inf);
  // A ring tumbling about a diameter at 10^7 rad per unit time past a point 0.5 off its sphere:
  // steps of 0.5 / 10^7, some 2e7 of them: past the default limit, for every rate above it too.
  for (const double rate : {1e7, 1e9, 1e15}) {
    thrown = false;
    try {
      first_contact(unit, V(0, 0, 1.5), Motion{V::Zero(), V(rate, 0, 0)}, Motion{}, 0.0);
    } catch (const evaluation_limit& e) {
      thrown = std::string(e.what()).find("first_contact") != std::string::npos;
    }
    CHECK(thrown);
    thrown = false;
    try {
      closest_approach(unit, V(0, 0, 1.5), Motion{V::Zero(), V(rate, 0, 0)}, Motion{});
    } catch (const evaluation_limit& e) {
      thrown = std::string(e.what()).find("closest_approach") != std::string::npos;
    }
    CHECK(thrown);
  }
}

// Rings spinning about their own axis are carried onto themselves: no speed from the spin.
void spinning_rings() {
  const Circle3<double> unit{V(0, 0, 0), V(0, 0, 1), 1.0};
  const Motion spin{V::Zero(), V(0, 0, 40 * pi), V::Zero()};
  CHECK(detail::rotation_speed(unit, spin) == 0);
  CHECK(detail::rotation_speed(Disk3<double>{V(0, 0, 5), V(0, 0, -2), 1.0}, spin) == 0);
  CHECK(detail::rotation_speed(swept(Annulus3<double>{V(0, 0, 0), V(0, 0, 1), 0.5, 1.0}, 0.2), spin) == 0);
  // Off the axis: the center's distance from it; tilted: the reach.
  CHECK(std::abs(detail::rotation_speed(Circle3<double>{V(3, 4, 1), V(0, 0, 1), 1.0}, spin) - 40 * pi * 5) <= 1e-12);
  CHECK(detail::rotation_speed(Circle3<double>{V(0, 0, 0), V(0, 1, 1), 1.0}, spin) == 40 * pi * 1);
  // A point 0.5 off the spinning ring: never reached, in one evaluation (it used to take steps).
  const Contact<double> c = first_contact(unit, V(1.5, 0, 0), spin, Motion{}, 0.0);
  CHECK(c.time == inf && c.evaluations == 1);
  // Rings whose center circles the axis while they spin about their own normal (a rotation
  // vector a power of two times the normal: exactly parallel), against the sampled references:
  // the center's speed is bound enough, and no contact is missed.
  double worst = 0;
  for (int i = 0; i < 12; ++i) {
    const Circle3<double> ring = source.circle(2);
    const Motion m{source.vector(2), 16 * ring.normal, source.vector(2)};
    CHECK(detail::spins_in_place(ring, m) && detail::rotation_speed(ring, m) < 16 * ring.normal.norm() * 10);
    const V q = source.vector(2);
    std::vector<double> samples;
    sampled_first_contact(ring, q, m, Motion{}, 0.0, 400, samples);
    const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
    const double within = *lo + 0.3 * (*hi - *lo);
    const double reference = sampled_first_contact(ring, q, m, Motion{}, within, 400, samples);
    const Contact<double> c = first_contact(ring, q, m, Motion{}, within);
    const double delta = contact_tolerance(std::max(detail::motion_size(ring, m), detail::motion_size(q, Motion{})));
    CHECK(c.time <= reference + 1e-3);
    CHECK(c.time < inf && distance(moved(ring, m, c.time), q) <= within + delta);
    for (int k = 0; k <= 400 && k / 400.0 < c.time; ++k) CHECK(samples[size_t(k)] + within >= within - delta);
    check_approach_against_sampling(ring, q, m, Motion{}, worst);
  }
  CHECK(worst <= 1e-12);
}

void random_approaches() {
  double worst = 0;
  for (int i = 0; i < check::scaled(3); ++i) {
    check_approach_against_sampling(source.vector(2), source.circle(2), random_motion(), random_motion(), worst);
    check_approach_against_sampling(source.segment(2), source.disk(2), random_motion(), random_motion(), worst);
    check_approach_against_sampling(source.circle(2), source.circle(2), random_motion(), random_motion(), worst);
    check_approach_against_sampling(random_arc(2), random_annulus(2), random_motion(), random_motion(), worst);
    check_approach_against_sampling(swept(source.segment(2), 0.1), source.disk(2), random_motion(), random_motion(),
                                    worst);
    check_approach_against_sampling(source.bezier(2), source.circle(2), random_motion(), random_motion(), worst);
    // A translating line against a turning disk.
    check_approach_against_sampling(Line3<double>{source.vector(2), source.direction()}, source.disk(2),
                                    Motion{source.vector(3)}, random_motion(), worst);
  }
  CHECK(worst <= 1e-12);
}

// Many near-equal dips: a ring tumbling 20 times about its diameter on x past a point 1e-3
// outside it, the point drifting slowly along x. Twice a turn the ring's plane holds the point
// (a dip of least about |p(t)| - 1); the drift makes the dips' leasts differ by as little as
// 1e-11 S, far less than the screen, so the search's samples (as far above each dip's least as
// the screen allows) mis-order them: the least dip is rarely among the few least samples, and
// every dip must be polished. The reference: the distance in closed form at long double (the ring's normal
// R_x(w t) e_z, the point's distance from its plane h and from its axis rho, d = |(rho - 1, h)|),
// sampled at 40 points a dip, every local least of the samples refined by golden section.
long double drifting_point_distance(long double t, long double w, const V& p, long double v) {
  const long double ny = -std::sin(w * t), nz = std::cos(w * t), px = p.x() + v * t;
  const long double y = p.y(), z = p.z(), h = y * ny + z * nz;
  const long double rho = std::sqrt(std::max(px * px + y * y + z * z - h * h, 0.0L));
  return std::sqrt((rho - 1) * (rho - 1) + h * h);
}

long double drifting_point_least(long double w, const V& p, long double v, int n) {
  const auto d = [&](long double t) { return drifting_point_distance(t, w, p, v); };
  std::vector<long double> samples(size_t(n) + 1);
  for (int i = 0; i <= n; ++i) samples[size_t(i)] = d((long double)(i) / n);
  long double least = *std::min_element(samples.begin(), samples.end());
  const long double g = (std::sqrt(5.0L) - 1) / 2;
  for (int i = 0; i <= n; ++i) {
    const size_t k = size_t(i);
    if ((i > 0 && samples[k] > samples[k - 1]) || (i < n && samples[k] > samples[k + 1])) continue;
    long double lo = std::max(0, i - 1) / (long double)(n), hi = std::min(n, i + 1) / (long double)(n);
    long double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = d(x1), f2 = d(x2);
    for (int it = 0; it < 200 && hi - lo > 1e-19L; ++it) {
      if (f1 <= f2) {
        hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = d(x1);
      } else {
        lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = d(x2);
      }
    }
    least = std::min({least, f1, f2});
  }
  return least;
}

void many_dips() {
  const Circle3<double> unit{V(0, 0, 0), V(0, 0, 1), 1.0};
  const double turns = 20, w = 2 * turns * pi;
  const Motion tumble{V::Zero(), V(w, 0, 0)};
  double worst = 0;
  for (const double phi : {0.3, 0.98, 2.2})
    for (const double v : {3e-4, 1e-3})
      for (int k = 0; k < 6; ++k) {
        // The drift crosses x = 0 (the least |p|) near the middle, at offsets across a dip's spacing.
        const double x0 = -v / 2 + k * v / (2 * turns) / 6;
        const V p(x0, 1.001 * std::cos(phi), 1.001 * std::sin(phi));
        const Motion drift{V(v, 0, 0)};
        const Approach<double> c = closest_approach(unit, p, tumble, drift);
        const double size = std::max(detail::motion_size(unit, tumble), detail::motion_size(p, drift));
        const long double reference = drifting_point_least(w, p, v, 80 * int(turns));
        CHECK(std::abs(c.distance - reference) <= contact_tolerance(size));
        CHECK(c.distance == distance(moved(unit, tumble, c.time), moved(p, drift, c.time)));
        worst = std::max(worst, double(std::abs(c.distance - reference)) / size);
      }
  CHECK(worst <= 1e-12);
}

}  // namespace

int main() {
  rotations();
  moved_shapes();
  reaches();
  analytic_contacts();
  random_contacts();
  evaluation_limits();
  spinning_rings();
  analytic_approaches();
  random_approaches();
  many_dips();
  return check::finish("test_motion");
}

}  // namespace test_motion

CHECK_SUITE(test_motion);
