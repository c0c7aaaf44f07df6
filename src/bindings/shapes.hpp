// Python-side shapes: validated, contiguous float64 fields with leading batch dimensions, and
// the per-kind traits that turn one batch element into a C++ primitive. No geometry here.
#pragma once

#include "../kernels/batch.hpp"

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

// An array handle holding no object: what a Field's arrays start as. (pybind11's default array_t
// is a new empty NumPy array: three per field were a fifth of a single shape's construction.)
template <class A> A no_array() { return py::reinterpret_steal<A>(py::handle()); }

// A field: `width` values per batch element (3 for vectors, 1 for scalars), as float64, and as
// long double too when it was given as np.longdouble (which float64 would round: a long-double
// query then reads those values; the other precisions read the float64 ones).
struct Field {
  using Wide = py::array_t<long double, py::array::c_style | py::array::forcecast>;
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const char* name;
  Array array = no_array<Array>();
  BatchShape batch;
  Index width = 0;
  bool single = false;   // given as float32: computing in float reproduces the input exactly
  bool is_wide = false;  // given as np.longdouble (wider than float64): `wide` holds the values
  Wide wide = no_array<Wide>();
  mutable bool is_widened = false;          // `widened`: the float64 values as long double, made
  mutable Wide widened = no_array<Wide>();  // on a long-double query's first use (the GIL held)
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
  // The values in the dtype they were given in (to_arrays): a float32 field as a read-only
  // float32 copy of the stored float64 values, which reproduce it exactly.
  py::object given() const {
    py::object out = value();
    if (single && !is_wide) {
      out = out.attr("astype")("float32");
      out.attr("setflags")(py::arg("write") = false);
    }
    return out;
  }
};

// Angle: an arc's angle, in (0, 2 pi] (float32's rounding of 2 pi, just above, is 2 pi given as float32).
enum class Check { Finite, NonzeroVector, NonNegative, Angle };

inline constexpr double kTwoPi = 2 * pi_v<double>();
// The largest angle a field takes: 2 pi, or its float32 rounding for a field given as float32.
inline double largest_angle(bool single) { return single ? double(float(kTwoPi)) : kTwoPi; }

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

// NumPy's functions and the keyword sets that make_field calls them with, made once: looking them
// up and building the keywords per field was most of a shape constructor's time.
struct NumpyCalls {
  py::object asarray, array;
  py::dict copy_double, copy_wide, view_double, view_wide;
};
inline const NumpyCalls& numpy_calls() {
  static const NumpyCalls* const calls = [] {  // never freed: it must outlive the interpreter's exit
    auto* c = new NumpyCalls;
    const py::module_ numpy = py::module_::import("numpy");
    c->asarray = numpy.attr("asarray");
    c->array = numpy.attr("array");
    for (const bool copy : {true, false})
      for (const char* dtype : {"float64", "longdouble"}) {
        py::dict& kwargs = copy ? (dtype[0] == 'f' ? c->copy_double : c->copy_wide)
                                : (dtype[0] == 'f' ? c->view_double : c->view_wide);
        kwargs["dtype"] = numpy.attr("dtype")(dtype);  // an object: a string is parsed on every call
        kwargs["order"] = py::str("C");
        if (copy) kwargs["copy"] = py::bool_(true);
      }
    return c;
  }();
  return *calls;
}

// fn(arg, **kwargs) with a ready-made keyword dict (pybind11's call syntax would build one).
inline py::object call_with(const py::object& fn, py::handle arg, const py::dict& kwargs) {
  const py::tuple args = py::make_tuple(py::reinterpret_borrow<py::object>(arg));
  PyObject* out = PyObject_Call(fn.ptr(), args.ptr(), kwargs.ptr());
  if (!out) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(out);
}

// Real numbers only: NumPy would turn complex values (dropping the imaginary part), datetime64
// values and numeric strings into float64 without a word. Object arrays are accepted when every
// element is a real number (numbers.Real: Fractions, mpmath numbers); None is not.
inline bool is_real_array(const py::array& given) {
  const char kind = given.dtype().kind();
  if (kind == 'f' || kind == 'i' || kind == 'u') return true;
  if (kind != 'O') return false;
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
inline py::object frozen_copy(const py::object& given, bool wide, bool copy = true) {
  const NumpyCalls& np = numpy_calls();
  py::object out = copy ? call_with(np.array, given, wide ? np.copy_wide : np.copy_double)
                        // asarray keeps 0-d (ascontiguousarray would make it 1-d)
                        : call_with(np.asarray, given, wide ? np.view_wide : np.view_double).attr("view")();
  py::detail::array_proxy(out.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return out;
}

// The MemoryError of a field whose copy (a contiguous float64 array) could not be made, naming
// the field, its shape and the bytes the copy needs (NumPy's own message names neither).
[[noreturn]] inline void throw_cannot_copy(const char* owner, const char* name, py::handle value) {
  std::ostringstream text;
  text << owner << ": " << name << " cannot be copied: out of memory";
  const py::object shape = py::getattr(value, "shape", py::none());
  if (py::isinstance<py::tuple>(shape)) {
    double bytes = double(sizeof(double));
    for (py::handle d : shape) bytes *= py::cast<double>(d);
    text.precision(3);
    text
        << " (shape " << py::str(shape).cast<std::string>() << ", " << bytes
        << " bytes as a contiguous float64 array; copy=False refers to a C-contiguous float64 array without copying it)";
  }
  PyErr_SetString(PyExc_MemoryError, text.str().c_str());
  throw py::error_already_set();
}

inline Field make_field(const char* owner, const char* name, py::handle value, Index width, Check check,
                        bool copy = true) {
  Field f{name};
  f.width = width;
  py::object converted;
  bool real = false;
  try {
    PyObject* as_array = PyObject_CallOneArg(numpy_calls().asarray.ptr(), value.ptr());
    if (!as_array) throw py::error_already_set();
    const py::array given = py::reinterpret_steal<py::array>(as_array);
    real = is_real_array(given);
    if (real) {
      const int type = given.dtype().num();
      f.single = type == py::detail::npy_api::NPY_FLOAT_;
      // np.longdouble is kept as it is where it is wider than float64 (x86's 80-bit format).
      if (type == py::detail::npy_api::NPY_LONGDOUBLE_ &&
          std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits)
        f.wide = Field::Wide::ensure(frozen_copy(given, true, copy)), f.is_wide = true;
      converted = frozen_copy(given, false, copy);
    }
  } catch (py::error_already_set& error) {
    // A valid array too large to copy is not a wrong type: say so, and how large.
    if (error.matches(PyExc_MemoryError)) throw_cannot_copy(owner, name, value);
    real = false;
  }
  if (!real) throw py::value_error(std::string(owner) + ": " + name + " must be a real number array");
  f.array = py::array_t < double, py::array::c_style | py::array::forcecast > ::ensure(converted);
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
    if (check == Check::Angle && !(e[0] > 0 && e[0] <= largest_angle(f.single))) {
      std::ostringstream got;
      got.precision(17);
      got << e[0];
      throw py::value_error(std::string(owner) + ": " + name + index_text(i, f.batch) + " must be in (0, 2 pi], got " +
                            got.str());
    }
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

// Where each field of a shape keeps the element of a flat index of the shape's batch: fields
// broadcast within a shape (a scalar radius for a batch of centers), so a field's element is the
// flat index itself (full-size fields), 0 (one value), or a walk over the batch's dimensions.
struct FieldElements {
  enum class Mode { Full, One, Strided };
  struct Map {
    Mode mode;
    std::vector<Index> strides;  // elements per step along each batch dimension (Strided)
  };
  BatchShape batch;
  std::vector<Map> maps;

  explicit FieldElements(const Shape& s) : batch(s.batch) {
    for (const Field& f : s.fields) {
      Map m{Mode::Strided, std::vector<Index>(batch.size(), 0)};
      if (f.batch.empty()) {
        m.mode = Mode::One;
      } else if (f.batch == batch) {
        m.mode = Mode::Full;
      } else {
        Index step = 1;
        for (size_t k = 0; k < f.batch.size(); ++k) {
          const size_t d = batch.size() - 1 - k;
          const Index extent = f.batch[f.batch.size() - 1 - k];
          m.strides[d] = extent == 1 ? 0 : step;
          step *= extent;
        }
      }
      maps.push_back(std::move(m));
    }
  }

  Index of(size_t field, Index flat) const {
    const Map& m = maps[field];
    if (m.mode == Mode::Full) return flat;
    if (m.mode == Mode::One) return 0;
    Index at = 0;
    for (size_t d = batch.size(); d-- > 0;) {
      at += (flat % batch[d]) * m.strides[d];
      flat /= batch[d];
    }
    return at;
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
  int not_along = -1;  // a vector field that must not be parallel to this field of the shape (check_across_fields)
  int at_most = -1;    // a number field that must not exceed this field of the shape (check_across_fields)
};

inline constexpr FieldSpec kPointFields[] = {{"p", 3, Check::Finite}};
inline constexpr FieldSpec kLinearFields[] = {{"origin", 3, Check::Finite}, {"direction", 3, Check::NonzeroVector}};
inline constexpr FieldSpec kSegmentFields[] = {{"p0", 3, Check::Finite}, {"p1", 3, Check::Finite}};
inline constexpr FieldSpec kRoundFields[] = {
    {"center", 3, Check::Finite}, {"normal", 3, Check::NonzeroVector}, {"radius", 1, Check::NonNegative}};

inline constexpr FieldSpec kBezierFields[] = {{"control_points", kControlPoints, Check::Finite}};
// An arc (primitives.hpp Arc3): its circle's fields, the start (whose projection onto the plane
// starts the arc, so not along the normal) and the angle in (0, 2 pi].
inline constexpr FieldSpec kArcFields[] = {{"center", 3, Check::Finite},
                                           {"normal", 3, Check::NonzeroVector},
                                           {"radius", 1, Check::NonNegative},
                                           {"start", 3, Check::NonzeroVector, 1},
                                           {"angle", 1, Check::Angle}};
// An annulus (primitives.hpp Annulus3): a disk's center and normal, then the inner radius, at most
// the outer one (inner 0 is the disk, inner = outer the circle; inner > outer, the empty set in
// C++, is refused here as a mistake).
inline constexpr FieldSpec kAnnulusFields[] = {{"center", 3, Check::Finite},
                                               {"normal", 3, Check::NonzeroVector},
                                               {"inner_radius", 1, Check::NonNegative, -1, 3},
                                               {"outer_radius", 1, Check::NonNegative}};

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

inline constexpr const FieldSpec* kFieldSpecs[kKindCount] = {kPointFields,   kLinearFields, kLinearFields,
                                                             kSegmentFields, kRoundFields,  kRoundFields,
                                                             kBezierFields,  kArcFields,    kAnnulusFields};

}  // namespace circledist::python

namespace circledist::python {

// The checks of a field against another of its shape (FieldSpec::not_along, FieldSpec::at_most),
// per element of the shape's broadcast batch, each an error naming both fields and the element:
//  - not_along: parallel within rounding (|a x b| <= 16 eps |a| |b|, each scaled by its largest
//    component first, so no square overflows or underflows);
//  - at_most: the field's value above the other's (compared as given: in long double for a field
//    given as np.longdouble).
inline long double field_value(const Field& f, Index at) { return f.is_wide ? f.wide.data()[at] : f.data()[at]; }
inline void check_across_fields(const Shape& s, const FieldSpec* spec) {
  for (size_t k = 0; k < kFieldCounts[s.kind]; ++k) {
    if (spec[k].not_along < 0 && spec[k].at_most < 0) continue;
    const size_t other = size_t(spec[k].not_along >= 0 ? spec[k].not_along : spec[k].at_most);
    const FieldElements e(s);
    Index count = 1;
    for (const Index d : s.batch) count *= d;
    const auto fail = [&](Index i, const std::string& relation, const std::string& why) {
      throw py::value_error(std::string(kind_name(s.kind)) + ": " + spec[k].name + index_text(i, s.batch) + relation +
                            spec[other].name + index_text(i, s.batch) + why);
    };
    for (Index i = 0; i < count; ++i) {
      if (spec[k].at_most >= 0) {
        const long double value = field_value(s.fields[k], e.of(k, i));
        const long double limit = field_value(s.fields[other], e.of(other, i));
        if (value > limit) {
          std::ostringstream got;
          got.precision(17);
          got << " (" << double(value) << " > " << double(limit) << ")";
          fail(i, " exceeds ", got.str());
        }
        continue;
      }
      const double* pa = s.fields[k].data() + 3 * e.of(k, i);
      const double* pb = s.fields[other].data() + 3 * e.of(other, i);
      Vec3<double> a(pa[0], pa[1], pa[2]), b(pb[0], pb[1], pb[2]);
      a /= a.cwiseAbs().maxCoeff();
      b /= b.cwiseAbs().maxCoeff();
      const double bound = 16 * std::numeric_limits<double>::epsilon();
      if (!(a.cross(b).squaredNorm() > bound * bound * a.squaredNorm() * b.squaredNorm()))
        fail(i, " is parallel to ", " (its projection onto the plane starts the arc)");
    }
  }
}

}  // namespace circledist::python
