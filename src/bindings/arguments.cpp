// The argument readers' out-of-line part (what only the rarer arguments and the error messages
// need), and the readers bound for the Python side's arguments (circledist.Scene,
// circledist.dask): one rule for every entry point.
#include "module.hpp"

#include <pybind11/pybind11.h>

#include <cmath>
#include <string>

namespace circledist::python {

std::string shown(py::handle value) {
  const std::string text = py::repr(value).cast<std::string>();
  if (text.size() <= 40 || !PyLong_Check(value.ptr())) return text;
  return "an integer of " + std::to_string(text.size() - (text[0] == '-' ? 1 : 0)) + " digits";
}

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

Index count_of(const char* owner, py::handle k) {
  constexpr const char* wanted = "an integer >= 1";
  const long long value = integer_of(owner, "k", k, wanted);
  if (value < 1) throw py::value_error(std::string(owner) + ": k must be " + wanted + ", got " + std::to_string(value));
  return Index(value);
}

void bind_arguments(py::module_& m) {
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

}  // namespace circledist::python
