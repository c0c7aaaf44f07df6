// Arc-arc (Query<Arc3, Arc3>). Derivation: docs/derivations/arc.md#an-arc.
#pragma once

#include "circle_arc.hpp"
#include "detail/arc_span.hpp"
#include "point_arc.hpp"
#include "query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace circledist {

namespace detail {

// ---------------------------------------------------------------------------------------------
// Arc against arc: the smaller parametrized against the other (ArcArcQuery); an arc that is
// whole is a circle (Query<Circle3, Arc3>), a zero radius a point.
template <class Real> struct ArcArcPair {
  static constexpr bool defined = true;
  using CircleArc = Query<Circle3<Real>, Arc3<Real>>;

  static bool first_parametrized(const Arc3<Real>& a, const Arc3<Real>& b) { return a.radius <= b.radius; }

  template <class Roots = DefaultRoots> static Real distance(const Arc3<Real>& a, const Arc3<Real>& b) {
    if (whole_arc(a)) return CircleArc::template distance<Roots>(arc_circle(a), b);
    if (whole_arc(b)) return CircleArc::template distance<Roots>(arc_circle(b), a);
    if (!(a.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template distance<Roots>(a.center, b);
    if (!(b.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template distance<Roots>(b.center, a);
    return first_parametrized(a, b) ? ArcArcQuery<Real>::template distance<Roots>(arc_circle(a), ArcSpan<Real>(a), b)
                                    : ArcArcQuery<Real>::template distance<Roots>(arc_circle(b), ArcSpan<Real>(b), a);
  }

  template <class Roots = DefaultRoots> static Result<Real> closest(const Arc3<Real>& a, const Arc3<Real>& b) {
    if (whole_arc(a)) return as_arc_result(CircleArc::template closest<Roots>(arc_circle(a), b), ArcSpan<Real>(a), 0);
    if (whole_arc(b))
      return as_arc_result(CircleArc::template closest<Roots>(arc_circle(b), a), ArcSpan<Real>(b), 0).swapped();
    if (!(a.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template closest<Roots>(a.center, b);
    if (!(b.radius > 0)) return Query<Vec3<Real>, Arc3<Real>>::template closest<Roots>(b.center, a).swapped();
    return first_parametrized(a, b)
               ? ArcArcQuery<Real>::template closest<Roots>(arc_circle(a), ArcSpan<Real>(a), b, true)
               : ArcArcQuery<Real>::template closest<Roots>(arc_circle(b), ArcSpan<Real>(b), a, true).swapped();
  }
};

}  // namespace detail

template <class Real> struct Query<Arc3<Real>, Arc3<Real>> : detail::ArcArcPair<Real> {};

}  // namespace circledist
