// Built with link-time optimization (cpp/tests/CMakeLists.txt): under GCC 12 with -flto (even at
// -O1), the header functions that changed an aggregate parameter passed by value (CurvePoly's
// scaling, without_far_roots, on_span) went wrong (-fno-ipa-modref hid it: the compiler's
// interprocedural mod/ref analysis; ASan, UBSan and valgrind are clean without LTO), and the eigenvalue
// policies answered this Bezier curve against a circle (a case of the differential test's
// concentric family) with 1.4925 where the distance is 0.62892639486222542 (50-digit reference,
// circledist_cases/reference_round.py bezier_circle). -fno-ipa-modref, -fno-inline or the
// sanitizers hid it. The headers now take such aggregates by const reference and copy them.
#include <circledist/circledist.hpp>

#include <cmath>
#include <cstdio>

#include "check.hpp"

namespace lto_aggregates {

int main() {
  using circledist::Vec3;
  const double control[8][3] = {{-2.0892587450569873, 2.407541006404772, 1.6559357922531128},
                                {-0.7682818082689475, 3.201689679637363, 2.843953743712082},
                                {-2.7971639421593295, 0.06532446873506648, 3.154375450024067},
                                {-2.468835853700635, 1.3175213782935564, 1.1268604308324832},
                                {0.46883585370063474, 0.18247862170644358, 1.3731395691675168},
                                {0.7971639421593293, 1.4346755312649335, -0.6543754500240666},
                                {-1.2317181917310525, -1.7016896796373628, -0.3439537437120823},
                                {0.08925874505698728, -0.907541006404772, 0.8440642077468873}};
  circledist::BezierCurve3<double> curve;
  curve.control.resize(3, 8);
  for (int i = 0; i < 8; ++i) curve.control.col(i) = Vec3<double>(control[i][0], control[i][1], control[i][2]);
  const circledist::Circle3<double> circle{Vec3<double>(-1.0, 0.75, 1.25), Vec3<double>(0, 4, 0), 1.5};
  const double truth = 0.62892639486222542, bar = 1e-12 * std::max(truth, 1.5);
  const double companion = circledist::distance<circledist::EigenCompanion>(curve, circle);
  const double eigen = circledist::distance<circledist::EigenPolynomialSolver>(curve, circle);
  const double bracketing = circledist::distance<circledist::Bracketing>(curve, circle);
  std::printf("EigenCompanion %.17g, EigenPolynomialSolver %.17g, Bracketing %.17g (truth %.17g)\n", companion, eigen,
              bracketing, truth);
  CHECK(std::abs(companion - truth) <= bar);
  CHECK(std::abs(eigen - truth) <= bar);
  CHECK(std::abs(bracketing - truth) <= bar);
  return check::finish("lto_aggregates");
}

}  // namespace lto_aggregates

CHECK_SUITE(lto_aggregates);
