// The reductions every annulus pair is answered by (the pair headers point_annulus.hpp ...
// annulus_annulus.hpp register them): each composes the disk's, the circle's, the arc's and the
// curve's own queries, so it lives beside the pairs, not in detail/. Derivation:
// docs/derivations/annulus.md.
//
// Annulus: an annulus against a point, line, ray,
// segment, circle, disk, arc, Bezier curve or annulus, from the disk's, the circle's, the arc's
// and the curve's queries.
//
// The annulus A is the outer disk D minus the open hole of its inner circle K. Its distance from
// a point is the disk's where the point's projection falls in the ring, else the inner circle's
// (docs/derivations/annulus.md, "A point"). Every query here is one of these reductions:
//  - a convex shape X (point, line, ray, segment, disk): the distance to X is convex over the
//    plane, so A's closest point is D's when D's lies in the ring (s >= inner), and otherwise
//    on K (docs/derivations/annulus.md, "Convex shapes"): the disk query, then the inner circle's only where
//    the disk's point fell in the hole;
//  - a circle, an arc or a Bezier curve (not convex): the least of the interior candidates
//    (circle-disk's or bezier-disk's height candidates, z = 0 or z' = 0, on the arc's angles and
//    with its ends for an arc, with its ends for a curve, kept where their projection lies in the
//    ring) and the shape against both rims (circle-circle, arc-circle, bezier-circle)
//    (docs/derivations/annulus.md, "A circle", "An arc", "A Bezier curve");
//  - an annulus against an annulus: the outer disks' closest pair where it lies in both rings,
//    else the least of each rim against the other annulus (the circle reduction), since a
//    closest pair has a point on a rim, and a common part has its ends on rims
//    (docs/derivations/annulus.md, "Two annuli").
// An inner radius of 0 (or less) is the disk, an inner radius equal to the outer one the circle:
// their own queries answer, to the bit (the annulus's parameter (s, theta) being the disk's, or
// (R, theta) for the circle's (theta, 0)).
#pragma once

#include "arc_arc.hpp"
#include "bezier_circle.hpp"
#include "bezier_disk.hpp"
#include "circle_arc.hpp"
#include "circle_circle.hpp"
#include "circle_disk.hpp"
#include "detail/annulus.hpp"
#include "disk_arc.hpp"
#include "disk_disk.hpp"
#include "linear_arc.hpp"
#include "linear_circle.hpp"
#include "linear_disk.hpp"
#include "linear_linear.hpp"
#include "point_arc.hpp"
#include "point_circle.hpp"
#include "point_disk.hpp"
#include "point_linear.hpp"
#include "point_point.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// distance(disk, disk) does, so the answers are the disk's to the bit.)
template <class Roots, class X, class Real>
Real degenerate_distance(const X& x, const Annulus3<Real>& a, AnnulusKind kind) {
  if (kind == AnnulusKind::kDisk) return circledist::distance<Roots>(x, annulus_disk(a));
  if (kind == AnnulusKind::kCircle) return circledist::distance<Roots>(x, outer_rim(a));
  return degenerate_annulus_result<Real>(kind).distance;
}
template <class Roots, class X, class Real>
Result<Real> degenerate_closest(const X& x, const Annulus3<Real>& a, AnnulusKind kind) {
  if (kind == AnnulusKind::kDisk) return circledist::closest_points<Roots>(x, annulus_disk(a));
  if (kind == AnnulusKind::kCircle)
    return rim_as_annulus(circledist::closest_points<Roots>(x, outer_rim(a)), a.outer_radius);
  return degenerate_annulus_result<Real>(kind);
}

// The length scale of a query against the annulus (tolerances follow it).
template <class Real> Real annulus_scale(const Vec3<Real>& other_point, const Annulus3<Real>& a) {
  const Real s = std::max(a.outer_radius, (other_point - a.center).norm());
  return s > 0 && std::isfinite(s) ? s : Real(1);
}

// Convex shapes (docs/derivations/annulus.md, "Convex shapes"). The disk's closest pair, kept when its
// point on the disk lies in the ring (s >= inner: s is the disk's parameter); otherwise the
// inner circle's, which is then the annulus's. When the disk's closest pairs were a continuum
// (not unique) reaching from the hole across the inner circle, the inner circle may meet it in one
// point while the annulus keeps a stretch of it: the continuum is followed a distinct-points
// tolerance past the inner circle's point, away from the disk's, and `unique` is false when that
// point is still as close to x (within the tie tolerance and its own coordinates' rounding) and
// on the annulus.
template <class Roots, class X, class Real> Result<Real> convex_annulus_closest(const X& x, const Annulus3<Real>& a) {
  const Result<Real> on_disk = circledist::closest_points<Roots>(x, annulus_disk(a));
  if (!(on_disk.param_b.x() < a.inner_radius)) return on_disk;  // in the ring (or NaN)
  Result<Real> r = rim_as_annulus(circledist::closest_points<Roots>(x, inner_rim(a)), a.inner_radius);
  if (r.unique && !on_disk.unique) {
    const Real scale = annulus_scale(r.point_a, a);
    const Vec3<Real> step = r.point_b - on_disk.point_b;
    const Real length = step.norm();
    if (length > 0) {
      const Vec3<Real> beyond = r.point_b + (distinct_points_tolerance(scale) / length) * step;
      const Real rho = (beyond - a.center).norm();
      const Real to_x = circledist::distance<Roots>(beyond, x);
      // The tie tolerance, and the rounding of `beyond`'s world coordinates (1.5e-8 at 1e8).
      const Real slack = tie_tolerance(std::max(scale, r.distance)) +
                         16 * std::numeric_limits<Real>::epsilon() * beyond.cwiseAbs().maxCoeff();
      if (rho <= a.outer_radius && to_x <= r.distance + slack) r.unique = false;
    }
  }
  return r;
}

// The annulus's distance from a point: the disk's over the ring and beyond, the inner circle's
// over the hole (detail/point_over_round.hpp, PointRingQuery: the same numbers as the disk's and
// the circle's closed forms, and closest() takes them too, so the two agree to the bit).
template <class Real> Real point_annulus_distance(const Vec3<Real>& p, const Annulus3<Real>& a) {
  return PointRingQuery<Real>::distance(p, a.center, a.normal, a.inner_radius, a.outer_radius);
}

// A circle against a true ring (docs/derivations/annulus.md, "A circle"): the candidates and the best. Each
// candidate is a Result (a's side the circle, b's the annulus).
template <class Real> struct CircleAnnulusCandidates {
  static constexpr int kCapacity = 16;
  Result<Real> item[kCapacity];
  int count = 0;
  int best = -1;
  void add(const Result<Real>& r) {
    if (count == kCapacity) return;
    item[count] = r;
    if (best < 0 || r.distance < item[best].distance) best = count;
    ++count;
  }
};

// The interior candidates: the circle's points where its height over the plane has z = 0 or
// z' = 0 (and t = 0, pi), circle-disk's height candidates (circle_disk.hpp), kept where their
// projection lies in the ring; there the annulus distance is |z| to the point below. Returns
// the verdict of circle-disk's shortcut (docs/derivations/annulus.md, "A circle"): the lowest |z| over the
// whole circle is at one of these candidates, and no annulus point is nearer to X(t) than
// |z(t)|; so when the best kept candidate is that low, it is the distance and the rims need not
// be solved.
template <class Real> struct InteriorVerdict {
  Real best = std::numeric_limits<Real>::infinity();
  bool decided = false;
};
// The interior candidates kept in the ring, a circle's, an arc's or a curve's (docs/derivations/annulus.md,
// "A circle", "A Bezier curve"): each candidate parameter x, its local point `local_at(x)` in the
// annulus's frame, kept where its projection lies in the ring, at the distance |z| to the point
// below (`side_a(x, r)` fills the shape's point and parameter); and the verdict (above), the
// lowest |z| taken over every candidate.
template <class Real, int N, class Add, class LocalAt, class SideA>
InteriorVerdict<Real> interior_in_ring(const Candidates<Real, N>& heights, const Annulus3<Real>& a,
                                       const Round<Real>& round, Real scale, bool with_points, const Add& add,
                                       const LocalAt& local_at, const SideA& side_a) {
  InteriorVerdict<Real> verdict;
  Real lowest = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < heights.count; ++i) {
    const Vec3<Real> p = local_at(heights.value[i]);
    lowest = std::min(lowest, std::abs(p.z()));
    const Real rho = length2d(p.x(), p.y());
    if (!(rho >= a.inner_radius && rho <= a.outer_radius)) continue;
    Result<Real> r;
    r.distance = std::abs(p.z());
    verdict.best = std::min(verdict.best, r.distance);
    if (with_points) {
      const Vec3<Real> below(p.x(), p.y(), 0);
      side_a(heights.value[i], r);
      r.point_b = round.world(below);
      r.param_b = DiskTarget<Real>::param(below);
    }
    add(r);
  }
  verdict.decided = verdict.best <= lowest + tie_tolerance(scale);
  return verdict;
}

// An arc (ArcSpan, detail/arc_span.hpp) takes the candidates on its angles only, and its two ends.
template <class Roots, class Real, class Add>
InteriorVerdict<Real> circle_annulus_interior(const Circle3<Real>& c, const Annulus3<Real>& a, bool with_points,
                                              const Add& add, const ArcSpan<Real>* span = nullptr) {
  using CircleDisk = Query<Circle3<Real>, Disk3<Real>>;
  const Round<Real> round(a.center, a.normal, a.outer_radius);
  const LocalCircle<Real> local(c, round);
  const Real scale = circle_round_scale(local, a.outer_radius);
  auto heights = CircleDisk::template height_candidates<Roots>(local, scale);
  if (span) {
    int kept = 0;
    for (int i = 0; i < heights.count; ++i)
      if (span->holds(heights.value[i])) heights.value[kept++] = heights.value[i];
    heights.count = kept;
    heights.push(span->lo());
    heights.push(span->hi());
  }
  return interior_in_ring(
      heights, a, round, scale, with_points, add, [&](Real x) { return local.at(span ? x : wrap_angle(x)); },
      [&](Real x, Result<Real>& r) {
        const Real t = span ? x : wrap_angle(x);
        r.point_a = c.center + c.radius * (std::cos(t) * local.frame.u + std::sin(t) * local.frame.v);
        r.param_a = Vec2<Real>(span ? span->param_of(t) : t, 0);
      });
}

// The best of a set of candidate Results, `unique` false when another reaches the same distance
// within the tie tolerance at a distinct pair (or the best is a continuum itself).
template <class Real, class Candidates> Result<Real> best_of(const Candidates& candidates, Real scale) {
  Result<Real> best = candidates.item[candidates.best];
  const Real tie = tie_tolerance(std::max(scale, best.distance));
  const Real apart = distinct_points_tolerance(scale);
  for (int i = 0; i < candidates.count; ++i) {
    if (i == candidates.best) continue;
    const Result<Real>& other = candidates.item[i];
    if (!(other.distance <= best.distance + tie)) continue;
    const bool same_pair =
        (other.point_a - best.point_a).norm() <= apart && (other.point_b - best.point_b).norm() <= apart;
    if (!same_pair || !other.unique) best.unique = false;
  }
  return best;
}

// A circle or an arc against a true ring: the interior candidates and both rims (circle-circle
// or arc-circle through the front end: the same order distance(circle, circle) takes). An arc
// (not whole, radius > 0) is the circle on its own angles, with its ends added to the interior
// candidates (docs/derivations/annulus.md, "A circle", "An arc"). distance() skips the rims when the
// interior decides (as circle-disk's distance() does); closest() solves them all, for the pair
// and for `unique`, and reports the same distance.
template <class Roots, class Real, class Add>
InteriorVerdict<Real> ring_interior(const Circle3<Real>& c, const Annulus3<Real>& a, bool with_points, const Add& add) {
  return circle_annulus_interior<Roots>(c, a, with_points, add);
}
template <class Roots, class Real, class Add>
InteriorVerdict<Real> ring_interior(const Arc3<Real>& arc, const Annulus3<Real>& a, bool with_points, const Add& add) {
  const ArcSpan<Real> span(arc);
  return circle_annulus_interior<Roots>(arc_circle(arc), a, with_points, add, &span);
}
// A Bezier curve (docs/derivations/annulus.md, "A Bezier curve"): the stationary points of its height
// (bezier-disk's interior candidates, refined on the curve: push_refined_curve_height_roots,
// detail/curve_round_query.hpp, since nothing polishes them here) and its two ends.
// An empty curve has none (its rims' answers are empty too).
template <class Roots, class Real, class Add> InteriorVerdict<Real> ring_interior(const BezierCurve3<Real>& b,
                                                                                  const Annulus3<Real>& a,
                                                                                  bool with_points, const Add& add) {
  if (b.control.cols() == 0) return {std::numeric_limits<Real>::infinity(), true};
  const Round<Real> round(a.center, a.normal, a.outer_radius);
  const LocalBezier<Real> c(b, round);
  const Real scale = bezier_round_scale(c, a.outer_radius);
  Candidates<Real, 4 * kMaxBezierDegree + 8> heights;  // the ends, the roots refined and as they came
  heights.push(Real(0));
  heights.push(Real(1));
  push_refined_curve_height_roots<Roots>(c, scale, heights);
  return interior_in_ring(
      heights, a, round, scale, with_points, add, [&](Real t) { return c.at(t); },
      [&](Real t, Result<Real>& r) {
        r.point_a = b.at(t);
        r.param_a = Vec2<Real>(t, 0);
      });
}

// The length scale of a ring query (tolerances follow it): the annulus's radius, the round's
// radius and the distance between their centers, or a curve's farthest control point.
template <class Real, class Curve> Real ring_scale(const Curve& curve, const Annulus3<Real>& a) {
  return std::max({a.outer_radius, curve.radius, (curve.center - a.center).norm()});
}
template <class Real> Real ring_scale(const BezierCurve3<Real>& b, const Annulus3<Real>& a) {
  Real s = a.outer_radius;
  for (int i = 0; i < int(b.control.cols()); ++i) s = std::max(s, (b.control.col(i) - a.center).norm());
  return s;
}

template <class Roots, class Real, template <class> class Curve>
Real curve_ring_distance(const Curve<Real>& curve, const Annulus3<Real>& a) {
  const InteriorVerdict<Real> interior = ring_interior<Roots>(curve, a, false, [](const Result<Real>&) {});
  if (interior.decided) return interior.best;
  return std::min({interior.best, circledist::distance<Roots>(curve, outer_rim(a)),
                   circledist::distance<Roots>(curve, inner_rim(a))});
}
template <class Roots, class Real, template <class> class Curve>
Result<Real> curve_ring_closest(const Curve<Real>& curve, const Annulus3<Real>& a) {
  CircleAnnulusCandidates<Real> candidates;
  const InteriorVerdict<Real> interior =
      ring_interior<Roots>(curve, a, true, [&](const Result<Real>& r) { candidates.add(r); });
  candidates.add(rim_as_annulus(circledist::closest_points<Roots>(curve, outer_rim(a)), a.outer_radius));
  candidates.add(rim_as_annulus(circledist::closest_points<Roots>(curve, inner_rim(a)), a.inner_radius));
  const Real scale = ring_scale(curve, a);
  Result<Real> r = best_of(candidates, scale > 0 ? scale : Real(1));
  r.distance = interior.decided ? interior.best : std::min(interior.best, r.distance);
  return r;
}

// A line, ray, segment or disk: convex (docs/derivations/annulus.md, "Convex shapes"). distance() needs to
// know where the disk's closest point lies, so it runs closest().
template <class Real, class X> struct ConvexAnnulusQuery {
  static constexpr bool defined = true;
  template <class Roots = DefaultRoots> static Real distance(const X& x, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_distance<Roots>(x, a, kind);
    return detail::convex_annulus_closest<Roots>(x, a).distance;
  }
  template <class Roots = DefaultRoots> static Result<Real> closest(const X& x, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_closest<Roots>(x, a, kind);
    return detail::convex_annulus_closest<Roots>(x, a);
  }
};

// A circle or a Bezier curve (docs/derivations/annulus.md, "A circle", "A Bezier curve"): not convex, the
// interior candidates and both rims.
template <class Real, class Curve> struct CurveAnnulusQuery {
  static constexpr bool defined = true;
  template <class Roots = DefaultRoots> static Real distance(const Curve& c, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_distance<Roots>(c, a, kind);
    return detail::curve_ring_distance<Roots>(c, a);
  }
  template <class Roots = DefaultRoots> static Result<Real> closest(const Curve& c, const Annulus3<Real>& a) {
    const detail::AnnulusKind kind = detail::annulus_kind(a);
    if (kind != detail::AnnulusKind::kRing) return detail::degenerate_closest<Roots>(c, a, kind);
    return detail::curve_ring_closest<Roots>(c, a);
  }
};

}  // namespace detail

}  // namespace circledist
