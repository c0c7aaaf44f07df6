// The module's side of a pair query: a Request (pairs.hpp) made from the Python shapes, the
// answers' arrays, the GIL released around the kernel, and the Python result.
#pragma once

#include "pairs.hpp"
#include "parallel.hpp"
#include "shapes.hpp"

#include <chrono>
#include <string>
#include <type_traits>
#include <utility>

namespace circledist::python {

struct ClosestPoints {
  py::object distance, point_a, point_b, param_a, param_b, unique;
};

template <class T> py::array_t<T> new_array(const BatchShape& batch, Index trailing) {
  BatchShape shape = batch;
  if (trailing > 0) shape.push_back(trailing);
  return py::array_t<T>(shape);
}

// A single result: a Python float in double, a NumPy long double in long double.
template <class Real> py::object scalar(Real value) {
  if constexpr (std::is_same_v<Real, long double>) {
    auto out = new_array<long double>({}, 0);
    *out.mutable_data() = value;
    return out[py::tuple()];
  } else {
    return py::float_(double(value));
  }
}

// The shape's fields in the storage type of the query (with the GIL held: a long-double query's
// first use of a float64 field makes its long-double copy, Field::data_as).
template <class Real> Operand<Real> operand(const Shape& s) {
  Operand<Real> out{s.kind, s.points, &s.batch};
  for (const Field& f : s.fields) out.fields[size_t(out.count++)] = {f.name, f.template data_as<Real>(), f.width, &f.batch};
  return out;
}

inline bool swept(const Shape& s) {
  const Field& sweep = s.fields.back();
  return !(sweep.batch.empty() && *sweep.data() == 0);
}

// Runs work(begin, end) over [0, size) in chunks on `workers` threads, the GIL released; Ctrl-C (a
// signal Python has seen, checked every 50 ms between the caller's chunks) stops it and raises
// KeyboardInterrupt. Every batched call and the all-pairs queries (bind_pairs.hpp) run this way.
template <class Work> void run_released(Index size, int workers, Work&& work) {
  bool complete;
  {
    py::gil_scoped_release release;
    auto checked = std::chrono::steady_clock::now();
    complete = run_in_chunks(size, workers, work, [&] {
      const auto now = std::chrono::steady_clock::now();
      if (now - checked < std::chrono::milliseconds(50)) return false;
      checked = now;
      py::gil_scoped_acquire gil;
      return PyErr_CheckSignals() != 0;
    });
  }
  if (!complete) throw py::error_already_set();
}

// One query of the table's entry for the caller's (a, b): the kernel's operands in its own order
// (swapped where the entry is `reversed`), `limit` the distances of within() if any.
template <class Real> struct Call {
  const PairTable<Real>& table;
  const Shape& a;
  const Shape& b;
  const Shape* limit = nullptr;
  int workers = 1;  // threads for a batch (run_in_chunks)

  bool reversed() const { return table.reversed[a.kind][b.kind]; }
  Request<Real> request() const {
    const Shape& first = reversed() ? b : a;
    const Shape& second = reversed() ? a : b;
    const Operand<Real> limit_operand = limit ? operand<Real>(*limit) : Operand<Real>{};
    return Request<Real>(operand<Real>(first), operand<Real>(second), limit ? &limit_operand : nullptr, reversed(),
                         swept(a) || swept(b));
  }
  KernelFn<Real> entry(KernelFn<Real> const (PairTable<Real>::*column)[kKindCount][kKindCount]) const {
    const KernelFn<Real> fn = (table.*column)[a.kind][b.kind];
    if (!fn)
      throw py::type_error(std::string("circledist has no query between a ") + kind_name(a.kind) + " and a " +
                           kind_name(b.kind));
    return fn;
  }
  // The batch in chunks on `workers` threads, the GIL released (run_released).
  void run(KernelFn<Real> fn, const Request<Real>& r) const {
    run_released(r.elements.size, workers, [&](Index begin, Index end) { fn(r, begin, end); });
  }

  // distance(), or distance_if_within() with a limit. A single query (every batch shape empty)
  // answers in a local, with the GIL held: no array, no thread switch (most of a scalar call's cost).
  py::object distance() const {
    const KernelFn<Real> fn = entry(limit ? &PairTable<Real>::distance_if_within : &PairTable<Real>::distance);
    Request<Real> r = request();
    if (r.elements.shape.empty()) {
      Real value;
      r.distance = &value;
      fn(r, 0, 1);
      return scalar<Real>(value);
    }
    auto out = new_array<Real>(r.elements.shape, 0);
    r.distance = out.mutable_data();
    run(fn, r);
    return std::move(out);
  }

  py::object within() const {
    const KernelFn<Real> fn = entry(&PairTable<Real>::within);
    Request<Real> r = request();
    if (r.elements.shape.empty()) {
      bool value;
      r.flag = &value;
      fn(r, 0, 1);
      return py::bool_(value);
    }
    auto out = new_array<bool>(r.elements.shape, 0);
    r.flag = out.mutable_data();
    run(fn, r);
    return std::move(out);
  }

  // A single query's distance and flag are a Python float (a NumPy long double) and bool.
  ClosestPoints closest() const {
    const KernelFn<Real> fn = entry(&PairTable<Real>::closest);
    Request<Real> r = request();
    const BatchShape& shape = r.elements.shape;
    auto distance = new_array<Real>(shape, 0), point_a = new_array<Real>(shape, 3), point_b = new_array<Real>(shape, 3);
    auto param_a = new_array<Real>(shape, 2), param_b = new_array<Real>(shape, 2);
    auto unique = new_array<bool>(shape, 0);
    r.distance = distance.mutable_data();
    r.flag = unique.mutable_data();
    r.point_a = point_a.mutable_data();
    r.point_b = point_b.mutable_data();
    r.param_a = param_a.mutable_data();
    r.param_b = param_b.mutable_data();
    if (reversed()) {
      std::swap(r.point_a, r.point_b);
      std::swap(r.param_a, r.param_b);
    }
    run(fn, r);
    if (shape.empty())
      return {scalar<Real>(r.distance[0]), std::move(point_a), std::move(point_b), std::move(param_a),
              std::move(param_b), py::bool_(r.flag[0])};
    return {std::move(distance), std::move(point_a), std::move(point_b), std::move(param_a), std::move(param_b),
            std::move(unique)};
  }
};

}  // namespace circledist::python
