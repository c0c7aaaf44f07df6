// Point against circle (point_circle.hpp): the closed form on a case whose answer is known, in
// float, double and long double.
#include <circledist/circledist.hpp>

#include "check.hpp"

#include <cmath>
#include <limits>

namespace test_point_circle {

using namespace circledist;

template <class Real> void analytic_cases() {
  using V = Vec3<Real>;
  const Real bar = check::closed_form_bar<Real>();
  const Circle3<Real> ring{V(0, 0, 0), V(0, 0, 3), Real(1)};
  const V p(0, 3, 4);
  const Real point_circle = std::sqrt(Real(4) + Real(16));
  CHECK_NEAR(distance(p, ring), point_circle, bar * 5);
  CHECK_NEAR(distance(ring, p), point_circle, bar * 5);
}

int main() {
  analytic_cases<float>();
  analytic_cases<double>();
  analytic_cases<long double>();
  return check::finish("point_circle");
}

}  // namespace test_point_circle

CHECK_SUITE(test_point_circle);
