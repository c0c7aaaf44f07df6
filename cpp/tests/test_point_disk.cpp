// Point against disk (point_disk.hpp): the closed form over the interior and beside the rim, in
// float, double and long double.
#include <circledist/circledist.hpp>

#include "check.hpp"

#include <cmath>
#include <limits>

namespace test_point_disk {

using namespace circledist;

template <class Real> void analytic_cases() {
  using V = Vec3<Real>;
  const Real bar = check::closed_form_bar<Real>();
  const Disk3<Real> disk{V(0, 0, 0), V(0, 0, 3), Real(1)};
  CHECK_NEAR(distance(V(Real(0.5), 0, -2), disk), Real(2), bar * 2);
  CHECK_NEAR(distance(V(3, 0, -2), disk), std::sqrt(Real(8)), bar * 3);
}

int main() {
  analytic_cases<float>();
  analytic_cases<double>();
  analytic_cases<long double>();
  return check::finish("point_disk");
}

}  // namespace test_point_disk

CHECK_SUITE(test_point_disk);
