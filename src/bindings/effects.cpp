// The requested effects (cpp/include/circledist/effects.hpp): intersects, within and
// distance_if_within over broadcast batches, and the work counters. Every pair goes through the
// one PairKernels template (kernels/pairs.hpp), like distance and closest_points.
#include "effects_doc.hpp"
#include "module.hpp"

#include <pybind11/pybind11.h>
#include <pybind11/typing.h>

#include <cstdint>
#include <string>

namespace circledist::python {

Shape limit_shape(const char* owner, py::handle d) {
  return Shape(kPoint, {make_field(owner, "d", d, 1, Check::NonNegative)});
}

py::object shapes_within(const Shape& a, const Shape& b, const Shape& limit, bool want_distance, const Choice& c,
                         py::handle progress) {
  auto within = [want_distance](const auto& call) { return want_distance ? call.distance() : call.within(); };
  if (!c.single()) return with_call(a, b, &limit, c, within, progress);
  const Shape fa = rounded_to_float(a), fb = rounded_to_float(b);
  const Shape fd(limit.kind, {rounded_to_float("within", limit.fields[0])});
  return to_float32(with_call(fa, fb, &fd, c, within, progress), "distance_if_within", "the distance", 1, false);
}

namespace {

py::object run_within(py::handle a, py::handle b, const Shape& limit, bool want_distance, const py::object& precision,
                      const py::object& solver, py::handle workers, const py::object& progress) {
  const Argument x(a), y(b);
  const Choice c(precision, solver, *x.shape, *y.shape, workers, progress);
  return shapes_within(*x.shape, *y.shape, limit, want_distance, c, c.progress);
}

py::typing::Dict<py::str, py::int_> stats_dict() {
  const Stats& s = stats();
  py::typing::Dict<py::str, py::int_> out;
  out["solves"] = s.solves;
  out["distances"] = s.distances;
  out["closest_points"] = s.closest_points;
  out["within"] = s.within;
  out["decided_by_bounds"] = s.decided_by_bounds;
  out["culled"] = s.culled;
  return out;
}

}  // namespace

void bind_effects(py::module_& m) {
  m.def(
      "intersects",
      [](ShapeLike a, ShapeLike b, PrecisionName precision, SolverName solver, Count workers, ProgressLike progress) {
        static const Shape* zero = new Shape(kPoint, {default_sweep()});  // d = 0 (a shared 0-d zero)
        return Flags(run_within(a, b, *zero, false, precision, solver, workers, progress));
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("precision") = py::none(), py::arg("solver") = py::none(),
      py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kIntersects());
  m.def(
      "within",
      [](ShapeLike a, ShapeLike b, ArrayLike d, PrecisionName precision, SolverName solver, Count workers,
         ProgressLike progress) {
        return Flags(run_within(a, b, limit_shape("within", d), false, precision, solver, workers, progress));
      },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kWithin());
  m.def(
      "distance_if_within",
      [](ShapeLike a, ShapeLike b, ArrayLike d, PrecisionName precision, SolverName solver, Count workers,
         ProgressLike progress) {
        return Distances(
            run_within(a, b, limit_shape("distance_if_within", d), true, precision, solver, workers, progress));
      },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(),
      doc::kDistanceIfWithin());
  m.def("stats", &stats_dict, doc::kStats);
  m.def("reset_stats", &reset_stats, doc::kResetStats);
  m.def(
      "_query_kinds",
      [] {
        const PairTable<double>& t = pairs().of<double>(pairs().default_solver);
        py::typing::List<py::typing::Tuple<py::str, py::str>> out;
        for (int a = 0; a < kKindCount; ++a)
          for (int b = 0; b < kKindCount; ++b)
            if (t.distance[a][b]) out.append(py::make_tuple(kind_name(a), kind_name(b)));
        return out;
      },
      "The (kind, kind) pairs that have a query (used by circledist.Scene).");
  m.def(
      "_count_culled", [](std::uint64_t n) { stats().culled += n; }, py::arg("n"),
      "Adds n to stats()['culled'] (used by circledist.Scene).");
}

}  // namespace circledist::python
