// Arcs (arc.hpp) against every kind: points, lines, rays, segments, circles, disks and arcs, against
// long-double references that use no library code: the arc sampled directly (its own u from the
// start's projection, v = n x u), the inner distance from an arc point to the other shape in
// closed form (point, line, ray, segment; the elementary projection onto a circle or disk, as
// round_reference.hpp does; against another arc, the ring's where the point's angle lies on it,
// else the nearer end's: ref::Arc), and the minimum
// over the arc's t found by dense sampling and zooming (ref::minimize). Bar in double:
// |error| <= 1e-12 * max(true distance, largest radius). Also: the closest points lie on their
// shapes, their separation is the distance, the arc's parameter gives its point, both argument
// orders agree, `unique` where the answer says it, and an arc of angle 2 pi is its circle exactly.
#include "round_reference.hpp"

#include <circledist/arc.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace test_arc {

using Arc = Arc3<double>;
using Line = Line3<double>;
using Ray = Ray3<double>;
using Segment = Segment3<double>;
using Circle = Circle3<double>;
using Disk = Disk3<double>;

// Random draws: check::scaled(n) of them (check.hpp): the
// references' dense sampling is most of this test's time; the hard cases all run at any scale.

namespace {

using ref::kTurn;

// ---------------------------------------------------------------------------------------------
// The references.

// The arc relative to an origin (differences of doubles are exact in long double): ref::Arc.
using RefArc = ref::Arc;

// A linear piece relative to an origin: points o + s d, s in [lo, hi].
struct RefPiece {
  V3 o, d;
  LD lo, hi;
  LD distance(const V3& p) const {
    const LD dd = d.squaredNorm();
    if (!(dd > 0)) return (p - o).norm();
    const LD s = (p - o).dot(d) / dd;
    if (s >= lo && s <= hi) return (p - o).cross(d).norm() / std::sqrt(dd);
    return (p - (o + std::min(std::max(s, lo), hi) * d)).norm();
  }
};
RefPiece ref_piece(const Line& l, const V3d& origin) {
  return {l.origin.cast<LD>() - origin.cast<LD>(), l.direction.cast<LD>(), -1e300L, 1e300L};
}
RefPiece ref_piece(const Ray& r, const V3d& origin) {
  return {r.origin.cast<LD>() - origin.cast<LD>(), r.direction.cast<LD>(), 0, 1e300L};
}
RefPiece ref_piece(const Segment& s, const V3d& origin) {
  return {s.p0.cast<LD>() - origin.cast<LD>(), s.p1.cast<LD>() - s.p0.cast<LD>(), 0, 1};
}

LD ref_point_arc(const V3d& p, const Arc& a) {
  const RefArc ra(a, a.center);
  const V3 q = p.cast<LD>() - a.center.cast<LD>();
  return ra.min_over([&](const V3& x) { return (x - q).norm(); });
}
template <class Piece> LD ref_piece_arc(const Piece& piece, const Arc& a) {
  const RefArc ra(a, a.center);
  const RefPiece rp = ref_piece(piece, a.center);
  return ra.min_over([&](const V3& x) { return rp.distance(x); });
}
LD ref_circle_arc(const Circle& c, const Arc& a) {
  const RefArc ra(a, a.center);
  const ref::Round rc(c.center, c.normal, c.radius, a.center);
  return ra.min_over([&](const V3& x) { return (x - rc.ring_point(x)).norm(); });
}
LD ref_disk_arc(const Disk& d, const Arc& a) {
  const RefArc ra(a, a.center);
  const ref::Round rd(d.center, d.normal, d.radius, a.center);
  return ra.min_over([&](const V3& x) { return (x - rd.disk_point(x)).norm(); });
}
// Arc against arc: one arc sampled and refined, the distance from its point to the other arc in
// closed form (ref::Arc::distance).
LD ref_arc_arc(const Arc& a, const Arc& b) {
  const RefArc ra(a, a.center), rb(b, a.center);
  return ra.min_over([&](const V3& x) { return rb.distance(x); });
}

// ---------------------------------------------------------------------------------------------
// The checks.

double size_of(const Arc& a) { return a.radius; }
template <class S> double size_of(const S&) { return 0; }
double size_of(const Circle& c) { return c.radius; }
double size_of(const Disk& d) { return d.radius; }

// A point's distance to a shape: the reference's for an arc, the library's closed forms else.
LD off(const V3d& p, const Arc& a) { return ref_point_arc(p, a); }
template <class S> LD off(const V3d& p, const S& s) { return distance(p, s); }

V3 arc_point_of(const Arc& a, double t) { return RefArc(a, V3d::Zero()).at(t); }

// An arc's side of a Result: on the arc, and its parameter gives it.
void expect_arc_side(const char* name, const Arc& a, const V3d& point, const Vec2<double>& param, double tol) {
  const bool in_range = param.x() >= 0 && param.x() <= std::min(a.angle, kTurn) && param.y() == 0;
  const double off_param = double((arc_point_of(a, param.x()) - point.cast<LD>()).norm());
  const bool ok = in_range && off_param <= tol;
  if (!ok)
    std::printf("  %s: arc parameter %.17g (angle %.17g) gives a point %.3g away\n", name, param.x(), a.angle,
                off_param);
  check::record(ok, name, __FILE__, __LINE__);
}

std::map<std::string, int> counts;

// One case: distance in both orders, closest points in both orders, their consistency, and
// `unique` when asked (1 or 0; -1 leaves it).
template <class S>
void arc_case(const std::string& kind, const char* name, const S& s, const Arc& a, LD truth, int unique = -1) {
  ++counts[kind];
  const double size = std::max(size_of(s), a.radius);
  const Result<double> r = closest_points(s, a), back = closest_points(a, s);
  expect_distance(kind, name, r.distance, truth, size);
  expect_distance(kind, name, back.distance, truth, size);
  expect_distance(kind, name, distance(s, a), truth, size);
  expect_distance(kind, name, distance(a, s), truth, size);
  const double world = 8 * std::numeric_limits<double>::epsilon() * std::max(r.point_a.norm(), r.point_b.norm());
  const double tol = 1e-12 * std::max(size, r.distance) + world;
  const double gap = (r.point_a - r.point_b).norm();
  const double on_s = double(off(r.point_a, s)), on_a = double(off(r.point_b, a));
  const bool ok = std::abs(gap - r.distance) <= tol && on_s <= tol && on_a <= tol;
  if (!ok)
    std::printf("  %s / %s: |a-b| %.17g vs %.17g, off first %.3g, off arc %.3g\n", kind.c_str(), name, gap, r.distance,
                on_s, on_a);
  check::record(ok, name, __FILE__, __LINE__);
  expect_arc_side(name, a, r.point_b, r.param_b, tol);
  expect_arc_side(name, a, back.point_a, back.param_a, tol);
  if (unique >= 0) {
    expect_unique(name, r.unique, unique == 1);
    expect_unique(name, back.unique, unique == 1);
  }
}

// Arc against arc: both sides are arcs.
void arc_arc_case(const char* name, const Arc& a, const Arc& b, LD truth, int unique = -1) {
  const std::string kind = "arc-arc";
  ++counts[kind];
  const double size = std::max(a.radius, b.radius);
  const Result<double> r = closest_points(a, b), back = closest_points(b, a);
  expect_distance(kind, name, r.distance, truth, size);
  expect_distance(kind, name, back.distance, truth, size);
  expect_distance(kind, name, distance(a, b), truth, size);
  CHECK(distance(a, b) == distance(b, a));
  const double world = 8 * std::numeric_limits<double>::epsilon() * std::max(r.point_a.norm(), r.point_b.norm());
  const double tol = 1e-12 * std::max(size, r.distance) + world;
  const double gap = (r.point_a - r.point_b).norm();
  const double on_a = double(off(r.point_a, a)), on_b = double(off(r.point_b, b));
  const bool ok = std::abs(gap - r.distance) <= tol && on_a <= tol && on_b <= tol;
  if (!ok)
    std::printf("  arc-arc / %s: |a-b| %.17g vs %.17g, off a %.3g, off b %.3g\n", name, gap, r.distance, on_a, on_b);
  check::record(ok, name, __FILE__, __LINE__);
  expect_arc_side(name, a, r.point_a, r.param_a, tol);
  expect_arc_side(name, b, r.point_b, r.param_b, tol);
  if (unique >= 0) {
    expect_unique(name, r.unique, unique == 1);
    expect_unique(name, back.unique, unique == 1);
  }
}

// An arc of angle 2 pi answers exactly as its circle (distance and points to the bit; the
// parameter is the circle's angle less the start's).
template <class S> void whole_case(const char* name, const S& s, const Arc& a) {
  ++counts["whole"];
  const Circle c{a.center, a.normal, a.radius};
  const Result<double> ra = closest_points(s, a), rc = closest_points(s, c);
  const bool same = distance(s, a) == distance(s, c) && distance(a, s) == distance(c, s) &&
                    ra.distance == rc.distance && ra.point_a == rc.point_a && ra.point_b == rc.point_b &&
                    ra.unique == rc.unique;
  if (!same) std::printf("  whole / %s: %.17g vs the circle's %.17g\n", name, ra.distance, rc.distance);
  check::record(same, name, __FILE__, __LINE__);
  expect_arc_side(name, a, ra.point_b, ra.param_b, 1e-12 * std::max(a.radius, ra.distance) + 1e-15 * ra.point_b.norm());
}

// ---------------------------------------------------------------------------------------------
// Shapes.

struct Draw : ShapeDraw {
  using ShapeDraw::ShapeDraw;
};

// The arc of circle (c, n, r) from canonical angle t0 (the library's Frame, so that the test can
// place an arc's end exactly at a point it built there) over `angle`.
Arc arc_from(const V3d& c, const V3d& n, double r, double t0, double angle) {
  const Frame<double> f(n);
  return {c, n, r, std::cos(t0) * f.u + std::sin(t0) * f.v, angle};
}

template <class S> S moved(const S& s, const V3d& t);
template <> Arc moved(const Arc& a, const V3d& t) { return {a.center + t, a.normal, a.radius, a.start, a.angle}; }
template <> Circle moved(const Circle& c, const V3d& t) { return {c.center + t, c.normal, c.radius}; }
template <> Disk moved(const Disk& d, const V3d& t) { return {d.center + t, d.normal, d.radius}; }
template <> Line moved(const Line& l, const V3d& t) { return {l.origin + t, l.direction}; }
template <> Ray moved(const Ray& r, const V3d& t) { return {r.origin + t, r.direction}; }
template <> Segment moved(const Segment& s, const V3d& t) { return {s.p0 + t, s.p1 + t}; }
template <> V3d moved(const V3d& p, const V3d& t) { return p + t; }

// ---------------------------------------------------------------------------------------------

void point_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1), x(1, 0, 0);
  const Arc quarter{o, z, 1, x, kTurn / 4};
  arc_case("point-arc", "over the middle", V3d(1, 1, 0.5), quarter,
           std::sqrt((std::sqrt(2.0L) - 1) * (std::sqrt(2.0L) - 1) + 0.25L), 1);
  arc_case("point-arc", "beyond the start", V3d(1, -1, 0), quarter, 1, 1);
  arc_case("point-arc", "on the axis", V3d(0, 0, 2), quarter, std::sqrt(5.0L), 0);
  arc_case("point-arc", "at the center", o, quarter, 1, 0);
  // Opposite the arc's middle, as far from both ends: two closest pairs.
  arc_case("point-arc", "opposite the middle", V3d(-1, -1, 0.3), quarter, ref_point_arc(V3d(-1, -1, 0.3), quarter), 0);
  arc_case("point-arc", "at the end", V3d(0, 1, 0), quarter, 0, 1);
  arc_case("point-arc", "on the end's radius", V3d(0, 3, 0.5), quarter, std::sqrt(4.25L), 1);
  arc_case("point-arc", "zero radius", V3d(1, 2, 2), Arc{o, z, 0, x, 1}, 3, 1);
  // No projection of the start: the arc starts at Frame's U, (0, 1, 0) for the normal z.
  arc_case("point-arc", "start along the normal", V3d(2, 0, 0), Arc{o, z, 1, z, 1}, std::sqrt(5.0L), 1);
  Draw d(11);
  for (int k = 0; k < check::scaled(200); ++k) {
    const Arc a = d.arc();
    const V3d p = a.center + 2 * d.vec();
    arc_case("point-arc", "random", p, a, ref_point_arc(p, a));
    if (k % 20 == 0) {
      const V3d t = 1e6 * d.vec();
      const V3d pt = moved(p, t);
      const Arc at = moved(a, t);
      arc_case("point-arc", "translated 1e6", pt, at, ref_point_arc(pt, at));
    }
    if (k % 10 == 0) whole_case("point", p, Arc{a.center, a.normal, a.radius, a.start, kTurn});
  }
}

// The arc's ends as the point query places a point against them (point_arc.hpp, sector_from_ends:
// the angle's cosines and sines that Arc3's constructor forms): points at the angles where the
// place changes (the start, the far end, the bisector of the gap and the edges of the band around
// it where both ends are measured), just on either side and on them, in and out of the plane, for
// angles up to, at and past pi and near 0 and 2 pi. Each against the reference, and the same
// arc with its angle assigned after it was made (no trigonometry carried: the general path)
// giving the same answer within the bar and the same `unique`.
void ends_tests() {
  Draw d(29);
  const double band = std::ldexp(1.0, -21);  // half the margin of point_arc.hpp
  const double angles[] = {1e-6, 0.5, kTurn / 4, kTurn / 2 - 1e-9, kTurn / 2, kTurn / 2 + 1e-9, 3.0, 4.5, kTurn - 1e-6};
  for (int k = 0; k < 3; ++k) {
    const V3d c = d.vec(), n = d.vec(), start = d.vec();
    const double r = d.radius();
    const V3d nn = n.normalized(), u = (start - start.dot(nn) * nn).normalized(), v = nn.cross(u);
    for (const double angle : angles) {
      const Arc a{c, n, r, start, angle};
      CHECK(a.trig.angle == angle);  // formed by the constructor
      Arc later;                     // the same arc, its angle given after it was made
      later.center = c;
      later.normal = n;
      later.radius = r;
      later.start = start;
      later.angle = angle;
      CHECK(!(later.trig.angle == later.angle));
      const double bisector = kTurn / 2 + angle / 2;
      const double places[] = {0, angle, bisector, bisector - band, bisector + band};
      for (const double place : places) {
        for (const double offset : {-1e-3, -1e-9, 0.0, 1e-9, 1e-3}) {
          for (const double height : {0.0, 0.7 * r}) {
            const double t = place + offset, rho = (0.3 + 1.4 * d.uniform(d.rng)) * r;
            const V3d p = c + rho * (std::cos(t) * u + std::sin(t) * v) + height * nn;
            // Exactly opposite the arc's middle (on the bisector, offset 0): two closest pairs.
            const bool tie = place == bisector && offset == 0;
            const LD truth = ref_point_arc(p, a);
            arc_case("point-arc", "ends", p, a, truth, tie ? -1 : 1);
            arc_case("point-arc", "ends, angle given later", p, later, truth, tie ? -1 : 1);
            const Result<double> x = closest_points(p, a), y = closest_points(p, later);
            CHECK(x.unique == y.unique);
          }
        }
      }
    }
  }
}

// The piece's origin moved back along it by `far` (a line: the same line; a ray or segment: a
// longer one): distances near the arc from a far origin (the fast path's anchored piece, arc.hpp).
Line far_back(const Line& l, double far) { return {l.origin - far * l.direction.normalized(), l.direction}; }
Ray far_back(const Ray& r, double far) { return {r.origin - far * r.direction.normalized(), r.direction}; }
Segment far_back(const Segment& s, double far) { return {s.p0 - far * (s.p1 - s.p0).normalized(), s.p1}; }

template <class Piece>
void piece_random(const char* kind, Draw& d, const std::function<Piece(Draw&, const Arc&)>& draw) {
  for (int k = 0; k < check::scaled(120); ++k) {
    const Arc a = d.arc();
    const Piece p = draw(d, a);
    arc_case(kind, "random", p, a, ref_piece_arc(p, a));
    if (k % 12 == 0) {
      const V3d t = 1e6 * d.vec();
      const Piece pt = moved(p, t);
      const Arc at = moved(a, t);
      arc_case(kind, "translated 1e6", pt, at, ref_piece_arc(pt, at));
    }
    if (k % 6 == 0) {
      const Piece pf = far_back(p, 1e5);
      arc_case(kind, "origin far back", pf, a, ref_piece_arc(pf, a));
    }
    if (k % 10 == 0) whole_case(kind, p, Arc{a.center, a.normal, a.radius, a.start, kTurn});
  }
}

void piece_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1), x(1, 0, 0);
  const Arc quarter{o, z, 1, x, kTurn / 4};
  // Along the axis: every arc point as close.
  arc_case("line-arc", "along the axis", Line{V3d(0, 0, 3), z}, quarter, 1, 0);
  arc_case("ray-arc", "along the axis", Ray{V3d(0, 0, 3), z}, quarter, std::sqrt(10.0L), 0);
  arc_case("segment-arc", "on the axis", Segment{V3d(0, 0, -1), V3d(0, 0, 1)}, quarter, 1, 0);
  // Parallel to the axis, over the arc's middle (closest at the middle) and opposite it (ends).
  const double h = std::sqrt(0.5);
  arc_case("line-arc", "parallel over the middle", Line{V3d(0.3 * h, 0.3 * h, 0), z}, quarter, 0.7L, 1);
  arc_case("line-arc", "parallel opposite the middle", Line{V3d(-0.3 * h, -0.3 * h, 0), z}, quarter,
           ref_piece_arc(Line{V3d(-0.3 * h, -0.3 * h, 0), z}, quarter), 0);
  // Tangent to the circle inside the arc, at an end, and just beyond an end.
  arc_case("line-arc", "tangent inside", Line{V3d(h, h, 0), V3d(-1, 1, 0)}, quarter, 0);
  arc_case("line-arc", "tangent at the start", Line{V3d(1, 0, 0), V3d(0, 1, 0)}, quarter, 0, 1);
  arc_case("line-arc", "tangent at the end, lifted", Line{V3d(0, 1, 1e-9), V3d(1, 0, 0)}, quarter, 1e-9L, 1);
  arc_case("line-arc", "tangent beyond the start",
           Line{V3d(std::cos(-0.1), std::sin(-0.1), 0), V3d(std::sin(0.1), std::cos(0.1), 0)}, quarter,
           ref_piece_arc(Line{V3d(std::cos(-0.1), std::sin(-0.1), 0), V3d(std::sin(0.1), std::cos(0.1), 0)}, quarter),
           1);
  // A segment with an end on the arc's axis, and a ray from the axis outward through the arc.
  arc_case("segment-arc", "end on the axis", Segment{V3d(0, 0, 0.5), V3d(-2, -1, 0.5)}, quarter,
           ref_piece_arc(Segment{V3d(0, 0, 0.5), V3d(-2, -1, 0.5)}, quarter));
  arc_case("ray-arc", "from the axis through the arc", Ray{V3d(0, 0, 0), V3d(1, 2, 0)}, quarter, 0, 1);
  arc_case("ray-arc", "from the axis away from the arc", Ray{V3d(0, 0, 0), V3d(-1, -2, 0)}, quarter,
           ref_piece_arc(Ray{V3d(0, 0, 0), V3d(-1, -2, 0)}, quarter), 0);  // every arc point 1 from the origin
  // Nearly along the axis: tilted by 1e-10 and 1e-9 off it.
  arc_case("line-arc", "nearly along the axis", Line{V3d(1e-9, 0, 0), V3d(1e-10, 0, 1)}, quarter,
           ref_piece_arc(Line{V3d(1e-9, 0, 0), V3d(1e-10, 0, 1)}, quarter));
  arc_case("segment-arc", "nearly along the axis", Segment{V3d(-1e-9, 0, -1), V3d(1e-9, 1e-9, 1)}, quarter,
           ref_piece_arc(Segment{V3d(-1e-9, 0, -1), V3d(1e-9, 1e-9, 1)}, quarter));
  arc_case("segment-arc", "zero radius arc", Segment{V3d(1, 0, 1), V3d(-1, 0, 1)}, Arc{o, z, 0, x, 1}, 1);
  arc_case("segment-arc", "a point segment", Segment{V3d(2, 2, 0), V3d(2, 2, 0)}, quarter, std::sqrt(8.0L) - 1, 1);
  // Translated far.
  for (const double shift : {1e6, 1e8}) {
    const V3d t = shift * unit(0.3, -1, 0.6);
    // The moved coordinates round (an ulp of 1e8 is 1.5e-8): the references are the moved scene's.
    const Arc q = moved(quarter, t);
    const Line l = moved(Line{V3d(h, h, 0), V3d(-1, 1, 0)}, t);
    const Segment s = moved(Segment{V3d(0, 0, 0.5), V3d(-2, -1, 0.5)}, t);
    arc_case("line-arc", "tangent inside, translated", l, q, ref_piece_arc(l, q));
    arc_case("segment-arc", "end on the axis, translated", s, q, ref_piece_arc(s, q));
  }
  Draw d(23);
  piece_random<Line>("line-arc", d, [](Draw& r, const Arc& a) { return Line{a.center + 1.5 * r.vec(), r.vec()}; });
  piece_random<Ray>("ray-arc", d, [](Draw& r, const Arc& a) { return Ray{a.center + 1.5 * r.vec(), r.vec()}; });
  piece_random<Segment>("segment-arc", d, [](Draw& r, const Arc& a) {
    const V3d p = a.center + 1.5 * r.vec();
    return Segment{p, p + 1.5 * r.vec()};
  });
  // Lines tangent to an arc's circle at random angles, the arc holding the tangency, ending at
  // it, or missing it; offset by 0 or up to 1e-12..1 off the circle.
  for (int k = 0; k < check::scaled(60); ++k) {
    const V3d c = d.vec(), n = d.vec().normalized();
    const double r = d.radius(), t = kTurn * d.uniform(d.rng);
    const Frame<double> f(n);
    const V3d p = c + r * (std::cos(t) * f.u + std::sin(t) * f.v);
    const V3d tangent = -std::sin(t) * f.u + std::cos(t) * f.v;
    const double lift = k % 2 == 0 ? 0.0 : std::pow(10.0, -12 * d.uniform(d.rng));
    const V3d dir = std::cos(0.3 * k) * tangent + std::sin(0.3 * k) * n;
    const Line l{p + lift * (p - c).normalized() + 0.7 * dir, dir};
    const Arc arcs[3] = {arc_from(c, n, r, t - 0.5, 1.2), arc_from(c, n, r, t, 2.0), arc_from(c, n, r, t + 0.3, 5.0)};
    const char* names[3] = {"tangent, holding", "tangent at the start", "tangent, missed"};
    for (int i = 0; i < 3; ++i) arc_case("line-arc", names[i], l, arcs[i], ref_piece_arc(l, arcs[i]));
    const Segment s{l.origin - 2 * dir, l.origin + 0.3 * dir};
    for (int i = 0; i < 3; ++i) arc_case("segment-arc", names[i], s, arcs[i], ref_piece_arc(s, arcs[i]));
  }
}

// Lines, rays and segments in the arc's plane (the toolpath case, linear_arc.hpp's
// piece_arc_planar): random planes whose points are formed in double (coplanar to rounding), the
// xy plane at a height with normals of either sign (exactly coplanar), the same lifted 1e-12 off
// the plane, and 1e6 from the origin; random pieces, and the hard ones: tangent at angles on,
// at and 1e-9 beside the arc's ends, crossing the circle there, missing it by 1e-9, segments
// ending 1e-9 short of the circle, rays out through it; arc radii 1e-3 and 1e3.
struct Plane {
  V3d origin, e1, e2, n;
  double lift;
  V3d at(double x, double y) const { return origin + x * e1 + y * e2 + lift * n.normalized(); }
  V3d along(double x, double y) const { return x * e1 + y * e2; }
  Arc arc(double r, double start, double angle) const {
    return {origin, n, r, std::cos(start) * e1 + std::sin(start) * e2, angle};
  }
};

void coplanar_tests() {
  Draw d(41);
  std::vector<Plane> planes;
  planes.push_back({V3d(0.25, -0.5, 1.75), V3d(1, 0, 0), V3d(0, 1, 0), V3d(0, 0, 2), 0});
  planes.push_back({V3d(0.25, -0.5, -3), V3d(0, 1, 0), V3d(1, 0, 0), V3d(0, 0, -0.5), 0});
  for (int k = 0; k < 3; ++k) {
    const V3d n = d.vec();
    const V3d e1 = n.cross(d.vec()).normalized(), e2 = n.normalized().cross(e1);
    planes.push_back({d.vec(), e1, e2, n, 0});
  }
  planes.push_back({planes[2].origin, planes[2].e1, planes[2].e2, planes[2].n, 1e-12});
  planes.push_back({planes[3].origin + 1e6 * unit(0.3, -1, 0.6), planes[3].e1, planes[3].e2, planes[3].n, 0});
  for (const Plane& p : planes) {
    const Arc a = p.arc(1, 0, 2);  // t in [0, 2], the plane's angle
    for (const double t : {1.0, 0.0, 2.0, 2.0 - 1e-9, 2.0 + 1e-9, -1e-9, 4.0}) {
      const double cs = std::cos(t), sn = std::sin(t);
      const V3d tangent = p.along(-sn, cs);
      const Line touching{p.at(cs, sn) - 3 * tangent, tangent};
      arc_case("line-arc", "coplanar tangent", touching, a, ref_piece_arc(touching, a));
      const Line missing{p.at((1 + 1e-9) * cs, (1 + 1e-9) * sn) + 2 * tangent, -tangent};
      arc_case("line-arc", "coplanar missing by 1e-9", missing, a, ref_piece_arc(missing, a));
      const Line crossing{p.at(cs, sn), p.along(std::cos(t + 2.5) - cs, std::sin(t + 2.5) - sn)};
      arc_case("line-arc", "coplanar crossing", crossing, a, ref_piece_arc(crossing, a));
      const Segment short_of{p.at(1.5 * cs, 1.5 * sn), p.at((1 + 1e-9) * cs, (1 + 1e-9) * sn)};
      arc_case("segment-arc", "coplanar short of the circle", short_of, a, ref_piece_arc(short_of, a));
      const Segment ending_on{p.at(1.5 * cs, 1.5 * sn), p.at(cs, sn)};
      arc_case("segment-arc", "coplanar ending on the circle", ending_on, a, ref_piece_arc(ending_on, a));
      const Ray out{p.at(0.2 * cs, 0.2 * sn), p.along(cs, sn)};
      arc_case("ray-arc", "coplanar out through the circle", out, a, ref_piece_arc(out, a));
    }
    // Chords of the circle between two angles: both crossings on the arc (two pairs at distance 0),
    // one, or none (the ends decide).
    const auto chord = [&](double t1, double t2) {
      return Line{p.at(std::cos(t1), std::sin(t1)), p.along(std::cos(t2) - std::cos(t1), std::sin(t2) - std::sin(t1))};
    };
    // (At 1e6 the chord's ends round by 1e-10 off the circle: the two crossings' distances differ.)
    const bool near_origin = p.origin.norm() < 10;
    arc_case("line-arc", "coplanar crossing the arc twice", chord(0.3, 1.7), a, ref_piece_arc(chord(0.3, 1.7), a),
             near_origin ? 0 : -1);
    arc_case("line-arc", "coplanar crossing the arc once", chord(1.0, 3.0), a, ref_piece_arc(chord(1.0, 3.0), a), 1);
    arc_case("line-arc", "coplanar crossing the gap", chord(2.5, 5.0), a, ref_piece_arc(chord(2.5, 5.0), a), 1);
    const Segment inside{p.at(-0.2, 0.3), p.at(0.4, 0.1)};
    arc_case("segment-arc", "coplanar inside the circle", inside, a, ref_piece_arc(inside, a));
    const Arc small = p.arc(1e-3, 0.5, 2), big = p.arc(1e3, 0, 0.01);
    const Line small_line{p.at(0, 5e-4), p.along(1, 0.1)};
    arc_case("line-arc", "coplanar tiny arc", small_line, small, ref_piece_arc(small_line, small));
    const Segment big_segment{p.at(999, 3), p.at(1001, 3.5)};
    arc_case("segment-arc", "coplanar huge arc", big_segment, big, ref_piece_arc(big_segment, big));
    for (int k = 0; k < check::scaled(24); ++k) {
      const double r = d.radius(), x = d.normal(d.rng), y = d.normal(d.rng);
      const Arc ra = p.arc(r, kTurn * d.uniform(d.rng), std::max(0.05, 6.2 * d.uniform(d.rng)));
      const V3d o = p.at(2 * x, 2 * y), dir = p.along(d.normal(d.rng), d.normal(d.rng));
      const Line l{o, dir};
      const Ray ray{o, dir};
      const Segment seg{o, o + 1.5 * dir};
      arc_case("line-arc", "coplanar random", l, ra, ref_piece_arc(l, ra));
      arc_case("ray-arc", "coplanar random", ray, ra, ref_piece_arc(ray, ra));
      arc_case("segment-arc", "coplanar random", seg, ra, ref_piece_arc(seg, ra));
    }
  }
}

template <class Round3> LD ref_round_arc(const Round3& s, const Arc& a);
template <> LD ref_round_arc(const Circle& s, const Arc& a) { return ref_circle_arc(s, a); }
template <> LD ref_round_arc(const Disk& s, const Arc& a) { return ref_disk_arc(s, a); }

template <class Round3> void round_tests(const char* kind) {
  const V3d o(0, 0, 0), z(0, 0, 1), x(1, 0, 0);
  const Arc quarter{o, z, 1, x, kTurn / 4};
  constexpr bool disk = std::is_same<Round3, Disk>::value;
  // Coplanar and concentric: every arc point as close (a circle of radius 1.5: 0.5; a disk: 0).
  arc_case(kind, "coplanar concentric", Round3{o, z, 1.5}, quarter, disk ? 0 : 0.5L, 0);
  arc_case(kind, "coaxial above", Round3{V3d(0, 0, 1), z, 0.5}, quarter, std::sqrt(1.25L), 0);
  // The arc's end on the round's axis, and the round's center on the arc's end.
  {
    const Round3 below{V3d(0, 0, -2), z, 0.5};
    const Arc down{o, V3d(0, 1, 0), 1, V3d(0, 0, -1), 1};  // starts at (0, 0, -1), on the round's axis
    arc_case(kind, "arc end on the axis", below, down, ref_round_arc(below, down));
  }
  {
    // The arc's start on the round's axis, the arc rising from it along the axis: the start is
    // closest, to every point of a ring (not unique), to the one point below it on a disk.
    const Arc rising{V3d(1, 0, 0.5), V3d(0, 1, 0), 1, V3d(-1, 0, 0), 1};  // (1 - cos t, 0, 0.5 + sin t)
    arc_case(kind, "start on the axis, rising", Round3{o, z, 1}, rising, disk ? 0.5L : std::sqrt(1.25L), disk ? 1 : 0);
  }
  arc_case(kind, "standing on the end", Round3{V3d(1.5, 0, 0), V3d(0, 1, 0), 0.5}, quarter, 0, 1);
  arc_case(kind, "standing beyond the end",
           Round3{V3d(std::cos(-0.2) * 1.5, std::sin(-0.2) * 1.5, 0), V3d(-std::sin(-0.2), std::cos(-0.2), 0), 0.5},
           quarter,
           ref_round_arc(
               Round3{V3d(std::cos(-0.2) * 1.5, std::sin(-0.2) * 1.5, 0), V3d(-std::sin(-0.2), std::cos(-0.2), 0), 0.5},
               quarter),
           1);
  {
    // Nearly coincident (circle_circle's hard family): centers 1e-12 apart, normals 1e-9, radii 1e-10.
    const Round3 near{V3d(1e-12, -1e-12, 0), unit(1e-9, 0, 1), 1 + 1e-10};
    arc_case(kind, "nearly coincident", near, quarter, ref_round_arc(near, quarter));
    const Arc tilted_back{o, z, 1, V3d(-1, 0.2, 0), 2};
    arc_case(kind, "nearly coincident, other side", near, tilted_back, ref_round_arc(near, tilted_back));
  }
  arc_case(kind, "zero radius arc", Round3{o, z, 1}, Arc{V3d(0.5, 0, 2), z, 0, x, 1}, disk ? 2 : std::sqrt(4.25L), 1);
  // Radius ratios 1e-3 and 1e3.
  {
    const Round3 small{V3d(1.2, 0.3, 0.1), unit(0.2, 1, 0.4), 1e-3};
    arc_case(kind, "round 1e-3 the arc", small, quarter, ref_round_arc(small, quarter));
    const Arc big{V3d(1e3 + 0.3, 0.1, 0.2), unit(0.1, 0.2, 1), 1e3, V3d(-1, 0.01, 0), 0.01};
    arc_case(kind, "arc 1e3 the round", Round3{o, z, 1}, big, ref_round_arc(Round3{o, z, 1}, big));
  }
  Draw d(disk ? 31 : 37);
  for (int k = 0; k < check::scaled(100); ++k) {
    const Arc a = d.arc();
    const Round3 s{d.vec(), d.vec(), d.radius()};
    arc_case(kind, "random", s, a, ref_round_arc(s, a));
    if (k % 10 == 0) {
      const V3d t = 1e6 * d.vec();
      const Round3 st = moved(s, t);
      const Arc at = moved(a, t);
      arc_case(kind, "translated 1e6", st, at, ref_round_arc(st, at));
      whole_case(kind, s, Arc{a.center, a.normal, a.radius, a.start, kTurn});
    }
  }
  // Tangencies (round_reference.hpp's configurations): the arc of A's circle holding the
  // tangency point, starting exactly at it, ending exactly at it, or missing it.
  int k = 0;
  for (const RoundCase& r : tangent_round_cases()) {
    const Round3 s{r.b.center, r.b.normal, r.b.radius};
    // The tangency's canonical angle on A, from A's closest point to B's circle (the touching
    // point itself when the offset is 0): only where the arcs are placed, not a reference.
    const Result<double> touch = closest_points(r.a, Circle{r.b.center, r.b.normal, r.b.radius});
    const double t = touch.param_a.x();
    const Arc arcs[4] = {arc_from(r.a.center, r.a.normal, r.a.radius, t - 0.4, 1.0),
                         arc_from(r.a.center, r.a.normal, r.a.radius, t, 1.5),
                         arc_from(r.a.center, r.a.normal, r.a.radius, t - 1.5, 1.5),
                         arc_from(r.a.center, r.a.normal, r.a.radius, t + 0.5, 4.0)};
    const char* names[4] = {"tangent, holding", "tangent at the start", "tangent at the end", "tangent, missed"};
    for (int i = 0; i < 4; ++i) arc_case(kind, names[i], s, arcs[i], ref_round_arc(s, arcs[i]));
    if (++k >= 24) break;
  }
}

void arc_arc_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1), x(1, 0, 0), y(0, 1, 0);
  const Arc quarter{o, z, 1, x, kTurn / 4};
  // Concentric and coplanar: overlapping in angle (a continuum), and apart (the nearest ends).
  arc_arc_case("concentric coplanar, overlapping", quarter, Arc{o, z, 1.5, V3d(1, 1, 0), 1}, 0.5L, 0);
  arc_arc_case("concentric coplanar, apart", quarter, Arc{o, z, 1.5, V3d(-1, 0, 0), 1},
               ref_arc_arc(quarter, Arc{o, z, 1.5, V3d(-1, 0, 0), 1}), 1);
  arc_arc_case("same circle, overlapping", quarter, Arc{o, z, 1, V3d(1, 1, 0), 1}, 0, 0);
  arc_arc_case("same circle, end to end", quarter, Arc{o, z, 1, y, 1}, 0, 1);
  arc_arc_case("coaxial, overlapping", quarter, Arc{V3d(0, 0, 1), z, 1, V3d(1, 1, 0), 1}, 1, 0);
  // Ends meeting at a tangency: two arcs of circles tangent at (1, 0, 0).
  arc_arc_case("tangent at both starts", quarter, Arc{V3d(2, 0, 0), z, 1, V3d(-1, 0, 0), 1}, 0, 1);
  arc_arc_case("end on the other's axis", Arc{o, y, 1, V3d(0, 0, 1), 1}, Arc{V3d(0, 0, 2), z, 0.5, x, 2},
               ref_arc_arc(Arc{o, y, 1, V3d(0, 0, 1), 1}, Arc{V3d(0, 0, 2), z, 0.5, x, 2}));
  arc_arc_case("start on the other's axis, rising", Arc{o, z, 1, x, 2}, Arc{V3d(1, 0, 0.5), y, 1, V3d(-1, 0, 0), 1},
               std::sqrt(1.25L), 0);
  {
    const Arc near{V3d(1e-12, -1e-12, 0), unit(1e-9, 0, 1), 1 + 1e-10, V3d(1, 1, 0), 1};
    arc_arc_case("nearly coincident, overlapping", quarter, near, ref_arc_arc(quarter, near));
    const Arc near_apart{V3d(1e-12, -1e-12, 0), unit(1e-9, 0, 1), 1 + 1e-10, V3d(-1, 0.1, 0), 1};
    arc_arc_case("nearly coincident, apart", quarter, near_apart, ref_arc_arc(quarter, near_apart));
  }
  arc_arc_case("zero radius", quarter, Arc{V3d(2, 0, 0), z, 0, x, 1}, 1, 1);
  arc_arc_case("both whole", Arc{o, z, 1, x, kTurn}, Arc{V3d(3, 0, 0), y, 1, x, kTurn}, 1);
  Draw d(41);
  for (int k = 0; k < check::scaled(40); ++k) {
    const Arc a = d.arc(), b{d.vec(), d.vec(), d.radius(), d.vec(), d.angle()};
    const LD truth = ref_arc_arc(a, b);
    arc_arc_case("random", a, b, truth);
    if (k % 8 == 0) {
      const V3d t = 1e6 * d.vec();
      const Arc at = moved(a, t), bt = moved(b, t);
      arc_arc_case("translated 1e6", at, bt, ref_arc_arc(at, bt));
      whole_case("arc", b, Arc{a.center, a.normal, a.radius, a.start, kTurn});
    }
  }
  int k = 0;
  for (const RoundCase& r : tangent_round_cases()) {
    const double t = closest_points(r.a, r.b).param_a.x(), s = closest_points(r.b, r.a).param_a.x();
    const Arc a1 = arc_from(r.a.center, r.a.normal, r.a.radius, t - 0.4, 1.0),
              a2 = arc_from(r.a.center, r.a.normal, r.a.radius, t, 1.5);
    const Arc b1 = arc_from(r.b.center, r.b.normal, r.b.radius, s - 0.3, 0.8),
              b2 = arc_from(r.b.center, r.b.normal, r.b.radius, s - 2, 2.0);
    arc_arc_case("tangent, both holding", a1, b1, ref_arc_arc(a1, b1));
    arc_arc_case("tangent, start and end", a2, b2, ref_arc_arc(a2, b2));
    if (++k >= 12) break;
  }
}

// Long double and float: a few scenes against the double references.
void precision_tests() {
  const Arc a{V3d(0.1, 0.2, 0.3), V3d(1, -2, 0.5), 1.3, V3d(0.3, 1, -0.2), 2.5};
  const Circle c{V3d(0.7, -0.4, 0.2), V3d(0.3, 1, 2), 0.9};
  const Segment s{V3d(-1, 0.5, 0.2), V3d(1.5, -0.3, 0.9)};
  const LD circle_truth = ref_circle_arc(c, a), segment_truth = ref_piece_arc(s, a),
           point_truth = ref_point_arc(V3d(2, 1, 0), a);
  const auto ld_arc = Arc3<LD>{a.center.cast<LD>(), a.normal.cast<LD>(), a.radius, a.start.cast<LD>(), a.angle};
  const auto f_arc = Arc3<float>{a.center.cast<float>(), a.normal.cast<float>(), float(a.radius), a.start.cast<float>(),
                                 float(a.angle)};
  CHECK_NEAR(distance(Circle3<LD>{c.center.cast<LD>(), c.normal.cast<LD>(), c.radius}, ld_arc), circle_truth, 1e-15L);
  CHECK_NEAR(distance(Segment3<LD>{s.p0.cast<LD>(), s.p1.cast<LD>()}, ld_arc), segment_truth, 1e-15L);
  CHECK_NEAR(distance(Vec3<LD>(2, 1, 0), ld_arc), point_truth, 1e-15L);
  CHECK_NEAR(distance(ld_arc, ld_arc), 0, 1e-15L);
  CHECK_NEAR(distance(Circle3<float>{c.center.cast<float>(), c.normal.cast<float>(), float(c.radius)}, f_arc),
             circle_truth, 1e-5);
  CHECK_NEAR(distance(Vec3<float>(2, 1, 0), f_arc), point_truth, 1e-5);
  CHECK_NEAR(closest_points(f_arc, Segment3<float>{s.p0.cast<float>(), s.p1.cast<float>()}).distance, segment_truth,
             1e-5);
  // The eigenvalue root policies.
  Draw d(53);
  for (int k = 0; k < check::scaled(30); ++k) {
    const Arc b = d.arc();
    const Circle e{d.vec(), d.vec(), d.radius()};
    const Segment g{b.center + d.vec(), b.center + d.vec()};
    const LD ce = ref_circle_arc(e, b), ge = ref_piece_arc(g, b);
    const double size = std::max(b.radius, e.radius);
    expect_distance("eigen circle-arc", "random", distance<EigenPolished>(e, b), ce, size);
    expect_distance("eigen circle-arc", "random", closest_points<EigenCompanion>(b, e).distance, ce, size);
    expect_distance("eigen segment-arc", "random", distance<EigenPolished>(g, b), ge, b.radius);
    expect_distance("eigen segment-arc", "random", closest_points<EigenCompanion>(g, b).distance, ge, b.radius);
    if (k % 3 == 0) {
      const Disk f{d.vec(), d.vec(), d.radius()};
      const Arc a2 = d.arc();
      const LD fe = ref_disk_arc(f, b), ae = ref_arc_arc(a2, b);
      expect_distance("eigen disk-arc", "random", closest_points<EigenPolished>(f, b).distance, fe,
                      std::max(b.radius, f.radius));
      expect_distance("eigen arc-arc", "random", closest_points<EigenCompanion>(a2, b).distance, ae,
                      std::max(b.radius, a2.radius));
    }
  }
}

}  // namespace

// Only the start's direction counts: a start scaled by 2^e answers bit for bit as the arc's own
// (the queries are homogeneous in it, and detail::moderate_start brings far lengths back), and
// one scaled by 1e+-200 (its direction rounded) within the bar. Before moderate_start, point-arc
// gave NaN or distances off by O(radius) for starts of 1e200 and 1e-200 (the crash fuzz).
template <class S> void start_length_case(const S& s, const Arc& a, int& same, int& close) {
  const double base = distance(s, a);
  const Result<double> base_closest = closest_points(a, s);
  for (const int e : {-900, -600, -200, 200, 600, 900}) {
    const Arc scaled{a.center, a.normal, a.radius, detail::ldexp3(a.start, e), a.angle};
    const Result<double> rs = closest_points(scaled, s);
    const bool ok = distance(s, scaled) == base && rs.distance == base_closest.distance &&
                    rs.point_a == base_closest.point_a && rs.point_b == base_closest.point_b &&
                    rs.param_a == base_closest.param_a && rs.unique == base_closest.unique;
    if (!ok) std::printf("  start * 2^%d: %.17g, closest %.17g, vs %.17g\n", e, distance(s, scaled), rs.distance, base);
    same += ok;
    check::record(ok, "start scaled by a power of two", __FILE__, __LINE__);
  }
  for (const double f : {1e-200, 1e200}) {
    const Arc scaled{a.center, a.normal, a.radius, f * a.start, a.angle};
    const double d = distance(s, scaled);
    const bool ok = std::abs(d - base) <= 1e-12 * std::max(base, a.radius) && closest_points(scaled, s).distance == d;
    if (!ok) std::printf("  start * %g: %.17g vs %.17g\n", f, d, base);
    close += ok;
    check::record(ok, "start scaled by 1e+-200", __FILE__, __LINE__);
  }
}

// Every kind against the arc a (a random one of each, drawn from d): run(shape) for each.
template <class Run> void each_kind_against(Draw& d, Run&& run) {
  run(d.vec());
  run(Line{d.vec(), d.vec()});
  run(Ray{d.vec(), d.vec()});
  run(Segment{d.vec(), d.vec()});
  run(Circle{d.vec(), d.vec(), d.radius()});
  run(Disk{d.vec(), d.vec(), d.radius()});
  run(d.arc());
}

void start_length_tests() {
  Draw d(20261126);
  int same = 0, close = 0;
  for (int i = 0; i < check::scaled(200) + 1; ++i) {
    Arc a = d.arc();
    a.angle = std::min(a.angle, 6.0);  // a whole arc is its circle, which has no start
    each_kind_against(d, [&](const auto& s) { start_length_case(s, a, same, close); });
  }
  counts["start length (bit for bit)"] = same;
  counts["start length (1e+-200)"] = close;
}

// Only the normal's direction counts too (README: any finite nonzero normal): scaled by 2^e
// (exact) or by 1e+-80 or 1e+-300 (its direction rounded), with the start scaled by 1e+-20 or
// 1e+-60, it answers as the arc's own within the bar, distance() and closest_points() alike (not
// bit for bit: a normal of 2^-1000 leaves line_ring_minimum's range, and its pair the fast
// path). The line-arc fast path (ArcEnds) brings the normal back too: from the raw normal of 1e-80 and a unit start,
// the end points' squared lengths lie in the subnormals, and a line's distance is 9-20% off.
template <class S> void normal_length_case(const S& s, const Arc& a, int& powers, int& decimal) {
  const double base = distance(s, a);
  const double bar = 1e-12 * std::max(base, a.radius);
  const auto case_ok = [&](const Arc& scaled) {
    const Result<double> ab = closest_points(scaled, s), ba = closest_points(s, scaled);
    const double d = distance(s, scaled);
    return std::abs(d - base) <= bar && std::abs(distance(scaled, s) - base) <= bar &&
           std::abs(ab.distance - base) <= bar && std::abs(ba.distance - base) <= bar &&
           std::abs((ab.point_a - ab.point_b).norm() - base) <= bar + 1e-9 * a.radius;
  };
  for (const int e : {-1000, -600, -270, -250, -200, 200, 600, 1000}) {
    const bool ok = case_ok(Arc{a.center, detail::ldexp3(a.normal, e), a.radius, a.start, a.angle});
    if (!ok) std::printf("  normal * 2^%d vs %.17g\n", e, base);
    powers += ok;
    check::record(ok, "normal scaled by a power of two", __FILE__, __LINE__);
  }
  for (const double f : {1e-300, 1e-90, 1e-80, 1e-70, 1e80, 1e300}) {
    for (const double g : {1e-60, 1e-20, 1.0, 1e20, 1e60}) {
      const bool ok = case_ok(Arc{a.center, f * a.normal, a.radius, g * a.start, a.angle});
      if (!ok) std::printf("  normal * %g, start * %g vs %.17g\n", f, g, base);
      decimal += ok;
      check::record(ok, "normal scaled by 1e+-80, 1e+-300", __FILE__, __LINE__);
    }
  }
}

void normal_length_tests() {
  Draw d(20261128);
  int powers = 0, decimal = 0;
  // The reported line: 0.8525 for 0.9405 at a normal of 1e-80.
  const Arc reported{V3d(0, 0, 0), V3d(-0.1, 0.0, -0.3), 1.0, V3d(0.9, 0.1, 1.2), 3.141592653589793};
  normal_length_case(Line{V3d(1.0, 2.4, -2.6), V3d(0.3, -0.7, 0.8)}, reported, powers, decimal);
  for (int i = 0; i < check::scaled(100) + 1; ++i) {
    Arc a = d.arc();
    a.angle = std::min(a.angle, 6.0);  // a whole arc is its circle, which has no start
    each_kind_against(d, [&](const auto& s) { normal_length_case(s, a, powers, decimal); });
  }
  counts["normal length (2^e)"] = powers;
  counts["normal length (1e+-80, 1e+-300)"] = decimal;
}

int main() {
  start_length_tests();
  normal_length_tests();
  point_tests();
  piece_tests();
  coplanar_tests();
  ends_tests();
  round_tests<Circle>("circle-arc");
  round_tests<Disk>("disk-arc");
  arc_arc_tests();
  precision_tests();
  for (const auto& [kind, n] : counts)
    std::printf("  %s: %d cases, worst relative error %.3g\n", kind.c_str(), n, worst[kind]);
  for (const auto& [kind, w] : worst)
    if (!counts.count(kind)) std::printf("  %s: worst relative error %.3g\n", kind.c_str(), w);
  return check::finish("arc");
}

}  // namespace test_arc

CHECK_SUITE(test_arc);
