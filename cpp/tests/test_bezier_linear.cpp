// Bezier curves against points, lines, rays and segments (bezier_point.hpp, bezier_linear.hpp):
// a few cases against 50-digit references computed without library code by
// cpp/tests/bezier_linear_reference.py (mpmath: the minimum over t of the closed-form distance),
// in double and long double, every root policy, both argument orders; plus closest points on
// their shapes, the far control point's pieces, and the degenerate cases' `unique`.
#include <circledist/circledist.hpp>

#include "check.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace test_bezier_linear {

using namespace circledist;

namespace {

template <class Real> BezierCurve3<Real> curve(const std::vector<std::array<double, 3>>& points) {
  BezierCurve3<Real> b;
  b.control.resize(3, Eigen::Index(points.size()));
  for (size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) b.control(k, Eigen::Index(i)) = Real(points[i][k]);
  return b;
}
template <class Real> Vec3<Real> v(double x, double y, double z) { return Vec3<Real>(Real(x), Real(y), Real(z)); }

const std::vector<std::array<double, 3>> kCubic = {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}};
const std::vector<std::array<double, 3>> kWavy = {{0, 0, 0}, {1, 2, 0.5}, {2, -1, -0.3}, {3, 1.5, 0.2}, {4, -0.5, 0}};
const std::vector<std::array<double, 3>> kFar = {{0, 0, 0}, {1e10, 0, 0}, {1, 1, 1}};
const std::vector<std::array<double, 3>> kStraight = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}};

// One query in both orders and every policy: the distance against the reference (relative to
// max(reference, scale)), closest_points' distance equal to distance(), its points on the shapes.
template <class Real, class Roots, class Other>
void check_case(const BezierCurve3<Real>& b, const Other& other, const char* reference, Real scale, Real bar) {
  const Real ref = Real(std::stold(reference));
  const Real d = distance<Roots>(b, other);
  CHECK(d == distance<Roots>(other, b));
  CHECK(std::abs(d - ref) <= bar * std::max(ref, scale));
  const Result<Real> r = closest_points<Roots>(b, other);
  CHECK(r.distance == d);
  CHECK(r.param_a.x() >= 0 && r.param_a.x() <= 1);
  CHECK((r.point_a - b.at(r.param_a.x())).norm() <= 8 * bar * scale);
  CHECK(std::abs((r.point_a - r.point_b).norm() - d) <= 8 * bar * scale);
  const Result<Real> s = closest_points<Roots>(other, b);
  CHECK(s.distance == d && s.point_a == r.point_b && s.point_b == r.point_a);
}

template <class Real, class Roots> void run(Real bar) {
  const auto cubic = curve<Real>(kCubic), wavy = curve<Real>(kWavy), far = curve<Real>(kFar);
  check_case<Real, Roots>(cubic, v<Real>(1.5, 0.3, 0.2), "0.4924428900898052507416995", Real(3), bar);
  check_case<Real, Roots>(wavy, v<Real>(2.5, 0.5, -1.0), "1.044400223699797152268785", Real(4.5), bar);
  // The far curve: held to the size of the curve near the answer (1), not to its extent 1e10.
  check_case<Real, Roots>(far, v<Real>(1, 0, 0), "3.5355339062862910126309e-21", Real(1), bar);
  check_case<Real, Roots>(wavy, Line3<Real>{v<Real>(1, 2, 0.5), v<Real>(0.3, -1, 0.7)}, "1.044050429113551784508112",
                          Real(4.5), bar);
  check_case<Real, Roots>(cubic, Line3<Real>{v<Real>(0, 2, 1), v<Real>(1, 0.1, 0.3)}, "1.866909963746739164216916",
                          Real(3), bar);
  check_case<Real, Roots>(cubic, Ray3<Real>{v<Real>(1.5, 2, 0.5), v<Real>(0, -1, -0.5)}, "0.1118033988749894848204587",
                          Real(3), bar);
  check_case<Real, Roots>(wavy, Ray3<Real>{v<Real>(5, 0, 0), v<Real>(1, 1, 0)}, "1.118033988749894848204587", Real(4.5),
                          bar);
  check_case<Real, Roots>(cubic, Segment3<Real>{v<Real>(-1, -1, 0.5), v<Real>(-1, 1, 0.5)},
                          "1.118033988749894848204587", Real(3), bar);
  check_case<Real, Roots>(wavy, Segment3<Real>{v<Real>(2, 0, -1), v<Real>(2.5, 1, 1)}, "0.08321529186510036966692278",
                          Real(4.5), bar);
}

void degenerate() {
  const auto straight = curve<double>(kStraight);
  // Along the line, overlapping a segment, a ray: a continuum of closest pairs.
  const auto line = closest_points(straight, Line3<double>{v<double>(7, 0, 0), v<double>(-2, 0, 0)});
  CHECK(line.distance == 0 && !line.unique);
  const auto segment = closest_points(straight, Segment3<double>{v<double>(1, 0, 0), v<double>(5, 0, 0)});
  CHECK(segment.distance == 0 && !segment.unique);
  const auto apart = closest_points(straight, Segment3<double>{v<double>(4, 0, 0), v<double>(5, 0, 0)});
  CHECK(apart.distance == 1 && apart.unique && apart.param_a.x() == 1 && apart.param_b.x() == 0);
  // All control points equal; a single control point; an empty curve.
  const auto dot = curve<double>({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}});
  CHECK(std::abs(distance(dot, v<double>(1, 2, 4)) - 1) <= 1e-15);
  CHECK(std::abs(distance(curve<double>({{1, 2, 3}}), v<double>(1, 2, 4)) - 1) <= 1e-15);
  CHECK(std::isinf(distance(BezierCurve3<double>{}, v<double>(0, 0, 0))));
  // Tied end points of a symmetric arch.
  const auto arch = curve<double>({{-1, 0, 0}, {0, 2, 0}, {1, 0, 0}});
  const auto tied = closest_points(arch, v<double>(0, -1, 0));
  CHECK(std::abs(tied.distance - std::sqrt(2.0)) <= 1e-15 && !tied.unique);
  // A degenerate segment is its point.
  CHECK(distance(arch, Segment3<double>{v<double>(0, 3, 0), v<double>(0, 3, 0)}) == distance(arch, v<double>(0, 3, 0)));
  // Swept: the tube against a capsule.
  CHECK(std::abs(distance(swept(arch, 0.25), swept(Segment3<double>{v<double>(-1, 2, 0), v<double>(1, 2, 0)}, 0.25)) -
                 0.5) <= 1e-15);
  CHECK(intersects(arch, Line3<double>{v<double>(0, 1, 0), v<double>(1, 0, 0)}));
  CHECK(!within(arch, Ray3<double>{v<double>(0, 1.5, 0), v<double>(0, 1, 0)}, 0.49));
}

}  // namespace

int main() {
  run<double, Bracketing>(1e-12);
  run<double, EigenCompanion>(1e-12);
  run<double, EigenPolished>(1e-12);
  run<double, EigenPolynomialSolver>(1e-12);
  run<long double, Bracketing>(1e-15L);
  run<long double, EigenCompanion>(1e-15L);
  degenerate();
  return check::finish("test_bezier_linear");
}

}  // namespace test_bezier_linear

CHECK_SUITE(test_bezier_linear);
