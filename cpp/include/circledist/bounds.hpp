// Cheap exact bounds on the distance between two shapes, with no polynomial solved: what
// within() and intersects() (effects.hpp) try before the solvers, and what a broadphase culls on.
//
// Lower bounds (the distance is at least):
//   - bounding balls: |c_a - c_b| - r_a - r_b for bounded shapes; the closed-form distance from a
//     line or ray to the other's ball center, less its radius, for unbounded ones;
//   - plane sides: a shape lying wholly on one side of a circle's or disk's plane is at least its
//     smallest height over that plane away from it (every point of the round is in the plane);
//   - a shape inside a circle's ball is at least the circle's radius less its own reach from the
//     circle's center away from the ring (every ring point is at the radius from the center).
// Upper bounds (the distance is at most): the closed-form point-circle / point-disk distance of a
// few concrete points of the other shape (the point of a segment, circle or disk nearest to the
// round's center, where it crosses the round's plane, a curve's end points and middle), and the
// exact disk-disk contact test (disk_disk.hpp, closed form).
// Every bound is exact up to rounding: callers keep a margin of sqrt(eps) * scale around them.
#pragma once

#include "detail/round_target.hpp"
#include "sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace circledist {

template <class Real> struct DistanceBounds {
  Real lower = 0;                                      // the distance is >= lower
  Real upper = std::numeric_limits<Real>::infinity();  // the distance is <= upper
  Real scale = 1;                                      // the pair's length scale (for tolerances)
  Real rounding = 0;  // what rounding of the shapes' coordinates can move the bounds by (far points)
};

// A ball holding the shape; radius +inf for unbounded shapes (lines, rays).
template <class Real> struct Ball {
  Vec3<Real> center = Vec3<Real>::Zero();
  Real radius = std::numeric_limits<Real>::infinity();
  bool bounded() const { return radius < std::numeric_limits<Real>::infinity(); }
};

template <class Real> Ball<Real> bounding_ball(const Vec3<Real>& p) { return {p, Real(0)}; }
template <class Real> Ball<Real> bounding_ball(const Line3<Real>& l) { return {l.origin}; }
template <class Real> Ball<Real> bounding_ball(const Ray3<Real>& r) { return {r.origin}; }
template <class Real> Ball<Real> bounding_ball(const Segment3<Real>& s) {
  return {(s.p0 + s.p1) / 2, (s.p1 - s.p0).norm() / 2};
}
// A circle or disk (any shape with a target policy, detail/round_target.hpp).
template <class R, class = detail::target_t<R>> Ball<scalar_t<R>> bounding_ball(const R& round) {
  return {round.center, round.radius};
}
// The curve lies in its control points' convex hull, so in the ball around their box's center.
template <class Real> Ball<Real> bounding_ball(const BezierCurve3<Real>& b) {
  if (b.control.cols() == 0) return {};
  const Vec3<Real> lo = b.control.rowwise().minCoeff(), hi = b.control.rowwise().maxCoeff();
  Ball<Real> out{(lo + hi) / 2, Real(0)};
  for (int i = 0; i < int(b.control.cols()); ++i) {
    out.radius = std::max(out.radius, (b.control.col(i) - out.center).norm());
  }
  return out;
}
// An arc (docs/derivations/arc.md): up to a half turn it lies in the ball on its chord (every point of the
// arc sees the chord at an inscribed angle of at least 90 degrees), otherwise in its circle's.
template <class Real> Ball<Real> bounding_ball(const Arc3<Real>& a) {
  if (!(a.angle <= pi_v<Real>())) return {a.center, a.radius};
  const detail::ArcSpan<Real> span(a);
  const Vec3<Real> p0 = span.world(a.center, a.radius, span.lo()), p1 = span.world(a.center, a.radius, span.hi());
  // Half the chord, and an ulp of the radius for the rounding of the ends.
  return {(p0 + p1) / 2, (p1 - p0).norm() / 2 + 4 * std::numeric_limits<Real>::epsilon() * a.radius};
}
// An annulus (docs/derivations/annulus.md): it lies in its outer disk, so in that disk's ball.
template <class Real> Ball<Real> bounding_ball(const Annulus3<Real>& a) { return {a.center, a.outer_radius}; }
template <class S> Ball<scalar_t<S>> bounding_ball(const Swept<S>& s) {
  Ball<scalar_t<S>> b = bounding_ball(s.shape);
  b.radius += s.sweep;
  return b;
}

// The closed-form distance from a point to a line, ray or segment (t clamped to the interval).
template <class Real> Real point_linear_distance(const Vec3<Real>& p, const detail::Linear<Real>& piece) {
  const Vec3<Real> w = p - piece.origin;
  const Real dd = piece.direction.squaredNorm();
  if (!(dd > 0)) return w.norm();
  const Real t = std::min(std::max(w.dot(piece.direction) / dd, piece.lo), piece.hi);
  return (w - t * piece.direction).norm();
}

// A round's plane: heights h(x) = n.(x - c) with n of unit length.
template <class Real> struct Plane {
  Vec3<Real> center, n;
  template <class R> explicit Plane(const R& round) : center(round.center), n(unit_vector(round.normal)) {}
  Real height(const Vec3<Real>& x) const { return n.dot(x - center); }
};

// The range [lo, hi] of heights a shape takes over a plane (infinite ends for unbounded ones).
template <class Real> struct Range {
  Real lo, hi;
  // The smallest |height|: > 0 when the shape lies strictly on one side.
  Real gap() const { return lo > 0 ? lo : (hi < 0 ? -hi : Real(0)); }
};

template <class Real> Range<Real> height_range(const Vec3<Real>& p, const Plane<Real>& plane) {
  const Real h = plane.height(p);
  return {h, h};
}
template <class Real> Range<Real> linear_height_range(const detail::Linear<Real>& piece, const Plane<Real>& plane) {
  const Real inf = std::numeric_limits<Real>::infinity();
  const Real h = plane.height(piece.origin), slope = plane.n.dot(piece.direction);
  if (slope == 0) return {h, h};
  const Real a = std::isfinite(piece.lo) ? h + piece.lo * slope : (slope > 0 ? -inf : inf);
  const Real b = std::isfinite(piece.hi) ? h + piece.hi * slope : (slope > 0 ? inf : -inf);
  return {std::min(a, b), std::max(a, b)};
}
template <class Real> Range<Real> height_range(const Line3<Real>& l, const Plane<Real>& plane) {
  return linear_height_range(detail::as_linear(l), plane);
}
template <class Real> Range<Real> height_range(const Ray3<Real>& r, const Plane<Real>& plane) {
  return linear_height_range(detail::as_linear(r), plane);
}
template <class Real> Range<Real> height_range(const Segment3<Real>& s, const Plane<Real>& plane) {
  const Real a = plane.height(s.p0), b = plane.height(s.p1);
  return {std::min(a, b), std::max(a, b)};
}
template <class Real, class R, class = detail::target_t<R>>
Range<Real> height_range(const R& round, const Plane<Real>& plane) {
  const Real h = plane.height(round.center);
  const Vec3<Real> m = unit_vector(round.normal);
  const Real spread = round.radius * plane.n.cross(m).norm();  // radius * sin(angle between the planes)
  return {h - spread, h + spread};
}
template <class Real> Range<Real> height_range(const BezierCurve3<Real>& b, const Plane<Real>& plane) {
  Range<Real> r{std::numeric_limits<Real>::infinity(), -std::numeric_limits<Real>::infinity()};
  for (int i = 0; i < int(b.control.cols()); ++i) {
    const Real h = plane.height(b.control.col(i));
    r.lo = std::min(r.lo, h);
    r.hi = std::max(r.hi, h);
  }
  return r;
}

// The range of e . (x - c) + base over an arc's points x, c its center and e a unit vector
// (docs/derivations/arc.md "The arc": the arc is its circle's canonical angles [theta0, theta0 + angle]).
// Along the circle it is base + R (a cos theta + b sin theta), a = e . U, b = e . V, extreme at
// atan2(b, a) and half a turn on: the ends and whichever of those two angles fall on the arc.
template <class Real> Range<Real> arc_range(const Arc3<Real>& arc, const Vec3<Real>& e, Real base) {
  const detail::ArcSpan<Real> span(arc);
  const Real a = e.dot(span.frame.u), b = e.dot(span.frame.v);
  const auto at = [&](Real theta) { return base + arc.radius * (a * std::cos(theta) + b * std::sin(theta)); };
  Range<Real> r{std::min(at(span.lo()), at(span.hi())), std::max(at(span.lo()), at(span.hi()))};
  const Real reach = arc.radius * std::hypot(a, b);
  const Real top = std::atan2(b, a);
  if (span.holds(top)) r.hi = std::max(r.hi, base + reach);
  if (span.holds(top + pi_v<Real>())) r.lo = std::min(r.lo, base - reach);
  return r;
}
template <class Real> Range<Real> height_range(const Arc3<Real>& arc, const Plane<Real>& plane) {
  return arc_range(arc, plane.n, plane.height(arc.center));
}

// An annulus: its outer disk's range, which holds the annulus's (a lower bound from it holds).
template <class Real> Range<Real> height_range(const Annulus3<Real>& a, const Plane<Real>& plane) {
  return height_range(detail::annulus_disk(a), plane);
}

// A round is a shape with a target policy (detail/round_target.hpp: a circle or a disk).
template <class T, class = void> struct is_round : std::false_type {};
template <class T> struct is_round<T, std::void_t<detail::target_t<T>>> : std::true_type {};
template <class T> constexpr bool is_round_v = is_round<T>::value;
template <class T> constexpr bool is_disk_v = std::is_same_v<T, Disk3<scalar_t<T>>>;
template <class T> constexpr bool is_circle_v = std::is_same_v<T, Circle3<scalar_t<T>>>;
template <class T> constexpr bool is_point_v = std::is_same_v<T, Vec3<scalar_t<T>>>;
template <class T> constexpr bool is_linear_v = std::is_same_v<T, Line3<scalar_t<T>>> ||
                                                std::is_same_v<T, Ray3<scalar_t<T>>> ||
                                                std::is_same_v<T, Segment3<scalar_t<T>>>;

// The exact distance from a point to a round (closed form).
template <class Real, class R, class = detail::target_t<R>>
Real point_round_distance(const Vec3<Real>& p, const R& round) {
  return Query<Vec3<Real>, R>::distance(p, round);
}

// Calls visit(point) for a few concrete points of a shape likely to be near a round: see the
// header comment. Every point lies on the shape (up to rounding).
template <class Real, class R, class Visit> void sample_points(const Vec3<Real>& p, const R&, const Visit& visit) {
  visit(p);
}

template <class Real, class R, class Visit>
void sample_linear_points(const detail::Linear<Real>& piece, const R& round, const Visit& visit) {
  const Real dd = piece.direction.squaredNorm();
  if (!(dd > 0)) {
    visit(piece.origin);
    return;
  }
  const auto at = [&](Real t) {
    t = std::min(std::max(t, piece.lo), piece.hi);
    return Vec3<Real>(piece.origin + t * piece.direction);
  };
  visit(at((round.center - piece.origin).dot(piece.direction) / dd));  // nearest to the center
  const Plane<Real> plane(round);
  const Real slope = plane.n.dot(piece.direction);
  if (slope != 0) visit(at(-plane.height(piece.origin) / slope));  // the plane crossing
}
template <class Real, class R, class Visit>
void sample_points(const Line3<Real>& l, const R& round, const Visit& visit) {
  sample_linear_points(detail::as_linear(l), round, visit);
}
template <class Real, class R, class Visit>
void sample_points(const Ray3<Real>& l, const R& round, const Visit& visit) {
  sample_linear_points(detail::as_linear(l), round, visit);
}
template <class Real, class R, class Visit>
void sample_points(const Segment3<Real>& s, const R& round, const Visit& visit) {
  sample_linear_points(detail::as_linear(s), round, visit);
}

// A circle or disk A (center c, unit normal m, radius ra) against the round B: the point of A
// nearest to B's center and A's rim crossings of B's plane; for a disk (a target with an
// interior) also the point of its chord in B's plane nearest to B's center.
template <class A, class R, class Visit, class Target = detail::target_t<A>>
void sample_points(const A& a, const R& round, const Visit& visit) {
  using Real = scalar_t<A>;
  constexpr bool filled = Target::interior;
  const Vec3<Real> m = unit_vector(a.normal);
  const Real ra = a.radius;
  const Vec3<Real> q = round.center - a.center;
  // q's part in A's plane as (m x q) x m, not q - (m.q) m: a cross product with m is orthogonal
  // to m to eps of its own length, where the difference keeps a normal component of eps |q|
  // whatever its in-plane part. With B's center on A's axis that rounding is all the difference
  // holds: its direction, scaled to the rim, is a point on A's axis, not on A (for a circle's
  // center on an annulus's axis, an upper bound of 2 - sqrt 2 for a distance of sqrt 6: within()
  // would say yes at 0.24 of the distance); near the axis (rho = 3e-17 |q|) it leaves A's plane by
  // eps |q| / rho. Orthogonal to m, any direction of it (noise included) gives a point of A's rim.
  const Vec3<Real> in_plane = m.cross(q).cross(m);
  const Real rho = in_plane.norm();
  if (filled && rho <= ra) {
    visit(Vec3<Real>(a.center + in_plane));
  } else if (rho > 0) {
    visit(Vec3<Real>(a.center + ra * (in_plane / rho)));
  } else {
    visit(Vec3<Real>(a.center + ra * Frame<Real>(m).u));
  }
  // Heights over B's plane along A: h(alpha) = hc + ra s cos(alpha) with alpha measured from e1,
  // the direction of steepest ascent in A's plane (s = |e1 unnormalized| = sin of the angle).
  // Planes parallel within rounding (g is then rounding noise, and g / s a direction that need
  // not lie in A's plane: sample points off A gave upper bounds below the distance) have no
  // crossing to sample. Otherwise e1 is made orthogonal to m again, so that every sample is a
  // point of A whatever the rounding of g.
  const Plane<Real> plane(round);
  const Vec3<Real> g = plane.n - plane.n.dot(m) * m;
  const Real s = g.norm();
  if (!(s > 64 * std::numeric_limits<Real>::epsilon()) || !(ra > 0)) return;
  Vec3<Real> e1 = g / s;
  e1 = unit_vector(Vec3<Real>(e1 - e1.dot(m) * m));
  const Vec3<Real> e2 = m.cross(e1);
  const Real hc = plane.height(a.center);
  const Real x = -hc / s;  // the chord's offset along e1
  if (!(std::abs(x) <= ra)) return;
  const Real half = std::sqrt(std::max(Real(0), (ra - x) * (ra + x)));
  const Vec3<Real> foot = a.center + x * e1;
  visit(Vec3<Real>(foot + half * e2));
  visit(Vec3<Real>(foot - half * e2));
  if (filled) {
    const Real y = std::min(std::max((round.center - foot).dot(e2), -half), half);
    visit(Vec3<Real>(foot + y * e2));
  }
}
// An arc: its ends, and its point toward the round's center where that angle falls on the arc.
template <class Real, class R, class Visit>
void sample_points(const Arc3<Real>& a, const R& round, const Visit& visit) {
  const detail::ArcSpan<Real> span(a);
  visit(span.world(a.center, a.radius, span.lo()));
  visit(span.world(a.center, a.radius, span.hi()));
  const Vec3<Real> q = span.frame.to_local(Vec3<Real>(round.center - a.center));
  if (q.x() != 0 || q.y() != 0) {
    const Real toward = std::atan2(q.y(), q.x());
    if (span.holds(toward)) visit(span.world(a.center, a.radius, toward));
  }
}
// An annulus: its outer disk's points that lie in the ring (not in the hole), and its inner rim's
// (the annulus's point where the disk's fell in the hole, docs/derivations/annulus.md "Convex shapes").
template <class Real, class R, class Visit>
void sample_points(const Annulus3<Real>& a, const R& round, const Visit& visit) {
  sample_points(detail::annulus_disk(a), round, [&](const Vec3<Real>& p) {
    if ((p - a.center).norm() >= a.inner_radius) visit(p);
  });
  sample_points(detail::inner_rim(a), round, visit);
}
template <class Real, class R, class Visit>
void sample_points(const BezierCurve3<Real>& b, const R&, const Visit& visit) {
  if (b.control.cols() == 0) return;
  visit(Vec3<Real>(b.control.col(0)));
  visit(Vec3<Real>(b.control.col(b.control.cols() - 1)));
  visit(b.at(Real(0.5)));
}

// The pair's length scale (for tolerances): the sizes and the separation of the bounding balls;
// a line or ray (unbounded) counts by its distance from the other's center, two of them by the
// separation of their origins. (Not 1: a scene of size 1e-20 would get a tolerance of 1e-14.)
template <class Real, class A, class B>
Real pair_scale(const Ball<Real>& ball_a, const A& a, const Ball<Real>& ball_b, const B& b) {
  Real s = 0;
  if (ball_a.bounded() && ball_b.bounded()) {
    s = std::max({ball_a.radius, ball_b.radius, (ball_a.center - ball_b.center).norm()});
  } else if (ball_b.bounded()) {
    // The point-piece query, not point_linear_distance: a ray whose origin lies 3e8 away cancels
    // to 0 in plain arithmetic, and within()'s tolerance would take the fallback scale 1.
    if constexpr (is_linear_v<core_t<A>>)
      s = std::max(ball_b.radius, Query<Vec3<Real>, core_t<A>>::distance(ball_b.center, core(a)) + sweep_of(a));
  } else if (ball_a.bounded()) {
    if constexpr (is_linear_v<core_t<B>>)
      s = std::max(ball_a.radius, Query<Vec3<Real>, core_t<B>>::distance(ball_a.center, core(b)) + sweep_of(b));
  } else {
    s = (ball_a.center - ball_b.center).norm() + sweep_of(a) + sweep_of(b);
  }
  return s > 0 ? s : Real(1);
}

// Bounds for any shape A against a round B.
template <class A, class R> DistanceBounds<scalar_t<R>> bounds_against_round(const A& a, const R& b) {
  using Real = scalar_t<R>;
  DistanceBounds<Real> out;
  const Ball<Real> ball_a = bounding_ball(a), ball_b = bounding_ball(b);
  out.scale = pair_scale(ball_a, a, ball_b, b);
  // Lower: balls.
  if (ball_a.bounded()) {
    const Real apart = (ball_a.center - ball_b.center).norm();
    out.lower = std::max(out.lower, apart - ball_a.radius - ball_b.radius);
    // Inside a circle's ball, away from its ring.
    if constexpr (is_circle_v<R>) out.lower = std::max(out.lower, b.radius - apart - ball_a.radius);
    if constexpr (is_circle_v<A>) out.lower = std::max(out.lower, a.radius - apart - ball_b.radius);
  } else if constexpr (is_linear_v<A>) {
    out.lower = std::max(out.lower, point_linear_distance(b.center, detail::as_linear(a)) - b.radius);
  }
  // Lower: plane sides.
  out.lower = std::max(out.lower, height_range(a, Plane<Real>(b)).gap());
  if constexpr (is_round_v<A>) out.lower = std::max(out.lower, height_range(b, Plane<Real>(a)).gap());
  // Upper: concrete points.
  if constexpr (is_disk_v<A> && is_disk_v<R>) {
    const detail::DiskContact<Real> contact =
        detail::disk_contact(a, detail::Round<Real>(b.center, b.normal, b.radius), b.radius);
    if (contact.intersect && !contact.borderline) {
      out.upper = 0;
      return out;
    }
  }
  sample_points(a, b, [&](const Vec3<Real>& p) { out.upper = std::min(out.upper, point_round_distance(p, b)); });
  if constexpr (is_round_v<A>) {
    sample_points(b, a, [&](const Vec3<Real>& p) { out.upper = std::min(out.upper, point_round_distance(p, a)); });
  }
  return out;
}

// Whether bounds are worth computing for a pair: one side is a circle or disk and the other is not
// a bare point (point-round distances are closed forms already cheaper than the bounds).
template <class A, class B> constexpr bool has_bounds_v =
    (is_round_v<A> || is_round_v<B>) && !is_point_v<A> && !is_point_v<B>;

// A shape moved by -anchor: only its points move (directions, normals and radii stay).
template <class Real> Vec3<Real> moved_by(const Vec3<Real>& p, const Vec3<Real>& o) { return p - o; }
template <class Real> Line3<Real> moved_by(const Line3<Real>& l, const Vec3<Real>& o) {
  return {l.origin - o, l.direction};
}
template <class Real> Ray3<Real> moved_by(const Ray3<Real>& r, const Vec3<Real>& o) {
  return {r.origin - o, r.direction};
}
template <class Real> Segment3<Real> moved_by(const Segment3<Real>& s, const Vec3<Real>& o) {
  return {s.p0 - o, s.p1 - o};
}
template <class R, class = detail::target_t<R>> R moved_by(const R& round, const Vec3<scalar_t<R>>& o) {
  return {round.center - o, round.normal, round.radius};
}
template <class Real> Arc3<Real> moved_by(const Arc3<Real>& a, const Vec3<Real>& o) {
  return {a.center - o, a.normal, a.radius, a.start, a.angle};
}
template <class Real> Annulus3<Real> moved_by(const Annulus3<Real>& a, const Vec3<Real>& o) {
  return {a.center - o, a.normal, a.inner_radius, a.outer_radius};
}
template <class Real> BezierCurve3<Real> moved_by(const BezierCurve3<Real>& b, const Vec3<Real>& o) {
  BezierCurve3<Real> out = b;
  out.control.colwise() -= o;
  return out;
}

// Bounds on the distance between the cores of a and b, then the sweeps taken off.
template <class A, class B> DistanceBounds<scalar_t<core_t<A>>> distance_bounds(const A& a, const B& b) {
  using Real = scalar_t<core_t<A>>;
  using CA = core_t<A>;
  using CB = core_t<B>;
  static_assert(has_bounds_v<CA, CB>, "circledist: no bounds for this pair of shapes");
  DistanceBounds<Real> out;
  // In a frame at the round's center (each coordinate rounded once, exactly where the shapes are
  // near it): in world coordinates a scene 5e10 from the origin carries eps * 5e10 = 1e-5 into
  // every bound, and a gap of 1e-6 was decided 'within' by an upper bound below it.
  // What is still far from it (a line's origin 1e11 along the line, a far control point) carries
  // its coordinates' rounding into the bounds: `rounding`, which judge() adds to its margin.
  const auto frame_bounds = [&](const auto& piece, const auto& round) {
    const Vec3<Real> anchor = round.center;
    const auto moved = moved_by(piece, anchor);
    DistanceBounds<Real> bounds = bounds_against_round(moved, moved_by(round, anchor));
    bounds.rounding = 64 * std::numeric_limits<Real>::epsilon() * std::max(extent(moved), round.radius);
    return bounds;
  };
  if constexpr (is_round_v<CB>) {
    out = frame_bounds(core(a), core(b));
  } else {
    out = frame_bounds(core(b), core(a));
  }
  const Real ra = sweep_of(a), rb = sweep_of(b);
  out.lower = (out.lower - ra) - rb;
  out.upper = swept_distance(out.upper, ra, rb);
  out.scale = out.scale + ra + rb;
  return out;
}

}  // namespace circledist
