// circledist: the whole library. Every query family (queries.hpp), swept shapes (sweep.hpp), the
// cheap distance bounds (bounds.hpp) and the effects within, intersects and distance_if_within
// with their work counters (effects.hpp). Include a family header alone to compile less: each
// public header compiles on its own (cpp/tests/CMakeLists.txt checks that).
#pragma once

#include "queries.hpp"
#include "sweep.hpp"
#include "bounds.hpp"
#include "effects.hpp"
