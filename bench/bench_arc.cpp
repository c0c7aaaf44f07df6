// bench_arc: the cost of each arc query against its circle counterpart (the target is at most
// 1.3x), in one run on the same random shapes: an arc is its circle's fields plus a random start
// and a random angle in (0.5, 6) rad; the circle counterpart replaces the arc by that circle (for
// arc-arc, both arcs: circle-circle). distance() and closest_points() through the front end, in
// double, the arc second (the first order the front end dispatches to the arc's query).
//
//   bench_arc [pairs per kind, default 4000] [repeats, default 7]
//
// stdout, one line per pair and call: ns/query for the arc and the circle (the least over the
// repeats of a full pass's thread CPU time, over the pairs; the arc's and the circle's passes
// alternate), and their ratio (the kinds ".../plane": the other shape in the arc's plane); then
// two "floor" lines: the sine and cosine of the arc's angle against point-circle's distance, and
// the share of the draws whose point-arc answer is the far end (the trigonometry it cannot do
// without). docs/derivations/arc.md "Cost".
#include <circledist/circledist.hpp>

#include <algorithm>
#include <cmath>
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
  // A point of arc a's plane at in-plane offsets up to s from its center, and an in-plane
  // direction (formed in double: in the plane to rounding).
  V in_plane(const Arc3<Real>& a, Real s, bool direction) {
    const V n = a.normal.normalized();
    const V e1 = n.cross(dir()).normalized(), e2 = n.cross(e1);
    const V offset = s * unit(rng) * e1 + s * unit(rng) * e2;
    return direction ? offset : V(a.center + offset);
  }
};

Circle3<Real> circle_of(const Arc3<Real>& a) { return {a.center, a.normal, a.radius}; }

// The least over `repeats` passes of the ns per query of f (the arc) and of g (its circle) over
// the n inputs, the two passes interleaved in each repeat so that a load that comes and goes on a
// shared machine weighs on both alike; `sink` keeps the answers alive.
struct PairTimes {
  double arc, circle;
};
template <class F> double one_pass(int n, const F& f, double& sink) {
  const double t0 = thread_seconds();
  double s = 0;
  for (int i = 0; i < n; ++i) s += f(i);
  sink += s;
  return thread_seconds() - t0;
}
template <class F, class G> PairTimes time_pair(int n, int repeats, const F& f, const G& g, double& sink) {
  double best_f = 1e300, best_g = 1e300;
  for (int k = 0; k < repeats; ++k) {
    best_f = std::min(best_f, one_pass(n, f, sink));
    best_g = std::min(best_g, one_pass(n, g, sink));
  }
  return {1e9 * best_f / n, 1e9 * best_g / n};
}

void report(const char* name, const char* call, PairTimes t) {
  std::printf("%-10s %-15s arc %8.1f ns  circle %8.1f ns  ratio %5.2f\n", name, call, t.arc, t.circle,
              t.arc / t.circle);
}

// One pair kind: `first[i]` against arcs[i] and against `second[i]` (its circle; for arc-arc,
// `first` holds arcs and `circles_first` their circles, compared with circle-circle).
template <class A, class B, class C> void run(const char* name, const std::vector<A>& first,
                                              const std::vector<Arc3<Real>>& arcs, const std::vector<B>& circle_first,
                                              const std::vector<C>& second, int repeats, double& sink) {
  const int n = int(arcs.size());
  report(name, "distance",
         time_pair(
             n, repeats, [&](int i) { return distance(first[i], arcs[i]); },
             [&](int i) { return distance(circle_first[i], second[i]); }, sink));
  report(name, "closest_points",
         time_pair(
             n, repeats, [&](int i) { return closest_points(first[i], arcs[i]).distance; },
             [&](int i) { return closest_points(circle_first[i], second[i]).distance; }, sink));
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
  std::vector<Circle3<Real>> arc_circles, other_circles;
  for (int i = 0; i < n; ++i) {
    arc_circles.push_back(circle_of(arcs[i]));
    other_circles.push_back(circle_of(others[i]));
  }
  std::printf(
      "bench_arc: %d random pairs per kind, least of %d passes (thread CPU time), arc and circle "
      "passes interleaved\n",
      n, repeats);
  run("point", points, arcs, points, arc_circles, repeats, sink);
  run("line", lines, arcs, lines, arc_circles, repeats, sink);
  run("ray", rays, arcs, rays, arc_circles, repeats, sink);
  run("segment", segments, arcs, segments, arc_circles, repeats, sink);
  run("circle", circles, arcs, circles, arc_circles, repeats, sink);
  run("disk", disks, arcs, disks, arc_circles, repeats, sink);
  // Arc-arc against circle-circle: both arcs become their circles.
  run("arc-arc", others, arcs, other_circles, arc_circles, repeats, sink);
  // In the arc's plane (the toolpath case: arcs and lines in one plane), the same shapes against
  // the arc and its circle; the target there is 1.5x (a point 2x).
  {
    std::vector<V> p;
    std::vector<Line3<Real>> l;
    std::vector<Ray3<Real>> r;
    std::vector<Segment3<Real>> s;
    std::vector<Circle3<Real>> c;
    for (const Arc3<Real>& a : arcs) {
      p.push_back(draw.in_plane(a, 3, false));
      l.push_back({draw.in_plane(a, 3, false), draw.in_plane(a, 1, true)});
      r.push_back({draw.in_plane(a, 3, false), draw.in_plane(a, 1, true)});
      const V p0 = draw.in_plane(a, 3, false);
      s.push_back({p0, p0 + draw.in_plane(a, 3, true)});
      c.push_back({draw.in_plane(a, 2, false), (draw.unit(draw.rng) < 0 ? -1 : 1) * a.normal, draw.radius()});
    }
    run("point/plane", p, arcs, p, arc_circles, repeats, sink);
    run("line/plane", l, arcs, l, arc_circles, repeats, sink);
    run("ray/plane", r, arcs, r, arc_circles, repeats, sink);
    run("seg/plane", s, arcs, s, arc_circles, repeats, sink);
    run("circ/plane", c, arcs, c, arc_circles, repeats, sink);
  }
  // The floor under point-arc: the sine and cosine of the arc's angle, which the far end's point
  // needs (there is no end point without them: the arc is given by its angle), timed alone in the
  // same loop against point-circle's whole distance. Where this ratio is above 0.3 a point-arc
  // query that reaches its far end cannot stay within 1.3x point-circle (docs/derivations/arc.md "Cost").
  const PairTimes trig = time_pair(
      n, repeats,
      [&](int i) { return std::sin(arcs[i].angle) * points[i].x() + std::cos(arcs[i].angle) * points[i].y(); },
      [&](int i) { return distance(points[i], arc_circles[i]); }, sink);
  std::printf("%-10s %-15s sin+cos %4.1f ns  point-circle distance %4.1f ns  ratio %5.2f\n", "floor", "angle trig",
              trig.arc, trig.circle, trig.arc / trig.circle);
  // How many of the draws need it: the point's angle from the start (in the arc's plane) past the
  // arc and nearer its far end than its start (in angle), found here in plain double from the
  // definition. Their share times sin+cos is what the far end costs on average, against the
  // 0.3 x point-circle that 1.3x leaves for everything the arc adds.
  int far = 0;
  for (int i = 0; i < n; ++i) {
    const V nrm = arcs[i].normal.normalized(), d = points[i] - arcs[i].center;
    const V u = (arcs[i].start - arcs[i].start.dot(nrm) * nrm).normalized(), v = nrm.cross(u);
    Real t = std::atan2(d.dot(v), d.dot(u));
    if (t < 0) t += 2 * pi_v<Real>();
    far += t > arcs[i].angle && t - arcs[i].angle < 2 * pi_v<Real>() - t;
  }
  const double share = double(far) / n;
  std::printf("%-10s %-15s %4.1f %% of the draws: %4.2f ns on average, against a 1.3x allowance of %4.2f ns\n", "floor",
              "far end", 100 * share, share * trig.arc, 0.3 * trig.circle);
  std::printf("(checksum %.6g)\n", sink);
  return 0;
}
