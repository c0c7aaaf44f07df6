// Forwards to point_arc.hpp, linear_arc.hpp, circle_arc.hpp, disk_arc.hpp, arc_arc.hpp: the arc
// pairs now live there. Kept for one release; include the new headers instead.
#pragma once

#include "point_arc.hpp"
#include "linear_arc.hpp"
#include "circle_arc.hpp"
#include "disk_arc.hpp"
#include "arc_arc.hpp"
