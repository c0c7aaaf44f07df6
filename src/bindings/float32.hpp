// precision="float32": the double query on the inputs rounded to float32, its answers rounded to
// float32. That is what circledist::distance() does for float shapes in C++ (query.hpp,
// promoted()), so float32 runs the double tables' entries and needs no instantiation of its own.
#pragma once

#include "calls.hpp"

#include <stdexcept>
#include <string>

namespace circledist::python {

// The field with every value rounded to float32 (kept when it was given as float32). A value
// outside float32's range is a ValueError naming the owner, the field and the index.
inline Field rounded_to_float(const char* owner, const Field& f) {
  check_float_range(owner, f);
  if (f.single) return f;
  Field out = f;
  out.array = decltype(f.array)(std::vector<Index>(f.array.shape(), f.array.shape() + f.array.ndim()));
  const double* from = f.data();
  double* to = out.array.mutable_data();
  for (Index i = 0, n = f.array.size(); i < n; ++i) to[i] = double(float(from[i]));
  out.is_wide = out.is_widened = false;
  out.single = true;
  return out;
}

inline Shape rounded_to_float(const Shape& s) {
  Shape out = s;
  for (Field& f : out.fields) f = rounded_to_float(kind_name(s.kind), f);
  return out;
}

// A double answer rounded to float32. With `check`, a value beyond float32's range is an
// OverflowError naming the entry point, the output and its index, as inputs beyond it are a
// ValueError (distance_if_within's inf means "beyond the limit" and is not checked).
// `width`: values per batch element (3 for points, 2 for parameters).
inline py::object to_float32(const py::object& value, const char* entry, const char* output, Index width,
                             bool check = true) {
  auto overflow = [&](Index flat, const BatchShape& batch) {
    return std::overflow_error(std::string(entry) + ": " + output + index_text(flat, batch) +
                               " is beyond float32's range (precision='float32'); ask for precision='float64'");
  };
  if (py::isinstance<py::float_>(value)) {
    const float x = float(value.cast<double>());
    if (check && !std::isfinite(x)) throw overflow(0, {});
    return py::float_(double(x));
  }
  if (!py::isinstance<py::array_t<double>>(value)) return value;  // within()'s booleans
  const auto from = py::array_t<double, py::array::c_style>::ensure(value);
  const BatchShape shape(from.shape(), from.shape() + from.ndim());
  const BatchShape batch(shape.begin(), shape.end() - (width > 1 ? 1 : 0));
  py::array_t<float> out(shape);
  const double* x = from.data();
  float* y = out.mutable_data();
  for (Index i = 0, n = from.size(); i < n; ++i) {
    y[i] = float(x[i]);
    if (check && !std::isfinite(y[i])) throw overflow(i / width, batch);
  }
  return std::move(out);
}

inline ClosestPoints to_float32(const ClosestPoints& r) {
  return {
      to_float32(r.distance, "closest_points", "distance", 1), to_float32(r.point_a, "closest_points", "point_a", 3),
      to_float32(r.point_b, "closest_points", "point_b", 3),   to_float32(r.param_a, "closest_points", "param_a", 2),
      to_float32(r.param_b, "closest_points", "param_b", 2),   r.unique};
}

}  // namespace circledist::python
