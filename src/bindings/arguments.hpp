// How the module reads its arguments, one rule for every entry point: the shapes (a Shape, or an
// array-like of points), the arithmetic of a query (precision, solver, workers: a Choice), the
// progress callback, and the integer arguments. Inline here, so that a scalar query's reading of
// its arguments compiles into the binding that calls it. circledist.Scene and circledist.dask
// read theirs through the same readers (arguments.cpp binds them).
#pragma once

#include "calls.hpp"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <limits>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>

namespace circledist::python {

// The kernels' tables: every unit of CIRCLEDIST_PAIR_UNITS (kernels/pairs.hpp) registered once.
inline const PairTables& pairs() {
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
inline int precision_of(const py::object& name, const Shape& a, const Shape& b) {
  if (name.is_none()) return a.wide() || b.wide() ? kLongDouble : a.single() && b.single() ? kFloat : kDouble;
  const std::string s = py::str(name);
  if (s == "float32" || s == "float") return kFloat;
  if (s == "float64" || s == "double") return kDouble;
  if (s == "longdouble" || s == "long double" || s == "float128") return kLongDouble;
  throw py::value_error("precision must be None, 'float32', 'float64' or 'longdouble', got '" + s + "'");
}

inline int solver_of(const py::object& name) {
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
std::string shown(py::handle value);

// The one reader of the integer arguments (k, workers, a count of any entry point): an int, a
// NumPy integer or another numbers.Integral, through __index__. bool is refused: True is not a
// count (NumPy refuses it as an array's size, and `k=True` is a slip, not a 1). A value beyond
// 64 bits is refused with the library's words (pybind11 would say "Unable to cast"). `wanted`
// says what the argument takes; `owner` (may be empty) the call, as the messages start.
inline long long integer_of(const std::string& owner, const char* name, py::handle value, const char* wanted) {
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
    throw py::value_error(prefix + " must be " + wanted +
                          (overflow > 0 ? " (at most 2**63 - 1)" : " (at least -2**63)") + ", got " + shown(value));
  if (out == -1 && PyErr_Occurred()) throw py::error_already_set();
  return out;
}

// A distance limit: a finite real number >= 0 (bool and strings refused), named in messages. An
// integer beyond float64's range is refused as not finite (float() of it would raise).
double limit_of(const char* owner, py::handle d);

// nearest's k: an integer >= 1 (integer_of's rules).
Index count_of(const char* owner, py::handle k);

// workers=: SciPy's convention, a positive thread count or -1 for every core. Counts beyond an
// int are the int's largest: the threads are bounded by the work's chunks anyway.
inline int workers_of(py::handle given, const std::string& owner = "") {
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
inline PyTypeObject* shape_type() {
  static PyTypeObject* const type = reinterpret_cast<PyTypeObject*>(py::type::of<Shape>().ptr());
  return type;
}

inline bool is_shape(py::handle value) { return PyType_IsSubtype(Py_TYPE(value.ptr()), shape_type()) != 0; }

// The Shape of a Python object, checked to be a shape built by its constructor: one made by
// Circle.__new__(Circle) alone has unconstructed storage, which must never be read. Every shape
// class holds one C++ object whose address is its Shape's (shapes.cpp, ShapeOf).
inline const Shape& constructed(py::handle value) {
  if (!is_shape(value))
    throw py::type_error(std::string("expected a circledist shape, got ") + Py_TYPE(value.ptr())->tp_name);
  const auto storage = reinterpret_cast<py::detail::instance*>(value.ptr())->get_value_and_holder();
  if (!storage.holder_constructed())
    throw py::type_error(
        std::string(Py_TYPE(value.ptr())->tp_name) +
        " was not initialized: build shapes with their constructor, e.g. Circle(center, normal, radius)");
  return *reinterpret_cast<const Shape*>(storage.value_ptr());
}

// progress=: None or False for none; True for a progress bar (circledist._progress: tqdm when it
// is installed, else a line on stderr), shown once the work has taken a second; or a callable.
inline py::object progress_of(const py::object& given) {
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
template <class Query> auto with_call(const Shape& a, const Shape& b, const Shape* limit, const Choice& c,
                                      Query&& query, py::handle progress) {
  if (c.precision == kLongDouble)
    return query(Call<long double>{pairs().of<long double>(c.solver), a, b, limit, c.workers, progress});
  return query(Call<double>{pairs().of<double>(c.solver), a, b, limit, c.workers, progress});
}
template <class Query>
auto with_call(const Shape& a, const Shape& b, const Shape* limit, const Choice& c, Query&& query) {
  return with_call(a, b, limit, c, std::forward<Query>(query), c.progress);
}

}  // namespace circledist::python
