// circledist.Motion (a batch of rigid motions, motion.hpp's Motion3) and Shape.moved: the motion's
// fields are read and validated as shape fields are (shapes.hpp's make_field), and a moved shape
// is the same kind rebuilt from its moved fields by its own constructor. first_contact and its
// answer, Contact, and closest_approach and its answer, Approach: motion.hpp's conservative
// advancement and closest_approach.hpp's branch and bound over the broadcast of both shapes,
// both motions (and the contact distance), each distance answered by the pair tables' kernels
// (kernels/pairs.hpp), so that they add no code per pair.
#include "module.hpp"
#include "motion_doc.hpp"

#include <circledist/closest_approach.hpp>
#include <circledist/motion.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
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
  // Every field float32, or zero (exact in every precision, as the defaults): a float32 query
  // stays float32 with Motion(translation=float32 values).
  bool single() const {
    for (const Field& f : fields) {
      if (f.single) continue;
      const double* p = f.data();
      for (Index i = 0, n = f.array.size(); i < n; ++i)
        if (p[i] != 0) return false;
    }
    return true;
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
    out[f.name] = f.given();
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

// first_contact's answer: the time, and closest_points' answers at that time.
struct Contacts {
  py::object time, distance, point_a, point_b, param_a, param_b, unique;
};
// closest_approach's answer: the time of the least distance, and closest_points' answers then.
struct Approaches : Contacts {};

// None: at rest (one motion of zero fields, made once and never freed, as default_sweep).
const Motions& motion_argument(const char* query, const char* name, py::handle value) {
  if (value.is_none()) {
    static const Motions* const rest = [] {
      const py::tuple zero = py::make_tuple(0.0, 0.0, 0.0);
      return new Motions(make_motions(zero, zero, zero, true));
    }();
    return *rest;
  }
  if (!py::isinstance<Motions>(value))
    throw py::type_error(std::string(query) + ": " + name + " must be a circledist.Motion or None, got " +
                         Py_TYPE(value.ptr())->tp_name);
  return motions_of(value);
}

Motions motions_rounded_to_float(const char* owner, const Motions& m) {
  Motions out = m;
  for (Field& f : out.fields) f = rounded_to_float(owner, f);
  return out;
}

// The points and vectors a motion moves in a shape's fields, each as motion.hpp's moved() moves
// it (a point by Placement::point, a vector by Placement::vector, an arc's start as its direction
// in the plane), with the place of its moved value (`out`: one pointer per field of the kind, as
// store()'s). Listed once per batch element, so that an evaluation moves only them: no shape
// rebuilt, no arc's frame or trigonometry formed again, no curve allocated, the same numbers.
template <class Real> struct MovingParts {
  struct Part {
    Vec3<Real> from;  // the field's value (an arc's start: its direction in the plane)
    Real* to;
    bool point;  // a point (a center, an origin, an end, a control point), else a vector
  };
  static constexpr int kCapacity = std::max(kMaxBezierDegree + 1, 3);
  std::array<Part, size_t(kCapacity)> list{};
  int count = 0;
  void point(const Vec3<Real>& x, Real* to) { list[size_t(count++)] = {x, to, true}; }
  void vector(const Vec3<Real>& v, Real* to) { list[size_t(count++)] = {v, to, false}; }
};
template <class Real> void list_parts(const Vec3<Real>& p, Real* const* out, MovingParts<Real>& to) {
  to.point(p, out[0]);
}
template <class Real> void list_parts(const Line3<Real>& l, Real* const* out, MovingParts<Real>& to) {
  to.point(l.origin, out[0]);
  to.vector(l.direction, out[1]);
}
template <class Real> void list_parts(const Ray3<Real>& r, Real* const* out, MovingParts<Real>& to) {
  to.point(r.origin, out[0]);
  to.vector(r.direction, out[1]);
}
template <class Real> void list_parts(const Segment3<Real>& s, Real* const* out, MovingParts<Real>& to) {
  to.point(s.p0, out[0]);
  to.point(s.p1, out[1]);
}
template <class Real> void list_parts(const Circle3<Real>& c, Real* const* out, MovingParts<Real>& to) {
  to.point(c.center, out[0]);
  to.vector(c.normal, out[1]);
}
template <class Real> void list_parts(const Disk3<Real>& d, Real* const* out, MovingParts<Real>& to) {
  to.point(d.center, out[0]);
  to.vector(d.normal, out[1]);
}
template <class Real> void list_parts(const Annulus3<Real>& a, Real* const* out, MovingParts<Real>& to) {
  to.point(a.center, out[0]);
  to.vector(a.normal, out[1]);
}
template <class Real> void list_parts(const Arc3<Real>& a, Real* const* out, MovingParts<Real>& to) {
  to.point(a.center, out[0]);
  to.vector(a.normal, out[1]);
  to.vector(detail::arc_start_in_plane(a), out[3]);
}
template <class Real> void list_parts(const BezierCurve3<Real>& b, Real* const* out, MovingParts<Real>& to) {
  for (int i = 0; i < int(b.control.cols()); ++i) to.point(Vec3<Real>(b.control.col(i)), out[0] + 3 * i);
}

// What a function calls inlined into it: the unit is compiled for size (CMakeLists.txt), where
// Eigen's small loops stay calls, and those calls were most of a cheap pair's evaluation.
#if defined(__GNUC__) || defined(__clang__)
#define CIRCLEDIST_FLATTEN __attribute__((flatten))
#else
#define CIRCLEDIST_FLATTEN
#endif

// One moving shape of first_contact at one element of the batch: its fields as given (`in`, the
// sweep last), its motion, and its fields at the time last moved to (`now`: the moved points and
// vectors in `moved`, the numbers, which a motion keeps, as given).
template <class Real> struct Mover {
  int kind = kPoint, points = 0, count = 0;
  std::array<const Real*, kMaxShapeFields> in{}, now{};
  std::array<std::array<Real, 3 * (kMaxBezierDegree + 1)>, kMaxShapeFields> moved{};
  Motion3<Real> motion;
  Real (*rotation_speed)(const Mover&) = nullptr;  // motion.hpp's detail::rotation_speed
  Real (*size)(const Mover&) = nullptr;            // motion.hpp's detail::motion_size
  BatchShape none;                                 // the one element's batch shape, ()
  std::array<FieldRef<Real>, kMaxShapeFields> refs{};
  MovingParts<Real> moving;
  // A motion whose rotation is exactly zero turns by R = I at every time (rotation_matrix): its
  // vectors stay as moved at t = 0, and a point x moves to (center + I (x - center)) + t
  // translation, Placement::point's sum in its order, the bracket formed once (`still`).
  bool turns = false;
  std::array<Vec3<Real>, size_t(MovingParts<Real>::kCapacity)> still{};

  template <class S> Swept<S> shape() const { return {ShapeTraits<S>::make(in.data(), points), *in[count - 1]}; }
  // `now` at time t: the fields as moved(shape, placement(motion, t)) has them.
  CIRCLEDIST_FLATTEN void move(Real t) {
    if (turns) {
      const Placement<Real> p = placement(motion, t);
      for (int i = 0; i < moving.count; ++i) {
        const auto& part = moving.list[size_t(i)];
        put(part.point ? p.point(part.from) : p.vector(part.from), part.to);
      }
      return;
    }
    const Vec3<Real> shift = t * motion.translation;
    for (int i = 0; i < moving.count; ++i)
      if (moving.list[size_t(i)].point) put(Vec3<Real>(still[size_t(i)] + shift), moving.list[size_t(i)].to);
  }
  template <class S> static Real speed_of(const Mover& m) { return detail::rotation_speed(m.shape<S>(), m.motion); }
  template <class S> static Real size_of(const Mover& m) { return detail::motion_size(m.shape<S>(), m.motion); }

  // The element `at` of the broadcast batch: its fields and motion, and the kind's operations.
  void set(const Shape& s, const Motions& m, const std::vector<Index>& at) {
    kind = s.kind;
    points = s.points;
    count = int(s.fields.size());
    for (int k = 0; k < count; ++k) {
      const Field& f = s.fields[size_t(k)];
      in[size_t(k)] = f.template data_as<Real>() + f.width * element_at(at, f.batch);
      // Vector fields read the moved values; numbers (width 1) the given ones.
      now[size_t(k)] = f.width == 1 ? in[size_t(k)] : moved[size_t(k)].data();
      refs[size_t(k)] = {f.name, now[size_t(k)], f.width, &none};
    }
    Vec3<Real>* parts[kMotionFieldCount] = {&motion.translation, &motion.rotation, &motion.center};
    for (int k = 0; k < kMotionFieldCount; ++k)
      *parts[k] =
          vec<Real>(m.fields[size_t(k)].template data_as<Real>() + 3 * element_at(at, m.fields[size_t(k)].batch));
    std::array<Real*, kMaxShapeFields> out{};
    for (int k = 0; k < count; ++k) out[size_t(k)] = moved[size_t(k)].data();
    moving.count = 0;
    visit_kind<Real>(kind, [&](auto tag) {
      using S = typename decltype(tag)::type;
      rotation_speed = &speed_of<S>;
      size = &size_of<S>;
      list_parts(ShapeTraits<S>::make(in.data(), points), out.data(), moving);
    });
    turns = motion.rotation != Vec3<Real>::Zero();
    if (turns) return;
    const Placement<Real> p = placement(motion, Real(0));  // R = I
    for (int i = 0; i < moving.count; ++i) {
      const auto& part = moving.list[size_t(i)];
      if (part.point)
        still[size_t(i)] = p.center + p.rotation * (part.from - p.center);
      else
        put(p.vector(part.from), part.to);
    }
  }
  Operand<Real> operand() const {
    Operand<Real> out{kind, points, &none};
    for (int k = 0; k < count; ++k) out.fields[size_t(k)] = refs[size_t(k)];
    out.count = count;
    return out;
  }
};

// first_contact and closest_approach over the pair tables: motion.hpp's first_contact and
// closest_approach.hpp's closest_approach, element by element, with the shapes moved here (per
// kind) and every distance and the answer's closest points answered by the table's distance and
// closest_points kernels of the pair (the solver's own). The searches are the headers' own
// (detail::advance, detail::least_over_time: the bound L, the bar delta), as are their pieces
// (rotation_speed, motion_size, contact_tolerance). So no pair gains code: the pair units, the
// build's long pole, and the module's size stay as they were. Both argument orders run the pair's
// one kernel (the table swaps the operands and the answers), so they agree to the bit. `batch`:
// the broadcast batch shape (checked by the caller); `within` is null for closest_approach.
template <class Real> Contacts run_motion(const char* query, const Shape& a, const Shape& b, const Motions& motion_a,
                                          const Motions& motion_b, const Field* within, const BatchShape& batch,
                                          const Choice& c) {
  constexpr Real nan = std::numeric_limits<Real>::quiet_NaN();
  const bool approach = within == nullptr;
  const PairTable<Real>& table = pairs().of<Real>(c.solver);
  const Call<Real> call{table, a, b, nullptr, c.workers, c.progress};
  const KernelFn<Real> distance_fn = call.entry(&PairTable<Real>::distance);
  const KernelFn<Real> closest_fn = call.entry(&PairTable<Real>::closest);
  const bool reversed = call.reversed();
  Index size = 1;
  for (const Index d : batch) size *= d;
  auto time = new_array<Real>(batch, 0), distance = new_array<Real>(batch, 0);
  auto point_a = new_array<Real>(batch, 3), point_b = new_array<Real>(batch, 3);
  auto param_a = new_array<Real>(batch, 2), param_b = new_array<Real>(batch, 2);
  auto unique = new_array<bool>(batch, 0);
  Real *out_time = time.mutable_data(), *out_distance = distance.mutable_data();
  Real *out_point_a = point_a.mutable_data(), *out_point_b = point_b.mutable_data();
  Real *out_param_a = param_a.mutable_data(), *out_param_b = param_b.mutable_data();
  bool* out_unique = unique.mutable_data();
  const Real* limits = approach ? nullptr : within->template data_as<Real>();
  // A long-double query's first read of a float64 field makes its long-double copy, with the GIL
  // held (Field::data_as): made here, before the threads read the fields without it.
  for (const Shape* s : {&a, &b})
    for (const Field& f : s->fields) f.template data_as<Real>();
  for (const Motions* m : {&motion_a, &motion_b})
    for (const Field& f : m->fields) f.template data_as<Real>();
  const auto work = [&](Index begin, Index end) {
    Mover<Real> first, second;  // a and b
    std::vector<Index> at(batch.size());
    for (Index i = begin; i < end; ++i) {
      Index flat = i;
      for (size_t d = batch.size(); d-- > 0;) {
        at[d] = flat % batch[d];
        flat /= batch[d];
      }
      // What first_contact answers where there is no contact (motion.hpp's Contact), and
      // closest_approach for NaN input.
      out_time[i] = approach ? nan : std::numeric_limits<Real>::infinity();
      out_distance[i] = nan;
      std::fill_n(out_point_a + 3 * i, 3, nan);
      std::fill_n(out_point_b + 3 * i, 3, nan);
      std::fill_n(out_param_a + 2 * i, 2, nan);
      std::fill_n(out_param_b + 2 * i, 2, nan);
      out_unique[i] = true;
      first.set(a, motion_a, at);
      second.set(b, motion_b, at);
      const Real limit = approach ? Real(0) : limits[element_at(at, within->batch)];
      Real spins[2] = {0, 0};
      for (const Mover<Real>* m : {&first, &second}) {
        try {
          spins[m == &first ? 0 : 1] = m->rotation_speed(*m);
        } catch (const std::invalid_argument& e) {
          std::string why = e.what();
          const std::string prefix = "circledist::first_contact: ";
          if (why.compare(0, prefix.size(), prefix) == 0) why.erase(0, prefix.size());
          const bool is_a = m == &first;
          throw std::invalid_argument(std::string(query) + ": " + (is_a ? "motion_a" : "motion_b") +
                                      index_text(i, batch) + " rotates the " + (is_a ? "first" : "second") +
                                      " argument, a " + kind_name(m->kind) + ": " + why);
        }
      }
      const Real speed = detail::combined_speed(first.motion, second.motion, spins[0], spins[1]);
      const Real extent = std::max(first.size(first), second.size(second));
      if (speed != speed || extent != extent || limit != limit) {
        out_time[i] = nan;
        continue;
      }
      // The table's kernel of the pair, on the moved fields (its operands in the table's order).
      const Operand<Real> oa = first.operand(), ob = second.operand();
      const bool swept_pair = *first.in[size_t(first.count - 1)] != 0 || *second.in[size_t(second.count - 1)] != 0;
      Request<Real> r(reversed ? ob : oa, reversed ? oa : ob, nullptr, reversed, swept_pair);
      Real d;
      std::uint64_t evaluations = 0;
      const auto distance_at = [&](Real t) {
        first.move(t);
        second.move(t);
        r.distance = &d;
        distance_fn(r, 0, 1);
        return d;
      };
      Real t;
      bool several = false;
      try {
        if (approach) {
          const detail::Least<Real> least =
              detail::least_over_time(distance_at, speed, extent, evaluations, kMotionEvaluationLimit, query);
          t = least.time;
          several = least.several;
          if (t == t) {  // the movers back at the least's time
            first.move(t);
            second.move(t);
          }
        } else {
          t = detail::advance(distance_at, limit, speed, contact_tolerance(extent), evaluations);
        }
      } catch (const evaluation_limit&) {
        throw std::runtime_error(std::string(query) + ": " +
                                 (batch.empty() ? std::string("the query") : "query" + index_text(i, batch)) +
                                 " needs more than " + std::to_string(kMotionEvaluationLimit) +
                                 " distance evaluations (its motions are too fast for the bar, or it grazes "
                                 "tangentially at a vast speed); no answer is given rather than one that could miss "
                                 "a closer time");
      }
      if (t != t) {
        out_time[i] = nan;
      } else if (t <= 1) {  // the movers are at t
        r.distance = out_distance + i;
        r.flag = out_unique + i;
        r.point_a = (reversed ? out_point_b : out_point_a) + 3 * i;
        r.point_b = (reversed ? out_point_a : out_point_b) + 3 * i;
        r.param_a = (reversed ? out_param_b : out_param_a) + 2 * i;
        r.param_b = (reversed ? out_param_a : out_param_b) + 2 * i;
        closest_fn(r, 0, 1);
        out_time[i] = t;
        if (several) out_unique[i] = false;
      }
    }
  };
  run_released(size, c.workers, work, c.progress);
  if (batch.empty())
    return {scalar<Real>(out_time[0]), scalar<Real>(out_distance[0]),
            std::move(point_a),        std::move(point_b),
            std::move(param_a),        std::move(param_b),
            py::bool_(out_unique[0])};
  return {std::move(time),    std::move(distance), std::move(point_a), std::move(point_b),
          std::move(param_a), std::move(param_b),  std::move(unique)};
}

// A float64 answer rounded to float32: inf and NaN (no contact) stay; a finite value beyond
// float32's range is an OverflowError naming the output and its index.
py::object contact_float32(const char* query, const py::object& value, const char* output, Index width) {
  const py::object out = to_float32(value, query, output, width, false);
  const auto check = [&](double x, Index flat, const BatchShape& batch) {
    if (std::isfinite(x) && !std::isfinite(float(x)))
      throw std::overflow_error(std::string(query) + ": " + output + index_text(flat, batch) +
                                " is beyond float32's range (precision='float32'); ask for precision='float64'");
  };
  if (py::isinstance<py::float_>(value)) {
    check(value.cast<double>(), 0, {});
    return out;
  }
  const auto from = py::array_t<double, py::array::c_style>::ensure(value);
  const BatchShape all(from.shape(), from.shape() + from.ndim());
  const BatchShape batch(all.begin(), all.end() - (width > 1 ? 1 : 0));
  for (Index i = 0, n = from.size(); i < n; ++i) check(from.data()[i], i / width, batch);
  return out;
}

// first_contact(a, b, motion_a, motion_b, within=, precision=, workers=, progress=) and
// closest_approach (the same without within: `within_given` null).
Contacts motion_query_of(const char* query, py::handle a_given, py::handle b_given, py::handle motion_a_given,
                         py::handle motion_b_given, const py::handle* within_given, const py::object& precision,
                         const py::object& solver, py::handle workers, const py::object& progress) {
  const Argument x(a_given), y(b_given);
  const Shape &a = *x.shape, &b = *y.shape;
  const Motions& motion_a = motion_argument(query, "motion_a", motion_a_given);
  const Motions& motion_b = motion_argument(query, "motion_b", motion_b_given);
  const Field within =
      make_field(query, "within", within_given ? *within_given : py::float_(0.0).ptr(), 1, Check::NonNegative);
  const Field* limit = within_given ? &within : nullptr;
  Choice c(precision, solver, a, b, workers, progress);
  // precision=None: NumPy's promotion over the shapes and the motions given (at rest decides nothing).
  if (precision.is_none()) {
    const bool given_a = !motion_a_given.is_none(), given_b = !motion_b_given.is_none();
    if ((given_a && motion_a.wide()) || (given_b && motion_b.wide()))
      c.precision = kLongDouble;
    else if (c.precision == kFloat && ((given_a && !motion_a.single()) || (given_b && !motion_b.single())))
      c.precision = kDouble;
  }
  // The batch shapes, named in the caller's words (the kernel's Broadcast would name fields).
  bool ok = true;
  BatchShape batch = broadcast_shapes(a.batch, b.batch, ok);
  if (!ok)
    throw py::value_error(std::string(query) + ": batch shapes " + shape_text(a.batch) + " of the " +
                          kind_name(a.kind) + " and " + shape_text(b.batch) + " of the " + kind_name(b.kind) +
                          " do not broadcast");
  const std::pair<const char*, const BatchShape*> others[] = {
      {"motion_a", &motion_a.batch}, {"motion_b", &motion_b.batch}, {"within", &within.batch}};
  for (const auto& [name, other] : others) {
    const BatchShape joined = broadcast_shapes(batch, *other, ok);
    if (!ok)
      throw py::value_error(std::string(query) + ": " + name + " of batch shape " + shape_text(*other) +
                            " does not broadcast with batch shape " + shape_text(batch) +
                            " of the arguments before it");
    batch = joined;
  }
  if (c.precision == kLongDouble) return run_motion<long double>(query, a, b, motion_a, motion_b, limit, batch, c);
  if (!c.single()) return run_motion<double>(query, a, b, motion_a, motion_b, limit, batch, c);
  const Shape fa = rounded_to_float(a), fb = rounded_to_float(b);
  const Motions fma = motions_rounded_to_float("motion_a", motion_a),
                fmb = motions_rounded_to_float("motion_b", motion_b);
  const Field fw = rounded_to_float(query, within);
  const Contacts r = run_motion<double>(query, fa, fb, fma, fmb, limit ? &fw : nullptr, batch, c);
  return {contact_float32(query, r.time, "time", 1),
          contact_float32(query, r.distance, "distance", 1),
          contact_float32(query, r.point_a, "point_a", 3),
          contact_float32(query, r.point_b, "point_b", 3),
          contact_float32(query, r.param_a, "param_a", 2),
          contact_float32(query, r.param_b, "param_b", 2),
          r.unique};
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

  py::class_<Contacts>(m, "Contact", doc::kContact)
      .def_property_readonly(
          "time", [](const Contacts& r) { return Distances(r.time); },
          "The earliest time in [0, 1] within reach; inf where the shapes never come within it.")
      .def_property_readonly(
          "distance", [](const Contacts& r) { return Distances(r.distance); },
          "The distance at that time (at most `within`, within rounding); NaN where there is no contact.")
      .def_property_readonly(
          "point_a", [](const Contacts& r) { return Array(r.point_a); },
          "A closest point on the first shape at that time, shape (..., 3); NaN where there is no contact.")
      .def_property_readonly(
          "point_b", [](const Contacts& r) { return Array(r.point_b); },
          "A closest point on the second shape at that time, shape (..., 3); NaN where there is no contact.")
      .def_property_readonly(
          "param_a", [](const Contacts& r) { return Array(r.param_a); },
          "point_a's parameters on the moved first shape, shape (..., 2), as closest_points' param_a.")
      .def_property_readonly(
          "param_b", [](const Contacts& r) { return Array(r.param_b); },
          "point_b's parameters on the moved second shape, shape (..., 2).")
      .def_property_readonly(
          "unique", [](const Contacts& r) { return Flags(r.unique); },
          "closest_points' unique at that time (True where there is no contact).")
      .def("__repr__", [](const Contacts& r) {
        return "Contact(time=" + py::repr(r.time).cast<std::string>() +
               ", distance=" + py::repr(r.distance).cast<std::string>() +
               ", point_a=" + py::repr(r.point_a).cast<std::string>() +
               ", point_b=" + py::repr(r.point_b).cast<std::string>() + ")";
      });
  m.def(
      "first_contact",
      [](ShapeLike a, ShapeLike b, OptionalMotion motion_a, OptionalMotion motion_b, ArrayLike within,
         PrecisionName precision, SolverName solver, Count workers, ProgressLike progress) {
        const py::handle limit = within;
        return motion_query_of("first_contact", a, b, motion_a, motion_b, &limit, precision, solver, workers, progress);
      },
      py::arg("a"), py::arg("b"), py::arg("motion_a") = py::none(), py::arg("motion_b") = py::none(), py::kw_only(),
      py::arg("within") = 0.0, py::arg("precision") = py::none(), py::arg("solver") = py::none(),
      py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kFirstContact());

  py::class_<Approaches>(m, "Approach", doc::kApproach)
      .def_property_readonly(
          "time", [](const Approaches& r) { return Distances(r.time); },
          "A time in [0, 1] of the least distance (the earliest of equal ones found); NaN for NaN input.")
      .def_property_readonly(
          "distance", [](const Approaches& r) { return Distances(r.distance); },
          "The least distance over [0, 1] (closest_points' distance at that time).")
      .def_property_readonly(
          "point_a", [](const Approaches& r) { return Array(r.point_a); },
          "A closest point on the first shape at that time, shape (..., 3).")
      .def_property_readonly(
          "point_b", [](const Approaches& r) { return Array(r.point_b); },
          "A closest point on the second shape at that time, shape (..., 3).")
      .def_property_readonly(
          "param_a", [](const Approaches& r) { return Array(r.param_a); },
          "point_a's parameters on the moved first shape, shape (..., 2), as closest_points' param_a.")
      .def_property_readonly(
          "param_b", [](const Approaches& r) { return Array(r.param_b); },
          "point_b's parameters on the moved second shape, shape (..., 2).")
      .def_property_readonly(
          "unique", [](const Approaches& r) { return Flags(r.unique); },
          "False where another time is as close (within the bar) or closest_points' pair is not unique.")
      .def("__repr__", [](const Approaches& r) {
        return "Approach(time=" + py::repr(r.time).cast<std::string>() +
               ", distance=" + py::repr(r.distance).cast<std::string>() +
               ", point_a=" + py::repr(r.point_a).cast<std::string>() +
               ", point_b=" + py::repr(r.point_b).cast<std::string>() + ")";
      });
  m.def(
      "closest_approach",
      [](ShapeLike a, ShapeLike b, OptionalMotion motion_a, OptionalMotion motion_b, PrecisionName precision,
         SolverName solver, Count workers, ProgressLike progress) {
        Approaches out;
        static_cast<Contacts&>(out) = motion_query_of("closest_approach", a, b, motion_a, motion_b, nullptr, precision,
                                                      solver, workers, progress);
        return out;
      },
      py::arg("a"), py::arg("b"), py::arg("motion_a") = py::none(), py::arg("motion_b") = py::none(), py::kw_only(),
      py::arg("precision") = py::none(), py::arg("solver") = py::none(), py::arg("workers") = 1,
      py::arg("progress") = py::none(), doc::kClosestApproach());
}

}  // namespace circledist::python
