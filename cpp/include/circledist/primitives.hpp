// circledist: exact 3D distances between points, lines, rays, segments, circles, disks and arcs.
// Primitives, the per-query Result, and the canonical frame of a plane.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

// The closed-form point queries are a few dozen instructions: inlined into a caller's loop, the
// latencies of consecutive queries overlap (a call per query costs about 10 % of one).
#if defined(__GNUC__) || defined(__clang__)
#define CIRCLEDIST_INLINE inline __attribute__((always_inline))
#else
#define CIRCLEDIST_INLINE inline
#endif

namespace circledist {

template <class Real> using Vec3 = Eigen::Matrix<Real, 3, 1>;
template <class Real> using Vec2 = Eigen::Matrix<Real, 2, 1>;

// pi in Real, to its last bit.
template <class Real> constexpr Real pi_v() {
  return Real(3.141592653589793238462643383279502884197169399375105820974944592307816406L);
}

// A circle (the ring only). `normal` need not be unit length; `radius` >= 0.
template <class Real> struct Circle3 {
  Vec3<Real> center, normal;
  Real radius;
};

// The filled disk bounded by the circle with the same fields.
template <class Real> struct Disk3 {
  Vec3<Real> center, normal;
  Real radius;
};

namespace detail {
// The cosine and sine of an arc's angle and of its half, for the angle `angle` (NaN: none, equal
// to no angle). point_arc.hpp places a point against the arc's ends with them (a few products,
// no atan2; docs/derivations/arc.md, "A point"); an arc made by Arc3's constructor carries them,
// so a query does no trigonometry of its own. Formed only for 0 < angle < 2 pi (the other
// angles are answered without them).
template <class Real> struct ArcTrig {
  Real angle = std::numeric_limits<Real>::quiet_NaN();
  Real cos_angle = 0, sin_angle = 0, cos_half = 0, sin_half = 0;

  ArcTrig() = default;
  explicit ArcTrig(Real a) {
    if (!(a > 0 && a < 2 * pi_v<Real>())) return;
    angle = a;
    cos_angle = std::cos(a);
    sin_angle = std::sin(a);
    cos_half = std::cos(a / 2);
    sin_half = std::sin(a / 2);
  }
};
}  // namespace detail

// A circular arc: the points center + radius (cos t u + sin t v), t in [0, angle], where n is
// the unit normal, u the unit projection of `start` onto the plane normal to n and v = n x u.
// 0 < angle <= 2 pi; an angle of 2 pi or more is the whole circle (answered as the
// Circle3 with the same fields), an angle of 0 or less the start point alone, a NaN angle NaN. A `start` with no
// projection (zero, or along the normal) starts at the circle's angle 0 (Frame's U). Queries
// report t as the arc's parameter (t, 0), as a circle's angle (detail/arc_span.hpp).
template <class Real> struct Arc3 {
  Vec3<Real> center, normal;
  Real radius;
  Vec3<Real> start;
  Real angle;
  // The angle's trigonometry, formed once by the constructor. Valid while trig.angle == angle:
  // an arc whose angle is assigned after it was made (or a default-constructed one) is answered
  // by the general path, which forms what it needs per query (point_arc.hpp).
  detail::ArcTrig<Real> trig;

  Arc3() = default;
  Arc3(const Vec3<Real>& center_, const Vec3<Real>& normal_, Real radius_, const Vec3<Real>& start_, Real angle_)
      : center(center_), normal(normal_), radius(radius_), start(start_), angle(angle_), trig(angle_) {}
};

// Points origin + t * direction, t in R. `direction` need not be unit length.
template <class Real> struct Line3 {
  Vec3<Real> origin, direction;
};

// Points origin + t * direction, t >= 0.
template <class Real> struct Ray3 {
  Vec3<Real> origin, direction;
};

// Points p0 + t * (p1 - p0), t in [0, 1]. p0 == p1 is allowed (a point).
template <class Real> struct Segment3 {
  Vec3<Real> p0, p1;
};

// A strict order on the shapes of one kind, lexicographic on their numbers. A query between two
// shapes of one kind is answered in this order whichever way it is asked (query.hpp), so that
// distance(a, b) and distance(b, a) agree to the bit.
template <class Real> bool precedes(const Vec3<Real>& x, const Vec3<Real>& y) {
  return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
}
namespace detail {
template <class Real>
bool precedes_pair(const Vec3<Real>& x0, const Vec3<Real>& x1, const Vec3<Real>& y0, const Vec3<Real>& y1) {
  return precedes(x0, y0) || (!precedes(y0, x0) && precedes(x1, y1));
}
}  // namespace detail
template <class Real> bool precedes(const Line3<Real>& x, const Line3<Real>& y) {
  return detail::precedes_pair(x.origin, x.direction, y.origin, y.direction);
}
template <class Real> bool precedes(const Ray3<Real>& x, const Ray3<Real>& y) {
  return detail::precedes_pair(x.origin, x.direction, y.origin, y.direction);
}
template <class Real> bool precedes(const Segment3<Real>& x, const Segment3<Real>& y) {
  return detail::precedes_pair(x.p0, x.p1, y.p0, y.p1);
}
namespace detail {
// Circles and disks: center, then normal, then radius.
template <class Round> bool precedes_round(const Round& x, const Round& y) {
  if (precedes_pair(x.center, x.normal, y.center, y.normal)) return true;
  return !precedes_pair(y.center, y.normal, x.center, x.normal) && x.radius < y.radius;
}
}  // namespace detail
template <class Real> bool precedes(const Circle3<Real>& x, const Circle3<Real>& y) {
  return detail::precedes_round(x, y);
}
template <class Real> bool precedes(const Disk3<Real>& x, const Disk3<Real>& y) { return detail::precedes_round(x, y); }
// Arcs: as circles, then the start and the angle.
template <class Real> bool precedes(const Arc3<Real>& x, const Arc3<Real>& y) {
  if (detail::precedes_round(x, y)) return true;
  if (detail::precedes_round(y, x)) return false;
  if (precedes(x.start, y.start)) return true;
  return !precedes(y.start, x.start) && x.angle < y.angle;
}

// What closest_points() returns. Parameters, per shape kind:
//   point: (0, 0); line, ray, segment: (t, 0) as in the definitions above;
//   circle: (theta, 0), the angle in the canonical frame (see Frame);
//   arc: (t, 0), t in [0, angle] from the arc's start (Arc3);
//   disk: (s, theta), the closest point being center + s (cos theta U + sin theta V).
// `unique` is false when another, distinct closest pair reaches the same distance within
// rounding (a tie between isolated pairs, or a continuum such as a line on a circle's axis).
template <class Real> struct Result {
  Real distance = std::numeric_limits<Real>::quiet_NaN();
  Vec3<Real> point_a = Vec3<Real>::Zero(), point_b = Vec3<Real>::Zero();
  Vec2<Real> param_a = Vec2<Real>::Zero(), param_b = Vec2<Real>::Zero();
  bool unique = true;

  // The same result in another precision (a float query computed in double).
  template <class To> Result<To> cast() const {
    Result<To> r;
    r.distance = To(distance);
    r.point_a = point_a.template cast<To>();
    r.point_b = point_b.template cast<To>();
    r.param_a = param_a.template cast<To>();
    r.param_b = param_b.template cast<To>();
    r.unique = unique;
    return r;
  }

  Result swapped() const {
    Result r = *this;
    std::swap(r.point_a, r.point_b);
    std::swap(r.param_a, r.param_b);
    return r;
  }
};

// Whole queries scaled by a power of two (exact): every length times 2^e (query.hpp rescales
// scenes whose coordinates square past overflow or into the subnormals). extent() is the largest coordinate or length a
// shape holds (directions and normals aside: their scale is handled where they are normalized).
namespace detail {
template <class Real> Vec3<Real> ldexp3(const Vec3<Real>& v, int e) {
  return Vec3<Real>(std::ldexp(v.x(), e), std::ldexp(v.y(), e), std::ldexp(v.z(), e));
}
template <class Real> constexpr Real power_of_two(int exponent) {
  Real x = 1;
  for (int i = 0; i < (exponent < 0 ? -exponent : exponent); ++i) x = exponent < 0 ? x / 2 : x * 2;
  return x;
}
}  // namespace detail

namespace detail {
// The exponent of a direction's largest component (0 for a zero direction): a line's direction
// is scaled to components in [1, 2) apart from the scene, which could carry a direction of 1e200
// in a scene of 1e-200 past overflow.
template <class Real> int direction_exponent(const Vec3<Real>& d) {
  const Real largest = d.cwiseAbs().maxCoeff();
  return largest > 0 && largest <= std::numeric_limits<Real>::max() ? std::ilogb(largest) : 0;
}

// The rule "scale a vector whose direction alone counts by a power of two" is written three
// times, and they are not one computation: moderate_start tests the largest component against
// [2^-100, 2^100] (inclusive); ArcEnds (linear_arc.hpp) tests the squared norm, formed by
// squaredNorm(), strictly inside it; PointOverRound::rescale_normal
// (detail/point_over_round.hpp) tests wx*wx + wy*wy + wz*wz strictly inside it and takes ilogb
// without direction_exponent's guard for a zero or non-finite component. Folding them into
// one function would change answers at those edges, so each keeps its own.
// An arc's start scaled by a power of two (exact: only its direction counts) to a largest
// component in [1, 2), where that component lies outside [2^-100, 2^100]: the arc queries form
// |W|^2 S - (S.W) W and its length, which overflowed for a start of 1e200 (a NaN or wrong
// point-arc distance) and underflowed to zero, read as "no projection", for one of 1e-200 (the
// crash fuzz's arcs). The common case pays one comparison.
template <class Real>
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline, cold))
#endif
Vec3<Real>
moderated_start(const Vec3<Real>& start) {
  return ldexp3(start, -direction_exponent(start));
}
template <class Real> CIRCLEDIST_INLINE Vec3<Real> moderate_start(const Vec3<Real>& start) {
  constexpr Real lo = power_of_two<Real>(-100), hi = power_of_two<Real>(100);
  const Real largest = start.cwiseAbs().maxCoeff();
  if (largest >= lo && largest <= hi) return start;
  return moderated_start(start);  // out of line: rare
}
}  // namespace detail

template <class Real> Vec3<Real> scaled(const Vec3<Real>& p, int e) { return detail::ldexp3(p, e); }
template <class Real> Line3<Real> scaled(const Line3<Real>& l, int e) {
  return {detail::ldexp3(l.origin, e), detail::ldexp3(l.direction, -detail::direction_exponent(l.direction))};
}
template <class Real> Ray3<Real> scaled(const Ray3<Real>& r, int e) {
  return {detail::ldexp3(r.origin, e), detail::ldexp3(r.direction, -detail::direction_exponent(r.direction))};
}
template <class Real> Segment3<Real> scaled(const Segment3<Real>& s, int e) {
  return {detail::ldexp3(s.p0, e), detail::ldexp3(s.p1, e)};
}
template <class Real> Circle3<Real> scaled(const Circle3<Real>& c, int e) {
  return {detail::ldexp3(c.center, e), c.normal, std::ldexp(c.radius, e)};
}
template <class Real> Disk3<Real> scaled(const Disk3<Real>& d, int e) {
  return {detail::ldexp3(d.center, e), d.normal, std::ldexp(d.radius, e)};
}
template <class Real> Arc3<Real> scaled(const Arc3<Real>& a, int e) {
  Arc3<Real> out = a;  // the angle and its trigonometry unchanged
  out.center = detail::ldexp3(a.center, e);
  out.radius = std::ldexp(a.radius, e);
  return out;
}
template <class Real> Real extent(const Vec3<Real>& p) { return p.cwiseAbs().maxCoeff(); }
template <class Real> Real extent(const Line3<Real>& l) { return extent(l.origin); }
template <class Real> Real extent(const Ray3<Real>& r) { return extent(r.origin); }
template <class Real> Real extent(const Segment3<Real>& s) { return std::max(extent(s.p0), extent(s.p1)); }
template <class Real> Real extent(const Circle3<Real>& c) { return std::max(extent(c.center), c.radius); }
template <class Real> Real extent(const Disk3<Real>& d) { return std::max(extent(d.center), d.radius); }
template <class Real> Real extent(const Arc3<Real>& a) { return std::max(extent(a.center), a.radius); }
// The parameters of the shape from those of the scaled one: a disk's s is a length; a line's or
// ray's t follows its direction's scaling (P = o + t' d 2^-k in the scene scaled by 2^e, so
// t = t' 2^(-k-e)); a segment's t, a curve's t and angles do not change.
template <class Real, class Shape> Vec2<Real> unscaled_param(const Vec2<Real>& param, const Shape&, int) {
  return param;
}
template <class Real> Vec2<Real> unscaled_param(const Vec2<Real>& param, const Disk3<Real>&, int e) {
  return Vec2<Real>(std::ldexp(param.x(), -e), param.y());
}
template <class Real> Vec2<Real> unscaled_param(const Vec2<Real>& param, const Line3<Real>& l, int e) {
  return Vec2<Real>(std::ldexp(param.x(), -detail::direction_exponent(l.direction) - e), param.y());
}
template <class Real> Vec2<Real> unscaled_param(const Vec2<Real>& param, const Ray3<Real>& r, int e) {
  return Vec2<Real>(std::ldexp(param.x(), -detail::direction_exponent(r.direction) - e), param.y());
}

// float queries are computed in double and rounded (query.hpp): float's 24 bits cannot hold
// the cancellations of tangencies (a circle-circle answer was off by 0.32), nor the squares of
// coordinates past 1.8e19. promoted() is the same shape in double, exactly.
// Templates deduced from the argument (no conversions: an Eigen vector of double would convert
// to one of float), enabled for float only.
template <class Real> using if_float = std::enable_if_t<std::is_same<Real, float>::value, int>;
template <class Real, if_float<Real> = 0> Vec3<double> promoted(const Vec3<Real>& p) {
  return p.template cast<double>();
}
template <class Real, if_float<Real> = 0> Line3<double> promoted(const Line3<Real>& l) {
  return {promoted(l.origin), promoted(l.direction)};
}
template <class Real, if_float<Real> = 0> Ray3<double> promoted(const Ray3<Real>& r) {
  return {promoted(r.origin), promoted(r.direction)};
}
template <class Real, if_float<Real> = 0> Segment3<double> promoted(const Segment3<Real>& s) {
  return {promoted(s.p0), promoted(s.p1)};
}
template <class Real, if_float<Real> = 0> Circle3<double> promoted(const Circle3<Real>& c) {
  return {promoted(c.center), promoted(c.normal), double(c.radius)};
}
template <class Real, if_float<Real> = 0> Disk3<double> promoted(const Disk3<Real>& d) {
  return {promoted(d.center), promoted(d.normal), double(d.radius)};
}
// The fields assigned, not given to the constructor: a float query is promoted per query, and the
// angle's trigonometry in double would cost it more than it saves (Arc3::trig).
template <class Real, if_float<Real> = 0> Arc3<double> promoted(const Arc3<Real>& a) {
  Arc3<double> out;
  out.center = promoted(a.center);
  out.normal = promoted(a.normal);
  out.radius = double(a.radius);
  out.start = promoted(a.start);
  out.angle = double(a.angle);
  return out;
}

// An annulus: the points of the plane disk of radius `outer_radius` about `center`
// (normal `normal`, any length) at distance >= `inner_radius` from the center. Its parameter in
// a Result is a disk's, (s, theta): the point center + s (cos theta U + sin theta V), s in
// [inner_radius, outer_radius]. inner_radius <= 0 is the disk, inner_radius == outer_radius
// the circle (both answered by their own queries, annulus_reduction.hpp), inner_radius > outer_radius
// the empty set (distance +inf), a NaN radius NaN. Its order, scaling and promotion follow the
// disk's (then the inner radius).
template <class Real> struct Annulus3 {
  Vec3<Real> center, normal;
  Real inner_radius, outer_radius;
};
template <class Real> bool precedes(const Annulus3<Real>& x, const Annulus3<Real>& y) {
  if (detail::precedes_pair(x.center, x.normal, y.center, y.normal)) return true;
  if (detail::precedes_pair(y.center, y.normal, x.center, x.normal)) return false;
  if (x.outer_radius != y.outer_radius) return x.outer_radius < y.outer_radius;
  return x.inner_radius < y.inner_radius;
}
template <class Real> Annulus3<Real> scaled(const Annulus3<Real>& a, int e) {
  return {detail::ldexp3(a.center, e), a.normal, std::ldexp(a.inner_radius, e), std::ldexp(a.outer_radius, e)};
}
template <class Real> Real extent(const Annulus3<Real>& a) { return std::max(extent(a.center), a.outer_radius); }
template <class Real> Vec2<Real> unscaled_param(const Vec2<Real>& param, const Annulus3<Real>&, int e) {
  return Vec2<Real>(std::ldexp(param.x(), -e), param.y());
}
template <class Real, if_float<Real> = 0> Annulus3<double> promoted(const Annulus3<Real>& a) {
  return {promoted(a.center), promoted(a.normal), double(a.inner_radius), double(a.outer_radius)};
}

// Bezier curves of degree 0 to kMaxBezierDegree (detail/curve_round_query.hpp answers their queries; a curve's
// polynomials against a round reach degree 6n - 2, detail/local_bezier.hpp).
constexpr int kMaxBezierDegree = 7;

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

// A closest point's parameters in the shape's domain: a ray's t >= 0, a segment's and a curve's t
// in [0, 1], an arc's t in [0, angle], a disk's s in [0, radius], an annulus's s in [inner_radius,
// outer_radius]. The solvers find a parameter from a point (a foot on the line, a projection's
// length), and its rounding can leave the domain by an ulp or a few; the point itself, on the
// shape within the accuracy bar, moves by no more than that rounding times the shape's size. The
// front end (query.hpp) passes every answer through these, so every pair keeps to the domain.
// NaN (the empty curve's answer) stays NaN: clamp_param(x, lo, hi) keeps x where it compares false.
namespace detail {
template <class Real> Real clamp_param(Real x, Real lo, Real hi) { return x < lo ? lo : x > hi ? hi : x; }
}  // namespace detail
template <class Real, class Shape> Vec2<Real> param_in_domain(const Vec2<Real>& param, const Shape&) { return param; }
template <class Real> Vec2<Real> param_in_domain(const Vec2<Real>& param, const Ray3<Real>&) {
  return Vec2<Real>(param.x() < 0 ? Real(0) : param.x(), param.y());
}
template <class Real> Vec2<Real> param_in_domain(const Vec2<Real>& param, const Segment3<Real>&) {
  return Vec2<Real>(detail::clamp_param(param.x(), Real(0), Real(1)), param.y());
}
template <class Real> Vec2<Real> param_in_domain(const Vec2<Real>& param, const BezierCurve3<Real>&) {
  return Vec2<Real>(detail::clamp_param(param.x(), Real(0), Real(1)), param.y());
}
template <class Real> Vec2<Real> param_in_domain(const Vec2<Real>& param, const Arc3<Real>& a) {
  return Vec2<Real>(detail::clamp_param(param.x(), Real(0), a.angle), param.y());
}
template <class Real> Vec2<Real> param_in_domain(const Vec2<Real>& param, const Disk3<Real>& d) {
  return Vec2<Real>(detail::clamp_param(param.x(), Real(0), d.radius), param.y());
}
template <class Real> Vec2<Real> param_in_domain(const Vec2<Real>& param, const Annulus3<Real>& a) {
  return Vec2<Real>(detail::clamp_param(param.x(), a.inner_radius, a.outer_radius), param.y());
}

// v / |v| for any finite nonzero v. |v|^2 overflows for |v| beyond about 1.3e154 (double) and
// loses digits in the subnormals below about 1e-138: such vectors are first scaled by a power of
// two (exact) to a largest component in [1, 2). The common case pays one comparison.
namespace detail {
// The rare path, kept out of line so that the common one stays a few instructions.
template <class Real>
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline, cold))
#endif
Vec3<Real>
unit_vector_scaled(const Vec3<Real>& v) {
  const int exponent = std::ilogb(v.cwiseAbs().maxCoeff());
  const Vec3<Real> w(std::ldexp(v.x(), -exponent), std::ldexp(v.y(), -exponent), std::ldexp(v.z(), -exponent));
  return w / w.norm();
}
}  // namespace detail

namespace detail {
// lo < x < hi for 0 < lo < hi: one unsigned comparison of the bit patterns for double (positive
// doubles order as their bits; negative values, inf and NaN fall outside), two comparisons for
// the other types. The check sits on the hottest paths (every point query normalizes a normal).
template <class Real> CIRCLEDIST_INLINE bool strictly_between(Real x, Real lo, Real hi) {
  if constexpr (std::is_same<Real, double>::value) {
    std::uint64_t bx, blo, bhi;
    std::memcpy(&bx, &x, 8);
    std::memcpy(&blo, &lo, 8);
    std::memcpy(&bhi, &hi, 8);
    return bx - blo - 1 < bhi - blo - 1;
  } else {
    return x > lo && x < hi;
  }
}
}  // namespace detail

template <class Real> CIRCLEDIST_INLINE Vec3<Real> unit_vector(const Vec3<Real>& v) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  constexpr Real tiny = std::numeric_limits<Real>::min() / (eps * eps);
  const Real n2 = v.squaredNorm();
  if (detail::strictly_between(n2, tiny, std::numeric_limits<Real>::max())) return v / std::sqrt(n2);
  return detail::unit_vector_scaled(v);
}

// The right-handed orthonormal frame {U, V, N} of a circle or disk, built the same way everywhere
// so that angles mean the same thing in C++ and Python (W the normal as given):
//   N = W / |W|;
//   U = (-W.z, 0, W.x) / |.| when |W.x| > |W.y|, else (0, W.z, -W.y) / |.|;   V = N x U.
// U is normalized from W itself, not from N: the same direction, and its square root and reciprocal
// run beside N's instead of after them (the frame is most of a point query's closest_points).
// The pair holds W.z and the larger of W.x, W.y, so its squared length is at least |W|^2 / 2:
// within range whenever |W|^2 is (the fast path's test).
template <class Real> struct Frame {
  Vec3<Real> u, v, n;

  CIRCLEDIST_INLINE explicit Frame(const Vec3<Real>& normal) {
    constexpr Real eps = std::numeric_limits<Real>::epsilon();
    constexpr Real tiny = std::numeric_limits<Real>::min() / (eps * eps);
    // N exactly as unit_vector() makes it (distance() and closest_points() must agree to the bit).
    Vec3<Real> w = normal;
    const Real n2 = w.squaredNorm();
    if (detail::strictly_between(n2, tiny, std::numeric_limits<Real>::max())) {
      n = w / std::sqrt(n2);
    } else {
      n = w = detail::unit_vector_scaled(normal);  // rescaled into range (NaN stays NaN)
    }
    const Real x = w.x(), y = w.y(), z = w.z();
    const bool x_major = std::abs(normal.x()) > std::abs(normal.y());  // on W as given: no rounding
    const Real major = x_major ? x : y;
    const Real inv_u = Real(1) / std::sqrt(major * major + z * z);
    const Real uz = z * inv_u, um = major * inv_u;
    u = x_major ? Vec3<Real>(-uz, Real(0), um) : Vec3<Real>(Real(0), uz, -um);
    v = n.cross(u);
  }

  // Coordinates (x, y, z) of a world vector in this frame (a rotation: lengths are kept).
  Vec3<Real> to_local(const Vec3<Real>& w) const { return Vec3<Real>(u.dot(w), v.dot(w), n.dot(w)); }
  Vec3<Real> to_world(const Vec3<Real>& l) const { return l.x() * u + l.y() * v + l.z() * n; }
};

}  // namespace circledist
