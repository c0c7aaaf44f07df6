// Line, ray and segment against a circle: note 000 §1 (the quartic), restricted to the piece's
// interval with its end points added for rays and segments.
#pragma once

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

template <class Real> struct Query<Line3<Real>, Circle3<Real>> : LinearCircleQuery<Real, Line3<Real>> {};
template <class Real> struct Query<Ray3<Real>, Circle3<Real>> : LinearCircleQuery<Real, Ray3<Real>> {};
template <class Real> struct Query<Segment3<Real>, Circle3<Real>> : LinearCircleQuery<Real, Segment3<Real>> {};

}  // namespace circledist
