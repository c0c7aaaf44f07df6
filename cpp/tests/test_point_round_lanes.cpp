// detail/point_round_lanes.hpp: point-round closest_points in AVX lanes must be the scalar front
// end's closest_points, bit for bit (every field, signed zeros included), for circles and disks,
// wherever the lanes answer (else the batch asks the scalar query), and for true rings (annuli,
// PointRingQuery) likewise. Blocks of cases are drawn
// from random scenes and from the hard ones:
// points on and near the axis, on the rim, in the plane, on the center, normals along and near
// the axes (the frame's choice of axis), normals of extreme length, radius 0, scenes far from the
// origin or of extreme size, infinities and NaN; each hard case in every lane beside random ones,
// so that a lane never borrows its neighbour's branch, and in all lanes at once.
#include <circledist/circledist.hpp>
#include <circledist/detail/point_round_lanes.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "check.hpp"
#include "random.hpp"

namespace test_point_round_lanes {

namespace {

using namespace circledist;
using V = Vec3<double>;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const V& a, const V& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}
bool same_bits(const Vec2<double>& a, const Vec2<double>& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y());
}
bool same_bits(const Result<double>& a, const Result<double>& b) {
  return same_bits(a.distance, b.distance) && same_bits(a.point_a, b.point_a) && same_bits(a.point_b, b.point_b) &&
         same_bits(a.param_a, b.param_a) && same_bits(a.param_b, b.param_b) && a.unique == b.unique;
}

struct Case {
  V point;
  V center, normal;
  double radius;
  double inner = 0;  // the inner radius when the round is taken as an annulus
};

int answered = 0, declined = 0;

#if CIRCLEDIST_POINT_ROUND_LANES
constexpr int kLanes = detail::kLanes;

// The lanes' answers for cases[0..kLanes), loaded and stored as the batch does (src/pairs.hpp:
// 3-vectors as twelve consecutive numbers, or lane by lane at a stride): false where they decline.
template <detail::LaneTarget Target>
__attribute__((target("avx"))) bool lanes_answer(const Case* cases, Result<double>* out, bool consecutive) {
  double points[3 * kLanes], centers[3 * kLanes], normals[3 * kLanes], radii[kLanes], inner[kLanes];
  for (int k = 0; k < kLanes; ++k) {
    for (int j = 0; j < 3; ++j) {
      points[3 * k + j] = cases[k].point[j];
      centers[3 * k + j] = cases[k].center[j];
      normals[3 * k + j] = cases[k].normal[j];
    }
    radii[k] = cases[k].radius;
    inner[k] = cases[k].inner;
  }
  detail::PointRoundLanes in;
  const auto load = [&](const double* x, detail::Lanes& a, detail::Lanes& b,
                        detail::Lanes& c) __attribute__((target("avx"))) {
    if (consecutive) return detail::load_triples(x, a, b, c);
    a = detail::strided_lanes(x, 3), b = detail::strided_lanes(x + 1, 3), c = detail::strided_lanes(x + 2, 3);
  };
  load(points, in.px, in.py, in.pz);
  load(centers, in.cx, in.cy, in.cz);
  load(normals, in.wx, in.wy, in.wz);
  in.radius = detail::strided_lanes(radii, 1);
  in.inner = detail::strided_lanes(inner, 1);
  detail::PointRoundAnswerLanes answer;
  if (!detail::point_round_closest_lanes<Target>(in, answer)) return false;
  double d[kLanes], point_a[3 * kLanes], point_b[3 * kLanes], param_a[2 * kLanes], param_b[2 * kLanes];
  answer.distance.to(d);
  detail::store_triples(in.px, in.py, in.pz, point_a);
  detail::store_triples(answer.bx, answer.by, answer.bz, point_b);
  detail::store_pairs(detail::Lanes::both(0), detail::Lanes::both(0), param_a);
  detail::store_pairs(answer.param0, answer.param1, param_b);
  for (int k = 0; k < kLanes; ++k) {
    out[k].distance = d[k];
    out[k].point_a = V(point_a[3 * k], point_a[3 * k + 1], point_a[3 * k + 2]);
    out[k].point_b = V(point_b[3 * k], point_b[3 * k + 1], point_b[3 * k + 2]);
    out[k].param_a = Vec2<double>(param_a[2 * k], param_a[2 * k + 1]);
    out[k].param_b = Vec2<double>(param_b[2 * k], param_b[2 * k + 1]);
    out[k].unique = true;  // the batch's flag (src/pairs.hpp)
  }
  return true;
}

Circle3<double> as(const Case& c, const Circle3<double>*) { return {c.center, c.normal, c.radius}; }
Disk3<double> as(const Case& c, const Disk3<double>*) { return {c.center, c.normal, c.radius}; }
Annulus3<double> as(const Case& c, const Annulus3<double>*) { return {c.center, c.normal, c.inner, c.radius}; }

template <class Round, detail::LaneTarget Target> void check_lanes(const Case* cases) {
  Result<double> lanes[kLanes], strided[kLanes];
  const bool answered_consecutive = lanes_answer<Target>(cases, lanes, true);
  CHECK(answered_consecutive == lanes_answer<Target>(cases, strided, false));
  for (int k = 0; answered_consecutive && k < kLanes; ++k) CHECK(same_bits(lanes[k], strided[k]));
  if (answered_consecutive) {
    ++answered;
    for (int k = 0; k < kLanes; ++k) {
      const Round round = as(cases[k], static_cast<const Round*>(nullptr));
      CHECK(same_bits(lanes[k], closest_points(cases[k].point, round)));
    }
  } else {
    ++declined;
  }
}

void check_both(const Case* cases) {
  check_lanes<Circle3<double>, detail::LaneTarget::kCircle>(cases);
  check_lanes<Disk3<double>, detail::LaneTarget::kDisk>(cases);
  check_lanes<Annulus3<double>, detail::LaneTarget::kRing>(cases);
}
#endif

std::vector<Case> hard_cases(test_random::Random& rng) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Case> out;
  const V normals[] = {V(0, 0, 1),
                       V(0, 0, -1),
                       V(1, 0, 0),
                       V(0, 1, 0),
                       V(-1, 0, 0),
                       V(1, 1, 0),
                       V(1, -1, 0),
                       V(1e-300, 0, 1),
                       V(1e-17, 1, 0),
                       V(1, 1e-17, 1e-17),
                       V(0, 1, 1),
                       V(3e-200, 1e-200, 2e-200),
                       V(3e200, -1e200, 2e200),
                       V(1e-16, 0, 0),
                       V(1e16, 1, 0)};
  for (const V& n : normals) {
    const Frame<double> f(n);
    for (double r : {0.0, 1.0, 0.5, 1e-300}) {
      const V c = rng.vector(2);
      const double inner = r * (rng.integer(0, 3) == 0 ? 0.0 : rng.integer(0, 3) == 0 ? 1.0 : rng.uniform(0.0, 1.0));
      for (const V& local :
           {V(0, 0, 0), V(0, 0, 1), V(0, 0, -2), V(1e-20, 0, 1), V(1, 0, 0), V(0, 1, 0), V(-1, 0, 0), V(0.5, 0.5, 0),
            V(1, 0, 1e-12), V(2, 0, 0), V(1 + 1e-15, 0, 0), V(0.3, -0.4, 5), V(1e-300, 1e-300, 0)}) {
        out.push_back({c + r * (local.x() * f.u + local.y() * f.v) + local.z() * f.n, c, n, r, inner});
        out.push_back({c + local.x() * f.u + local.y() * f.v + local.z() * f.n, c, n, r, inner});
        // on, just inside and just outside the inner rim, and on the axis over the hole
        for (double at : {1.0, 1 - 1e-15, 1 + 1e-15, 0.0, 1e-20})
          out.push_back({c + inner * at * (local.x() * f.u + local.y() * f.v) + local.z() * f.n, c, n, r, inner});
      }
    }
  }
  for (double offset : {1e6, 1e12, 1e100, 1e300, 1e-300}) {
    const V c = offset * V(1, -0.7, 0.4);
    out.push_back({c + rng.vector(1), c, rng.direction(), 0.7});
    out.push_back({offset * rng.vector(1), offset * rng.vector(1), rng.direction(), offset});
  }
  for (double bad : {inf, -inf, nan}) {
    out.push_back({V(bad, 0, 0), V(0, 0, 0), V(0, 0, 1), 1});
    out.push_back({V(1, 0, 0), V(0, bad, 0), V(0, 0, 1), 1});
    out.push_back({V(1, 0, 2), V(0, 0, 0), V(0, 0, bad), 1});
    out.push_back({V(1, 0, 2), V(0, 0, 0), V(0, 0, 1), bad});
  }
  out.push_back({V(1, 2, 3), V(0, 0, 0), V(0, 0, 0), 1});  // a zero normal
  return out;
}

}  // namespace

int main() {
#if CIRCLEDIST_POINT_ROUND_LANES
  if (!detail::has_lanes()) {
    std::printf("this processor has no AVX: the scalar query answers every batch\n");
    CHECK(true);
    return check::finish("test_point_round_lanes");
  }
  test_random::Random rng(20261127);
  const auto random_case = [&] {
    const double radius = rng.uniform(0.0, 2.0);
    return Case{rng.vector(3), rng.vector(2), rng.direction(), radius, radius * rng.uniform(0.0, 1.0)};
  };
  Case cases[kLanes];
  const int blocks = check::scaled(100000);
  for (int i = 0; i < blocks; ++i) {
    for (Case& c : cases) c = random_case();
    check_both(cases);
  }
  const int random_answered = answered;
  // Each hard case in every lane, beside random ones, and in all lanes at once.
  for (const Case& hard : hard_cases(rng)) {
    for (int lane = 0; lane < kLanes; ++lane) {
      for (Case& c : cases) c = random_case();
      cases[lane] = hard;
      check_both(cases);
    }
    for (Case& c : cases) c = hard;
    check_both(cases);
  }
  std::printf("lanes answered %d blocks of %d (%d of them random), declined %d\n", answered, kLanes, random_answered,
              declined);
  // The common path is the lanes': random blocks of moderate scenes off the axis answer there.
  CHECK(random_answered > 3 * blocks * 99 / 100);
#else
  std::printf("no AVX lanes in this build (not x86, or not GCC or Clang): the scalar query answers every batch\n");
  CHECK(true);
#endif
  return check::finish("test_point_round_lanes");
}

}  // namespace test_point_round_lanes

CHECK_SUITE(test_point_round_lanes);
