// bench_arc: the cost of each arc query against its circle counterpart (issue 19 asks for at most
// 1.3x), in one run on the same random shapes: an arc is its circle's fields plus a random start
// and a random angle in (0.5, 6) rad; the circle counterpart replaces the arc by that circle (for
// arc-arc, both arcs: circle-circle). distance() and closest_points() through the front end, in
// double, the arc second (the first order the front end dispatches to the arc's query).
//
//   bench_arc [pairs per kind, default 4000] [repeats, default 7]
//
// stdout, one line per pair and call: ns/query for the arc and the circle (the least over the
// repeats of a full pass's thread CPU time, over the pairs), and their ratio. docs/arc.md "Cost".
#include <circledist/circledist.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <time.h>  // clock_gettime (POSIX)

namespace {

using Real = double;
using namespace circledist;
using V = Vec3<Real>;

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Draw {
  std::mt19937_64 rng{20261126};
  std::uniform_real_distribution<Real> unit{-1, 1};
  V vec(Real s) { return V(s * unit(rng), s * unit(rng), s * unit(rng)); }
  V dir() {
    for (;;) {
      const V d = vec(1);
      if (d.norm() > 0.1) return d;
    }
  }
  Real radius() { return std::uniform_real_distribution<Real>(0.2, 2)(rng); }
  Real angle() { return std::uniform_real_distribution<Real>(0.5, 6)(rng); }
  Arc3<Real> arc() { return {vec(2), dir(), radius(), dir(), angle()}; }
};

Circle3<Real> circle_of(const Arc3<Real>& a) { return {a.center, a.normal, a.radius}; }

// The least over `repeats` passes of the ns per query of f over the n inputs; `sink` keeps the
// answers alive.
template <class F> double time_pass(int n, int repeats, const F& f, double& sink) {
  double best = 1e300;
  for (int k = 0; k < repeats; ++k) {
    const double t0 = thread_seconds();
    double s = 0;
    for (int i = 0; i < n; ++i) s += f(i);
    best = std::min(best, thread_seconds() - t0);
    sink += s;
  }
  return 1e9 * best / n;
}

// One pair kind: `first[i]` against arcs[i] and against its circle; `both` makes the first an
// arc too (compared with circle-circle).
template <class A> void run(const char* name, const std::vector<A>& first, const std::vector<Arc3<Real>>& arcs,
                            int repeats, double& sink) {
  const int n = int(arcs.size());
  std::vector<Circle3<Real>> circles;
  for (const auto& a : arcs) circles.push_back(circle_of(a));
  const double ad = time_pass(n, repeats, [&](int i) { return distance(first[i], arcs[i]); }, sink);
  const double cd = time_pass(n, repeats, [&](int i) { return distance(first[i], circles[i]); }, sink);
  const double ac = time_pass(n, repeats, [&](int i) { return closest_points(first[i], arcs[i]).distance; }, sink);
  const double cc = time_pass(n, repeats, [&](int i) { return closest_points(first[i], circles[i]).distance; }, sink);
  std::printf("%-10s distance        arc %8.1f ns  circle %8.1f ns  ratio %5.2f\n", name, ad, cd, ad / cd);
  std::printf("%-10s closest_points  arc %8.1f ns  circle %8.1f ns  ratio %5.2f\n", name, ac, cc, ac / cc);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 4000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 7;
  Draw draw;
  std::vector<Arc3<Real>> arcs, others;
  std::vector<V> points;
  std::vector<Line3<Real>> lines;
  std::vector<Ray3<Real>> rays;
  std::vector<Segment3<Real>> segments;
  std::vector<Circle3<Real>> circles;
  std::vector<Disk3<Real>> disks;
  for (int i = 0; i < n; ++i) {
    arcs.push_back(draw.arc());
    others.push_back(draw.arc());
    points.push_back(draw.vec(3));
    lines.push_back({draw.vec(3), draw.dir()});
    rays.push_back({draw.vec(3), draw.dir()});
    segments.push_back({draw.vec(3), draw.vec(3)});
    circles.push_back({draw.vec(2), draw.dir(), draw.radius()});
    disks.push_back({draw.vec(2), draw.dir(), draw.radius()});
  }
  double sink = 0;
  std::printf("bench_arc: %d random pairs per kind, least of %d passes (thread CPU time)\n", n, repeats);
  run("point", points, arcs, repeats, sink);
  run("line", lines, arcs, repeats, sink);
  run("ray", rays, arcs, repeats, sink);
  run("segment", segments, arcs, repeats, sink);
  run("circle", circles, arcs, repeats, sink);
  run("disk", disks, arcs, repeats, sink);
  // Arc-arc against circle-circle: both arcs become their circles.
  {
    std::vector<Circle3<Real>> first;
    for (const auto& a : others) first.push_back(circle_of(a));
    const int m = int(arcs.size());
    std::vector<Circle3<Real>> second;
    for (const auto& a : arcs) second.push_back(circle_of(a));
    const double ad = time_pass(m, repeats, [&](int i) { return distance(others[i], arcs[i]); }, sink);
    const double cd = time_pass(m, repeats, [&](int i) { return distance(first[i], second[i]); }, sink);
    const double ac = time_pass(m, repeats, [&](int i) { return closest_points(others[i], arcs[i]).distance; }, sink);
    const double cc = time_pass(m, repeats, [&](int i) { return closest_points(first[i], second[i]).distance; }, sink);
    std::printf("%-10s distance        arc %8.1f ns  circle %8.1f ns  ratio %5.2f\n", "arc-arc", ad, cd, ad / cd);
    std::printf("%-10s closest_points  arc %8.1f ns  circle %8.1f ns  ratio %5.2f\n", "arc-arc", ac, cc, ac / cc);
  }
  std::printf("(checksum %.6g)\n", sink);
  return 0;
}
