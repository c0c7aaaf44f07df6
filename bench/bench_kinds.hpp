// The query kinds the C++ benchmarks time (bench_queries.cpp, accuracy_vs_time.cpp): a name and
// a pair of shape types in precision Real, one line each, in the order the reports list them.
// A kind is added here once (and a shape reader in each program if its shape is new); the
// Python drivers (bench_queries.py, accuracy_vs_time.py) name the same kinds.
#pragma once

#include <circledist/circledist.hpp>

namespace circledist::bench {

// Calls v.template add<A, B>(name) for every kind.
template <class Real, class Visitor> void for_each_kind(Visitor&& v) {
  v.template add<Vec3<Real>, Circle3<Real>>("point-circle");
  v.template add<Vec3<Real>, Disk3<Real>>("point-disk");
  v.template add<Line3<Real>, Circle3<Real>>("line-circle");
  v.template add<Ray3<Real>, Circle3<Real>>("ray-circle");
  v.template add<Segment3<Real>, Circle3<Real>>("segment-circle");
  v.template add<Line3<Real>, Disk3<Real>>("line-disk");
  v.template add<Ray3<Real>, Disk3<Real>>("ray-disk");
  v.template add<Segment3<Real>, Disk3<Real>>("segment-disk");
  v.template add<Circle3<Real>, Circle3<Real>>("circle-circle");
  v.template add<Circle3<Real>, Disk3<Real>>("circle-disk");
  v.template add<Disk3<Real>, Disk3<Real>>("disk-disk");
  v.template add<BezierCurve3<Real>, Circle3<Real>>("bezier-circle");
  v.template add<BezierCurve3<Real>, Disk3<Real>>("bezier-disk");
  v.template add<BezierCurve3<Real>, BezierCurve3<Real>>("bezier-bezier");
  // Arcs and annuli: the arc or annulus second, the order the front end answers in.
  v.template add<Vec3<Real>, Arc3<Real>>("point-arc");
  v.template add<Line3<Real>, Arc3<Real>>("line-arc");
  v.template add<Ray3<Real>, Arc3<Real>>("ray-arc");
  v.template add<Segment3<Real>, Arc3<Real>>("segment-arc");
  v.template add<Circle3<Real>, Arc3<Real>>("circle-arc");
  v.template add<Disk3<Real>, Arc3<Real>>("disk-arc");
  v.template add<Arc3<Real>, Arc3<Real>>("arc-arc");
  v.template add<BezierCurve3<Real>, Arc3<Real>>("bezier-arc");
  // In the arc's plane (the toolpath case), and the same inputs against the arc's circle.
  v.template add<Vec3<Real>, Arc3<Real>>("point-arc-coplanar");
  v.template add<Line3<Real>, Arc3<Real>>("line-arc-coplanar");
  v.template add<Ray3<Real>, Arc3<Real>>("ray-arc-coplanar");
  v.template add<Segment3<Real>, Arc3<Real>>("segment-arc-coplanar");
  v.template add<Circle3<Real>, Arc3<Real>>("circle-arc-coplanar");
  v.template add<Vec3<Real>, Circle3<Real>>("point-circle-coplanar");
  v.template add<Line3<Real>, Circle3<Real>>("line-circle-coplanar");
  v.template add<Ray3<Real>, Circle3<Real>>("ray-circle-coplanar");
  v.template add<Segment3<Real>, Circle3<Real>>("segment-circle-coplanar");
  v.template add<Circle3<Real>, Circle3<Real>>("circle-circle-coplanar");
  v.template add<Vec3<Real>, Annulus3<Real>>("point-annulus");
  v.template add<Line3<Real>, Annulus3<Real>>("line-annulus");
  v.template add<Ray3<Real>, Annulus3<Real>>("ray-annulus");
  v.template add<Segment3<Real>, Annulus3<Real>>("segment-annulus");
  v.template add<Circle3<Real>, Annulus3<Real>>("circle-annulus");
  v.template add<Disk3<Real>, Annulus3<Real>>("disk-annulus");
  v.template add<Arc3<Real>, Annulus3<Real>>("arc-annulus");
  v.template add<Annulus3<Real>, Annulus3<Real>>("annulus-annulus");
  v.template add<BezierCurve3<Real>, Annulus3<Real>>("bezier-annulus");
}

}  // namespace circledist::bench
