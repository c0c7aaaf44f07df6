// One template evaluates every pair of shape kinds over broadcast batches; the module registers
// each pair with a single line. Loops run in C++ with the GIL released.
#pragma once

#include "shapes.hpp"

#include <circledist/effects.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <type_traits>

namespace circledist::python {

// The body run for each batch element is inlined into the loop over the batch: a call per
// element keeps the latencies of consecutive closed-form queries from overlapping (measured 2x
// on the point queries).
#if defined(__GNUC__) || defined(__clang__)
#define CIRCLEDIST_PER_ELEMENT __attribute__((always_inline))
#define CIRCLEDIST_GLUE __attribute__((noinline))
#else
#define CIRCLEDIST_PER_ELEMENT
#define CIRCLEDIST_GLUE
#endif
// CIRCLEDIST_GLUE: the Python-facing steps shared by every pair (building arrays and results,
// broadcasting) stay out of line, one copy per unit instead of one per pair and entry point.
// (Measured: this alone changed neither a unit's compile time nor its size by more than 2 %;
// the time is in the queries themselves.)

constexpr int kMaxFields = 12;  // two shapes of up to 5 fields (with the sweep), and a limit

// Offsets (in values of the storage type T: double, or long double for long-double queries) of
// every field of both shapes for each element of the broadcast batch. Fields that are full-size
// in the result's layout or constant step linearly (the fast path); others (e.g. (N, 1) against
// (M,)) walk an odometer.
template <class T> class Broadcast {
 public:
  BatchShape shape;
  Index size = 1;

  // `limit` (optional): a third batch, the distances of within(), broadcast with both shapes.
  // `reversed`: the caller gave b first (see PairOf), which the message keeps.
  CIRCLEDIST_GLUE Broadcast(const Shape& a, const Shape& b, const Shape* limit = nullptr, bool reversed = false) {
    bool ok = true;
    shape = broadcast_shapes(a.batch, b.batch, ok);
    if (!ok) {
      const Shape& first = reversed ? b : a;
      const Shape& second = reversed ? a : b;
      throw py::value_error(std::string("batch shapes ") + shape_text(first.batch) + " of the " +
                            kind_name(first.kind) + " and " + shape_text(second.batch) + " of the " +
                            kind_name(second.kind) + " do not broadcast");
    }
    if (limit) {
      const BatchShape joined = broadcast_shapes(shape, limit->batch, ok);
      if (!ok)
        throw py::value_error(std::string(limit->fields[0].name) + " of batch shape " + shape_text(limit->batch) +
                              " does not broadcast with the shapes' batch shape " + shape_text(shape));
      shape = joined;
    }
    for (Index d : shape) size *= d;
    add(a);
    add(b);
    if (limit) add(*limit);
  }

  // Calls fn(flat_index, field_pointers) for every element. `Count`: the pair's field count (a
  // constant of the pair, PairOf::kFields), so that the pointers stay in registers and advance by
  // a fixed step (most of the loop's own cost on the point queries), in one copy of the loop.
  template <int Count, class Fn> void for_each(Fn&& fn) const {
    static_assert(Count <= kMaxFields, "kMaxFields");
    if (count_ != Count) throw std::logic_error("circledist: a pair's field count disagrees with its shapes");
    if (linear_) return run<Count>(fn, base_.data(), step_.data(), 0, size);
    // Other broadcasts (e.g. (N, 1) against (M,)) walk an odometer that gathers each chunk of
    // elements into contiguous scratch, over which the same loop runs: the query is compiled
    // into one loop only (the build's time), and the gathering costs little beside it.
    constexpr Index kChunk = 256;
    std::array<std::vector<T>, kMaxFields> scratch;
    std::array<const T*, kMaxFields> base{};
    std::array<Index, kMaxFields> step{}, offset{};
    for (int f = 0; f < count_; ++f) {
      scratch[f].resize(size_t(kChunk * width_[f]));
      base[f] = scratch[f].data();
      step[f] = width_[f];
    }
    const size_t nd = shape.size();
    std::vector<Index> idx(nd, 0);
    for (Index start = 0; start < size; start += kChunk) {
      const Index n = std::min(kChunk, size - start);
      for (Index j = 0; j < n; ++j) {
        for (int f = 0; f < count_; ++f)
          std::copy_n(base_[f] + offset[f], width_[f], scratch[f].data() + j * width_[f]);
        for (size_t d = nd; d-- > 0;) {
          ++idx[d];
          for (int f = 0; f < count_; ++f) offset[f] += stride_[f][d];
          if (idx[d] < shape[d]) break;
          for (int f = 0; f < count_; ++f) offset[f] -= stride_[f][d] * shape[d];
          idx[d] = 0;
        }
      }
      run<Count>(fn, base.data(), step.data(), start, n);
    }
  }

 private:
  // fn(start + i, pointers) for i in [0, n), each field's pointer advancing by its step.
  template <int N, class Fn>
  void run(Fn& fn, const T* const* base, const Index* step, Index start, Index n) const {
    std::array<const T*, N> ptr{};
    std::array<Index, N> st{};
    for (int f = 0; f < N; ++f) ptr[f] = base[f], st[f] = step[f];
    for (Index i = 0; i < n; ++i) {
      fn(start + i, ptr.data());
      for (int f = 0; f < N; ++f) ptr[f] += st[f];
    }
  }

  int count_ = 0;
  bool linear_ = true;
  std::array<const T*, kMaxFields> base_{};
  std::array<Index, kMaxFields> step_{}, width_{};
  std::array<std::vector<Index>, kMaxFields> stride_;

  void add(const Shape& s) {
    const size_t nd = shape.size();
    for (const Field& field : s.fields) {
      const int f = count_++;
      base_[f] = field.template data_as<T>();
      width_[f] = field.width;
      std::vector<Index>& st = stride_[f];
      st.assign(nd, 0);
      Index step = field.width;
      bool full = field.batch.size() == nd;
      for (size_t k = 0; k < field.batch.size(); ++k) {
        const size_t d = nd - 1 - k;
        const Index extent = field.batch[field.batch.size() - 1 - k];
        if (extent != shape[d]) full = false;
        st[d] = extent == 1 ? 0 : step;
        step *= extent;
      }
      if (field.batch.empty() || step == field.width) {
        step_[f] = 0;  // one element repeated
      } else if (full) {
        step_[f] = field.width;
      } else {
        linear_ = false;
      }
    }
  }
};

struct ClosestPoints {
  py::object distance, point_a, point_b, param_a, param_b, unique;
};

template <class T> CIRCLEDIST_GLUE py::array_t<T> new_array(const BatchShape& batch, Index trailing) {
  BatchShape shape = batch;
  if (trailing > 0) shape.push_back(trailing);
  return py::array_t<T>(shape);
}

// A single result: a Python float in double, a NumPy long double in long double.
template <class Real> CIRCLEDIST_GLUE py::object scalar(Real value) {
  if constexpr (std::is_same_v<Real, long double>) {
    auto out = new_array<long double>({}, 0);
    *out.mutable_data() = value;
    return out[py::tuple()];
  } else {
    return py::float_(double(value));
  }
}

// The arrays closest_points() fills, in the caller's order, and where a pair's answers go: the
// first shape's points and parameters to the caller's second ones when the caller gave them in
// the other order (`reversed`, PairOf).
template <class Real> struct ClosestArrays {
  BatchShape shape;
  py::array_t<Real> distance, point_a, point_b, param_a, param_b;
  py::array_t<bool> unique;
  Real *d, *xa, *xb, *ua, *ub;
  bool* u;

  CIRCLEDIST_GLUE ClosestArrays(const BatchShape& batch, bool reversed)
      : shape(batch),
        distance(new_array<Real>(batch, 0)),
        point_a(new_array<Real>(batch, 3)),
        point_b(new_array<Real>(batch, 3)),
        param_a(new_array<Real>(batch, 2)),
        param_b(new_array<Real>(batch, 2)),
        unique(new_array<bool>(batch, 0)),
        d(distance.mutable_data()),
        xa(point_a.mutable_data()),
        xb(point_b.mutable_data()),
        ua(param_a.mutable_data()),
        ub(param_b.mutable_data()),
        u(unique.mutable_data()) {
    if (reversed) {
      std::swap(xa, xb);
      std::swap(ua, ub);
    }
  }

  CIRCLEDIST_INLINE void store(Index i, const Result<Real>& r) {
    d[i] = r.distance;
    for (int k = 0; k < 3; ++k) {
      xa[3 * i + k] = r.point_a[k];
      xb[3 * i + k] = r.point_b[k];
    }
    for (int k = 0; k < 2; ++k) {
      ua[2 * i + k] = r.param_a[k];
      ub[2 * i + k] = r.param_b[k];
    }
    u[i] = r.unique;
  }

  // A single query's distance and flag are a Python float (a NumPy long double) and bool.
  CIRCLEDIST_GLUE ClosestPoints result() {
    if (shape.empty())
      return {scalar<Real>(d[0]), std::move(point_a), std::move(point_b), std::move(param_a), std::move(param_b),
              py::bool_(u[0])};
    return {std::move(distance), std::move(point_a), std::move(point_b), std::move(param_a), std::move(param_b),
            std::move(unique)};
  }
};

// Evaluation of one pair of C++ primitive types (of scalar Real: double or long double) with one
// root policy. The other argument order runs the same code with `reversed` set: the shapes come
// in as (A, B) and the answers go out in the caller's order, so one instantiation serves both
// orders and the two orders agree to the bit by construction (circledist::distance(b, a) calls
// the (A, B) query too, query.hpp).
template <class Roots, class A, class B, class Real> struct PairOf {
  // The values an element reads: float64 for double, long double for long double (float32
  // queries are double queries on inputs rounded to float32: float32.hpp).
  using T = Real;
  using Broadcast = circledist::python::Broadcast<T>;
  // Fields of both shapes, each with its sweep (within() adds the limit after them).
  static constexpr int kFields =
      int(kFieldCounts[ShapeTraits<A>::kind] + 1 + kFieldCounts[ShapeTraits<B>::kind] + 1);
  // Where each shape's fields sit among an element's field pointers, read once per call: the
  // per-element work is then only the loads (no vector sizes in the loop).
  struct Layout {
    int b_at, limit_at, a_points, b_points;  // limit_at: within()'s distance, after both shapes
    Layout(const Shape& a, const Shape& b)
        : b_at(int(a.fields.size())),
          limit_at(int(a.fields.size() + b.fields.size())),
          a_points(a.points),
          b_points(b.points) {}

    // The C++ primitives of one element, swept by each shape's last field (sweep.hpp: a sweep of
    // 0 gives the core's results bit for bit); `points` is each shape's Bezier control point count.
    Swept<A> first(const T* const* f) const { return {first_core(f), Real(*f[b_at - 1])}; }
    Swept<B> second(const T* const* f) const { return {second_core(f), Real(*f[limit_at - 1])}; }
    // The bare primitives, for pairs where neither shape is swept (the common case: no
    // per-element sweep read, no swept wrapper in the loop).
    A first_core(const T* const* f) const { return ShapeTraits<A>::make(f, a_points); }
    B second_core(const T* const* f) const { return ShapeTraits<B>::make(f + b_at, b_points); }
  };

  static bool unswept(const Shape& s) {
    const Field& sweep = s.fields.back();
    return sweep.batch.empty() && *sweep.data() == 0;
  }

  static py::object distance(const Shape& a, const Shape& b, bool reversed) {
    if (a.batch.empty() && b.batch.empty()) {
      std::array<const T*, kMaxFields> f{};
      int k = 0;
      for (const Field& x : a.fields) f[k++] = x.template data_as<T>();
      for (const Field& x : b.fields) f[k++] = x.template data_as<T>();
      ++stats().distances;
      const Layout at(a, b);
      return scalar<Real>(circledist::distance<Roots>(at.first(f.data()), at.second(f.data())));
    }
    const Broadcast bc(a, b, nullptr, reversed);
    const Layout at(a, b);
    auto out = new_array<Real>(bc.shape, 0);
    Real* o = out.mutable_data();
    {
      py::gil_scoped_release release;
      if (unswept(a) && unswept(b)) {
        bc.template for_each<kFields>([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
          o[i] = circledist::distance<Roots>(at.first_core(f), at.second_core(f));
        });
      } else {
        bc.template for_each<kFields>([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
          o[i] = circledist::distance<Roots>(at.first(f), at.second(f));
        });
      }
    }
    stats().distances += std::uint64_t(bc.size);
    return std::move(out);
  }

  // effects.hpp over the broadcast of a, b and the limits d: within() (a bool per element) or,
  // with `want_distance`, distance_if_within() (the distance, +inf beyond d).
  static py::object within(const Shape& a, const Shape& b, const Shape& limit, bool want_distance, bool reversed) {
    const Broadcast bc(a, b, &limit, reversed);
    const Layout at(a, b);
    if (want_distance) {
      auto out = new_array<Real>(bc.shape, 0);
      Real* o = out.mutable_data();
      {
        py::gil_scoped_release release;
        bc.template for_each<kFields + 1>([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
          o[i] = circledist::distance_if_within<Roots>(at.first(f), at.second(f), Real(*f[at.limit_at]));
        });
      }
      if (bc.shape.empty()) return scalar<Real>(o[0]);
      return std::move(out);
    }
    auto out = new_array<bool>(bc.shape, 0);
    bool* o = out.mutable_data();
    {
      py::gil_scoped_release release;
      bc.template for_each<kFields + 1>([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
        o[i] = circledist::within<Roots>(at.first(f), at.second(f), Real(*f[at.limit_at]));
      });
    }
    if (bc.shape.empty()) return py::bool_(o[0]);
    return std::move(out);
  }

  static ClosestPoints closest(const Shape& a, const Shape& b, bool reversed) {
    const Broadcast bc(a, b, nullptr, reversed);
    const Layout at(a, b);
    ClosestArrays<Real> out(bc.shape, reversed);
    {
      py::gil_scoped_release release;
      bc.template for_each<kFields>([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
        out.store(i, circledist::closest_points<Roots>(at.first(f), at.second(f)));
      });
    }
    stats().closest_points += std::uint64_t(bc.size);
    return out.result();
  }
};

// The table entries of a pair in the caller's order: Forward for (A, B), Reversed for (B, A).
template <class Pair> struct Forward {
  static py::object distance(const Shape& a, const Shape& b) { return Pair::distance(a, b, false); }
  static ClosestPoints closest(const Shape& a, const Shape& b) { return Pair::closest(a, b, false); }
  static py::object within(const Shape& a, const Shape& b, const Shape& limit, bool want_distance) {
    return Pair::within(a, b, limit, want_distance, false);
  }
};
template <class Pair> struct Reversed {
  static py::object distance(const Shape& b, const Shape& a) { return Pair::distance(a, b, true); }
  static ClosestPoints closest(const Shape& b, const Shape& a) { return Pair::closest(a, b, true); }
  static py::object within(const Shape& b, const Shape& a, const Shape& limit, bool want_distance) {
    return Pair::within(a, b, limit, want_distance, true);
  }
};

using DistanceFn = py::object (*)(const Shape&, const Shape&);
using ClosestFn = ClosestPoints (*)(const Shape&, const Shape&);
using WithinFn = py::object (*)(const Shape&, const Shape&, const Shape&, bool);

// The pairs of one precision and root policy, indexed by the kinds of both arguments.
struct PairTable {
  DistanceFn distance[kKindCount][kKindCount] = {};
  ClosestFn closest[kKindCount][kKindCount] = {};
  WithinFn within[kKindCount][kKindCount] = {};
};

enum Precision : int { kFloat, kDouble, kLongDouble, kPrecisionCount };
enum Solver : int { kCompanion, kPolished, kBracketing, kEigen, kSolverCount };

// The table index of a root policy.
template <class Roots> constexpr int solver_index() {
  if constexpr (std::is_same_v<Roots, EigenPolished>) return kPolished;
  else if constexpr (std::is_same_v<Roots, Bracketing>) return kBracketing;
  else if constexpr (std::is_same_v<Roots, EigenPolynomialSolver>) return kEigen;
  else return kCompanion;
}

// The tables of the precisions that have their own instantiations: double and long double
// (float32 queries run the double table's entries, precision.hpp).
struct PairTables {
  PairTable table[kPrecisionCount][kSolverCount];
  int default_solver = solver_index<DefaultRoots>();  // solver=None: the C++ default
};

// Registers both argument orders of a pair with one policy (one instantiation, see PairOf).
template <class Roots, class Real> struct PairRegistrar {
  PairTable& table;
  template <class A, class B> void add() {
    using Pair = PairOf<Roots, A, B, Real>;
    constexpr int ka = ShapeTraits<A>::kind, kb = ShapeTraits<B>::kind;
    table.distance[ka][kb] = &Forward<Pair>::distance;
    table.closest[ka][kb] = &Forward<Pair>::closest;
    table.within[ka][kb] = &Forward<Pair>::within;
    if constexpr (ka != kb) {
      table.distance[kb][ka] = &Reversed<Pair>::distance;
      table.closest[kb][ka] = &Reversed<Pair>::closest;
      table.within[kb][ka] = &Reversed<Pair>::within;
    }
  }
};

// The one list of pairs the module offers.
template <class Real, class Visitor> void for_each_pair(Visitor&& v) {
  v.template add<Vec3<Real>, Circle3<Real>>();
  v.template add<Vec3<Real>, Disk3<Real>>();
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
  // Closed forms (linear_linear.hpp): points, lines, rays and segments against each other.
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

// Every pair of one precision and root policy: one translation unit each (pair_unit.cpp, built
// once per precision and policy by CMakeLists.txt), so that both cores stay busy. Counted<>:
// every polynomial solve is counted in circledist::stats() (effects.hpp).
// The three eigenvalue policies are one unit, SelectedEigenPolicy (roots.hpp), whose entries fill
// the three solvers' tables; the query's Choice (_core.cpp) selects among them for the call.
template <class Real, class Roots> void register_pairs(PairTables& t) {
  constexpr int precision = std::is_same_v<Real, long double> ? kLongDouble : kDouble;
  if constexpr (std::is_same_v<Roots, SelectedEigenPolicy>) {
    for (const int solver : {kCompanion, kPolished, kEigen})
      for_each_pair<Real>(PairRegistrar<Counted<Roots>, Real>{t.table[precision][solver]});
  } else {
    for_each_pair<Real>(PairRegistrar<Counted<Roots>, Real>{t.table[precision][solver_index<Roots>()]});
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
#define CIRCLEDIST_PAIR_UNITS(X)                                                        \
  X(double, Bracketing) X(double, SelectedEigenPolicy)                                  \
  X(long double, Bracketing) X(long double, SelectedEigenPolicy)
#define CIRCLEDIST_DECLARE_PAIR_UNIT(REAL, ROOTS) extern template void register_pairs<REAL, ROOTS>(PairTables&);
CIRCLEDIST_PAIR_UNITS(CIRCLEDIST_DECLARE_PAIR_UNIT)
#undef CIRCLEDIST_DECLARE_PAIR_UNIT

}  // namespace circledist::python
