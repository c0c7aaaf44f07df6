// The shape classes: Shape, the base, and one class per kind, bound from the kinds' tables
// (shapes.hpp's fields, shapes_doc.hpp's docstrings) with no per-kind code; and those tables for
// the Python side (scene files, the command line, circledist.Scene).
#include "module.hpp"
#include "shapes_doc.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/typing.h>

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace circledist::python {
namespace {

template <int K> struct ShapeOf : Shape {
  using Shape::Shape;
};

// Every shape class holds one C++ object, a ShapeOf<K>: a Shape with nothing added, so the two
// share their address (standard layout) and the first value slot of the instance is the Shape.
static_assert(std::is_standard_layout_v<ShapeOf<kCircle>>,
              "a ShapeOf<K> must be pointer-interconvertible with its Shape");

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

// Every kind's class, from the kinds' tables (shapes.hpp's fields, shapes_doc.hpp's docstrings).
template <size_t... K> void bind_kinds(py::module_& m, std::index_sequence<K...>) {
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
    out[f.name] = f.given();
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

void bind_shapes(py::module_& m) {
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
            if (s.batch.empty())
              throw py::type_error(std::string("len() of a single ") + kind_name(s.kind) + " (batch shape ())");
            return s.batch[0];
          },
          "The length of the first batch axis; TypeError for a single shape.")
      // A shape is a value: true, whatever its length (len() alone would make a single shape's
      // truth a TypeError).
      .def("__bool__", [](py::handle) { return true; })
      // Iterating a batch gives its shapes along the first axis (not NumPy's sequence probing).
      .def("__iter__",
           [](py::handle self) { return py::module_::import("circledist._batch").attr("iterate_shape")(self); })
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

  bind_kinds(m, std::make_index_sequence<kKindCount>());
}

void bind_shape_fields(py::module_& m) {
  m.def(
      "_shape_fields", &shape_fields,
      "Each kind's constructor fields in order, as (name, role) pairs; role 'vector' (shape (3,)), 'direction' "
      "(shape (3,), not zero), 'length' (a number >= 0), 'angle' (a number in (0, 2 pi]) or 'control_points' (shape (k + 1, 3)). Read by the scene "
      "files, the command line and circledist.Scene.");
  m.attr("_max_control_points") = kMaxBezierDegree + 1;  // a Bezier curve's, from primitives.hpp
  m.def(
      "_sweep_field", [] { return FieldPair(py::make_tuple(kSweepField.name, field_role(kSweepField))); },
      "The (name, role) of the optional keyword field every kind takes after its own fields.");
}

}  // namespace circledist::python
