// Annuli (annulus.hpp) against points, lines, rays, segments, circles, disks and annuli, against
// long-double references that use no library code: the annulus's closest point to a point is the
// elementary projection with its distance from the axis clamped to [inner, outer] (any inner
// circle point on the axis); the other shape is sampled directly on its own parameter (a
// line's t over a range that must hold the minimum, a circle's angle in a frame built
// differently from the library's) and the minimum found by dense sampling and zooming
// (ref::minimize, round_reference.hpp). A disk or an annulus against an annulus: a closest pair
// has a point on a rim, and a common part has its ends on rims (docs/derivations/annulus.md), so the
// reference is the least of every rim sampled against the other shape. Bar in double:
// |error| <= 1e-12 * max(true distance, largest radius); long double 1e-15. Also: both argument
// orders, distance() == closest_points().distance to the bit, the closest points on their
// shapes at the distance apart, the annulus's (s, theta) giving its point with s in the ring,
// `unique` where the geometry says it, inner = 0 equal to the disk's answers and inner = outer
// to the circle's, to the bit, and the eigenvalue root policies.
#include "round_reference.hpp"

#include <circledist/annulus.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

namespace test_annulus {

// Random draws: check::scaled(n) of them (check.hpp); the hard cases all run at any scale.

using Annulus = Annulus3<double>;
using Line = Line3<double>;
using Ray = Ray3<double>;
using Segment = Segment3<double>;
using Circle = Circle3<double>;
using Disk = Disk3<double>;
using Arc = Arc3<double>;

namespace {

// ---------------------------------------------------------------------------------------------
// The references.

struct RefAnnulus {
  V3 c;
  ref::Basis b;
  LD ri, ro;
  RefAnnulus(const Annulus& a, const V3d& origin)
      : c(a.center.cast<LD>() - origin.cast<LD>()), b(a.normal.cast<LD>()), ri(a.inner_radius), ro(a.outer_radius) {}
  V3 point(const V3& p) const {
    const V3 d = p - c;
    const V3 q = d - b.n.dot(d) * b.n;
    const LD rho = q.norm();
    const LD s = std::min(std::max(rho, ri), ro);
    return rho > 0 ? V3(c + (s / rho) * q) : V3(c + ri * b.u);
  }
  LD distance(const V3& p) const { return (p - point(p)).norm(); }
  V3 rim(LD radius, LD t) const { return c + radius * (std::cos(t) * b.u + std::sin(t) * b.v); }
};

// A linear piece relative to an origin: points o + s d, s in [lo, hi] (either may be infinite).
struct RefPiece {
  V3 o, d;
  LD lo, hi;
  V3 at(LD s) const { return o + s * d; }
  LD distance(const V3& p) const {
    const LD dd = d.squaredNorm();
    if (!(dd > 0)) return (p - o).norm();
    const LD s = std::min(std::max((p - o).dot(d) / dd, lo), hi);
    return (p - at(s)).norm();
  }
};
const LD kInf = std::numeric_limits<LD>::infinity();
RefPiece ref_piece(const Line& l, const V3d& origin) {
  return {l.origin.cast<LD>() - origin.cast<LD>(), l.direction.cast<LD>(), -kInf, kInf};
}
RefPiece ref_piece(const Ray& r, const V3d& origin) {
  return {r.origin.cast<LD>() - origin.cast<LD>(), r.direction.cast<LD>(), 0, kInf};
}
RefPiece ref_piece(const Segment& s, const V3d& origin) {
  return {s.p0.cast<LD>() - origin.cast<LD>(), s.p1.cast<LD>() - s.p0.cast<LD>(), 0, 1};
}

LD ref_point(const V3d& p, const Annulus& a) {
  return RefAnnulus(a, a.center).distance(p.cast<LD>() - a.center.cast<LD>());
}

// Over the piece's parameter: the minimum lies within |P(t0) - c| + 2 R of the piece's point
// nearest the center along the line (t0), since the annulus lies within R of c.
template <class Piece> LD ref_piece_annulus(const Piece& piece, const Annulus& a) {
  const RefAnnulus ra(a, a.center);
  const RefPiece rp = ref_piece(piece, a.center);
  const LD dd = rp.d.squaredNorm();
  const LD t0 = -rp.o.dot(rp.d) / dd;
  const LD reach = 1.01L * ((rp.at(t0)).norm() + 2 * ra.ro) / std::sqrt(dd);
  const LD lo = std::max(rp.lo, t0 - reach), hi = std::min(rp.hi, t0 + reach);
  if (!(lo < hi)) return ra.distance(rp.at(std::isfinite(rp.lo) ? rp.lo : rp.hi));
  return ref::minimize([&](LD t) { return ra.distance(rp.at(t)); }, lo, hi, false);
}
LD ref_circle_annulus(const Circle& c, const Annulus& a) {
  const RefAnnulus ra(a, a.center);
  const ref::Round rc(c.center, c.normal, c.radius, a.center);
  return ref::minimize([&](LD t) { return ra.distance(rc.at(t)); }, -ref::kPi, ref::kPi, true);
}
// The rim of radius r of annulus a sampled against f.
LD ref_rim_min(const Annulus& a, LD r, const V3d& origin, const std::function<LD(const V3&)>& f) {
  const RefAnnulus ra(a, origin);
  return ref::minimize([&](LD t) { return f(ra.rim(r, t)); }, -ref::kPi, ref::kPi, true);
}
LD ref_disk_annulus(const Disk& d, const Annulus& a) {
  const RefAnnulus ra(a, a.center);
  const ref::Round rd(d.center, d.normal, d.radius, a.center);
  const LD rim = ref::minimize([&](LD t) { return ra.distance(rd.at(t)); }, -ref::kPi, ref::kPi, true);
  const auto to_disk = [&](const V3& p) { return (p - rd.disk_point(p)).norm(); };
  return std::min(
      {rim, ref_rim_min(a, a.outer_radius, a.center, to_disk), ref_rim_min(a, a.inner_radius, a.center, to_disk)});
}
LD ref_annulus_annulus(const Annulus& a, const Annulus& b) {
  const RefAnnulus ra(a, a.center), rb(b, a.center);
  const auto to_a = [&](const V3& p) { return ra.distance(p); };
  const auto to_b = [&](const V3& p) { return rb.distance(p); };
  return std::min({ref_rim_min(a, a.outer_radius, a.center, to_b), ref_rim_min(a, a.inner_radius, a.center, to_b),
                   ref_rim_min(b, b.outer_radius, a.center, to_a), ref_rim_min(b, b.inner_radius, a.center, to_a)});
}

// An arc sampled on its own t (its u from the start's projection, v = n x u), against the annulus.
LD ref_arc_annulus(const Arc& arc, const Annulus& a) {
  const RefAnnulus ra(a, a.center);
  const V3 c = arc.center.cast<LD>() - a.center.cast<LD>();
  const V3 n = arc.normal.cast<LD>() / arc.normal.cast<LD>().norm();
  const V3 st = arc.start.cast<LD>();
  const V3 q = st - n.dot(st) * n;
  const V3 u = q / q.norm(), v = n.cross(u);
  const bool whole = arc.angle >= 2 * double(ref::kPi);
  const LD angle = whole ? 2 * ref::kPi : LD(arc.angle);
  return ref::minimize([&](LD t) { return ra.distance(c + LD(arc.radius) * (std::cos(t) * u + std::sin(t) * v)); }, 0,
                       angle, whole);
}

// ---------------------------------------------------------------------------------------------
// The checks.

std::map<std::string, int> counts;

double size_of(const Annulus& a) { return a.outer_radius; }
double size_of(const Circle& c) { return c.radius; }
double size_of(const Disk& d) { return d.radius; }
double size_of(const Arc& d) { return d.radius; }
template <class S> double size_of(const S&) { return 0; }

// A point's distance to a shape: the reference's for an annulus, the library's closed forms else.
LD off(const V3d& p, const Annulus& a) { return ref_point(p, a); }
// An arc's distance from p, sampled: an annulus of radii 0 about p is the point p.
LD off(const V3d& p, const Arc& arc) { return ref_arc_annulus(arc, Annulus{p, V3d(0, 0, 1), 0, 0}); }
template <class S> LD off(const V3d& p, const S& s) { return distance(p, s); }

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// The annulus's side of a Result: (s, theta) gives the point, s within the ring.
void expect_annulus_side(const char* name, const Annulus& a, const V3d& point, const Vec2<double>& param, double tol) {
  const Frame<double> f(a.normal);
  const V3d at = a.center + param.x() * (std::cos(param.y()) * f.u + std::sin(param.y()) * f.v);
  const double slack = tol + 8 * std::numeric_limits<double>::epsilon() * a.outer_radius;
  const bool ok =
      (at - point).norm() <= tol && param.x() >= a.inner_radius - slack && param.x() <= a.outer_radius + slack;
  if (!ok)
    std::printf("  %s: param (%.17g, %.17g) off its point by %.3g\n", name, param.x(), param.y(), (at - point).norm());
  check::record(ok, name, __FILE__, __LINE__);
}

// One case: both orders, distance against closest_points to the bit, the points, the params, `unique`.
template <class X, class Roots = DefaultRoots>
void annulus_case(const std::string& kind, const char* name, const X& x, const Annulus& a, LD truth, int unique = -1) {
  ++counts[kind];
  const double size = std::max(size_of(x), a.outer_radius);
  const Result<double> r = closest_points<Roots>(x, a), s = closest_points<Roots>(a, x);
  const double d1 = distance<Roots>(x, a), d2 = distance<Roots>(a, x);
  expect_distance(kind, name, r.distance, truth, size);
  expect_distance(kind, name, s.distance, truth, size);
  expect_distance(kind, name, d1, truth, size);
  const bool agree = same_bits(d1, r.distance) && same_bits(d2, s.distance);
  if (!agree)
    std::printf("  %s / %s: distance %.17g %.17g, closest %.17g %.17g\n", kind.c_str(), name, d1, d2, r.distance,
                s.distance);
  check::record(agree, name, __FILE__, __LINE__);
  // The points: on their shapes, at the distance apart (world points round by an ulp of their
  // coordinates).
  const double world = 8 * std::numeric_limits<double>::epsilon() * std::max(r.point_a.norm(), r.point_b.norm());
  const double tol = 1e-12 * std::max(size, r.distance) + world;
  const double gap = (r.point_a - r.point_b).norm();
  const double on_x = double(off(r.point_a, x)), on_a = double(off(r.point_b, a));
  const bool ok = std::abs(gap - r.distance) <= tol && on_x <= tol && on_a <= tol;
  if (!ok)
    std::printf("  %s / %s: |a-b| %.17g vs %.17g, off x %.3g, off annulus %.3g\n", kind.c_str(), name, gap, r.distance,
                on_x, on_a);
  check::record(ok, name, __FILE__, __LINE__);
  expect_annulus_side(name, a, r.point_b, r.param_b, 1e-12 * std::max(size, (r.point_b - a.center).norm()) + world);
  expect_annulus_side(name, a, s.point_a, s.param_a, 1e-12 * std::max(size, (s.point_a - a.center).norm()) + world);
  if constexpr (std::is_same_v<X, Arc>) {
    // The arc's (t, 0) gives its point, t in [0, angle] (its own frame from the start).
    const V3d nn = x.normal.normalized(), q = x.start - nn.dot(x.start) * nn;
    const V3d u = q.normalized(), v = nn.cross(u);
    const double t = r.param_a.x();
    const V3d at = x.center + x.radius * (std::cos(t) * u + std::sin(t) * v);
    const bool in =
        t >= 0 && t <= std::min(x.angle, 2 * double(ref::kPi)) && (at - r.point_a).norm() <= 1e-12 * size + world;
    if (!in) std::printf("  %s / %s: arc param %.17g off by %.3g\n", kind.c_str(), name, t, (at - r.point_a).norm());
    check::record(in, name, __FILE__, __LINE__);
  }
  if (unique >= 0) {
    expect_unique(name, r.unique, unique == 1);
    expect_unique(name, s.unique, unique == 1);
  }
}

// An annulus equal to a disk (inner 0) or a circle (inner = outer) answers as that shape to the bit.
template <class X> void expect_same_as(const char* name, const X& x, const Annulus& a) {
  const bool as_disk = a.inner_radius == 0;
  const Disk disk{a.center, a.normal, a.outer_radius};
  const Circle circle{a.center, a.normal, a.outer_radius};
  const Result<double> r = closest_points(x, a);
  const Result<double> e = as_disk ? closest_points(x, disk) : closest_points(x, circle);
  const double d = distance(a, x), de = as_disk ? distance(disk, x) : distance(circle, x);
  const Vec2<double> param = as_disk ? e.param_b : Vec2<double>(a.outer_radius, e.param_b.x());
  const bool ok = same_bits(d, de) && same_bits(r.distance, e.distance) && r.point_a == e.point_a &&
                  r.point_b == e.point_b && r.param_b == param && r.unique == e.unique;
  if (!ok) std::printf("  %s (%s): %.17g vs %.17g\n", name, as_disk ? "disk" : "circle", d, de);
  check::record(ok, name, __FILE__, __LINE__);
}

template <class S> S moved(const S& s, const V3d& t);
template <> Annulus moved(const Annulus& a, const V3d& t) {
  return {a.center + t, a.normal, a.inner_radius, a.outer_radius};
}
template <> Circle moved(const Circle& c, const V3d& t) { return {c.center + t, c.normal, c.radius}; }
template <> Disk moved(const Disk& d, const V3d& t) { return {d.center + t, d.normal, d.radius}; }
template <> Line moved(const Line& l, const V3d& t) { return {l.origin + t, l.direction}; }
template <> Ray moved(const Ray& l, const V3d& t) { return {l.origin + t, l.direction}; }
template <> Segment moved(const Segment& s, const V3d& t) { return {s.p0 + t, s.p1 + t}; }
template <> V3d moved(const V3d& p, const V3d& t) { return p + t; }

LD ref_of(const V3d& p, const Annulus& a) { return ref_point(p, a); }
LD ref_of(const Line& p, const Annulus& a) { return ref_piece_annulus(p, a); }
LD ref_of(const Ray& p, const Annulus& a) { return ref_piece_annulus(p, a); }
LD ref_of(const Segment& p, const Annulus& a) { return ref_piece_annulus(p, a); }
LD ref_of(const Circle& c, const Annulus& a) { return ref_circle_annulus(c, a); }
LD ref_of(const Disk& d, const Annulus& a) { return ref_disk_annulus(d, a); }
LD ref_of(const Annulus& b, const Annulus& a) { return ref_annulus_annulus(b, a); }

// The case, then moved by 1e6 and 1e8 (the geometry kept, the coordinates rounded).
template <class X>
void with_translations(const std::string& kind, const char* name, const X& x, const Annulus& a, LD truth, int unique) {
  annulus_case(kind, name, x, a, truth, unique);
  for (double shift : {1e6, 1e8}) {
    const V3d t = shift * V3d(0.6, -0.3, 0.74);
    const X xt = moved(x, t);
    const Annulus at = moved(a, t);
    annulus_case(kind, shift == 1e6 ? "translated 1e6" : "translated 1e8", xt, at, ref_of(xt, at), -1);
  }
}

struct Draw : ShapeDraw {
  using ShapeDraw::ShapeDraw;
  Annulus annulus() {
    const double ro = radius();
    return {vec(), vec(), ro * (0.1 + 0.8 * uniform(rng)), ro};
  }
};

const V3d kO(0, 0, 0), kZ(0, 0, 1), kX(1, 0, 0), kY(0, 1, 0);
const Annulus kRing{kO, kZ, 1, 2};

// ---------------------------------------------------------------------------------------------

void point_tests() {
  const std::string k = "point-annulus";
  with_translations(k, "over the ring", V3d(1.2, 0.9, 0.7), kRing, 0.7L, 1);
  with_translations(k, "over the hole", V3d(0.3, 0.4, 0.5), kRing, std::sqrt(0.25L + 0.25L), 1);
  with_translations(k, "beyond", V3d(3, 0, -1), kRing, std::sqrt(2.0L), 1);
  annulus_case(k, "on the axis", V3d(0, 0, 0.5), kRing, std::sqrt(1.25L), 0);
  annulus_case(k, "at the center", kO, kRing, 1, 0);
  annulus_case(k, "on the inner rim", V3d(0.6, 0.8, 0), kRing, 0, 1);
  annulus_case(k, "radius ratio 1e-3", V3d(0.5, 0, 0.2), Annulus{kO, kZ, 1e-3, 1}, 0.2L, 1);
  annulus_case(k, "radius ratio 1e3", V3d(999.5, 0, 0.2), Annulus{kO, kZ, 1000, 1001}, std::sqrt(0.25L + 0.04L), 1);
  Draw d(3);
  for (int i = 0; i < check::scaled(200) + 20; ++i) {
    const Annulus a = d.annulus();
    const V3d p = a.center + 1.5 * a.outer_radius * d.vec();
    annulus_case(k, "random", p, a, ref_point(p, a));
    expect_same_as("point, inner 0", p, Annulus{a.center, a.normal, 0, a.outer_radius});
    expect_same_as("point, inner = outer", p, Annulus{a.center, a.normal, a.outer_radius, a.outer_radius});
  }
}

template <class Piece> Piece piece_from(const V3d& p, const V3d& q);
template <> Line piece_from(const V3d& p, const V3d& q) { return {p, q - p}; }
template <> Ray piece_from(const V3d& p, const V3d& q) { return {p, q - p}; }
template <> Segment piece_from(const V3d& p, const V3d& q) { return {p, q}; }

template <class Piece> void piece_tests(const std::string& k) {
  // Through the hole along the axis: every inner-circle point is closest.
  with_translations(k, "along the axis", piece_from<Piece>(V3d(0, 0, -3), V3d(0, 0, 3)), kRing, 1, 0);
  // Nearly along the axis, off it by 1e-10 and tilted by 1e-9.
  {
    const Piece p = piece_from<Piece>(V3d(1e-10, 0, -3), V3d(1e-10 + 6e-9, 2e-9, 3));
    annulus_case(k, "near the axis", p, kRing, ref_piece_annulus(p, kRing));
  }
  // Crossing the plane in the hole, the ring, beyond; on the inner rim.
  annulus_case(k, "crossing in the ring", piece_from<Piece>(V3d(1.5, 0.2, -1), V3d(1.3, 0.1, 1)), kRing, 0, 1);
  {
    const Piece p = piece_from<Piece>(V3d(0.3, 0.2, -1), V3d(0.1, 0.4, 1));
    with_translations(k, "crossing in the hole", p, kRing, ref_piece_annulus(p, kRing), -1);
  }
  annulus_case(k, "crossing on the inner rim", piece_from<Piece>(V3d(0.6, 0.8, -1), V3d(0.6, 0.8, 1)), kRing, 0, 1);
  // Parallel to the plane at height 0.5, its shadow tangent to the inner rim (a chord of the ring):
  // a continuum at 0.5; tangent to the outer rim: one pair.
  annulus_case(k, "tangent to the inner rim above", piece_from<Piece>(V3d(-3, 1, 0.5), V3d(3, 1, 0.5)), kRing, 0.5L, 0);
  annulus_case(k, "tangent to the outer rim above", piece_from<Piece>(V3d(-3, 2, 0.5), V3d(3, 2, 0.5)), kRing, 0.5L, 1);
  annulus_case(k, "tangent to the outer rim in the plane", piece_from<Piece>(V3d(-3, 2, 0), V3d(3, 2, 0)), kRing, 0, 1);
  // In the plane through the hole: zero along two stretches of the ring.
  annulus_case(k, "in the plane through the hole", piece_from<Piece>(V3d(-3, 0.5, 0), V3d(3, 0.5, 0)), kRing, 0, 0);
  // Tilted lines tangent to the inner rim's cylinder, just above and touching it.
  annulus_case(k, "touching the inner rim, tilted", piece_from<Piece>(V3d(-1, 1, -1), V3d(1, 1, 1)), kRing, 0, 1);
  {
    const Piece p = piece_from<Piece>(V3d(-1, 1, -1 + 1e-7), V3d(1, 1, 1 + 1e-7));
    annulus_case(k, "near the inner rim, tilted", p, kRing, ref_piece_annulus(p, kRing));
  }
  annulus_case(k, "radius ratio 1e-3, along the axis", piece_from<Piece>(V3d(0, 0, -1), V3d(0, 0, 1)),
               Annulus{kO, kZ, 1e-3, 1}, 1e-3L, 0);
  {
    const Annulus big{kO, kZ, 1000, 1001};
    const Piece p = piece_from<Piece>(V3d(999.5, -3, 0.2), V3d(999.7, 3, 0.3));
    annulus_case(k, "radius ratio 1e3", p, big, ref_piece_annulus(p, big));
  }
  Draw d(11);
  for (int i = 0; i < check::scaled(60) + 6; ++i) {
    const Annulus a = d.annulus();
    const Piece p =
        piece_from<Piece>(a.center + 1.5 * a.outer_radius * d.vec(), a.center + 1.5 * a.outer_radius * d.vec());
    annulus_case(k, "random", p, a, ref_piece_annulus(p, a));
    expect_same_as("piece, inner 0", p, Annulus{a.center, a.normal, 0, a.outer_radius});
    expect_same_as("piece, inner = outer", p, Annulus{a.center, a.normal, a.outer_radius, a.outer_radius});
  }
}

// Segments whose continuum runs from over the hole across the inner rim: the disk's closest
// point lies in the hole, the inner circle meets the continuum once (annulus.hpp's extension).
void segment_continuum_tests() {
  const std::string k = "segment-annulus";
  // The same, moved by 1e6 and 1e8: `unique` kept through the coordinates' rounding.
  for (double shift : {1e6, 1e8}) {
    const V3d t = shift * V3d(0.6, -0.3, 0.74);
    const Annulus ring = moved(kRing, t);
    annulus_case(k, "above, hole to ring, translated", Segment{V3d(0.2, 0.1, 0.5) + t, V3d(1.5, 0.3, 0.5) + t}, ring,
                 0.5L, 0);
    annulus_case(k, "in the plane, hole to ring, translated", Segment{V3d(0.2, 0.1, 0) + t, V3d(1.5, 0.3, 0) + t}, ring,
                 0, 0);
    annulus_case(k, "above, in the hole, translated", Segment{V3d(0.2, 0.1, 0.5) + t, V3d(0.6, 0.3, 0.5) + t}, ring,
                 ref_piece_annulus(Segment{V3d(0.2, 0.1, 0.5) + t, V3d(0.6, 0.3, 0.5) + t}, ring), 1);
    annulus_case("disk-annulus", "parallel, hole to ring, translated", Disk{V3d(0.5, 0, 0.5) + t, kZ, 0.8}, ring, 0.5L,
                 0);
  }
  annulus_case(k, "in the plane, hole to ring", Segment{V3d(0.2, 0.1, 0), V3d(1.5, 0.3, 0)}, kRing, 0, 0);
  annulus_case(k, "above, hole to ring", Segment{V3d(0.2, 0.1, 0.5), V3d(1.5, 0.3, 0.5)}, kRing, 0.5L, 0);
  annulus_case(k, "above, in the hole", Segment{V3d(0.2, 0.1, 0.5), V3d(0.6, 0.3, 0.5)}, kRing,
               ref_piece_annulus(Segment{V3d(0.2, 0.1, 0.5), V3d(0.6, 0.3, 0.5)}, kRing), 1);
  annulus_case(k, "in the plane, in the hole", Segment{V3d(0.2, 0.1, 0), V3d(0.6, 0, 0)}, kRing, 0.4L, 1);
}

void circle_tests() {
  const std::string k = "circle-annulus";
  with_translations(k, "in the hole, coplanar, concentric", Circle{kO, kZ, 0.5}, kRing, 0.5L, 0);
  with_translations(k, "in the hole, coplanar, off center", Circle{V3d(0.2, 0, 0), kZ, 0.5}, kRing, 0.3L, 1);
  with_translations(k, "in the hole, lifted, concentric", Circle{V3d(0, 0, 0.3), kZ, 0.6}, kRing, 0.5L, 0);
  annulus_case(k, "on the ring, coplanar, concentric", Circle{kO, kZ, 1.5}, kRing, 0, 0);
  annulus_case(k, "over the ring, concentric", Circle{V3d(0, 0, 0.4), kZ, 1.5}, kRing, 0.4L, 0);
  annulus_case(k, "the inner rim itself", Circle{kO, -kZ, 1}, kRing, 0, 0);
  annulus_case(k, "coaxial, larger, lifted", Circle{V3d(0, 0, 1), kZ, 3}, kRing, std::sqrt(2.0L), 0);
  // Linked through the hole: a vertical circle through the hole, crossing the ring.
  annulus_case(k, "linked, crossing the ring", Circle{V3d(1, 0, 0), kY, 0.5}, kRing, 0, 1);
  {
    const Circle c{V3d(0.6, 0, 0), kY, 0.5};  // meeting the plane at 0.1 (the hole) and 1.1 (the ring)
    annulus_case(k, "linked, crossing the ring near the inner rim", c, kRing, 0, 1);
    const Circle c1{V3d(1.5, 0, 0), kY, 0.3};  // meeting the ring at 1.2 and 1.8: two pairs
    annulus_case(k, "standing, crossing the ring twice", c1, kRing, 0, 0);
    const Circle c2{V3d(0.3, 0, 0), kY, 0.5};  // crossing the plane at -0.2 and 0.8: in the hole only
    annulus_case(k, "through the hole, not touching", c2, kRing, ref_circle_annulus(c2, kRing), 1);
    const Circle c3{V3d(0.5, 0, 0), kY, 0.5};  // touching the inner rim at (1, 0, 0)
    annulus_case(k, "through the hole, touching the inner rim", c3, kRing, 0, 1);
  }
  // Tilted circles of the hole's size.
  for (double tilt : {1e-9, 1e-3, 0.3}) {
    const Circle c{V3d(0, 0, 0.2), unit(std::sin(tilt), 0, std::cos(tilt)), 0.9};
    annulus_case(k, "in the hole, tilted", c, kRing, ref_circle_annulus(c, kRing));
  }
  annulus_case(k, "radius ratio 1e-3", Circle{V3d(0.5, 0.1, 0.2), unit(1, 2, 3), 1e-3}, Annulus{kO, kZ, 1e-3, 1},
               ref_circle_annulus(Circle{V3d(0.5, 0.1, 0.2), unit(1, 2, 3), 1e-3}, Annulus{kO, kZ, 1e-3, 1}));
  {
    const Circle c{V3d(0.3, 0.1, 0.2), unit(1, 2, 3), 1000};
    annulus_case(k, "radius ratio 1e3", c, kRing, ref_circle_annulus(c, kRing));
  }
  // Tangencies (round_reference.hpp's configurations): B's circle tangent to A's, A made the
  // outer rim or the inner rim of an annulus.
  int n = 0;
  for (const RoundCase& r : tangent_round_cases()) {
    const Annulus outer{r.a.center, r.a.normal, 0.4 * r.a.radius, r.a.radius},
        inner{r.a.center, r.a.normal, r.a.radius, 2.5 * r.a.radius};
    annulus_case(k, "tangent to the outer rim", r.b, outer, ref_circle_annulus(r.b, outer));
    annulus_case(k, "tangent to the inner rim", r.b, inner, ref_circle_annulus(r.b, inner));
    if (++n >= check::scaled(48) + 6) break;
  }
  Draw d(17);
  for (int i = 0; i < check::scaled(60) + 6; ++i) {
    const Annulus a = d.annulus();
    const Circle c{a.center + a.outer_radius * d.vec(), d.vec(), d.radius()};
    annulus_case(k, "random", c, a, ref_circle_annulus(c, a));
    expect_same_as("circle, inner 0", c, Annulus{a.center, a.normal, 0, a.outer_radius});
    expect_same_as("circle, inner = outer", c, Annulus{a.center, a.normal, a.outer_radius, a.outer_radius});
  }
}

void disk_tests() {
  const std::string k = "disk-annulus";
  with_translations(k, "coplanar overlapping", Disk{V3d(2, 0.5, 0), kZ, 1}, kRing, 0, 0);
  annulus_case(k, "coplanar in the hole", Disk{V3d(0.2, 0, 0), kZ, 0.5}, kRing, 0.3L, 1);
  annulus_case(k, "coplanar covering the hole", Disk{kO, kZ, 1.5}, kRing, 0, 0);
  annulus_case(k, "parallel over the hole only", Disk{V3d(0, 0, 0.5), kZ, 0.5}, kRing, std::sqrt(0.5L), 0);
  annulus_case(k, "parallel over the ring", Disk{V3d(0, 0, 0.5), kZ, 1.5}, kRing, 0.5L, 0);
  annulus_case(k, "parallel, hole to ring", Disk{V3d(0.5, 0, 0.5), kZ, 0.8}, kRing, 0.5L, 0);
  // Standing through the hole: crossing the ring on both sides (a continuum), or inside the hole only.
  annulus_case(k, "standing across the hole", Disk{kO, kY, 1.5}, kRing, 0, 0);
  annulus_case(k, "standing in the hole", Disk{V3d(0.1, 0, 0), kY, 0.5}, kRing, 0.4L, 1);
  annulus_case(k, "standing, hole to ring", Disk{V3d(0.5, 0, 0.3), kY, 0.8}, kRing, 0, 0);
  annulus_case(k, "standing on the inner rim", Disk{V3d(0.5, 0, 0.5), kY, std::sqrt(0.5)}, kRing, 0, 1);
  Draw d(19);
  for (int i = 0; i < check::scaled(40) + 4; ++i) {
    const Annulus a = d.annulus();
    const Disk x{a.center + a.outer_radius * d.vec(), d.vec(), d.radius()};
    annulus_case(k, "random", x, a, ref_disk_annulus(x, a));
    expect_same_as("disk, inner 0", x, Annulus{a.center, a.normal, 0, a.outer_radius});
    expect_same_as("disk, inner = outer", x, Annulus{a.center, a.normal, a.outer_radius, a.outer_radius});
  }
  int n = 0;
  for (const RoundCase& r : tangent_round_cases()) {
    const Annulus inner{r.a.center, r.a.normal, r.a.radius, 2.5 * r.a.radius};
    annulus_case(k, "tangent to the inner rim", r.db, inner, ref_disk_annulus(r.db, inner));
    if (++n >= check::scaled(24) + 4) break;
  }
}

void annulus_annulus_tests() {
  const std::string k = "annulus-annulus";
  with_translations(k, "coplanar overlapping", Annulus{V3d(2.5, 0.5, 0), kZ, 0.5, 1}, kRing, 0, 0);
  with_translations(k, "concentric coplanar, apart", Annulus{kO, kZ, 3, 4}, kRing, 1, 0);
  annulus_case(k, "concentric coplanar, overlapping", Annulus{kO, kZ, 1.5, 3}, kRing, 0, 0);
  annulus_case(k, "concentric coplanar, same", Annulus{kO, kZ, 1, 2}, Annulus{kO, -kZ, 1, 2}, 0, 0);
  annulus_case(k, "concentric coplanar, nested in the hole", Annulus{kO, kZ, 0.2, 0.5}, kRing, 0.5L, 0);
  annulus_case(k, "stacked concentric", Annulus{V3d(0, 0, 0.5), kZ, 1.5, 3}, kRing, 0.5L, 0);
  annulus_case(k, "coplanar in the hole, off center", Annulus{V3d(0.2, 0, 0), kZ, 0.1, 0.5}, kRing, 0.3L, 1);
  // Stacked over the hole: the outer disks' continuum lies over the hole (the rims answer), or
  // reaches the inner rim's shadow only (a circle of pairs).
  annulus_case(k, "stacked over the hole", Annulus{V3d(0, 0, 0.5), kZ, 0.5, 0.9}, kRing, std::sqrt(0.26L), 0);
  annulus_case(k, "stacked onto the inner rim's shadow", Annulus{V3d(0, 0, 0.5), kZ, 0.5, 1}, kRing, 0.5L, 0);
  {
    const Annulus off{V3d(0.3, 0, 0.5), kZ, 0.2, 0.6};  // over the hole, off center: one pair
    annulus_case(k, "stacked over the hole, off center", off, kRing, ref_annulus_annulus(off, kRing), 1);
  }
  // Chain links: each through the other's hole.
  {
    const Annulus link{V3d(1.5, 0, 0), kY, 0.9, 1.2};
    annulus_case(k, "linked, apart", link, kRing, ref_annulus_annulus(link, kRing));
    const Annulus crossing{V3d(1.5, 0, 0), kY, 0.3, 1.2};
    annulus_case(k, "linked, crossing", crossing, kRing, 0, 0);
  }
  annulus_case(k, "radius ratio 1e-3", Annulus{V3d(1.5, 0.2, 0.01), unit(1, 2, 3), 1e-4, 1e-3}, kRing,
               ref_annulus_annulus(Annulus{V3d(1.5, 0.2, 0.01), unit(1, 2, 3), 1e-4, 1e-3}, kRing));
  {
    const Annulus big{V3d(0.3, 0.1, 5), unit(0.1, 0.2, 1), 500, 1000};
    annulus_case(k, "radius ratio 1e3", big, kRing, ref_annulus_annulus(big, kRing));
  }
  Draw d(23);
  for (int i = 0; i < check::scaled(30) + 3; ++i) {
    const Annulus a = d.annulus(), b0 = d.annulus();
    const Annulus b{a.center + a.outer_radius * b0.center, b0.normal, b0.inner_radius, b0.outer_radius};
    annulus_case(k, "random", b, a, ref_annulus_annulus(b, a));
    expect_same_as("annulus, inner 0", b, Annulus{a.center, a.normal, 0, a.outer_radius});
    expect_same_as("annulus, inner = outer", b, Annulus{a.center, a.normal, a.outer_radius, a.outer_radius});
  }
}

// Random shapes in the annulus's plane, and tilted out of it by 1e-9 and 1e-5 about a random
// in-plane axis (coplanar overlaps, circles and disks in the hole or across a rim).
void coplanar_tests() {
  Draw d(37);
  for (int i = 0; i < check::scaled(40) + 6; ++i) {
    const Annulus a = d.annulus();
    const Frame<double> f(a.normal);
    const double tilt = i % 3 == 0 ? 0.0 : i % 3 == 1 ? 1e-9 : 1e-5;
    const double phi = ref::kTurn * d.uniform(d.rng);
    const V3d axis = std::cos(phi) * f.u + std::sin(phi) * f.v;
    const V3d n = std::cos(tilt) * f.n + std::sin(tilt) * axis.cross(f.n);
    const auto in_plane = [&](double spread) {
      return V3d(a.center + spread * a.outer_radius * (d.normal(d.rng) * f.u + d.normal(d.rng) * f.v));
    };
    const Circle c{in_plane(1), n, a.outer_radius * (0.1 + d.uniform(d.rng))};
    annulus_case("coplanar circle-annulus", "random", c, a, ref_circle_annulus(c, a));
    const Disk x{in_plane(1), n, a.outer_radius * (0.1 + d.uniform(d.rng))};
    annulus_case("coplanar disk-annulus", "random", x, a, ref_disk_annulus(x, a));
    const double ro = a.outer_radius * (0.1 + d.uniform(d.rng));
    const Annulus b{in_plane(1), n, ro * d.uniform(d.rng), ro};
    annulus_case("coplanar annulus-annulus", "random", b, a, ref_annulus_annulus(b, a));
    const V3d p0 = in_plane(1), p1 = in_plane(1);
    const Segment s{p0, p1 + tilt * a.outer_radius * f.n};
    annulus_case("coplanar segment-annulus", "random", s, a, ref_piece_annulus(s, a));
  }
}

// A thin ring, inner = outer (1 - 1e-9): close to the circle, but its interior still counts.
void thin_ring_tests() {
  const Annulus thin{kO, kZ, 1 - 1e-9, 1};
  annulus_case("point-annulus", "thin ring, over it", V3d(1 - 5e-10, 0, 0.3), thin, 0.3L, 1);
  annulus_case("point-annulus", "thin ring, on the axis", V3d(0, 0, 0.3), thin, ref_point(V3d(0, 0, 0.3), thin), 0);
  {
    const Line l{V3d(-2, 1 - 5e-10, 0.2), kX};  // over the ring's chord tangent to nothing: two stretches
    annulus_case("line-annulus", "thin ring, across above", l, thin, ref_piece_annulus(l, thin));
  }
  {
    const Circle c{V3d(0.3, 0.2, 0.1), unit(0.2, 0.1, 1), 0.9};
    annulus_case("circle-annulus", "thin ring", c, thin, ref_circle_annulus(c, thin));
    const Annulus b{V3d(0.1, 0, 0.05), unit(0.1, 0, 1), 0.5, 1.2};
    annulus_case("annulus-annulus", "thin ring", b, thin, ref_annulus_annulus(b, thin));
    const Disk x{V3d(0.1, 0, 0.05), unit(0.1, 0, 1), 1.2};
    annulus_case("disk-annulus", "thin ring", x, thin, ref_disk_annulus(x, thin));
  }
}

void arc_tests() {
  const std::string k = "arc-annulus";
  // In the hole, coplanar and concentric: every arc point at 0.5 from the inner rim.
  annulus_case(k, "in the hole, concentric", Arc{kO, kZ, 0.5, kX, 2}, kRing, 0.5L, 0);
  // Over the ring at a height, concentric: a continuum; tilted so that its lowest point is past
  // its end, over the ring: the end.
  annulus_case(k, "over the ring, concentric", Arc{V3d(0, 0, 0.4), kZ, 1.5, kX, 1}, kRing, 0.4L, 0);
  {
    const Arc tilted{V3d(0, 0, 0.4), unit(0.3, 0, 1), 1.5, kY, 1.2};
    annulus_case(k, "tilted over the ring, end lowest", tilted, kRing, ref_arc_annulus(tilted, kRing));
  }
  // Standing through the hole, crossing the ring once; an arc stopping short of the plane.
  annulus_case(k, "standing, crossing the ring", Arc{V3d(1, 0, 0), kY, 0.5, kX, 3}, kRing, 0, 1);
  {
    const Arc short_arc{V3d(1.5, 0, 0.6), kY, 0.5, kX, 1};
    annulus_case(k, "standing, short of the plane", short_arc, kRing, ref_arc_annulus(short_arc, kRing));
  }
  // Whole: the circle's answer; zero radius: the point's.
  annulus_case(k, "whole", Arc{V3d(0.2, 0.1, 0.3), unit(1, 2, 3), 0.7, kX, 7}, kRing,
               ref_circle_annulus(Circle{V3d(0.2, 0.1, 0.3), unit(1, 2, 3), 0.7}, kRing));
  Draw d(41);
  for (int i = 0; i < check::scaled(40) + 4; ++i) {
    const Annulus a = d.annulus();
    const Arc arc{a.center + a.outer_radius * d.vec(), d.vec(), d.radius(), d.vec(), 6.28 * d.uniform(d.rng)};
    annulus_case(k, "random", arc, a, ref_arc_annulus(arc, a));
    expect_same_as("arc, inner 0", arc, Annulus{a.center, a.normal, 0, a.outer_radius});
    expect_same_as("arc, inner = outer", arc, Annulus{a.center, a.normal, a.outer_radius, a.outer_radius});
    if (i % 5 == 0) {
      const LD truth = ref_arc_annulus(arc, a);
      annulus_case<Arc, EigenCompanion>("eigen arc-annulus", "random", arc, a, truth);
      annulus_case<Arc, EigenPolished>("eigen arc-annulus", "random", arc, a, truth);
    }
    if (i % 4 == 0) {
      const V3d t = 1e6 * d.vec();
      const Arc at{arc.center + t, arc.normal, arc.radius, arc.start, arc.angle};
      const Annulus aa{a.center + t, a.normal, a.inner_radius, a.outer_radius};
      annulus_case(k, "translated 1e6", at, aa, ref_arc_annulus(at, aa));
    }
  }
}

// The eigenvalue root policies on random scenes of the polynomial families.
void policy_tests() {
  Draw d(29);
  for (int i = 0; i < check::scaled(20) + 3; ++i) {
    const Annulus a = d.annulus();
    const Circle c{a.center + a.outer_radius * d.vec(), d.vec(), d.radius()};
    const Segment s{a.center + 1.5 * a.outer_radius * d.vec(), a.center + 1.5 * a.outer_radius * d.vec()};
    const LD tc = ref_circle_annulus(c, a), ts = ref_piece_annulus(s, a);
    annulus_case<Circle, EigenCompanion>("eigen circle-annulus", "random", c, a, tc);
    annulus_case<Circle, EigenPolished>("eigen circle-annulus", "random", c, a, tc);
    annulus_case<Segment, EigenCompanion>("eigen segment-annulus", "random", s, a, ts);
    annulus_case<Segment, EigenPolished>("eigen segment-annulus", "random", s, a, ts);
    if (i % 3 == 0) {
      const Annulus b{a.center + a.outer_radius * d.vec(), d.vec(), 0.3, 0.9};
      const LD tb = ref_annulus_annulus(b, a);
      annulus_case<Annulus, EigenCompanion>("eigen annulus-annulus", "random", b, a, tb);
      annulus_case<Annulus, EigenPolished>("eigen annulus-annulus", "random", b, a, tb);
    }
  }
  // The hard ones under every policy.
  annulus_case<Line, EigenCompanion>("eigen line-annulus", "along the axis", Line{V3d(0, 0, -1), kZ}, kRing, 1, 0);
  annulus_case<Circle, EigenCompanion>("eigen circle-annulus", "in the hole, concentric", Circle{kO, kZ, 0.5}, kRing,
                                       0.5L, 0);
  annulus_case<Annulus, EigenPolished>("eigen annulus-annulus", "concentric apart", Annulus{kO, kZ, 3, 4}, kRing, 1, 0);
}

// Long double (1e-15) and float (1e-5) against the double references.
void precision_tests() {
  const Annulus a{V3d(0.1, 0.2, 0.3), V3d(1, -2, 0.5), 0.6, 1.3};
  const Circle c{V3d(0.7, -0.4, 0.2), V3d(0.3, 1, 2), 0.9};
  const Segment s{V3d(-1, 0.5, 0.2), V3d(1.5, -0.3, 0.9)};
  const Annulus b{V3d(0.9, 0.3, -0.2), V3d(0.2, 1, 0.4), 0.3, 1.1};
  const LD tc = ref_circle_annulus(c, a), ts = ref_piece_annulus(s, a), tp = ref_point(V3d(2, 1, 0), a),
           tb = ref_annulus_annulus(b, a);
  using A = Annulus3<LD>;
  const A al{a.center.cast<LD>(), a.normal.cast<LD>(), a.inner_radius, a.outer_radius};
  const A bl{b.center.cast<LD>(), b.normal.cast<LD>(), b.inner_radius, b.outer_radius};
  CHECK_NEAR(distance(Circle3<LD>{c.center.cast<LD>(), c.normal.cast<LD>(), c.radius}, al), tc, 1e-15L);
  CHECK_NEAR(distance(Segment3<LD>{s.p0.cast<LD>(), s.p1.cast<LD>()}, al), ts, 1e-15L);
  CHECK_NEAR(distance(Vec3<LD>(2, 1, 0), al), tp, 1e-15L);
  CHECK_NEAR(closest_points(bl, al).distance, tb, 1e-15L);
  using F = Annulus3<float>;
  const F af{a.center.cast<float>(), a.normal.cast<float>(), float(a.inner_radius), float(a.outer_radius)};
  CHECK_NEAR(distance(Circle3<float>{c.center.cast<float>(), c.normal.cast<float>(), float(c.radius)}, af), tc, 1e-5);
  CHECK_NEAR(closest_points(af, Segment3<float>{s.p0.cast<float>(), s.p1.cast<float>()}).distance, ts, 1e-5);
  // Scenes of 1e180 and 1e-180 (the front end rescales them, query.hpp): the distance of the
  // scene at unit size, times the same power of two, and the annulus's s scaled back.
  for (int e : {600, -600}) {
    const Circle c{V3d(0.7, -0.4, 0.2), V3d(0.3, 1, 2), 0.9};
    const Annulus b{V3d(0.9, 0.3, -0.2), V3d(0.2, 1, 0.4), 0.3, 1.1};
    const V3d p(0.2, 0.3, 0.1);
    const Segment g{V3d(-1, 0.5, 0.2), V3d(1.5, -0.3, 0.9)};
    const Annulus as = scaled(a, e);
    const double f = std::ldexp(1.0, e);
    CHECK_NEAR(distance(scaled(c, e), as) / f, distance(c, a), 1e-12);
    CHECK_NEAR(distance(scaled(b, e), as) / f, distance(b, a), 1e-12);
    CHECK_NEAR(distance(scaled(p, e), as) / f, distance(p, a), 1e-12);
    CHECK_NEAR(distance(scaled(g, e), as) / f, distance(g, a), 1e-12);
    const Result<double> r = closest_points(scaled(g, e), as), r1 = closest_points(g, a);
    CHECK_NEAR(r.param_b.x() / f, r1.param_b.x(), 1e-12);
  }
  // Degenerate definitions: empty (inner > outer) and NaN.
  CHECK(distance(V3d(1, 2, 3), Annulus{kO, kZ, 2, 1}) == std::numeric_limits<double>::infinity());
  CHECK(std::isnan(distance(Circle{kO, kZ, 1}, Annulus{kO, kZ, std::nan(""), 1})));
}

// The disk counterpart of a shape: an annulus's outer disk, any other shape itself.
Disk as_disk(const Annulus& a) { return {a.center, a.normal, a.outer_radius}; }
template <class X> const X& as_disk(const X& x) { return x; }

// The cost against the disk counterpart: one loop of distance() over 1000 random pairs each,
// the annulus's and the disk's loops alternated 25 times and the fastest of each kept (the
// machine is shared: the minimum is the least disturbed run).
template <class X, class Make> void time_pair(const char* name, const Make& make) {
  Draw d(31);
  std::vector<X> xs;
  std::vector<Annulus> as;
  for (int i = 0; i < 1000; ++i) {
    const Annulus a = d.annulus();
    xs.push_back(make(d, a));
    as.push_back(a);
  }
  double sum = 0;
  const auto run = [&](bool ring) {
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < xs.size(); ++i) {
      if (ring)
        sum += distance(xs[i], as[i]);
      else
        sum += distance(as_disk(xs[i]), Disk{as[i].center, as[i].normal, as[i].outer_radius});
    }
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / xs.size();
  };
  double disk = 1e300, ring = 1e300;
  for (int rep = 0; rep < 25; ++rep) {
    disk = std::min(disk, run(false));
    ring = std::min(ring, run(true));
  }
  std::printf("  cost, %s: annulus %.0f ns, disk %.0f ns a distance() (x%.2f)%s\n", name, ring, disk, ring / disk,
              sum == 0.5 ? " " : "");
}

}  // namespace

int main(int argc, char** argv) {
  point_tests();
  piece_tests<Line>("line-annulus");
  piece_tests<Ray>("ray-annulus");
  piece_tests<Segment>("segment-annulus");
  segment_continuum_tests();
  circle_tests();
  disk_tests();
  annulus_annulus_tests();
  coplanar_tests();
  thin_ring_tests();
  arc_tests();
  policy_tests();
  precision_tests();
  for (const auto& [kind, n] : counts)
    std::printf("  %s: %d cases, worst relative error %.3g\n", kind.c_str(), n, worst[kind]);
  if (argc > 1 && std::strcmp(argv[1], "--time") == 0) {
    time_pair<V3d>("point", [](Draw& d, const Annulus& a) { return V3d(a.center + 1.5 * a.outer_radius * d.vec()); });
    time_pair<Segment>("segment", [](Draw& d, const Annulus& a) {
      return Segment{a.center + 1.5 * a.outer_radius * d.vec(), a.center + 1.5 * a.outer_radius * d.vec()};
    });
    time_pair<Line>("line",
                    [](Draw& d, const Annulus& a) { return Line{a.center + 1.5 * a.outer_radius * d.vec(), d.vec()}; });
    time_pair<Circle>("circle", [](Draw& d, const Annulus& a) {
      return Circle{a.center + a.outer_radius * d.vec(), d.vec(), d.radius()};
    });
    time_pair<Disk>("disk", [](Draw& d, const Annulus& a) {
      return Disk{a.center + a.outer_radius * d.vec(), d.vec(), d.radius()};
    });
    time_pair<Arc>("arc", [](Draw& d, const Annulus& a) {
      return Arc{a.center + a.outer_radius * d.vec(), d.vec(), d.radius(), d.vec(), 6.28 * d.uniform(d.rng)};
    });
    time_pair<Annulus>("annulus", [](Draw& d, const Annulus& a) {
      return Annulus{a.center + a.outer_radius * d.vec(), d.vec(), 0.3, 0.9};
    });
  }
  return check::finish("annulus");
}

}  // namespace test_annulus

CHECK_SUITE(test_annulus);
