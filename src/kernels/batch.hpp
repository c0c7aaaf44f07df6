// The pybind11-free side of a batched query: shape kinds, batch shapes and their broadcasting,
// and the C++ primitive of one batch element. The pair units (pair_unit.cpp) include this and
// pairs.hpp only, not pybind11: a unit then compiles its queries and nothing else (pybind11's
// headers cost each unit about 7 s of a 2-core build).
#pragma once

#include <circledist/circledist.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace circledist::python {

using Index = std::ptrdiff_t;
using BatchShape = std::vector<Index>;

enum Kind : int { kPoint, kLine, kRay, kSegment, kCircle, kDisk, kBezier, kArc, kAnnulus, kKindCount };

inline const char* kind_name(int kind) {
  static const char* names[] = {"Point", "Line", "Ray", "Segment", "Circle", "Disk", "Bezier", "Arc", "Annulus"};
  return names[kind];
}

inline std::string shape_text(const BatchShape& shape) {
  std::ostringstream s;
  s << '(';
  for (size_t i = 0; i < shape.size(); ++i)
    s << shape[i] << (shape.size() == 1 ? "," : (i + 1 < shape.size() ? ", " : ""));
  s << ')';
  return s.str();
}

// "[i]" or "[i, j]" for a flat index into a batch, "" for an unbatched field.
inline std::string index_text(Index flat, const BatchShape& batch) {
  if (batch.empty()) return "";
  std::vector<Index> idx(batch.size());
  for (size_t d = batch.size(); d-- > 0;) {
    idx[d] = flat % batch[d];
    flat /= batch[d];
  }
  std::ostringstream s;
  s << '[';
  for (size_t d = 0; d < idx.size(); ++d) s << (d ? ", " : "") << idx[d];
  s << ']';
  return s.str();
}

inline constexpr size_t kFieldCounts[kKindCount] = {1, 2, 2, 2, 3, 3, 1, 5, 4};

// NumPy broadcasting of two batch shapes; `ok` is false when they do not broadcast.
inline BatchShape broadcast_shapes(const BatchShape& a, const BatchShape& b, bool& ok) {
  ok = true;
  const size_t n = std::max(a.size(), b.size());
  BatchShape out(n, 1);
  for (size_t i = 0; i < n; ++i) {
    const Index da = i < a.size() ? a[a.size() - 1 - i] : 1;
    const Index db = i < b.size() ? b[b.size() - 1 - i] : 1;
    if (da != db && da != 1 && db != 1) ok = false;
    out[n - 1 - i] = da == 1 ? db : da;
  }
  return out;
}

// One C++ primitive per kind, built from pointers to one batch element of each field.
template <class S> struct ShapeTraits;

template <class Real, class T> Vec3<Real> vec(const T* p) { return Vec3<Real>(Real(p[0]), Real(p[1]), Real(p[2])); }

template <class Real> struct ShapeTraits<Vec3<Real>> {
  static constexpr int kind = kPoint;
  template <class T> static Vec3<Real> make(const T* const* f, int) { return vec<Real>(f[0]); }
};
template <class Real> struct ShapeTraits<Line3<Real>> {
  static constexpr int kind = kLine;
  template <class T> static Line3<Real> make(const T* const* f, int) { return {vec<Real>(f[0]), vec<Real>(f[1])}; }
};
template <class Real> struct ShapeTraits<Ray3<Real>> {
  static constexpr int kind = kRay;
  template <class T> static Ray3<Real> make(const T* const* f, int) { return {vec<Real>(f[0]), vec<Real>(f[1])}; }
};
template <class Real> struct ShapeTraits<Segment3<Real>> {
  static constexpr int kind = kSegment;
  template <class T> static Segment3<Real> make(const T* const* f, int) { return {vec<Real>(f[0]), vec<Real>(f[1])}; }
};
template <class Real> struct ShapeTraits<Circle3<Real>> {
  static constexpr int kind = kCircle;
  template <class T> static Circle3<Real> make(const T* const* f, int) {
    return {vec<Real>(f[0]), vec<Real>(f[1]), Real(*f[2])};
  }
};
template <class Real> struct ShapeTraits<Disk3<Real>> {
  static constexpr int kind = kDisk;
  template <class T> static Disk3<Real> make(const T* const* f, int) {
    return {vec<Real>(f[0]), vec<Real>(f[1]), Real(*f[2])};
  }
};
template <class Real> struct ShapeTraits<BezierCurve3<Real>> {
  static constexpr int kind = kBezier;
  template <class T> static BezierCurve3<Real> make(const T* const* f, int points) {
    BezierCurve3<Real> curve;
    curve.control.resize(3, points);
    for (int i = 0; i < points; ++i) curve.control.col(i) = vec<Real>(f[0] + 3 * i);
    return curve;
  }
};

// An arc: center, normal, radius, start, angle (bindings/shapes.hpp checks 0 < angle <= 2 pi). An angle of
// float64's 2 pi is the whole circle in every precision: it lies 2.4e-16 below long double's 2 pi,
// which would leave a long-double query a gap in the circle (arc.hpp takes angle >= 2 pi whole).
// The fields are assigned, not given to Arc3's constructor: the constructor's trigonometry of the
// angle (Arc3::trig) would be formed for every element, and costs more than the point query
// saves with it; an arc without it takes the general path (point_arc.hpp), which forms only what
// it needs.
template <class Real> struct ShapeTraits<Arc3<Real>> {
  static constexpr int kind = kArc;
  template <class T> static Arc3<Real> make(const T* const* f, int) {
    const Real angle = Real(*f[4]);
    const Real whole = 2 * pi_v<Real>();
    Arc3<Real> a;
    a.center = vec<Real>(f[0]);
    a.normal = vec<Real>(f[1]);
    a.radius = Real(*f[2]);
    a.start = vec<Real>(f[3]);
    a.angle = angle >= Real(2 * pi_v<double>()) && angle < whole ? whole : angle;
    return a;
  }
};

// An annulus: center, normal, inner radius, outer radius (bindings/shapes.hpp checks 0 <= inner <= outer).
template <class Real> struct ShapeTraits<Annulus3<Real>> {
  static constexpr int kind = kAnnulus;
  template <class T> static Annulus3<Real> make(const T* const* f, int) {
    return {vec<Real>(f[0]), vec<Real>(f[1]), Real(*f[2]), Real(*f[3])};
  }
};

// The C++ primitive of each kind, in Kind's order: the one list a new kind adds its type to, so
// that code over every kind (the broadphase's volumes, bindings/all_pairs.cpp) has no per-kind branch.
template <class Real> using KindTypes = std::tuple<Vec3<Real>, Line3<Real>, Ray3<Real>, Segment3<Real>, Circle3<Real>,
                                                   Disk3<Real>, BezierCurve3<Real>, Arc3<Real>, Annulus3<Real>>;
static_assert(std::tuple_size_v<KindTypes<double>> == kKindCount, "a kind without a primitive in KindTypes");

template <class T> struct TypeTag {
  using type = T;
};

// fn(TypeTag<S>{}) for the primitive S (of scalar Real) of `kind`.
template <class Real, class Fn, size_t... K> void visit_kind(int kind, Fn&& fn, std::index_sequence<K...>) {
  static_assert(((ShapeTraits<std::tuple_element_t<K, KindTypes<Real>>>::kind == int(K)) && ...),
                "KindTypes and ShapeTraits disagree on a kind");
  (void)((kind == int(K) ? (fn(TypeTag<std::tuple_element_t<K, KindTypes<Real>>>{}), true) : false) || ...);
}
template <class Real, class Fn> void visit_kind(int kind, Fn&& fn) {
  visit_kind<Real>(kind, std::forward<Fn>(fn), std::make_index_sequence<kKindCount>());
}

// A shape batch as a query reads it: per field, its values in the storage type T of the query's
// precision (double, or long double), its width (values per element) and its batch shape. The
// module makes it from a Shape (bindings/shapes.hpp) with the GIL held; it borrows the Shape's storage.
constexpr int kMaxShapeFields = 6;  // an arc's center, normal, radius, start, angle, and the sweep
template <class T> struct FieldRef {
  const char* name;
  const T* data;
  Index width;
  const BatchShape* batch;
};
template <class T> struct Operand {
  int kind;
  int points;  // control points per Bezier curve
  const BatchShape* batch;
  int count = 0;
  std::array<FieldRef<T>, kMaxShapeFields> fields{};
};

constexpr int kMaxFields = 2 * kMaxShapeFields + 1;  // two shapes, and within()'s limit

// Offsets (in values of the storage type T: double, or long double for long-double queries) of
// every field of both shapes for each element of the broadcast batch. Fields that are full-size
// in the result's layout or constant step linearly (the fast path); others (e.g. (N, 1) against
// (M,)) walk an odometer.
template <class T> class Broadcast {
 public:
  BatchShape shape;
  Index size = 1;

  // `limit` (optional): a third batch, the distances of within(), broadcast with both shapes.
  // `reversed`: the caller gave b first (the pair tables' order, pairs.hpp), which the message keeps.
  Broadcast(const Operand<T>& a, const Operand<T>& b, const Operand<T>* limit = nullptr, bool reversed = false) {
    if (a.batch->empty() && b.batch->empty() && (!limit || limit->batch->empty())) {  // a single query
      for (const Operand<T>* s : {&a, &b, limit})
        for (int k = 0; s && k < s->count; ++k, ++count_) {
          base_[count_] = s->fields[size_t(k)].data;  // step 0: the one element
          width_[count_] = s->fields[size_t(k)].width;
        }
      return;
    }
    bool ok = true;
    shape = broadcast_shapes(*a.batch, *b.batch, ok);
    if (!ok) {
      const Operand<T>& first = reversed ? b : a;
      const Operand<T>& second = reversed ? a : b;
      throw std::invalid_argument(std::string("batch shapes ") + shape_text(*first.batch) + " of the " +
                                  kind_name(first.kind) + " and " + shape_text(*second.batch) + " of the " +
                                  kind_name(second.kind) + " do not broadcast");
    }
    if (limit) {
      const BatchShape joined = broadcast_shapes(shape, *limit->batch, ok);
      if (!ok)
        throw std::invalid_argument(std::string(limit->fields[0].name) + " of batch shape " +
                                    shape_text(*limit->batch) + " does not broadcast with the shapes' batch shape " +
                                    shape_text(shape));
      shape = joined;
    }
    for (Index d : shape) size *= d;
    add(a);
    add(b);
    if (limit) add(*limit);
  }

  // Calls fn(flat_index, field_pointers) for every element of [begin, end) (a chunk of the batch:
  // threads run disjoint chunks, bindings/calls.hpp). `Count`: the pair's field count (a constant of
  // the pair, PairKernels::kFields), so that the pointers stay in registers and advance by a fixed
  // step (most of the loop's own cost on the point queries), in one copy of the loop.
  template <int Count, class Fn> void for_each(Fn&& fn, Index begin, Index end) const {
    walk<Count>(
        [&](const T* const* base, const Index* step, Index start, Index n) { run<Count>(fn, base, step, start, n); },
        begin, end);
  }

  // As for_each, but block(first_index, field_pointers, field_steps) answers each Width
  // consecutive elements of a run at once (the elements first_index ... first_index + Width - 1,
  // field f of element k at pointers[f] + k * steps[f]), and fn the few left at a run's end.
  template <int Count, int Width, class Block, class Fn>
  void for_each_block(const Block& block, Fn&& fn, Index begin, Index end) const {
    walk<Count>(
        [&](const T* const* base, const Index* step, Index start, Index n) {
          std::array<const T*, Count> ptr{};
          for (int f = 0; f < Count; ++f) ptr[f] = base[f];
          Index i = 0;
          for (; i + Width <= n; i += Width) {
            block(start + i, ptr.data(), step);
            for (int f = 0; f < Count; ++f) ptr[f] += Width * step[f];
          }
          run<Count>(fn, ptr.data(), step, start + i, n - i);
        },
        begin, end);
  }

 private:
  // runner(field_pointers, field_steps, first_index, count) over runs covering [begin, end): one
  // run where every field steps linearly, else chunks gathered into contiguous scratch.
  template <int Count, class Runner> void walk(const Runner& runner, Index begin, Index end) const {
    static_assert(Count <= kMaxFields, "kMaxFields");
    if (count_ != Count) throw std::logic_error("circledist: a pair's field count disagrees with its shapes");
    if (linear_) {
      std::array<const T*, kMaxFields> base{};
      for (int f = 0; f < count_; ++f) base[f] = base_[f] + begin * step_[f];
      return runner(base.data(), step_.data(), begin, end - begin);
    }
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
    for (size_t d = nd, rest = size_t(begin); d-- > 0;) {  // the odometer at `begin`
      idx[d] = Index(rest % size_t(shape[d]));
      rest /= size_t(shape[d]);
      for (int f = 0; f < count_; ++f) offset[f] += idx[d] * stride_[size_t(f) * nd + d];
    }
    for (Index start = begin; start < end; start += kChunk) {
      const Index n = std::min(kChunk, end - start);
      for (Index j = 0; j < n; ++j) {
        for (int f = 0; f < count_; ++f)
          std::copy_n(base_[f] + offset[f], width_[f], scratch[f].data() + j * width_[f]);
        for (size_t d = nd; d-- > 0;) {
          ++idx[d];
          for (int f = 0; f < count_; ++f) offset[f] += stride_[size_t(f) * nd + d];
          if (idx[d] < shape[d]) break;
          for (int f = 0; f < count_; ++f) offset[f] -= stride_[size_t(f) * nd + d] * shape[d];
          idx[d] = 0;
        }
      }
      runner(base.data(), step.data(), start, n);
    }
  }

  // fn(start + i, pointers) for i in [0, n), each field's pointer advancing by its step.
  template <int N, class Fn> void run(Fn& fn, const T* const* base, const Index* step, Index start, Index n) const {
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
  std::vector<Index> stride_;  // field f's step along batch dimension d at [f * nd + d] (none for a single query)

  void add(const Operand<T>& s) {
    const size_t nd = shape.size();
    for (int k = 0; k < s.count; ++k) {
      const FieldRef<T>& field = s.fields[size_t(k)];
      const int f = count_++;
      base_[f] = field.data;
      width_[f] = field.width;
      stride_.resize(size_t(count_) * nd, 0);
      Index* st = stride_.data() + size_t(f) * nd;
      Index step = field.width;
      bool full = field.batch->size() == nd;
      for (size_t k = 0; k < field.batch->size(); ++k) {
        const size_t d = nd - 1 - k;
        const Index extent = (*field.batch)[field.batch->size() - 1 - k];
        if (extent != shape[d]) full = false;
        st[d] = extent == 1 ? 0 : step;
        step *= extent;
      }
      if (field.batch->empty() || step == field.width) {
        step_[f] = 0;  // one element repeated
      } else if (full) {
        step_[f] = field.width;
      } else {
        linear_ = false;
      }
    }
  }
};

}  // namespace circledist::python
