// The pair queries: distance() and closest_points() over every registered pair of kinds, and
// closest_points' answer, ClosestPoints. Thin by design: the math lives in cpp/include/circledist,
// the loops over a batch in kernels/pairs.hpp.
#include "module.hpp"
#include "queries_doc.hpp"

#include <pybind11/pybind11.h>

#include <string>

namespace circledist::python {

py::object shapes_distance(const Shape& a, const Shape& b, const Choice& c, py::handle progress) {
  auto distance = [](const auto& call) { return call.distance(); };
  if (!c.single()) return with_call(a, b, nullptr, c, distance, progress);
  const Shape fa = rounded_to_float(a), fb = rounded_to_float(b);
  return to_float32(with_call(fa, fb, nullptr, c, distance, progress), "distance", "the distance", 1);
}

namespace {

py::object run_distance(py::handle a, py::handle b, const py::object& precision, const py::object& solver,
                        py::handle workers, const py::object& progress) {
  const Argument x(a), y(b);
  const Choice c(precision, solver, *x.shape, *y.shape, workers, progress);
  return shapes_distance(*x.shape, *y.shape, c, c.progress);
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

}  // namespace

void bind_queries(py::module_& m) {
  // Properties rather than def_readonly, so that signatures and stubs name the result types.
  py::class_<ClosestPoints>(m, "ClosestPoints", doc::kClosestPoints)
      .def_property_readonly(
          "distance", [](const ClosestPoints& r) { return Distances(r.distance); },
          "The distance, as distance() gives it.")
      .def_property_readonly(
          "point_a", [](const ClosestPoints& r) { return Array(r.point_a); },
          "A closest point on the first argument, shape (..., 3).")
      .def_property_readonly(
          "point_b", [](const ClosestPoints& r) { return Array(r.point_b); },
          "A closest point on the second argument, shape (..., 3).")
      .def_property_readonly(
          "param_a", [](const ClosestPoints& r) { return Array(r.param_a); },
          "point_a's parameters, shape (..., 2): (t, 0), (theta, 0) on circles, (s, theta) on disks.")
      .def_property_readonly(
          "param_b", [](const ClosestPoints& r) { return Array(r.param_b); }, "point_b's parameters, shape (..., 2).")
      .def_property_readonly(
          "unique", [](const ClosestPoints& r) { return Flags(r.unique); },
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
}

}  // namespace circledist::python
