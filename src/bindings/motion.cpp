// circledist.Motion (a batch of rigid motions, motion.hpp's Motion3) and Shape.moved: the motion's
// fields are read and validated as shape fields are (shapes.hpp's make_field), and a moved shape
// is the same kind rebuilt from its moved fields by its own constructor.
#include "module.hpp"
#include "motion_doc.hpp"

#include <circledist/motion.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace circledist::python {
namespace {

constexpr const char* kMotionFields[] = {"translation", "rotation", "center"};
constexpr int kMotionFieldCount = 3;

// A batch of motions: its three vector fields and their broadcast batch shape.
struct Motions {
  std::vector<Field> fields;
  BatchShape batch;
  bool wide() const {
    for (const Field& f : fields)
      if (f.has_wide()) return true;
    return false;
  }
};

Motions make_motions(py::handle translation, py::handle rotation, py::handle center, bool copy) {
  Motions out;
  const py::handle given[kMotionFieldCount] = {translation, rotation, center};
  for (int i = 0; i < kMotionFieldCount; ++i) {
    Field f = make_field("Motion", kMotionFields[i], given[i], 3, Check::Finite, copy);
    bool ok = true;
    const BatchShape joined = broadcast_shapes(out.batch, f.batch, ok);
    if (!ok)
      throw py::value_error(std::string("Motion: ") + kMotionFields[i] + " of batch shape " + shape_text(f.batch) +
                            " does not broadcast with batch shape " + shape_text(out.batch) + " of the other fields");
    out.batch = joined;
    out.fields.push_back(std::move(f));
  }
  return out;
}

const Motions& motions_of(py::handle self) {
  const auto storage = reinterpret_cast<py::detail::instance*>(self.ptr())->get_value_and_holder();
  if (!storage.holder_constructed())
    throw py::type_error("Motion was not initialized: build motions with their constructor, e.g. Motion(translation)");
  return *reinterpret_cast<const Motions*>(storage.value_ptr());
}

// The fields as NumPy arrays by name: as shapes.cpp's to_arrays (float32 fields as float32,
// np.longdouble ones as long double, the others float64; read-only).
py::dict motion_arrays(py::handle self) {
  const Motions& m = motions_of(self);
  py::dict out;
  for (const Field& f : m.fields) {
    py::object value = f.value();
    if (f.single && !f.is_wide) {
      value = value.attr("astype")("float32");
      value.attr("setflags")(py::arg("write") = false);
    }
    out[f.name] = value;
  }
  return out;
}

MotionObject motion_from_arrays(const py::dict& arrays, bool copy) {
  std::string expected;
  for (const char* name : kMotionFields) expected += std::string(expected.empty() ? "" : ", ") + name;
  for (auto item : arrays) {
    const std::string key = py::str(item.first);
    bool known = false;
    for (const char* name : kMotionFields) known = known || key == name;
    if (!known) throw py::type_error("Motion.from_arrays: unknown array '" + key + "'; expected " + expected);
  }
  py::dict options;
  for (const char* name : kMotionFields) {
    if (!arrays.contains(name)) throw py::type_error(std::string("Motion.from_arrays: no array '") + name + "'");
    options[name] = arrays[name];
  }
  options["copy"] = py::bool_(copy);
  return py::reinterpret_borrow<MotionObject>(py::module_::import("circledist._core").attr("Motion")(**options));
}

std::string motion_repr(py::handle self) {
  const Motions& m = motions_of(self);
  if (!m.batch.empty()) return "Motion(batch shape " + shape_text(m.batch) + ")";
  std::string out = "Motion(";
  for (size_t i = 0; i < m.fields.size(); ++i)
    out += std::string(i ? ", " : "") + m.fields[i].name + "=" + py::repr(m.fields[i].value()).cast<std::string>();
  return out + ")";
}

// The element of a field of batch shape `field` at the broadcast batch's coordinates `at` (the
// field's dimensions align with the trailing ones; a dimension of 1 repeats its one element).
Index element_at(const std::vector<Index>& at, const BatchShape& field) {
  Index out = 0, step = 1;
  for (size_t k = 0; k < field.size(); ++k) {
    const Index extent = field[field.size() - 1 - k];
    if (extent != 1) out += at[at.size() - 1 - k] * step;
    step *= extent;
  }
  return out;
}

// The vector fields of each kind's primitive, in the kind's field order (shapes.hpp), written to
// `out` (one pointer per field of the kind; scalar fields, which a motion keeps, are copied by the
// caller and left alone here).
template <class Real, class T> void put(const Vec3<Real>& v, T* out) {
  for (int i = 0; i < 3; ++i) out[i] = T(v[i]);
}
template <class Real, class T> void store(const Vec3<Real>& p, T* const* out) { put(p, out[0]); }
template <class Real, class T> void store(const Line3<Real>& l, T* const* out) {
  put(l.origin, out[0]);
  put(l.direction, out[1]);
}
template <class Real, class T> void store(const Ray3<Real>& r, T* const* out) {
  put(r.origin, out[0]);
  put(r.direction, out[1]);
}
template <class Real, class T> void store(const Segment3<Real>& s, T* const* out) {
  put(s.p0, out[0]);
  put(s.p1, out[1]);
}
template <class Real, class T> void store(const Circle3<Real>& c, T* const* out) {
  put(c.center, out[0]);
  put(c.normal, out[1]);
}
template <class Real, class T> void store(const Disk3<Real>& d, T* const* out) {
  put(d.center, out[0]);
  put(d.normal, out[1]);
}
template <class Real, class T> void store(const BezierCurve3<Real>& b, T* const* out) {
  for (int i = 0; i < int(b.control.cols()); ++i) put(Vec3<Real>(b.control.col(i)), out[0] + 3 * i);
}
template <class Real, class T> void store(const Arc3<Real>& a, T* const* out) {
  put(a.center, out[0]);
  put(a.normal, out[1]);
  put(a.start, out[3]);
}
template <class Real, class T> void store(const Annulus3<Real>& a, T* const* out) {
  put(a.center, out[0]);
  put(a.normal, out[1]);
}

// The moved point and vector fields of every element of the broadcast batch, computed in Real
// and stored as Real (double, or long double where an input was np.longdouble); the scalar fields
// (radii, angles), which a motion keeps, are left to the caller.
template <class Real> py::dict moved_fields(const Shape& s, const Motions& m, const Field& t, const BatchShape& batch) {
  using T = Real;
  const int kind = s.kind;
  const size_t count_fields = kFieldCounts[kind];
  const FieldSpec* spec = kFieldSpecs[kind];
  Index count = 1;
  for (const Index d : batch) count *= d;
  std::vector<py::array_t<T>> outputs(count_fields, no_array<py::array_t<T>>());
  std::array<T*, kMaxShapeFields> out{};
  for (size_t k = 0; k < count_fields; ++k) {
    if (spec[k].width == 1) continue;
    BatchShape dims = batch;
    if (spec[k].width == kControlPoints) {
      dims.push_back(s.points);
      dims.push_back(3);
    } else if (spec[k].width == 3) {
      dims.push_back(3);
    }
    outputs[k] = py::array_t<T>(dims);
    out[k] = outputs[k].mutable_data();
  }
  std::array<const T*, kMaxShapeFields> in{};
  std::vector<Index> at(batch.size());
  const FieldElements e(s);
  visit_kind<Real>(kind, [&](auto tag) {
    using S = typename decltype(tag)::type;
    for (Index i = 0; i < count; ++i) {
      Index flat = i;
      for (size_t d = batch.size(); d-- > 0;) {
        at[d] = flat % batch[d];
        flat /= batch[d];
      }
      const Index shape_element = element_at(at, s.batch);
      std::array<T*, kMaxShapeFields> here{};
      for (size_t k = 0; k < count_fields; ++k) {
        const Index width = s.fields[k].width;
        in[k] = s.fields[k].template data_as<T>() + width * e.of(k, shape_element);
        if (out[k]) here[k] = out[k] + width * i;
      }
      Motion3<Real> motion;
      Vec3<Real>* parts[kMotionFieldCount] = {&motion.translation, &motion.rotation, &motion.center};
      for (int k = 0; k < kMotionFieldCount; ++k)
        *parts[k] = vec<Real>(m.fields[k].template data_as<T>() + 3 * element_at(at, m.fields[k].batch));
      const Real time = Real(t.template data_as<T>()[element_at(at, t.batch)]);
      const S moved_shape = moved(ShapeTraits<S>::make(in.data(), s.points), placement(motion, time));
      store(moved_shape, here.data());
    }
  });
  py::dict arrays;
  for (size_t k = 0; k < count_fields; ++k)
    if (out[k]) arrays[spec[k].name] = outputs[k];
  return arrays;
}

ShapeObject moved_shape(py::handle self, py::handle motion, py::handle t) {
  const Shape& s = constructed(self);
  if (!py::isinstance<Motions>(motion))
    throw py::type_error(std::string("moved: motion must be a circledist.Motion, got ") +
                         Py_TYPE(motion.ptr())->tp_name);
  const Motions& m = motions_of(motion);
  const Field time = make_field("moved", "t", t, 1, Check::Finite);
  bool ok = true;
  BatchShape batch = broadcast_shapes(s.batch, m.batch, ok);
  if (ok) batch = broadcast_shapes(batch, time.batch, ok);
  if (!ok)
    throw py::value_error("moved: batch shapes " + shape_text(s.batch) + " of the " + kind_name(s.kind) + ", " +
                          shape_text(m.batch) + " of the motion and " + shape_text(time.batch) +
                          " of t do not broadcast");
  const bool wide = s.wide() || m.wide() || time.has_wide();
  py::dict arrays = wide ? moved_fields<long double>(s, m, time, batch) : moved_fields<double>(s, m, time, batch);
  // Radii, angles and the sweep: the shape's own arrays, in the dtypes they were given in (they
  // broadcast with the new batch, which holds the shape's).
  for (size_t k = 0; k < s.fields.size(); ++k) {
    const Field& f = s.fields[k];
    if (f.width != 1 || is_default_sweep(f)) continue;
    arrays[f.name] = f.single && !f.is_wide ? f.value().attr("astype")("float32") : f.value();
  }
  arrays["copy"] = py::bool_(false);
  return py::reinterpret_borrow<ShapeObject>(py::type::of(self)(**arrays));
}

}  // namespace

void bind_motion(py::module_& m) {
  py::class_<Motions> cls(m, "Motion", doc::kMotion);
  const py::tuple zero = py::make_tuple(0.0, 0.0, 0.0);
  cls.def(py::init([](ArrayLike translation, ArrayLike rotation, ArrayLike center, bool copy) {
            return make_motions(translation, rotation, center, copy);
          }),
          py::arg("translation") = zero, py::arg("rotation") = zero, py::arg("center") = zero, py::kw_only(),
          py::arg("copy") = true);
  for (int i = 0; i < kMotionFieldCount; ++i) {
    cls.def_property_readonly(
        kMotionFields[i], [i](py::handle self) { return Array(motions_of(self).fields[size_t(i)].value()); },
        doc::motion_field(kMotionFields[i]));
  }
  cls.def_property_readonly(
         "batch_shape",
         [](py::handle self) {
           const Motions& ms = motions_of(self);
           py::typing::Tuple<py::int_, py::ellipsis> out(ms.batch.size());
           for (size_t i = 0; i < ms.batch.size(); ++i) out[i] = py::int_(ms.batch[i]);
           return out;
         },
         "Leading batch dimensions; () for a single motion.")
      .def("__repr__", &motion_repr)
      .def("to_arrays", &motion_arrays, doc::kMotionToArrays)
      .def("__reduce__", [](py::handle self) -> py::tuple {
        const py::object rebuild = py::module_::import("circledist._core").attr("_motion_from_arrays");
        return py::make_tuple(rebuild, py::make_tuple(motion_arrays(self), false));
      });
  cls.attr("from_arrays") = py::reinterpret_steal<py::object>(PyClassMethod_New(
      py::cpp_function(
          [](const py::type&, const py::dict& arrays, bool copy) { return motion_from_arrays(arrays, copy); },
          py::name("from_arrays"), py::is_method(cls), py::arg("arrays"), py::kw_only(), py::arg("copy") = true,
          doc::kMotionFromArrays)
          .ptr()));
  m.def("_motion_from_arrays", &motion_from_arrays, py::arg("arrays"), py::arg("copy"),
        "Motion.from_arrays(arrays, copy=copy): how pickle rebuilds a motion.");

  // Shape.moved, on the base class every kind derives from.
  const py::object shape = py::type::of<Shape>();
  shape.attr("moved") =
      py::cpp_function([](py::handle self, MotionObject motion, ArrayLike t) { return moved_shape(self, motion, t); },
                       py::name("moved"), py::is_method(shape), py::arg("motion"), py::arg("t"), doc::kMoved);
}

}  // namespace circledist::python
