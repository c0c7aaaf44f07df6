// Line, ray and segment against a circle: note 000 §1 (the quartic), restricted to the piece's
// interval with its end points added for rays and segments.
#pragma once

#include <type_traits>

#include "linear.hpp"
#include "query.hpp"

namespace circledist {

template <class Real, class Piece> struct LinearCircleQuery {
  static constexpr bool defined = true;

  template <class Roots> static Minima<Real> solve(const LocalLinear<Real>& line, Real radius, Real scale) {
    Candidates<Real> stationary, exact;
    push_line_circle_roots<Roots>(line, radius, scale, stationary);
    push_linear_candidates(line, exact);
    const auto h = [&](Real tau) { return ring_distance_local(line.at(tau), radius); };
    const auto jet = [&](Real tau) { return ring_jet(line, radius, tau); };
    return minimize_linear<Roots>(jet, h, line, radius, stationary, exact, scale);
  }

  template <class Roots = DefaultRoots> static Real distance(const Piece& piece, const Circle3<Real>& c) {
    const Round<Real> round(c.center, c.normal, c.radius);
    const LocalLinear<Real> line(as_linear(piece), round);
    return solve<Roots>(line, c.radius, linear_round_scale(line, c.radius)).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Piece& piece, const Circle3<Real>& c) {
    const Round<Real> round(c.center, c.normal, c.radius);
    const Linear<Real> linear = as_linear(piece);
    const LocalLinear<Real> line(linear, round);
    const Real scale = linear_round_scale(line, c.radius);
    const Minima<Real> minima = solve<Roots>(line, c.radius, scale);
    return linear_round_result(
        linear, line, round, minima, scale,
        [&](const Vec3<Real>& p, bool& ambiguous) { return round.ring_point(p, scale, ambiguous); },
        &Round<Real>::ring_param);
  }
};

// A full line against a circle, seen from the circle's side. With the line's unit direction m
// and its point a closest to the center (both relative to the center, a.m = 0), the squared
// distance from the ring point R z (z a unit vector of the circle's plane) to the line is
//   |R z - a|^2 - (R z.m)^2 = R^2 (s^2 z2^2 - 2 b.z) + const,   s^2 = |m_xy|^2, b = a_xy / R,
// in the plane's basis e1 = m_xy / s, e2 = n x e1: a quadratic minimized over the unit circle,
// a trust-region subproblem. Its global minimum (More and Sorensen) is
//   z = (b1 / mu, b2 / (mu + s^2))  at the root mu >= 0 of  b1^2 / mu^2 + b2^2 / (mu + s^2)^2 = 1,
// which lies in [max(|b1|, |b| - s^2), |b|] (|z1| <= 1, |z2| <= 1, |z| = 1) and is the only
// sign change there of the quartic (note 000's quartic seen from the circle)
//   P(mu) = (mu^2 - b1^2) (mu + s^2)^2 - b2^2 mu^2.
// So one bracketed root gives the answer: no isolation, no candidates, no polish. b1 = 0 with
// |b2| < s^2 is the "hard case" mu = 0: two mirror-image closest points (unique = false).
template <class Real> struct LineRingMinimum {
  Vec3<Real> ring_point, line_point;  // relative to the center
  Real distance = 0;
  Vec3<Real> mirror;  // the ring point reflected across the plane of e2 and n: the other minimum's
                      // neighbor when b1 is small (the two minima differ by 4 R^2 |b1 z1|)
  Vec3<Real> anchor, unit_direction, unit_normal;  // a, m and n
  bool on_axis = false;  // a line along the axis: every ring point is closest
};

// False when the line is too extreme for the direct method (a zero or huge direction, a zero
// radius, non-finite input): LinearCircleQuery then answers.
template <class Roots, class Real>
bool line_ring_minimum(const Line3<Real>& line, const Circle3<Real>& circle, LineRingMinimum<Real>& out) {
  const Real radius = circle.radius;
  const Real normal_length = circle.normal.norm();
  const Real d2 = line.direction.squaredNorm();
  // Far from overflow and underflow (accurate_cross needs its error terms above the subnormals):
  // within 2^(+-0.3 max_exponent), 2^+-307 in double, 2^+-38 in float.
  constexpr Real bound = detail::power_of_two<Real>(std::numeric_limits<Real>::max_exponent * 3 / 10);
  const auto moderate = [bound](Real x) { return x > 1 / bound && x < bound; };
  if (!(moderate(radius) && moderate(d2) && moderate(normal_length))) return false;
  // Reciprocals once: a division per component would be most of the query's time.
  const Real inverse_normal = 1 / normal_length, inverse_length = 1 / std::sqrt(d2);
  const Vec3<Real> n = circle.normal * inverse_normal;
  // The anchor from w = o x d to one rounding per component (as LocalLinear): accurate relative
  // to its own length however far along the line the origin lies.
  const Vec3<Real> m = line.direction * inverse_length;
  const Vec3<Real> a = m.cross(offset_cross(ExactDifference<Real>(line.origin, circle.center), line.direction)) *
                       inverse_length;
  if (!a.allFinite()) return false;
  // m x n from the inputs to one rounding per component: for a line nearly along the axis,
  // m - (m.n) n would carry m's rounding, eps, into a tilt of size s, and tip the ring point
  // out of the plane by eps / s.
  const Vec3<Real> tilt = accurate_cross(line.direction, circle.normal) * (inverse_length * inverse_normal);
  const Vec3<Real> a_xy = a - a.dot(n) * n, m_xy = n.cross(tilt);
  const Real s2 = tilt.squaredNorm();  // |m_xy|^2 without 1 - (m.n)^2's cancellation
  Vec3<Real> direction;  // of the closest ring point
  if (!(s2 > std::numeric_limits<Real>::epsilon() * std::numeric_limits<Real>::epsilon())) {
    // Parallel to the axis (to a tilt below eps): the ring point toward the line.
    const Real rho = a_xy.norm();
    out.on_axis = rho <= 8 * std::numeric_limits<Real>::epsilon() * std::max(radius, a.norm());
    direction = rho > 0 ? a_xy : Frame<Real>(circle.normal).u;  // angle 0 when all are closest
    out.mirror = out.ring_point = radius * direction / direction.norm();
  } else {
    // a_xy.m_xy = R s b1 is -(a.n)(m.n) because a.m = 0, and a.n = a.(n - (m.n) m) for the same
    // reason. Each form matters at one extreme. Taken directly, a_xy.m_xy would carry a.m's
    // rounding, eps |a|, which swamps it for a line nearly parallel to the plane and close to it
    // (and picks the wrong one of the two crossings). And for a line nearly along the axis, a.n
    // is of size |a| s while its rounding is eps |a|: at a tilt s near eps, b1 would be noise and
    // the closest ring point anywhere on the ring. n - (m.n) m = tilt x m comes from the
    // accurate tilt, to eps relative to its length s, so (tilt x m).a is accurate at both ends.
    const Real along = -a.dot(tilt.cross(m)) * m.dot(n);
    const Real inverse_s2 = 1 / s2;
    const Vec3<Real> a_parallel = (along * inverse_s2) * m_xy, a_across = a_xy - a_parallel;
    const Real s = std::sqrt(s2);
    // The secular root in double for float scenes: with s^2 and b1 both near float's eps, the
    // quartic's low coefficients b1^2 s^4 would fall below float's smallest normal.
    using Work = std::conditional_t<std::is_same<Real, float>::value, double, Real>;
    const Work inverse_radius = 1 / Work(radius), t2 = Work(s2);
    const Work b1 = Work(along) * inverse_radius / Work(s);
    const Work b2_squared = Work(a_across.squaredNorm()) * (inverse_radius * inverse_radius);
    const Work b_norm = std::sqrt(b1 * b1 + b2_squared);
    const Work lo = std::max(std::abs(b1), b_norm - t2), hi = b_norm;
    const Work c[5] = {-b1 * b1 * t2 * t2, -2 * b1 * b1 * t2, (t2 - b_norm) * (t2 + b_norm), 2 * t2, 1};
    // With |b1| <= eps^2 the b1 = 0 minimizer (the hard-case formula below, which also covers
    // |b2| > s^2) is within 2 |b1| R^2 of the minimum squared distance, so within eps R of the
    // distance; solving instead would square b1 into the subnormals and lose the root.
    const Work eps = std::numeric_limits<Real>::epsilon();
    Real mu = 0;
    if (std::abs(b1) > eps * eps) {
      // P at the ends in closed form (with b^2 = b1^2 + b2^2): -b1^2 b2^2 at |b1|,
      // b1^2 (lo^2 - b^2) at b - s^2, b2^2 s^2 (2 b + s^2) at b.
      const Work p_lo = lo == std::abs(b1) ? -b1 * b1 * b2_squared : b1 * b1 * (lo - b_norm) * (lo + b_norm);
      const Work p_hi = b2_squared * t2 * (2 * b_norm + t2);
      mu = Real(hi > lo ? Roots::bracketed_root(c, 4, lo, hi, p_lo, p_hi) : lo);
    }
    if (mu > 0) {
      direction = a_parallel * (mu + s2) + a_across * mu;  // z = (b1 / mu, b2 / (mu + s^2)), scaled
    } else {
      // The hard case: z2 = b2 / s^2 across, the rest of the unit length along m_xy.
      const Vec3<Real> across = a_across * (inverse_s2 / radius);
      const Real rest = std::sqrt(std::max(Real(0), 1 - across.squaredNorm()));
      direction = across + (along < 0 ? -rest : rest) / s * m_xy;
    }
    const Real length = direction.norm();
    if (!(length > 0) || !std::isfinite(length)) return false;
    out.ring_point = (radius / length) * direction;
    out.mirror = out.ring_point - (2 * out.ring_point.dot(m_xy) * inverse_s2) * m_xy;
  }
  const Vec3<Real> offset = out.ring_point - a;
  out.distance = offset.cross(m).norm();
  out.line_point = a + offset.dot(m) * m;
  out.anchor = a;
  out.unit_direction = m;
  out.unit_normal = n;
  return true;
}

// Whether the line's ring minimum m is tied with its mirror image (b1 near 0): which of the two
// lies on a piece, and whether a piece's closest pair is unique, is then the general path's call.
template <class Real> bool tied_with_mirror(const Circle3<Real>& c, const LineRingMinimum<Real>& m) {
  if (m.on_axis) return false;
  const Real scale = std::max(c.radius, m.anchor.norm());
  const Real mirror_distance = (m.mirror - m.anchor).cross(m.unit_direction).norm();
  return mirror_distance <= m.distance + tie_tolerance(std::max(scale, m.distance));
}

// The closest points of a line's minimum over the ring (line_ring_minimum). `line` is the full
// line through the piece (for a ray or a segment, the piece's own parametrization: t = param).
template <class Real>
Result<Real> line_ring_result(const Line3<Real>& line, const Circle3<Real>& c, const LineRingMinimum<Real>& m) {
  Result<Real> r;
  r.distance = m.distance;
  r.point_a = c.center + m.line_point;
  r.point_b = c.center + m.ring_point;
  const Real d2 = line.direction.squaredNorm();
  r.param_a = Vec2<Real>((m.line_point - (line.origin - c.center)).dot(line.direction) / d2, 0);
  const Frame<Real> frame(c.normal);
  r.param_b = Round<Real>::ring_param(frame.to_local(m.ring_point));
  // Another pair at the same distance within rounding: the whole ring (a line on the axis), the
  // mirror-image minimum when b1 is (nearly) zero (the mirror point bounds it from above), or
  // a distance flat to rounding over the ring (a line within rounding of the center's axis).
  const Real scale = std::max(c.radius, m.anchor.norm());
  r.unique = !m.on_axis &&
             !(tied_with_mirror(c, m) && (m.mirror - m.ring_point).norm() > distinct_points_tolerance(scale));
  return r;
}

// A ray or segment whose full line has its minimum over the ring on the piece has that minimum
// too: the piece is part of the line, so it is no closer, and it holds the line's closest point.
// Then one bracketed root answers it, as for a full line; otherwise (or where the line's minimum
// is tied with its mirror image, either of which might be the piece's) the general path does.
// A segment's line is taken through p0 along the rounded p1 - p0, which misses p1 by about eps
// times its length: only segments shorter than 64 radii (an error below 64 eps R) take it.
template <class Real> struct PieceLine {
  Line3<Real> line;
  bool usable = true;
};
template <class Real> PieceLine<Real> piece_line(const Line3<Real>& l, Real) { return {l}; }
template <class Real> PieceLine<Real> piece_line(const Ray3<Real>& r, Real) { return {{r.origin, r.direction}}; }
template <class Real> PieceLine<Real> piece_line(const Segment3<Real>& s, Real radius) {
  const Vec3<Real> d = s.p1 - s.p0;
  return {{s.p0, d}, d.squaredNorm() <= 4096 * radius * radius};
}

// Whether `point` (relative to `center`) of `line` lies on the piece: its parameter on the line,
// which is the piece's own parametrization, within [lo, hi].
template <class Real>
bool on_piece(const Line3<Real>& line, const Vec3<Real>& center, const Vec3<Real>& point, const Linear<Real>& piece) {
  const Real t = (point - (line.origin - center)).dot(line.direction) / line.direction.squaredNorm();
  return t >= piece.lo && t <= piece.hi;
}

// The line's minimum over the ring for a piece: false where the general path must answer.
// `for_closest` also leaves out ties (the piece may hold one of the pair, so be unique).
template <class Roots, class Piece, class Real>
bool piece_ring_minimum(const Piece& piece, const Circle3<Real>& c, Line3<Real>& line, LineRingMinimum<Real>& m,
                        bool for_closest) {
  const PieceLine<Real> pl = piece_line(piece, c.radius);
  line = pl.line;
  return pl.usable && line_ring_minimum<Roots>(line, c, m) && on_piece(line, c.center, m.line_point, as_linear(piece)) &&
         !(for_closest && tied_with_mirror(c, m));
}

template <class Real> struct Query<Line3<Real>, Circle3<Real>> {
  static constexpr bool defined = true;
  using General = LinearCircleQuery<Real, Line3<Real>>;

  template <class Roots = DefaultRoots> static Real distance(const Line3<Real>& line, const Circle3<Real>& c) {
    LineRingMinimum<Real> m;
    if (!line_ring_minimum<Roots>(line, c, m)) return General::template distance<Roots>(line, c);
    return m.distance;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Line3<Real>& line, const Circle3<Real>& c) {
    LineRingMinimum<Real> m;
    if (!line_ring_minimum<Roots>(line, c, m)) return General::template closest<Roots>(line, c);
    return line_ring_result(line, c, m);
  }
};

// Rays and segments: the full line's answer where piece_ring_minimum allows, else the general path.
template <class Real, class Piece> struct PieceCircleQuery : LinearCircleQuery<Real, Piece> {
  using General = LinearCircleQuery<Real, Piece>;

  template <class Roots = DefaultRoots> static Real distance(const Piece& piece, const Circle3<Real>& c) {
    Line3<Real> line;
    LineRingMinimum<Real> m;
    if (piece_ring_minimum<Roots>(piece, c, line, m, false)) return m.distance;
    return General::template distance<Roots>(piece, c);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Piece& piece, const Circle3<Real>& c) {
    Line3<Real> line;
    LineRingMinimum<Real> m;
    if (piece_ring_minimum<Roots>(piece, c, line, m, true)) return line_ring_result(line, c, m);
    return General::template closest<Roots>(piece, c);
  }
};

template <class Real> struct Query<Ray3<Real>, Circle3<Real>> : PieceCircleQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Circle3<Real>> : PieceCircleQuery<Real, Segment3<Real>> {};

}  // namespace circledist
