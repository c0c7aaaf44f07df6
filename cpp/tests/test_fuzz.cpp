// A bounded C++ fuzz driver: random and extreme inputs for every pair of shapes, in
// both orders, through distance() and closest_points() of every root policy. Built and run with
// the other tests, and under AddressSanitizer and UndefinedBehaviorSanitizer by
// `bash tools/run.sh test`: a buffer overrun or undefined behavior stops it there. Asserted here:
// no NaN for valid inputs, distances >= 0, distance() == closest_points().distance, finite closest
// points for a finite distance.
#include <circledist/circledist.hpp>
#include <circledist/linear_linear.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "check.hpp"

namespace test_fuzz {

using namespace circledist;

namespace {

using Real = double;
using V = Vec3<Real>;
std::mt19937_64 rng(15);

Real uniform(Real lo, Real hi) { return std::uniform_real_distribution<Real>(lo, hi)(rng); }
Real normal() { return std::normal_distribution<Real>()(rng); }

// A length scale: mostly moderate, often extreme (1e-300 .. 1e300).
Real magnitude() {
  const Real r = uniform(0, 1);
  if (r < 0.5) return std::pow(Real(10), uniform(-2, 2));
  return std::pow(Real(10), uniform(-300, 300));
}

V vector(Real scale) {
  V v(normal(), normal(), normal());
  if (uniform(0, 1) < 0.15) v[std::uniform_int_distribution<int>(0, 2)(rng)] = 0;
  return v * scale;
}

V direction() {
  V v = vector(magnitude());
  if (v.isZero()) v.z() = 1;
  return v;
}

struct Scene {
  Real scale;
  V center;
  V near() { return center + vector(scale); }
};

V make_point(Scene& s) { return s.near(); }
Line3<Real> make_line(Scene& s) { return {s.near(), direction()}; }
Ray3<Real> make_ray(Scene& s) { return {s.near(), direction()}; }
Segment3<Real> make_segment(Scene& s) {
  const V p0 = s.near();
  return {p0, uniform(0, 1) < 0.1 ? p0 : s.near()};
}
Circle3<Real> make_circle(Scene& s) {
  return {s.near(), direction(), uniform(0, 1) < 0.05 ? 0 : s.scale * uniform(0.1, 3)};
}
Disk3<Real> make_disk(Scene& s) {
  return {s.near(), direction(), uniform(0, 1) < 0.05 ? 0 : s.scale * uniform(0.1, 3)};
}
BezierCurve3<Real> make_bezier(Scene& s) {
  BezierCurve3<Real> b;
  const int count = std::uniform_int_distribution<int>(2, kMaxBezierDegree + 1)(rng);
  b.control.resize(3, count);
  for (int i = 0; i < count; ++i) b.control.col(i) = s.near();
  // One dominant control point: it once overflowed the stack.
  if (uniform(0, 1) < 0.3) b.control.col(count / 2) = vector(s.scale * std::pow(Real(10), uniform(2, 200)));
  return b;
}

int nan_answers = 0;

// `scale`: the scene's length scale (the shapes' sizes are within a factor 10 of it); the two
// entry points agree within the accuracy bar, 1e-12 x max(distance, scale).
template <class Roots, class A, class B> void check_pair(const A& a, const B& b, Real scale) {
  const Real d = distance<Roots>(a, b);
  const Result<Real> r = closest_points<Roots>(a, b);
  const bool agree = d == r.distance || std::abs(d - r.distance) <= 1e-12 * std::max({d, r.distance, scale});
  const bool fine = d == d && d >= 0 && r.distance == r.distance && agree &&
                    (!std::isfinite(d) || (r.point_a.allFinite() && r.point_b.allFinite()));
  if (!fine && nan_answers++ < 5) std::printf("  bad answer: distance %g, closest %g\n", d, r.distance);
  CHECK(fine);
}

template <class A, class B, class MakeA, class MakeB>
void fuzz_pair(const char* name, MakeA make_a, MakeB make_b, int n) {
  const int before = nan_answers;
  for (int i = 0; i < n; ++i) {
    Scene s{magnitude(), V::Zero()};
    s.center = vector(s.scale * (uniform(0, 1) < 0.2 ? std::pow(Real(10), uniform(0, 8)) : Real(1)));
    const A a = make_a(s);
    const B b = make_b(s);
    check_pair<Bracketing>(a, b, s.scale);
    check_pair<EigenCompanion>(a, b, s.scale);
    check_pair<EigenPolished>(a, b, s.scale);
    check_pair<Bracketing>(b, a, s.scale);
  }
  if (nan_answers > before) std::printf("%s: %d bad answers\n", name, nan_answers - before);
}

}  // namespace

int main() {
  const int n = 300;
  fuzz_pair<V, Circle3<Real>>("point-circle", make_point, make_circle, n);
  fuzz_pair<V, Disk3<Real>>("point-disk", make_point, make_disk, n);
  fuzz_pair<Line3<Real>, Circle3<Real>>("line-circle", make_line, make_circle, n);
  fuzz_pair<Ray3<Real>, Circle3<Real>>("ray-circle", make_ray, make_circle, n);
  fuzz_pair<Segment3<Real>, Circle3<Real>>("segment-circle", make_segment, make_circle, n);
  fuzz_pair<Line3<Real>, Disk3<Real>>("line-disk", make_line, make_disk, n);
  fuzz_pair<Ray3<Real>, Disk3<Real>>("ray-disk", make_ray, make_disk, n);
  fuzz_pair<Segment3<Real>, Disk3<Real>>("segment-disk", make_segment, make_disk, n);
  fuzz_pair<Circle3<Real>, Circle3<Real>>("circle-circle", make_circle, make_circle, n);
  fuzz_pair<Circle3<Real>, Disk3<Real>>("circle-disk", make_circle, make_disk, n);
  fuzz_pair<Disk3<Real>, Disk3<Real>>("disk-disk", make_disk, make_disk, n);
  fuzz_pair<BezierCurve3<Real>, Circle3<Real>>("bezier-circle", make_bezier, make_circle, n / 3);
  fuzz_pair<BezierCurve3<Real>, Disk3<Real>>("bezier-disk", make_bezier, make_disk, n / 3);
  fuzz_pair<Line3<Real>, Line3<Real>>("line-line", make_line, make_line, n);
  fuzz_pair<Segment3<Real>, Ray3<Real>>("segment-ray", make_segment, make_ray, n);
  fuzz_pair<V, Segment3<Real>>("point-segment", make_point, make_segment, n);
  return check::finish("fuzz");
}

}  // namespace test_fuzz

CHECK_SUITE(test_fuzz);
