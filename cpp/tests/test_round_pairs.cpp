// Circle-circle, circle-disk, disk-disk and Bezier-disk/circle against references computed
// independently in long double: no library code is used for them. A shape is sampled directly
// (its own frame, built differently from the library's), the closest point of a disk or circle
// to a point is the elementary projection, and the minimum over the sampled parameter is found
// by dense sampling followed by zooming (33 samples on +-h around the 4 best, h /= 8, down to
// h ~ 1e-21). Analytic values are used where the geometry gives them.
// Tolerance in double: |error| <= 1e-12 * max(true distance, largest radius).
#include <circledist/circledist.hpp>

#include "check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace circledist;
using LD = long double;
using V3 = Vec3<LD>;
using V3d = Vec3<double>;

namespace ref {

const LD kPi = 3.141592653589793238462643383279502884L;

// Any right-handed orthonormal frame of n: the angle origin differs from the library's on purpose.
struct Basis {
  V3 u, v, n;
  explicit Basis(const V3& normal) {
    n = normal / normal.norm();
    const V3 axis = std::abs(n.z()) < 0.6L ? V3(0, 0, 1) : V3(1, 0, 0);
    u = n.cross(axis).normalized();
    v = n.cross(u);
  }
};

// A circle or disk relative to an origin (a shape's center): differences of doubles are exact in
// long double, so far-away scenes are as accurate as centered ones.
struct Round {
  V3 c;
  Basis b;
  LD r;
  Round(const V3d& center, const V3d& normal, double radius, const V3d& origin)
      : c(center.cast<LD>() - origin.cast<LD>()), b(normal.cast<LD>()), r(radius) {}
  V3 at(LD t) const { return c + r * (std::cos(t) * b.u + std::sin(t) * b.v); }
  // Closest point of the ring / of the disk to p (on the axis any ring point is closest).
  V3 ring_point(const V3& p) const {
    const V3 d = p - c;
    const V3 q = d - b.n.dot(d) * b.n;
    const LD rho = q.norm();
    return rho > 0 ? V3(c + (r / rho) * q) : V3(c + r * b.u);
  }
  V3 disk_point(const V3& p) const {
    const V3 d = p - c;
    const V3 q = d - b.n.dot(d) * b.n;
    const LD rho = q.norm();
    return rho <= r ? V3(c + q) : V3(c + (r / rho) * q);
  }
};

// Minimum of f over [lo, hi] (periodic or not): dense samples, then a zoom from each of the
// lowest local minima of the samples. Each zoom level samples 33 points on +-h around every
// kept point, keeps the 4 lowest distinct local minima of those samples (a beam: near a
// tangency two narrow valleys lie side by side, and the lower one need not hold the lowest
// sample at first), and divides h by 8, down to h ~ 1e-21.
template <class F> LD minimize(const F& f, LD lo, LD hi, bool periodic, int samples = 4096) {
  std::vector<LD> value(samples + 1);
  const LD step = (hi - lo) / samples;
  for (int i = 0; i <= samples; ++i) value[i] = f(lo + step * i);
  std::vector<std::pair<LD, int>> minima;
  const int last = periodic ? samples - 1 : samples;
  for (int i = 0; i <= last; ++i) {
    const int prev = i > 0 ? i - 1 : (periodic ? samples - 1 : 0);
    const int next = i < last ? i + 1 : (periodic ? 0 : last);
    if (value[i] <= value[prev] && value[i] <= value[next]) minima.push_back({value[i], i});
  }
  std::sort(minima.begin(), minima.end());
  if (minima.size() > 24) minima.resize(24);
  LD best = std::numeric_limits<LD>::infinity();
  for (const auto& m : minima) {
    std::vector<std::pair<LD, LD>> beams{{m.first, lo + step * m.second}};  // (value, t)
    for (LD h = 2 * step; h > 1e-21L * (1 + std::abs(beams[0].second)); h /= 8) {
      std::vector<std::pair<LD, LD>> next;
      for (const auto& beam : beams) {
        LD v[33], x[33];
        for (int k = 0; k < 33; ++k) {
          x[k] = beam.second + h * (k - 16) / 16;
          if (!periodic) x[k] = std::min(std::max(x[k], lo), hi);
          v[k] = f(x[k]);
        }
        for (int k = 0; k < 33; ++k) {
          if ((k == 0 || v[k] <= v[k - 1]) && (k == 32 || v[k] <= v[k + 1])) next.push_back({v[k], x[k]});
        }
      }
      std::sort(next.begin(), next.end());
      beams.clear();
      for (const auto& c : next) {
        bool duplicate = false;
        for (const auto& kept : beams) duplicate = duplicate || std::abs(kept.second - c.second) < h / 32;
        if (!duplicate) beams.push_back(c);
        if (beams.size() == 4) break;
      }
    }
    best = std::min(best, beams[0].first);
  }
  return best;
}

LD circle_circle(const Circle3<double>& a, const Circle3<double>& b) {
  const Round ra(a.center, a.normal, a.radius, b.center), rb(b.center, b.normal, b.radius, b.center);
  return minimize([&](LD t) { const V3 p = ra.at(t); return (p - rb.ring_point(p)).norm(); }, -kPi, kPi, true);
}

LD circle_disk(const Circle3<double>& a, const Disk3<double>& b) {
  const Round ra(a.center, a.normal, a.radius, b.center), rb(b.center, b.normal, b.radius, b.center);
  return minimize([&](LD t) { const V3 p = ra.at(t); return (p - rb.disk_point(p)).norm(); }, -kPi, kPi, true);
}

// If the disks do not intersect a closest pair has a rim point (docs/disk_disk.md); the cases
// that intersect are checked against 0 analytically.
LD disk_disk(const Disk3<double>& a, const Disk3<double>& b) {
  return std::min(circle_disk({a.center, a.normal, a.radius}, b), circle_disk({b.center, b.normal, b.radius}, a));
}

V3 bezier_at(const BezierCurve3<double>& c, const V3d& origin, LD t) {
  std::vector<V3> q;
  for (int i = 0; i < c.control.cols(); ++i) q.push_back(c.control.col(i).cast<LD>() - origin.cast<LD>());
  for (int k = int(q.size()) - 1; k > 0; --k)
    for (int i = 0; i < k; ++i) q[i] = (1 - t) * q[i] + t * q[i + 1];
  return q[0];
}

LD bezier_disk(const BezierCurve3<double>& c, const Disk3<double>& d) {
  const Round rd(d.center, d.normal, d.radius, d.center);
  return minimize([&](LD t) { const V3 p = bezier_at(c, d.center, t); return (p - rd.disk_point(p)).norm(); }, 0, 1,
                  false);
}

LD bezier_circle(const BezierCurve3<double>& c, const Circle3<double>& k) {
  const Round rk(k.center, k.normal, k.radius, k.center);
  return minimize([&](LD t) { const V3 p = bezier_at(c, k.center, t); return (p - rk.ring_point(p)).norm(); }, 0, 1,
                  false);
}

}  // namespace ref

// ---------------------------------------------------------------------------------------------

std::map<std::string, double> worst;  // largest relative error per kind

// Relative error against the reference, recorded per kind; prints the case on failure.
void expect_distance(const std::string& kind, const char* name, double got, LD truth, LD size, double tol = 1e-12) {
  const LD denominator = std::max(truth, size);
  const double err = double(std::abs(LD(got) - truth) / denominator);
  worst[kind] = std::max(worst[kind], err);
  const bool ok = err <= tol;
  if (!ok) std::printf("  %s / %s: got %.17g, true %.17Lg, relative error %.3g\n", kind.c_str(), name, got, truth, err);
  check::record(ok, name, __FILE__, __LINE__);
}

void expect_unique(const char* name, bool got, bool expected) {
  if (got != expected) std::printf("  %s: unique %d, expected %d\n", name, got, expected);
  check::record(got == expected, name, __FILE__, __LINE__);
}

V3d unit(double x, double y, double z) { return V3d(x, y, z).normalized(); }

// The closest points are on their shapes, |a - b| is the distance, and the parameters give them.
// (A Bezier curve's point is checked through its parameter instead.)
template <class A> double off_shape(const V3d& p, const A& a) { return distance(p, a); }
double off_shape(const V3d&, const BezierCurve3<double>&) { return 0; }

template <class A, class B> void expect_consistent(const char* name, const A& a, const B& b, const Result<double>& r,
                                                   double size) {
  // World points carry the rounding of their coordinates (an ulp of 1e8 is 1.5e-8).
  const double world = 8 * std::numeric_limits<double>::epsilon() * std::max(r.point_a.norm(), r.point_b.norm());
  const double tol = 1e-12 * std::max(size, r.distance) + world;
  const double gap = (r.point_a - r.point_b).norm();
  const double on_a = off_shape(r.point_a, a), on_b = off_shape(r.point_b, b);
  const bool ok = std::abs(gap - r.distance) <= tol && on_a <= tol && on_b <= tol;
  if (!ok) std::printf("  %s: |a-b| %.17g vs %.17g, off a %.3g, off b %.3g\n", name, gap, r.distance, on_a, on_b);
  check::record(ok, name, __FILE__, __LINE__);
}

// The world point of a circle's parameter (theta, 0) or a disk's (s, theta), in the library's frame.
V3d circle_point(const Circle3<double>& c, const Vec2<double>& p) {
  const Frame<double> f(c.normal);
  return c.center + c.radius * (std::cos(p.x()) * f.u + std::sin(p.x()) * f.v);
}
V3d disk_point(const Disk3<double>& d, const Vec2<double>& p) {
  const Frame<double> f(d.normal);
  return d.center + p.x() * (std::cos(p.y()) * f.u + std::sin(p.y()) * f.v);
}

void expect_param(const char* name, const V3d& from_param, const V3d& point, double size) {
  const bool ok = (from_param - point).norm() <= 1e-12 * size + 8 * std::numeric_limits<double>::epsilon() * point.norm();
  if (!ok) std::printf("  %s: parameter point off by %.3g\n", name, (from_param - point).norm());
  check::record(ok, name, __FILE__, __LINE__);
}

// ---------------------------------------------------------------------------------------------

void circle_circle_case(const char* name, const Circle3<double>& a, const Circle3<double>& b, LD truth, int unique = -1) {
  const double size = std::max(a.radius, b.radius);
  const Result<double> r = closest_points(a, b);
  expect_distance("circle-circle", name, r.distance, truth, size);
  expect_distance("circle-circle", name, distance(a, b), truth, size);
  expect_distance("circle-circle", name, distance(b, a), truth, size);
  expect_consistent(name, a, b, r, size);
  expect_param(name, circle_point(a, r.param_a), r.point_a, std::max(size, (a.center - b.center).norm()));
  expect_param(name, circle_point(b, r.param_b), r.point_b, std::max(size, (a.center - b.center).norm()));
  if (unique >= 0) {
    expect_unique(name, r.unique, unique == 1);
    expect_unique(name, closest_points(b, a).unique, unique == 1);
  }
}

void circle_disk_case(const char* name, const Circle3<double>& a, const Disk3<double>& b, LD truth, int unique = -1) {
  const double size = std::max(a.radius, b.radius);
  const Result<double> r = closest_points(a, b);
  expect_distance("circle-disk", name, r.distance, truth, size);
  expect_distance("circle-disk", name, distance(a, b), truth, size);
  expect_distance("circle-disk", name, closest_points(b, a).distance, truth, size);
  expect_consistent(name, a, b, r, size);
  expect_param(name, circle_point(a, r.param_a), r.point_a, std::max(size, (a.center - b.center).norm()));
  expect_param(name, disk_point(b, r.param_b), r.point_b, std::max(size, (a.center - b.center).norm()));
  if (unique >= 0) expect_unique(name, r.unique, unique == 1);
}

void disk_disk_case(const char* name, const Disk3<double>& a, const Disk3<double>& b, LD truth, int unique = -1) {
  const double size = std::max(a.radius, b.radius);
  const Result<double> r = closest_points(a, b);
  expect_distance("disk-disk", name, r.distance, truth, size);
  expect_distance("disk-disk", name, distance(a, b), truth, size);
  expect_distance("disk-disk", name, distance(b, a), truth, size);
  expect_consistent(name, a, b, r, size);
  expect_param(name, disk_point(a, r.param_a), r.point_a, std::max(size, (a.center - b.center).norm()));
  expect_param(name, disk_point(b, r.param_b), r.point_b, std::max(size, (a.center - b.center).norm()));
  if (unique >= 0) {
    expect_unique(name, r.unique, unique == 1);
    expect_unique(name, closest_points(b, a).unique, unique == 1);
  }
}

double curve_size(const BezierCurve3<double>& c, const V3d& center) {
  double s = 0;
  for (int i = 0; i < c.control.cols(); ++i) s = std::max(s, (c.control.col(i) - center).norm());
  return s;
}

template <class Round3>
void bezier_case(const char* kind, const char* name, const BezierCurve3<double>& c, const Round3& k, LD truth,
                 int unique = -1) {
  const double size = std::max(k.radius, curve_size(c, k.center));
  const Result<double> r = closest_points(c, k);
  expect_distance(kind, name, r.distance, truth, size);
  expect_distance(kind, name, distance(k, c), truth, size);
  expect_consistent(name, c, k, r, size);
  expect_param(name, c.at(r.param_a.x()), r.point_a, size);
  if (unique >= 0) expect_unique(name, r.unique, unique == 1);
}

BezierCurve3<double> bezier(std::initializer_list<V3d> points) {
  BezierCurve3<double> c;
  c.control.resize(3, int(points.size()));
  int i = 0;
  for (const V3d& p : points) c.control.col(i++) = p;
  return c;
}

// ---------------------------------------------------------------------------------------------

void circle_circle_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  circle_circle_case("coplanar overlapping", {o, z, 1}, {V3d(1, 0, 0), z, 1}, 0, 0);
  circle_circle_case("coplanar nested", {o, z, 3}, {V3d(0.5, 0, 0), z, 1}, 1.5L, 1);
  circle_circle_case("coplanar disjoint", {o, z, 1}, {V3d(3, 0, 0), z, 0.5}, 1.5L, 1);
  circle_circle_case("concentric coplanar", {V3d(0.3, -0.2, 0.7), unit(1, 2, 3), 1}, {V3d(0.3, -0.2, 0.7), unit(1, 2, 3), 2},
                     1, 0);
  circle_circle_case("coaxial parallel planes", {o, z, 1}, {V3d(0, 0, 0.5), z, 2}, std::sqrt(1.25L), 0);
  {
    const V3d n = unit(1, 2, 3);
    circle_circle_case("coaxial tilted", {V3d(1, 1, 1), n, 1}, {V3d(1, 1, 1) + 0.5 * n, -n, 2}, std::sqrt(1.25L), 0);
  }
  // B crosses A's plane at (1,0,0), on A, and at the origin, inside A: one common point.
  circle_circle_case("linked, touching (distance 0)", {o, z, 1}, {V3d(0.5, 0, 0), V3d(0, 1, 0), 0.5}, 0, 1);
  {
    const Circle3<double> a{o, z, 1}, b{V3d(0.6, 0.05, 0.1), unit(0, 1, 0.2), 0.9};
    circle_circle_case("linked", a, b, ref::circle_circle(a, b));
  }
  // Every point of B = (1 + cos s, 0, sin s) is at distance 1 from A (and vice versa).
  circle_circle_case("through the other's center, orthogonal normals", {o, z, 1}, {V3d(1, 0, 0), V3d(0, 1, 0), 1}, 1, 0);
  circle_circle_case("touching, orthogonal planes", {o, z, 1}, {V3d(2, 0, 0), V3d(0, 1, 0), 1}, 0, 1);
  circle_circle_case("touching, coplanar outside", {o, z, 1}, {V3d(2, 0, 0), z, 1}, 0, 1);
  circle_circle_case("touching, coplanar inside", {o, z, 2}, {V3d(1, 0, 0), z, 1}, 0, 1);
  {
    const double tilt = 1e-9;
    const Circle3<double> a{o, z, 1};
    const Circle3<double> b{V3d(0.3, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 0.8};
    circle_circle_case("near-coplanar crossing", a, b, ref::circle_circle(a, b));
    const Circle3<double> c{V3d(3, 0.5, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 1};
    circle_circle_case("near-coplanar disjoint", a, c, ref::circle_circle(a, c));
    const Circle3<double> d{V3d(0.2, 0.1, 0), V3d(std::sin(tilt), 0, std::cos(tilt)), 0.5};
    circle_circle_case("near-coplanar nested", a, d, ref::circle_circle(a, d));
  }
  {
    const Circle3<double> a{V3d(0.1, 0.2, 0.3), unit(1, -2, 0.5), 1.3}, b{V3d(0.7, -0.4, 0.2), unit(0.3, 1, 2), 0.9};
    const LD truth = ref::circle_circle(a, b);
    circle_circle_case("generic", a, b, truth);
    for (double shift : {1e6, 1e8}) {
      const V3d t(shift, -0.7 * shift, 0.3 * shift);
      const Circle3<double> at{a.center + t, a.normal, a.radius}, bt{b.center + t, b.normal, b.radius};
      circle_circle_case(shift == 1e6 ? "translated 1e6" : "translated 1e8", at, bt, ref::circle_circle(at, bt));
    }
  }
  {
    const Circle3<double> big{o, z, 1};
    const Circle3<double> small{V3d(1.2, 0.3, 0.1), unit(0.2, 1, 0.4), 1e-6};
    circle_circle_case("radius ratio 1e-6", small, big, ref::circle_circle(small, big));
    const Circle3<double> onrim{V3d(0.6, 0.8, 2e-6), unit(1, 0.3, 0.2), 1e-6};
    circle_circle_case("radius ratio 1e-6 at the rim", onrim, big, ref::circle_circle(onrim, big));
    const Circle3<double> coax{V3d(0, 0, 0.5), z, 1e-6};
    circle_circle_case("radius ratio 1e-6 coaxial", coax, big, std::sqrt(0.25L + (1 - 1e-6L) * (1 - 1e-6L)), 0);
    const Circle3<double> huge{V3d(1e6 + 0.3, 0.1, 0.2), unit(0.1, 0.2, 1), 1e6};
    circle_circle_case("radius ratio 1e6", huge, big, ref::circle_circle(huge, big));
  }
  {
    // Same center, orthogonal tilted normals: A's points have rho <= 1 from B's axis, so the
    // distance 1 + 4 - 4 rho is least at A's two crossings of B's plane.
    const V3d n1 = unit(1, 2, 3), n2 = n1.cross(V3d(0, 0, 1)).normalized();
    const V3d c(0.4, -1.1, 2.3);
    circle_circle_case("same center, orthogonal normals", {c, n2, 1}, {c, n1, 2}, 1, 0);
    circle_circle_case("same center, orthogonal normals, equal radii", {c, n2, 1.5}, {c, n1, 1.5}, 0, 0);
  }
}

void circle_disk_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  circle_disk_case("in the disk's plane, inside", {V3d(0.2, 0.1, 0), z, 0.5}, {o, z, 1}, 0, 0);
  circle_disk_case("in the disk's plane, inside, tilted", {V3d(0.2, 0.1, 0), unit(1, 1, 1), 0.5},
                   {V3d(0.2, 0.1, 0), unit(1, 1, 1), 1}, 0, 0);
  circle_disk_case("crossing the disk twice", {V3d(0.1, 0, 0), V3d(0, 1, 0), 0.5}, {o, z, 1}, 0, 0);
  circle_disk_case("parallel above, projection inside", {V3d(0.1, 0.2, 0.3), z, 0.4}, {o, z, 1}, 0.3L, 0);
  circle_disk_case("coaxial, wider than the disk", {V3d(0, 0, 0.5), z, 2}, {o, z, 1}, std::sqrt(1.25L), 0);
  // In the disk frame the circle is (2 cos, 0, 2 sin): sqrt(5 - 4 |cos|) outside, least at the rim.
  circle_disk_case("same center, orthogonal, radius 2 vs 1", {o, V3d(0, 1, 0), 2}, {o, z, 1}, 1, 0);
  circle_disk_case("same center, orthogonal, radius 1 vs 2", {o, V3d(0, 1, 0), 1}, {o, z, 2}, 0, 0);
  circle_disk_case("touching the rim", {V3d(2, 0, 0), V3d(0, 1, 0), 1}, {o, z, 1}, 0, 1);
  circle_disk_case("resting on the disk", {V3d(0.2, 0, 0.5), V3d(0, 1, 0), 0.5}, {o, z, 1}, 0, 1);
  {
    const Circle3<double> a{V3d(2, 0, 0.3), V3d(0, 1, 0), 1};
    circle_disk_case("beside the rim", a, {o, z, 1}, ref::circle_disk(a, {o, z, 1}), 1);
  }
  {
    const double tilt = 1e-9;
    const Circle3<double> a{V3d(0.3, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 0.5};
    const Disk3<double> d{o, z, 1};
    circle_disk_case("near-coplanar inside", a, d, ref::circle_disk(a, d));
    const Circle3<double> b{V3d(0.3, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 1.5};
    circle_disk_case("near-coplanar around", b, d, ref::circle_disk(b, d));
    const Circle3<double> c{V3d(3, 0.2, 1e-3), V3d(std::sin(tilt), 0, std::cos(tilt)), 1.5};
    circle_disk_case("near-coplanar outside", c, d, ref::circle_disk(c, d));
  }
  {
    const Circle3<double> a{V3d(0.1, 0.2, 0.3), unit(1, -2, 0.5), 1.3};
    const Disk3<double> d{V3d(0.7, -0.4, 0.2), unit(0.3, 1, 2), 0.9};
    circle_disk_case("generic", a, d, ref::circle_disk(a, d));
    const Circle3<double> lifted{V3d(0.1, 0.2, 1.9), unit(1, -2, 0.5), 1.3};
    const LD truth = ref::circle_disk(lifted, d);
    circle_disk_case("generic lifted", lifted, d, truth);
    for (double shift : {1e6, 1e8}) {
      const V3d t(-0.4 * shift, shift, 0.9 * shift);
      const Circle3<double> at{lifted.center + t, lifted.normal, lifted.radius};
      const Disk3<double> dt{d.center + t, d.normal, d.radius};
      circle_disk_case(shift == 1e6 ? "translated 1e6" : "translated 1e8", at, dt, ref::circle_disk(at, dt));
    }
  }
  {
    const Disk3<double> big{o, z, 1};
    const Circle3<double> small{V3d(1.2, 0.3, 0.1), unit(0.2, 1, 0.4), 1e-6};
    circle_disk_case("radius ratio 1e-6", small, big, ref::circle_disk(small, big));
    const Circle3<double> over{V3d(0.3, 0.3, 1e-3), unit(0.2, 1, 0.4), 1e-6};
    circle_disk_case("radius ratio 1e-6 over the disk", over, big, ref::circle_disk(over, big));
    const Circle3<double> huge{V3d(1e6 + 0.3, 0.1, 0.2), unit(0.1, 0.2, 1), 1e6};
    circle_disk_case("radius ratio 1e6", huge, big, ref::circle_disk(huge, big));
    const Disk3<double> tiny{V3d(0.3, 0.1, 0.2), unit(0.1, 0.2, 1), 1e-6};
    const Circle3<double> unit_circle{o, unit(1, 0.5, 0.2), 1};
    circle_disk_case("disk radius ratio 1e-6", unit_circle, tiny, ref::circle_disk(unit_circle, tiny));
  }
}

void disk_disk_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  disk_disk_case("coplanar overlapping", {o, z, 1}, {V3d(1, 0.5, 0), z, 1}, 0, 0);
  disk_disk_case("coplanar nested", {o, z, 2}, {V3d(0.5, 0, 0), z, 1}, 0, 0);
  disk_disk_case("coplanar disjoint", {o, z, 1}, {V3d(3, 0, 0), z, 0.5}, 1.5L, 1);
  disk_disk_case("coplanar tangent", {o, z, 1}, {V3d(0, 2, 0), z, 1}, 0, 1);
  disk_disk_case("parallel stacked", {o, z, 1}, {V3d(0, 0, 0.5), -z, 1}, 0.5L, 0);
  disk_disk_case("parallel, partly over", {o, z, 1}, {V3d(1.2, 0, 0.5), z, 0.7}, 0.5L, 0);
  disk_disk_case("parallel, beside", {o, z, 1}, {V3d(3, 0, 0.5), z, 1}, std::sqrt(1.25L), 1);
  disk_disk_case("crossing", {o, z, 1}, {V3d(0.2, 0.1, 0.1), unit(1, 0.3, 0.2), 0.8}, 0, 0);
  disk_disk_case("T touching", {o, z, 1}, {V3d(0.3, 0.2, 0.5), V3d(1, 0, 0), 0.5}, 0, 1);
  disk_disk_case("rim over the face", {o, z, 1}, {V3d(0.3, 0.2, 0.6), V3d(1, 0, 0), 0.5}, 0.1L, 1);
  {
    const double tilt = 1e-9;
    const Disk3<double> a{o, z, 1};
    const Disk3<double> b{V3d(0.5, 0.2, 1e-3), V3d(std::sin(tilt), 0, std::cos(tilt)), 1};
    disk_disk_case("near-parallel above", a, b, ref::disk_disk(a, b));
    const Disk3<double> c{V3d(0.5, 0.2, 1e-10), V3d(std::sin(tilt), 0, std::cos(tilt)), 1};
    disk_disk_case("near-coplanar crossing", a, c, 0, 0);
  }
  {
    const Disk3<double> a{V3d(0.1, 0.2, 1.9), unit(1, -2, 0.5), 1.3}, b{V3d(0.7, -0.4, 0.2), unit(0.3, 1, 2), 0.9};
    disk_disk_case("generic", a, b, ref::disk_disk(a, b));
    for (double shift : {1e6, 1e8}) {
      const V3d t(shift, 0.3 * shift, -0.8 * shift);
      const Disk3<double> at{a.center + t, a.normal, a.radius}, bt{b.center + t, b.normal, b.radius};
      disk_disk_case(shift == 1e6 ? "translated 1e6" : "translated 1e8", at, bt, ref::disk_disk(at, bt));
    }
  }
}

void bezier_tests() {
  const V3d o(0, 0, 0), z(0, 0, 1);
  const Disk3<double> disk{o, z, 1};
  const Circle3<double> ring{o, z, 1};
  {
    // Collinear, evenly spaced control points: the segment itself, with the same parameter.
    const V3d p(-1.5, 0.7, 0.4), q(2.1, -0.3, -0.2);
    const BezierCurve3<double> line = bezier({p, (2 * p + q) / 3, (p + 2 * q) / 3, q});
    const Segment3<double> seg{p, q};
    const double expected = distance(seg, disk);
    bezier_case("bezier-disk", "straight = segment", line, disk, ref::bezier_disk(line, disk));
    check::record(std::abs(distance(line, disk) - expected) <= 1e-12, "straight vs segment-disk", __FILE__, __LINE__);
    const BezierCurve3<double> high = bezier({V3d(-2, 0.5, 0.3), V3d(2, -0.5, -0.1)});
    bezier_case("bezier-disk", "degree 1 over the disk", high, disk, ref::bezier_disk(high, disk));
    check::record(std::abs(distance(high, disk) - distance(Segment3<double>{V3d(-2, 0.5, 0.3), V3d(2, -0.5, -0.1)}, disk)) <=
                      1e-12,
                  "degree 1 vs segment-disk", __FILE__, __LINE__);
  }
  {
    // y = 1 + (2t - 1)^2, x = 2t - 1 in the disk's plane: touches the rim at (0, 1, 0).
    const BezierCurve3<double> touch = bezier({V3d(-1, 2, 0), V3d(0, 0, 0), V3d(1, 2, 0)});
    bezier_case("bezier-disk", "tangent to the rim", touch, disk, 0, 1);
    bezier_case("bezier-circle", "tangent to the circle", touch, ring, 0, 1);
    const BezierCurve3<double> lifted = bezier({V3d(-1, 2, 1e-3), V3d(0, 0, 1e-3), V3d(1, 2, 1e-3)});
    bezier_case("bezier-disk", "tangent to the rim, lifted", lifted, disk, 1e-3L, 1);
    bezier_case("bezier-circle", "tangent to the circle, lifted", lifted, ring, 1e-3L, 1);
  }
  {
    const BezierCurve3<double> flat = bezier({V3d(-2, 0.1, 0), V3d(-0.5, 0.8, 0), V3d(0.5, -0.6, 0), V3d(2, 0.2, 0)});
    bezier_case("bezier-disk", "in the disk's plane, across", flat, disk, 0, 0);
    bezier_case("bezier-circle", "in the circle's plane, across", flat, ring, ref::bezier_circle(flat, ring));
    const BezierCurve3<double> outside = bezier({V3d(1.5, -1, 0), V3d(2.5, 0, 0), V3d(1.5, 1, 0)});
    bezier_case("bezier-disk", "in the disk's plane, outside", outside, disk, ref::bezier_disk(outside, disk));
  }
  {
    const BezierCurve3<double> rim = bezier({V3d(0.2, 0.1, 0.5), V3d(0.8, 0.3, 0.4), V3d(1.6, 0.4, 0.1), V3d(2.2, -0.2, 0.3)});
    bezier_case("bezier-disk", "crossing the rim", rim, disk, ref::bezier_disk(rim, disk));
    bezier_case("bezier-circle", "crossing the rim", rim, ring, ref::bezier_circle(rim, ring));
  }
  {
    // A quintic with four local minima of the distance to the disk and to the circle (at
    // 0.110, 0.121, 0.381 and 0.442: the two lowest are close competitors).
    const BezierCurve3<double> four = bezier({V3d(1.9, -1.2, 0.7), V3d(-0.1, 0.9, -1.6), V3d(-1.2, 0, 0.5),
                                              V3d(-1.1, -3.2, -0.6), V3d(-1.1, 0.9, -0.8), V3d(1.4, 0, 0)});
    bezier_case("bezier-disk", "degree 5, four local minima", four, disk, ref::bezier_disk(four, disk), 1);
    bezier_case("bezier-circle", "degree 5, four local minima", four, ring, ref::bezier_circle(four, ring), 1);
    // A quintic waving over the disk and around the circle.
    const BezierCurve3<double> wave = bezier({V3d(-1.6, -0.2, 0.4), V3d(-1.0, 1.4, -0.3), V3d(-0.3, -1.5, 0.9),
                                              V3d(0.4, 1.6, -0.6), V3d(1.0, -1.2, 0.7), V3d(1.7, 0.3, 0.2)});
    bezier_case("bezier-disk", "degree 5 waving", wave, disk, ref::bezier_disk(wave, disk));
    bezier_case("bezier-circle", "degree 5 waving", wave, ring, ref::bezier_circle(wave, ring));
    const Disk3<double> tilted{V3d(0.1, 0.2, 0.6), unit(0.3, 0.4, 1), 0.8};
    bezier_case("bezier-disk", "degree 5 waving, tilted disk", wave, tilted, ref::bezier_disk(wave, tilted));
    for (double shift : {1e6, 1e8}) {
      BezierCurve3<double> moved = wave;
      const V3d t(0.6 * shift, -shift, 0.2 * shift);
      for (int i = 0; i < moved.control.cols(); ++i) moved.control.col(i) += t;
      const Disk3<double> dt{tilted.center + t, tilted.normal, tilted.radius};
      bezier_case("bezier-disk", shift == 1e6 ? "translated 1e6" : "translated 1e8", moved, dt, ref::bezier_disk(moved, dt));
    }
  }
}

// Random configurations of every kind against the references.
void random_tests() {
  std::mt19937_64 rng(20240611);
  std::normal_distribution<double> normal;
  auto vec = [&] { return V3d(normal(rng), normal(rng), normal(rng)); };
  auto radius = [&] { return std::exp(0.7 * normal(rng)); };
  for (int k = 0; k < 60; ++k) {
    const Circle3<double> a{vec(), vec(), radius()}, b{vec(), vec(), radius()};
    circle_circle_case("random", a, b, ref::circle_circle(a, b));
    const Disk3<double> d{b.center, b.normal, b.radius};
    circle_disk_case("random", a, d, ref::circle_disk(a, d));
    const Disk3<double> e{a.center, a.normal, a.radius};
    disk_disk_case("random", e, d, ref::disk_disk(e, d));
    const int degree = 1 + k % 7;
    BezierCurve3<double> c;
    c.control.resize(3, degree + 1);
    for (int i = 0; i <= degree; ++i) c.control.col(i) = vec();
    bezier_case("bezier-disk", "random", c, d, ref::bezier_disk(c, d));
    bezier_case("bezier-circle", "random", c, b, ref::bezier_circle(c, b));
  }
}

// ring_search_intervals (the octic's pruning): for random, touching and linked pairs, the angle
// at which A comes closest to B's ring, found by the reference minimizer on the library's own
// parametrization of A, lies in the intervals kept for the sampled bound. So does every angle
// whose distance ties with it (two-sample check: the second-best local minimum when it ties).
void pruning_tests() {
  std::mt19937_64 rng(20261123);
  std::normal_distribution<double> normal;
  auto vec = [&] { return V3d(normal(rng), normal(rng), normal(rng)); };
  auto radius = [&] { return std::exp(0.7 * normal(rng)); };
  int pruned = 0, total = 0;
  for (int k = 0; k < 300; ++k) {
    Circle3<double> a{vec(), vec(), radius()}, b{vec(), vec(), radius()};
    if (k % 3 == 1) b.center = a.center + a.radius * Frame<double>(a.normal).u + 1e-9 * vec();  // touching
    if (k % 3 == 2) b = {a.center + a.radius * Frame<double>(a.normal).u, Frame<double>(a.normal).u, a.radius};  // linked
    const circledist::Round<double> round(b.center, b.normal, b.radius);
    const LocalCircle<double> c(a, round);
    const double scale = circle_round_scale(c, b.radius);
    const V3 o = c.center.cast<LD>(), e1 = c.e1.cast<LD>(), e2 = c.e2.cast<LD>();
    LD best_t = 0, best_h = std::numeric_limits<LD>::infinity();
    const auto h = [&](LD t) {
      const V3 p = o + std::cos(t) * e1 + std::sin(t) * e2;
      const LD rho = std::sqrt(p.x() * p.x() + p.y() * p.y());
      const LD value = std::sqrt(p.z() * p.z() + (rho - LD(b.radius)) * (rho - LD(b.radius)));
      if (value < best_h) {
        best_h = value;
        best_t = t;
      }
      return value;
    };
    ref::minimize(h, -ref::kPi, ref::kPi, true);
    const double bound = sampled_distance(c, [&](const V3d& p) { return RingTarget<double>::distance_squared(p, b.radius); });
    CHECK(bound >= double(best_h) - 1e-15 * scale);
    const Intervals<double> kept = ring_search_intervals(c, b.radius, bound + 1e-4 * scale);
    const double u = std::tan(double(best_t) / 2);
    CHECK(kept.contains(u));
    if (!kept.contains(u)) std::printf("pruning case %d: u* = %.17g outside the kept intervals\n", k, u);
    ++total;
    if (!(kept.count == 1 && kept.lo[0] == -std::numeric_limits<double>::infinity() &&
          kept.hi[0] == std::numeric_limits<double>::infinity()))
      ++pruned;
  }
  // Not a requirement, but pruning that never prunes would be a defect worth seeing.
  CHECK(pruned > total / 2);
  std::printf("pruning: %d of %d pairs searched on part of the circle only\n", pruned, total);
}

// Tangencies (multiple roots: the hardest candidates) in random orientations: B touches A at a
// point p with a common tangent line, exactly or offset by up to 1e-12..1, and curves tangent to
// A's rim at p.
void tangency_tests() {
  std::mt19937_64 rng(77);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0, 1);
  auto vec = [&] { return V3d(normal(rng), normal(rng), normal(rng)); };
  for (int k = 0; k < 48; ++k) {
    const V3d ca = vec(), na = vec().normalized();
    const double ra = std::exp(normal(rng)), rb = std::exp(normal(rng));
    const Frame<double> f(na);
    const double t = 6.283185307179586 * uniform(rng);
    const V3d p = ca + ra * (std::cos(t) * f.u + std::sin(t) * f.v);
    const V3d tangent = -std::sin(t) * f.u + std::cos(t) * f.v, radial = (p - ca).normalized();
    const double offset = k % 2 == 0 ? 0.0 : std::pow(10.0, -12 * uniform(rng));
    V3d cb, nb;
    if (k % 3 == 0) {  // B's plane turned about the common tangent
      const double phi = 6.283185307179586 * uniform(rng);
      const V3d in_b = std::cos(phi) * radial + std::sin(phi) * na;
      cb = p + rb * in_b + offset * vec();
      nb = tangent.cross(in_b);
    } else if (k % 3 == 1) {  // coplanar, outside or inside
      cb = p + (uniform(rng) < 0.5 ? rb : -rb) * radial + offset * vec();
      nb = na;
    } else {  // B standing on A's rim
      cb = p + rb * radial + offset * vec();
      nb = tangent;
    }
    const Circle3<double> a{ca, na, ra}, b{cb, nb, rb};
    const Disk3<double> da{ca, na, ra}, db{cb, nb, rb};
    circle_circle_case("tangent", a, b, ref::circle_circle(a, b));
    circle_disk_case("tangent", b, da, ref::circle_disk(b, da));
    disk_disk_case("tangent", da, db, ref::disk_disk(da, db));
    const int degree = 2 + k % 6;
    const double bend = (uniform(rng) - 0.3) * 0.5, lift = k % 4 < 2 ? 0.0 : 10 * offset;
    BezierCurve3<double> c;
    c.control.resize(3, degree + 1);
    for (int j = 0; j <= degree; ++j) {
      const double s = -1 + 2.0 * j / degree;
      c.control.col(j) = p + s * tangent + bend * s * s * radial + lift * na;
    }
    bezier_case("bezier-disk", "tangent", c, da, ref::bezier_disk(c, da));
    bezier_case("bezier-circle", "tangent", c, a, ref::bezier_circle(c, a));
  }
}

// ---------------------------------------------------------------------------------------------

// Every query for float and long double: compiles, and agrees with the double answer.
template <class Real> void other_precision(const char* name, double tol) {
  using V = Vec3<Real>;
  const Circle3<Real> a{V(Real(0.1), Real(0.2), Real(1.9)), V(Real(1), Real(-2), Real(0.5)), Real(1.3)};
  const Circle3<Real> b{V(Real(0.7), Real(-0.4), Real(0.2)), V(Real(0.3), Real(1), Real(2)), Real(0.9)};
  const Disk3<Real> da{a.center, a.normal, a.radius}, db{b.center, b.normal, b.radius};
  BezierCurve3<Real> c;
  c.control.resize(3, 6);
  const double wave[6][3] = {{-1.6, -0.2, 0.4}, {-1.0, 1.4, -0.3}, {-0.3, -1.5, 0.9},
                             {0.4, 1.6, -0.6},  {1.0, -1.2, 0.7}, {1.7, 0.3, 0.2}};
  for (int i = 0; i < 6; ++i) c.control.col(i) = V(Real(wave[i][0]), Real(wave[i][1]), Real(wave[i][2]));
  const Circle3<double> ad{a.center.template cast<double>(), a.normal.template cast<double>(), double(a.radius)};
  const Circle3<double> bd{b.center.template cast<double>(), b.normal.template cast<double>(), double(b.radius)};
  const Disk3<double> dad{ad.center, ad.normal, ad.radius}, dbd{bd.center, bd.normal, bd.radius};
  BezierCurve3<double> cd;
  cd.control = c.control.template cast<double>();
  const double values[][2] = {
      {double(distance(a, b)), double(ref::circle_circle(ad, bd))},
      {double(closest_points(b, a).distance), double(ref::circle_circle(ad, bd))},
      {double(distance(a, db)), double(ref::circle_disk(ad, dbd))},
      {double(closest_points(db, a).distance), double(ref::circle_disk(ad, dbd))},
      {double(distance(da, db)), double(ref::disk_disk(dad, dbd))},
      {double(closest_points(db, da).distance), double(ref::disk_disk(dad, dbd))},
      {double(distance(c, db)), double(ref::bezier_disk(cd, dbd))},
      {double(closest_points(db, c).distance), double(ref::bezier_disk(cd, dbd))},
      {double(distance(c, b)), double(ref::bezier_circle(cd, bd))},
      {double(closest_points(b, c).distance), double(ref::bezier_circle(cd, bd))},
  };
  for (const auto& v : values) {
    const bool ok = std::abs(v[0] - v[1]) <= tol * std::max(1.0, v[1]);
    if (!ok) std::printf("  %s: %.17g vs %.17g\n", name, v[0], v[1]);
    check::record(ok, name, __FILE__, __LINE__);
  }
}

int main() {
  circle_circle_tests();
  circle_disk_tests();
  disk_disk_tests();
  bezier_tests();
  random_tests();
  tangency_tests();
  pruning_tests();
  other_precision<float>("float", 1e-5);
  other_precision<long double>("long double", 1e-15);
  for (const auto& w : worst) std::printf("largest relative error, %s: %.3g\n", w.first.c_str(), w.second);
  return check::finish("round_pairs");
}
