// Python-side shapes: validated, contiguous float64 fields with leading batch dimensions, and
// the per-kind traits that turn one batch element into a C++ primitive. No geometry here.
#pragma once

#include "batch.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace circledist::python {

namespace py = pybind11;
// A field: `width` values per batch element (3 for vectors, 1 for scalars), as float64, and as
// long double too when it was given as np.longdouble (which float64 would round: a long-double
// query then reads those values; the other precisions read the float64 ones).
struct Field {
  using Wide = py::array_t<long double, py::array::c_style | py::array::forcecast>;
  const char* name;
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  BatchShape batch;
  Index width;
  bool single = false;  // given as float32: computing in float reproduces the input exactly
  bool is_wide = false;  // given as np.longdouble (wider than float64): `wide` holds the values
  Wide wide;
  mutable bool is_widened = false;  // `widened`: the float64 values as long double, made on a
  mutable Wide widened;             // long-double query's first use (the GIL held)
  const double* data() const { return array.data(); }
  bool has_wide() const { return is_wide; }

  // The values in the storage type T of a query's precision (double, or long double).
  template <class T> const T* data_as() const {
    if constexpr (std::is_same_v<T, long double>) {
      if (is_wide) return wide.data();
      if (!is_widened) {
        widened = Wide::ensure(py::reinterpret_borrow<py::object>(array.attr("astype")("longdouble")));
        is_widened = true;
      }
      return widened.data();
    } else {
      return array.data();
    }
  }
  // The array a user reads back: the long double one when that is what was given.
  py::object value() const { return is_wide ? py::object(wide) : py::object(array); }
};

enum class Check { Finite, NonzeroVector, NonNegative };

// The width of a field of Bezier control points, (..., k + 1, 3): known once the array is seen.
constexpr Index kControlPoints = -1;

// True when no value is NaN or inf (all exponent bits set), in one branch-free pass that
// vectorizes: adding one to an all-ones exponent carries into the sign bit.
inline bool all_finite(const double* p, Index n) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000ull, exponent_one = 0x0010000000000000ull;
  std::uint64_t carry = 0;
  for (Index i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, p + i, sizeof bits);
    carry |= (bits & exponent) + exponent_one;
  }
  return (carry >> 63) == 0;
}

// Real numbers only: NumPy would turn complex values (dropping the imaginary part), datetime64
// values and numeric strings into float64 without a word. Object arrays are accepted when every
// element is a real number (numbers.Real: Fractions, mpmath numbers); None is not.
inline bool is_real_array(const py::object& given) {
  const std::string kind = py::str(given.attr("dtype").attr("kind"));
  if (kind == "f" || kind == "i" || kind == "u") return true;
  if (kind != "O") return false;
  const py::object real = py::module_::import("numbers").attr("Real");
  for (py::handle x : given.attr("flat"))
    if (!py::isinstance(x, real)) return false;
  return true;
}

// A shape is a value: its fields are private read-only copies, so neither the caller's array nor
// the shape's own attributes can change a validated shape afterwards. With copy=False (as
// scipy.spatial.cKDTree's copy_data=False) a field given as a C-contiguous array of the
// field's dtype is referred to, not copied: a read-only view of the caller's array, which the
// caller promises not to change (a batch then costs no memory beyond its inputs).
inline py::object frozen_copy(const py::module_& numpy, const py::object& given, const char* dtype, bool copy = true) {
  py::object out = copy ? numpy.attr("array")(given, py::arg("dtype") = dtype, py::arg("order") = "C",
                                              py::arg("copy") = true)
                        : numpy.attr("asarray")(given, py::arg("dtype") = dtype, py::arg("order") = "C").attr("view")();  // asarray: keeps 0-d (ascontiguousarray makes it 1-d)
  out.attr("setflags")(py::arg("write") = false);
  return out;
}

inline Field make_field(const char* owner, const char* name, py::handle value, Index width, Check check,
                        bool copy = true) {
  Field f{name, {}, {}, width};
  py::object converted;
  bool real = false;
  try {
    const py::module_ numpy = py::module_::import("numpy");
    const py::object given = numpy.attr("asarray")(value);
    real = is_real_array(given);
    if (real) {
      f.single = py::object(given.attr("dtype")).equal(numpy.attr("dtype")("float32"));
      // np.longdouble is kept as it is where it is wider than float64 (x86's 80-bit format).
      if (py::object(given.attr("dtype")).equal(numpy.attr("dtype")("longdouble")) &&
          std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits)
        f.wide = Field::Wide::ensure(frozen_copy(numpy, given, "longdouble", copy)), f.is_wide = true;
      converted = frozen_copy(numpy, given, "float64", copy);
    }
  } catch (py::error_already_set&) {
    real = false;
  }
  if (!real) throw py::value_error(std::string(owner) + ": " + name + " must be a real number array");
  f.array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(converted);
  if (!f.array) {
    PyErr_Clear();
    throw py::value_error(std::string(owner) + ": " + name + " must be a real number array");
  }
  const Index ndim = f.array.ndim();
  if (width == kControlPoints) {
    const Index count = ndim >= 2 ? f.array.shape(ndim - 2) : 0;
    if (ndim < 2 || f.array.shape(ndim - 1) != 3 || count < 2 || count > kMaxBezierDegree + 1) {
      BatchShape got(f.array.shape(), f.array.shape() + ndim);
      throw py::value_error(std::string(owner) + ": " + name + " must have shape (k + 1, 3) or (..., k + 1, 3) with " +
                            "degree k from 1 to " + std::to_string(kMaxBezierDegree) + ", got " + shape_text(got));
    }
    f.width = width = 3 * count;
    f.batch.assign(f.array.shape(), f.array.shape() + ndim - 2);
  } else if (width == 3) {
    if (ndim < 1 || f.array.shape(ndim - 1) != 3) {
      BatchShape got(f.array.shape(), f.array.shape() + ndim);
      throw py::value_error(std::string(owner) + ": " + name + " must have shape (3,) or (..., 3), got " +
                            shape_text(got));
    }
    f.batch.assign(f.array.shape(), f.array.shape() + ndim - 1);
  } else {
    f.batch.assign(f.array.shape(), f.array.shape() + ndim);
  }
  const double* p = f.array.data();
  const Index count = f.array.size() / width;
  // Finite values only need the per-element pass below to name the first bad one.
  const bool finite = all_finite(p, f.array.size());
  if (finite && check == Check::Finite) return f;
  for (Index i = 0; i < count; ++i) {
    const double* e = p + i * width;
    for (Index k = 0; k < width && !finite; ++k) {
      if (!std::isfinite(e[k]))
        throw py::value_error(std::string(owner) + ": " + name + index_text(i, f.batch) + " contains NaN or inf");
    }
    // Any nonzero component (a squared length would underflow for |v| = 1e-200).
    if (check == Check::NonzeroVector && e[0] == 0 && e[1] == 0 && e[2] == 0)
      throw py::value_error(std::string(owner) + ": " + name + index_text(i, f.batch) + " has zero length");
    if (check == Check::NonNegative && e[0] < 0)
      throw py::value_error(std::string(owner) + ": " + name + index_text(i, f.batch) + " is negative");
  }
  return f;
}

// precision="float32" rounds every input to float32: a value beyond float32's range (which would
// become inf) or a nonzero one below its smallest subnormal (which would become 0, turning a
// direction of 1e-50 into a zero vector) is an error naming the argument and its index.
inline void check_float_range(const char* owner, const Field& f) {
  if (f.single) return;  // given as float32
  const double* p = f.data();
  const Index n = f.array.size();
  const double high = double(std::numeric_limits<float>::max());
  const double low = double(std::numeric_limits<float>::denorm_min()) / 2;
  for (Index i = 0; i < n; ++i) {
    const double a = std::abs(p[i]);
    if (a > high || (a > 0 && a <= low))
      throw py::value_error(std::string(owner) + ": " + f.name + index_text(i / f.width, f.batch) +
                            " is outside float32's range (precision='float32'): " + std::to_string(p[i]));
  }
}

// A batch of one kind of shape. Fields broadcast against each other (a scalar radius with
// (N, 3) centers is N circles).
struct Shape {
  int kind = kPoint;
  std::vector<Field> fields;
  BatchShape batch;
  int points = 0;  // control points per Bezier curve

  bool single() const {
    for (const Field& f : fields)
      if (!f.single) return false;
    return true;
  }
  bool wide() const {
    for (const Field& f : fields)
      if (f.has_wide()) return true;
    return false;
  }

  Shape(int k, std::vector<Field> f) : kind(k), fields(std::move(f)) {
    if (kind == kBezier) points = int(fields[0].width / 3);
    for (const Field& field : fields) {
      bool ok = true;
      const BatchShape joined = broadcast_shapes(batch, field.batch, ok);
      if (!ok)
        throw py::value_error(std::string(kind_name(kind)) + ": " + field.name + " of batch shape " +
                              shape_text(field.batch) + " does not broadcast with batch shape " + shape_text(batch) +
                              " of the other fields");
      batch = joined;
    }
  }
};

inline void check_float_range(const Shape& s) {
  for (const Field& f : s.fields) check_float_range(kind_name(s.kind), f);
}

}  // namespace circledist::python

namespace circledist::python {

// The constructor arguments of each kind, in the order ShapeTraits reads them.
struct FieldSpec {
  const char* name;
  Index width;
  Check check;
};

inline constexpr FieldSpec kPointFields[] = {{"p", 3, Check::Finite}};
inline constexpr FieldSpec kLinearFields[] = {{"origin", 3, Check::Finite}, {"direction", 3, Check::NonzeroVector}};
inline constexpr FieldSpec kSegmentFields[] = {{"p0", 3, Check::Finite}, {"p1", 3, Check::Finite}};
inline constexpr FieldSpec kRoundFields[] = {
    {"center", 3, Check::Finite}, {"normal", 3, Check::NonzeroVector}, {"radius", 1, Check::NonNegative}};

inline constexpr FieldSpec kBezierFields[] = {{"control_points", kControlPoints, Check::Finite}};

// Every kind takes an optional `sweep` radius (>= 0, default 0) after its own fields: the field
// is always present, last, so that a shape is swept (sweep.hpp) without per-kind code.
inline constexpr FieldSpec kSweepField = {"sweep", 1, Check::NonNegative};

// The default sweep, 0: exact in every precision, so it never decides the precision.
inline Field default_sweep() {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  static const Array* zero = [] {  // never freed: no Python object is released after finalization
    auto* a = new Array(BatchShape{});
    *a->mutable_data() = 0;
    a->attr("setflags")(py::arg("write") = false);
    return a;
  }();
  Field f{kSweepField.name, *zero, {}, 1};
  f.single = true;
  return f;
}

// Whether a field is the default sweep (the shape was built without one).
inline bool is_default_sweep(const Field& f) { return f.array.ptr() == default_sweep().array.ptr(); }

inline Field sweep_field(const char* owner, py::handle value, bool copy = true) {
  if (value.is_none()) return default_sweep();
  return make_field(owner, kSweepField.name, value, kSweepField.width, kSweepField.check, copy);
}

inline constexpr const FieldSpec* kFieldSpecs[kKindCount] = {kPointFields,   kLinearFields, kLinearFields, kSegmentFields,
                                                             kRoundFields,   kRoundFields,  kBezierFields};

}  // namespace circledist::python
