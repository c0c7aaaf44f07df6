// circledist.hpp alone gives the whole library: every query family, swept shapes and the effects
// (this file includes nothing else of it). The answers are known in closed form here.
#include <circledist/circledist.hpp>

#include "check.hpp"

#include <cmath>
#include <limits>

namespace test_umbrella {

int main() {
  using namespace circledist;
  using V = Vec3<double>;
  const Segment3<double> rod{V(-1, 0, 2), V(1, 0, 2)};      // 2 above the plane z = 0
  const Segment3<double> post{V(0, 3, -1), V(0, 3, 1)};     // crosses z = 0 at y = 3
  const Circle3<double> ring{V(0, 0, 0), V(0, 0, 1), 1.0};  // unit ring in z = 0
  const Disk3<double> plate{V(0, 0, -1), V(0, 0, 1), 5.0};  // z = -1, radius 5
  const Vec3<double> above(0, 0, 3);

  const double tol = 4 * std::numeric_limits<double>::epsilon() * 4;
  CHECK_NEAR(distance(rod, post), std::sqrt(10.0), tol);  // (0, 0, 2) to (0, 3, 1)
  CHECK_NEAR(distance(above, ring), std::sqrt(10.0), tol);
  CHECK_NEAR(distance(ring, plate), 1.0, tol);
  CHECK_NEAR(distance(rod, ring), 2.0, tol);  // from either end of the rod to the ring below it
  const auto capsule = swept(rod, 0.5);
  CHECK_NEAR(distance(capsule, ring), 1.5, tol);
  reset_stats();
  CHECK(within(capsule, plate, 2.5));
  CHECK(!within(capsule, plate, 2.4));
  CHECK(!intersects(rod, ring));
  CHECK(distance_if_within(rod, plate, 2.0) == std::numeric_limits<double>::infinity());  // 3 > 2
  CHECK_NEAR(distance_if_within(rod, plate, 3.5), 3.0, tol);
  CHECK(stats().within == 5);
  const auto r = closest_points(rod, ring);
  CHECK(!r.unique);  // both ends of the rod are 2 from the ring
  return check::finish("test_umbrella");
}

}  // namespace test_umbrella

CHECK_SUITE(test_umbrella);
