// Bezier-Bezier (Query<BezierCurve3, BezierCurve3>). Derivation: docs/derivations/bezier_bezier.md.
//
// Bezier curves against Bezier curves: the global minimum of |A(s) - B(t)| over s, t in [0, 1]
// (docs/derivations/bezier_bezier.md).
//
// A closest pair either has s or t at an end of its interval, or is a stationary point of the
// squared distance F(s, t) = |A(s) - B(t)|^2 inside the square. The four edges (A(0), A(1)
// against B, B(0), B(1) against A) are the Bezier-point query (bezier_point.hpp), always
// evaluated (§2). The interior is searched by a branch and bound over pairs of sub-curves (§3):
// a piece's control points hold it, so a separating axis between two pieces' control polygons
// bounds their distance from below, and their end points (points of the curves) bound the
// minimum from above; pairs that cannot beat the best value so far are dropped, the others are
// halved (the longer piece, by blossoming from the whole curve) until both pieces are flat. Each
// surviving flat pair is solved locally (§4): its chords' closest pair (the segment query,
// linear_linear.hpp) seeds damped Newton steps on the true squared distance of the whole curves;
// a descent that ends above what the chords promise (their distance plus the pieces' deviation
// from them) ran into another basin, and the pair is halved further (§3).
// The smallest candidate wins; distinct tied candidates make `unique` false (§5).
#pragma once

#include "bezier_point.hpp"
#include "linear_linear.hpp"
#include "query.hpp"
#include "detail/minimize.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace circledist {

namespace detail {

template <class Real> struct CurvePairSolver {
  using Points = std::array<Vec3<Real>, kMaxBezierDegree + 1>;

  // One candidate closest pair: parameters, the distance and the points (local coordinates for
  // the interior, world for the edges' point queries); `tied` when its own query saw a tie (an
  // end point equidistant from two points of the other curve).
  struct Candidate {
    Real s = 0, t = 0, value = std::numeric_limits<Real>::infinity();
    Vec3<Real> pa = Vec3<Real>::Zero(), pb = Vec3<Real>::Zero();
    bool tied = false;
  };

  // A pair of pieces (§3): their spans, local control points and lower bound.
  struct Pair {
    Real lower;
    Real a0, a1, b0, b1;
    Points qa, qb;
  };

  // §3: the piece [t0, t1] of a curve by blossoming: its k-th control point is the polar form at
  // (t0 x (n - k), t1 x k), each from the whole curve's points, so that a piece's rounding does
  // not grow with the depth of the halving (as PreciseBezier::piece does in double-double; in
  // Real here, the bar being relative to the curves' size, not to a far round's).
  static Points blossom(const Points& q, int n, Real t0, Real t1) {
    Points out{};
    for (int k = 0; k <= n; ++k) {
      Points p;
      for (int i = 0; i <= n; ++i) p[i] = q[i];
      for (int level = 0; level < n; ++level) {
        const Real t = level < n - k ? t0 : t1;
        for (int i = 0; i + level < n; ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
      }
      out[k] = p[0];
    }
    return out;
  }

  // §3: a lower bound on the distance between two pieces from their control polygons (which
  // hold them): the larger of the gap between their bounding boxes and the separation of their
  // projections on the axis joining the boxes' centers (tight to second order in the pieces'
  // size when the axis is the direction of closest approach, where the boxes' gap is not).
  static Real lower_bound(const Points& qa, int na, const Points& qb, int nb) {
    Vec3<Real> loa = qa[0], hia = qa[0], lob = qb[0], hib = qb[0];
    for (int i = 1; i <= na; ++i) {
      loa = loa.cwiseMin(qa[i]);
      hia = hia.cwiseMax(qa[i]);
    }
    for (int i = 1; i <= nb; ++i) {
      lob = lob.cwiseMin(qb[i]);
      hib = hib.cwiseMax(qb[i]);
    }
    const Vec3<Real> gap = (lob - hia).cwiseMax(loa - hib).cwiseMax(Vec3<Real>::Zero());
    Real lower = std::sqrt(gap.squaredNorm());
    const Vec3<Real> axis = (lob + hib) / 2 - (loa + hia) / 2;
    const Real length = std::sqrt(axis.squaredNorm());
    if (length > 0) {
      const Vec3<Real> u = axis / length;
      Real top = -std::numeric_limits<Real>::infinity(), bottom = std::numeric_limits<Real>::infinity();
      for (int i = 0; i <= na; ++i) top = std::max(top, qa[i].dot(u));
      for (int i = 0; i <= nb; ++i) bottom = std::min(bottom, qb[i].dot(u));
      lower = std::max(lower, bottom - top);
    }
    return lower;
  }

  // §3: a piece is flat when its control points lie within kFlat of its chord's length from the
  // chord (the segment between its end points, so that a piece folding back along its chord is
  // not flat); `off`, that largest distance, bounds how far the piece strays from the chord (its
  // convex hull does not stray farther). Its extent (the farthest control point from the first)
  // picks the piece to halve.
  static constexpr Real kFlat = Real(1) / 32;
  static bool flat(const Points& q, int n, Real& extent, Real& off) {
    const Vec3<Real> chord = q[n] - q[0];
    const Real length2 = chord.squaredNorm();
    extent = 0;
    off = 0;
    for (int i = 1; i <= n; ++i) {
      const Vec3<Real> d = q[i] - q[0];
      extent = std::max(extent, std::sqrt(d.squaredNorm()));
      const Real x = length2 > 0 ? std::min(std::max(d.dot(chord) / length2, Real(0)), Real(1)) : Real(0);
      off = std::max(off, std::sqrt((d - x * chord).squaredNorm()));
    }
    return off <= kFlat * std::sqrt(length2);
  }

  // A point, its first and second derivatives along a local curve.
  static void derivatives(const LocalBezier<Real>& c, Real t, Vec3<Real>& p, Vec3<Real>& p1, Vec3<Real>& p2) {
    p = c.at(t);
    p1 = c.n >= 1 ? LocalBezier<Real>::casteljau(c.d1, c.n - 1, t) : Vec3<Real>::Zero();
    p2 = c.n >= 2 ? LocalBezier<Real>::casteljau(c.d2, c.n - 2, t) : Vec3<Real>::Zero();
  }

  // §4: from (s, t), damped Newton (Levenberg-Marquardt) steps on the true squared distance
  // F(s, t) = |A(s) - B(t)|^2 over [0, 1]^2 (steps clamped to the square: a minimum on its edge
  // is the edges' point query's, §2), each kept only if F decreases; the damping grows where the
  // Hessian is not positive definite or a step fails (a saddle, the flat valley of nearly
  // parallel pieces), and shrinks after every success, so that the last steps are Newton's.
  //
  // A flat valley (nearly parallel pieces, where F varies by little along a curve of pairs: a
  // near-continuum of closest pairs) leaves the Hessian nearly singular; the steps along the
  // valley are then damped to a crawl and stop short of its lowest point, by up to how much F
  // varies along it (4.8e-13 of the curves' size for two nearly parallel straight cubics
  // translated by 1e6 and rotated, over the long-double bar). There the valley is searched in one
  // parameter: g(s) = min over t of F(s, t) (valley_minimum), over the pair's span [s_lo, s_hi].
  static Candidate polish(const LocalBezier<Real>& ca, const LocalBezier<Real>& cb, Real s, Real t, Real tol_s,
                          Real tol_t, Real s_lo, Real s_hi) {
    Vec3<Real> a, a1, a2, b, b1, b2;
    const auto state = [&](Real x, Real y, Real& f, Real& g1, Real& g2, Real& h11, Real& h12, Real& h22) {
      derivatives(ca, x, a, a1, a2);
      derivatives(cb, y, b, b1, b2);
      const Vec3<Real> r = a - b;
      f = r.squaredNorm();
      g1 = r.dot(a1);  // half the gradient and Hessian of F
      g2 = -r.dot(b1);
      h11 = a1.squaredNorm() + r.dot(a2);
      h22 = b1.squaredNorm() - r.dot(b2);
      h12 = -a1.dot(b1);
    };
    Real f, g1, g2, h11, h12, h22;
    state(s, t, f, g1, g2, h11, h12, h22);
    Real lambda = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      // A parameter on its bound where F rises inward is held there (projected Newton): the
      // step is then one-dimensional along the edge; both held, a corner is the minimum within
      // reach. The edges' own minima are the point queries' (§2); this keeps a descent that
      // starts on an edge (a chords' closest pair at an end of a piece) from stopping there
      // while F falls inward.
      const bool hold_s = (s == 0 && g1 > 0) || (s == 1 && g1 < 0);
      const bool hold_t = (t == 0 && g2 > 0) || (t == 1 && g2 < 0);
      if (hold_s && hold_t) break;
      const Real mu = lambda * (std::abs(h11) + std::abs(h22));
      const Real a11 = h11 + mu, a22 = h22 + mu, det = a11 * a22 - h12 * h12;
      const bool definite = hold_s ? a22 > 0 : hold_t ? a11 > 0 : (a11 > 0 && a22 > 0 && det > 0 && std::isfinite(det));
      if (!definite) {
        lambda = lambda == 0 ? Real(1e-6) : lambda * 8;
        if (!(lambda < Real(1e12)) || !(std::abs(h11) + std::abs(h22) > 0)) break;
        continue;
      }
      const Real ds = hold_s ? Real(0) : hold_t ? -g1 / a11 : (-g1 * a22 + g2 * h12) / det;
      const Real dt = hold_t ? Real(0) : hold_s ? -g2 / a22 : (-g2 * a11 + g1 * h12) / det;
      const Real ns = std::min(std::max(s + ds, Real(0)), Real(1)), nt = std::min(std::max(t + dt, Real(0)), Real(1));
      if (ns == s && nt == t) break;  // converged, or held at the square's edge
      Real nf, n1, n2, m11, m12, m22;
      state(ns, nt, nf, n1, n2, m11, m12, m22);
      // Converged only on an undamped (Newton) step below the tolerance: a damped step is short
      // because of the damping, not because the minimum is near.
      const bool small = lambda == 0 && std::abs(ns - s) <= tol_s && std::abs(nt - t) <= tol_t;
      if (nf < f) {
        s = ns, t = nt, f = nf, g1 = n1, g2 = n2, h11 = m11, h12 = m12, h22 = m22;
        lambda = lambda < Real(1e-5) ? Real(0) : lambda / 8;
        if (small) break;
      } else {
        if (small) break;  // a Newton step below the tolerance that does not lower F: rounding at the minimum
        lambda = lambda == 0 ? Real(1e-6) : lambda * 8;
        if (!(lambda < Real(1e12))) break;
      }
    }
    // Nearly singular: det below 1e-6 of h11 h22 (the tangents within about 1e-3 rad of parallel).
    if (h11 > 0 && h22 > 0 && h11 * h22 - h12 * h12 <= Real(1e-6) * h11 * h22)
      valley_minimum(ca, cb, s, t, f, tol_s, tol_t, s_lo, s_hi);
    Candidate c;
    c.s = s;
    c.t = t;
    c.pa = ca.at(s);
    c.pb = cb.at(t);
    c.value = std::sqrt((c.pa - c.pb).squaredNorm());
    return c;
  }

  // t in [0, 1] nearest B(t) to the point p, by Newton on |p - B(t)|^2 from t (clamped to the
  // interval); near a valley's pairs the minimum over t is simple (B's tangent is not parallel to
  // itself), so a few steps from the last one's t suffice.
  static Real nearest_t(const LocalBezier<Real>& cb, const Vec3<Real>& p, Real t, Real tol_t) {
    Vec3<Real> b, b1, b2;
    for (int iteration = 0; iteration < 32; ++iteration) {
      derivatives(cb, t, b, b1, b2);
      const Vec3<Real> r = p - b;
      const Real slope = -r.dot(b1), curvature = b1.squaredNorm() - r.dot(b2);
      if (!(curvature > 0)) break;
      const Real next = std::min(std::max(t - slope / curvature, Real(0)), Real(1));
      const bool done = std::abs(next - t) <= tol_t;
      t = next;
      if (done) break;
    }
    return t;
  }

  // §4: the valley's lowest point: Brent's minimization (detail/minimize.hpp) of g(s) = min over t of
  // F(s, t) over [s_lo, s_hi] from s, each g by nearest_t from the last t; (s, t) and f move
  // only where it finds a lower F.
  static void valley_minimum(const LocalBezier<Real>& ca, const LocalBezier<Real>& cb, Real& s, Real& t, Real& f,
                             Real tol_s, Real tol_t, Real s_lo, Real s_hi) {
    if (!(s_hi > s_lo)) return;
    Real t_last = t;
    const auto g = [&](Real x) {
      const Vec3<Real> a = ca.at(x);
      t_last = nearest_t(cb, a, t_last, tol_t);
      return (a - cb.at(t_last)).squaredNorm();
    };
    Real value = g(s);
    const Real x = brent_minimize(g, s_lo, s_hi, std::min(std::max(s, s_lo), s_hi), value, tol_s);
    const Real y = nearest_t(cb, ca.at(x), t_last, tol_t);
    const Real fy = (ca.at(x) - cb.at(y)).squaredNorm();
    if (fy < f) {
      s = x;
      t = y;
      f = fy;
    }
  }

  // §3-§4: the interior candidates, appended to `out`; `upper` is the best value so far (the
  // edges'), lowered as the search goes.
  template <class Roots> static void interior(const LocalBezier<Real>& ca, const LocalBezier<Real>& cb, Real scale,
                                              Real upper, std::vector<Candidate>& out) {
    // At most kMaxLeaves flat pairs are polished and kMaxPairs pairs examined: a continuum of
    // closest pairs (identical or parallel curves) keeps every pair along it alive; past the caps
    // the pairs left are polished as they are, while leaves remain.
    constexpr int kMaxLeaves = 192, kMaxPairs = 2048;
    const int na = ca.n, nb = cb.n;
    const Real tie = tie_tolerance(scale) + 8 * Real(na + nb + 2) * std::numeric_limits<Real>::epsilon() * scale;
    const Real tol_s = parameter_tolerance(ca.speed, scale), tol_t = parameter_tolerance(cb.speed, scale);
    // The pairs are kept in a pool and the heap orders their bounds and places (a min-heap on
    // `lower`, best first), so that the heap moves a few numbers, not control points.
    struct Entry {
      Real lower;
      int index;
    };
    const auto later = [](const Entry& x, const Entry& y) { return x.lower > y.lower; };
    std::vector<Pair> pool;
    std::vector<Entry> heap;
    pool.reserve(64);
    heap.reserve(64);
    pool.push_back({lower_bound(ca.q, na, cb.q, nb), Real(0), Real(1), Real(0), Real(1), ca.q, cb.q});
    heap.push_back({pool.back().lower, 0});
    int leaves = 0, pairs = 0;
    while (!heap.empty() && leaves < kMaxLeaves) {
      std::pop_heap(heap.begin(), heap.end(), later);
      const Pair p = pool[heap.back().index];
      heap.pop_back();
      if (p.lower > upper + tie) break;  // best first: every pair left is as far
      ++pairs;
      // The pieces' end points are points of the curves: the minimum is at most their distance.
      for (const int i : {0, na})
        for (const int j : {0, nb}) upper = std::min(upper, std::sqrt((p.qa[i] - p.qb[j]).squaredNorm()));
      Real extent_a, extent_b, off_a, off_b;
      const bool flat_a = flat(p.qa, na, extent_a, off_a), flat_b = flat(p.qb, nb, extent_b, off_b);
      bool described = false;
      if ((flat_a && flat_b) || pairs >= kMaxPairs) {
        // §4: a flat pair (or one past the caps): its chords' closest pair seeds the polish.
        ++leaves;
        const Result<Real> seed = Query<Segment3<Real>, Segment3<Real>>::template closest<Roots>(
            Segment3<Real>{p.qa[0], p.qa[na]}, Segment3<Real>{p.qb[0], p.qb[nb]});
        const Real u = std::isfinite(seed.param_a.x()) ? seed.param_a.x() : Real(0.5);
        const Real v = std::isfinite(seed.param_b.x()) ? seed.param_b.x() : Real(0.5);
        const Candidate c =
            polish(ca, cb, p.a0 + u * (p.a1 - p.a0), p.b0 + v * (p.b1 - p.b0), tol_s, tol_t, p.a0, p.a1);
        if (c.value < upper) upper = c.value;
        out.push_back(c);
        // §3: the pieces lie within off_a and off_b of their chords, so the pair's minimum is at most
        // the chords' distance plus both; a descent that ends above that left a better minimum of
        // the pair behind (it ran into another basin): the pair is halved further, its pieces then
        // searched in turn.
        described = !(c.value > seed.distance + off_a + off_b + tie);
      }
      if (described || pairs >= kMaxPairs) continue;
      const bool split_a = flat_a == flat_b ? extent_a >= extent_b : !flat_a;
      const Real mid_a = (p.a0 + p.a1) / 2, mid_b = (p.b0 + p.b1) / 2;
      const bool can_a = mid_a > p.a0 && mid_a<p.a1, can_b = mid_b> p.b0 && mid_b < p.b1;
      const bool halve_a = split_a ? can_a : !can_b && can_a, halve_b = !halve_a && can_b;
      if (!halve_a && !halve_b) continue;  // neither span splits any more (t at rounding)
      for (int half = 0; half < 2; ++half) {
        Pair child = p;
        if (halve_a) {
          child.a0 = half == 0 ? p.a0 : mid_a;
          child.a1 = half == 0 ? mid_a : p.a1;
          child.qa = blossom(ca.q, na, child.a0, child.a1);
        } else {
          child.b0 = half == 0 ? p.b0 : mid_b;
          child.b1 = half == 0 ? mid_b : p.b1;
          child.qb = blossom(cb.q, nb, child.b0, child.b1);
        }
        child.lower = lower_bound(child.qa, na, child.qb, nb);
        if (child.lower > upper + tie) continue;
        pool.push_back(child);
        heap.push_back({child.lower, int(pool.size()) - 1});
        std::push_heap(heap.begin(), heap.end(), later);
      }
    }
  }
};

// A curve against a curve: the edges (§2), the interior (§3-§4), the smallest candidate and its
// `unique` (§5). Degree 0 curves are points: the Bezier-point query answers them.
template <class Real> struct BezierBezierPair {
  static constexpr bool defined = true;
  using Solver = CurvePairSolver<Real>;
  using Candidate = typename Solver::Candidate;
  using PointQuery = Query<BezierCurve3<Real>, Vec3<Real>>;

  template <class Roots = DefaultRoots>
  static Result<Real> closest(const BezierCurve3<Real>& a, const BezierCurve3<Real>& b) {
    if (a.control.cols() == 0 || b.control.cols() == 0) return empty_curve_result<Real>();
    if (a.control.cols() == 1) {
      Result<Real> r = PointQuery::template closest<Roots>(b, Vec3<Real>(a.control.col(0))).swapped();
      return r;
    }
    if (b.control.cols() == 1) return PointQuery::template closest<Roots>(a, Vec3<Real>(b.control.col(0)));
    // §1: one local frame for both curves, centered at A's first control point (the frame of the
    // z axis, a permutation: exact), so that translated scenes lose nothing to the subtraction.
    const Round<Real> round(Vec3<Real>(a.control.col(0)), Vec3<Real>(0, 0, 1), Real(0));
    const LocalBezier<Real> ca(a, round), cb(b, round);
    const Real scale = std::max(bezier_round_scale(ca, Real(0)), bezier_round_scale(cb, Real(0)));
    // §2: the edges, each the Bezier-point query of an end point against the other curve.
    std::vector<Candidate> found;
    found.reserve(16);
    const int na = a.degree(), nb = b.degree();
    for (const int i : {0, na}) {
      const Vec3<Real> p = a.control.col(i);
      const Result<Real> r = PointQuery::template closest<Roots>(b, p);
      Candidate c;
      c.s = Real(i == 0 ? 0 : 1);
      c.t = r.param_a.x();
      c.value = r.distance;
      c.pa = p;
      c.pb = r.point_a;
      c.tied = !r.unique;
      found.push_back(c);
    }
    for (const int j : {0, nb}) {
      const Vec3<Real> p = b.control.col(j);
      const Result<Real> r = PointQuery::template closest<Roots>(a, p);
      Candidate c;
      c.s = r.param_a.x();
      c.t = Real(j == 0 ? 0 : 1);
      c.value = r.distance;
      c.pa = r.point_a;
      c.pb = p;
      c.tied = !r.unique;
      found.push_back(c);
    }
    const int edges = int(found.size());
    Real upper = std::numeric_limits<Real>::infinity();
    for (const Candidate& c : found) upper = std::min(upper, c.value);
    // §3-§4: the interior, in local coordinates; its points are moved to world coordinates below.
    if (std::isfinite(upper)) Solver::template interior<Roots>(ca, cb, scale, upper, found);
    int best = 0;
    for (int i = 1; i < int(found.size()); ++i)
      if (found[i].value < found[best].value) best = i;
    Result<Real> r;
    const Candidate& w = found[best];
    r.distance = w.value;
    r.param_a = Vec2<Real>(w.s, 0);
    r.param_b = Vec2<Real>(w.t, 0);
    r.point_a = best < edges ? w.pa : a.at(w.s);
    r.point_b = best < edges ? w.pb : b.at(w.t);
    // §5: another candidate within the tie tolerance at a point farther than the distinct-points
    // tolerance (of each curve's own size) from the best one's, or a tie inside an edge's query.
    const Real tie = tie_tolerance(std::max(scale, w.value));
    const Real apart_a = std::max(distinct_points_tolerance(std::min(scale, ca.size)), tie);
    const Real apart_b = std::max(distinct_points_tolerance(std::min(scale, cb.size)), tie);
    const auto local_a = [&](int i) { return i < edges ? round.local(found[i].pa) : found[i].pa; };
    const auto local_b = [&](int i) { return i < edges ? round.local(found[i].pb) : found[i].pb; };
    const Vec3<Real> best_a = local_a(best), best_b = local_b(best);
    for (int i = 0; i < int(found.size()); ++i) {
      if (!(found[i].value <= w.value + tie)) continue;
      if (found[i].tied || (local_a(i) - best_a).norm() > apart_a || (local_b(i) - best_b).norm() > apart_b) {
        r.unique = false;
        break;
      }
    }
    return r;
  }

  template <class Roots = DefaultRoots> static Real distance(const BezierCurve3<Real>& a, const BezierCurve3<Real>& b) {
    return closest<Roots>(a, b).distance;
  }
};

}  // namespace detail

template <class Real> struct Query<BezierCurve3<Real>, BezierCurve3<Real>> : detail::BezierBezierPair<Real> {};

}  // namespace circledist
