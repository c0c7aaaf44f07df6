// One template evaluates every pair of shape kinds over a broadcast batch (PairKernels), and the
// tables the module looks a pair up in. Free of pybind11, like batch.hpp: the module (bindings/calls.hpp)
// turns the Python arguments into a Request, allocates the answers' arrays and releases the
// GIL; the kernels here only loop.
#pragma once

#include "batch.hpp"

#include <circledist/detail/point_round_lanes.hpp>
#include <circledist/effects.hpp>

#include <array>
#include <type_traits>

namespace circledist::python {

// The body run for each batch element is inlined into the loop over the batch: a call per
// element keeps the latencies of consecutive closed-form queries from overlapping (measured 2x
// on the point queries).
#if defined(__GNUC__) || defined(__clang__)
#define CIRCLEDIST_PER_ELEMENT __attribute__((always_inline))
#else
#define CIRCLEDIST_PER_ELEMENT
#endif

// One call of a pair over a batch, resolved by the module: both operands' fields broadcast
// (shape a first, in the table's order), where each element's fields sit, and where the answers
// go. closest_points' pointers are the caller's arrays, swapped when the caller gave b first, so
// that the answers land in the caller's order.
template <class Real> struct Request {
  Broadcast<Real> elements;
  int a_points, b_points;    // control points per Bezier curve
  bool swept;                // a shape has a sweep field that is not the constant 0
  Real* distance = nullptr;  // distance(), distance_if_within(), closest_points()
  bool* flag = nullptr;      // within(): the answer; closest_points(): `unique`
  Real *point_a = nullptr, *point_b = nullptr, *param_a = nullptr, *param_b = nullptr;

  Request(const Operand<Real>& a, const Operand<Real>& b, const Operand<Real>* limit, bool reversed, bool any_sweep)
      : elements(a, b, limit, reversed), a_points(a.points), b_points(b.points), swept(any_sweep) {}

  void store(Index i, const Result<Real>& r) const {
    distance[i] = r.distance;
    for (int k = 0; k < 3; ++k) {
      point_a[3 * i + k] = r.point_a[k];
      point_b[3 * i + k] = r.point_b[k];
    }
    for (int k = 0; k < 2; ++k) {
      param_a[2 * i + k] = r.param_a[k];
      param_b[2 * i + k] = r.param_b[k];
    }
    flag[i] = r.unique;
  }
};

// The queries of one pair of C++ primitive types (of scalar Real: double or long double) with one
// root policy, over a Request. Both argument orders run this code (the module swaps the operands
// and the answers' arrays, see Request), so the two orders agree to the bit by construction
// (circledist::distance(b, a) calls the (A, B) query too, query.hpp).
template <class Roots, class A, class B, class Real> struct PairKernels {
  // A point against a circle, a disk or an annulus in double: closest_points answers kLanes
  // elements at once (detail/point_round_lanes.hpp: the scalar query's answers, bit for bit).
  static constexpr bool kPointRoundLanes =
      std::is_same_v<A, Vec3<double>> &&
      (std::is_same_v<B, Circle3<double>> || std::is_same_v<B, Disk3<double>> || std::is_same_v<B, Annulus3<double>>);
  // Fields of both shapes, each with its sweep (within() adds the limit after them).
  static constexpr int kFields = int(kFieldCounts[ShapeTraits<A>::kind] + 1 + kFieldCounts[ShapeTraits<B>::kind] + 1);
  // Where shape b's fields and within()'s limit start: constants of the pair (a shape's fields
  // and its sweep), so that every field pointer sits at a fixed index and can stay in a register
  // (read at a runtime offset, the pointers lived in memory: 14.5 against 12.4 ns per
  // point-circle distance in a C++ loop over the kernel).
  static constexpr int kBAt = int(kFieldCounts[ShapeTraits<A>::kind] + 1), kLimitAt = kFields;
  using Fields = const Real* const*;

  // The C++ primitives of one element, swept by each shape's last field (sweep.hpp: a sweep of 0
  // gives the core's results bit for bit), and the bare ones for pairs where neither shape is swept
  // (the common case: no per-element sweep read, no swept wrapper in the loop).
  static A first_core(const Request<Real>& r, Fields f) { return ShapeTraits<A>::make(f, r.a_points); }
  static B second_core(const Request<Real>& r, Fields f) { return ShapeTraits<B>::make(f + kBAt, r.b_points); }
  static Swept<A> first(const Request<Real>& r, Fields f) { return {first_core(r, f), *f[kBAt - 1]}; }
  static Swept<B> second(const Request<Real>& r, Fields f) { return {second_core(r, f), *f[kLimitAt - 1]}; }

  // Each kernel answers the elements [begin, end) of the request's batch.
  static void distance(const Request<Real>& r, Index begin, Index end) {
    Real* out = r.distance;
    if (!r.swept) {
      r.elements.template for_each<kFields>(
          [&](Index i, Fields f)
              CIRCLEDIST_PER_ELEMENT { out[i] = circledist::distance<Roots>(first_core(r, f), second_core(r, f)); },
          begin, end);
    } else {
      r.elements.template for_each<kFields>(
          [&](Index i, Fields f)
              CIRCLEDIST_PER_ELEMENT { out[i] = circledist::distance<Roots>(first(r, f), second(r, f)); },
          begin, end);
    }
    stats().distances += std::uint64_t(end - begin);
  }

  // effects.hpp over the broadcast of a, b and the limits d.
  static void within(const Request<Real>& r, Index begin, Index end) {
    bool* out = r.flag;
    r.elements.template for_each<kFields + 1>(
        [&](Index i, Fields f)
            CIRCLEDIST_PER_ELEMENT { out[i] = circledist::within<Roots>(first(r, f), second(r, f), *f[kLimitAt]); },
        begin, end);
  }
  static void distance_if_within(const Request<Real>& r, Index begin, Index end) {
    Real* out = r.distance;
    r.elements.template for_each<kFields + 1>(
        [&](Index i, Fields f) CIRCLEDIST_PER_ELEMENT {
          out[i] = circledist::distance_if_within<Roots>(first(r, f), second(r, f), *f[kLimitAt]);
        },
        begin, end);
  }

  // closest_points of one element of an unswept pair, stored.
  CIRCLEDIST_PER_ELEMENT static void store_closest(const Request<Real>& r, Index i, Fields f) {
    r.store(i, circledist::closest_points<Roots>(first_core(r, f), second_core(r, f)));
  }

  static void closest(const Request<Real>& r, Index begin, Index end) {
    const auto one = [&](Index i, Fields f) CIRCLEDIST_PER_ELEMENT { store_closest(r, i, f); };
#if CIRCLEDIST_POINT_ROUND_LANES
    if constexpr (kPointRoundLanes) {
      if (!r.swept && detail::has_lanes()) {
        r.elements.template for_each_block<kFields, detail::kLanes>(PointRoundBlock{r}, one, begin, end);
        stats().closest_points += std::uint64_t(end - begin);
        return;
      }
    }
#endif
    if (!r.swept) {
      r.elements.template for_each<kFields>(one, begin, end);
    } else {
      r.elements.template for_each<kFields>(
          [&](Index i, Fields f)
              CIRCLEDIST_PER_ELEMENT { r.store(i, circledist::closest_points<Roots>(first(r, f), second(r, f))); },
          begin, end);
    }
    stats().closest_points += std::uint64_t(end - begin);
  }

#if CIRCLEDIST_POINT_ROUND_LANES
  // closest_points of kLanes consecutive elements of a point-round pair (fields: the point, its
  // sweep, the round's center, normal, radius (an annulus's inner and outer ones), its sweep):
  // loads the lanes, lets the query answer them, and stores the answers in the caller's layout;
  // where the lanes decline, the scalar query answers each element.
  struct PointRoundBlock {
    const Request<Real>& r;
    __attribute__((target("avx"))) void operator()(Index i, Fields f, const Index* step) const {
      // Field j (a 3-vector, or a number) of the kLanes elements: twelve consecutive numbers where
      // the field's elements are consecutive (the usual layout), else gathered lane by lane.
      const auto vector_lanes = [&](int j, detail::Lanes& x, detail::Lanes& y, detail::Lanes& z)
                                    __attribute__((target("avx"))) {
                                      if (step[j] == 3) return detail::load_triples(f[j], x, y, z);
                                      x = detail::strided_lanes(f[j], step[j]);
                                      y = detail::strided_lanes(f[j] + 1, step[j]);
                                      z = detail::strided_lanes(f[j] + 2, step[j]);
                                    };
      detail::PointRoundLanes in;
      vector_lanes(0, in.px, in.py, in.pz);
      vector_lanes(kBAt, in.cx, in.cy, in.cz);
      vector_lanes(kBAt + 1, in.wx, in.wy, in.wz);
      constexpr bool annulus = std::is_same_v<B, Annulus3<double>>;  // fields: inner, outer radius
      constexpr auto target = annulus                            ? detail::LaneTarget::kRing
                              : std::is_same_v<B, Disk3<double>> ? detail::LaneTarget::kDisk
                                                                 : detail::LaneTarget::kCircle;
      constexpr int outer = annulus ? kBAt + 3 : kBAt + 2;
      in.radius = detail::strided_lanes(f[outer], step[outer]);
      in.inner = annulus ? detail::strided_lanes(f[kBAt + 2], step[kBAt + 2]) : in.radius;
      detail::PointRoundAnswerLanes out;
      if (!detail::point_round_closest_lanes<target>(in, out)) {
        for (int k = 0; k < detail::kLanes; ++k) {
          std::array<const Real*, kFields> g{};
          for (int j = 0; j < kFields; ++j) g[j] = f[j] + k * step[j];
          store_closest(r, i + k, g.data());
        }
        return;
      }
      out.distance.to(r.distance + i);
      detail::store_triples(in.px, in.py, in.pz, r.point_a + 3 * i);  // the point itself
      detail::store_triples(out.bx, out.by, out.bz, r.point_b + 3 * i);
      detail::store_pairs(detail::Lanes::both(0), detail::Lanes::both(0), r.param_a + 2 * i);
      detail::store_pairs(out.param0, out.param1, r.param_b + 2 * i);
      for (int k = 0; k < detail::kLanes; ++k) r.flag[i + k] = true;
    }
  };
#endif
};

template <class Real> using KernelFn = void (*)(const Request<Real>&, Index begin, Index end);

// The pairs of one precision and root policy, indexed by the kinds of both arguments in the
// caller's order; `reversed` where the entry is the (B, A) kernel's, run with the operands swapped.
template <class Real> struct PairTable {
  KernelFn<Real> distance[kKindCount][kKindCount] = {};
  KernelFn<Real> closest[kKindCount][kKindCount] = {};
  KernelFn<Real> within[kKindCount][kKindCount] = {};
  KernelFn<Real> distance_if_within[kKindCount][kKindCount] = {};
  bool reversed[kKindCount][kKindCount] = {};
};

enum Precision : int { kFloat, kDouble, kLongDouble, kPrecisionCount };
enum Solver : int { kCompanion, kPolished, kBracketing, kEigen, kSolverCount };

// The table index of a root policy.
template <class Roots> constexpr int solver_index() {
  if constexpr (std::is_same_v<Roots, EigenPolished>)
    return kPolished;
  else if constexpr (std::is_same_v<Roots, Bracketing>)
    return kBracketing;
  else if constexpr (std::is_same_v<Roots, EigenPolynomialSolver>)
    return kEigen;
  else
    return kCompanion;
}

// The tables of the precisions that have their own instantiations: double and long double
// (float32 queries run the double tables' entries, bindings/float32.hpp).
struct PairTables {
  PairTable<double> doubles[kSolverCount];
  PairTable<long double> long_doubles[kSolverCount];
  int default_solver = solver_index<DefaultRoots>();  // solver=None: the C++ default

  template <class Real> PairTable<Real>& of(int solver) {
    if constexpr (std::is_same_v<Real, long double>)
      return long_doubles[solver];
    else
      return doubles[solver];
  }
  template <class Real> const PairTable<Real>& of(int solver) const {
    return const_cast<PairTables*>(this)->of<Real>(solver);
  }
};

// Enters a pair's kernels with one policy, for both argument orders (one instantiation).
template <class Roots, class Real> struct PairRegistrar {
  PairTable<Real>& table;
  template <class A, class B> void add() {
    using Kernels = PairKernels<Roots, A, B, Real>;
    constexpr int ka = ShapeTraits<A>::kind, kb = ShapeTraits<B>::kind;
    for (const bool reversed : {false, true}) {
      const int first = reversed ? kb : ka, second = reversed ? ka : kb;
      table.distance[first][second] = &Kernels::distance;
      table.closest[first][second] = &Kernels::closest;
      table.within[first][second] = &Kernels::within;
      table.distance_if_within[first][second] = &Kernels::distance_if_within;
      table.reversed[first][second] = reversed && ka != kb;
    }
  }
};

// The pairs the module offers, in two lists: those whose queries solve polynomials (compiled
// once per precision and root policy), and those answered in closed form, which no root policy
// changes (compiled once per precision, with NoRoots, and entered in every solver's table).
template <class Real, class Visitor> void for_each_polynomial_pair(Visitor&& v) {
  v.template add<Line3<Real>, Circle3<Real>>();
  v.template add<Ray3<Real>, Circle3<Real>>();
  v.template add<Segment3<Real>, Circle3<Real>>();
  v.template add<Line3<Real>, Disk3<Real>>();
  v.template add<Ray3<Real>, Disk3<Real>>();
  v.template add<Segment3<Real>, Disk3<Real>>();
  v.template add<Circle3<Real>, Circle3<Real>>();
  v.template add<Circle3<Real>, Disk3<Real>>();
  v.template add<Disk3<Real>, Disk3<Real>>();
  v.template add<BezierCurve3<Real>, Disk3<Real>>();
  v.template add<BezierCurve3<Real>, Circle3<Real>>();
  v.template add<BezierCurve3<Real>, Vec3<Real>>();   // bezier_point.hpp
  v.template add<BezierCurve3<Real>, Line3<Real>>();  // bezier_linear.hpp
  v.template add<BezierCurve3<Real>, Ray3<Real>>();
  v.template add<BezierCurve3<Real>, Segment3<Real>>();
  v.template add<BezierCurve3<Real>, BezierCurve3<Real>>();  // bezier_bezier.hpp
  // arc.hpp: an arc against every kind; bezier_arc.hpp: against a Bezier curve.
  v.template add<BezierCurve3<Real>, Arc3<Real>>();
  v.template add<Line3<Real>, Arc3<Real>>();
  v.template add<Ray3<Real>, Arc3<Real>>();
  v.template add<Segment3<Real>, Arc3<Real>>();
  v.template add<Circle3<Real>, Arc3<Real>>();
  v.template add<Disk3<Real>, Arc3<Real>>();
  v.template add<Arc3<Real>, Arc3<Real>>();
  // annulus.hpp: an annulus against every kind.
  v.template add<BezierCurve3<Real>, Annulus3<Real>>();
  v.template add<Line3<Real>, Annulus3<Real>>();
  v.template add<Ray3<Real>, Annulus3<Real>>();
  v.template add<Segment3<Real>, Annulus3<Real>>();
  v.template add<Circle3<Real>, Annulus3<Real>>();
  v.template add<Disk3<Real>, Annulus3<Real>>();
  v.template add<Arc3<Real>, Annulus3<Real>>();
  v.template add<Annulus3<Real>, Annulus3<Real>>();
}
template <class Real, class Visitor> void for_each_closed_form_pair(Visitor&& v) {
  v.template add<Vec3<Real>, Circle3<Real>>();   // point_circle.hpp
  v.template add<Vec3<Real>, Disk3<Real>>();     // point_disk.hpp
  v.template add<Vec3<Real>, Arc3<Real>>();      // arc.hpp (closed form)
  v.template add<Vec3<Real>, Annulus3<Real>>();  // annulus.hpp (closed form)
  // linear_linear.hpp: points, lines, rays and segments against each other.
  v.template add<Vec3<Real>, Vec3<Real>>();
  v.template add<Vec3<Real>, Line3<Real>>();
  v.template add<Vec3<Real>, Ray3<Real>>();
  v.template add<Vec3<Real>, Segment3<Real>>();
  v.template add<Line3<Real>, Line3<Real>>();
  v.template add<Line3<Real>, Ray3<Real>>();
  v.template add<Line3<Real>, Segment3<Real>>();
  v.template add<Ray3<Real>, Ray3<Real>>();
  v.template add<Ray3<Real>, Segment3<Real>>();
  v.template add<Segment3<Real>, Segment3<Real>>();
}

// The root "policy" of the closed-form pairs: it has no members, so a closed-form query that
// reached for a root solver would not compile here.
struct NoRoots {};

// The pairs of one precision and root policy: one translation unit each (pair_unit.cpp, built
// once per entry of CIRCLEDIST_PAIR_UNITS by CMakeLists.txt), so that both cores stay busy.
// Counted<>: every polynomial solve is counted in circledist::stats() (effects.hpp).
// The three eigenvalue policies are one unit, SelectedEigenPolicy (roots.hpp), whose entries fill
// the three solvers' tables; the query's Choice (bindings/arguments.hpp) selects among them for the call.
// NoRoots: the closed-form pairs, the same entries in every solver's table.
template <class Real, class Roots> void register_pairs(PairTables& t) {
  if constexpr (std::is_same_v<Roots, NoRoots>) {
    for (const int solver : {kCompanion, kPolished, kBracketing, kEigen})
      for_each_closed_form_pair<Real>(PairRegistrar<NoRoots, Real>{t.of<Real>(solver)});
  } else if constexpr (std::is_same_v<Roots, SelectedEigenPolicy>) {
    for (const int solver : {kCompanion, kPolished, kEigen})
      for_each_polynomial_pair<Real>(PairRegistrar<Counted<Roots>, Real>{t.of<Real>(solver)});
  } else {
    for_each_polynomial_pair<Real>(PairRegistrar<Counted<Roots>, Real>{t.of<Real>(solver_index<Roots>())});
  }
}

// What SelectedEigenPolicy runs for a table's solver (the default policy has a unit of its own).
inline SelectedEigenPolicy::Which selected_eigen_policy(int solver) {
  if (solver == kPolished) return SelectedEigenPolicy::Which::Polished;
  if (solver == kEigen) return SelectedEigenPolicy::Which::PolynomialSolver;
  return SelectedEigenPolicy::Which::Companion;
}

// The units, listed once: X(Real, Roots) for each precision and policy. Each is compiled by
// pair_unit.cpp alone (CMakeLists.txt builds it once per entry, with the same list); the module
// sees the declarations only, and registers each unit once. The default policy, Bracketing, has
// its own unit, so its path pays no switch.
// clang-format off: one line per precision
#define CIRCLEDIST_PAIR_UNITS(X)                                                         \
  X(double, Bracketing) X(double, SelectedEigenPolicy) X(double, NoRoots)                \
  X(long double, Bracketing) X(long double, SelectedEigenPolicy) X(long double, NoRoots)
// clang-format on
#define CIRCLEDIST_DECLARE_PAIR_UNIT(REAL, ROOTS) extern template void register_pairs<REAL, ROOTS>(PairTables&);
CIRCLEDIST_PAIR_UNITS(CIRCLEDIST_DECLARE_PAIR_UNIT)
#undef CIRCLEDIST_DECLARE_PAIR_UNIT

}  // namespace circledist::python
