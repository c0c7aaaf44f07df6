// What the translation units of the bindings share: each binds one topic of the module (its
// functions and their docstrings, *_doc.hpp), and module.cpp calls them in this order, the order
// the module's names are defined in. Behind them: the arguments' readers (arguments.hpp), the
// calls into the kernels (calls.hpp, float32.hpp) and the signatures' types (types.hpp).
#pragma once

#include "arguments.hpp"
#include "float32.hpp"
#include "types.hpp"

namespace circledist::python {

// The classes: Shape, each kind's class (shapes.cpp).
void bind_shapes(py::module_& m);
// ClosestPoints, distance, closest_points (queries.cpp).
void bind_queries(py::module_& m);
// intersects, within, distance_if_within, the work counters (effects.cpp).
void bind_effects(py::module_& m);
// Every kind's fields and their roles, for the Python side (shapes.cpp).
void bind_shape_fields(py::module_& m);
// pairs_within, nearest, circledist.Scene's broadphase (all_pairs.cpp).
void bind_all_pairs(py::module_& m);
// The argument readers, for the Python side's arguments (arguments.cpp).
void bind_arguments(py::module_& m);
// Motion, Shape.moved (motion.cpp).
void bind_motion(py::module_& m);

// distance() of two shapes already read, reporting to `progress` (queries.cpp; also the all-pairs
// queries' kernel, which reports its progress elsewhere).
py::object shapes_distance(const Shape& a, const Shape& b, const Choice& c, py::handle progress);

// within() (a bool per element) or, with `want_distance`, distance_if_within() (the distance,
// inf beyond the limit d), over the broadcast of two shapes already read and `limit`, reporting to
// `progress` (effects.cpp; also the scene's all-pairs kernel).
py::object shapes_within(const Shape& a, const Shape& b, const Shape& limit, bool want_distance, const Choice& c,
                         py::handle progress);

// The limits d of within(), a batch of scalars >= 0 broadcast with both shapes (effects.cpp).
Shape limit_shape(const char* owner, py::handle d);

}  // namespace circledist::python
