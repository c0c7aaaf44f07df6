// circledist: the whole library. Every pair header (all_pairs.hpp; the front end is query.hpp),
// swept shapes (sweep.hpp), the cheap distance bounds (bounds.hpp), the effects within, intersects
// and distance_if_within with their work counters (effects.hpp), the broadphase over bounding
// volumes (broadphase.hpp), and rigid motions with the first contact of moving shapes
// (motion.hpp) and their closest approach (closest_approach.hpp). Include a family header alone
// to compile less: each public header compiles on its own (cpp/tests/CMakeLists.txt checks that).
#pragma once

#include "all_pairs.hpp"
#include "sweep.hpp"
#include "bounds.hpp"
#include "effects.hpp"
#include "broadphase.hpp"
#include "motion.hpp"
#include "closest_approach.hpp"
