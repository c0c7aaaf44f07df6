// Line, ray and segment against an arc (Query<Line3 | Ray3 | Segment3, Arc3>). Derivation:
// docs/derivations/arc.md#a-line-ray-or-segment.
#pragma once

#include "detail/arc_span.hpp"
#include "detail/arc_target.hpp"
#include "detail/linear.hpp"
#include "detail/point_over_round.hpp"
#include "detail/trig.hpp"
#include "linear_circle.hpp"
#include "point_arc.hpp"
#include "point_linear.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace circledist {

namespace detail {

// ---------------------------------------------------------------------------------------------
// Lines, rays and segments against an arc: the arc parametrized, the piece's exact distance
// (docs/derivations/arc.md, "A line, ray or segment").

// The piece seen from the arc's circle's frame (LocalLinear: anchored at its point nearest the
// center, a unit direction m, tau in [lo, hi]): the distance from a local point (|w x m| for
// w = p - a when p's foot lies on the piece, else the distance to the nearer end), its square's
// jet along the arc, and the piece's closest point.
template <class Real> struct PieceOverArc {
  const LocalLinear<Real>& line;

  Real clamped(Real tau) const { return std::min(std::max(tau, line.lo), line.hi); }
  bool inside(Real tau) const { return !line.is_point && tau >= line.lo && tau <= line.hi; }
  Real tau_of(const Vec3<Real>& p) const { return line.is_point ? Real(0) : clamped((p - line.anchor).dot(line.dir)); }
  Vec3<Real> point(const Vec3<Real>& p) const { return line.anchor + tau_of(p) * line.dir; }

  Real distance(const Vec3<Real>& p) const {
    const Vec3<Real> w = p - line.anchor;
    const Real tau = w.dot(line.dir);
    if (inside(tau)) return w.cross(line.dir).norm();
    return (w - clamped(tau) * line.dir).norm();
  }
  Jet<Real> jet(const Vec3<Real>& p, const Vec3<Real>& p1, const Vec3<Real>& p2) const {
    const Vec3<Real> w = p - line.anchor;
    const Real tau = w.dot(line.dir);
    if (!inside(tau)) return point_jet(p, p1, p2, Vec3<Real>(line.anchor + clamped(tau) * line.dir));
    const Vec3<Real> q = w.cross(line.dir), q1 = p1.cross(line.dir), q2 = p2.cross(line.dir);
    return {q.squaredNorm(), 2 * q.dot(q1), 2 * (q1.squaredNorm() + q.dot(q2))};
  }
};

// The candidate angles of a piece against the arc's circle (radius R, its frame: P = R (cos, sin, 0)):
// with w = P - a and L = w.m = R (m_x cos + m_y sin) - a.m, the squared distance to the full line
// f = |w|^2 - L^2 has f' / 2 = R (a_x sin - a_y cos) - L L', trigonometric of degree 2 (a quartic
// in tan(theta / 2)); beyond an end (the foot L past lo or hi) the distance is the end's, least at
// the end's own angle (where it changes form the distance is C^1: a minimum there is a root of
// f' too, docs/derivations/arc.md). Plus t = 0 and pi (the half-angle substitution's blind spot). In units
// of `scale`.
template <class Roots, class Real, int N>
void push_piece_arc_candidates(const LocalLinear<Real>& line, Real radius, Real scale, Candidates<Real, N>& out) {
  push_circle_candidates(out);
  const auto push_end = [&](Real tau) {
    const Vec3<Real> e = line.at(tau);
    if (e.x() != 0 || e.y() != 0) out.push(std::atan2(e.y(), e.x()));
  };
  if (line.is_point) {
    push_end(Real(0));
    return;
  }
  const Vec3<Real> a = line.anchor / scale;
  const Vec3<Real>& m = line.dir;
  const Real r = radius / scale;
  Trig<Real, 1> along;
  along.c[0] = -a.dot(m);
  along.c[1] = r * m.x();
  along.s[1] = r * m.y();
  Trig<Real, 2> slope = Real(-1) * (along * along.derivative());
  slope.c[1] -= r * a.y();
  slope.s[1] += r * a.x();
  push_trig_roots<Roots>(slope, out);
  for (const Real tau : {line.lo, line.hi})
    if (std::isfinite(tau)) push_end(tau);
}

// The fast path (docs/derivations/arc.md, "A line, ray or segment: the fast path"). Over the whole circle the
// squared distance to the full line has at most two local minima, the global one
// (line_ring_minimum) and, inside the astroid, the other (other_line_minimum). The arc's
// distance to the piece is least at an arc end, or at an interior angle where it is a local
// minimum over the whole circle of the distance to the piece: there the piece's closest point is
// inside the piece (a local minimum of the line's distance, with its foot on the piece) or one of
// its ends E (the angle of E's projection, point-arc's answer for E). Every candidate value is the
// distance between a point of the arc and a point of the piece, so the least is the distance.
// The arc's unit u and v and its end points, relative to its center (u from |W|^2 S - (S.W) W, as
// point-arc takes it).
template <class Real> struct ArcEnds {
  Vec3<Real> u, v;  // |W|^2 times the start's in-plane part (u'), and W x u' (|v| = |W| |u|)
  Vec3<Real> end[2];
  Real angle = 0, s = 0, length = 0;  // |W|, |u|
  bool usable = false;                // false: a start along the normal, a zero or huge normal, a NaN angle

  // Unnormalized (no division: the sector test is an angle, scale-free; find_ends scales).
  // W is first scaled by a power of two (exact: only its direction counts) to |W|^2 in
  // [2^-100, 2^100], as PointOverRound takes it: u' is |W|^2 |S| and v' |W|^3 |S|, and |u'|^2
  // |W|^4 |S|^2, in the subnormals for a normal of 1e-80 and a unit start (its rounding moves the
  // ends' points off their circle by up to a fifth of the radius, and a line's distance as much).
  explicit ArcEnds(const Arc3<Real>& a) {
    constexpr Real lo = detail::power_of_two<Real>(-100), hi = detail::power_of_two<Real>(100);
    Vec3<Real> w = a.normal;
    Real n2 = w.squaredNorm();
    if (!detail::strictly_between(n2, lo, hi)) {
      w = detail::ldexp3(w, -detail::direction_exponent(w));
      n2 = w.squaredNorm();
    }
    const Vec3<Real> start = detail::moderate_start(a.start);
    u = n2 * start - w.dot(start) * w;
    length = u.norm();
    usable = length > 0 && std::isfinite(length) && n2 > 0 && std::isfinite(n2) && !std::isnan(a.angle);
    if (!usable) return;
    s = std::sqrt(n2);
    v = w.cross(u);
    angle = std::max(a.angle, Real(0));
  }
  // The end points (a sine and cosine: only where the ends are candidates).
  void find_ends(Real radius) {
    const Real to_u = radius / length, to_v = to_u / s;
    end[0] = to_u * u;
    end[1] = (std::cos(angle) * to_u) * u + (std::sin(angle) * to_v) * v;
  }
  // The arc's t of a point relative to the center (its angle from u toward v), in [0, 2 pi).
  Real offset(const Vec3<Real>& p) const {
    const Real t = detail::atan2(p.dot(v), s * p.dot(u));
    return t < 0 ? t + 2 * pi_v<Real>() : t;
  }
  // offset(p) <= angle, the atan2 only where the octant of the same two numbers does not decide
  // (detail::octant_bounds: where it does, offset answers the same).
  bool holds(const Vec3<Real>& p) const {
    Real lo, hi;
    if (detail::octant_bounds(s * p.dot(u), p.dot(v), lo, hi)) {
      if (hi < angle) return true;
      if (lo > angle) return false;
    }
    return offset(p) <= angle;
  }
};

// The piece relative to the arc's center c along its line's anchor a (its point nearest c, from
// line_ring_minimum, to one rounding) and unit direction m: tau in [lo, hi] from a, the ends'
// tau taken as (E - c).m (rounding along the line only). A point's distance |w - clamp(w.m) m|,
// w = p - a, stays accurate however far the piece's origin lies, where the point-ray closed form
// from a far origin would carry eps |origin - c| across the line into every distance.
template <class Real> struct AnchoredPiece {
  Vec3<Real> anchor, dir;
  Real lo, hi;

  template <class Piece>
  AnchoredPiece(const Piece& piece, const Linear<Real>& linear, const LineRingMinimum<Real>& m, const Vec3<Real>& c)
      : anchor(m.anchor), dir(m.unit_direction), lo(linear.lo), hi(linear.hi) {
    if (std::isfinite(lo)) lo = (piece_end(piece, lo) - c).dot(dir);
    if (std::isfinite(hi)) hi = (piece_end(piece, hi) - c).dot(dir);
  }
  Vec3<Real> point(const Vec3<Real>& p) const {
    const Real tau = std::min(std::max((p - anchor).dot(dir), lo), hi);
    return anchor + tau * dir;
  }
  Real distance(const Vec3<Real>& p) const { return (p - point(p)).norm(); }
};

// The fast path's answer: the least candidate, and whether another lies within the tie
// tolerance at distinct points (closest() then takes the pair and `unique` from the general path).
template <class Real> struct PieceArcPick {
  Real value = std::numeric_limits<Real>::infinity();
  Vec3<Real> piece_point = Vec3<Real>::Zero(), arc_point = Vec3<Real>::Zero();  // world
  Real piece_param = 0, arc_param = 0;
  bool unique = true, tied = false;
};

// The piece in the arc's plane (docs/derivations/arc.md, "A line, ray or segment in the arc's
// plane"): the problem taken in the plane, in the arc's unit u and v, on the line's data
// (line_ring_minimum's anchor a, unit direction m and unit normal n, before its root). The
// candidates are the ring points that can be the plane problem's closest: the line's crossings of
// the circle (or, where it misses, the ring point toward it), the arc's two ends and the ring
// points toward the piece's finite ends, those on the arc; each against the piece's clamped point.
// The least in the plane, V2, is at most the distance f* (projecting onto the plane shortens every
// distance from a plane point); its pair's distance in space, V, is at least f* and at most
// V2 + |h| (h the piece point's height over the plane). So V is the answer within |h|, and it is
// taken only where |h|, bounded with its rounding, is below 64 eps max(R, V): a piece in the plane
// to rounding. Returns 1 decided (`out` holds V, and for closest the pair and `unique`), 0 not.
// The first candidate list entry that is a line minimum on the arc and on the piece is the plane
// problem's global minimum: distance() stops there; closest() goes on only to the other crossing
// (the one pair that can tie with it at a distinct point).
// The arc's span test of a plane point (x, y) in the arc's u, v coordinates: its angle from u
// toward v, atan2(y, x) in [0, 2 pi), at most `angle`; the atan2 only where the octant of the
// same two numbers does not decide (detail::octant_bounds: where it does, the angle answers the
// same).
template <class Real> CIRCLEDIST_INLINE bool plane_angle_holds(Real x, Real y, Real angle) {
  Real lo, hi;
  if (detail::octant_bounds(x, y, lo, hi)) {
    if (hi < angle) return true;
    if (lo > angle) return false;
  }
  const Real t = detail::atan2(y, x);
  return (t < 0 ? t + 2 * pi_v<Real>() : t) <= angle;
}

// piece_arc_planar's candidates: a ring point (x, y) of the arc and the piece's point at its
// foot's tau clamped to [lo, hi], and the pair's distance in the plane.
template <class Real> struct PlaneCandidates {
  struct Item {
    Real x, y, value;  // the ring point in the plane, and its plane distance to the piece
    Real tau;          // the piece point's tau, clamped
    int clamped_end;   // -1 inside the piece, 0 or 1 at its end lo or hi
    int arc_end;       // -1 inside the arc, 0 or 1 its start or far end
  };
  Real ax, ay, mx, my, lo, hi;  // the anchor and the unit direction in the plane, the interval
  Item item[6];
  int count = 0;

  // Adds the pair; true where the piece's point is inside the piece.
  CIRCLEDIST_INLINE bool take(Real x, Real y, int arc_end) {
    const Real tau_free = (x - ax) * mx + (y - ay) * my;
    Item& k = item[count++];
    k.clamped_end = tau_free < lo ? 0 : (tau_free > hi ? 1 : -1);
    k.tau = k.clamped_end < 0 ? tau_free : (k.clamped_end == 0 ? lo : hi);
    k.arc_end = arc_end;
    k.x = x;
    k.y = y;
    k.value = length2d(x - (ax + k.tau * mx), y - (ay + k.tau * my));
    return k.clamped_end < 0;
  }
};

template <bool for_closest, class Real, class Piece>
int piece_arc_planar(const Piece& piece, const Arc3<Real>& arc, const ArcEnds<Real>& ends, const Linear<Real>& linear,
                     const LineRingMinimum<Real>& line, PieceArcPick<Real>& out) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Vec3<Real>&a = line.anchor, &m = line.unit_direction, &n = line.unit_normal;
  const Real radius = arc.radius;
  const Real height = a.x() * n.x() + a.y() * n.y() + a.z() * n.z();
  const Real tilt = m.x() * n.x() + m.y() * n.y() + m.z() * n.z();
  // |a| bounded without a square root: |a|_max <= |a| <= |a|_1.
  const Real a_max = std::max({std::abs(a.x()), std::abs(a.y()), std::abs(a.z())});
  const Real a_sum = std::abs(a.x()) + std::abs(a.y()) + std::abs(a.z());
  // Cheap refusal of a piece out of the plane: the bound below before V is known (V >= 0 and
  // |tau| <= R + V <= 2 R + |a| at the plane's answer).
  if (!(std::abs(height) + std::abs(tilt) * (2 * radius + a_sum) <= 32 * eps * (radius + a_max))) return 0;
  // The arc's unit u (from u', ArcEnds) and v = n x u.
  const Real inv_u = 1 / ends.length;
  const Real ux = ends.u.x() * inv_u, uy = ends.u.y() * inv_u, uz = ends.u.z() * inv_u;
  const Real vx = n.y() * uz - n.z() * uy, vy = n.z() * ux - n.x() * uz, vz = n.x() * uy - n.y() * ux;
  PlaneCandidates<Real> k;
  k.ax = a.x() * ux + a.y() * uy + a.z() * uz;
  k.ay = a.x() * vx + a.y() * vy + a.z() * vz;
  k.mx = m.x() * ux + m.y() * uy + m.z() * uz;
  k.my = m.x() * vx + m.y() * vy + m.z() * vz;
  // The unit m is in the plane to 32 eps (the refusal above): its plane part's squared length
  // is 1 to rounding, and is taken as 1 (tau and the foot then round as by eps |a|).
  // The piece's interval in tau from the anchor (AnchoredPiece's ends).
  const Vec3<Real>& c = arc.center;
  k.lo = std::isfinite(linear.lo) ? (piece_end(piece, linear.lo) - c).dot(m) : linear.lo;
  k.hi = std::isfinite(linear.hi) ? (piece_end(piece, linear.hi) - c).dot(m) : linear.hi;
  // The line's minima over the ring, in the plane: its foot f from the center at distance d0
  // (|a x m| in the plane); the crossings f +- w m (w = sqrt(R^2 - d0^2)) where d0 < R, else the
  // ring point toward f.
  const Real cross = k.ax * k.my - k.ay * k.mx;
  const Real fx = cross * k.my, fy = -cross * k.mx;
  const Real d0_squared = cross * cross, r_squared = radius * radius;
  int best = -1;
  if (d0_squared < r_squared) {
    // (R^2 - d0^2) rounds by eps R^2 as (R - d0)(R + d0) would by eps R 2R: near a tangency the
    // crossings' place is that sensitive to the inputs' rounding anyway, and the distance is not.
    const Real w = std::sqrt(r_squared - d0_squared);
    const Real wx = w * k.mx, wy = w * k.my;
    if (plane_angle_holds(fx + wx, fy + wy, ends.angle) && k.take(fx + wx, fy + wy, -1)) best = 0;
    if (best < 0 || for_closest) {
      if (plane_angle_holds(fx - wx, fy - wy, ends.angle) && k.take(fx - wx, fy - wy, -1) && best < 0)
        best = k.count - 1;
    }
  } else if (d0_squared > 0) {
    const Real to_ring = radius / std::sqrt(d0_squared);
    const Real x = fx * to_ring, y = fy * to_ring;
    if (plane_angle_holds(x, y, ends.angle) && k.take(x, y, -1)) best = 0;
  } else {
    return 0;  // a radius of zero (the caller's case) or NaN
  }
  if (best < 0) {
    // The arc's ends and the ring points toward the piece's finite ends.
    k.take(radius, 0, 0);
    k.take(radius * std::cos(ends.angle), radius * std::sin(ends.angle), 1);
    for (const Real t : {linear.lo, linear.hi}) {
      if (!std::isfinite(t)) continue;
      const Vec3<Real> e = piece_end(piece, t) - c;
      const Real ex = e.x() * ux + e.y() * uy + e.z() * uz, ey = e.x() * vx + e.y() * vy + e.z() * vz;
      const Real length = length2d(ex, ey);
      if (length > 0 && plane_angle_holds(ex, ey, ends.angle))
        k.take(ex * (radius / length), ey * (radius / length), -1);
    }
    best = 0;
    for (int i = 1; i < k.count; ++i)
      if (k.item[i].value < k.item[best].value) best = i;
  }
  // The pair in space, relative to the center.
  const auto arc_point = [&](const typename PlaneCandidates<Real>::Item& q) {
    return Vec3<Real>(q.x * ux + q.y * vx, q.x * uy + q.y * vy, q.x * uz + q.y * vz);
  };
  const auto piece_point = [&](const typename PlaneCandidates<Real>::Item& q) {
    if (q.clamped_end >= 0) return Vec3<Real>(piece_end(piece, q.clamped_end == 0 ? linear.lo : linear.hi) - c);
    return Vec3<Real>(a.x() + q.tau * m.x(), a.y() + q.tau * m.y(), a.z() + q.tau * m.z());
  };
  const typename PlaneCandidates<Real>::Item& w = k.item[best];
  const Real value = w.value;
  // |h| at the pair's piece point, with the rounding of height and tilt (a few eps |a| and eps).
  const Real tau_bound = std::abs(w.tau);
  if (!(std::abs(height) + std::abs(tilt) * tau_bound + 8 * eps * (a_sum + tau_bound) <=
        64 * eps * std::max(radius, value)))
    return 0;
  out.value = value;
  if constexpr (for_closest) {
    const Vec3<Real> pa = arc_point(w), pp = piece_point(w);
    // Another candidate's pair as close at distinct points: not unique. Near either threshold
    // (within a factor 4) `tied`: the general path takes the pair and `unique`, this distance kept.
    const Real scale = std::max(radius, a.norm());
    const Real tie = tie_tolerance(std::max(scale, value));
    const Real apart_arc = distinct_points_tolerance(radius), apart_piece = distinct_points_tolerance(scale);
    const auto near = [](Real x, Real threshold) { return x > threshold / 4 && x < 4 * threshold; };
    bool other_pair = false;
    for (int i = 0; i < k.count; ++i) {
      if (i == best) continue;
      const Vec3<Real> qa = arc_point(k.item[i]), qp = piece_point(k.item[i]);
      const Real gap = k.item[i].value - value;
      const Real da = (qa - pa).norm(), dp = (qp - pp).norm();
      const bool apart = da > apart_arc / 4 || dp > apart_piece / 4;
      if ((near(gap, tie) && apart) || (gap <= tie && (near(da, apart_arc) || near(dp, apart_piece)))) {
        out.tied = true;
        return 1;
      }
      if (gap <= tie && (da > apart_arc || dp > apart_piece)) other_pair = true;
    }
    out.arc_point = c + pa;
    if (w.arc_end < 0) {  // the plane's angle, as plane_angle_holds took it (on the arc: t <= angle)
      const Real t = detail::atan2(w.y, w.x);
      out.arc_param = std::min(t < 0 ? t + 2 * pi_v<Real>() : t, ends.angle);
    } else {
      out.arc_param = w.arc_end == 0 ? Real(0) : ends.angle;
    }
    if (w.clamped_end >= 0) {
      out.piece_point = piece_end(piece, w.clamped_end == 0 ? linear.lo : linear.hi);
      out.piece_param = w.clamped_end == 0 ? linear.lo : linear.hi;
    } else {
      out.piece_point = c + pp;
      out.piece_param = line_param(Line3<Real>{linear.origin, linear.direction}, c, pp);
    }
    out.unique = !other_pair;
    out.tied = false;
  }
  return out.value == out.value;
}

// False where the fast path does not decide (the general path answers): the line declined by
// line_ring_minimum or along the axis, the second minimum undecided, a segment too long for its
// line (piece_line).
template <class Roots, bool for_closest, class Real, class Piece>
bool piece_arc_fast(const Piece& piece, const Arc3<Real>& arc, PieceArcPick<Real>& out) {
  ArcEnds<Real> ends(arc);
  if (!ends.usable) return false;
  const Circle3<Real> c = arc_circle(arc);
  const PieceLine<Real> pl = piece_line(piece, arc.radius);
  if (!pl.usable) return false;
  const Linear<Real> linear = as_linear(piece);
  using PointArc = Query<Vec3<Real>, Arc3<Real>>;
  // Before the root (docs/derivations/arc.md, "Before the root"): where the line has one local minimum over
  // the ring, an end at which the ring's distance rises along the piece (p0, a ray's origin) or
  // falls toward the piece's end (p1) is the piece's closest point to the circle, as for a circle
  // (choose_from_line, linear_circle.hpp); it is the arc's answer too where that end's nearest ring
  // point lies on the arc (point-arc's `on_ring`): the arc is no nearer than its circle anywhere,
  // and as near at that end. The answer is the end's point-arc candidate the rest of this path
  // would have found, by the same call.
  SecondMinimumTest<Real> test;
  bool tested = false;  // a full line has no end to answer before the root: its test comes after
  const auto before_root = [&](const LineRingMinimum<Real>& line_data) {
    // A piece in the arc's plane: the plane's candidates, no root (piece_arc_planar).
    if (piece_arc_planar<for_closest>(piece, arc, ends, linear, line_data, out)) return true;
    if constexpr (std::is_same<Piece, Line3<Real>>::value) return false;
    test = second_minimum_test(line_data, arc.radius);
    tested = true;
    if (test.verdict != 0 || line_data.on_axis) return false;
    const Vec3<Real>& direction = pl.line.direction;
    Real tau;
    if (std::isfinite(linear.lo) &&
        end_point_slope(piece_end(piece, linear.lo), c, line_data.unit_normal, direction) > 0)
      tau = linear.lo;
    else if (std::isfinite(linear.hi) &&
             end_point_slope(piece_end(piece, linear.hi), c, line_data.unit_normal, direction) < 0)
      tau = linear.hi;
    else
      return false;
    const Vec3<Real> end = piece_end(piece, tau);
    bool on_ring;
    const Result<Real> r = PointArc::template solve<for_closest>(end, arc, on_ring);
    if (!on_ring) return false;
    out.value = r.distance;
    if constexpr (for_closest) {
      out.piece_point = end;
      out.piece_param = tau;
      out.arc_point = r.point_b;
      out.arc_param = r.param_b.x();
      out.tied = !r.unique;
    }
    return true;
  };
  LineRingMinimum<Real> m;
  const LineRingOutcome outcome = line_ring_minimum<Roots>(pl.line, c, m, before_root);
  if (outcome == LineRingOutcome::AnsweredBeforeRoot) return out.value == out.value;
  if (outcome == LineRingOutcome::Declined || m.on_axis) return false;
  // The line's global minimum over the whole circle on the arc, its foot on the piece: no point of
  // the arc is nearer the line, so none nearer the piece, and this pair is the answer. It is the
  // only pair at that distance unless it is tied with its mirror image (the trust-region
  // subproblem's global minimizer is unique outside its hard case, b1 = 0, which the mirror
  // bounds: line_ring_minimum.hpp), where closest() asks the general path.
  // distance() needs only whether a ring point is on the arc (ArcEnds::holds), closest() its t.
  const auto on_arc_at = [&](const Vec3<Real>& ring_point, Real& t) {
    if constexpr (for_closest) {
      t = ends.offset(ring_point);
      return t <= ends.angle;
    } else {
      return ends.holds(ring_point);
    }
  };
  Real global_t = 0;
  const bool on_arc = on_arc_at(m.ring_point, global_t);
  if (on_arc && on_piece(pl.line, c.center, m.line_point, linear)) {
    out.value = m.distance;
    if constexpr (for_closest) {
      out.piece_point = c.center + m.line_point;
      out.arc_point = c.center + m.ring_point;
      out.piece_param = line_param(pl.line, c.center, m.line_point);
      out.arc_param = global_t;
      out.tied = tied_with_mirror(c, m);
    }
    return out.value == out.value;
  }
  LineRingMinimum<Real> second;
  // The secular data second_minimum_test reads are the same after the root (its test, the same).
  if (!tested) test = second_minimum_test(m, arc.radius);
  const int other = other_line_minimum<Roots>(m, arc.radius, second, [](Real) { return true; }, test);
  if (other < 0) return false;
  // Closest points keep every candidate (for the tie test); the distance keeps the least value.
  PieceArcPick<Real> list[for_closest ? 6 : 1];
  int count = 0;
  Real least = std::numeric_limits<Real>::infinity();
  if (other == 1) {  // the global minimum is off the arc or the piece (above)
    Real t = 0;
    if (on_arc_at(second.ring_point, t) && on_piece(pl.line, c.center, second.line_point, linear)) {
      least = second.distance;
      if constexpr (for_closest) {
        PieceArcPick<Real>& k = list[count++];
        k.value = second.distance;
        k.piece_point = c.center + second.line_point;
        k.arc_point = c.center + second.ring_point;
        k.piece_param = line_param(pl.line, c.center, second.line_point);
        k.arc_param = t;
      }
    }
  }
  const AnchoredPiece<Real> local(piece, linear, m, c.center);
  ends.find_ends(arc.radius);
  for (int e = 0; e < 2; ++e) {
    if constexpr (for_closest) {
      const Vec3<Real> q = local.point(ends.end[e]);
      PieceArcPick<Real>& k = list[count++];
      k.value = (ends.end[e] - q).norm();
      k.piece_point = c.center + q;
      k.piece_param = line_param(pl.line, c.center, q);  // the piece's own parameter
      k.arc_point = c.center + ends.end[e];
      k.arc_param = e == 0 ? Real(0) : ends.angle;
    } else {
      least = std::min(least, local.distance(ends.end[e]));
    }
  }
  for (const Real tau : {linear.lo, linear.hi}) {
    if (!std::isfinite(tau)) continue;
    const Vec3<Real> end = piece_end(piece, tau);
    if constexpr (for_closest) {
      const Result<Real> r = PointArc::template closest<Roots>(end, arc);
      PieceArcPick<Real>& k = list[count++];
      k.value = r.distance;
      k.piece_point = end;
      k.piece_param = tau;
      k.arc_point = r.point_b;
      k.arc_param = r.param_b.x();
      k.unique = r.unique;
    } else {
      least = std::min(least, PointArc::template distance<Roots>(end, arc));
    }
  }
  if constexpr (!for_closest) {
    out.value = least;
  } else {
    int best = 0;
    for (int i = 1; i < count; ++i)
      if (list[i].value < list[best].value) best = i;
    out = list[best];
    const Real scale = std::max(arc.radius, out.value);
    const Real tie = tie_tolerance(scale), apart = distinct_points_tolerance(scale);
    for (int i = 0; i < count; ++i)
      if (i != best && list[i].value <= out.value + tie &&
          ((list[i].arc_point - out.arc_point).norm() > apart ||
           (list[i].piece_point - out.piece_point).norm() > apart))
        out.tied = true;
    if (!out.unique) out.tied = true;
  }
  // Non-finite input is declined above (line_ring_minimum, ArcEnds); a NaN least all the same
  // goes to the general path.
  return out.value == out.value;
}

template <class Real, class Piece> struct PieceArcQuery {
  static constexpr bool defined = true;
  using Circle = Query<Piece, Circle3<Real>>;
  using Point = Query<Vec3<Real>, Piece>;

  template <class Roots>
  static ArcMinima<Real> solve(const ArcSpan<Real>& span, const LocalLinear<Real>& line, Real radius, Real scale) {
    const PieceOverArc<Real> piece{line};
    const auto h = [&](Real t) { return piece.distance(ArcSpan<Real>::local(radius, t)); };
    const auto jet = [&](Real t) {
      const Real cs = std::cos(t), sn = std::sin(t);
      const Vec3<Real> p(radius * cs, radius * sn, 0);
      return piece.jet(p, Vec3<Real>(-radius * sn, radius * cs, 0), Vec3<Real>(-p));
    };
    Candidates<Real, 24> candidates;
    push_piece_arc_candidates<Roots>(line, radius, scale, candidates);
    return polish_on_arc<Roots>(span, candidates, jet, h, radius, scale);
  }

  template <class Roots = DefaultRoots> static Real distance(const Piece& piece, const Arc3<Real>& arc) {
    if (whole_arc(arc)) return Circle::template distance<Roots>(piece, arc_circle(arc));
    if (!(arc.radius > 0)) return Point::template distance<Roots>(arc.center, piece);
    PieceArcPick<Real> pick;
    if (piece_arc_fast<Roots, false>(piece, arc, pick)) return pick.value;
    const Round<Real> round(arc.center, arc.normal, arc.radius);
    const LocalLinear<Real> line(as_linear(piece), round);
    return solve<Roots>(ArcSpan<Real>(arc), line, arc.radius, linear_round_scale(line, arc.radius)).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Piece& piece, const Arc3<Real>& arc) {
    const ArcSpan<Real> span(arc);
    if (whole_arc(arc)) return as_arc_result(Circle::template closest<Roots>(piece, arc_circle(arc)), span, 1);
    if (!(arc.radius > 0)) return Point::template closest<Roots>(arc.center, piece).swapped();
    PieceArcPick<Real> pick;
    const bool fast = piece_arc_fast<Roots, true>(piece, arc, pick);
    if (fast && !pick.tied) {
      Result<Real> r;
      r.distance = pick.value;
      r.point_a = pick.piece_point;
      r.param_a = Vec2<Real>(pick.piece_param, 0);
      r.point_b = pick.arc_point;
      r.param_b = Vec2<Real>(pick.arc_param, 0);
      r.unique = pick.unique;
      return r;
    }
    const Round<Real> round(arc.center, arc.normal, arc.radius);
    const Linear<Real> linear = as_linear(piece);
    const LocalLinear<Real> line(linear, round);
    const Real scale = linear_round_scale(line, arc.radius);
    ArcMinima<Real> minima = solve<Roots>(span, line, arc.radius, scale);
    const PieceOverArc<Real> over{line};
    const Real best = minima.best.x;
    const auto at = [&](Real t) { return ArcSpan<Real>::local(arc.radius, t); };
    const auto piece_point_of = [&](const Vec3<Real>& q, bool&) { return over.point(q); };
    add_ends_for_ties(minima, span, [&](Real t) { return (at(t) - over.point(at(t))).norm(); });
    const Vec3<Real> pa = at(best);
    const Vec3<Real> pb = over.point(pa);
    Result<Real> r;
    // A tie the fast path saw: the general path's pair and `unique`, the fast path's distance
    // (as distance() answers it).
    r.distance = fast ? pick.value : minima.best.value;
    Real t;
    r.point_a = piece_point(linear, line, round, over.tau_of(pa), t);
    r.param_a = Vec2<Real>(t, 0);
    r.point_b = span.world(arc.center, arc.radius, best);
    r.param_b = span.param(best);
    r.unique =
        !another_closest_pair(minima, scale, at, piece_point_of, pa, pb,
                              distinct_points_tolerance(std::min(scale, arc.radius)), distinct_points_tolerance(scale));
    return r;
  }
};

}  // namespace detail

template <class Real> struct Query<Line3<Real>, Arc3<Real>> : detail::PieceArcQuery<Real, Line3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Arc3<Real>> : detail::PieceArcQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Arc3<Real>> : detail::PieceArcQuery<Real, Segment3<Real>> {};

}  // namespace circledist
