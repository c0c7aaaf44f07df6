// The module's side of a pair query: a Request (kernels/pairs.hpp) made from the Python shapes, the
// answers' arrays, the GIL released around the kernel, and the Python result.
#pragma once

#include "../kernels/pairs.hpp"
#include "../kernels/parallel.hpp"
#include "shapes.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <new>
#include <string>
#include <thread>
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
  for (const Field& f : s.fields)
    out.fields[size_t(out.count++)] = {f.name, f.template data_as<Real>(), f.width, &f.batch};
  return out;
}

inline bool swept(const Shape& s) {
  const Field& sweep = s.fields.back();
  return !(sweep.batch.empty() && *sweep.data() == 0);
}

// progress(done, total) with the GIL held, unless progress is None; false (the Python error set)
// when it raised.
inline bool report_progress(py::handle progress, Index done, Index total) {
  if (progress.is_none()) return true;
  try {
    progress(done, total);
  } catch (py::error_already_set& e) {
    e.restore();
    return false;
  }
  return true;
}

// Runs work(begin, end) over [0, size) in chunks on `workers` threads, the GIL released. Every
// batched call and the all-pairs queries (all_pairs.cpp) run this way. Every 50 ms between the
// caller's chunks, Ctrl-C (a signal Python has seen) stops it and raises KeyboardInterrupt, and
// every 100 ms progress(done, total) is called (unless None); an exception it raises stops the
// work likewise; it is called once more with (size, size) at the end. `fixed_chunk`: see
// run_in_chunks.
template <class Work>
void run_released(Index size, int workers, Work&& work, py::handle progress = py::none(), Index fixed_chunk = 0) {
  bool complete;
  {
    py::gil_scoped_release release;
    auto checked = std::chrono::steady_clock::now(), reported = checked;
    complete = run_in_chunks(
        size, workers, work,
        [&](Index done) {
          const auto now = std::chrono::steady_clock::now();
          if (now - checked < std::chrono::milliseconds(50)) return false;
          checked = now;
          py::gil_scoped_acquire gil;
          if (PyErr_CheckSignals() != 0) return true;
          if (progress.is_none() || now - reported < std::chrono::milliseconds(100) || done >= size) return false;
          reported = now;
          return !report_progress(progress, done, size);
        },
        fixed_chunk);
  }
  if (!complete || !report_progress(progress, size, size)) throw py::error_already_set();
}

// Ctrl-C for work that runs with the GIL released and is not cut in run_released's chunks (a
// tree's build, broadphase.hpp's Interrupted): called now and then from any of the work's
// threads, it answers whether a signal stopped the work. On the caller's thread (the one Python
// delivers signals to), every 50 ms as run_released does, it takes the GIL and asks
// PyErr_CheckSignals, which leaves KeyboardInterrupt set for the caller to raise; other threads
// read the answer.
class SignalCheck {
 public:
  bool operator()() {
    if (std::this_thread::get_id() != caller_) return raised_.load(std::memory_order_relaxed);
    const auto now = std::chrono::steady_clock::now();
    if (raised_.load(std::memory_order_relaxed) || now - checked_ < std::chrono::milliseconds(50)) return raised_;
    checked_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) raised_.store(true, std::memory_order_relaxed);
    return raised_;
  }
  // Throws py::error_already_set (the GIL held) when a signal was seen: the error it left.
  void raise_if_seen() const {
    if (raised_) throw py::error_already_set();
  }

 private:
  std::thread::id caller_ = std::this_thread::get_id();
  std::chrono::steady_clock::time_point checked_ = std::chrono::steady_clock::now();
  std::atomic<bool> raised_{false};
};

// One query of the table's entry for the caller's (a, b): the kernel's operands in its own order
// (swapped where the entry is `reversed`), `limit` the distances of within() if any.
template <class Real> struct Call {
  const PairTable<Real>& table;
  const Shape& a;
  const Shape& b;
  const Shape* limit = nullptr;
  int workers = 1;                   // threads for a batch (run_in_chunks)
  py::handle progress = py::none();  // None, or a callable progress(done, total) (arguments.hpp resolves True)

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
  // progress(done, total), with the GIL held; false (the Python error set) when it raised.
  bool report(Index done, Index total) const { return report_progress(progress, done, total); }
  // The batch in chunks on `workers` threads, the GIL released (run_released), with progress.
  void run(KernelFn<Real> fn, const Request<Real>& r) const {
    run_released(r.elements.size, workers, [&](Index begin, Index end) { fn(r, begin, end); }, progress);
  }

  // One answer per element into the Request's `slot` (distance or flag): a single query (every
  // batch shape empty) answers in a local, with the GIL held: no array, no thread switch (most of
  // a scalar call's cost), and `single` makes it a Python object.
  template <class T, class Single>
  py::object answers(KernelFn<Real> fn, T* Request<Real>::* slot, Single&& single) const {
    Request<Real> r = request();
    if (r.elements.shape.empty()) {
      T value;
      r.*slot = &value;
      fn(r, 0, 1);
      if (!report(1, 1)) throw py::error_already_set();
      return single(value);
    }
    auto out = new_array<T>(r.elements.shape, 0);
    r.*slot = out.mutable_data();
    run(fn, r);
    return std::move(out);
  }

  // distance(), or distance_if_within() with a limit.
  py::object distance() const {
    return answers(entry(limit ? &PairTable<Real>::distance_if_within : &PairTable<Real>::distance),
                   &Request<Real>::distance, [](Real value) { return scalar<Real>(value); });
  }

  py::object within() const {
    return answers(entry(&PairTable<Real>::within), &Request<Real>::flag,
                   [](bool value) { return py::object(py::bool_(value)); });
  }

  // A single query's distance and flag are a Python float (a NumPy long double) and bool.
  ClosestPoints closest() const {
    const KernelFn<Real> fn = entry(&PairTable<Real>::closest);
    Request<Real> r = request();
    const BatchShape& shape = r.elements.shape;
    // The six answers are views of one allocation: six separate arrays of a large batch were each
    // mapped afresh by malloc and faulted in page by page, which cost more than the queries of
    // the point kinds (measured 29.6 against 2.6 ns per element for 10^5 elements); one block
    // is reused, or (4 MB and more) NumPy maps it with huge pages. Any one of them keeps the
    // block alive (documented in ClosestPoints' help: copy what you keep of large batches).
    const Index size = r.elements.size;
    constexpr Index values = 1 + 3 + 3 + 2 + 2;  // distance, both points, both params
    constexpr Index bytes_per_element = values * Index(sizeof(Real)) + Index(sizeof(bool));
    // Checked before the product (the views are each checked by NumPy on their own, smaller, size).
    if (size > std::numeric_limits<Index>::max() / bytes_per_element)
      throw std::bad_alloc();  // MemoryError, as a NumPy array of that size raises
    py::array_t<std::uint8_t> block(size * bytes_per_element);
    std::uint8_t* next = block.mutable_data();
    auto view = [&](auto* type, Index trailing) {
      using T = std::remove_pointer_t<decltype(type)>;
      BatchShape view_shape = shape;
      if (trailing > 0) view_shape.push_back(trailing);
      py::array_t<T> out(view_shape, reinterpret_cast<T*>(next), block);
      next += size * std::max<Index>(trailing, 1) * Index(sizeof(T));
      return out;
    };
    auto distance = view((Real*)nullptr, 0), point_a = view((Real*)nullptr, 3), point_b = view((Real*)nullptr, 3);
    auto param_a = view((Real*)nullptr, 2), param_b = view((Real*)nullptr, 2);
    auto unique = view((bool*)nullptr, 0);
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
      return {scalar<Real>(r.distance[0]), std::move(point_a), std::move(point_b),
              std::move(param_a),          std::move(param_b), py::bool_(r.flag[0])};
    return {std::move(distance), std::move(point_a), std::move(point_b),
            std::move(param_a),  std::move(param_b), std::move(unique)};
  }
};

}  // namespace circledist::python
