// The broadphase (broadphase.hpp) against brute force: its candidate pairs are exactly the pairs
// whose lower bound is within the pair's own limit (PairLimit, every pair checked), the lower bounds never exceed the
// exact distance, and no pair the exact distance puts within d is culled. Random mixed sets
// (lines and rays among them, swept shapes), duplicates, every shape at one spot, d = 0 with
// touching shapes, empty sets; the k nearest by bound, and the exact k nearest built on them.
#include <circledist/broadphase.hpp>
#include <circledist/circledist.hpp>

#include "check.hpp"
#include "random.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <random>
#include <set>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace test_broadphase {

using namespace circledist;

namespace {

using V = Vec3<double>;
using Any =
    std::variant<Swept<V>, Swept<Line3<double>>, Swept<Ray3<double>>, Swept<Segment3<double>>, Swept<Circle3<double>>,
                 Swept<Disk3<double>>, Swept<BezierCurve3<double>>, Swept<Arc3<double>>, Swept<Annulus3<double>>>;
using Pairs = std::vector<std::pair<BroadIndex, BroadIndex>>;

test_random::Random source(20261125);
double uniform(double a, double b) { return source.uniform(a, b); }
V random_vector(double scale) { return source.vector(scale); }
V random_direction() { return source.direction(); }

// A shape of a random kind near `at` (kinds in [first, last)), swept by up to `sweep`.
Any random_shape(const V& at, int first = 0, int last = 7, double sweep = 0.3) {
  const double r = uniform(0, 1) < 0.5 ? 0.0 : uniform(0, sweep);
  switch (source.integer(first, last - 1)) {
    case 0:
      return swept(V(at), r);
    case 1:
      return swept(Line3<double>{at, random_direction()}, r);
    case 2:
      return swept(Ray3<double>{at, random_direction()}, r);
    case 3:
      return swept(Segment3<double>{at, V(at + random_vector(1.5))}, r);
    case 4:
      return swept(Circle3<double>{at, random_direction(), uniform(0.1, 1.2)}, r);
    case 5:
      return swept(Disk3<double>{at, random_direction(), uniform(0.1, 1.2)}, r);
    case 6: {
      BezierCurve3<double> b;
      b.control.resize(3, 4);
      for (int i = 0; i < 4; ++i) b.control.col(i) = at + random_vector(1.0);
      return swept(b, r);
    }
    case 7:  // an arc (its box is its own, not its circle's)
      return swept(Arc3<double>{at, random_direction(), uniform(0.1, 1.2), random_direction(), uniform(0.05, 6.3)}, r);
    default: {  // kind 8: an annulus (its box is its outer disk's)
      const double outer = uniform(0.1, 1.2);
      return swept(Annulus3<double>{at, random_direction(), outer * uniform(0, 1), outer}, r);
    }
  }
}

// The shape moved by `by` (a far-translated scene).
template <class S> void translate(Swept<S>& s, const V& by) {
  S& x = s.shape;
  if constexpr (std::is_same_v<S, V>)
    x += by;
  else if constexpr (std::is_same_v<S, Segment3<double>>)
    x.p0 += by, x.p1 += by;
  else if constexpr (std::is_same_v<S, BezierCurve3<double>>)
    x.control.colwise() += by;
  else if constexpr (std::is_same_v<S, Line3<double>> || std::is_same_v<S, Ray3<double>>)
    x.origin += by;
  else
    x.center += by;
}

std::vector<Volume<double>> volumes_of(const std::vector<Any>& shapes) {
  std::vector<Volume<double>> out;
  for (const Any& s : shapes) out.push_back(std::visit([](const auto& x) { return volume(x); }, s));
  return out;
}

// The exact distance, or NaN where the library has no query for the pair (Bezier curves with
// anything but circles and disks).
double exact(const Any& a, const Any& b) {
  return std::visit(
      [](const auto& x, const auto& y) -> double {
        using A = core_t<std::decay_t<decltype(x)>>;
        using B = core_t<std::decay_t<decltype(y)>>;
        if constexpr (has_symmetric_query_v<A, B>)
          return distance(x, y);
        else
          return std::nan("");
      },
      a, b);
}

// Pairs within d that the checks saw (the sets must exercise the culling, not only far pairs).
long exercised = 0;

bool kept(double bound, double limit) { return !(bound > limit); }

// Checks one pair of sets (b_same: B is A, pairs i < j) at distance d against brute force, each
// pair culled at its own limit. Returns the candidates.
Pairs check_sets(const std::vector<Any>& a, const std::vector<Any>& b, bool b_same, double d) {
  const std::vector<Volume<double>> va = volumes_of(a), vb = volumes_of(b);
  const BoundingVolumeHierarchy<double> tree(vb);
  const BoundingVolumeHierarchy<double> tree_a(va);
  const double scale = std::max(tree.scale(), tree_a.scale());
  const PairLimit<double> limit{d};
  Pairs got;
  if (b_same) {
    // In two parts, as threads split the work, joined by sort_pairs.
    const BroadIndex half = tree.size() / 2;
    candidate_pairs(tree, limit, 0, half, got);
    candidate_pairs(tree, limit, half, tree.size(), got);
    sort_pairs(got, tree.size());
    CHECK(got == candidate_pairs(tree, limit));
  } else {
    const std::vector<BroadIndex> order = spatial_order(va);
    const BroadIndex half = BroadIndex(a.size()) / 2;
    candidate_pairs(va, order, tree, limit, 0, half, got);
    candidate_pairs(va, order, tree, limit, half, BroadIndex(a.size()), got);
    sort_pairs(got, BroadIndex(a.size()));
    CHECK(got == candidate_pairs(va, tree, limit));
  }
  Pairs expected;
  for (size_t i = 0; i < a.size(); ++i) {
    for (size_t j = b_same ? i + 1 : 0; j < b.size(); ++j) {
      const double bound = lower_bound(va[i], vb[j]), pair_limit = limit(va[i].reach(), vb[j].reach());
      if (kept(bound, pair_limit)) expected.emplace_back(BroadIndex(i), BroadIndex(j));
      const double D = exact(a[i], b[j]);
      if (D == D) {
        // Lower bounds hold (up to rounding far below the margin).
        CHECK(!(bound > D + 1e-12 * (1 + scale)));
        // Nothing within d is culled.
        if (D <= d) {
          ++exercised;
          CHECK(kept(bound, pair_limit));
        }
      }
    }
  }
  CHECK(got == expected);
  if (got != expected) {
    std::printf("  sets of %zu and %zu, d = %g: %zu candidates, brute force %zu\n", a.size(), b.size(), d, got.size(),
                expected.size());
    for (size_t k = 0, shown = 0; k < expected.size() && shown < 5; ++k)
      if (std::find(got.begin(), got.end(), expected[k]) == got.end()) {
        const auto& [i, j] = expected[k];
        std::printf("  missing (%td, %td): bound %g, kinds %d %d\n", i, j, lower_bound(va[size_t(i)], vb[size_t(j)]),
                    int(va[size_t(i)].kind), int(vb[size_t(j)].kind));
        ++shown;
      }
  }
  CHECK(std::is_sorted(got.begin(), got.end()));
  return got;
}

// The k nearest of B to each shape of A: the k smallest bounds as brute force sorts them, and the
// exact k nearest found from them (tau = the largest exact distance of the k by bound; every
// shape with bound <= tau tested) equal to sorting every exact distance.
void check_nearest(const std::vector<Any>& a, const std::vector<Any>& b, BroadIndex k) {
  const std::vector<Volume<double>> va = volumes_of(a), vb = volumes_of(b);
  const BoundingVolumeHierarchy<double> tree(vb);
  for (size_t i = 0; i < a.size(); ++i) {
    const auto by_bound = tree.nearest_by_bound(va[i], k);
    std::vector<std::pair<double, BroadIndex>> all;
    for (size_t j = 0; j < b.size(); ++j) {
      double bound = lower_bound(va[i], vb[j]);
      if (bound != bound) bound = -INFINITY;
      all.emplace_back(bound, BroadIndex(j));
    }
    std::sort(all.begin(), all.end());
    all.resize(std::min<size_t>(all.size(), size_t(k)));
    CHECK(by_bound == all);
    // The exact k nearest (pairs without a query are left out of these sets).
    double tau = -INFINITY;
    for (const auto& [bound, j] : by_bound) tau = std::max(tau, exact(a[i], b[size_t(j)]));
    std::set<BroadIndex> tested;
    for (const auto& e : by_bound) tested.insert(e.second);
    if (std::isfinite(tau)) {
      tree.visit_within(va[i], PairLimit<double>{tau}, [&](BroadIndex j, double) { tested.insert(j); });
    } else {
      for (size_t j = 0; j < b.size(); ++j) tested.insert(BroadIndex(j));
    }
    std::vector<std::pair<double, BroadIndex>> found, brute;
    for (const BroadIndex j : tested) found.emplace_back(exact(a[i], b[size_t(j)]), j);
    for (size_t j = 0; j < b.size(); ++j) brute.emplace_back(exact(a[i], b[j]), BroadIndex(j));
    std::sort(found.begin(), found.end());
    std::sort(brute.begin(), brute.end());
    found.resize(std::min<size_t>(found.size(), size_t(k)));
    brute.resize(std::min<size_t>(brute.size(), size_t(k)));
    CHECK(found == brute);
  }
}

std::vector<Any> random_set(int n, double box, int first = 0, int last = 7) {
  std::vector<Any> out;
  for (int i = 0; i < n; ++i) out.push_back(random_shape(random_vector(box), first, last));
  return out;
}

}  // namespace

int main() {
  // Random mixed sets without Bezier curves (every pair has an exact distance), then with them.
  for (const double box : {3.0, 10.0}) {
    const std::vector<Any> a = random_set(220, box, 0, 6), b = random_set(180, box, 0, 6);
    for (const double d : {0.0, 0.25, 1.0}) {
      check_sets(a, b, false, d);
      check_sets(a, a, true, d);
    }
    check_nearest(a, b, 1);
    check_nearest(a, b, 5);
    check_nearest(a, a, 3);
  }
  {
    std::vector<Any> rounds = random_set(150, 6.0, 4, 6), curves = random_set(120, 6.0, 6, 7);
    check_sets(curves, rounds, false, 0.5);
    check_sets(rounds, curves, false, 0.0);
    check_nearest(curves, rounds, 4);
    std::vector<Any> mixed = random_set(200, 6.0);
    check_sets(mixed, mixed, true, 0.4);
  }
  // Arcs (kind 7) against every kind that has an arc query, and among themselves: their boxes
  // (the ends and the circle's extremes on the arc) and balls (the chord's up to a half turn)
  // never cull a pair within d. And the box is the arc's: a quarter arc's is a quarter of its
  // circle's square, not the whole square.
  {
    const std::vector<Any> arcs = random_set(160, 5.0, 7, 8), others = random_set(200, 5.0, 0, 6);
    for (const double d : {0.0, 0.3}) {
      check_sets(arcs, others, false, d);
      check_sets(others, arcs, false, d);
      check_sets(arcs, arcs, true, d);
    }
    check_nearest(arcs, others, 3);
    check_nearest(others, arcs, 2);
    const Volume<double> quarter = volume(Arc3<double>{V(0, 0, 0), V(0, 0, 1), 1.0, V(1, 0, 0), 1.5707963267948966});
    CHECK_NEAR(quarter.lo.x(), 0.0, 1e-15);
    CHECK_NEAR(quarter.lo.y(), 0.0, 1e-15);
    CHECK_NEAR(quarter.hi.x(), 1.0, 1e-15);
    CHECK_NEAR(quarter.hi.y(), 1.0, 1e-15);
    CHECK_NEAR(quarter.lo.z(), 0.0, 1e-15);
    CHECK_NEAR(quarter.hi.z(), 0.0, 1e-15);
    const Volume<double> past_left = volume(Arc3<double>{V(0, 0, 0), V(0, 0, 1), 2.0, V(0, 1, 0), 2.0});
    CHECK_NEAR(past_left.lo.x(), -2.0, 1e-15);  // through the circle's leftmost point
    CHECK_NEAR(past_left.hi.y(), 2.0, 1e-15);
    CHECK(std::abs(past_left.hi.x()) < 1e-15);  // from (0, 2) over (-2, 0) to 2 (-sin 2, cos 2)
    CHECK_NEAR(past_left.lo.y(), 2 * std::cos(2.0), 1e-15);
  }
  // Annuli (kind 8) against every kind that has an annulus query (not Bezier curves), and among
  // themselves: their boxes and balls (the outer disk's) never cull a pair within d.
  {
    const std::vector<Any> rings = random_set(160, 5.0, 8, 9);
    std::vector<Any> others = random_set(160, 5.0, 0, 6), arcs = random_set(40, 5.0, 7, 8);
    others.insert(others.end(), arcs.begin(), arcs.end());
    for (const double d : {0.0, 0.3}) {
      check_sets(rings, others, false, d);
      check_sets(others, rings, false, d);
      check_sets(rings, rings, true, d);
    }
    check_nearest(rings, others, 3);
    check_nearest(others, rings, 2);
    const Volume<double> tilted = volume(Annulus3<double>{V(1, 2, 3), V(0, 0, 2), 0.5, 1.5});
    CHECK_NEAR(tilted.lo.x(), -0.5, 1e-15);
    CHECK_NEAR(tilted.hi.y(), 3.5, 1e-15);
    CHECK_NEAR(tilted.lo.z(), 3.0, 1e-15);
    CHECK_NEAR(tilted.hi.z(), 3.0, 1e-15);
  }
  // Far and huge shapes: each pair's margin is its own, so one shape moved to 1e12 or grown to a
  // radius of 1e9 adds at most its own pairs to the candidates (not every pair, as a margin of
  // the whole set's extent did); whole sets moved far keep every pair within d (the margin of
  // their coordinates' size), and the candidates stay brute force's under the pair's limit.
  {
    const std::vector<Any> base = random_set(300, 6.0, 0, 6);
    for (const double d : {0.0, 0.3}) {
      const size_t plain = check_sets(base, base, true, d).size();
      for (int outlier = 0; outlier < 4; ++outlier) {
        std::vector<Any> a = base;
        a[17] = outlier == 0   ? Any(swept(Circle3<double>{V(1e12, 0, 0), V(0, 0, 1), 1.0}, 0.0))
                : outlier == 1 ? Any(swept(Circle3<double>{V(0, 0, 0), V(0, 0, 1), 1e9}, 0.0))
                : outlier == 2 ? Any(swept(V(-3e11, 2e11, 5e10), 0.0))
                               : Any(swept(Line3<double>{V(0, 4e12, 0), V(1, 0, 0)}, 0.0));
        const size_t with = check_sets(a, a, true, d).size();
        CHECK(with <= plain + a.size() - 1);
        check_sets(a, base, false, d);
        check_nearest(a, base, 3);
      }
    }
    for (const double offset : {1e6, 1e9}) {
      std::vector<Any> far;
      for (const Any& s : base) {
        far.push_back(std::visit(
            [&](auto x) -> Any {
              translate(x, V(offset, -0.5 * offset, 0.25 * offset));
              return x;
            },
            s));
      }
      check_sets(far, far, true, 0.3);
      check_nearest(far, far, 2);
    }
  }
  // Only bounded shapes, then only lines and rays.
  {
    const std::vector<Any> a = random_set(300, 8.0, 3, 6);
    check_sets(a, a, true, 0.2);
    const std::vector<Any> lines = random_set(40, 8.0, 1, 3);
    check_sets(lines, a, false, 0.1);
    check_sets(a, lines, false, 0.0);
    check_sets(lines, lines, true, 0.0);
    check_nearest(lines, a, 3);
    check_nearest(a, lines, 2);
  }
  // Duplicates: each shape four times.
  {
    std::vector<Any> a = random_set(60, 4.0, 0, 6), dup;
    for (int copy = 0; copy < 4; ++copy) dup.insert(dup.end(), a.begin(), a.end());
    check_sets(dup, dup, true, 0.0);
    check_sets(dup, a, false, 0.3);
    check_nearest(a, dup, 6);
    check_nearest(dup, dup, 6);  // four ties at distance 0 each: the k smallest (0, index) first
  }
  // Every shape at one spot: points (all pairs at distance 0), then mixed kinds.
  {
    std::vector<Any> points(200, Any(swept(V(1.5, -2, 0.25), 0.0)));
    check_sets(points, points, true, 0.0);
    const std::vector<Volume<double>> v = volumes_of(points);
    const BoundingVolumeHierarchy<double> tree(v);
    CHECK(candidate_pairs(tree, cull_limit(0.0, tree.scale())).size() == 200u * 199u / 2u);
    check_nearest(points, points, 7);
    std::vector<Any> spot;
    for (int i = 0; i < 120; ++i) spot.push_back(random_shape(V(1, 1, 1)));
    check_sets(spot, spot, true, 0.0);
    check_sets(spot, points, false, 0.0);
  }
  // Touching at d = 0: balls in contact, segments end to end, a point on a ring. Each pair is a
  // candidate, and the candidates are exactly those brute force keeps.
  {
    const std::vector<Any> a = {swept(V(0, 0, 0), 0.5), swept(Segment3<double>{V(3, 0, 0), V(4, 0, 0)}, 0.0),
                                swept(Circle3<double>{V(10, 0, 0), V(0, 0, 1), 2.0}, 0.0)};
    const std::vector<Any> b = {swept(V(1, 0, 0), 0.5), swept(Segment3<double>{V(4, 0, 0), V(5, 1, 0)}, 0.0),
                                swept(V(12, 0, 0), 0.0), swept(V(30, 0, 0), 0.0)};
    check_sets(a, b, false, 0.0);
    const std::vector<Volume<double>> va = volumes_of(a), vb = volumes_of(b);
    const BoundingVolumeHierarchy<double> tree(vb);
    const Pairs got = candidate_pairs(va, tree, cull_limit(0.0, std::max(tree.scale(), 12.0)));
    for (const auto& p : Pairs{{0, 0}, {1, 1}, {2, 2}}) CHECK(std::find(got.begin(), got.end(), p) != got.end());
    CHECK(std::none_of(got.begin(), got.end(), [](const auto& p) { return p.second == 3; }));
  }
  // Empty sets.
  {
    const std::vector<Any> none, some = random_set(10, 2.0);
    check_sets(none, some, false, 1.0);
    check_sets(some, none, false, 1.0);
    check_sets(none, none, true, 1.0);
    const BoundingVolumeHierarchy<double> empty{std::vector<Volume<double>>{}};
    CHECK(empty.nearest_by_bound(volumes_of(some)[0], 3).empty());
    CHECK(empty.scale() == 0);
  }
  // A tree built on several threads is the same tree: the same order, the same candidates.
  {
    const std::vector<Volume<double>> v = volumes_of(random_set(30000, 40.0, 3, 6));  // bounded: all in the tree
    const BoundingVolumeHierarchy<double> one(v, 4, 1), four(v, 4, 4), three(v, 8, 3);
    CHECK(one.order() == four.order());
    // The same volumes at the same positions (placed by slices on several threads).
    bool same_volumes = true;
    for (BroadIndex i = 0; i < one.size(); ++i) {
      const Volume<double>&x = one.volume(i), &y = four.volume(i);
      same_volumes = same_volumes && x.lo == y.lo && x.hi == y.hi && x.center == y.center && x.radius == y.radius;
    }
    CHECK(same_volumes);
    // The spatial order, keyed and sorted on several threads, is the one thread's.
    const std::vector<BroadIndex> order = spatial_order(v);
    for (const int threads : {2, 3, 4, 7}) CHECK(spatial_order(v, threads) == order);
    const double limit = cull_limit(0.3, one.scale());
    const Pairs expected = candidate_pairs(one, limit);
    CHECK(candidate_pairs(four, limit) == expected);
    CHECK(candidate_pairs(three, limit) == expected);
    CHECK(expected.size() > 1000);
  }
  // A growing hierarchy (batches of 1 to 150 shapes, lines among them, a query after each) answers
  // as one tree over every shape so far: the same shapes within a limit (with their bounds), the
  // same k nearest by bound, the same pairs once merged; it keeps at most log2(n) + 1 trees.
  {
    const std::vector<Volume<double>> v = volumes_of(random_set(3000, 25.0));
    const std::vector<Volume<double>> probes = volumes_of(random_set(40, 25.0));
    GrowingHierarchy<double> growing;
    BroadIndex added = 0, batches = 0;
    while (added < BroadIndex(v.size())) {
      const BroadIndex count =
          std::min<BroadIndex>(BroadIndex(v.size()) - added, batches % 9 == 8 ? 150 : 1 + batches % 3);
      growing.add(std::vector<Volume<double>>(v.begin() + added, v.begin() + added + count), 1 + int(batches % 3));
      added += count;
      ++batches;
      CHECK(growing.size() == added);
      CHECK(double(growing.trees()) <= std::log2(double(added)) + 1);
      if (batches % 5 != 0 && added < BroadIndex(v.size())) continue;
      const BoundingVolumeHierarchy<double> one(std::vector<Volume<double>>(v.begin(), v.begin() + added));
      CHECK(growing.scale() == one.scale());
      for (const Volume<double>& q : probes) {
        std::vector<std::pair<BroadIndex, double>> got, expected;
        const double limit = cull_limit(1.0, growing.scale());
        growing.visit_within(q, limit, [&](BroadIndex j, double bound) { got.emplace_back(j, bound); });
        one.visit_within(q, limit, [&](BroadIndex j, double bound) { expected.emplace_back(j, bound); });
        std::sort(got.begin(), got.end());
        std::sort(expected.begin(), expected.end());
        CHECK(got == expected);
        CHECK(growing.nearest_by_bound(q, 5) == one.nearest_by_bound(q, 5));
      }
    }
    CHECK(batches > 120);
    const double limit = cull_limit(0.3, growing.scale());
    const BoundingVolumeHierarchy<double> one(v);
    CHECK(candidate_pairs(growing.merged(2), limit) == candidate_pairs(one, limit));
    CHECK(growing.trees() == 1);
    GrowingHierarchy<double> empty;
    CHECK(empty.merged().size() == 0 && empty.nearest_by_bound(probes[0], 3).empty());
    empty.add(std::vector<Volume<double>>(v.begin(), v.begin() + 10));
    CHECK(empty.size() == 10 && empty.trees() == 1);
  }
  // Overflowed volumes are always candidates.
  {
    const Volume<double> huge = volume(Segment3<double>{V(-1e308, 0, 0), V(1e308, 0, 0)});
    CHECK(huge.kind == Volume<double>::Kind::Anywhere);
    CHECK(lower_bound(huge, volume(V(0, 5, 0))) == -INFINITY);
    const Volume<double> far_line = volume(Line3<double>{V(0, 0, 0), V(1e200, 1e200, 0)});
    CHECK_NEAR(lower_bound(far_line, volume(V(0, 1, 0))), std::sqrt(0.5), 1e-15);
  }
  CHECK(exercised > 20000);
  return check::finish("test_broadphase");
}

}  // namespace test_broadphase

CHECK_SUITE(test_broadphase);
