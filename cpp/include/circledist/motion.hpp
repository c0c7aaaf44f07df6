// Rigid motions over t in [0, 1] and the shapes they carry: Motion3 (a constant-velocity screw
// about a center), the rotation R(w) it turns by, moved(shape, motion, t) for every shape kind,
// reach(shape, center) (how far a shape extends from a point: the speed bound of a rotating
// shape), and first_contact(a, b, motion_a, motion_b, within): the earliest t at which the moving
// shapes come within `within` of each other, by conservative advancement on the exact distance.
// Derivation: docs/derivations/motion.md.
#pragma once

#include "effects.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace circledist {

template <class Real> using Mat3 = Eigen::Matrix<Real, 3, 3>;

// A rigid motion over t in [0, 1] at constant velocity: a point x moves to
//   center + R(t rotation) (x - center) + t translation,
// R(w) the rotation by |w| radians about w / |w| (right-handed; R(0) = I). Every field zero is
// the motion at rest.
template <class Real> struct Motion3 {
  Vec3<Real> translation = Vec3<Real>::Zero(), rotation = Vec3<Real>::Zero(), center = Vec3<Real>::Zero();
};

namespace detail {
// |v| for any v: scaled by a power of two where |v|^2 would overflow or reach the subnormals (a
// rotation vector of 1e-200 rad is a rotation by 1e-200, not by 0); NaN for a NaN component.
template <class Real> Real safe_norm(const Vec3<Real>& v) {
  if (v.hasNaN()) return std::numeric_limits<Real>::quiet_NaN();
  const Real largest = v.cwiseAbs().maxCoeff();
  if (!(largest > 0) || !(largest < std::numeric_limits<Real>::infinity())) return largest;
  if (moderate(largest)) return v.norm();
  const int e = std::ilogb(largest);
  return std::ldexp(ldexp3(v, -e).norm(), e);
}
}  // namespace detail

// R(w) by Rodrigues' formula, with k = w / |w| and theta = |w|:
//   R = cos(theta) I + sin(theta) [k]x + (1 - cos(theta)) k k^T,
// 1 - cos(theta) taken as 2 sin^2(theta / 2), which keeps its digits for tiny angles (where
// 1 - cos cancels to 0 below 1e-8 rad). Huge angles (many turns) are as accurate as theta itself:
// sin and cos reduce their argument exactly. A NaN or infinite w gives NaN.
template <class Real> Mat3<Real> rotation_matrix(const Vec3<Real>& w) {
  const Real theta = detail::safe_norm(w);
  if (theta == 0) return Mat3<Real>::Identity();
  if (!(theta < std::numeric_limits<Real>::infinity())) {
    return Mat3<Real>::Constant(std::numeric_limits<Real>::quiet_NaN());
  }
  const Vec3<Real> k = unit_vector(w);
  const Real c = std::cos(theta), s = std::sin(theta), half = std::sin(theta / 2);
  const Real one_minus_c = 2 * half * half;
  Mat3<Real> r = one_minus_c * (k * k.transpose());
  r.diagonal().array() += c;
  r(0, 1) -= s * k.z();
  r(1, 0) += s * k.z();
  r(0, 2) += s * k.y();
  r(2, 0) -= s * k.y();
  r(1, 2) -= s * k.x();
  r(2, 1) += s * k.x();
  return r;
}

// A motion at one instant: x -> center + rotation (x - center) + shift. Points and vectors
// (directions, normals, an arc's start) map through it; moved() below uses one per time.
template <class Real> struct Placement {
  Mat3<Real> rotation = Mat3<Real>::Identity();
  Vec3<Real> center = Vec3<Real>::Zero(), shift = Vec3<Real>::Zero();

  Vec3<Real> point(const Vec3<Real>& x) const { return center + rotation * (x - center) + shift; }
  // A vector of any length: one beyond the moderate range (a direction of 1e200) is rotated at a
  // largest component in [1, 2) and scaled back (exact), so that its sums cannot overflow.
  Vec3<Real> vector(const Vec3<Real>& v) const {
    const Real largest = v.cwiseAbs().maxCoeff();
    if (!(largest > 0) || detail::moderate(largest)) return rotation * v;
    const int e = detail::direction_exponent(v);
    return detail::ldexp3(Vec3<Real>(rotation * detail::ldexp3(v, -e)), e);
  }
};

template <class Real> Placement<Real> placement(const Motion3<Real>& m, Real t) {
  return {rotation_matrix<Real>(Vec3<Real>(t * m.rotation)), m.center, Vec3<Real>(t * m.translation)};
}

// Shapes under a placement: points (centers, origins, ends, control points) move as points;
// directions and normals rotate; radii, angles and sweeps stay.
template <class Real> Vec3<Real> moved(const Vec3<Real>& p, const Placement<Real>& m) { return m.point(p); }
template <class Real> Line3<Real> moved(const Line3<Real>& l, const Placement<Real>& m) {
  return {m.point(l.origin), m.vector(l.direction)};
}
template <class Real> Ray3<Real> moved(const Ray3<Real>& r, const Placement<Real>& m) {
  return {m.point(r.origin), m.vector(r.direction)};
}
template <class Real> Segment3<Real> moved(const Segment3<Real>& s, const Placement<Real>& m) {
  return {m.point(s.p0), m.point(s.p1)};
}
template <class Real> Circle3<Real> moved(const Circle3<Real>& c, const Placement<Real>& m) {
  return {m.point(c.center), m.vector(c.normal), c.radius};
}
template <class Real> Disk3<Real> moved(const Disk3<Real>& d, const Placement<Real>& m) {
  return {m.point(d.center), m.vector(d.normal), d.radius};
}
template <class Real> Annulus3<Real> moved(const Annulus3<Real>& a, const Placement<Real>& m) {
  return {m.point(a.center), m.vector(a.normal), a.inner_radius, a.outer_radius};
}

namespace detail {
// The direction an arc starts in, in its plane: the start's projection x U + y V in the frame of
// its normal, formed as ArcSpan (detail/arc_span.hpp) forms it, or U where it has none. The start
// as given may lean out of the plane (only its projection counts); rotated as given, a start
// along the normal would turn into one with a rounding-sized projection in an arbitrary
// direction. Its projection rotates into the moved arc's plane with its angle kept.
template <class Real> Vec3<Real> arc_start_in_plane(const Arc3<Real>& a) {
  const Frame<Real> frame(a.normal);
  const Vec3<Real> start = moderate_start(a.start);
  const Real x = frame.u.dot(start), y = frame.v.dot(start);
  if (x == 0 && y == 0) return frame.u;
  return x * frame.u + y * frame.v;
}
}  // namespace detail

template <class Real> Arc3<Real> moved(const Arc3<Real>& a, const Placement<Real>& m) {
  return {m.point(a.center), m.vector(a.normal), a.radius, m.vector(detail::arc_start_in_plane(a)), a.angle};
}
template <class Real> BezierCurve3<Real> moved(const BezierCurve3<Real>& b, const Placement<Real>& m) {
  BezierCurve3<Real> out = b;
  for (int i = 0; i < int(b.control.cols()); ++i) out.control.col(i) = m.point(Vec3<Real>(b.control.col(i)));
  return out;
}
template <class S> Swept<S> moved(const Swept<S>& s, const Placement<scalar_t<S>>& m) {
  return {moved(s.shape, m), s.sweep};
}

// The shape at time t of `motion` (t outside [0, 1] extrapolates the same screw).
template <class Shape>
Shape moved(const Shape& shape, const Motion3<scalar_t<core_t<Shape>>>& motion, scalar_t<core_t<Shape>> t) {
  return moved(shape, placement(motion, t));
}

// reach(shape, c): the largest distance from c to a point of the shape (an upper bound for an
// arc), +inf for lines and rays, 0 for the empty curve. A motion's point x has speed at most
// |translation| + |rotation| |x - center| (docs/derivations/motion.md), and rotation keeps
// |x - center|: so the shape's reach from its motion's center bounds its speed at every t.
template <class Real> Real reach(const Vec3<Real>& p, const Vec3<Real>& c) {
  return detail::safe_norm(Vec3<Real>(p - c));
}
template <class Real> Real reach(const Line3<Real>&, const Vec3<Real>&) {
  return std::numeric_limits<Real>::infinity();
}
template <class Real> Real reach(const Ray3<Real>&, const Vec3<Real>&) { return std::numeric_limits<Real>::infinity(); }
template <class Real> Real reach(const Segment3<Real>& s, const Vec3<Real>& c) {
  return std::max(reach(s.p0, c), reach(s.p1, c));  // a convex function is largest at an end
}
namespace detail {
// The farthest point of a circle (center o, normal n, radius r) from c: with h the height of c
// over the plane and q the distance of c's foot from o, the rim point opposite the foot, at
// sqrt(h^2 + (q + r)^2). A disk's and an annulus's farthest points are on their outer rims.
template <class Real> Real ring_reach(const Vec3<Real>& o, const Vec3<Real>& n, Real r, const Vec3<Real>& c) {
  const Vec3<Real> d = o - c;
  const Vec3<Real> unit = unit_vector(n);
  const Real h = unit.dot(d);
  const Real q = (d - h * unit).norm();
  return std::hypot(h, q + r);
}
}  // namespace detail
template <class Real> Real reach(const Circle3<Real>& s, const Vec3<Real>& c) {
  return detail::ring_reach(s.center, s.normal, s.radius, c);
}
template <class Real> Real reach(const Disk3<Real>& s, const Vec3<Real>& c) {
  return detail::ring_reach(s.center, s.normal, s.radius, c);
}
template <class Real> Real reach(const Annulus3<Real>& s, const Vec3<Real>& c) {
  return detail::ring_reach(s.center, s.normal, s.outer_radius, c);
}
// An arc: its circle's reach, or its bounding ball's (bounds.hpp) where that is less.
template <class Real> Real reach(const Arc3<Real>& s, const Vec3<Real>& c) {
  const Ball<Real> ball = bounding_ball(s);
  return std::min(detail::ring_reach(s.center, s.normal, s.radius, c), reach(ball.center, c) + ball.radius);
}
// A curve lies in its control points' convex hull: the farthest control point.
template <class Real> Real reach(const BezierCurve3<Real>& b, const Vec3<Real>& c) {
  Real out = 0;
  for (int i = 0; i < int(b.control.cols()); ++i) out = std::max(out, reach(Vec3<Real>(b.control.col(i)), c));
  return out;
}
template <class S> scalar_t<S> reach(const Swept<S>& s, const Vec3<scalar_t<S>>& c) {
  return reach(s.shape, c) + s.sweep;
}

// What first_contact() returns: the earliest time (+inf when the shapes never come within
// `within` over [0, 1], NaN for NaN input), and closest_points() of the shapes at that time
// (NaN when there is no contact). `evaluations` counts the exact distances evaluated.
template <class Real> struct Contact {
  Real time = std::numeric_limits<Real>::infinity();
  Real distance = std::numeric_limits<Real>::quiet_NaN();
  Vec3<Real> point_a = Vec3<Real>::Constant(std::numeric_limits<Real>::quiet_NaN());
  Vec3<Real> point_b = Vec3<Real>::Constant(std::numeric_limits<Real>::quiet_NaN());
  Vec2<Real> param_a = Vec2<Real>::Constant(std::numeric_limits<Real>::quiet_NaN());
  Vec2<Real> param_b = Vec2<Real>::Constant(std::numeric_limits<Real>::quiet_NaN());
  bool unique = true;
  std::uint64_t evaluations = 0;
};

// The contact bar delta for a query of size S: 1e-12 S, or 64 eps S in a type too short for it
// (float). first_contact's time has distance <= within + delta and no earlier time has distance
// < within - delta (docs/derivations/motion.md).
template <class Real> Real contact_tolerance(Real size) {
  return std::max(Real(1e-12), 64 * std::numeric_limits<Real>::epsilon()) * size;
}

// The most distances a motion query evaluates (first_contact, closest_approach): a motion
// whose speed bound L is vast against the bar (hundreds of thousands of turns of a shape of its
// size) or a tangential approach at a vast L would take more; the query then throws
// evaluation_limit rather than answer "no contact" for a contact it has not excluded
// (docs/derivations/motion.md, "The evaluation limit").
constexpr std::uint64_t kMotionEvaluationLimit = std::uint64_t(1) << 20;

// The error of a query that reached its evaluation limit (std::runtime_error: RuntimeError in
// Python, where the message names the query and the batch element).
class evaluation_limit : public std::runtime_error {
 public:
  evaluation_limit(const char* query, std::uint64_t limit)
      : std::runtime_error(std::string("circledist::") + query + ": more than " + std::to_string(limit) +
                           " distance evaluations (the motion is too fast for the bar, L / delta too large); no "
                           "answer rather than one that could miss a contact") {}
};

namespace detail {
// The size of a moving shape: its largest coordinate or radius (sweep included) at both ends of
// the motion, and how far it travels.
template <class A> scalar_t<core_t<A>> motion_size(const A& a, const Motion3<scalar_t<core_t<A>>>& m) {
  using Real = scalar_t<core_t<A>>;
  const Real sweep = sweep_of(a);
  const Real at0 = extent(core(a)) + sweep, at1 = extent(core(moved(a, m, Real(1)))) + sweep;
  const Real travel = safe_norm(m.translation);
  // A rotating shape swings about the center in between: up to |center| + reach + travel.
  const Real swing = safe_norm(m.rotation) > 0 ? safe_norm(m.center) + reach(a, m.center) + travel : Real(0);
  return std::max({at0, at1, travel, swing});
}

// A ring (circle, disk, annulus, or one swept) turning about an axis along its own normal is
// carried onto the same ring about its moved center: its points can be taken to follow the
// center, at |rotation| times the center's distance from the axis (docs/derivations/motion.md,
// "Rings spinning about their axis"). Exactly parallel only (the rotation's cross product with
// the normal exactly zero); otherwise the reach bounds it.
template <class Real> bool turns_about_own_normal(const Vec3<Real>& normal, const Motion3<Real>& m) {
  return m.rotation.cross(normal) == Vec3<Real>::Zero();
}
template <class Real> Real axis_offset(const Vec3<Real>& center, const Motion3<Real>& m) {
  const Vec3<Real> k = unit_vector(m.rotation), d = center - m.center;
  return safe_norm(Vec3<Real>(d - k.dot(d) * k));
}
template <class S, class M> bool spins_in_place(const S&, const M&) { return false; }
template <class Real> bool spins_in_place(const Circle3<Real>& s, const Motion3<Real>& m) {
  return turns_about_own_normal(s.normal, m);
}
template <class Real> bool spins_in_place(const Disk3<Real>& s, const Motion3<Real>& m) {
  return turns_about_own_normal(s.normal, m);
}
template <class Real> bool spins_in_place(const Annulus3<Real>& s, const Motion3<Real>& m) {
  return turns_about_own_normal(s.normal, m);
}
template <class S, class M> bool spins_in_place(const Swept<S>& s, const M& m) { return spins_in_place(s.shape, m); }

// How far from m's center the points of a shape effectively are: its reach, or for a ring that
// spins in place its center's distance from the axis.
template <class S, class M> auto spin_reach(const S& s, const M& m) { return reach(s, m.center); }
template <class Real> Real spin_reach(const Circle3<Real>& s, const Motion3<Real>& m) {
  return spins_in_place(s, m) ? axis_offset(s.center, m) : reach(s, m.center);
}
template <class Real> Real spin_reach(const Disk3<Real>& s, const Motion3<Real>& m) {
  return spins_in_place(s, m) ? axis_offset(s.center, m) : reach(s, m.center);
}
template <class Real> Real spin_reach(const Annulus3<Real>& s, const Motion3<Real>& m) {
  return spins_in_place(s, m) ? axis_offset(s.center, m) : reach(s, m.center);
}
template <class S, class M> auto spin_reach(const Swept<S>& s, const M& m) {
  return spins_in_place(s.shape, m) ? spin_reach(s.shape, m) : reach(s, m.center);
}

// |rotation| reach(a, center): the most a's rotation adds to the speed of any of its points (0
// when it does not rotate, whatever its reach). `query` names the caller in the refusal of a
// rotating line or ray.
template <class A> scalar_t<core_t<A>> rotation_speed(const A& a, const Motion3<scalar_t<core_t<A>>>& m,
                                                      const char* query = "first_contact") {
  using Real = scalar_t<core_t<A>>;
  const Real w = safe_norm(m.rotation);
  if (w == 0) return Real(0);
  const Real r = spin_reach(a, m);
  if (!(r < std::numeric_limits<Real>::infinity()) && w == w && r == r) {
    throw std::invalid_argument(std::string("circledist::") + query +
                                ": a line or ray cannot rotate (its points reach infinitely far from the motion's "
                                "center, so no speed bound exists); give it a motion without rotation");
  }
  return w * r;
}

// L of docs/derivations/motion.md (4) from each shape's rotation_speed: |T_a - T_b| + spin_a +
// spin_b, the most the distance can change per unit time; 0 for one motion of both (one rigid
// motion of the pair keeps every distance: relative rest).
template <class Real>
Real combined_speed(const Motion3<Real>& motion_a, const Motion3<Real>& motion_b, Real spin_a, Real spin_b) {
  const Real speed = safe_norm(Vec3<Real>(motion_a.translation - motion_b.translation)) + spin_a + spin_b;
  if (motion_a.translation == motion_b.translation && motion_a.rotation == motion_b.rotation &&
      motion_a.center == motion_b.center && speed == speed)
    return Real(0);
  return speed;
}
template <class A, class B>
scalar_t<core_t<A>> relative_speed(const A& a, const B& b, const Motion3<scalar_t<core_t<A>>>& motion_a,
                                   const Motion3<scalar_t<core_t<A>>>& motion_b, const char* query) {
  return combined_speed(motion_a, motion_b, rotation_speed(a, motion_a, query), rotation_speed(b, motion_b, query));
}

// The next time after t: t + h, or less by an ulp or two, so that the stretch (t, next] is no
// longer than h whatever the rounding of t + h (docs/derivations/motion.md, "Time"); at least
// the next representable time, and at most 1.
template <class Real> Real next_time(Real t, Real h) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  Real next = t + h < 1 ? t + h : Real(1);
  while (next > t && (next - t) * (1 + 2 * eps) > h) next = std::nextafter(next, t);
  if (!(next > t)) next = std::nextafter(t, Real(2));
  return next;
}
}  // namespace detail

namespace detail {
// The conservative advancement of first_contact (docs/derivations/motion.md, "The method"), on
// any evaluation of the distance: distance_at(t) moves the shapes to t and answers their exact
// distance (the caller keeps them there: the last call is at the contact's time). `speed` is the
// bound L, `delta` the bar. Returns the contact's time, +inf for none over [0, 1], NaN where a
// distance is NaN; `evaluations` counts the calls; after `limit` of them, evaluation_limit
// (never "no contact" for a contact not excluded). One copy of the loop: motion.hpp's
// first_contact and the Python module's batched kernel both run it.
//   - contact at t when g = distance - within <= delta / 2;
//   - else no time in (t, t + g / L] has distance below within (less the distance's own
//     rounding): step there. The bar's lower allowance (within - delta) is not spent on longer
//     steps: a step of (g + delta / 2) / L would jump over an instant of touching (a ring turning
//     through a point, distance exactly `within` at one instant) and miss it.
template <class Real, class Distance> Real advance(Distance&& distance_at, Real within, Real speed, Real delta,
                                                   std::uint64_t& evaluations,
                                                   std::uint64_t limit = kMotionEvaluationLimit) {
  Real t = 0;
  for (;;) {
    if (evaluations >= limit) throw evaluation_limit("first_contact", limit);
    const Real d = distance_at(t);
    ++evaluations;
    if (d != d) return std::numeric_limits<Real>::quiet_NaN();
    const Real gap = d - within;
    if (gap <= delta / 2) return t;
    // At rest relative to each other (the distance cannot change), or at the end: no contact.
    if (speed == 0 || t >= 1) return std::numeric_limits<Real>::infinity();
    t = next_time(t, gap / speed);
  }
}
}  // namespace detail

// The earliest t in [0, 1] at which distance(a(t), b(t)) <= within, a(t) = moved(a, motion_a,
// t). Conservative advancement (docs/derivations/motion.md, detail::advance above): with L a
// bound on how fast the distance can fall (the relative speed of any point of one shape against
// the other) and delta the bar (contact_tolerance), steps of (distance - within) / L.
// The steps are longer than delta / (2 L), so the loop ends; a tangential approach (g falling
// quadratically to its least) takes of the order of sqrt(S / delta) steps. A rotating line or
// ray has no speed bound: std::invalid_argument. More than `max_evaluations` distances:
// evaluation_limit.
template <class Roots = DefaultRoots, class A, class B>
Contact<scalar_t<core_t<A>>> first_contact(const A& a, const B& b, const Motion3<scalar_t<core_t<A>>>& motion_a,
                                           const Motion3<scalar_t<core_t<A>>>& motion_b, scalar_t<core_t<A>> within = 0,
                                           std::uint64_t max_evaluations = kMotionEvaluationLimit) {
  using Real = scalar_t<core_t<A>>;
  static_assert(std::is_same<Real, scalar_t<core_t<B>>>::value, "circledist::first_contact: shapes of one scalar type");
  Contact<Real> out;
  const Real speed = detail::relative_speed(a, b, motion_a, motion_b, "first_contact");
  const Real size = std::max(detail::motion_size(a, motion_a), detail::motion_size(b, motion_b));
  const Real delta = contact_tolerance(size);
  if (speed != speed || size != size || within != within) {
    out.time = std::numeric_limits<Real>::quiet_NaN();
    return out;
  }
  const auto at = [&](Real t) {
    return std::make_pair(moved(a, placement(motion_a, t)), moved(b, placement(motion_b, t)));
  };
  const Real t = detail::advance(
      [&](Real time) {
        const auto [a_t, b_t] = at(time);
        return counted_distance<Roots>(a_t, b_t);
      },
      within, speed, delta, out.evaluations, max_evaluations);
  out.time = t;
  if (!(t <= 1)) return out;  // +inf (no contact) or NaN
  const auto [a_t, b_t] = at(t);
  const Result<Real> r = counted_closest_points<Roots>(a_t, b_t);
  out.distance = r.distance;
  out.point_a = r.point_a;
  out.point_b = r.point_b;
  out.param_a = r.param_a;
  out.param_b = r.param_b;
  out.unique = r.unique;
  return out;
}

}  // namespace circledist
