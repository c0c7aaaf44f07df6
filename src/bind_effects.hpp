// Python bindings of the requested effects (cpp/include/circledist/effects.hpp): intersects,
// within, distance_if_within over broadcast batches, and the work counters. Every pair goes
// through the one PairKernels template (pairs.hpp), like distance and closest_points.
// Included by _core.cpp after its helpers (pairs(), run_within()).
#pragma once

#include "calls.hpp"

#include <string>

namespace {

// The limits d of within(), a batch of scalars >= 0 broadcast with both shapes.
Shape limit_shape(const char* owner, py::handle d) {
  return Shape(kPoint, {make_field(owner, "d", d, 1, Check::NonNegative)});
}

py::dict stats_dict() {
  const Stats& s = stats();
  py::dict out;
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
      [](py::handle a, py::handle b, py::object precision, py::object solver, int workers) {
        static const Shape* zero = new Shape(kPoint, {default_sweep()});  // d = 0 (a shared 0-d zero)
        return run_within(a, b, *zero, false, precision, solver, workers);
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("precision") = py::none(), py::arg("solver") = py::none(),
      py::arg("workers") = 1,
      "Whether a and b touch or overlap (sweeps included): within(a, b, 0). Cheap exact bounds decide first; "
      "the polynomial solver runs only where they cannot. A bool, or a bool array of the broadcast batch shape.");
  m.def(
      "within",
      [](py::handle a, py::handle b, py::handle d, py::object precision, py::object solver, int workers) {
        return run_within(a, b, limit_shape("within", d), false, precision, solver, workers);
      },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1,
      "Whether distance(a, b) <= d (d >= 0, up to a rounding tolerance of 64 eps times the pair's size). Cheap "
      "exact bounds decide first; the polynomial solver runs only where they cannot. d broadcasts with a and b.");
  m.def(
      "distance_if_within",
      [](py::handle a, py::handle b, py::handle d, py::object precision, py::object solver, int workers) {
        return run_within(a, b, limit_shape("distance_if_within", d), true, precision, solver, workers);
      },
      py::arg("a"), py::arg("b"), py::arg("d"), py::kw_only(), py::arg("precision") = py::none(),
      py::arg("solver") = py::none(), py::arg("workers") = 1,
      "distance(a, b) where within(a, b, d) holds, inf elsewhere; the distance is only computed where the bounds "
      "cannot show that it exceeds d.");
  m.def("stats", &stats_dict,
        "The calling thread's work counters: solves (polynomial solves), distances (exact distance evaluations), "
        "closest_points, within (within/intersects pair tests), decided_by_bounds (of those, decided without "
        "a solve), culled (pairs a Scene's broadphase skipped).");
  m.def("reset_stats", &reset_stats, "Sets every counter of stats() to 0.");
  m.def(
      "_query_kinds",
      [] {
        const PairTable<double>& t = pairs().of<double>(pairs().default_solver);
        py::list out;
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
