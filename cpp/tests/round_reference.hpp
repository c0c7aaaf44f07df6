// The reference machinery of the round-pair tests (test_circle_circle.cpp, test_circle_disk.cpp,
// test_disk_disk.cpp, test_bezier.cpp): circle-circle, circle-disk, disk-disk and Bezier-disk/circle
// against references computed independently in long double: no library code is used for them. A
// shape is sampled directly (its own frame, built differently from the library's), the closest
// point of a disk or circle to a point is the elementary projection, and the minimum over the
// sampled parameter is found by dense sampling followed by zooming (33 samples on +-h around the 4
// best, h /= 8, down to h ~ 1e-21). Analytic values are used where the geometry gives them.
// Tolerance in double: |error| <= 1e-12 * max(true distance, largest radius).
// Also the random and tangent configurations every family draws from the same seeded streams.
#pragma once

#include <circledist/circledist.hpp>

#include "check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

using namespace circledist;
using LD = long double;
using V3 = Vec3<LD>;
using V3d = Vec3<double>;

namespace ref {

// A whole turn, 2 pi rounded to double: an arc of this angle is its circle.
inline constexpr double kTurn = 6.283185307179586;

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

inline LD circle_circle(const Circle3<double>& a, const Circle3<double>& b) {
  const Round ra(a.center, a.normal, a.radius, b.center), rb(b.center, b.normal, b.radius, b.center);
  return minimize(
      [&](LD t) {
        const V3 p = ra.at(t);
        return (p - rb.ring_point(p)).norm();
      },
      -kPi, kPi, true);
}

inline LD circle_disk(const Circle3<double>& a, const Disk3<double>& b) {
  const Round ra(a.center, a.normal, a.radius, b.center), rb(b.center, b.normal, b.radius, b.center);
  return minimize(
      [&](LD t) {
        const V3 p = ra.at(t);
        return (p - rb.disk_point(p)).norm();
      },
      -kPi, kPi, true);
}

// If the disks do not intersect a closest pair has a rim point (docs/derivations/disk_disk.md); the cases
// that intersect are checked against 0 analytically.
inline LD disk_disk(const Disk3<double>& a, const Disk3<double>& b) {
  return std::min(circle_disk({a.center, a.normal, a.radius}, b), circle_disk({b.center, b.normal, b.radius}, a));
}

inline V3 bezier_at(const BezierCurve3<double>& c, const V3d& origin, LD t) {
  std::vector<V3> q;
  for (int i = 0; i < c.control.cols(); ++i) q.push_back(c.control.col(i).cast<LD>() - origin.cast<LD>());
  for (int k = int(q.size()) - 1; k > 0; --k)
    for (int i = 0; i < k; ++i) q[i] = (1 - t) * q[i] + t * q[i + 1];
  return q[0];
}

inline LD bezier_disk(const BezierCurve3<double>& c, const Disk3<double>& d) {
  const Round rd(d.center, d.normal, d.radius, d.center);
  return minimize(
      [&](LD t) {
        const V3 p = bezier_at(c, d.center, t);
        return (p - rd.disk_point(p)).norm();
      },
      0, 1, false);
}

inline LD bezier_circle(const BezierCurve3<double>& c, const Circle3<double>& k) {
  const Round rk(k.center, k.normal, k.radius, k.center);
  return minimize(
      [&](LD t) {
        const V3 p = bezier_at(c, k.center, t);
        return (p - rk.ring_point(p)).norm();
      },
      0, 1, false);
}

// An arc relative to an origin, in its own frame: u from the start's projection onto the plane
// (the circle's angle 0, Frame's U, where the start has none: the definition's fallback), v = n x u.
struct Arc {
  V3 c, n, u, v;
  LD r, angle;
  bool whole;
  Arc(const Arc3<double>& a, const V3d& origin) : c(a.center.cast<LD>() - origin.cast<LD>()), r(a.radius) {
    n = a.normal.cast<LD>() / a.normal.cast<LD>().norm();
    const V3 s = a.start.cast<LD>();
    const V3 q = s - n.dot(s) * n;
    u = q.norm() > 0 ? V3(q / q.norm()) : V3(Frame<double>(a.normal).u.cast<LD>());
    v = n.cross(u);
    whole = a.angle >= kTurn;
    angle = whole ? 2 * kPi : LD(std::max(a.angle, 0.0));
  }
  V3 at(LD t) const { return c + r * (std::cos(t) * u + std::sin(t) * v); }
  // The distance from p (relative to the origin): the ring's where p's angle lies on the arc (the
  // distance to the circle's point rises with the angular gap up to pi), else the nearer end's.
  LD distance(const V3& p) const {
    const V3 d = p - c;
    const LD z = d.dot(n), x = d.dot(u), y = d.dot(v);
    const LD rho = std::hypot(x, y);
    LD phi = std::atan2(y, x);
    if (phi < 0) phi += 2 * kPi;
    if (phi <= angle || rho == 0) return std::hypot(z, rho - r);
    return std::min((p - at(0)).norm(), (p - at(angle)).norm());
  }
  // The minimum over the arc of f(point): dense sampling and zooming.
  template <class F> LD min_over(const F& f, int samples = 4096) const {
    if (!(r > 0) || angle == 0) return f(at(0));
    return minimize([&](LD t) { return f(at(t)); }, 0, angle, whole, samples);
  }
};

}  // namespace ref

// ---------------------------------------------------------------------------------------------

inline std::map<std::string, double> worst;  // largest relative error per kind

// Relative error against the reference, recorded per kind; prints the case on failure.
inline void expect_distance(const std::string& kind, const char* name, double got, LD truth, LD size,
                            double tol = 1e-12) {
  const LD denominator = std::max(truth, size);
  const double err = double(std::abs(LD(got) - truth) / denominator);
  worst[kind] = std::max(worst[kind], err);
  const bool ok = err <= tol;
  if (!ok) std::printf("  %s / %s: got %.17g, true %.17Lg, relative error %.3g\n", kind.c_str(), name, got, truth, err);
  check::record(ok, name, __FILE__, __LINE__);
}

inline void expect_unique(const char* name, bool got, bool expected) {
  if (got != expected) std::printf("  %s: unique %d, expected %d\n", name, got, expected);
  check::record(got == expected, name, __FILE__, __LINE__);
}

inline V3d unit(double x, double y, double z) { return V3d(x, y, z).normalized(); }

// The closest points are on their shapes, |a - b| is the distance, and the parameters give them.
// (A Bezier curve's point is checked through its parameter instead.)
template <class A> double off_shape(const V3d& p, const A& a) { return distance(p, a); }
inline double off_shape(const V3d&, const BezierCurve3<double>&) { return 0; }

template <class A, class B>
void expect_consistent(const char* name, const A& a, const B& b, const Result<double>& r, double size) {
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
inline V3d round_point(const Circle3<double>& c, const Vec2<double>& p) {
  const Frame<double> f(c.normal);
  return c.center + c.radius * (std::cos(p.x()) * f.u + std::sin(p.x()) * f.v);
}
inline V3d round_point(const Disk3<double>& d, const Vec2<double>& p) {
  const Frame<double> f(d.normal);
  return d.center + p.x() * (std::cos(p.y()) * f.u + std::sin(p.y()) * f.v);
}

inline void expect_param(const char* name, const V3d& from_param, const V3d& point, double size) {
  const bool ok =
      (from_param - point).norm() <= 1e-12 * size + 8 * std::numeric_limits<double>::epsilon() * point.norm();
  if (!ok) std::printf("  %s: parameter point off by %.3g\n", name, (from_param - point).norm());
  check::record(ok, name, __FILE__, __LINE__);
}

// ---------------------------------------------------------------------------------------------

// A round-round case (`kind` its family): the distance in both orders, the closest points'
// consistency and parameters and, when `unique` >= 0, their uniqueness. For two rounds of one
// kind the other order is distance(b, a) and uniqueness is checked in both orders; circle-disk
// checks the other order through closest_points(b, a)'s distance.
template <class A, class B>
void round_round_case(const char* kind, const char* name, const A& a, const B& b, LD truth, int unique) {
  constexpr bool one_kind = std::is_same_v<A, B>;
  const double size = std::max(a.radius, b.radius);
  const Result<double> r = closest_points(a, b);
  expect_distance(kind, name, r.distance, truth, size);
  expect_distance(kind, name, distance(a, b), truth, size);
  expect_distance(kind, name, one_kind ? distance(b, a) : closest_points(b, a).distance, truth, size);
  expect_consistent(name, a, b, r, size);
  expect_param(name, round_point(a, r.param_a), r.point_a, std::max(size, (a.center - b.center).norm()));
  expect_param(name, round_point(b, r.param_b), r.point_b, std::max(size, (a.center - b.center).norm()));
  if (unique >= 0) {
    expect_unique(name, r.unique, unique == 1);
    if (one_kind) expect_unique(name, closest_points(b, a).unique, unique == 1);
  }
}
inline void circle_circle_case(const char* name, const Circle3<double>& a, const Circle3<double>& b, LD truth,
                               int unique = -1) {
  round_round_case("circle-circle", name, a, b, truth, unique);
}
inline void circle_disk_case(const char* name, const Circle3<double>& a, const Disk3<double>& b, LD truth,
                             int unique = -1) {
  round_round_case("circle-disk", name, a, b, truth, unique);
}
inline void disk_disk_case(const char* name, const Disk3<double>& a, const Disk3<double>& b, LD truth,
                           int unique = -1) {
  round_round_case("disk-disk", name, a, b, truth, unique);
}

inline double curve_size(const BezierCurve3<double>& c, const V3d& center) {
  double s = 0;
  for (int i = 0; i < c.control.cols(); ++i) s = std::max(s, (c.control.col(i) - center).norm());
  return s;
}

template <class Round3> inline void bezier_case(const char* kind, const char* name, const BezierCurve3<double>& c,
                                                const Round3& k, LD truth, int unique = -1) {
  const double size = std::max(k.radius, curve_size(c, k.center));
  const Result<double> r = closest_points(c, k);
  expect_distance(kind, name, r.distance, truth, size);
  expect_distance(kind, name, distance(k, c), truth, size);
  expect_consistent(name, c, k, r, size);
  expect_param(name, c.at(r.param_a.x()), r.point_a, size);
  if (unique >= 0) expect_unique(name, r.unique, unique == 1);
}

// A shape moved by t: its points move, its normal and radius stay.
inline Circle3<double> translated(const Circle3<double>& c, const V3d& t) { return {c.center + t, c.normal, c.radius}; }
inline Disk3<double> translated(const Disk3<double>& d, const V3d& t) { return {d.center + t, d.normal, d.radius}; }
inline BezierCurve3<double> translated(const BezierCurve3<double>& c, const V3d& t) {
  BezierCurve3<double> moved = c;
  for (int i = 0; i < moved.control.cols(); ++i) moved.control.col(i) += t;
  return moved;
}

// A scene far from the origin: check(name, a', b') for a and b moved together by 1e6 and 1e8
// times `direction` (the coordinates then round, the geometry stays).
template <class A, class B, class Check>
void translated_cases(const A& a, const B& b, const V3d& direction, const Check& check) {
  for (double shift : {1e6, 1e8}) {
    const V3d t = shift * direction;
    check(shift == 1e6 ? "translated 1e6" : "translated 1e8", translated(a, t), translated(b, t));
  }
}

// The cases circle-circle and circle-disk both check, with B a circle or a disk
// (`check(name, circle, round)`): a circle and a round in general position, and circles a
// million times smaller and larger than a unit round at the origin.
template <class Round3> Round3 generic_round() { return {V3d(0.7, -0.4, 0.2), unit(0.3, 1, 2), 0.9}; }
inline Circle3<double> generic_circle() { return {V3d(0.1, 0.2, 0.3), unit(1, -2, 0.5), 1.3}; }
template <class Round3, class Check> void circle_round_shared_cases(const Check& check) {
  check("generic", generic_circle(), generic_round<Round3>());
  const Round3 big{V3d(0, 0, 0), V3d(0, 0, 1), 1};
  check("radius ratio 1e-6", Circle3<double>{V3d(1.2, 0.3, 0.1), unit(0.2, 1, 0.4), 1e-6}, big);
  check("radius ratio 1e6", Circle3<double>{V3d(1e6 + 0.3, 0.1, 0.2), unit(0.1, 0.2, 1), 1e6}, big);
}

// The random stream the shape tests draw from (test_arc.cpp, test_annulus.cpp,
// test_bezier_arc.cpp each add their shapes): normal vectors, radii e^(0.7 N).
struct ShapeDraw {
  std::mt19937_64 rng;
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform{0, 1};
  explicit ShapeDraw(std::uint64_t seed) : rng(seed) {}
  V3d vec() { return V3d(normal(rng), normal(rng), normal(rng)); }
  double radius() { return std::exp(0.7 * normal(rng)); }
  // An arc's angle: a tenth below 1e-6..1, a tenth within 1e-3 of 2 pi, the rest up to 2 pi.
  double angle() {
    const double turn = ref::kTurn, x = uniform(rng);
    return x < 0.1   ? std::pow(10.0, -6 * uniform(rng))
           : x < 0.2 ? turn * (1 - 1e-3 * uniform(rng))
                     : turn * uniform(rng);
  }
  Arc3<double> arc() { return {vec(), vec(), radius(), vec(), angle()}; }
};

inline BezierCurve3<double> bezier(std::initializer_list<V3d> points) {
  BezierCurve3<double> c;
  c.control.resize(3, int(points.size()));
  int i = 0;
  for (const V3d& p : points) c.control.col(i++) = p;
  return c;
}

// ---------------------------------------------------------------------------------------------

// A configuration every round family checks: A and B as circles (a, b) and as disks (da, db),
// and a curve (c).
struct RoundCase {
  Circle3<double> a, b;
  Disk3<double> da, db;
  BezierCurve3<double> c;
};

// Random configurations of every kind against the references, a curve of degree 1 + k % 7.
// Drawn in one stream, whichever family checks them.
inline std::vector<RoundCase> random_round_cases() {
  std::mt19937_64 rng(20240611);
  std::normal_distribution<double> normal;
  auto vec = [&] { return V3d(normal(rng), normal(rng), normal(rng)); };
  auto radius = [&] { return std::exp(0.7 * normal(rng)); };
  std::vector<RoundCase> out;
  for (int k = 0; k < 60; ++k) {
    const Circle3<double> a{vec(), vec(), radius()}, b{vec(), vec(), radius()};
    const Disk3<double> da{a.center, a.normal, a.radius}, db{b.center, b.normal, b.radius};
    const int degree = 1 + k % 7;
    BezierCurve3<double> c;
    c.control.resize(3, degree + 1);
    for (int i = 0; i <= degree; ++i) c.control.col(i) = vec();
    out.push_back({a, b, da, db, c});
  }
  return out;
}

// Tangencies (multiple roots: the hardest candidates) in random orientations: B touches A at a
// point p with a common tangent line, exactly or offset by up to 1e-12..1, and curves tangent to
// A's rim at p (c).
inline std::vector<RoundCase> tangent_round_cases() {
  std::mt19937_64 rng(77);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0, 1);
  auto vec = [&] { return V3d(normal(rng), normal(rng), normal(rng)); };
  std::vector<RoundCase> out;
  for (int k = 0; k < 48; ++k) {
    const V3d ca = vec(), na = vec().normalized();
    const double ra = std::exp(normal(rng)), rb = std::exp(normal(rng));
    const Frame<double> f(na);
    const double t = ref::kTurn * uniform(rng);
    const V3d p = ca + ra * (std::cos(t) * f.u + std::sin(t) * f.v);
    const V3d tangent = -std::sin(t) * f.u + std::cos(t) * f.v, radial = (p - ca).normalized();
    const double offset = k % 2 == 0 ? 0.0 : std::pow(10.0, -12 * uniform(rng));
    V3d cb, nb;
    if (k % 3 == 0) {  // B's plane turned about the common tangent
      const double phi = ref::kTurn * uniform(rng);
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
    const int degree = 2 + k % 6;
    const double bend = (uniform(rng) - 0.3) * 0.5, lift = k % 4 < 2 ? 0.0 : 10 * offset;
    BezierCurve3<double> c;
    c.control.resize(3, degree + 1);
    for (int j = 0; j <= degree; ++j) {
      const double s = -1 + 2.0 * j / degree;
      c.control.col(j) = p + s * tangent + bend * s * s * radial + lift * na;
    }
    out.push_back({a, b, da, db, c});
  }
  return out;
}

// Every query for float and long double: the same shapes in Real and in double (the references).
template <class Real> struct PrecisionScene {
  using V = Vec3<Real>;
  Circle3<Real> a{V(Real(0.1), Real(0.2), Real(1.9)), V(Real(1), Real(-2), Real(0.5)), Real(1.3)};
  Circle3<Real> b{V(Real(0.7), Real(-0.4), Real(0.2)), V(Real(0.3), Real(1), Real(2)), Real(0.9)};
  Disk3<Real> da{a.center, a.normal, a.radius}, db{b.center, b.normal, b.radius};
  BezierCurve3<Real> c;
  Circle3<double> ad{a.center.template cast<double>(), a.normal.template cast<double>(), double(a.radius)};
  Circle3<double> bd{b.center.template cast<double>(), b.normal.template cast<double>(), double(b.radius)};
  Disk3<double> dad{ad.center, ad.normal, ad.radius}, dbd{bd.center, bd.normal, bd.radius};
  BezierCurve3<double> cd;

  PrecisionScene() {
    c.control.resize(3, 6);
    const double wave[6][3] = {{-1.6, -0.2, 0.4}, {-1.0, 1.4, -0.3}, {-0.3, -1.5, 0.9},
                               {0.4, 1.6, -0.6},  {1.0, -1.2, 0.7},  {1.7, 0.3, 0.2}};
    for (int i = 0; i < 6; ++i) c.control.col(i) = V(Real(wave[i][0]), Real(wave[i][1]), Real(wave[i][2]));
    cd.control = c.control.template cast<double>();
  }
};

// The two rows of one pair (x, y) of a PrecisionScene: its distance in one order and its closest
// points' distance in the other, each against the double reference ref(xd, yd).
template <class X, class Y, class XD, class YD, class Ref>
std::vector<std::array<double, 2>> precision_rows(const X& x, const Y& y, const XD& xd, const YD& yd, const Ref& ref) {
  const double truth = double(ref(xd, yd));
  return {{double(distance(x, y)), truth}, {double(closest_points(y, x).distance), truth}};
}

// The answers in float and long double agree with the double references: `rows(scene)` gives
// each query's (answer, reference) pair on a PrecisionScene, agreeing within 1e-5 in float and
// 1e-15 in long double (relative above 1).
template <class Rows> void other_precisions(const Rows& rows) {
  const auto expect = [](const char* name, double tol, const std::vector<std::array<double, 2>>& values) {
    for (const auto& v : values) {
      const bool ok = std::abs(v[0] - v[1]) <= tol * std::max(1.0, v[1]);
      if (!ok) std::printf("  %s: %.17g vs %.17g\n", name, v[0], v[1]);
      check::record(ok, name, __FILE__, __LINE__);
    }
  };
  expect("float", 1e-5, rows(PrecisionScene<float>()));
  expect("long double", 1e-15, rows(PrecisionScene<long double>()));
}

// One family's checks on the shared cases: `random` and `tangent` check a random and a tangent
// RoundCase, `rows` gives the float and long double rows (other_precisions).
template <class Random, class Tangent, class Rows>
void shared_round_cases(const Random& random, const Tangent& tangent, const Rows& rows) {
  for (const RoundCase& r : random_round_cases()) random(r);
  for (const RoundCase& r : tangent_round_cases()) tangent(r);
  other_precisions(rows);
}

// The largest relative error per kind, then the "N passed, N failed" line and the exit code.
inline int finish_round(const char* name) {
  for (const auto& w : worst) std::printf("largest relative error, %s: %.3g\n", w.first.c_str(), w.second);
  return check::finish(name);
}
