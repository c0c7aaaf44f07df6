// Bezier curves against arcs (bezier_arc.hpp) and against annuli (annulus.hpp), against long-double
// references that use no library code: the curve evaluated by de Casteljau in long double
// (ref::bezier_at), the distance from its point to the arc or the annulus in closed form (an
// arc: the ring's where the point's angle, from the arc's own u = the start's projection and
// v = n x u, falls in [0, angle], else the nearer end; an annulus: |z| over the ring, else the
// nearer rim's), and the minimum over t in [0, 1] by dense sampling and zooming (ref::minimize).
// Bar in double: |error| <= 1e-12 * max(true distance, largest size: the radius or the curve's
// farthest control point from the center); long double 1e-15. Also: distance() and
// closest_points().distance equal to the bit, both argument orders equal to the bit, the points
// on their shapes at the distance apart, the parameters give the points, every root policy,
// within/intersects/distance_if_within, `unique` where the geometry says it, an arc of angle
// 2 pi its circle's answer to the bit, an annulus of inner radius 0 the disk's and of inner = outer
// the circle's.
#include "random.hpp"
#include "round_reference.hpp"

#include <circledist/circledist.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace test_bezier_arc {

using Arc = Arc3<double>;
using Annulus = Annulus3<double>;
using Curve = BezierCurve3<double>;

// Random draws: check::scaled(n) of them (a longer run: CIRCLEDIST_TEST_SCALE=10, check.hpp).

namespace {

using ref::kTurn;
std::map<std::string, int> counts;

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// ---------------------------------------------------------------------------------------------
// The references.

// The arc relative to an origin, in its own frame, with its distance in closed form: ref::Arc.
using RefArc = ref::Arc;

// The annulus relative to an origin: |z| over the ring, else the nearer rim's distance.
struct RefAnnulus {
  V3 c, n;
  LD inner, outer;
  RefAnnulus(const Annulus& a, const V3d& origin)
      : c(a.center.cast<LD>() - origin.cast<LD>()),
        n(a.normal.cast<LD>() / a.normal.cast<LD>().norm()),
        inner(a.inner_radius),
        outer(a.outer_radius) {}
  LD distance(const V3& p) const {
    const V3 d = p - c;
    const LD z = d.dot(n);
    const LD rho = (d - z * n).norm();
    if (rho < inner) return std::hypot(z, inner - rho);
    if (rho > outer) return std::hypot(z, rho - outer);
    return std::abs(z);
  }
};

LD ref_curve_arc(const Curve& b, const Arc& a) {
  const RefArc ra(a, a.center);
  return ref::minimize([&](LD t) { return ra.distance(ref::bezier_at(b, a.center, t)); }, 0, 1, false);
}
LD ref_curve_annulus(const Curve& b, const Annulus& a) {
  const RefAnnulus ra(a, a.center);
  return ref::minimize([&](LD t) { return ra.distance(ref::bezier_at(b, a.center, t)); }, 0, 1, false);
}
LD ref_point_arc(const V3d& p, const Arc& a) {
  return RefArc(a, a.center).distance(p.cast<LD>() - a.center.cast<LD>());
}
LD ref_point_annulus(const V3d& p, const Annulus& a) {
  return RefAnnulus(a, a.center).distance(p.cast<LD>() - a.center.cast<LD>());
}

// ---------------------------------------------------------------------------------------------
// The checks.

template <class Roots> const char* policy_name();
template <> const char* policy_name<Bracketing>() { return "bracketing"; }
template <> const char* policy_name<EigenCompanion>() { return "companion"; }
template <> const char* policy_name<EigenPolished>() { return "polished"; }
template <> const char* policy_name<EigenPolynomialSolver>() { return "eigen"; }

double size_of(const Arc& a) { return a.radius; }
double size_of(const Annulus& a) { return a.outer_radius; }
V3d center_of(const Arc& a) { return a.center; }
V3d center_of(const Annulus& a) { return a.center; }
LD off(const V3d& p, const Arc& a) { return ref_point_arc(p, a); }
LD off(const V3d& p, const Annulus& a) { return ref_point_annulus(p, a); }
LD ref_of(const Curve& b, const Arc& a) { return ref_curve_arc(b, a); }
LD ref_of(const Curve& b, const Annulus& a) { return ref_curve_annulus(b, a); }

// The shape's parameter gives its point: an arc's (t, 0) with t in [0, angle] (its own frame),
// an annulus's (s, theta) (the library's frame, as a disk's) with s in the ring.
double param_gap(const Arc& a, const V3d& point, const Vec2<double>& p) {
  const bool in_range = p.x() >= 0 && p.x() <= std::min(a.angle, kTurn) && p.y() == 0;
  if (!in_range) return std::numeric_limits<double>::infinity();
  return double((RefArc(a, V3d::Zero()).at(p.x()) - point.cast<LD>()).norm());
}
double param_gap(const Annulus& a, const V3d& point, const Vec2<double>& p) {
  const double slack = 1e-12 * a.outer_radius;
  if (!(p.x() >= a.inner_radius - slack && p.x() <= a.outer_radius + slack))
    return std::numeric_limits<double>::infinity();
  const Frame<double> f(a.normal);
  return (a.center + p.x() * (std::cos(p.y()) * f.u + std::sin(p.y()) * f.v) - point).norm();
}

// One case with one root policy: distance and closest points in both orders, equal to the bit,
// within the bar of `truth`; the points and parameters; `unique` when asked (1 or 0).
template <class Roots = DefaultRoots, class S> void curve_case(const std::string& family, const char* name,
                                                               const Curve& b, const S& s, LD truth, int unique = -1,
                                                               double bar = 1e-12) {
  const std::string kind = family + " " + policy_name<Roots>();
  ++counts[kind];
  const double size = std::max(size_of(s), curve_size(b, center_of(s)));
  const Result<double> r = closest_points<Roots>(b, s), back = closest_points<Roots>(s, b);
  const double d1 = distance<Roots>(b, s), d2 = distance<Roots>(s, b);
  expect_distance(kind, name, d1, truth, size, bar);
  expect_distance(kind, name, r.distance, truth, size, bar);
  const bool agree = same_bits(d1, d2) && same_bits(d1, r.distance) && same_bits(d1, back.distance);
  if (!agree)
    std::printf("  %s / %s: distance %.17g %.17g, closest %.17g %.17g\n", kind.c_str(), name, d1, d2, r.distance,
                back.distance);
  check::record(agree, name, __FILE__, __LINE__);
  const double world = 8 * std::numeric_limits<double>::epsilon() * std::max(r.point_a.norm(), r.point_b.norm());
  const double tol = bar * std::max(size, r.distance) + world;
  const double gap = (r.point_a - r.point_b).norm();
  const double on_s = double(off(r.point_b, s));
  const double on_curve = (b.at(r.param_a.x()) - r.point_a).norm();
  const double param_off = param_gap(s, r.point_b, r.param_b);
  const bool ok = std::abs(gap - r.distance) <= tol && on_s <= tol && on_curve <= tol && param_off <= tol &&
                  r.param_a.x() >= 0 && r.param_a.x() <= 1 && back.point_a == r.point_b && back.point_b == r.point_a;
  if (!ok)
    std::printf("  %s / %s: |a-b| %.17g vs %.17g, off shape %.3g, off curve %.3g, param off %.3g\n", kind.c_str(), name,
                gap, r.distance, on_s, on_curve, param_off);
  check::record(ok, name, __FILE__, __LINE__);
  if (unique >= 0) {
    expect_unique(name, r.unique, unique == 1);
    expect_unique(name, back.unique, unique == 1);
  }
}

template <class S> void effects_case(const std::string& family, const char* name, const Curve& b, const S& s);

// Every policy, and the effects (within, intersects, distance_if_within: decided by the bounds
// or by the distance, so they must agree with it).
template <class S>
void full_case(const std::string& family, const char* name, const Curve& b, const S& s, LD truth, int unique = -1) {
  curve_case<Bracketing>(family, name, b, s, truth, unique);
  curve_case<EigenCompanion>(family, name, b, s, truth, unique);
  curve_case<EigenPolished>(family, name, b, s, truth, unique);
  curve_case<EigenPolynomialSolver>(family, name, b, s, truth, unique);
  // (The annulus has no effects yet: sweep.hpp and bounds.hpp do not know it, as for every
  // annulus pair.)
  if constexpr (std::is_same_v<S, Arc>) effects_case(family, name, b, s);
}

template <class S> void effects_case(const std::string& family, const char* name, const Curve& b, const S& s) {
  const double d = distance(b, s), size = std::max(size_of(s), curve_size(b, center_of(s)));
  const double margin = 1e-9 * std::max(size, d);
  bool ok = within(b, s, d + margin) && within(s, b, d + margin);
  if (d > 2 * margin) ok = ok && !within(b, s, d - margin) && !intersects(b, s) && !intersects(s, b);
  const double dw = distance_if_within(b, s, 2 * d + 1);
  ok = ok && std::abs(dw - d) <= 1e-12 * std::max(size, d);
  if (!ok)
    std::printf("  %s / %s: within/intersects/distance_if_within disagree with %.17g\n", family.c_str(), name, d);
  check::record(ok, name, __FILE__, __LINE__);
}

// ---------------------------------------------------------------------------------------------
// Shapes.

struct Draw : ShapeDraw {
  using ShapeDraw::ShapeDraw;
  Annulus annulus() {
    const double outer = radius();
    return {vec(), vec(), outer * (0.05 + 0.9 * uniform(rng)), outer};
  }
  Curve curve(int degree, const V3d& around, double spread = 1) {
    Curve c;
    c.control.resize(3, degree + 1);
    for (int i = 0; i <= degree; ++i) c.control.col(i) = around + spread * vec();
    return c;
  }
};

Curve curve_of(std::initializer_list<V3d> points) { return bezier(points); }

// The arc of circle (c, n, r) from canonical angle t0 over `angle` (the library's Frame, so that a
// case can put a curve's point exactly at its end).
Arc arc_from(const V3d& c, const V3d& n, double r, double t0, double angle) {
  const Frame<double> f(n);
  return {c, n, r, std::cos(t0) * f.u + std::sin(t0) * f.v, angle};
}
V3d circle_point(const V3d& c, const V3d& n, double r, double t) {
  const Frame<double> f(n);
  return c + r * (std::cos(t) * f.u + std::sin(t) * f.v);
}

Curve moved(const Curve& b, const V3d& t) { return translated(b, t); }
Arc moved(const Arc& a, const V3d& t) { return {a.center + t, a.normal, a.radius, a.start, a.angle}; }
Annulus moved(const Annulus& a, const V3d& t) { return {a.center + t, a.normal, a.inner_radius, a.outer_radius}; }

// A curve of every degree 1..7 around the shape, and each moved with it by 1e6 and 1e8.
template <class S> void degrees_and_translated(const std::string& family, const S& s, std::uint64_t seed) {
  Draw d(seed);
  for (int degree = 1; degree <= 7; ++degree) {
    const Curve b = d.curve(degree, center_of(s) + 0.5 * d.vec());
    full_case(family, "degree 1..7", b, s, ref_of(b, s));
    for (double shift : {1e6, 1e8}) {
      const V3d t = shift * V3d(0.6, -1, 0.2);
      full_case(family, shift == 1e6 ? "translated 1e6" : "translated 1e8", moved(b, t), moved(s, t),
                ref_of(moved(b, t), moved(s, t)));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Bezier against arc.

// Random shapes (`shape_of(draw)`) against random curves of degree 1 + k % 7 around them.
template <class ShapeOf> void random_cases(const std::string& family, std::uint64_t seed, const ShapeOf& shape_of) {
  Draw d(seed);
  for (int k = 0; k < check::scaled(140); ++k) {
    const auto s = shape_of(d);
    const Curve b = d.curve(1 + k % 7, s.center + 0.7 * d.vec());
    full_case(family, "random", b, s, ref_of(b, s));
  }
}

void arc_random() {
  random_cases("bezier-arc", 1901, [](Draw& d) { return d.arc(); });
}

void arc_hard() {
  const V3d c(0.3, -0.2, 0.1), n = unit(0.2, -0.5, 1);
  const Frame<double> f(n);
  const double r = 1.3;
  const Arc a = arc_from(c, n, r, 0.4, 2.0);
  const V3d e0 = circle_point(c, n, r, 0.4), e1 = circle_point(c, n, r, 2.4);
  const V3d mid = circle_point(c, n, r, 1.4);
  const V3d tangent = -std::sin(1.4) * f.u + std::cos(1.4) * f.v, radial = (mid - c).normalized();
  {
    // A curve's end exactly at the arc's end, leaving it outward, and one tangent there.
    const Curve from_end = curve_of({e1, e1 + 0.5 * (e1 - c) + 0.3 * n, e1 + (e1 - c) - 0.2 * n});
    full_case("bezier-arc", "curve end at the arc end", from_end, a, 0);
    const V3d t1 = (-std::sin(2.4) * f.u + std::cos(2.4) * f.v);
    const Curve tangent_end = curve_of({e1, e1 + 0.4 * t1, e1 + 0.8 * t1 + 0.3 * n, e1 + 1.2 * t1 + 0.1 * (e1 - c)});
    full_case("bezier-arc", "curve end at the arc end, tangent", tangent_end, a, 0);
  }
  {
    // The arc's end on the curve's interior: a quadratic through e0 at t = 1/2 (up to rounding).
    const V3d p0 = e0 + V3d(0.5, 0.7, -0.4), p2 = e0 - V3d(0.6, 0.2, -0.5);
    const Curve through = curve_of({p0, 2 * e0 - (p0 + p2) / 2, p2});
    full_case("bezier-arc", "arc end on the curve", through, a, ref_curve_arc(through, a));
    // The same curve lifted: the end is the nearest arc point, the curve's stationary point
    // against it the minimum ((q - E).q' = 0).
    const Curve lifted = translated(through, 0.05 * n);
    full_case("bezier-arc", "arc end below the curve", lifted, a, ref_curve_arc(lifted, a));
  }
  {
    // The curve's end point exactly at a tangency with the arc's interior: it touches the arc
    // at `mid` and leaves outward (distance 0), and lifted off the plane (distance 1e-3).
    const Curve touch = curve_of({mid, mid + 0.5 * tangent, mid + tangent + 0.3 * radial});
    full_case("bezier-arc", "end at a tangency", touch, a, 0);
    const Curve lifted = translated(touch, 1e-3 * n);
    full_case("bezier-arc", "end at a tangency, lifted", lifted, a, ref_curve_arc(lifted, a));
    // A curve tangent to the arc at its interior point (a double root of the ring's equation),
    // outside the circle by 1e-9.
    const Curve kiss =
        curve_of({mid - tangent + 0.4 * radial, mid + 1e-9 * radial - 0.2 * radial, mid + tangent + 0.4 * radial});
    full_case("bezier-arc", "tangent inside the arc", kiss, a, ref_curve_arc(kiss, a));
  }
  {
    // Planar: coplanar with the arc, crossing it (0), crossing the circle off the arc (the end
    // nearer), and inside the circle.
    const auto planar = [&](double x0, double y0, double x1, double y1, double x2, double y2, double x3, double y3) {
      return curve_of(
          {c + x0 * f.u + y0 * f.v, c + x1 * f.u + y1 * f.v, c + x2 * f.u + y2 * f.v, c + x3 * f.u + y3 * f.v});
    };
    const Curve across = planar(0, 0, 0.4, 1.2, 0.9, 1.5, 1.8, 1.9);
    full_case("bezier-arc", "coplanar, across the arc", across, a, 0);
    const Curve off_arc = planar(0.2, -0.3, 1.0, -1.9, 1.9, -0.8, 2.3, -0.2);
    full_case("bezier-arc", "coplanar, across the circle off the arc", off_arc, a, ref_curve_arc(off_arc, a));
    const Curve inside = planar(-0.5, -0.5, 0.1, 0.6, 0.5, -0.2, 0.2, 0.3);
    full_case("bezier-arc", "coplanar, inside the circle", inside, a, ref_curve_arc(inside, a));
  }
  {
    // Along the axis: every arc point as close (unique false); crossing the axis.
    const Curve axis = curve_of({c - 0.7 * n, c + 0.2 * n, c + 1.1 * n});
    full_case("bezier-arc", "along the axis", axis, a, r, 0);
    const Curve cross = curve_of({c + 0.8 * n - 0.5 * f.u, c + 0.8 * n + 0.1 * f.v, c + 0.8 * n + 0.5 * f.u});
    full_case("bezier-arc", "across the axis", cross, a, ref_curve_arc(cross, a));
  }
  {
    // Translated scenes, extreme size ratios, every degree.
    degrees_and_translated("bezier-arc", a, 7);
    const Arc tiny = arc_from(V3d(0.2, 0.1, 0.3), n, 1e-6, 1.0, 2.5);
    const Curve unit_curve = curve_of({V3d(-1, 0.5, 0.2), V3d(0.3, -1, 0.4), V3d(1, 1, -0.3)});
    full_case("bezier-arc", "arc 1e-6 of the curve", unit_curve, tiny, ref_curve_arc(unit_curve, tiny));
    const Arc huge = arc_from(V3d(0, 0, 0), V3d(0, 0, 1), 1e6, -0.1, 0.2);
    const Curve near_rim = curve_of({V3d(1e6 - 0.5, -0.3, 0.2), V3d(1e6 + 0.2, 0.4, -0.3), V3d(1e6 + 0.7, 0.1, 0.5)});
    full_case("bezier-arc", "arc 1e6 of the curve", near_rim, huge, ref_curve_arc(near_rim, huge));
    const Curve long_curve = curve_of({V3d(-1e5, 3, 0.2), V3d(0.1, 2.1, -0.5), V3d(1e5, -4, 0.3)});
    const Arc unit_arc = arc_from(V3d(0, 0, 0), unit(0.1, 0.3, 1), 1, 0.5, 2);
    full_case("bezier-arc", "curve 1e5 of the arc", long_curve, unit_arc, ref_curve_arc(long_curve, unit_arc));
  }
  {
    // Tiny angles; the arc a point (radius 0); an empty curve.
    const Curve b = curve_of({V3d(1, 1, 1), V3d(2, -1, 0), V3d(0.5, 0.4, -1)});
    const Arc sliver = arc_from(c, n, r, 0.4, 1e-6);
    full_case("bezier-arc", "angle 1e-6", b, sliver, ref_curve_arc(b, sliver));
    const Arc point{c, n, 0, f.u, 1};
    const Result<double> rp = closest_points(b, point);
    CHECK(distance(b, point) == distance(b, c) && rp.distance == distance(b, c) && rp.point_b == c);
    Curve empty;
    CHECK(std::isinf(distance(empty, a)) && std::isinf(closest_points(a, empty).distance));
  }
}

// Curves wandering around an arc's end, off its angles: a minimum against the end (a root of
// (q - E).q' = 0) that no other candidate's basin holds. (Without the ends' equations, 313 of
// 20000 such draws of degrees 1..7 were answered up to 0.22 too far; these draws hold such cases.)
void arc_near_ends() {
  Draw d(5);
  for (int k = 0; k < check::scaled(70); ++k) {
    const Arc a{V3d(0, 0, 0), V3d(0, 0, 1), 1, V3d(1, 0, 0), 0.2 + 2 * d.uniform(d.rng)};
    const V3d e = k % 2 ? V3d(1, 0, 0) : V3d(std::cos(a.angle), std::sin(a.angle), 0);
    const Curve b = d.curve(1 + k % 7, e, 0.6);
    full_case("bezier-arc", "around an end", b, a, ref_curve_arc(b, a));
  }
}

// An arc of angle 2 pi (or more) is its circle: distance and points to the bit, the parameter
// the circle's angle less the start's.
void arc_whole() {
  Draw d(33);
  for (int k = 0; k < 20; ++k) {
    Arc a = d.arc();
    a.angle = k % 2 ? kTurn : 7.0;
    const Circle3<double> circle{a.center, a.normal, a.radius};
    const Curve b = d.curve(1 + k % 7, a.center + 0.7 * d.vec());
    const Result<double> ra = closest_points(b, a), rc = closest_points(b, circle);
    const bool same = same_bits(distance(b, a), distance(b, circle)) &&
                      same_bits(distance(a, b), distance(circle, b)) && same_bits(ra.distance, rc.distance) &&
                      ra.point_a == rc.point_a && ra.point_b == rc.point_b && ra.unique == rc.unique;
    check::record(same, "whole arc = circle", __FILE__, __LINE__);
    ++counts["bezier-arc whole"];
    const double off_param = param_gap(a, ra.point_b, ra.param_b);
    check::record(off_param <= 1e-12 * std::max(a.radius, ra.distance) + 1e-15 * ra.point_b.norm(), "whole arc param",
                  __FILE__, __LINE__);
  }
}

// ---------------------------------------------------------------------------------------------
// Bezier against annulus.

void annulus_random() {
  random_cases("bezier-annulus", 1902, [](Draw& d) { return d.annulus(); });
}

void annulus_hard() {
  const V3d c(-0.2, 0.4, 0.3), n = unit(-0.3, 0.2, 1);
  const Frame<double> f(n);
  const Annulus a{c, n, 0.6, 1.5};
  const auto at = [&](double x, double y, double z) { return V3d(c + x * f.u + y * f.v + z * n); };
  {
    // Through the hole along the axis: every inner-rim point as close (unique false); a curve
    // crossing the hole above the plane; one dipping through the hole.
    const Curve axis = curve_of({at(0, 0, -0.8), at(0, 0, 0.1), at(0, 0, 0.9)});
    full_case("bezier-annulus", "through the hole along the axis", axis, a, 0.6L, 0);
    const Curve over = curve_of({at(-0.5, 0.1, 0.3), at(0, 0.2, 0.5), at(0.5, -0.1, 0.2)});
    full_case("bezier-annulus", "across the hole", over, a, ref_curve_annulus(over, a));
    const Curve dip = curve_of({at(-0.3, 0.1, 0.6), at(0, 0, -1.2), at(0.3, -0.2, 0.6)});
    full_case("bezier-annulus", "dipping through the hole", dip, a, ref_curve_annulus(dip, a));
  }
  {
    // Coplanar: across the ring (0), in the hole (the inner rim), across the hole from rim to rim
    // (0), outside the outer rim.
    const Curve across = curve_of({at(0.1, 0.1, 0), at(0.9, 0.3, 0), at(1.8, -0.2, 0)});
    full_case("bezier-annulus", "coplanar, across the ring", across, a, 0);
    const Curve hole = curve_of({at(-0.2, 0.1, 0), at(0.1, 0.3, 0), at(0.3, -0.2, 0), at(0.1, -0.3, 0)});
    full_case("bezier-annulus", "coplanar, in the hole", hole, a, ref_curve_annulus(hole, a));
    const Curve outside = curve_of({at(1.7, -1, 0), at(2.6, 0, 0), at(1.7, 1, 0)});
    full_case("bezier-annulus", "coplanar, outside", outside, a, ref_curve_annulus(outside, a));
  }
  {
    // Hovering over the ring: the lowest point (z' = 0) over the ring is the distance; a curve
    // whose end point is exactly on the outer rim, tangent to it; the end on the inner rim.
    const Curve dome = curve_of({at(-1.2, 0.5, 0.8), at(-0.9, 0.6, -0.4), at(-0.6, 0.7, 0.9)});
    full_case("bezier-annulus", "over the ring", dome, a, ref_curve_annulus(dome, a));
    const V3d rim = at(1.5, 0, 0);
    const Curve tangent_end = curve_of({rim, rim + 0.5 * f.v, rim + f.v + 0.3 * f.u});
    full_case("bezier-annulus", "end on the outer rim, tangent", tangent_end, a, 0);
    const V3d inner = at(0, 0.6, 0);
    const Curve from_inner = curve_of({inner, inner + 0.2 * n - 0.1 * f.v, inner - 0.3 * f.v + 0.5 * n});
    full_case("bezier-annulus", "end on the inner rim", from_inner, a, 0);
    const Curve lifted = translated(tangent_end, 1e-3 * n);
    full_case("bezier-annulus", "end over the outer rim, lifted", lifted, a, ref_curve_annulus(lifted, a));
  }
  {
    degrees_and_translated("bezier-annulus", a, 8);
    const Annulus tiny{V3d(0.2, 0.1, 0.3), n, 5e-7, 1e-6};
    const Curve unit_curve = curve_of({V3d(-1, 0.5, 0.2), V3d(0.3, -1, 0.4), V3d(1, 1, -0.3)});
    full_case("bezier-annulus", "annulus 1e-6 of the curve", unit_curve, tiny, ref_curve_annulus(unit_curve, tiny));
    const Annulus huge{V3d(0, 0, 0), V3d(0, 0, 1), 0.5e6, 1e6};
    const Curve near_rim = curve_of({V3d(1e6 - 0.5, -0.3, 0.2), V3d(1e6 + 0.2, 0.4, -0.3), V3d(1e6 + 0.7, 0.1, 0.5)});
    full_case("bezier-annulus", "annulus 1e6 of the curve", near_rim, huge, ref_curve_annulus(near_rim, huge));
    const Curve long_curve = curve_of({V3d(-1e5, 0.3, 2), V3d(0.1, 0.2, -2.5), V3d(1e5, -0.4, 3)});
    const Annulus unit_annulus{V3d(0, 0, 0), unit(0.1, 0.3, 1), 0.5, 1};
    full_case("bezier-annulus", "curve 1e5 of the annulus", long_curve, unit_annulus,
              ref_curve_annulus(long_curve, unit_annulus));
    Curve empty;
    CHECK(std::isinf(distance(empty, a)) && std::isinf(closest_points(a, empty).distance));
  }
}

// An annulus of inner radius 0 is its disk, of inner = outer its circle: the same answers to the bit.
void annulus_degenerate() {
  Draw d(34);
  for (int k = 0; k < 20; ++k) {
    const Annulus a = d.annulus();
    const Curve b = d.curve(1 + k % 7, a.center + 0.7 * d.vec());
    const Annulus as_disk{a.center, a.normal, 0, a.outer_radius},
        as_circle{a.center, a.normal, a.outer_radius, a.outer_radius};
    const Disk3<double> disk{a.center, a.normal, a.outer_radius};
    const Circle3<double> circle{a.center, a.normal, a.outer_radius};
    const Result<double> rd = closest_points(b, as_disk), rk = closest_points(b, disk);
    const Result<double> rc = closest_points(b, as_circle), rl = closest_points(b, circle);
    const bool same = same_bits(distance(b, as_disk), distance(b, disk)) && same_bits(rd.distance, rk.distance) &&
                      rd.point_a == rk.point_a && rd.point_b == rk.point_b && rd.param_b == rk.param_b &&
                      same_bits(distance(as_circle, b), distance(circle, b)) && same_bits(rc.distance, rl.distance) &&
                      rc.point_a == rl.point_a && rc.point_b == rl.point_b && rc.param_b.x() == a.outer_radius;
    check::record(same, "annulus inner 0 = disk, inner = outer = circle", __FILE__, __LINE__);
    ++counts["bezier-annulus degenerate"];
  }
}

// Curves crossing the annulus's face inside the ring (true distance 0) in long double, every
// policy: the interior candidates where the height z = 0 are refined on the curve
// (push_refined_curve_height_roots, bezier.hpp). Degree-2 arches elevated to degree 2..7, their
// height linear in t (the height polynomial's higher coefficients rounding noise: the companion
// and eigen policies' roots of such a polynomial were 1e-14 off, and the answer up to 7e-15 x the
// outer radius, tests/accuracy/test_regressions.py), and random curves through the point at t = 1/2; the
// point anywhere in the ring or 1e-9..1e-4 x outer from a rim, the crossing 0.1..1.4 rad from
// the plane, so the inputs' rounding (1e-16) moves it by far less than its margin: the truth is
// 0. Also the two scenes of the long run (their 50-digit references below 1e-30). Bar 1e-15 x
// the outer radius; distance() and closest_points().distance equal to the bit, both orders.
template <class Roots> void crossing_case(const char* name, const BezierCurve3<LD>& b, const Annulus3<LD>& a) {
  const std::string kind = std::string("bezier-annulus crossing ") + policy_name<Roots>();
  ++counts[kind];
  const LD d1 = distance<Roots>(b, a), d2 = distance<Roots>(a, b);
  const LD d3 = closest_points<Roots>(b, a).distance, d4 = closest_points<Roots>(a, b).distance;
  const LD relative = d1 / a.outer_radius;
  worst[kind] = std::max(worst[kind], double(relative));
  const bool ok = relative <= 1e-15L && same_bits(d1, d2) && same_bits(d1, d3) && same_bits(d1, d4);
  if (!ok)
    std::printf("  %s / %s: %.3Lg %.3Lg %.3Lg %.3Lg (outer %.3Lg)\n", kind.c_str(), name, d1, d2, d3, d4,
                a.outer_radius);
  check::record(ok, name, __FILE__, __LINE__);
}

template <class Roots> void crossing_policy(const char* name, const Curve& b, const Annulus& a) {
  BezierCurve3<LD> bl;
  bl.control = b.control.cast<LD>();
  const Annulus3<LD> al{a.center.cast<LD>(), a.normal.cast<LD>(), a.inner_radius, a.outer_radius};
  crossing_case<Roots>(name, bl, al);
}

void crossing_all(const char* name, const Curve& b, const Annulus& a) {
  crossing_policy<Bracketing>(name, b, a);
  crossing_policy<EigenCompanion>(name, b, a);
  crossing_policy<EigenPolished>(name, b, a);
  crossing_policy<EigenPolynomialSolver>(name, b, a);
}

Curve elevated(const std::vector<V3d>& lower, int degree) {
  const std::vector<V3d> p = test_random::elevated(lower, degree);
  Curve b;
  b.control.resize(3, int(p.size()));
  for (int i = 0; i < int(p.size()); ++i) b.control.col(i) = p[i];
  return b;
}

void annulus_crossing() {
  {
    // ann_inner_tangent/1/166 (crossing 6e-12 outside the hole) and ann_tangent/1/760 (a 1e-6
    // hole): companion and eigen answered 9.7e-16 and 2.1e-14.
    const Curve by_the_hole = curve_of({V3d(-0.7101942833985928, -0.39068014472128004, -0.32302582640059707),
                                        V3d(-0.6991227002034476, -0.480351626562345, -0.07555890804429077),
                                        V3d(-0.7760518042453024, -0.56429297580268, 0.08499566795781921),
                                        V3d(-0.9409815955241572, -0.642504192442285, 0.15863790160573277),
                                        V3d(-1.193912074040012, -0.7149852764811601, 0.14536779289944998)});
    crossing_all("by the hole", by_the_hole,
                 Annulus{V3d(-0.5042840475030932, -0.5819890339998373, 0.35340234813746907),
                         V3d(-0.33713368487841255, 0.04617337810703753, 0.3443995953674146), 0.44428672172024514,
                         0.796808950921382});
    const Curve tiny_hole = curve_of({V3d(1.9410124537551017, 3.753351541927369, 1.546877829541188),
                                      V3d(1.5903067891120657, 1.9164191936285198, 1.148426524700254),
                                      V3d(1.204019489879799, 0.8481093996068911, 1.4815797077809183),
                                      V3d(0.7821505560583013, 0.548422159862483, 2.5463373787831807),
                                      V3d(0.32469998764757324, 1.0173574743952956, 4.342699537707042)});
    crossing_all("tiny hole", tiny_hole,
                 Annulus{V3d(1.2892608342819993, -0.9932455752506648, -0.27109272677878005),
                         V3d(0.17834981144890788, -3.126647222115497, 3.2935248372402555), 1.0466447969211326e-06,
                         3.0744569231399432});
  }
  Draw d(35);
  for (int k = 0; k < check::scaled(200); ++k) {
    const V3d c = d.vec(), n = d.vec().normalized();
    const double outer = 0.2 + 2.8 * d.uniform(d.rng);
    const double inner = outer * (k % 5 == 0 ? 1e-6 : 0.05 + 0.85 * d.uniform(d.rng));
    const Frame<double> f(n);
    const double phi = kTurn * d.uniform(d.rng);
    const V3d r = std::cos(phi) * f.u + std::sin(phi) * f.v, t = -std::sin(phi) * f.u + std::cos(phi) * f.v;
    const double margin = outer * std::pow(10.0, -9 + 5 * d.uniform(d.rng));
    const double rho = k % 3 == 0   ? inner + (outer - inner) * d.uniform(d.rng)
                       : k % 3 == 1 ? inner + margin
                                    : outer - margin;
    const V3d y = c + rho * r;
    const double psi = 0.1 + 1.3 * d.uniform(d.rng);
    const V3d dir = std::cos(psi) * t + std::sin(psi) * n;
    const int degree = 1 + k % 7;
    Curve b;
    if (k % 2 == 0) {
      const double length = outer * (0.2 + 1.3 * d.uniform(d.rng));
      const V3d bulge = -r * rho * (0.05 + 0.45 * d.uniform(d.rng));
      b = elevated({y - length * dir - bulge, y + bulge, y + length * dir - bulge}, std::max(degree, 2));
    } else {
      // Through y at t = 1/2, crossing steeply: a random curve whose middle is moved onto y,
      // then given the height slope s there by adding s (t - 1/2) n (control point i moved by
      // s (i / degree - 1/2) n: the point at 1/2 stays), |s| at least a fifth of the in-plane
      // speed there (the crossing 0.197 rad or more from the plane).
      b = d.curve(degree, y, outer);
      const V3d mid = b.at(0.5);
      for (int i = 0; i <= degree; ++i) b.control.col(i) += y - mid;
      V3d speed = V3d::Zero();  // P'(1/2): the hodograph's control points, averaged by de Casteljau
      {
        std::vector<V3d> h(degree);
        for (int i = 0; i < degree; ++i) h[i] = degree * (b.control.col(i + 1) - b.control.col(i));
        for (int m = degree - 1; m > 0; --m)
          for (int i = 0; i < m; ++i) h[i] = 0.5 * (h[i] + h[i + 1]);
        speed = h[0];
      }
      const double along = speed.dot(n), in_plane = (speed - along * n).norm();
      const double slope = (k % 4 == 1 ? 1 : -1) * std::max(in_plane, outer) * (0.2 + 1.8 * d.uniform(d.rng));
      for (int i = 0; i <= degree; ++i) b.control.col(i) += (slope - along) * (double(i) / degree - 0.5) * n;
    }
    crossing_all(k % 2 == 0 ? "elevated arch through the ring" : "random curve through the ring", b,
                 Annulus{c, n, inner, outer});
  }
}

// ---------------------------------------------------------------------------------------------

void precision_tests() {
  const Arc a = arc_from(V3d(0.1, 0.2, 0.3), unit(1, -2, 0.5), 1.3, 0.3, 2.5);
  const Annulus an{V3d(0.1, 0.2, 0.3), unit(1, -2, 0.5), 0.5, 1.3};
  Draw d(5);
  for (int k = 0; k < 8; ++k) {
    const Curve b = d.curve(1 + k % 7, a.center + 0.6 * d.vec());
    BezierCurve3<LD> bl;
    bl.control = b.control.cast<LD>();
    const Arc3<LD> al{a.center.cast<LD>(), a.normal.cast<LD>(), a.radius, a.start.cast<LD>(), a.angle};
    const Annulus3<LD> anl{an.center.cast<LD>(), an.normal.cast<LD>(), an.inner_radius, an.outer_radius};
    const double size_a = std::max(a.radius, curve_size(b, a.center)),
                 size_n = std::max(an.outer_radius, curve_size(b, an.center));
    const LD ta = ref_curve_arc(b, a), tn = ref_curve_annulus(b, an);
    const LD da = distance(bl, al), dn = distance(anl, bl);
    const bool ok = std::abs(da - ta) <= 1e-15L * std::max(ta, LD(size_a)) &&
                    std::abs(dn - tn) <= 1e-15L * std::max(tn, LD(size_n)) && closest_points(al, bl).distance == da &&
                    closest_points(bl, anl).distance == dn;
    if (!ok)
      std::printf("  long double: arc %.3Lg, annulus %.3Lg\n", std::abs(da - ta) / size_a, std::abs(dn - tn) / size_n);
    check::record(ok, "long double", __FILE__, __LINE__);
    ++counts["long double"];
    const BezierCurve3<float> bf{b.control.cast<float>()};
    const Arc3<float> af{a.center.cast<float>(), a.normal.cast<float>(), float(a.radius), a.start.cast<float>(),
                         float(a.angle)};
    check::record(std::abs(double(distance(bf, af)) - double(ta)) <= 1e-5 * std::max(double(ta), size_a), "float",
                  __FILE__, __LINE__);
  }
}

}  // namespace

int main() {
  arc_hard();
  arc_whole();
  arc_near_ends();
  arc_random();
  annulus_hard();
  annulus_degenerate();
  annulus_random();
  annulus_crossing();
  precision_tests();
  for (const auto& [kind, n] : counts)
    std::printf("  %s: %d cases, worst relative error %.3g\n", kind.c_str(), n, worst[kind]);
  return check::finish("bezier-arc");
}

}  // namespace test_bezier_arc

CHECK_SUITE(test_bezier_arc);
