// Bezier curves through or near the center of a circle or disk, every root policy, against an
// independent long double reference. No library code is used for the reference: the
// curve is evaluated by de Casteljau in long double relative to the round's center, the distance
// of a point to the circle or disk is the elementary projection on the round's plane, and the
// minimum over t in [0, 1] is found by dense sampling (10^5 samples for the fixed cases, 2 10^4
// for the random ones), each of the 12 lowest sampled local minima refined by golden section.
// Tolerance in double: |error| <= 1e-12 * max(true distance, largest size).
//
// The class: a curve nearly point-symmetric about the round's center with even degree (the
// differential test's concentric family, whose even powers in w = 2t - 1 are the float32
// rounding of its control points) gives a stationary polynomial of degree 6n - 2 whose leading
// coefficient is 1e-9 of the others, so one root near 1e7; Eigen's QR on the balanced companion
// matrix then lost the roots in [-1, 1], and EigenCompanion answered 0.1713 for 0.1601 (the
// finding below). The other fixed cases were found by a search of 4 10^4 such curves, where the
// eigenvalue policies answered as far off as 1.14 for 0.786, or, between two nearly tied
// mirror-image minima, the higher one. The random cases cover degrees 1 to 7: exactly and
// nearly symmetric curves, the middle control point at the center, curves through and near the
// center, lower-degree curves raised in degree through the center; half of them lifted along the
// axis (so that the disk distance is not 0), tilted normals, float32 inputs.
#include <circledist/circledist.hpp>

#include "check.hpp"
#include "random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace test_bezier_center {

using namespace circledist;
using LD = long double;
using V3 = Eigen::Matrix<LD, 3, 1>;
using V3d = Vec3<double>;

namespace {

// ---- the independent reference ------------------------------------------------------------

struct Reference {
  std::array<V3, kMaxBezierDegree + 1> q;  // control points minus the round's center
  int n;                                   // the degree
  V3 normal;                               // unit
  LD radius;
  bool disk;

  Reference(const BezierCurve3<double>& b, const V3d& center, const V3d& axis, double r, bool is_disk)
      : n(int(b.control.cols()) - 1), normal(axis.cast<LD>() / axis.cast<LD>().norm()), radius(r), disk(is_disk) {
    for (int i = 0; i <= n; ++i) q[i] = b.control.col(i).cast<LD>() - center.cast<LD>();
  }

  LD distance(LD t) const {
    std::array<V3, kMaxBezierDegree + 1> p = q;
    for (int k = n; k > 0; --k)
      for (int i = 0; i < k; ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
    const LD height = p[0].dot(normal);
    const LD rho = (p[0] - height * normal).norm();
    if (disk && rho <= radius) return std::abs(height);
    return std::sqrt(height * height + (rho - radius) * (rho - radius));
  }

  LD minimum(int samples) const {
    std::vector<LD> value(samples + 1);
    for (int i = 0; i <= samples; ++i) value[i] = distance(LD(i) / samples);
    std::vector<std::pair<LD, int>> minima;
    for (int i = 0; i <= samples; ++i)
      if ((i == 0 || value[i] <= value[i - 1]) && (i == samples || value[i] <= value[i + 1]))
        minima.push_back({value[i], i});
    std::sort(minima.begin(), minima.end());
    if (minima.size() > 12) minima.resize(12);
    const LD golden = (std::sqrt(5.0L) - 1) / 2;
    LD best = std::numeric_limits<LD>::infinity();
    for (const auto& m : minima) {
      LD a = std::max(LD(0), LD(m.second - 1) / samples), b = std::min(LD(1), LD(m.second + 1) / samples);
      LD x1 = b - golden * (b - a), x2 = a + golden * (b - a), f1 = distance(x1), f2 = distance(x2);
      for (int iteration = 0; iteration < 120 && b - a > 1e-21L; ++iteration) {
        if (f1 <= f2) {
          b = x2, x2 = x1, f2 = f1, x1 = b - golden * (b - a), f1 = distance(x1);
        } else {
          a = x1, x1 = x2, f1 = f2, x2 = a + golden * (b - a), f2 = distance(x2);
        }
      }
      best = std::min({best, m.first, f1, f2, distance(a), distance(b)});
    }
    return best;
  }
};

// ---- the cases ------------------------------------------------------------------------------

struct Scene {
  std::string name;
  BezierCurve3<double> curve;
  V3d center, normal;
  double radius;
};

double largest_size(const Scene& s) {
  double size = s.radius;
  for (int i = 0; i < s.curve.control.cols(); ++i) size = std::max(size, (s.curve.control.col(i) - s.center).norm());
  return size;
}

const char* const kPolicies[4] = {"Bracketing", "EigenCompanion", "EigenPolynomialSolver", "EigenPolished"};
std::array<double, 4> worst{};
std::array<int, 4> failures{};

template <class Policy, class Round> double policy_distance(const Scene& s) {
  const Round round{s.center, s.normal, s.radius};
  return distance<Policy>(s.curve, round);
}

template <class Round> void check_scene(const Scene& s, int samples) {
  const bool disk = std::is_same_v<Round, Disk3<double>>;
  const LD truth = Reference(s.curve, s.center, s.normal, s.radius, disk).minimum(samples);
  const double scale = std::max(double(truth), largest_size(s));
  const double got[4] = {policy_distance<Bracketing, Round>(s), policy_distance<EigenCompanion, Round>(s),
                         policy_distance<EigenPolynomialSolver, Round>(s), policy_distance<EigenPolished, Round>(s)};
  for (int p = 0; p < 4; ++p) {
    const double error = double(std::abs(LD(got[p]) - truth)) / scale;
    worst[p] = std::max(worst[p], error);
    const bool ok = error <= 1e-12;
    if (!ok) {
      ++failures[p];
      std::printf("  %s, %s, %s: got %.17g, true %.17Lg, relative error %.3g\n", s.name.c_str(),
                  disk ? "disk" : "circle", kPolicies[p], got[p], truth, error);
    }
    check::record(ok, s.name.c_str(), __FILE__, __LINE__);
  }
}

BezierCurve3<double> curve_of(const std::vector<V3d>& points) {
  BezierCurve3<double> b;
  b.control.resize(3, int(points.size()));
  for (int i = 0; i < int(points.size()); ++i) b.control.col(i) = points[i];
  return b;
}

// A case once listed among the open findings: degree 6, the middle control point at the center;
// 50-digit reference for the circle 0.1601137907534006.
Scene finding() {
  const std::vector<V3d> points = {{-0.7396453022956848, -0.739128053188324, -1.4231096506118774},
                                   {-0.35104236006736755, 0.1521882861852646, -1.4333250522613525},
                                   {-1.105171799659729, -1.6972906589508057, -1.7876821756362915},
                                   {-1.1054109334945679, -0.7729302644729614, -1.427234172821045},
                                   {-1.1056499481201172, 0.15143021941184998, -1.0667861700057983},
                                   {-1.8597793579101562, -1.698048710823059, -1.4211431741714478},
                                   {-1.4711765050888062, -0.8067324161529541, -1.4313586950302124}};
  return {"open finding", curve_of(points), V3d(-1.1054109334945679, -0.7729302644729614, -1.427234172821045),
          V3d(-0.37762004137039185, -0.29596588015556335, 1.6394959688186646), 0.5424387454986572};
}

void finding_tests() {
  const Scene s = finding();
  check_scene<Circle3<double>>(s, 100000);
  check_scene<Disk3<double>>(s, 100000);
  // The 50-digit reference, and the float32 query (solved in double, the answer rounded).
  const double truth = 0.1601137907534006;
  const Circle3<double> circle{s.center, s.normal, s.radius};
  CHECK(std::abs(distance<EigenCompanion>(s.curve, circle) - truth) <= 1e-12 * s.radius);
  CHECK(std::abs(closest_points<EigenCompanion>(circle, s.curve).distance - truth) <= 1e-12 * s.radius);
  BezierCurve3<float> curve;
  curve.control = s.curve.control.cast<float>();
  const Circle3<float> round{s.center.cast<float>(), s.normal.cast<float>(), float(s.radius)};
  const double bar = 1e-12 * s.radius + 4 * double(std::nextafter(float(truth), 1.0f) - float(truth));
  CHECK(std::abs(double(distance<Bracketing>(curve, round)) - truth) <= bar);
  CHECK(std::abs(double(distance<EigenCompanion>(curve, round)) - truth) <= bar);
  CHECK(std::abs(double(distance<EigenPolynomialSolver>(curve, round)) - truth) <= bar);
  CHECK(std::abs(double(distance<EigenPolished>(curve, round)) - truth) <= bar);
}

// Nearly point-symmetric curves of degree 4 and 6 (asymmetry 1.5e-9 to 6e-7 of their size) on
// which the eigenvalue policies missed the minimum before the fix (case numbers of the search).
struct Hunted {
  int k;
  std::vector<V3d> points;
  V3d center, normal;
  double radius;
};

void hunted_tests() {
  const std::vector<Hunted> hunted = {{5842,
                                       {{1.35576907187656, -3.2880724687556127, 0.968655584068703},
                                        {-1.7979910147925091, -0.18542158067603282, -1.0151850928368822},
                                        {-0.24525855848060207, -3.1790341342668333, 0.11837799412508404},
                                        {0.073031575315220573, 0.036674631706400403, -0.090892944252535537},
                                        {0.39132170794897897, 3.2523833964384181, -0.30016389505167729},
                                        {1.9440541651755581, 0.25877084588113719, 0.83339919976428023},
                                        {-1.2097059256330585, 3.3614217377592621, -1.150441476603673}},
                                       {0.073031574883480013, 0.036674631764033752, -0.090892947118212331},
                                       {-0.98577904358686408, 0.11673844345830985, 0.12087933257550078},
                                       1.3121566205658441},
                                      {16239,
                                       {{-0.11867099982288881, -0.071154173330570891, -0.20789919535171744},
                                        {0.46575704205470986, -0.75016386278677383, 0.67379810774515547},
                                        {0.18739542901521827, 0.033945746946122381, -0.040120488977057792},
                                        {-0.090966196954060885, 0.8180553751854962, -0.75403910820957876},
                                        {0.49346176814103826, 0.13904572035471954, 0.12765818955340136}},
                                       {0.18739539769930191, 0.03394571712360047, -0.040120499307234221},
                                       {0.941956597296432, 0.31900312662446456, -0.10466505631557872},
                                       0.54230494838733667},
                                      {19979,
                                       {{-2.3457314514462126, -3.6532071624846805, 27.259908223607116},
                                        {-1.57445678751883, -2.9934008333606812, 27.293550860755722},
                                        {-3.9975713966565243, -3.9005029797475341, 28.134242680880096},
                                        {-1.6150120914094575, -3.3941025872199901, 27.869726240357284},
                                        {0.76754738420328184, -2.8877023038970817, 27.605209641757043},
                                        {-1.6555672265093409, -3.79480427790552, 28.445901438216207},
                                        {-0.88429246190285815, -3.1349979911718528, 28.479544193590691}},
                                       {-1.6150119726394665, -3.394102589654076, 27.869726211833346},
                                       {-0.055418103082118232, -0.31879048796707088, 0.94620370884524463},
                                       1.3636547918160242},
                                      {22720,
                                       {{-0.74202153898567746, 6.2796877073955999, 0.22660053480569892},
                                        {-0.6210721620554891, 6.1277981143484954, 0.094263213463088857},
                                        {-0.033699271071552239, 6.7745071933171586, 1.1677819712568944},
                                        {-0.56923481757154215, 6.3866792128432373, 0.61097377960956434},
                                        {-1.1047701673468491, 5.9988508370008313, 0.054165382209788837},
                                        {-0.51739736550468662, 6.6455594683890995, 1.1276837090957628},
                                        {-0.39644755396138315, 6.4936703964974969, 0.99534635962055584}},
                                       {-0.56923483312504974, 6.3866789452904174, 0.61097364418874045},
                                       {-0.69021962990177133, -0.7105742370683914, -0.13667887954228711},
                                       0.50578252650195377},
                                      {23843,
                                       {{0.80797887526069578, 3.466352049599116, -1.288525702039808},
                                        {0.43182995543485675, 3.4284417323341896, -0.78500768232302442},
                                        {1.0604111687178031, 3.3290244244212142, -0.84492695147821373},
                                        {0.72766165728534038, 3.4739670912349507, -0.93700758576881504},
                                        {0.39491216230101789, 3.6189097480472667, -1.0290882082732806},
                                        {1.023493361344799, 3.5194924405490253, -1.0890074783013588},
                                        {0.64734445059115842, 3.4815821180761808, -0.58548946923900291}},
                                       {0.7276616644833579, 3.4739670905916196, -0.93700758405337436},
                                       {-0.038056943000888473, 0.15866724423040018, -0.98659838571617264},
                                       0.41244571430495036},
                                      {25486,
                                       {{-4.3345354546784245, 13.27616232794978, -3.3391063966216978},
                                        {-4.5978019942297719, 13.002554075185143, -2.9628653466000561},
                                        {-3.2354475768515361, 13.270838671577984, -4.3458833632989533},
                                        {-4.1877354717466648, 13.127305153786075, -3.7135809555057988},
                                        {-5.1400231603383482, 12.983771507823979, -3.0812784394037762},
                                        {-3.7776688713218225, 13.252056226615238, -4.464296516317015},
                                        {-4.0409353895265792, 12.978447805833497, -4.0880555064030162}},
                                       {-4.1877354404747269, 13.127305103025762, -3.7135809641256232},
                                       {-0.68334792514627296, 0.72955713676127965, -0.02796421640180732},
                                       0.47354798415781013},
                                      {33161,
                                       {{0.87725602870308639, -1.8256286721808432, 0.57095372215082407},
                                        {-0.81431563484780889, -2.1782250016522275, 0.35151508281816879},
                                        {-1.56339105636408, -3.261499103703013, 0.7624113022352611},
                                        {0.19565996920783532, -1.5259000097004207, 0.11864419977395332},
                                        {1.954710981520341, 0.20969908577239882, -0.52512287296796911},
                                        {1.2056355888393981, -0.87357503743838605, -0.11422669129598426},
                                        {-0.48593609570375551, -1.2261713557215375, -0.33366528176965171}},
                                       {0.19565996955343004, -1.5259000185038736, 0.11864420337154022},
                                       {0.65109281924206197, -0.22917760484444946, 0.72357153493568638},
                                       0.96245003231712001},
                                      {34109,
                                       {{3.6300568195651577, -0.22819898627187851, 1.8025446526957054},
                                        {5.4630219968319915, -0.70834032210233344, 3.1890660897500727},
                                        {0.086697147253052442, -1.8314294473439259, 1.82779675204977},
                                        {3.1801838785338896, -1.8104276256163567, 1.8034901457827255},
                                        {6.2736709683960168, -1.7894255819867553, 1.7791844633636711},
                                        {0.89734685548230653, -2.9125145664373031, 0.41791479500782214},
                                        {2.7303113845848572, -3.3926559878297207, 1.8044364804522801}},
                                       {3.180184244886469, -1.8104274629082853, 1.8034907316272093},
                                       {-0.4651095132872588, 0.25988635898842039, -0.84624595778144251},
                                       1.0643256080796828},
                                      {38483,
                                       {{-0.34408872447716043, -4.53511557792394, 1.2252535559673499},
                                        {-1.0935727303911855, -3.7192997698984103, 0.24307179955322167},
                                        {0.76377734694464516, 3.362631339287474, 1.27567932817289},
                                        {1.1121609064313605, -1.7663704956732307, 2.0736649275914973},
                                        {1.4605439220877321, -6.8953724906992289, 2.8716503221467522},
                                        {3.317894209746993, 0.18655864770239416, 3.9042577755198131},
                                        {2.5684102073489083, 1.0023744237817203, 2.9220762172130437}},
                                       {1.1121608066385711, -1.7663705659667264, 2.073664884436166},
                                       {0.92451666924197207, -0.3470004970420682, -0.15766922130297856},
                                       2.1179919542716328},
                                      {38788,
                                       {{0.87693955402025447, 1.6452719303044163, -2.4325950905935243},
                                        {-0.11675140217743596, 1.3026086340774223, -4.6765061331600748},
                                        {-1.2803954724401785, 2.8101094510487519, -3.0980311775102036},
                                        {0.65978053470913967, 0.98750456226961025, -3.0073281757031327},
                                        {2.5999566269691385, -0.83510017800068626, -2.9166251651006796},
                                        {1.4363124964314213, 0.67240057961849842, -1.3381501741796056},
                                        {0.44262148104054555, 0.32973722625708568, -3.5820613659930109}},
                                       {0.65978055705752747, 0.9875046143368108, -3.0073281723404608},
                                       {-0.29097726029701138, 0.43466036555288928, 0.85229255576208918},
                                       0.86499192737618136},
                                      {38836,
                                       {{-0.76690073080907173, -0.5228309182833949, -0.75646608023897932},
                                        {2.2385768601868539, 1.1253334391208565, 0.62674996390208848},
                                        {0.16016534979424629, 0.15608534181983663, -2.6751878081569815},
                                        {0.19728497108304802, 0.13870744420562583, -0.297970155565073},
                                        {0.23440450577763239, 0.12132952862567284, 2.0792477711811927},
                                        {-1.8440070715881869, -0.8479186751959078, -1.2226899773203832},
                                        {1.1614705705257526, 0.80024578924408563, 0.16052603990220016}},
                                       {0.19728487971862316, 0.13870740327697884, -0.29796997426943783},
                                       {-0.45910672604470237, 0.8858624238438132, 0.066848935085601038},
                                       0.83554491818076249}};
  for (const Hunted& h : hunted) {
    const Scene s{"nearly symmetric, search case " + std::to_string(h.k), curve_of(h.points), h.center, h.normal,
                  h.radius};
    check_scene<Circle3<double>>(s, 100000);
    check_scene<Disk3<double>>(s, 100000);
  }
}

// Random curves of degree 1..7 through or near the center.
void random_tests() {
  std::mt19937_64 rng(14);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0, 1);
  const auto vec = [&] { return V3d(normal(rng), normal(rng), normal(rng)); };
  const char* const kinds[7] = {"symmetric",
                                "nearly symmetric (1e-15..1e-3)",
                                "nearly symmetric (3e-10..1e-6)",
                                "middle point at the center",
                                "through the center",
                                "near the center (1e-15..1e-2)",
                                "lower degree elevated, through the center"};
  for (int k = 0; k < 98; ++k) {
    const int n = 1 + k % 7, kind = (k / 7) % 7;
    const bool lifted = (k / 49) % 2 == 1, single = k % 2 == 1;
    Scene s;
    s.radius = std::exp(0.7 * normal(rng));
    s.center = vec() * std::pow(10.0, 2 * uniform(rng) - 1);
    s.normal = k % 5 == 0 ? V3d(0, 0, 1) : V3d(vec().normalized());
    const double size = s.radius * std::exp(0.5 * normal(rng));
    std::vector<V3d> q(n + 1);
    for (V3d& p : q) p = vec() * size;
    const auto symmetric = [](std::vector<V3d>& p) {
      const int m = int(p.size()) - 1;
      for (int i = 0; i <= m / 2; ++i) p[m - i] = -p[i];
      if (m % 2 == 0) p[m / 2].setZero();
    };
    const auto through = [&](std::vector<V3d>& p, double t0) {  // moved so that the point at t0 is the center
      std::vector<V3d> r = p;
      for (int m = int(r.size()) - 1; m > 0; --m)
        for (int i = 0; i < m; ++i) r[i] = (1 - t0) * r[i] + t0 * r[i + 1];
      for (V3d& x : p) x -= r[0];
    };
    if (kind <= 2) symmetric(q);
    if (kind == 1 || kind == 2) {
      const double asymmetry =
          kind == 1 ? std::pow(10.0, -15 + 12 * uniform(rng)) : std::pow(10.0, -9.5 + 3.5 * uniform(rng));
      for (V3d& p : q) p += asymmetry * size * vec();
    }
    if (kind == 3) q[n / 2].setZero();
    if (kind == 4) through(q, uniform(rng));
    if (kind == 5) {
      through(q, uniform(rng));
      const V3d offset = std::pow(10.0, -15 + 13 * uniform(rng)) * s.radius * vec().normalized();
      for (V3d& p : q) p += offset;
    }
    if (kind == 6) {  // degree m < n, raised to n: its power-basis coefficients above m are rounding
      std::vector<V3d> p(std::max(1, n - 1 - int(2 * uniform(rng))) + 1);
      for (V3d& x : p) x = vec() * size;
      through(p, uniform(rng));
      q = test_random::elevated(p, n);
    }
    if (lifted) {
      const V3d lift = s.normal * s.radius * (0.05 + 0.95 * uniform(rng)) * (uniform(rng) < 0.5 ? -1 : 1);
      for (V3d& p : q) p += lift;
    }
    for (V3d& p : q) p += s.center;
    if (single) {  // float32 inputs, as the differential test draws them
      for (V3d& p : q) p = p.cast<float>().cast<double>();
      s.center = s.center.cast<float>().cast<double>();
      s.normal = s.normal.cast<float>().cast<double>();
      s.radius = double(float(s.radius));
    }
    s.curve = curve_of(q);
    s.name = std::string(kinds[kind]) + (lifted ? ", lifted" : "") + (single ? ", float32" : "") + ", degree " +
             std::to_string(n) + ", case " + std::to_string(k);
    check_scene<Circle3<double>>(s, 20000);
    check_scene<Disk3<double>>(s, 20000);
  }
}

}  // namespace

int main() {
  finding_tests();
  hunted_tests();
  random_tests();
  for (int p = 0; p < 4; ++p)
    std::printf("%s: %d failures, largest relative error %.3g\n", kPolicies[p], failures[p], worst[p]);
  return check::finish("bezier_center");
}

}  // namespace test_bezier_center

CHECK_SUITE(test_bezier_center);
