// The compiled part of circledist: shape classes, and distance / closest_points over every
// registered pair of kinds. Thin by design: the math lives in cpp/include/circledist.
#include "float32.hpp"
#include "calls.hpp"
#include "help.hpp"

namespace py = pybind11;
using namespace circledist;
using namespace circledist::python;

namespace {

template <int K> struct ShapeOf : Shape {
  using Shape::Shape;
};

const PairTables& pairs() {
  static const PairTables tables = [] {
    PairTables t;
#define CIRCLEDIST_REGISTER_PAIR_UNIT(REAL, ROOTS) register_pairs<REAL, ROOTS>(t);
    CIRCLEDIST_PAIR_UNITS(CIRCLEDIST_REGISTER_PAIR_UNIT)
#undef CIRCLEDIST_REGISTER_PAIR_UNIT
    return t;
  }();
  return tables;
}

// precision=None follows NumPy's promotion of the inputs: long double when any field was given as
// np.longdouble, float when every one was float32, double otherwise.
int precision_of(const py::object& name, const Shape& a, const Shape& b) {
  if (name.is_none()) return a.wide() || b.wide() ? kLongDouble : a.single() && b.single() ? kFloat : kDouble;
  const std::string s = py::str(name);
  if (s == "float32" || s == "float") return kFloat;
  if (s == "float64" || s == "double") return kDouble;
  if (s == "longdouble" || s == "long double" || s == "float128") return kLongDouble;
  throw py::value_error("precision must be None, 'float32', 'float64' or 'longdouble', got '" + s + "'");
}

int solver_of(const py::object& name) {
  if (name.is_none()) return pairs().default_solver;
  const std::string s = py::str(name);
  if (s == "companion") return kCompanion;
  if (s == "polished") return kPolished;
  if (s == "bracketing") return kBracketing;
  if (s == "eigen") return kEigen;
  if (s == "default") return pairs().default_solver;
  throw py::value_error("solver must be None, 'default', 'companion', 'polished', 'bracketing' or 'eigen', got '" + s +
                        "'");
}

// An argument as the messages show it: its repr, or for an integer of many digits how many.
std::string shown(py::handle value) {
  const std::string text = py::repr(value).cast<std::string>();
  if (text.size() <= 40 || !PyLong_Check(value.ptr())) return text;
  return "an integer of " + std::to_string(text.size() - (text[0] == '-' ? 1 : 0)) + " digits";
}

// The one reader of the integer arguments (k, workers, a count of any entry point): an int, a
// NumPy integer or another numbers.Integral, through __index__. bool is refused: True is not a
// count (NumPy refuses it as an array's size, and `k=True` is a slip, not a 1). A value beyond
// 64 bits is refused with the library's words (pybind11 would say "Unable to cast"). `wanted`
// says what the argument takes; `owner` (may be empty) the call, as the messages start.
long long integer_of(const std::string& owner, const char* name, py::handle value, const char* wanted) {
  const std::string prefix = owner.empty() ? std::string(name) : owner + ": " + name;
  PyObject* index = nullptr;
  if (PyLong_CheckExact(value.ptr())) {  // the common case, without the ABC check's cost
    index = value.ptr();
    Py_INCREF(index);
  } else if (!PyBool_Check(value.ptr()) && !py::isinstance(value, py::module_::import("numpy").attr("bool_")) &&
             py::isinstance(value, py::module_::import("numbers").attr("Integral"))) {
    index = PyNumber_Index(value.ptr());
    if (!index) PyErr_Clear();
  }
  if (!index) throw py::type_error(prefix + " must be " + wanted + ", got " + shown(value));
  const py::object held = py::reinterpret_steal<py::object>(index);
  int overflow = 0;
  const long long out = PyLong_AsLongLongAndOverflow(index, &overflow);
  if (overflow != 0)
    throw py::value_error(prefix + " must be " + wanted + (overflow > 0 ? " (at most 2**63 - 1)" : " (at least -2**63)") +
                          ", got " + shown(value));
  if (out == -1 && PyErr_Occurred()) throw py::error_already_set();
  return out;
}

// A distance limit: a finite real number >= 0 (bool and strings refused), named in messages. An
// integer beyond float64's range is refused as not finite (float() of it would raise).
double limit_of(const char* owner, py::handle d) {
  const py::module_ numbers = py::module_::import("numbers");
  if (PyBool_Check(d.ptr()) || py::isinstance(d, py::module_::import("numpy").attr("bool_")) ||
      !py::isinstance(d, numbers.attr("Real")))
    throw py::type_error(std::string(owner) + ": d must be a real number >= 0, got " + shown(d));
  const double value = PyFloat_AsDouble(d.ptr());
  if (value == -1 && PyErr_Occurred()) {
    if (!PyErr_ExceptionMatches(PyExc_OverflowError)) throw py::error_already_set();
    PyErr_Clear();
  } else if (value >= 0 && std::isfinite(value)) {
    return value;
  }
  throw py::value_error(std::string(owner) + ": d must be a finite number >= 0, got " + shown(d));
}

// nearest's k: an integer >= 1 (integer_of's rules).
Index count_of(const char* owner, py::handle k) {
  constexpr const char* wanted = "an integer >= 1";
  const long long value = integer_of(owner, "k", k, wanted);
  if (value < 1) throw py::value_error(std::string(owner) + ": k must be " + wanted + ", got " + std::to_string(value));
  return Index(value);
}

// workers=: SciPy's convention, a positive thread count or -1 for every core. Counts beyond an
// int are the int's largest: the threads are bounded by the work's chunks anyway.
int workers_of(py::handle given, const std::string& owner = "") {
  constexpr const char* wanted = "a positive integer or -1 (every core)";
  const long long workers = integer_of(owner, "workers", given, wanted);
  if (workers == -1) return int(std::max(1u, std::thread::hardware_concurrency()));
  if (workers < 1)
    throw py::value_error((owner.empty() ? std::string() : owner + ": ") + "workers must be " + wanted + ", got " +
                          std::to_string(workers));
  return int(std::min<long long>(workers, std::numeric_limits<int>::max()));
}

// The Shape base class's Python type, looked up once. Queries test their arguments against it with
// PyType_IsSubtype: py::isinstance goes through the metaclass's __instancecheck__ (a bound method
// made and dropped per call), which cost as much as a whole line-circle query.
PyTypeObject* shape_type() {
  static PyTypeObject* const type = reinterpret_cast<PyTypeObject*>(py::type::of<Shape>().ptr());
  return type;
}

bool is_shape(py::handle value) { return PyType_IsSubtype(Py_TYPE(value.ptr()), shape_type()) != 0; }

// Every shape class holds one C++ object, a ShapeOf<K>: a Shape with nothing added, so the two
// share their address (standard layout) and the first value slot of the instance is the Shape.
static_assert(std::is_standard_layout_v<ShapeOf<kCircle>>, "a ShapeOf<K> must be pointer-interconvertible with its Shape");

// The Shape of a Python object, checked to be a shape built by its constructor: one made by
// Circle.__new__(Circle) alone has unconstructed storage, which must never be read.
const Shape& constructed(py::handle value) {
  if (!is_shape(value))
    throw py::type_error(std::string("expected a circledist shape, got ") + Py_TYPE(value.ptr())->tp_name);
  const auto storage = reinterpret_cast<py::detail::instance*>(value.ptr())->get_value_and_holder();
  if (!storage.holder_constructed())
    throw py::type_error(std::string(Py_TYPE(value.ptr())->tp_name) +
                         " was not initialized: build shapes with their constructor, e.g. Circle(center, normal, radius)");
  return *reinterpret_cast<const Shape*>(storage.value_ptr());
}

// progress=: None or False for none; True for a progress bar (circledist._progress: tqdm when it
// is installed, else a line on stderr), shown once the work has taken a second; or a callable.
py::object progress_of(const py::object& given) {
  if (given.is_none() || given.ptr() == Py_False) return py::none();
  if (given.ptr() == Py_True) return py::module_::import("circledist._progress").attr("ProgressBar")();
  if (!PyCallable_Check(given.ptr()))
    throw py::type_error(std::string("progress must be None, True or a callable progress(done, total), got ") +
                         Py_TYPE(given.ptr())->tp_name);
  return given;
}

// A shape argument: a Shape object, or an array-like of points (made a Point).
struct Argument {
  py::object keep;
  const Shape* shape;
  explicit Argument(py::handle value) {
    if (is_shape(value)) {
      keep = py::reinterpret_borrow<py::object>(value);
    } else {
      keep = py::module_::import("circledist._core").attr("Point")(value);
    }
    shape = &constructed(keep);
  }
};

// A query's precision and solver, resolved from the call's arguments.
// While it lives, the calling thread's SelectedEigenPolicy runs the chosen eigenvalue policy.
struct Choice {
  int precision, solver, workers;
  py::object progress;
  SelectedEigenPolicy::Use eigen_policy;
  Choice(const py::object& precision_name, const py::object& solver_name, const Shape& a, const Shape& b,
         py::handle workers_given, const py::object& progress_given)
      : precision(precision_of(precision_name, a, b)),
        solver(solver_of(solver_name)),
        workers(workers_of(workers_given)),
        progress(progress_of(progress_given)),
        eigen_policy(selected_eigen_policy(solver)) {}
  bool single() const { return precision == kFloat; }
};

// Runs `query` (a Call<Real> -> result) on the table of the choice: float32 runs the double one
// (float32.hpp).
// `progress` is the choice's own unless a caller reports elsewhere (the all-pairs queries' stages).
template <class Query>
auto with_call(const Shape& a, const Shape& b, const Shape* limit, const Choice& c, Query&& query,
               py::handle progress) {
  if (c.precision == kLongDouble)
    return query(Call<long double>{pairs().of<long double>(c.solver), a, b, limit, c.workers, progress});
  return query(Call<double>{pairs().of<double>(c.solver), a, b, limit, c.workers, progress});
}
template <class Query> auto with_call(const Shape& a, const Shape& b, const Shape* limit, const Choice& c, Query&& query) {
  return with_call(a, b, limit, c, std::forward<Query>(query), c.progress);
}

// distance() of two shapes already read (also the all-pairs queries' kernel, bind_pairs.hpp,
// which reports its progress elsewhere).
py::object shapes_distance(const Shape& a, const Shape& b, const Choice& c, py::handle progress) {
  auto distance = [](const auto& call) { return call.distance(); };
  if (!c.single()) return with_call(a, b, nullptr, c, distance, progress);
  const Shape fa = rounded_to_float(a), fb = rounded_to_float(b);
  return to_float32(with_call(fa, fb, nullptr, c, distance, progress), "distance", "the distance", 1);
}
py::object shapes_distance(const Shape& a, const Shape& b, const Choice& c) { return shapes_distance(a, b, c, c.progress); }

py::object run_distance(py::handle a, py::handle b, const py::object& precision, const py::object& solver,
                        py::handle workers, const py::object& progress) {
  const Argument x(a), y(b);
  return shapes_distance(*x.shape, *y.shape, Choice(precision, solver, *x.shape, *y.shape, workers, progress));
}

ClosestPoints run_closest(py::handle a, py::handle b, const py::object& precision, const py::object& solver,
                          py::handle workers, const py::object& progress) {
  const Argument x(a), y(b);
  const Choice c(precision, solver, *x.shape, *y.shape, workers, progress);
  auto closest = [](const auto& call) { return call.closest(); };
  if (!c.single()) return with_call(*x.shape, *y.shape, nullptr, c, closest);
  const Shape fa = rounded_to_float(*x.shape), fb = rounded_to_float(*y.shape);
  return to_float32(with_call(fa, fb, nullptr, c, closest));
}

// within() (a bool per element) or, with `want_distance`, distance_if_within() (the distance,
// inf beyond the limit d), over the broadcast of two shapes already read and `limit` (also the
// scene's all-pairs kernel, bind_pairs.hpp, which reports its progress elsewhere).
py::object shapes_within(const Shape& a, const Shape& b, const Shape& limit, bool want_distance, const Choice& c,
                         py::handle progress) {
  auto within = [want_distance](const auto& call) { return want_distance ? call.distance() : call.within(); };
  if (!c.single()) return with_call(a, b, &limit, c, within, progress);
  const Shape fa = rounded_to_float(a), fb = rounded_to_float(b);
  const Shape fd(limit.kind, {rounded_to_float("within", limit.fields[0])});
  return to_float32(with_call(fa, fb, &fd, c, within, progress), "distance_if_within", "the distance", 1, false);
}

py::object run_within(py::handle a, py::handle b, const Shape& limit, bool want_distance, const py::object& precision,
                      const py::object& solver, py::handle workers, const py::object& progress) {
  const Argument x(a), y(b);
  const Choice c(precision, solver, *x.shape, *y.shape, workers, progress);
  return shapes_within(*x.shape, *y.shape, limit, want_distance, c, c.progress);
}

py::typing::Tuple<py::int_, py::ellipsis> batch_tuple(py::handle self) {
  const Shape& s = constructed(self);
  py::typing::Tuple<py::int_, py::ellipsis> out(s.batch.size());
  for (size_t i = 0; i < s.batch.size(); ++i) out[i] = py::int_(s.batch[i]);
  return out;
}

template <int K, size_t... I> void bind_shape(py::module_& m, const std::string& doc, std::index_sequence<I...>) {
  static const FieldSpec* spec = kFieldSpecs[K];
  py::class_<ShapeOf<K>, Shape> cls(m, kind_name(K), doc.c_str());
  cls.def(py::init([](decltype((void)I, ArrayLike())... values, OptionalArrayLike sweep, bool copy) {
            ShapeOf<K> shape(K, {make_field(kind_name(K), spec[I].name, values, spec[I].width, spec[I].check, copy)...,
                                 sweep_field(kind_name(K), sweep, copy)});
            check_across_fields(shape, spec);
            return shape;
          }),
          py::arg(spec[I].name)..., py::kw_only(), py::arg(kSweepField.name) = py::none(), py::arg("copy") = true);
  (cls.def_property_readonly(
       spec[I].name, [](py::handle s) { return Array(constructed(s).fields[I].value()); }, doc::field(spec[I].name)),
   ...);
}

template <int K> void bind_shape(py::module_& m, const std::string& doc) {
  bind_shape<K>(m, doc, std::make_index_sequence<kFieldCounts[K]>());
}

// Every kind's class, from the kinds' tables (shapes.hpp's fields, help.hpp's docstrings).
template <size_t... K> void bind_shapes(py::module_& m, std::index_sequence<K...>) {
  (bind_shape<int(K)>(m, doc::shape_class(int(K))), ...);
}

// The constructor's arguments as arrays, by name: float32 fields as float32 (the values they were
// read from, exactly), np.longdouble ones as long double, the others float64; read-only. The
// sweep is left out when none was given (the default, whose dtype would otherwise decide the
// precision of a rebuilt shape).
py::dict to_arrays(py::handle self) {
  const Shape& s = constructed(self);
  py::dict out;
  for (size_t i = 0; i < s.fields.size(); ++i) {
    const Field& f = s.fields[i];
    if (i + 1 == s.fields.size() && is_default_sweep(f)) break;
    py::object value = f.value();
    if (f.single && !f.is_wide) {
      value = value.attr("astype")("float32");
      value.attr("setflags")(py::arg("write") = false);
    }
    out[f.name] = value;
  }
  return out;
}

// cls(**arrays, copy=copy) for a shape class, with the names checked first (a missing or unknown
// one is a TypeError naming it and the expected ones).
py::object from_arrays(const py::type& cls, const py::dict& arrays, bool copy) {
  const std::string name = py::str(cls.attr("__name__"));
  int kind = -1;
  for (int k = 0; k < kKindCount; ++k)
    if (name == kind_name(k)) kind = k;
  if (kind < 0 || PyObject_IsSubclass(cls.ptr(), py::type::of<Shape>().ptr()) != 1)
    throw py::type_error("from_arrays is called on a shape class, e.g. circledist.Circle.from_arrays(arrays)");
  std::string expected;
  py::list args;
  for (size_t i = 0; i < kFieldCounts[kind]; ++i) {
    const char* field = kFieldSpecs[kind][i].name;
    expected += std::string(field) + ", ";
    if (!arrays.contains(field)) throw py::type_error(name + ".from_arrays: no array '" + field + "'");
    args.append(arrays[field]);
  }
  expected += std::string(kSweepField.name) + " (optional)";
  for (auto item : arrays) {
    const std::string key = py::str(item.first);
    bool known = key == kSweepField.name;
    for (size_t i = 0; i < kFieldCounts[kind]; ++i) known = known || key == kFieldSpecs[kind][i].name;
    if (!known) throw py::type_error(name + ".from_arrays: unknown array '" + key + "'; expected " + expected);
  }
  py::dict options;
  if (arrays.contains(kSweepField.name)) options[kSweepField.name] = arrays[kSweepField.name];
  options["copy"] = py::bool_(copy);
  return cls(*args, **options);
}

std::string repr(py::handle self) {
  const Shape& s = constructed(self);
  std::string out = kind_name(s.kind);
  if (!s.batch.empty()) return out + "(batch shape " + shape_text(s.batch) + ")";
  out += "(";
  for (size_t i = 0; i < s.fields.size(); ++i) {
    const Field& f = s.fields[i];
    if (i + 1 == s.fields.size() && *f.data() == 0) break;  // the default sweep is not shown
    out += std::string(i ? ", " : "") + f.name + "=" + py::repr(f.value()).cast<std::string>();
  }
  return out + ")";
}

// A field's role, the word the Python side (scene files, the command line, Scene) reads it by:
// "vector" (3 values), "direction" (3 values, not all zero), "length" (one value >= 0) or
// "control_points" (k + 1 rows of 3). Derived from the FieldSpec, so that the field table of
// shapes.hpp is the only place a field is described.
const char* field_role(const FieldSpec& f) {
  if (f.width == kControlPoints) return "control_points";
  if (f.width == 3) return f.check == Check::NonzeroVector ? "direction" : "vector";
  if (f.width == 1 && f.check == Check::NonNegative) return "length";
  if (f.width == 1 && f.check == Check::Angle) return "angle";
  throw std::logic_error(std::string("field '") + f.name + "' has no role: give it one in field_role");
}

using FieldPair = py::typing::Tuple<py::str, py::str>;

// kind -> its constructor's fields in order, as (name, role): shapes.hpp's table, for Python.
py::typing::Dict<py::str, py::typing::Tuple<FieldPair, py::ellipsis>> shape_fields() {
  py::typing::Dict<py::str, py::typing::Tuple<FieldPair, py::ellipsis>> out;
  for (int k = 0; k < kKindCount; ++k) {
    py::tuple fields(kFieldCounts[k]);
    for (size_t i = 0; i < kFieldCounts[k]; ++i)
      fields[i] = py::make_tuple(kFieldSpecs[k][i].name, field_role(kFieldSpecs[k][i]));
    out[kind_name(k)] = fields;
  }
  return out;
}

}  // namespace

#include "bind_effects.hpp"
#include "bind_pairs.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "circledist: exact distances and closest points between circles, disks, arcs, annuli, lines, rays, segments, points "
      "and Bezier curves in 3D";
  m.attr("__version__") = CIRCLEDIST_VERSION;  // CMakeLists.txt's project() version

  py::class_<Shape> shape(m, "Shape", doc::kShape);
  shape.def_property_readonly("batch_shape", &batch_tuple, "Leading batch dimensions; () for a single shape.")
      .def_property_readonly(
          "kind", [](py::handle s) { return kind_name(constructed(s).kind); }, "The class name, e.g. 'Circle'.")
      .def_property_readonly(
          kSweepField.name, [](py::handle s) { return Array(constructed(s).fields.back().value()); },
          doc::field(kSweepField.name))
      .def("__repr__", &repr)
      .def("to_arrays", &to_arrays, doc::kToArrays)
      // Indexing the batch axes: circledist/_batch.py, shared with circledist.dask's shapes.
      .def(
          "__getitem__",
          [](py::handle self, py::object key) {
            return py::module_::import("circledist._batch").attr("index_shape")(self, key);
          },
          py::arg("key"), doc::kGetItem)
      .def(
          "__len__",
          [](py::handle self) {
            const Shape& s = constructed(self);
            if (s.batch.empty()) throw py::type_error(std::string("len() of a single ") + kind_name(s.kind) + " (batch shape ())");
            return s.batch[0];
          },
          "The length of the first batch axis; TypeError for a single shape.")
      // A shape is a value: true, whatever its length (len() alone would make a single shape's
      // truth a TypeError).
      .def("__bool__", [](py::handle) { return true; })
      // Iterating a batch gives its shapes along the first axis (not NumPy's sequence probing).
      .def("__iter__", [](py::handle self) {
        return py::module_::import("circledist._batch").attr("iterate_shape")(self);
      })
      // A shape pickles, copies and deep-copies as its arrays (to_arrays), rebuilt by its class.
      .def("__reduce__", [](py::handle self) -> py::tuple {
        const py::object rebuild = py::module_::import("circledist._core").attr("_from_arrays");
        const py::object cls = py::type::of(self);
        return py::make_tuple(rebuild, py::make_tuple(cls, to_arrays(self), false));
      });
  shape.attr("from_arrays") = py::reinterpret_steal<py::object>(PyClassMethod_New(
      py::cpp_function(
          [](const py::type& cls, const py::dict& arrays, bool copy) { return from_arrays(cls, arrays, copy); },
          py::name("from_arrays"), py::is_method(shape), py::arg("arrays"), py::kw_only(), py::arg("copy") = true,
          doc::kFromArrays)
          .ptr()));
  m.def("_from_arrays", &from_arrays, py::arg("cls"), py::arg("arrays"), py::arg("copy"),
        "cls.from_arrays(arrays, copy=copy): how pickle rebuilds a shape.");

  bind_shapes(m, std::make_index_sequence<kKindCount>());

  // Properties rather than def_readonly, so that signatures and stubs name the result types.
  py::class_<ClosestPoints>(m, "ClosestPoints", doc::kClosestPoints)
      .def_property_readonly("distance", [](const ClosestPoints& r) { return Distances(r.distance); },
                             "The distance, as distance() gives it.")
      .def_property_readonly("point_a", [](const ClosestPoints& r) { return Array(r.point_a); },
                             "A closest point on the first argument, shape (..., 3).")
      .def_property_readonly("point_b", [](const ClosestPoints& r) { return Array(r.point_b); },
                             "A closest point on the second argument, shape (..., 3).")
      .def_property_readonly("param_a", [](const ClosestPoints& r) { return Array(r.param_a); },
                             "point_a's parameters, shape (..., 2): (t, 0), (theta, 0) on circles, (s, theta) on disks.")
      .def_property_readonly("param_b", [](const ClosestPoints& r) { return Array(r.param_b); },
                             "point_b's parameters, shape (..., 2).")
      .def_property_readonly("unique", [](const ClosestPoints& r) { return Flags(r.unique); },
                             "False when another distinct pair is as close.")
      .def("__repr__", [](const ClosestPoints& r) {
        return "ClosestPoints(distance=" + py::repr(r.distance).cast<std::string>() +
               ", point_a=" + py::repr(r.point_a).cast<std::string>() +
               ", point_b=" + py::repr(r.point_b).cast<std::string>() +
               ", unique=" + py::repr(r.unique).cast<std::string>() + ")";
      });

  m.def(
      "distance",
      [](ShapeLike a, ShapeLike b, PrecisionName precision, SolverName solver, Count workers, ProgressLike progress) {
        return Distances(run_distance(a, b, precision, solver, workers, progress));
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("precision") = py::none(), py::arg("solver") = py::none(),
      py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kDistance());
  m.def(
      "closest_points",
      [](ShapeLike a, ShapeLike b, PrecisionName precision, SolverName solver, Count workers, ProgressLike progress) {
        return run_closest(a, b, precision, solver, workers, progress);
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("precision") = py::none(), py::arg("solver") = py::none(),
      py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kClosest());

  bind_effects(m);
  m.def("_shape_fields", &shape_fields,
        "Each kind's constructor fields in order, as (name, role) pairs; role 'vector' (shape (3,)), 'direction' "
        "(shape (3,), not zero), 'length' (a number >= 0), 'angle' (a number in (0, 2 pi]) or 'control_points' (shape (k + 1, 3)). Read by the scene "
        "files, the command line and circledist.Scene.");
  m.attr("_max_control_points") = kMaxBezierDegree + 1;  // a Bezier curve's, from primitives.hpp
  m.def(
      "_sweep_field", [] { return FieldPair(py::make_tuple(kSweepField.name, field_role(kSweepField))); },
      "The (name, role) of the optional keyword field every kind takes after its own fields.");
  bind_pairs(m);
  // The readers above, for the Python side's arguments (circledist.Scene, circledist.dask): one
  // rule for every entry point.
  m.def(
      "_integer_argument",
      [](const std::string& owner, const char* name, py::handle value, const char* wanted) {
        return integer_of(owner, name, value, wanted);
      },
      py::arg("owner"), py::arg("name"), py::arg("value"), py::arg("wanted"),
      "The integer argument `value` (bools refused, 64 bits at most), or a TypeError / ValueError naming it.");
  m.def(
      "_distance_limit", [](const char* owner, py::handle d) { return limit_of(owner, d); }, py::arg("owner"),
      py::arg("d"), "The distance limit d as a float (finite, >= 0), or a TypeError / ValueError naming it.");
}
