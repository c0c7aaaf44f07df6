// Bezier curves against Bezier curves (bezier_bezier.hpp): cases against 50-digit references
// computed without library code by cpp/tests/bezier_bezier_reference.py (mpmath: the edges by
// one-parameter minimisation, the interior by 50-digit Newton descents from a dense grid), in
// double and long double, every root policy, both argument orders; closest points on their
// curves and apart by the distance; the continua's `unique`; degenerate curves against the point
// and segment queries; swept curves and the effects.
#include <circledist/circledist.hpp>

#include "check.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace test_bezier_bezier {

using namespace circledist;

namespace {

using Points = std::vector<std::array<double, 3>>;

template <class Real> BezierCurve3<Real> curve(const Points& points) {
  BezierCurve3<Real> b;
  b.control.resize(3, Eigen::Index(points.size()));
  for (size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) b.control(k, Eigen::Index(i)) = Real(points[i][k]);
  return b;
}
template <class Real> Vec3<Real> v(double x, double y, double z) { return Vec3<Real>(Real(x), Real(y), Real(z)); }

Points shifted(const Points& p, double x, double y, double z) {
  Points out = p;
  for (auto& q : out) q = {q[0] + x, q[1] + y, q[2] + z};
  return out;
}
Points scaled_by(const Points& p, double f) {
  Points out = p;
  for (auto& q : out) q = {q[0] * f, q[1] * f, q[2] * f};
  return out;
}

// The cases of bezier_bezier_reference.py, in its order.
const Points kArch = {{-1, 0, 0}, {0, 2, 0}, {1, 0, 0}};
const Points kCross = {{0, 1, -1}, {0.5, 1, -0.3}, {-0.5, 1, 0.3}, {0, 1, 1}};
const Points kNear = {{0, 1 + 1e-9, -1}, {0.5, 1 + 1e-9, -0.3}, {-0.5, 1 + 1e-9, 0.3}, {0, 1 + 1e-9, 1}};
const Points kCubicA = {{0, 0, 0}, {1, 2, 0.5}, {2, -1, -0.3}, {3, 1.5, 0.2}};
const Points kCubicB = {{0.5, 1, 1.5}, {1.5, -1, 1}, {2.5, 2, 0.7}, {3.5, 0, 1.2}};
const Points kQuadA = {{-1, 0.5, 0}, {0.2, 2, -1}, {1.3, -0.4, 0.6}};
const Points kQuadB = {{0.8, 1.9, 0.7}, {-0.6, 0.1, 1.4}, {0.4, -1.2, -0.2}};
const Points kWavy = {{0, 0, 0},    {1, 2, 0.5}, {2, -1, -0.3}, {3, 1.5, 0.2},
                      {4, -0.5, 0}, {5, 1, 1},   {6, 0, -0.5},  {7, 1, 0}};
// Random curves whose closest pair a flat leaf's descent once missed (bezier_bezier_reference.py).
const Points kMissedA = {{0.39474543867705547, -0.42444917948091332, -1.6536656591517627},
                         {-1.699138253536101, -1.8319160918726984, 1.8737655599474268},
                         {1.7442957767367999, -0.18004921106059824, 0.25100164667863378},
                         {0.60531914564781664, -1.7493154679953511, 1.2578684001083298},
                         {1.0573342279069462, -0.68592973953708514, -0.34871979198153435},
                         {-1.4751657306234964, -0.022886383733474069, 1.1186187475530667}};
const Points kMissedB = {{0.68918367564520988, -2.2712453641131716, 0.96806154723334348},
                         {0.30006825230758982, -2.5191148849726726, 2.8222541915342454},
                         {1.4425582671788817, -1.2817819741205687, 0.061747844195398249},
                         {1.422717757521708, -1.6565285174645219, 2.9875888490803115},
                         {2.9167547053385672, -0.72137933800183607, 2.1295530247378522},
                         {1.4743330217926154, -0.98911081694770397, -0.073385985641913454},
                         {-0.23237114587419772, -1.0586974773428661, 0.93982196594780054}};
const Points kMissedC = {{1.6300852267430948, -1.4823250784567454, -1.8807650229301882},
                         {1.7363520518527644, 0.78817408841162706, 1.537807655714913},
                         {1.8945695311145339, 0.94460108639216323, 0.1064757827064966},
                         {-1.5687514993468357, 0.62750025866420245, -0.89576192908983665},
                         {0.70534797193760435, 0.3043629664354297, -0.68483248304606659},
                         {-0.052015692483024178, 0.72748659351915812, -0.94927295231932707},
                         {1.5287995969196122, -1.4566640288644939, 1.6588311243601774}};
const Points kMissedD = {{-1.8578544124498564, 0.58430243026410555, -0.42884786932778324},
                         {-1.5478785121413405, 1.7804948888882837, 0.9537805819310049},
                         {1.6572131829106291, 0.95243983624782069, -0.14067249622065162},
                         {1.7073801561252784, -2.0115728707494545, 0.89353975241506933},
                         {-1.8916584276318542, -1.2754406790763819, 0.59911589997176817},
                         {0.21070827799196953, -1.3960938657582826, -0.7238886780354824},
                         {1.6505403039981872, 0.66252563211070736, 0.85291341708662005}};
const Points kSmall = {{1109.5, 698.9, 152.6}, {1110.2, 699.4, 153.1}, {1110.9, 698.95, 152.9}};

struct Case {
  const char* name;
  Points a, b;
  const char* reference;
};

std::vector<Case> cases() {
  return {
      {"cubics", kCubicA, kCubicB, "0.884500270816127347399284"},
      {"quadratics", kQuadA, kQuadB, "1.14475309924805420473579"},
      {"cubic_quadratic", kCubicA, kQuadB, "0.6676835268987501766745908"},
      {"degree7_line", kWavy, {{1, -1, 0.3}, {5, 2, -0.4}}, "0.1424297171471749175328174"},
      {"crossing", kArch, kCross, "0.0"},
      {"nearly_touching", kArch, kNear, "1.000000082740370999090374e-9"},
      {"big_small", scaled_by(kCubicA, 1e3), kSmall, "0.4708260612302045797227504"},
      {"translated", shifted(kCubicA, 1e6, -1e6, 1e6), shifted(kCubicB, 1e6, -1e6, 1e6), "0.8845002708244053631631715"},
      {"missed_basin_1", kMissedA, kMissedB, "0.0000002629715225110312695109746"},
      {"missed_basin_2", kMissedC, kMissedD, "0.02930175555416616937829862"},
  };
}

// The largest distance of a control point from its curve's first one.
double size_of(const Points& p) {
  double s = 0;
  for (const auto& q : p) s = std::max(s, std::hypot(q[0] - p[0][0], q[1] - p[0][1], q[2] - p[0][2]));
  return s;
}
double coordinates_of(const Points& p) {
  double s = 0;
  for (const auto& q : p) s = std::max({s, std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
  return s;
}

// One query in both orders: the distance against the reference (relative to max(reference, the
// larger curve's size)), closest_points' distance equal to distance(), its points on the curves
// and apart by the distance (to rounding of their coordinates), the reversed order the same answer.
template <class Real, class Roots> void check_case(const Case& c, Real bar) {
  const auto a = curve<Real>(c.a), b = curve<Real>(c.b);
  const Real ref = Real(std::stold(c.reference));
  const Real scale = Real(std::max(size_of(c.a), size_of(c.b)));
  const Real points =
      64 * std::numeric_limits<Real>::epsilon() * Real(std::max(coordinates_of(c.a), coordinates_of(c.b)));
  const Real d = distance<Roots>(a, b);
  CHECK(d == distance<Roots>(b, a));
  CHECK(std::abs(d - ref) <= bar * std::max(ref, scale));
  if (!(std::abs(d - ref) <= bar * std::max(ref, scale)))
    std::printf("  %s: %.20Lg against %s (%.3Lg of the bar)\n", c.name, (long double)d, c.reference,
                (long double)(std::abs(d - ref) / (bar * std::max(ref, scale))));
  const Result<Real> r = closest_points<Roots>(a, b);
  CHECK(r.distance == d);
  CHECK(r.param_a.x() >= 0 && r.param_a.x() <= 1 && r.param_b.x() >= 0 && r.param_b.x() <= 1);
  CHECK((r.point_a - a.at(r.param_a.x())).norm() <= bar * scale + points);
  CHECK((r.point_b - b.at(r.param_b.x())).norm() <= bar * scale + points);
  CHECK(std::abs((r.point_a - r.point_b).norm() - d) <= bar * std::max(ref, scale) + points);
  const Result<Real> s = closest_points<Roots>(b, a);
  CHECK(s.distance == d && s.point_a == r.point_b && s.point_b == r.point_a && s.unique == r.unique);
}

template <class Real, class Roots> void run(Real bar) {
  for (const Case& c : cases()) check_case<Real, Roots>(c, bar);
}

void continua_and_degenerate() {
  // Two copies of a segment-like curve shifted sideways: every s pairs with s, a continuum.
  const Points line = {{0, 0, 0}, {1, 0, 0}, {2.5, 0, 0}, {3, 0, 0}};
  const auto straight = curve<double>(line);
  const auto beside = closest_points(straight, curve<double>(shifted(line, 0, 0.5, 0)));
  CHECK(std::abs(beside.distance - 0.5) <= 1e-15 && !beside.unique);
  const auto overlapping = closest_points(straight, curve<double>(shifted(line, 1.25, 0.5, 0)));
  CHECK(std::abs(overlapping.distance - 0.5) <= 1e-15 && !overlapping.unique);
  // Identical curves: distance 0 along the whole curve.
  const auto cubic = curve<double>(kCubicA);
  const auto same = closest_points(cubic, cubic);
  CHECK(same.distance <= 1e-15 && !same.unique);
  // A single crossing is unique; end to end apart is unique.
  const auto crossing = closest_points(curve<double>(kArch), curve<double>(kCross));
  CHECK(crossing.distance <= 1e-15 && crossing.unique);
  CHECK(std::abs(crossing.param_a.x() - 0.5) <= 1e-7 && std::abs(crossing.param_b.x() - 0.5) <= 1e-7);
  const auto ends = closest_points(straight, curve<double>(shifted(line, 4, 0, 0)));
  CHECK(ends.distance == 1 && ends.unique && ends.param_a.x() == 1 && ends.param_b.x() == 0);
  // All control points equal: the point query.
  const auto dot = curve<double>({{1, 0.5, 0.25}, {1, 0.5, 0.25}, {1, 0.5, 0.25}});
  const auto quad = curve<double>(kQuadA);
  CHECK(std::abs(distance(dot, quad) - distance(quad, v<double>(1, 0.5, 0.25))) <= 1e-15);
  CHECK(distance(curve<double>({{1, 0.5, 0.25}}), quad) == distance(quad, v<double>(1, 0.5, 0.25)));
  // Collinear control points: a segment (here traversed once, unevenly), against a segment-like
  // curve and against a curve: the segment queries.
  const Points seg_a = {{-1, 0.2, 0.1}, {-0.2, 0.36, 0.14}, {1, 0.6, 0.2}};
  const Points seg_b = {{0.3, -1, 1}, {0.3, 0, 0.4}, {0.3, 0.5, 0.1}, {0.3, 1, -0.2}};
  const Segment3<double> sa{v<double>(-1, 0.2, 0.1), v<double>(1, 0.6, 0.2)};
  const Segment3<double> sb{v<double>(0.3, -1, 1), v<double>(0.3, 1, -0.2)};
  CHECK(std::abs(distance(curve<double>(seg_a), curve<double>(seg_b)) - distance(sa, sb)) <= 1e-15);
  CHECK(std::abs(distance(curve<double>(seg_a), quad) - distance(quad, sa)) <= 1e-15);
  // Empty curves are infinitely far.
  CHECK(std::isinf(distance(BezierCurve3<double>{}, quad)));
  // Swept: tubes; the effects.
  const auto arch = curve<double>(kArch), cross = curve<double>(kNear);
  CHECK(distance(swept(arch, 0.25), swept(curve<double>(kCubicB), 0.25)) ==
        std::max(0.0, distance(arch, curve<double>(kCubicB)) - 0.5));
  CHECK(intersects(arch, curve<double>(kCross)));
  CHECK(!intersects(arch, cross));
  CHECK(within(arch, cross, 2e-9) && !within(arch, cross, 5e-10));
  // float runs in double.
  CHECK(std::abs(distance(curve<float>(kCubicA), curve<float>(kCubicB)) - 0.8845003f) <= 1e-6f);
}

}  // namespace

int main() {
  run<double, Bracketing>(1e-12);
  run<double, EigenCompanion>(1e-12);
  run<double, EigenPolished>(1e-12);
  run<double, EigenPolynomialSolver>(1e-12);
  run<long double, Bracketing>(1e-15L);
  run<long double, EigenCompanion>(1e-15L);
  continua_and_degenerate();
  return check::finish("test_bezier_bezier");
}

}  // namespace test_bezier_bezier

CHECK_SUITE(test_bezier_bezier);
