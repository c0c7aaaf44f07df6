// Disk-disk (Query<Disk3, Disk3>). Derivation: docs/derivations/disk_disk.md.
//
// Disk against disk (docs/derivations/disk_disk.md). Zero when the disks intersect, decided in B's local
// frame: disk A meets B's plane in a chord (A's points at height 0), and the disks intersect
// exactly when that chord meets disk B, a 1-D interval overlap along the chord. Coplanar disks
// (A's heights all within rounding of 0) intersect when their centers are no farther apart than
// the radii's sum (the rims confirm it unless they are exactly coplanar). Otherwise a closest
// pair has a point on one of the rims, so the distance is min(circle(A)-disk(B),
// circle(B)-disk(A)) (circle_disk.hpp).
#pragma once

#include "circle_disk.hpp"
#include "query.hpp"

namespace circledist {

namespace detail {

// Where two disks meet, if they do: a point common to both (B-local coordinates) and whether it
// is the only one (the common part shorter than the distinct-points tolerance).
template <class Real> struct DiskContact {
  bool intersect = false;
  bool unique = true;
  // Contact decided within rounding: the common part is so short that the square roots giving
  // its ends (which turn eps scale^2 in their radicands into sqrt(eps) scale) cannot tell a
  // touch from a gap of 1e-8 scale. The rims then decide: when two disks meet, an end of their
  // common part lies on a rim, so min(circle(A)-disk(B), circle(B)-disk(A)) is 0 exactly when
  // they meet and the distance otherwise.
  bool borderline = false;
  Vec3<Real> point = Vec3<Real>::Zero();
};

template <class Real> DiskContact<Real> disk_contact(const Disk3<Real>& a, const Round<Real>& round, Real rb) {
  DiskContact<Real> out;
  const Frame<Real> fa(a.normal);
  const Real ra = a.radius;
  const Vec3<Real> o = round.local(a.center);
  const Vec3<Real> ua = round.frame.to_local(fa.u), va = round.frame.to_local(fa.v);
  // Height over B's plane of A's point o + x ua + y va: c + gx x + gy y, |(gx, gy)| = sin(angle).
  const Real gx = ua.z(), gy = va.z(), c = o.z();
  const Real sine = length2d(gx, gy);
  const Real scale = std::max(std::max(ra, rb), o.norm()) > 0 ? std::max(std::max(ra, rb), o.norm()) : Real(1);
  const Real flat = 16 * std::numeric_limits<Real>::epsilon() * scale;
  const Real apart = distinct_points_tolerance(scale);

  if (ra * sine <= flat && std::abs(c) <= flat) {
    // Coplanar within rounding: the overlap of the two disks along the line of centers.
    const Real d = length2d(o.x(), o.y());
    if (!(d <= ra + rb)) return out;
    const Vec2<Real> dir = d > 0 ? Vec2<Real>(o.x() / d, o.y() / d) : Vec2<Real>(1, 0);
    const Real lo = std::max(-rb, d - ra), hi = std::min(rb, d + ra);
    const Real mid = (lo + hi) / 2;
    out.intersect = true;
    // Not exactly coplanar: A may be a few ulps above B's plane, and the point in B's plane is
    // then off A by more than its rounding; the rims decide (a gap of 6e-15 was reported as 0).
    out.borderline = !(c == 0 && gx == 0 && gy == 0);
    out.point = Vec3<Real>(mid * dir.x(), mid * dir.y(), 0);
    // The common part: a lens whose common chord has half-length k, or the smaller disk.
    Real extent = hi - lo;
    if (d <= std::abs(ra - rb)) {
      extent = 2 * std::min(ra, rb);
    } else {
      const Real x = (d * d + rb * rb - ra * ra) / (2 * d);  // chord's foot from B's center
      extent = std::max(extent, 2 * std::sqrt(std::max(Real(0), (rb - x) * (rb + x))));
    }
    out.unique = !(extent > apart);
    return out;
  }
  // A lies strictly on one side of B's plane (or touches it within rounding: the rims decide).
  if (!(std::abs(c) <= ra * sine)) return out;
  // A's chord in B's plane, in A's plane coordinates: foot -c (gx, gy) / sine^2, direction
  // (-gy, gx) / sine, half-length sqrt(ra^2 - c^2 / sine^2).
  const Real half = std::sqrt(std::max(Real(0), (ra * sine - std::abs(c)) * (ra * sine + std::abs(c)))) / sine;
  const Real k = -c / (sine * sine);
  const Vec3<Real> foot = o + (k * gx) * ua + (k * gy) * va;
  const Vec3<Real> e = (-gy / sine) * ua + (gx / sine) * va;
  // The chord meets disk B where |foot_xy + s e_xy| <= rb: e2 s^2 + 2 f s + (|foot_xy|^2 - rb^2) <= 0.
  const Real e2 = e.x() * e.x() + e.y() * e.y();
  const Real f = foot.x() * e.x() + foot.y() * e.y();
  const Real rho = length2d(foot.x(), foot.y());
  const Real g = (rho - rb) * (rho + rb);
  const Real disc = f * f - e2 * g;
  if (!(disc >= 0) || !(e2 > 0)) return out;
  const Real root = std::sqrt(disc);
  const Real lo = std::max(-half, (-f - root) / e2), hi = std::min(half, (-f + root) / e2);
  if (!(lo <= hi)) return out;
  const Real mid = (lo + hi) / 2;
  out.intersect = true;
  out.borderline = !(hi - lo > 64 * std::sqrt(std::numeric_limits<Real>::epsilon()) * scale);
  out.point = foot + mid * e;
  out.point.z() = 0;
  out.unique = !(hi - lo > apart);
  return out;
}

template <class Real> struct DiskDiskPair {
  static constexpr bool defined = true;
  using CircleDisk = Query<Circle3<Real>, Disk3<Real>>;

  static Circle3<Real> rim(const Disk3<Real>& d) { return {d.center, d.normal, d.radius}; }

  // Which rims are clear of the other disk's cylinder (docs/derivations/disk_disk.md, "A rim
  // clear of the other cylinder"): a clear rim's query is circle-circle between the rims, and
  // the other rim's query is at most that (its distance is at most its rim part, the same
  // circle-circle distance), so only the other one is solved. Both clear: the one
  // circle-circle query, which runs the same computation in either order
  // (CircleCirclePair::parametrized_first).
  struct ClearRims {
    bool a, b;
  };
  static ClearRims clear_rims(const Disk3<Real>& a, const Disk3<Real>& b, const Round<Real>& round_b) {
    return {CircleDisk::clear_of_cylinder(rim(a), round_b),
            CircleDisk::clear_of_cylinder(rim(b), Round<Real>(a.center, a.normal, a.radius))};
  }

  template <class Roots = DefaultRoots> static Real distance(const Disk3<Real>& a, const Disk3<Real>& b) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const DiskContact<Real> contact = disk_contact(a, round, b.radius);
    if (contact.intersect && !contact.borderline) return Real(0);
    const ClearRims clear = clear_rims(a, b, round);
    if (clear.a) return CircleDisk::template distance<Roots>(rim(b), a);
    if (clear.b) return CircleDisk::template distance<Roots>(rim(a), b);
    return std::min(CircleDisk::template distance<Roots>(rim(a), b), CircleDisk::template distance<Roots>(rim(b), a));
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Disk3<Real>& a, const Disk3<Real>& b) {
    const Round<Real> round(b.center, b.normal, b.radius);
    const DiskContact<Real> contact = disk_contact(a, round, b.radius);
    if (contact.intersect && !contact.borderline) {
      const Round<Real> round_a(a.center, a.normal, a.radius);
      Result<Real> r;
      r.distance = 0;
      r.point_b = round.world(contact.point);
      r.point_a = r.point_b;
      r.param_a = DiskTarget<Real>::param(round_a.local(r.point_a));
      r.param_b = DiskTarget<Real>::param(contact.point);
      r.unique = contact.unique;
      return r;
    }
    // The rim's parameter (theta, 0) becomes the disk's (radius, theta): the same frame.
    const auto rim_a = [&] {
      Result<Real> r = CircleDisk::template closest<Roots>(rim(a), b);
      r.param_a = Vec2<Real>(a.radius, r.param_a.x());
      return r;
    };
    const auto rim_b = [&] {
      Result<Real> r = CircleDisk::template closest<Roots>(rim(b), a).swapped();
      r.param_b = Vec2<Real>(b.radius, r.param_b.x());
      return r;
    };
    const ClearRims clear = clear_rims(a, b, round);
    if (clear.a) return rim_b();
    if (clear.b) return rim_a();
    const Result<Real> ra = rim_a(), rb = rim_b();
    const bool a_wins = ra.distance <= rb.distance;
    Result<Real> best = a_wins ? ra : rb;
    const Result<Real>& other = a_wins ? rb : ra;
    // Both rims reaching the same distance at a different pair (or with a continuum of their
    // own) is a tie; the same pair found from both sides is not.
    const Real scale = std::max(std::max(a.radius, b.radius), (a.center - b.center).norm());
    const Real apart = distinct_points_tolerance(scale > 0 ? scale : Real(1));
    if (other.distance <= best.distance + tie_tolerance(std::max(scale, best.distance))) {
      const bool same_pair =
          (other.point_a - best.point_a).norm() <= apart && (other.point_b - best.point_b).norm() <= apart;
      if (!same_pair || !other.unique) best.unique = false;
    }
    return best;
  }
};

}  // namespace detail

template <class Real> struct Query<Disk3<Real>, Disk3<Real>> : detail::DiskDiskPair<Real> {};

}  // namespace circledist
