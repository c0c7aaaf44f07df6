// The compiled part of circledist, circledist._core: shape classes, and distance, closest_points,
// the effects and the all-pairs queries over every registered pair of kinds. Each topic is bound
// by a translation unit of its own (module.hpp lists them); here they are called in the order the
// module's names are defined in.
#include "module.hpp"

#include <pybind11/pybind11.h>

namespace py = pybind11;
using namespace circledist::python;

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "circledist: exact distances and closest points between circles, disks, arcs, annuli, lines, rays, segments, points "
      "and Bezier curves in 3D";
  m.attr("__version__") = CIRCLEDIST_VERSION;  // CMakeLists.txt's project() version

  bind_shapes(m);
  bind_queries(m);
  bind_effects(m);
  bind_shape_fields(m);
  bind_all_pairs(m);
  bind_arguments(m);
  bind_motion(m);
}
