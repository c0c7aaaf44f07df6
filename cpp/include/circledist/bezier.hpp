// Bezier curves (degree 1 to 7, t in [0, 1]) against disks and circles: note 001 §3 with
// polynomial curves. In the round's local frame (center subtracted from the control points
// first, exact for translated scenes) the curve is converted to the power basis in w = 2t - 1,
// the variable whose roots of interest lie in [-1, 1], where the power basis is best
// conditioned. Against a disk, [0, 1] is cut where x^2 + y^2 = r^2 (degree 2n); inside pieces
// minimize |z| (z = 0 or z' = 0, degrees n and n-1); outside pieces use note 001 eq. (2)
// squared, degree 6n - 2 (28 for a quintic). Against a circle only the last equation is needed.
// Squaring adds extraneous roots; they are harmless because every candidate is judged (and
// polished) on the exact point-round distance, never on the polynomial.
#pragma once

#include "detail/circle_over_round.hpp"
#include "detail/double_double.hpp"

#include <array>
#include <type_traits>
#include <vector>

namespace circledist {

constexpr int kMaxBezierDegree = 7;
static_assert(6 * kMaxBezierDegree - 2 <= kMaxCurveDegree, "circledist: curve polynomials exceed kMaxCurveDegree");

// Control points P_0 .. P_n as the columns of a fixed-capacity matrix (no heap): the curve is
// sum_i C(n, i) t^i (1 - t)^(n - i) P_i for t in [0, 1]. A single column is a point; no column
// is the empty set, at distance +infinity (the infimum over nothing) from everything.
template <class Real> struct BezierCurve3 {
  using ControlPoints = Eigen::Matrix<Real, 3, Eigen::Dynamic, Eigen::ColMajor, 3, kMaxBezierDegree + 1>;
  ControlPoints control;

  int degree() const { return int(control.cols()) - 1; }

  // De Casteljau: convex combinations only, exact at t = 0 and t = 1.
  Vec3<Real> at(Real t) const {
    std::array<Vec3<Real>, kMaxBezierDegree + 1> q;
    const int n = degree();
    for (int i = 0; i <= n; ++i) q[i] = control.col(i);
    for (int k = n; k > 0; --k) {
      for (int i = 0; i < k; ++i) q[i] = (1 - t) * q[i] + t * q[i + 1];
    }
    return q[0];
  }
};

// The order of same-kind queries (primitives.hpp): by degree, then control point by point.
template <class Real> bool precedes(const BezierCurve3<Real>& x, const BezierCurve3<Real>& y) {
  if (x.control.cols() != y.control.cols()) return x.control.cols() < y.control.cols();
  return std::lexicographical_compare(x.control.data(), x.control.data() + x.control.size(), y.control.data(),
                                      y.control.data() + y.control.size());
}

// As for the other primitives (primitives.hpp): the curve scaled by 2^e, its largest
// coordinate, and the same curve in double.
template <class Real> BezierCurve3<Real> scaled(const BezierCurve3<Real>& b, int e) {
  BezierCurve3<Real> out = b;
  for (int i = 0; i < int(b.control.cols()); ++i) out.control.col(i) = detail::ldexp3(Vec3<Real>(b.control.col(i)), e);
  return out;
}
template <class Real> Real extent(const BezierCurve3<Real>& b) {
  return b.control.cols() > 0 ? b.control.cwiseAbs().maxCoeff() : Real(0);
}
template <class Real, if_float<Real> = 0> BezierCurve3<double> promoted(const BezierCurve3<Real>& b) {
  BezierCurve3<double> out;
  out.control = b.control.template cast<double>();
  return out;
}

// A polynomial of degree <= kMaxCurveDegree, coefficients ascending.
template <class Real> struct CurvePoly {
  std::array<Real, kMaxCurveDegree + 1> c{};
  int degree = 0;

  CurvePoly derivative() const {
    CurvePoly d;
    d.degree = std::max(degree - 1, 0);
    for (int i = 1; i <= degree; ++i) d.c[i - 1] = i * c[i];
    return d;
  }
};

template <class Real> CurvePoly<Real> operator*(const CurvePoly<Real>& a, const CurvePoly<Real>& b) {
  CurvePoly<Real> p;
  p.degree = a.degree + b.degree;
  for (int i = 0; i <= a.degree; ++i) {
    for (int j = 0; j <= b.degree; ++j) p.c[i + j] += a.c[i] * b.c[j];
  }
  return p;
}

template <class Real> CurvePoly<Real> operator+(const CurvePoly<Real>& a, const CurvePoly<Real>& b) {
  CurvePoly<Real> p;
  p.degree = std::max(a.degree, b.degree);
  for (int i = 0; i <= p.degree; ++i) p.c[i] = a.c[i] + b.c[i];
  return p;
}

// (A const reference and a local copy, here and wherever a function changes a copy of an
// aggregate: built by GCC 12 with -flto, functions that changed an aggregate parameter passed by
// value gave wrong answers, hidden by -fno-ipa-modref; cpp/tests/lto_aggregates.cpp.)
template <class Real> CurvePoly<Real> operator*(Real s, const CurvePoly<Real>& a) {
  CurvePoly<Real> p = a;
  for (int i = 0; i <= p.degree; ++i) p.c[i] *= s;
  return p;
}

template <class Real> CurvePoly<Real> operator-(const CurvePoly<Real>& a, const CurvePoly<Real>& b) {
  return a + Real(-1) * b;
}

// The curve in a round's local frame: control points q_i = frame(P_i - center), and the control
// points of its first and second derivatives in t.
template <class Real> struct LocalBezier {
  int n = 0;
  std::array<Vec3<Real>, kMaxBezierDegree + 1> q{}, d1{}, d2{};
  Real speed = 0;  // max |P'(t)|, bounded by the largest hodograph control point
  Real size = 0;   // max |q_i - q_0|, the curve's extent

  LocalBezier(const BezierCurve3<Real>& b, const Round<Real>& round) : n(std::max(b.degree(), 0)) {
    for (int i = 0; i <= n && i < int(b.control.cols()); ++i) q[i] = round.local(b.control.col(i));
    derive();
  }

  // A curve from its local control points (a piece of another, piece_of below).
  LocalBezier(const std::array<Vec3<Real>, kMaxBezierDegree + 1>& local, int degree) : n(degree), q(local) { derive(); }

  void derive() {
    for (int i = 0; i <= n; ++i) size = std::max(size, (q[i] - q[0]).norm());
    for (int i = 0; i < n; ++i) {
      d1[i] = Real(n) * (q[i + 1] - q[i]);
      speed = std::max(speed, d1[i].norm());
    }
    for (int i = 0; i + 1 < n; ++i) d2[i] = Real(n - 1) * (d1[i + 1] - d1[i]);
  }

  static Vec3<Real> casteljau(std::array<Vec3<Real>, kMaxBezierDegree + 1> p, int m, Real t) {
    for (int k = m; k > 0; --k) {
      for (int i = 0; i < k; ++i) p[i] = (1 - t) * p[i] + t * p[i + 1];
    }
    return p[0];
  }

  Vec3<Real> at(Real t) const { return casteljau(q, n, t); }

  // The target's (round_target.hpp) squared distance and its derivatives at t.
  template <class Target> Jet<Real> jet(Real t, Real radius) const {
    const Vec3<Real> p1 = n >= 1 ? casteljau(d1, n - 1, t) : Vec3<Real>::Zero();
    const Vec3<Real> p2 = n >= 2 ? casteljau(d2, n - 2, t) : Vec3<Real>::Zero();
    return Target::jet(at(t), p1, p2, radius);
  }

  // Coordinate i in the power basis of w = 2t - 1, in units of `scale`:
  // C(n, k) t^k (1-t)^(n-k) = C(n, k) 2^-n (1 + w)^k (1 - w)^(n-k).
  CurvePoly<Real> coordinate(int i, Real scale) const {
    CurvePoly<Real> out;
    out.degree = n;
    Real binomial = 1;  // C(n, k)
    for (int k = 0; k <= n; ++k) {
      std::array<Real, kMaxBezierDegree + 1> basis{};
      basis[0] = 1;
      for (int m = 0; m < n; ++m) {  // times (1 + w) for m < k, then (1 - w)
        const Real sign = m < k ? Real(1) : Real(-1);
        for (int j = m + 1; j > 0; --j) basis[j] = basis[j] + sign * basis[j - 1];
      }
      const Real weight = binomial * std::ldexp(q[k][i] / scale, -n);
      for (int j = 0; j <= n; ++j) out.c[j] += weight * basis[j];
      binomial = binomial * Real(n - k) / Real(k + 1);
    }
    return out;
  }
};

// The curve's local control points in double-double, and its pieces. A curve far larger than
// the round (1e5 times, or one control point 1e10 away) is solved piece by piece
// (CurveRoundBase::solve_pieces); a piece next to the round has control points of the round's
// size, but computed in plain arithmetic they would carry eps times the curve's farthest control
// point (1e-11 radii for a curve 1e5 times larger), above the bar. Here the control points are
// moved into the round's frame in double-double (the difference from the center exactly, the
// rotation with exact products) and each piece is cut from them in double-double, so a piece's
// points, and the polynomials built from them, are as accurate as a small curve's.
template <class Real> struct PreciseBezier {
  using DD = detail::DoubleDouble<Real>;
  using Point = std::array<DD, 3>;
  int n = 0;
  std::array<Point, kMaxBezierDegree + 1> q{};

  PreciseBezier() = default;
  PreciseBezier(const BezierCurve3<Real>& b, const Round<Real>& round) : n(std::max(b.degree(), 0)) {
    const Frame<Real>& f = round.frame;
    const Vec3<Real>* axes[3] = {&f.u, &f.v, &f.n};
    for (int i = 0; i <= n; ++i) {
      Point offset;  // P_i - center, exactly
      for (int j = 0; j < 3; ++j) offset[j] = DD::two_sum(b.control(j, i), -round.center[j]);
      for (int k = 0; k < 3; ++k) {
        DD sum;
        Real small = 0;  // the rotation of the difference's low parts: plain arithmetic suffices
        for (int j = 0; j < 3; ++j) {
          sum = sum + DD::two_product((*axes[k])[j], offset[j].hi);
          small += (*axes[k])[j] * offset[j].lo;
        }
        q[i][k] = sum + DD(small);
      }
    }
  }

  // The piece t in [t0, t1] by blossoming: its k-th control point is the polar form at
  // (t0 x (n - k), t1 x k), de Casteljau's steps with t0 then t1, each from the whole curve's
  // points (repeated halving would carry a far control point's rounding into every piece).
  PreciseBezier piece(Real t0, Real t1) const {
    PreciseBezier out;
    out.n = n;
    for (int k = 0; k <= n; ++k) {
      std::array<Point, kMaxBezierDegree + 1> p = q;
      for (int level = 0; level < n; ++level) {
        const Real t = level < n - k ? t0 : t1;
        for (int i = 0; i + level < n; ++i) p[i] = lerp(p[i], p[i + 1], t);
      }
      out.q[k] = p[0];
    }
    return out;
  }

  Vec3<Real> at(Real t) const {
    std::array<Point, kMaxBezierDegree + 1> p = q;
    for (int k = n; k > 0; --k) {
      for (int i = 0; i < k; ++i) p[i] = lerp(p[i], p[i + 1], t);
    }
    return rounded(p[0]);
  }

  std::array<Vec3<Real>, kMaxBezierDegree + 1> rounded() const {
    std::array<Vec3<Real>, kMaxBezierDegree + 1> out{};
    for (int i = 0; i <= n; ++i) out[i] = rounded(q[i]);
    return out;
  }

 private:
  static Point lerp(const Point& a, const Point& b, Real t) {
    Point out;
    for (int j = 0; j < 3; ++j) out[j] = a[j] + (b[j] - a[j]) * t;
    return out;
  }
  static Vec3<Real> rounded(const Point& p) { return Vec3<Real>(p[0].value(), p[1].value(), p[2].value()); }
};

// Where the best minimum of a curve solved in pieces lies: its piece and the piece's parameter,
// so that its point is evaluated there (at the curve's t, rounded to Real, a point 1e10 radii
// along the curve per unit of t would move by 1e-6 radii per ulp).
template <class Real> struct BestPiece {
  PreciseBezier<Real> piece;
  Real s = 0;
  bool valid = false;
};

template <class Real> Real bezier_round_scale(const LocalBezier<Real>& c, Real radius) {
  Real s = radius;
  for (int i = 0; i <= c.n; ++i) s = std::max(s, c.q[i].norm());
  return s > 0 ? s : Real(1);
}

// A root policy that can solve the curve degrees: the asked one when it accepts a large
// Candidates, EigenCompanion otherwise.
template <class Roots, class Real, class = void> struct CurveRoots {
  using type = EigenCompanion;
};
template <class Roots, class Real>
struct CurveRoots<Roots, Real,
                  std::void_t<decltype(Roots::roots(std::declval<const Real*>(), 0, Real(0), Real(0),
                                                    std::declval<Candidates<Real, kMaxCurveDegree + 8>&>()))>> {
  using type = Roots;
};

// p without the roots far outside [-1, 1] that a nearly vanishing leading coefficient makes,
// for the policies whose roots are eigenvalues. A curve whose highest power of w
// nearly cancels (nearly point-symmetric about the round's center with even degree, its even
// powers only the float32 rounding of its control points; or nearly of lower degree) gives a
// polynomial whose leading coefficient is 1e-9 of the others, hence one root near 1e7; Eigen's
// real Schur QR on the balanced companion matrix then returned the roots in [-1, 1] as complex
// pairs 0.1 to 0.5 off (LAPACK's QR on the same matrix does not), and EigenCompanion answered
// 0.1713 for a curve 0.1601 from a circle. Such a root is divided out exactly, as long as there
// is one. Where |c_{d-1}| r^(d-1) exceeds the sum of the other |c_i| r^i (here by a third at
// least) for r = |c_{d-1} / c_d| / 4 > 64, p has d - 1 roots inside |w| = r and one beyond
// (Pellet's theorem), real: nothing near [-1, 1] is removed. Its reciprocal v is the small root
// of the reversed polynomial, found by Newton from -c_d / c_{d-1}, and p = (1 - v w) s is
// divided from the constant term, s_i = c_i + v s_{i-1}, where errors shrink by |v| at every
// step (from the leading coefficient they would grow by 1 / |v|). Not a truncation: s has the
// other roots of p (dropping the small leading terms, a change of sqrt(eps) of the coefficients,
// lost a cluster of roots at the end of a piece of a larger curve). Bracketing searches
// [-1, 1] alone and needs none of this.
template <class Real> CurvePoly<Real> without_far_roots(const CurvePoly<Real>& polynomial) {
  CurvePoly<Real> p = polynomial;
  const int trimmed = trimmed_degree(p.c.data(), p.degree);
  if (trimmed < 0) return p;
  p.degree = trimmed;
  while (p.degree >= 3) {
    const int d = p.degree;
    const Real* c = p.c.data();
    const Real r = std::abs(c[d - 1] / c[d]) / 4;
    if (!(r > 64) || !std::isfinite(r)) break;
    Real rest = 0, power = 1;  // sum over i < d - 1 of |c_i| r^(i - (d - 1)), against |c_{d-1}|
    for (int i = d - 2; i >= 0; --i) {
      power /= r;
      rest += std::abs(c[i]) * power;
    }
    if (!(rest < std::abs(c[d - 1]) / 2)) break;
    Real v = -c[d] / c[d - 1];
    for (int iteration = 0; iteration < 16; ++iteration) {
      Real value = 0, slope = 0;  // the reversed polynomial c_d + c_{d-1} v + ... + c_0 v^d
      for (int i = 0; i <= d; ++i) {
        slope = slope * v + value;
        value = value * v + c[i];
      }
      if (!(slope != 0)) break;
      const Real step = value / slope;
      v -= step;
      if (!(std::abs(step) > std::numeric_limits<Real>::epsilon() * std::abs(v))) break;
    }
    if (!(std::abs(v) * r < 1)) break;  // Newton did not reach the root beyond r (or is NaN): p as it is
    CurvePoly<Real> s;
    s.degree = d - 1;
    s.c[0] = c[0];
    for (int i = 1; i < d; ++i) s.c[i] = c[i] + v * s.c[i - 1];
    p = s;
  }
  return p;
}

// Appends t = (1 + w) / 2 for the near-real roots w of p in [-1, 1] (a little slack, clamped:
// a root pushed just outside by rounding still seeds the polish at the end point).
template <class Roots, class Real, int N> void push_curve_roots(const CurvePoly<Real>& p, Candidates<Real, N>& out) {
  Candidates<Real, kMaxCurveDegree + 8> roots;
  const Real slack = Real(1e-3);
  using Policy = typename CurveRoots<Roots, Real>::type;
  if constexpr (!has_accurate_roots<Policy>::value) {
    const CurvePoly<Real> q = without_far_roots(p);
    Policy::roots(q.c.data(), q.degree, -1 - slack, 1 + slack, roots);
  } else {
    Policy::roots(p.c.data(), p.degree, -1 - slack, 1 + slack, roots);
  }
  for (int i = 0; i < roots.count; ++i) {
    const Real w = roots.value[i];
    if (w >= -1 - slack && w <= 1 + slack) out.push(std::min(std::max((1 + w) / 2, Real(0)), Real(1)));
  }
}

// Note 001 eq. (2) squared, in w: (P.P')^2 (x^2 + y^2) - R^2 (x x' + y y')^2 = 0, degree 6n - 2.
// Both sides carry P' twice, so d/dw in place of d/dt changes nothing.
template <class Roots, class Real, int N>
void push_curve_ring_roots(const LocalBezier<Real>& c, Real radius, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> x = c.coordinate(0, scale), y = c.coordinate(1, scale), z = c.coordinate(2, scale);
  const CurvePoly<Real> h = x * x.derivative() + y * y.derivative();
  const CurvePoly<Real> dot = h + z * z.derivative();
  const Real r = radius / scale;
  push_curve_roots<Roots>((dot * dot) * (x * x + y * y) - (r * r) * (h * h), out);
}

// Note 001 §3: where x^2 + y^2 = R^2 (the pieces' ends), and z z' = 0 (the inside pieces).
template <class Roots, class Real, int N>
void push_curve_disk_roots(const LocalBezier<Real>& c, Real radius, Real scale, Candidates<Real, N>& out) {
  if (c.n < 1) return;
  const CurvePoly<Real> x = c.coordinate(0, scale), y = c.coordinate(1, scale), z = c.coordinate(2, scale);
  CurvePoly<Real> g = x * x + y * y;
  const Real r = radius / scale;
  g.c[0] -= r * r;
  push_curve_roots<Roots>(g, out);
  push_curve_roots<Roots>(z, out);
  push_curve_roots<Roots>(z.derivative(), out);
}

// As circle_round_result, for a curve parameter t in [0, 1].
// A curve solved in pieces reports its point from the best piece (`where`), in local and in world
// coordinates: plain evaluation at t errs by eps times its farthest control point.
template <class Target, class Real, int N>
Result<Real> curve_round_result(const BezierCurve3<Real>& b, const LocalBezier<Real>& c, const Round<Real>& round,
                                const BestPiece<Real>& where, const Minima<Real, N>& minima, Real scale) {
  const Minimum<Real>& best = minima.best;
  const Vec3<Real> pa = where.valid ? where.piece.at(where.s) : c.at(best.x);
  Result<Real> r = round_side_result<Target>(minima, [&](Real x) { return c.at(x); }, pa, round, scale,
                                             distinct_points_tolerance(std::min(scale, c.size)));
  r.point_a = where.valid ? round.world(pa) : b.at(best.x);
  r.param_a = Vec2<Real>(best.x, 0);
  return r;
}

template <class Real> Result<Real> empty_curve_result() {
  Result<Real> r;
  r.distance = std::numeric_limits<Real>::infinity();
  r.unique = false;
  return r;
}

template <class Real> struct CurveRoundBase {
  // 2 end points + 6n-2 + 2n + n + (n-1) roots for a disk: 69 at degree 7 (a circle: 6n-2 + n + (n-1)).
  using Starts = Candidates<Real, 72>;
  using Found = Minima<Real, Starts::capacity>;

  template <class Roots, class H, class J>
  static Found polish(const LocalBezier<Real>& c, const Starts& starts, Real scale, const H& h, const J& jet) {
    return polish_offsets<Roots>(jet, h, starts, Real(1e-3), Real(0), Real(1), parameter_tolerance(c.speed, scale),
                                 screening_margin(scale));
  }

  // Minima over a piece's parameter s, moved to the curve's t = t0 + s (t1 - t0) (the whole
  // curve, t0 = 0 and t1 = 1, unchanged).
  static Found on_span(const Found& piece_minima, Real t0, Real t1) {
    Found found = piece_minima;
    if (t0 == 0 && t1 == 1) return found;
    for (int i = 0; i < found.count; ++i) found.item[i].x = t0 + found.item[i].x * (t1 - t0);
    found.best.x = t0 + found.best.x * (t1 - t0);
    return found;
  }

  // A curve far larger than the round (1e5 times, or one control point 1e10 away) cannot be
  // solved as a whole: in units of its own size the round is a speck, and the polynomials'
  // roots near it are lost to rounding (a relative error of 1e-2, or the minimum missed). So the
  // curve is cut into pieces, each small next to max(radius, its distance to the round), and
  // each piece is solved in its own variable and scale. Branch and bound: a piece's control
  // points hold it (convex hull), so its ball's center's distance minus the ball's radius bounds
  // its distance from below, and pieces that cannot beat an end point already seen are dropped.
  // A curve of the round's size is one piece: the whole curve, solved as before.
  // `distance_of(p)` is the exact distance of a local point; `solve_piece(piece, scale)` the
  // minima over one piece (parameter s in [0, 1], mapped here to t = t0 + s (t1 - t0)). The
  // pieces are cut from the curve in double-double (PreciseBezier); `where` (optional) receives
  // the piece and parameter of the best minimum.
  template <class DistanceOf, class SolvePiece>
  static Found solve_pieces(const LocalBezier<Real>& c, const BezierCurve3<Real>& b, const Round<Real>& round,
                            Real scale, const DistanceOf& distance_of, const SolvePiece& solve_piece,
                            BestPiece<Real>* where) {
    const Real radius = round.radius;
    // Halving stops where t no longer splits (about 1075 levels next to t = 0: a control point
    // 1e300 times farther than the round is reached in about 1000). At most 64 pieces are
    // solved; past that every remaining piece is solved as it is.
    constexpr int kPieceRatio = 4, kMaxPieces = 64;
    struct Span {
      Real t0, t1;
    };
    const auto ball = [](const LocalBezier<Real>& p, Vec3<Real>& center) {
      Vec3<Real> lo = p.q[0], hi = p.q[0];
      for (int i = 1; i <= p.n; ++i) {
        lo = lo.cwiseMin(p.q[i]);
        hi = hi.cwiseMax(p.q[i]);
      }
      center = (lo + hi) / 2;
      Real r = 0;
      for (int i = 0; i <= p.n; ++i) r = std::max(r, (p.q[i] - center).norm());
      return r;
    };
    Vec3<Real> center;
    const Real whole = ball(c, center);
    if (!(whole > kPieceRatio * std::max(radius, distance_of(center) - whole))) return solve_piece(c, scale);
    const PreciseBezier<Real> precise(b, round);
    Found out;
    Real upper = std::min(distance_of(c.q[0]), distance_of(c.q[c.n]));
    std::vector<Span> stack{{Real(0), Real(1)}};  // on the heap: deep for extreme curves only
    int pieces = 0;
    while (!stack.empty()) {
      const Span span = stack.back();
      stack.pop_back();
      const PreciseBezier<Real> precise_piece = precise.piece(span.t0, span.t1);
      const LocalBezier<Real> piece(precise_piece.rounded(), c.n);
      const Real r = ball(piece, center);
      const Real lower = distance_of(center) - r;
      if (lower > upper + tie_tolerance(std::max(scale, upper))) continue;
      upper = std::min(upper, std::min(distance_of(piece.q[0]), distance_of(piece.q[piece.n])));
      const Real mid = (span.t0 + span.t1) / 2;
      if (r > kPieceRatio * std::max(radius, lower) && pieces < kMaxPieces && mid > span.t0 && mid < span.t1) {
        stack.push_back({mid, span.t1});
        stack.push_back({span.t0, mid});
        continue;
      }
      ++pieces;
      const Found found = solve_piece(piece, bezier_round_scale(piece, radius));
      if (found.best.value < out.best.value && where) *where = {precise_piece, found.best.x, true};
      const Found on_curve = on_span(found, span.t0, span.t1);
      for (int i = 0; i < on_curve.count; ++i) out.add(on_curve.item[i]);
      if (on_curve.best.value < out.best.value) out.best = on_curve.best;
    }
    return out;
  }
};

// A curve against a ring or a disk: the end points; the roots of note 001 eq. (2) squared (the
// ring's stationary points); for a disk, the rim crossings and z z' = 0 (note 001 §3); for a
// ring, z z' = 0 as well (see below); all polished on the target's exact distance.
template <class Real, class Target> struct CurveRoundQuery : CurveRoundBase<Real> {
  static constexpr bool defined = true;
  using Base = CurveRoundBase<Real>;
  using Shape = typename Target::Shape;

  template <class Roots>
  static auto solve(const LocalBezier<Real>& c, const BezierCurve3<Real>& b, const Round<Real>& round, Real scale,
                    BestPiece<Real>* where = nullptr) {
    const Real radius = round.radius;
    const auto distance_of = [&](const Vec3<Real>& p) { return Target::distance(p, radius); };
    return Base::solve_pieces(c, b, round, scale, distance_of, [&](const LocalBezier<Real>& piece, Real s) {
      typename Base::Starts starts;
      starts.push(Real(0));
      starts.push(Real(1));
      if constexpr (Target::interior) push_curve_disk_roots<Roots>(piece, radius, s, starts);
      push_curve_ring_roots<Roots>(piece, radius, s, starts);
      if constexpr (!Target::interior) {
        // Eq. (2) squared carries the factor x^2 + y^2: on a curve lying along the axis it
        // vanishes identically and has no roots, while the distance sqrt(R^2 + z^2) is smallest
        // where z z' = 0. Those roots (degrees n and n - 1, cheap) seed the polish there and near
        // it. (A disk's candidates hold them already: push_curve_disk_roots.)
        if (piece.n >= 1) {
          const CurvePoly<Real> z = piece.coordinate(2, s);
          push_curve_roots<Roots>(z, starts);
          push_curve_roots<Roots>(z.derivative(), starts);
        }
      }
      const auto h = [&](Real t) { return Target::distance(piece.at(t), radius); };
      const auto jet = [&](Real t) { return piece.template jet<Target>(t, radius); };
      return Base::template polish<Roots>(piece, starts, s, h, jet);
    }, where);
  }

  template <class Roots = DefaultRoots> static Real distance(const BezierCurve3<Real>& b, const Shape& shape) {
    if (b.control.cols() == 0) return std::numeric_limits<Real>::infinity();
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const LocalBezier<Real> c(b, round);
    return solve<Roots>(c, b, round, bezier_round_scale(c, shape.radius)).best.value;
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const BezierCurve3<Real>& b, const Shape& shape) {
    if (b.control.cols() == 0) return empty_curve_result<Real>();
    const Round<Real> round(shape.center, shape.normal, shape.radius);
    const LocalBezier<Real> c(b, round);
    const Real scale = bezier_round_scale(c, shape.radius);
    BestPiece<Real> where;
    const auto minima = solve<Roots>(c, b, round, scale, &where);
    return curve_round_result<Target>(b, c, round, where, minima, scale);
  }
};

template <class Real> struct Query<BezierCurve3<Real>, Disk3<Real>> : CurveRoundQuery<Real, DiskTarget<Real>> {};
template <class Real> struct Query<BezierCurve3<Real>, Circle3<Real>> : CurveRoundQuery<Real, RingTarget<Real>> {};

}  // namespace circledist
