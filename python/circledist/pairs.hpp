// One template evaluates every pair of shape kinds over broadcast batches; the module registers
// each pair with a single line. Loops run in C++ with the GIL released.
#pragma once

#include "shapes.hpp"

#include <circledist/effects.hpp>

#include <array>
#include <stdexcept>
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
  Broadcast(const Shape& a, const Shape& b, const Shape* limit = nullptr) {
    bool ok = true;
    shape = broadcast_shapes(a.batch, b.batch, ok);
    if (!ok)
      throw py::value_error(std::string("batch shapes ") + shape_text(a.batch) + " of the " + kind_name(a.kind) +
                            " and " + shape_text(b.batch) + " of the " + kind_name(b.kind) + " do not broadcast");
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

  // Calls fn(flat_index, field_pointers) for every element.
  template <class Fn> void for_each(Fn&& fn) const {
    std::array<const T*, kMaxFields> ptr{};
    if (linear_) {
      // The field count as a constant: the pointers stay in registers and advance by a fixed
      // step (most of the loop's own cost on the point queries).
      switch (count_) {
        case 4: return linear_loop<4>(fn);
        case 5: return linear_loop<5>(fn);
        case 6: return linear_loop<6>(fn);
        case 7: return linear_loop<7>(fn);
        case 8: return linear_loop<8>(fn);
        default: break;
      }
      for (Index i = 0; i < size; ++i) {
        for (int f = 0; f < count_; ++f) ptr[f] = base_[f] + i * step_[f];
        fn(i, ptr.data());
      }
      return;
    }
    const size_t nd = shape.size();
    std::vector<Index> idx(nd, 0);
    std::array<Index, kMaxFields> offset{};
    for (Index i = 0; i < size; ++i) {
      for (int f = 0; f < count_; ++f) ptr[f] = base_[f] + offset[f];
      fn(i, ptr.data());
      for (size_t d = nd; d-- > 0;) {
        ++idx[d];
        for (int f = 0; f < count_; ++f) offset[f] += stride_[f][d];
        if (idx[d] < shape[d]) break;
        for (int f = 0; f < count_; ++f) offset[f] -= stride_[f][d] * shape[d];
        idx[d] = 0;
      }
    }
  }

 private:
  template <int N, class Fn> void linear_loop(Fn& fn) const {
    std::array<const T*, N> ptr{};
    std::array<Index, N> step{};
    for (int f = 0; f < N; ++f) ptr[f] = base_[f], step[f] = step_[f];
    for (Index i = 0; i < size; ++i) {
      fn(i, ptr.data());
      for (int f = 0; f < N; ++f) ptr[f] += step[f];
    }
  }

  int count_ = 0;
  bool linear_ = true;
  std::array<const T*, kMaxFields> base_{};
  std::array<Index, kMaxFields> step_{};
  std::array<std::vector<Index>, kMaxFields> stride_;

  void add(const Shape& s) {
    const size_t nd = shape.size();
    for (const Field& field : s.fields) {
      const int f = count_++;
      base_[f] = field.template data_as<T>();
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

template <class T> py::array_t<T> new_array(const BatchShape& batch, Index trailing) {
  BatchShape shape = batch;
  if (trailing > 0) shape.push_back(trailing);
  return py::array_t<T>(shape);
}

// A single result: a Python float in float and double, a NumPy long double otherwise.
template <class Real> py::object scalar(Real value) {
  if constexpr (std::is_same_v<Real, long double>) {
    auto out = new_array<long double>({}, 0);
    *out.mutable_data() = value;
    return out[py::tuple()];
  } else {
    return py::float_(double(value));
  }
}

// The values a query of precision Real reads: float64 for float and double (a float query
// reads float32 inputs exactly from their float64 copies), long double for long double.
template <class Real> using Storage = std::conditional_t<std::is_same_v<Real, long double>, long double, double>;

// Evaluation of one ordered pair of C++ primitive types (of scalar Real) with one root policy.
template <class Roots, class A, class B, class Real> struct PairOf {
  using T = Storage<Real>;
  using Broadcast = circledist::python::Broadcast<T>;
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

  // float queries read float64 copies of the inputs rounded to float: they must fit.
  static void check_range(const Shape& a, const Shape& b, const Shape* limit = nullptr) {
    if constexpr (std::is_same_v<Real, float>) {
      check_float_range(a);
      check_float_range(b);
      if (limit) check_float_range("within", limit->fields[0]);
    }
  }

  // float32 answers are solved in double and rounded: a distance, point or parameter beyond
  // float32's range would come back as inf, a number that is not the answer. That is an
  // OverflowError naming the entry point, the output and its index, as inputs beyond the range
  // are a ValueError (pybind11 maps std::overflow_error to OverflowError).
  static void check_output_range(const char* entry, const char* output, const Real* v, Index count, int width,
                                 const BatchShape& shape) {
    if constexpr (std::is_same_v<Real, float>) {
      for (Index i = 0; i < count * width; ++i) {
        if (!std::isfinite(v[i]))
          throw std::overflow_error(std::string(entry) + ": " + output + index_text(i / width, shape) +
                                    " is beyond float32's range (precision='float32'); ask for "
                                    "precision='float64'");
      }
    }
  }

  static bool unswept(const Shape& s) {
    const Field& sweep = s.fields.back();
    return sweep.batch.empty() && *sweep.data() == 0;
  }

  static py::object distance(const Shape& a, const Shape& b) {
    check_range(a, b);
    if (a.batch.empty() && b.batch.empty()) {
      std::array<const T*, kMaxFields> f{};
      int k = 0;
      for (const Field& x : a.fields) f[k++] = x.template data_as<T>();
      for (const Field& x : b.fields) f[k++] = x.template data_as<T>();
      ++stats().distances;
      const Layout at(a, b);
      const Real d = circledist::distance<Roots>(at.first(f.data()), at.second(f.data()));
      check_output_range("distance", "the distance", &d, 1, 1, {});
      return scalar<Real>(d);
    }
    const Broadcast bc(a, b);
    const Layout at(a, b);
    auto out = new_array<Real>(bc.shape, 0);
    Real* o = out.mutable_data();
    {
      py::gil_scoped_release release;
      if (unswept(a) && unswept(b)) {
        bc.for_each([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
          o[i] = circledist::distance<Roots>(at.first_core(f), at.second_core(f));
        });
      } else {
        bc.for_each([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
          o[i] = circledist::distance<Roots>(at.first(f), at.second(f));
        });
      }
    }
    stats().distances += std::uint64_t(bc.size);
    check_output_range("distance", "the distance", o, bc.size, 1, bc.shape);
    return std::move(out);
  }

  // effects.hpp over the broadcast of a, b and the limits d: within() (a bool per element) or,
  // with `want_distance`, distance_if_within() (the distance, +inf beyond d).
  static py::object within(const Shape& a, const Shape& b, const Shape& limit, bool want_distance) {
    check_range(a, b, &limit);
    const Broadcast bc(a, b, &limit);
    const Layout at(a, b);
    if (want_distance) {
      auto out = new_array<Real>(bc.shape, 0);
      Real* o = out.mutable_data();
      {
        py::gil_scoped_release release;
        bc.for_each([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
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
      bc.for_each([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
        o[i] = circledist::within<Roots>(at.first(f), at.second(f), Real(*f[at.limit_at]));
      });
    }
    if (bc.shape.empty()) return py::bool_(o[0]);
    return std::move(out);
  }

  static ClosestPoints closest(const Shape& a, const Shape& b) {
    check_range(a, b);
    const Broadcast bc(a, b);
    const Layout at(a, b);
    auto dist = new_array<Real>(bc.shape, 0);
    auto pa = new_array<Real>(bc.shape, 3), pb = new_array<Real>(bc.shape, 3);
    auto ta = new_array<Real>(bc.shape, 2), tb = new_array<Real>(bc.shape, 2);
    auto unique = new_array<bool>(bc.shape, 0);
    Real *d = dist.mutable_data(), *xa = pa.mutable_data(), *xb = pb.mutable_data();
    Real *ua = ta.mutable_data(), *ub = tb.mutable_data();
    bool* u = unique.mutable_data();
    {
      py::gil_scoped_release release;
      bc.for_each([&](Index i, const T* const* f) CIRCLEDIST_PER_ELEMENT {
        const Result<Real> r = circledist::closest_points<Roots>(at.first(f), at.second(f));
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
      });
    }
    stats().closest_points += std::uint64_t(bc.size);
    check_output_range("closest_points", "distance", d, bc.size, 1, bc.shape);
    check_output_range("closest_points", "point_a", xa, bc.size, 3, bc.shape);
    check_output_range("closest_points", "point_b", xb, bc.size, 3, bc.shape);
    check_output_range("closest_points", "param_a", ua, bc.size, 2, bc.shape);
    check_output_range("closest_points", "param_b", ub, bc.size, 2, bc.shape);
    if (bc.shape.empty())
      return {scalar<Real>(d[0]), std::move(pa), std::move(pb), std::move(ta), std::move(tb), py::bool_(u[0])};
    return {std::move(dist), std::move(pa), std::move(pb), std::move(ta), std::move(tb), std::move(unique)};
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

struct PairTables {
  PairTable table[kPrecisionCount][kSolverCount];
  int default_solver = solver_index<DefaultRoots>();  // solver=None: the C++ default
};

// Registers both argument orders of a pair with one policy.
template <class Roots, class Real> struct PairRegistrar {
  PairTable& table;
  template <class A, class B> void add() {
    constexpr int ka = ShapeTraits<A>::kind, kb = ShapeTraits<B>::kind;
    table.distance[ka][kb] = &PairOf<Roots, A, B, Real>::distance;
    table.closest[ka][kb] = &PairOf<Roots, A, B, Real>::closest;
    table.distance[kb][ka] = &PairOf<Roots, B, A, Real>::distance;
    table.closest[kb][ka] = &PairOf<Roots, B, A, Real>::closest;
    table.within[ka][kb] = &PairOf<Roots, A, B, Real>::within;
    table.within[kb][ka] = &PairOf<Roots, B, A, Real>::within;
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

// Counted<>: every polynomial solve is counted in circledist::stats() (effects.hpp).
template <class Real> void register_precision(PairTable (&tables)[kSolverCount]) {
  for_each_pair<Real>(PairRegistrar<Counted<EigenCompanion>, Real>{tables[kCompanion]});
  for_each_pair<Real>(PairRegistrar<Counted<EigenPolished>, Real>{tables[kPolished]});
  for_each_pair<Real>(PairRegistrar<Counted<Bracketing>, Real>{tables[kBracketing]});
  for_each_pair<Real>(PairRegistrar<Counted<EigenPolynomialSolver>, Real>{tables[kEigen]});
}

// Defined in pairs_float.cpp, pairs_double.cpp and pairs_longdouble.cpp (compiled in parallel).
void register_float(PairTables& t);
void register_double(PairTables& t);
void register_long_double(PairTables& t);

}  // namespace circledist::python
