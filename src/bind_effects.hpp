// Python bindings of the requested effects (cpp/include/circledist/effects.hpp): intersects,
// within, distance_if_within over broadcast batches, and the work counters. Every pair goes
// through the one PairKernels template (pairs.hpp), like distance and closest_points.
// Included by _core.cpp after its helpers (pairs(), run_within()).
#pragma once

#include "calls.hpp"

#include <pybind11/typing.h>

#include <string>

namespace {

// The limits d of within(), a batch of scalars >= 0 broadcast with both shapes.
Shape limit_shape(const char* owner, py::handle d) {
  return Shape(kPoint, {make_field(owner, "d", d, 1, Check::NonNegative)});
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

inline void bind_effects(py::module_& m) {
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
      [](ShapeLike a, ShapeLike b, ArrayLike d, PrecisionName precision, SolverName solver, Count workers, ProgressLike progress) {
        return Flags(run_within(a, b, limit_shape("within", d), false, precision, solver, workers, progress));
      },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kWithin());
  m.def(
      "distance_if_within",
      [](ShapeLike a, ShapeLike b, ArrayLike d, PrecisionName precision, SolverName solver, Count workers, ProgressLike progress) {
        return Distances(run_within(a, b, limit_shape("distance_if_within", d), true, precision, solver, workers, progress));
      },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1, py::arg("progress") = py::none(), doc::kDistanceIfWithin());
  m.def("stats", &stats_dict,
        doc::kStats);
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
