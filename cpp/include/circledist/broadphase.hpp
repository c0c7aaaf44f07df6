// A broadphase: which pairs of shapes can be within a distance d of each other, and which shapes
// can be nearest to a query, from bounding volumes alone (no query solved). Candidates are the
// pairs whose lower bound on the distance is at most d plus a margin; the exact test of each is
// the caller's (distance(), within(), ...).
//
// Each shape is summarized by a Volume:
//   - bounded shapes: a box and a ball (bounds.hpp's bounding_ball), both holding the shape grown
//     by its sweep. Two of them are at least max(box gap, |c_a - c_b| - r_a - r_b) apart;
//   - lines and rays (unbounded): the line piece and its sweep. Against a ball they are at least
//     the closed-form point-line distance to its center less the radii apart (bounds.hpp); two
//     of them are always candidates (no cheap bound is kept for them);
//   - shapes whose volume overflowed (coordinates near the largest double): always candidates.
// A lower bound that rounding made NaN is no bound: the pair stays a candidate.
//
// BoundingVolumeHierarchy holds the bounded shapes of a set in a binary tree, each node with a box
// and a ball holding those under it, built top down by median splits along the longest axis
// (O(n log n), any input: duplicates and shapes at one spot split by count); the unbounded ones
// are kept in a list every query visits. A node's bound never exceeds lower_bound() of a shape
// under it, so a query visits the shapes brute force over lower_bound() keeps (up to a tie with
// the limit that rounding decides differently: the margin covers such pairs anyway).
//
// Margin: the bounds are exact up to rounding (a few eps times the coordinates' size), and the
// exact distances the caller compares with d are accurate to about as much. Culling keeps every
// pair whose bound is within cull_limit(d, scale) = d + sqrt(eps) (d + 2 scale), scale the larger
// of the pair's two reaches from the origin (Volume::reach: the size of the coordinates the
// pair's bound and exact distance are computed from): every pair at distance <= d, as the
// caller's exact test computes it, is a candidate. The margin is the pair's own (a PairLimit), so
// a far or huge shape widens only its own pairs' margins, not every pair's: a tree node's limit
// is that of the largest reach under it, at least every shape's under it.
#pragma once

#include "bounds.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace circledist {

using BroadIndex = std::ptrdiff_t;

// What the broadphase knows of one shape (sweep included).
template <class Real> struct Volume {
  enum class Kind { Bounded, Unbounded, Anywhere };
  Kind kind = Kind::Anywhere;
  Vec3<Real> lo = Vec3<Real>::Constant(-std::numeric_limits<Real>::infinity());  // box (Bounded)
  Vec3<Real> hi = Vec3<Real>::Constant(std::numeric_limits<Real>::infinity());
  Vec3<Real> center = Vec3<Real>::Zero();  // ball (Bounded); the line's origin (Unbounded)
  Real radius = std::numeric_limits<Real>::infinity();
  Vec3<Real> direction = Vec3<Real>::Zero();  // Unbounded: the line piece origin + t direction,
  bool ray = false;                           // t >= 0 for a ray
  Real sweep = 0;                             // Unbounded: the tube's radius

  bool bounded() const { return kind == Kind::Bounded; }
  // How far from the origin the shape reaches (lines: their origin), for the culling margin.
  Real reach() const {
    if (kind == Kind::Unbounded) return center.norm() + sweep;
    return center.norm() + radius;
  }
  detail::Linear<Real> piece() const {
    const Real inf = std::numeric_limits<Real>::infinity();
    return {center, direction, ray ? Real(0) : -inf, inf};
  }
};

// A build stopped by its `interrupted` callback (BoundingVolumeHierarchy, GrowingHierarchy): the
// caller's signal to give up (a Ctrl-C). What was being built is dropped; nothing else changed.
struct BuildInterrupted : std::exception {
  const char* what() const noexcept override { return "circledist: the broadphase build was interrupted"; }
};

// A long build's way out: `interrupted` (empty: never) is asked at every large node of the tree
// (BoundingVolumeHierarchy::kStopCheck shapes or more: a few hundredths of a second of work
// apart), from whichever of the build's threads reaches it; once it answers true, every thread
// stops at its next node and the build throws BuildInterrupted.
using Interrupted = std::function<bool()>;

namespace detail {

struct Stop {
  const Interrupted& interrupted;
  std::atomic<bool> stopped{false};
  bool operator()() {
    if (stopped.load(std::memory_order_relaxed)) return true;
    if (interrupted && interrupted()) stopped.store(true, std::memory_order_relaxed);
    return stopped.load(std::memory_order_relaxed);
  }
};

// Runs work(begin, end) over up to `threads` contiguous slices of [0, size), side by side, the
// caller's thread taking the last; a slice is at least `smallest` long (a thread costs tens of
// microseconds). Where no thread can be had, the caller runs the slices left. `work` must not
// throw: it runs on threads that have no one to pass an exception to.
template <class Work> void run_in_slices(std::ptrdiff_t size, int threads, std::ptrdiff_t smallest, Work&& work) {
  const std::ptrdiff_t slices =
      std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(threads, size / std::max<std::ptrdiff_t>(smallest, 1)));
  const auto bound = [&](std::ptrdiff_t s) { return size * s / slices; };
  std::vector<std::thread> pool;
  std::ptrdiff_t s = 0;
  for (; s + 1 < slices; ++s) {
    try {
      pool.emplace_back([&work, begin = bound(s), end = bound(s + 1)] { work(begin, end); });
    } catch (const std::system_error&) {
      break;
    }
  }
  for (; s < slices; ++s) work(bound(s), bound(s + 1));
  for (std::thread& t : pool) t.join();
}

// Sorts v on up to `threads` threads: slices sorted side by side, then merged pairwise, the pairs
// of a round side by side. For elements no two of which compare equal (a total order, as pairs
// with distinct indices are), the result is std::sort's whatever the thread count.
template <class T> void sort_in_slices(std::vector<T>& v, int threads, std::ptrdiff_t smallest) {
  const std::ptrdiff_t size = std::ptrdiff_t(v.size());
  const std::ptrdiff_t slices =
      std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(threads, size / std::max<std::ptrdiff_t>(smallest, 1)));
  if (slices == 1) {
    std::sort(v.begin(), v.end());
    return;
  }
  std::vector<std::ptrdiff_t> bounds;
  for (std::ptrdiff_t s = 0; s <= slices; ++s) bounds.push_back(size * s / slices);
  run_in_slices(slices, int(slices), 1, [&](std::ptrdiff_t first, std::ptrdiff_t last) {
    for (std::ptrdiff_t s = first; s < last; ++s)
      std::sort(v.begin() + bounds[size_t(s)], v.begin() + bounds[size_t(s + 1)]);
  });
  std::vector<T> other(v.size());
  while (bounds.size() > 2) {
    // Runs 2r and 2r + 1 merge into run r of the next round; an odd last run is copied over.
    const std::ptrdiff_t runs = std::ptrdiff_t(bounds.size()) - 1, merges = (runs + 1) / 2;
    run_in_slices(merges, threads, 1, [&](std::ptrdiff_t first, std::ptrdiff_t last) {
      for (std::ptrdiff_t r = first; r < last; ++r) {
        const std::ptrdiff_t a = bounds[size_t(2 * r)], b = bounds[size_t(std::min(2 * r + 1, runs))],
                             c = bounds[size_t(std::min(2 * r + 2, runs))];
        std::merge(v.begin() + a, v.begin() + b, v.begin() + b, v.begin() + c, other.begin() + a);
      }
    });
    std::vector<std::ptrdiff_t> next;
    for (std::ptrdiff_t r = 0; r < runs; r += 2) next.push_back(bounds[size_t(r)]);
    next.push_back(size);
    bounds.swap(next);
    v.swap(other);
  }
}

template <class Real> bool finite_box(const Vec3<Real>& lo, const Vec3<Real>& hi) {
  return lo.allFinite() && hi.allFinite();
}

// A bounded shape's volume from its box and ball, grown by `sweep`; Anywhere when they overflowed.
template <class Real>
Volume<Real> bounded_volume(const Vec3<Real>& box_lo, const Vec3<Real>& box_hi, const Ball<Real>& ball, Real sweep) {
  Volume<Real> v;
  // Copies, not changed by-value parameters (cpp/tests/lto_aggregates.cpp).
  const Vec3<Real> lo = box_lo.array() - sweep, hi = box_hi.array() + sweep;
  const Real radius = ball.radius + sweep;
  if (!finite_box(lo, hi) || !ball.center.allFinite() || !std::isfinite(radius)) return v;
  v.kind = Volume<Real>::Kind::Bounded;
  // The ball's box may be tighter than the shape's own on some axis (a Bezier curve's hull).
  v.lo = lo.cwiseMax(Vec3<Real>(ball.center.array() - radius));
  v.hi = hi.cwiseMin(Vec3<Real>(ball.center.array() + radius));
  v.center = ball.center;
  v.radius = radius;
  return v;
}

template <class Real>
Volume<Real> line_volume(const Vec3<Real>& origin, const Vec3<Real>& direction, bool ray, Real sweep) {
  Volume<Real> v;
  if (!origin.allFinite() || !direction.allFinite() || !std::isfinite(sweep)) return v;
  v.kind = Volume<Real>::Kind::Unbounded;
  v.center = origin;
  // Of unit length: point_linear_distance squares the direction, which overflows for 1e200.
  v.direction = unit_vector(direction);
  v.ray = ray;
  v.sweep = sweep;
  return v;
}

}  // namespace detail

// The volume of a shape grown by `sweep` (the Swept overload passes its own).
template <class Real> Volume<Real> volume(const Vec3<Real>& p, Real sweep = 0) {
  return detail::bounded_volume<Real>(p, p, bounding_ball(p), sweep);
}
template <class Real> Volume<Real> volume(const Line3<Real>& l, Real sweep = 0) {
  return detail::line_volume<Real>(l.origin, l.direction, false, sweep);
}
template <class Real> Volume<Real> volume(const Ray3<Real>& r, Real sweep = 0) {
  return detail::line_volume<Real>(r.origin, r.direction, true, sweep);
}
template <class Real> Volume<Real> volume(const Segment3<Real>& s, Real sweep = 0) {
  return detail::bounded_volume<Real>(s.p0.cwiseMin(s.p1), s.p0.cwiseMax(s.p1), bounding_ball(s), sweep);
}
// A circle or disk (detail/round_target.hpp's targets): its box along axis k spans
// radius * sin(angle between the axis and the normal) = radius * sqrt(1 - n_k^2) on either side
// of the center.
template <class R, class = detail::target_t<R>> Volume<scalar_t<R>> volume(const R& round, scalar_t<R> sweep = 0) {
  using Real = scalar_t<R>;
  const Vec3<Real> n = unit_vector(round.normal);
  const Vec3<Real> reach = round.radius * (Vec3<Real>::Ones() - n.cwiseProduct(n)).cwiseMax(Real(0)).cwiseSqrt();
  return detail::bounded_volume<Real>(round.center - reach, round.center + reach, bounding_ball(round), sweep);
}
// The curve lies in its control points' convex hull, so in their box.
template <class Real> Volume<Real> volume(const BezierCurve3<Real>& b, Real sweep = 0) {
  if (b.control.cols() == 0) return {};
  const Vec3<Real> lo = b.control.rowwise().minCoeff(), hi = b.control.rowwise().maxCoeff();
  return detail::bounded_volume<Real>(lo, hi, bounding_ball(b), sweep);
}
// An arc: its box along each axis is arc_range's (bounds.hpp: the ends and the circle's extremes
// on the arc), not its whole circle's; the ball is bounding_ball's.
template <class Real> Volume<Real> volume(const Arc3<Real>& a, Real sweep = 0) {
  Vec3<Real> lo, hi;
  for (int k = 0; k < 3; ++k) {
    const Range<Real> r = arc_range(a, Vec3<Real>(Vec3<Real>::Unit(k)), a.center[k]);
    lo[k] = r.lo;
    hi[k] = r.hi;
  }
  return detail::bounded_volume<Real>(lo, hi, bounding_ball(a), sweep);
}
// An annulus: its outer disk's volume (the annulus lies in the disk; docs/derivations/annulus.md).
template <class Real> Volume<Real> volume(const Annulus3<Real>& a, Real sweep = 0) {
  return volume(detail::annulus_disk(a), sweep);
}
template <class S> Volume<scalar_t<S>> volume(const Swept<S>& s) { return volume(s.shape, s.sweep); }

// The gap between two boxes (0 when they overlap).
template <class Real>
Real box_gap(const Vec3<Real>& lo_a, const Vec3<Real>& hi_a, const Vec3<Real>& lo_b, const Vec3<Real>& hi_b) {
  return (lo_a - hi_b).cwiseMax(lo_b - hi_a).cwiseMax(Real(0)).norm();
}

// A lower bound on the distance between the shapes of two volumes; -inf when there is none.
template <class Real> Real lower_bound(const Volume<Real>& a, const Volume<Real>& b) {
  using Kind = typename Volume<Real>::Kind;
  const Real none = -std::numeric_limits<Real>::infinity();
  if (a.kind == Kind::Anywhere || b.kind == Kind::Anywhere) return none;
  if (a.bounded() && b.bounded()) {
    const Real bound = std::max(box_gap(a.lo, a.hi, b.lo, b.hi), (a.center - b.center).norm() - a.radius - b.radius);
    return bound == bound ? bound : none;
  }
  if (!a.bounded() && !b.bounded()) return none;  // two lines or rays: always candidates
  const Volume<Real>& line = a.bounded() ? b : a;
  const Volume<Real>& ball = a.bounded() ? a : b;
  const Real bound = point_linear_distance(ball.center, line.piece()) - ball.radius - line.sweep;
  return bound == bound ? bound : none;
}

// The limit bounds are culled against for pairs within d (see the header comment): `scale` is
// the larger of both sets' scale(), `relative` the margin per unit of size (sqrt(eps) by
// default; a caller whose exact test is less accurate, e.g. in float, passes its own).
template <class Real>
Real cull_limit(Real d, Real scale, Real relative = std::sqrt(std::numeric_limits<Real>::epsilon())) {
  return d + relative * (d + 2 * scale);
}

// The culling limit of each pair from its own reaches: cull_limit(d, max(reach_a, reach_b)).
// cull_limit grows with the scale (every step of it rounds monotonically), so the limit of a
// node (of the largest reach under it) is at least that of each shape under it.
template <class Real> struct PairLimit {
  Real d;
  Real relative = std::sqrt(std::numeric_limits<Real>::epsilon());
  Real operator()(Real reach_a, Real reach_b) const { return cull_limit(d, std::max(reach_a, reach_b), relative); }
};

namespace detail {
// The limit of a pair (or of a query and a node) of reaches a and b: a fixed limit (one for every
// pair, as a caller with a set-wide scale passes it) or a PairLimit's.
template <class Real> Real limit_of(Real fixed, Real, Real) { return fixed; }
template <class Real> Real limit_of(const PairLimit<Real>& limit, Real a, Real b) { return limit(a, b); }
}  // namespace detail

// The largest reach from the origin of the shapes of a set (0 for none; overflowed volumes,
// always candidates, do not count): the `scale` of cull_limit.
template <class Real> Real scale_of(const std::vector<Volume<Real>>& volumes) {
  Real scale = 0;
  for (const Volume<Real>& v : volumes)
    if (v.kind != Volume<Real>::Kind::Anywhere) scale = std::max(scale, v.reach());
  return scale;
}

template <class Real> class BoundingVolumeHierarchy {
 public:
  BoundingVolumeHierarchy() = default;

  // `leaf_size`: shapes per leaf at most. `threads`: how many threads build the tree's top
  // subtrees side by side (the tree is the same for any count). `interrupted`: see Interrupted
  // (BuildInterrupted is thrown when it stopped the build).
  explicit BoundingVolumeHierarchy(std::vector<Volume<Real>> volumes, int leaf_size = 4, int threads = 1,
                                   const Interrupted& interrupted = {})
      : volumes_(std::move(volumes)), leaf_size_(std::max(1, leaf_size)) {
    threads = std::max(1, threads);
    detail::Stop stop{interrupted};
    std::vector<BroadIndex> unbounded;
    index_.reserve(volumes_.size());
    for (BroadIndex i = 0; i < BroadIndex(volumes_.size()); ++i)
      (volumes_[size_t(i)].bounded() ? index_ : unbounded).push_back(i);
    scale_ = scale_of(volumes_);
    bounded_ = BroadIndex(index_.size());
    // The buffers the volumes are placed in below: with threads to spare, made on a thread of
    // their own while the tree is built (a large set's first touch of megabytes is a thread's
    // milliseconds of page faults).
    std::vector<Volume<Real>> placed;
    const auto make_buffers = [&] {
      placed.resize(volumes_.size());
      position_.resize(volumes_.size());
    };
    std::thread making;
    std::exception_ptr failure;
    if (threads > 1 && BroadIndex(volumes_.size()) >= kSliceSmallest) {
      try {
        making = std::thread([&] {
          try {
            make_buffers();
          } catch (...) {
            failure = std::current_exception();
          }
        });
      } catch (const std::system_error&) {  // no thread to be had: made after the tree
      }
    }
    if (bounded_ > 0) {
      try {
        nodes_.resize(size_t(node_count(bounded_)));
        build(0, bounded_, 0, threads, stop);
      } catch (...) {
        if (making.joinable()) making.join();
        throw;
      }
    }
    if (making.joinable())
      making.join();
    else if (!stop.stopped)
      make_buffers();
    if (failure) std::rethrow_exception(failure);
    if (stop.stopped) throw BuildInterrupted();
    // The volumes in the leaves' order, then the unbounded ones: a leaf's shapes lie side by side
    // in memory (queries read them in runs, not scattered over the whole set). Each position is
    // written once, so slices of them are placed side by side.
    index_.insert(index_.end(), unbounded.begin(), unbounded.end());
    detail::run_in_slices(BroadIndex(index_.size()), threads, kSliceSmallest, [&](BroadIndex begin, BroadIndex end) {
      for (BroadIndex k = begin; k < end; ++k) {
        placed[size_t(k)] = volumes_[size_t(index_[size_t(k)])];
        position_[size_t(index_[size_t(k)])] = k;
      }
    });
    volumes_ = std::move(placed);
  }

  BroadIndex size() const { return BroadIndex(volumes_.size()); }
  const Volume<Real>& volume(BroadIndex i) const { return volumes_[size_t(position_[size_t(i)])]; }
  // The shapes' indices in a spatially coherent order (the leaves', then lines and rays): queries
  // asked in this order find the tree's nodes in cache.
  const std::vector<BroadIndex>& order() const { return index_; }
  // The largest reach from the origin of a shape of the set (0 for an empty set): for cull_limit.
  Real scale() const { return scale_; }

  // Calls visit(j, bound) for every shape j whose lower bound to q is <= limit (or unknown), the
  // tree's shapes first, in no particular order. `limit`: a Real (every pair's), or a
  // PairLimit<Real> (each pair's from the reaches of q and of shape j; a node's from its largest).
  // `below`: only the shapes j < below (a subtree whose least index is not below it is skipped
  // whole).
  template <class Limit, class Visit>
  void visit_within(const Volume<Real>& q, const Limit& limit, Visit&& visit,
                    BroadIndex below = std::numeric_limits<BroadIndex>::max()) const {
    const Real reach = q.reach();
    if (!nodes_.empty()) {
      // Depth first, on a stack of fixed size: a median split halves the count, so the depth is
      // below 64 and the stack holds at most one pending sibling per level.
      BroadIndex stack[2 * 64];
      int top = 0;
      stack[top++] = 0;
      while (top > 0) {
        const BroadIndex at = stack[--top];
        const Node& node = nodes_[size_t(at)];
        if (node.least >= below || !node_within(q, node, detail::limit_of(limit, reach, node.reach))) continue;
        if (node.count > 0) {
          for (BroadIndex k = node.first; k < node.first + node.count; ++k) {
            if (index_[size_t(k)] >= below) continue;
            const Volume<Real>& v = volumes_[size_t(k)];
            const Real bound = lower_bound(q, v);
            if (!(bound > detail::limit_of(limit, reach, v.reach()))) visit(index_[size_t(k)], bound);
          }
        } else {
          stack[top++] = node.right;
          stack[top++] = at + 1;
        }
      }
    }
    for (BroadIndex k = bounded_; k < size(); ++k) {
      if (index_[size_t(k)] >= below) continue;
      const Volume<Real>& v = volumes_[size_t(k)];
      const Real bound = lower_bound(q, v);
      if (!(bound > detail::limit_of(limit, reach, v.reach()))) visit(index_[size_t(k)], bound);
    }
  }

  // The k shapes of smallest lower bound to q (fewer when the set holds fewer), sorted by bound,
  // then index (unknown bounds count as -inf). An upper bound on the k-th smallest distance is
  // then the largest of their exact distances: every shape the caller must test is within it.
  std::vector<std::pair<Real, BroadIndex>> nearest_by_bound(const Volume<Real>& q, BroadIndex k) const {
    using Entry = std::pair<Real, BroadIndex>;
    std::vector<Entry> best;  // a max-heap of the k best (bound, index)
    if (k <= 0) return best;
    const auto offer = [&](BroadIndex position) {
      Real bound = lower_bound(q, volumes_[size_t(position)]);
      if (bound != bound) bound = -std::numeric_limits<Real>::infinity();
      const Entry e{bound, index_[size_t(position)]};
      if (BroadIndex(best.size()) < k) {
        best.push_back(e);
        std::push_heap(best.begin(), best.end());
      } else if (e < best.front()) {
        std::pop_heap(best.begin(), best.end());
        best.back() = e;
        std::push_heap(best.begin(), best.end());
      }
    };
    for (BroadIndex p = bounded_; p < size(); ++p) offer(p);
    if (!nodes_.empty()) {
      // Best first: nodes by (lower bound, least index under them), the order of the entries
      // themselves, stopping at the first node that cannot hold an entry before the k-th: every
      // entry under a node is at least (its bound, its least index). Ties of the bound (shapes
      // that coincide) are cut by the index, so a query among n coincident shapes visits
      // O(k log n) nodes, not n.
      struct NodeEntry {
        Real bound;
        BroadIndex least, at;
        bool operator>(const NodeEntry& o) const { return bound > o.bound || (bound == o.bound && least > o.least); }
      };
      std::priority_queue<NodeEntry, std::vector<NodeEntry>, std::greater<NodeEntry>> open;
      const auto push = [&](BroadIndex at) {
        open.push({node_bound(q, nodes_[size_t(at)]), nodes_[size_t(at)].least, at});
      };
      push(0);
      while (!open.empty()) {
        const NodeEntry top = open.top();
        open.pop();
        if (BroadIndex(best.size()) == k && !(Entry{top.bound, top.least} < best.front())) break;
        const Node& node = nodes_[size_t(top.at)];
        if (node.count > 0) {
          for (BroadIndex p = node.first; p < node.first + node.count; ++p) offer(p);
        } else {
          push(top.at + 1);
          push(node.right);
        }
      }
    }
    std::sort(best.begin(), best.end());
    return best;
  }

 private:
  struct Node {
    Vec3<Real> lo, hi;  // the box of the boxes under the node
    Vec3<Real> center;  // a ball holding the balls under the node
    Real radius = 0;
    Real reach = 0;                   // the largest Volume::reach under the node (for a PairLimit)
    BroadIndex first = 0, count = 0;  // a leaf: the shapes at positions [first, first + count)
    BroadIndex right = 0;             // an inner node: its children are the next node and `right`
    BroadIndex least = 0;             // the least index of a shape under the node
  };

  std::vector<Volume<Real>> volumes_;  // by position: the bounded shapes in the leaves' order, then
                                       // lines, rays and overflowed volumes
  std::vector<BroadIndex> index_;      // the shape at each position
  std::vector<BroadIndex> position_;   // the position of each shape
  BroadIndex bounded_ = 0;             // positions [0, bounded_) are in the tree
  std::vector<Node> nodes_;            // depth first: a node's left child follows it
  int leaf_size_ = 4;
  // The fewest shapes worth a thread of their own in a loop over them (a thread costs tens of
  // microseconds, a shape a few nanoseconds).
  static constexpr BroadIndex kSliceSmallest = 8192;
  Real scale_ = 0;

  // A lower bound on the distance from q to the shapes under a node, from the node's box and
  // ball, which hold every box and ball under it: never above lower_bound(q, v) for a volume v
  // under the node (so the tree visits exactly the shapes brute force over lower_bound keeps).
  Real node_bound(const Volume<Real>& q, const Node& node) const {
    const Real none = -std::numeric_limits<Real>::infinity();
    if (q.kind == Volume<Real>::Kind::Anywhere) return none;
    Real bound;
    if (q.bounded()) {
      bound = std::max(box_gap(q.lo, q.hi, node.lo, node.hi), (q.center - node.center).norm() - node.radius - q.radius);
    } else {
      bound = point_linear_distance(node.center, q.piece()) - node.radius - q.sweep;
    }
    return bound == bound ? bound : none;
  }

  // Whether node_bound(q, node) <= limit (or unknown), deciding on the boxes' squared gap first:
  // no square root for most of the nodes a query skips.
  bool node_within(const Volume<Real>& q, const Node& node, Real limit) const {
    if (q.bounded()) {
      const Real gap2 = (q.lo - node.hi).cwiseMax(node.lo - q.hi).cwiseMax(Real(0)).squaredNorm();
      if (gap2 > limit * limit) return false;
    }
    return !(node_bound(q, node) > limit);
  }

  // The nodes of a subtree over m shapes: median splits make it a function of m alone, so every
  // subtree's place in nodes_ is known before it is built (and subtrees can be built apart).
  // Memoized: the sizes at one depth take at most three values.
  BroadIndex node_count(BroadIndex m) const {
    std::map<BroadIndex, BroadIndex> memo;
    return node_count(m, memo);
  }
  BroadIndex node_count(BroadIndex m, std::map<BroadIndex, BroadIndex>& memo) const {
    if (m <= leaf_size_) return 1;
    const auto known = memo.find(m);
    if (known != memo.end()) return known->second;
    const BroadIndex count = 1 + node_count(m / 2, memo) + node_count(m - m / 2, memo);
    memo.emplace(m, count);
    return count;
  }

  // The box of the boxes (lo, hi) and the box of the balls' centers (clo, chi: where to split) of
  // the shapes at positions [first, last).
  struct Extent {
    Vec3<Real> lo = Vec3<Real>::Constant(std::numeric_limits<Real>::infinity()), hi = -lo, clo = lo, chi = hi;
    Real reach = 0;  // the largest Volume::reach
    void add(const Extent& e) {
      lo = lo.cwiseMin(e.lo), hi = hi.cwiseMax(e.hi), clo = clo.cwiseMin(e.clo), chi = chi.cwiseMax(e.chi);
      reach = std::max(reach, e.reach);
    }
  };
  Extent extent(BroadIndex first, BroadIndex last) const {
    Extent e;
    for (BroadIndex k = first; k < last; ++k) {
      const Volume<Real>& v = volumes_[size_t(index_[size_t(k)])];
      e.lo = e.lo.cwiseMin(v.lo);
      e.hi = e.hi.cwiseMax(v.hi);
      e.clo = e.clo.cwiseMin(v.center);
      e.chi = e.chi.cwiseMax(v.center);
      e.reach = std::max(e.reach, v.reach());
    }
    return e;
  }
  // How far the balls of the shapes at positions [first, last) reach from `center`.
  Real reach(BroadIndex first, BroadIndex last, const Vec3<Real>& center) const {
    Real radius = 0;
    for (BroadIndex k = first; k < last; ++k) {
      const Volume<Real>& v = volumes_[size_t(index_[size_t(k)])];
      radius = std::max(radius, (v.center - center).norm() + v.radius);
    }
    return radius;
  }

  // The fewest shapes under a node at which the build asks whether it is interrupted.
  static constexpr BroadIndex kStopCheck = 4096;

  // Builds the subtree of the shapes at positions [first, last) into nodes_[at, ...).
  void build(BroadIndex first, BroadIndex last, BroadIndex at, int threads, detail::Stop& stop) {
    if (last - first >= kStopCheck && stop()) return;
    Extent e;
    Real radius = 0;
    // The ball: around the box's center, out to the farthest ball under the node, rounded up a
    // few ulps (below) so that the rounding of the radius does not make the node's bound exceed a
    // shape's.
    Vec3<Real> center;
    if (threads > 1 && last - first >= 2 * kSliceSmallest) {
      // The top of the tree, with threads to spare: minima and maxima are the same numbers in any
      // grouping, so slices of the shapes are taken side by side.
      const int slices = int(std::min<BroadIndex>(threads, (last - first) / kSliceSmallest));
      const auto bound = [&](BroadIndex s) { return first + (last - first) * s / slices; };
      std::vector<Extent> parts(static_cast<size_t>(slices));
      detail::run_in_slices(slices, slices, 1, [&](BroadIndex s0, BroadIndex s1) {
        for (BroadIndex s = s0; s < s1; ++s) parts[size_t(s)] = extent(bound(s), bound(s + 1));
      });
      for (const Extent& part : parts) e.add(part);
      center = (e.lo + e.hi) / 2;
      std::vector<Real> radii(static_cast<size_t>(slices));
      detail::run_in_slices(slices, slices, 1, [&](BroadIndex s0, BroadIndex s1) {
        for (BroadIndex s = s0; s < s1; ++s) radii[size_t(s)] = reach(bound(s), bound(s + 1), center);
      });
      radius = *std::max_element(radii.begin(), radii.end());
    } else {
      e = extent(first, last);
      center = (e.lo + e.hi) / 2;
      radius = reach(first, last, center);
    }
    radius *= 1 + 8 * std::numeric_limits<Real>::epsilon();
    Node& node = nodes_[size_t(at)];
    node.lo = e.lo;
    node.hi = e.hi;
    node.center = center;
    node.radius = radius;
    node.reach = e.reach;
    if (last - first <= leaf_size_) {
      node.first = first;
      node.count = last - first;
      node.least = *std::min_element(index_.begin() + first, index_.begin() + last);
      return;
    }
    int axis;
    (e.chi - e.clo).maxCoeff(&axis);
    const BroadIndex middle = first + (last - first) / 2;
    // Ties broken by index: the tree (and every traversal) is the same on every platform.
    std::nth_element(index_.begin() + first, index_.begin() + middle, index_.begin() + last,
                     [&](BroadIndex x, BroadIndex y) {
                       const Real cx = volumes_[size_t(x)].center[axis], cy = volumes_[size_t(y)].center[axis];
                       return cx < cy || (cx == cy && x < y);
                     });
    node.right = at + 1 + node_count(middle - first);
    // The two subtrees touch disjoint positions and nodes: with threads to spare, the left one is
    // built on a thread of its own (a large one only: a thread costs tens of microseconds).
    if (threads > 1 && last - first > 4096) {
      std::thread left;
      try {
        left = std::thread([&] { build(first, middle, at + 1, threads / 2, stop); });
      } catch (const std::system_error&) {  // no thread to be had: this one builds both
        build(first, middle, at + 1, 1, stop);
      }
      build(middle, last, node.right, threads - threads / 2, stop);
      if (left.joinable()) left.join();
    } else {
      build(first, middle, at + 1, 1, stop);
      build(middle, last, node.right, 1, stop);
    }
    node.least = std::min(nodes_[size_t(at + 1)].least, nodes_[size_t(node.right)].least);
  }
};

// A hierarchy that grows: shapes come in batches, numbered on from the ones before, with queries
// between the batches (a scene's adds). One tree rebuilt for every batch would cost O(n) per
// batch; here the shapes live in a few trees over consecutive numbers, each at least twice the
// size of the next newer one (the logarithmic method, Bentley and Saxe 1980): a batch is built
// into one tree together with the newer trees smaller than twice it, so a shape's tree grows at
// least 1.5-fold each time it is rebuilt (O(log n) rebuilds of a shape: O(n log^2 n) in all
// however the n shapes come), and a query searches at most log2(n) + 1 trees. Its answers are
// those of one tree over every shape: each tree's are brute force's over lower_bound().
template <class Real> class GrowingHierarchy {
 public:
  using Tree = BoundingVolumeHierarchy<Real>;

  // Adds shapes, numbered size(), size() + 1, ...; `threads` build the new tree (as
  // BoundingVolumeHierarchy's: the trees are the same for any count). When the build throws
  // (BuildInterrupted, bad_alloc), the hierarchy is as it was.
  void add(std::vector<Volume<Real>> volumes, int threads = 1, const Interrupted& interrupted = {}) {
    if (volumes.empty()) return;
    BroadIndex taken = 0;
    size_t keep = trees_.size();
    while (keep > 0 && trees_[keep - 1].size() < 2 * (BroadIndex(volumes.size()) + taken))
      taken += trees_[--keep].size();
    if (taken > 0) {
      std::vector<Volume<Real>> all;
      all.reserve(size_t(taken) + volumes.size());
      for (size_t t = keep; t < trees_.size(); ++t)
        for (BroadIndex i = 0; i < trees_[t].size(); ++i) all.push_back(trees_[t].volume(i));
      all.insert(all.end(), volumes.begin(), volumes.end());
      volumes.swap(all);
    }
    const BroadIndex added = BroadIndex(volumes.size()) - taken;
    Tree tree(std::move(volumes), kLeafSize, threads, interrupted);
    trees_.resize(keep);
    first_.resize(keep);
    first_.push_back(size_ - taken);
    size_ += added;
    trees_.push_back(std::move(tree));
    scale_ = std::max(scale_, trees_.back().scale());
  }

  BroadIndex size() const { return size_; }
  // The volume of shape i (i in [0, size())).
  const Volume<Real>& volume(BroadIndex i) const {
    const size_t t = size_t(std::upper_bound(first_.begin(), first_.end(), i) - first_.begin()) - 1;
    return trees_[t].volume(i - first_[t]);
  }
  // The largest reach from the origin of a shape of the set: for cull_limit.
  Real scale() const { return scale_; }
  size_t trees() const { return trees_.size(); }

  // One tree over every shape, the trees merged first if there are several: for queries over the
  // whole set (its pairs), which cost O(n) anyway. When the build throws, the trees stay as
  // they were.
  const Tree& merged(int threads = 1, const Interrupted& interrupted = {}) {
    if (trees_.size() != 1) {
      std::vector<Volume<Real>> all;
      all.reserve(size_t(size_));
      for (const Tree& t : trees_)
        for (BroadIndex i = 0; i < t.size(); ++i) all.push_back(t.volume(i));
      Tree tree(std::move(all), kLeafSize, threads, interrupted);
      trees_.clear();
      first_.assign(1, 0);
      trees_.push_back(std::move(tree));
    }
    return trees_.front();
  }

  // BoundingVolumeHierarchy's visit_within over every tree.
  template <class Limit, class Visit>
  void visit_within(const Volume<Real>& q, const Limit& limit, Visit&& visit) const {
    for (size_t t = 0; t < trees_.size(); ++t)
      trees_[t].visit_within(q, limit, [&, first = first_[t]](BroadIndex j, Real bound) { visit(first + j, bound); });
  }

  // BoundingVolumeHierarchy's nearest_by_bound: the k smallest (bound, index) of every tree's k.
  std::vector<std::pair<Real, BroadIndex>> nearest_by_bound(const Volume<Real>& q, BroadIndex k) const {
    std::vector<std::pair<Real, BroadIndex>> best;
    for (size_t t = 0; t < trees_.size(); ++t)
      for (const auto& [bound, j] : trees_[t].nearest_by_bound(q, k)) best.emplace_back(bound, first_[t] + j);
    std::sort(best.begin(), best.end());
    if (BroadIndex(best.size()) > k) best.resize(size_t(std::max<BroadIndex>(k, 0)));
    return best;
  }

 private:
  static constexpr int kLeafSize = 4;
  std::vector<Tree> trees_;        // oldest first
  std::vector<BroadIndex> first_;  // the number of each tree's first shape
  BroadIndex size_ = 0;
  Real scale_ = 0;
};

using BroadPairs = std::vector<std::pair<BroadIndex, BroadIndex>>;

// The order of a Z-order (Morton) curve through the volumes' centers, the unbounded ones last:
// queries asked in this order visit the tree's nodes while they are still in cache (twice as fast
// as random order on 10^5 shapes).
// `threads`: how many threads compute the keys and sort them (the order is the same for any
// count: no two keys are equal, each carries its index).
template <class Real> std::vector<BroadIndex> spatial_order(const std::vector<Volume<Real>>& volumes, int threads = 1) {
  Vec3<Real> lo = Vec3<Real>::Constant(std::numeric_limits<Real>::infinity()), hi = -lo;
  for (const Volume<Real>& v : volumes)
    if (v.bounded()) lo = lo.cwiseMin(v.center), hi = hi.cwiseMax(v.center);
  const Vec3<Real> span = (hi - lo).cwiseMax(std::numeric_limits<Real>::min());
  const auto spread = [](std::uint64_t x) {  // 21 bits to every third of 63
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffull;
    x = (x | x << 16) & 0x1f0000ff0000ffull;
    x = (x | x << 8) & 0x100f00f00f00f00full;
    x = (x | x << 4) & 0x10c30c30c30c30c3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
  };
  constexpr BroadIndex smallest = 8192;  // keys worth a thread of their own
  const BroadIndex n = BroadIndex(volumes.size());
  std::vector<std::pair<std::uint64_t, BroadIndex>> keys(volumes.size());
  detail::run_in_slices(n, threads, smallest, [&](BroadIndex begin, BroadIndex end) {
    for (BroadIndex i = begin; i < end; ++i) {
      const Volume<Real>& v = volumes[size_t(i)];
      std::uint64_t key = ~std::uint64_t(0);  // unbounded: last
      if (v.bounded()) {
        key = 0;
        for (int a = 0; a < 3; ++a) {
          const Real t = std::min(std::max((v.center[a] - lo[a]) / span[a], Real(0)), Real(1));
          key |= spread(std::uint64_t(t * Real(0x1fffff))) << a;
        }
      }
      keys[size_t(i)] = {key, i};
    }
  });
  detail::sort_in_slices(keys, threads, smallest);
  std::vector<BroadIndex> out(volumes.size());
  detail::run_in_slices(n, threads, smallest, [&](BroadIndex begin, BroadIndex end) {
    for (BroadIndex i = begin; i < end; ++i) out[size_t(i)] = keys[size_t(i)].second;
  });
  return out;
}

// Sorts pairs by (first, second), every first in [0, n): a counting sort on the first index, then
// each run by the second (O(m + n) and short runs).
inline void sort_pairs(BroadPairs& pairs, BroadIndex n) {
  std::vector<size_t> start(size_t(n) + 1, 0);
  for (const auto& p : pairs) ++start[size_t(p.first) + 1];
  for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  BroadPairs out(pairs.size());
  std::vector<size_t> at(start.begin(), start.end() - 1);
  for (const auto& p : pairs) out[at[size_t(p.first)]++] = p;
  for (size_t i = 0; i + 1 < start.size(); ++i)
    if (start[i + 1] - start[i] > 1)
      std::sort(out.begin() + std::ptrdiff_t(start[i]), out.begin() + std::ptrdiff_t(start[i + 1]));
  pairs.swap(out);
}

// Candidate pairs (i, j), i of `queries` and j of `tree`, whose lower bound is <= limit, for the
// queries i = order[k], k in [begin, end) (order: e.g. spatial_order(queries)), appended to `out`
// unsorted. Threads split [0, queries.size()) and sort_pairs joins their parts.
template <class Real, class Limit> void candidate_pairs(const std::vector<Volume<Real>>& queries,
                                                        const std::vector<BroadIndex>& order,
                                                        const BoundingVolumeHierarchy<Real>& tree, const Limit& limit,
                                                        BroadIndex begin, BroadIndex end, BroadPairs& out) {
  for (BroadIndex k = begin; k < end; ++k) {
    const BroadIndex i = order[size_t(k)];
    tree.visit_within(queries[size_t(i)], limit, [&](BroadIndex j, Real) { out.emplace_back(i, j); });
  }
}

// Candidate pairs i < j within the tree's own set, for the shapes i = tree.order()[k], k in
// [begin, end) (each pair is found from both ends and kept from the one of smaller index),
// appended to `out` unsorted.
template <class Real, class Limit> void candidate_pairs(const BoundingVolumeHierarchy<Real>& tree, const Limit& limit,
                                                        BroadIndex begin, BroadIndex end, BroadPairs& out) {
  for (BroadIndex k = begin; k < end; ++k) {
    const BroadIndex i = tree.order()[size_t(k)];
    tree.visit_within(tree.volume(i), limit, [&](BroadIndex j, Real) {
      if (j > i) out.emplace_back(i, j);
    });
  }
}

// Every candidate pair between two sets, sorted by (i, j) (one thread).
template <class Real, class Limit> BroadPairs candidate_pairs(const std::vector<Volume<Real>>& queries,
                                                              const BoundingVolumeHierarchy<Real>& tree,
                                                              const Limit& limit) {
  BroadPairs out;
  candidate_pairs(queries, spatial_order(queries), tree, limit, 0, BroadIndex(queries.size()), out);
  sort_pairs(out, BroadIndex(queries.size()));
  return out;
}

// Every candidate pair i < j within one set, sorted (one thread).
template <class Real, class Limit>
BroadPairs candidate_pairs(const BoundingVolumeHierarchy<Real>& tree, const Limit& limit) {
  BroadPairs out;
  candidate_pairs(tree, limit, 0, tree.size(), out);
  sort_pairs(out, tree.size());
  return out;
}

}  // namespace circledist
