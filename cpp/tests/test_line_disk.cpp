// Line, ray and segment against disks (line_disk.hpp), on cases whose answer is known in closed
// form (the interior, piercing, the plane, the rim), in float, double and long double.
#include <circledist/circledist.hpp>

#include "check.hpp"

#include <cmath>
#include <limits>

namespace test_line_disk {

using namespace circledist;

template <class Real> void analytic_cases() {
  using V = Vec3<Real>;
  const Real bar = check::closed_form_bar<Real>();
  const Disk3<Real> disk{V(0, 0, 0), V(0, 0, 3), Real(1)};

  // Disk: parallel above the interior (continuum), piercing (0, unique), in the plane.
  const Result<Real> above = closest_points(Line3<Real>{V(0, Real(0.5), 2), V(1, 0, 0)}, disk);
  CHECK_NEAR(above.distance, Real(2), bar * 2);
  CHECK(!above.unique);
  const Result<Real> pierce = closest_points(Segment3<Real>{V(Real(0.5), 0, -1), V(Real(0.5), 0, 1)}, disk);
  CHECK_NEAR(pierce.distance, Real(0), bar);
  CHECK(pierce.unique);
  CHECK_NEAR(pierce.point_a.x(), Real(0.5), bar);
  CHECK_NEAR(distance(Segment3<Real>{V(Real(0.2), 0, 0), V(Real(0.3), 0, 0)}, disk), Real(0), bar);
  CHECK_NEAR(distance(Line3<Real>{V(3, 0, 1), V(0, 1, 0)}, disk), std::sqrt(Real(5)), bar * 3);
  // A segment ending exactly on the rim, from above.
  CHECK_NEAR(distance(Segment3<Real>{V(1, 0, 0), V(1, 0, 5)}, disk), Real(0), bar);
  CHECK_NEAR(distance(Segment3<Real>{V(0, 1, 1), V(0, 2, 1)}, disk), Real(1), bar);
  // A ray starting beyond the disk's cylinder and pointing away: its rim crossings lie behind
  // its origin and must not count; the origin is the closest point.
  CHECK_NEAR(distance(Ray3<Real>{V(3, 0, 1), V(1, 0, 0)}, disk), std::sqrt(Real(5)), bar * 3);
}

int main() {
  analytic_cases<float>();
  analytic_cases<double>();
  analytic_cases<long double>();
  return check::finish("line_disk");
}

}  // namespace test_line_disk

CHECK_SUITE(test_line_disk);
