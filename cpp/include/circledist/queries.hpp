// Every query family: the shapes, the symmetric front end (query.hpp) and one header per pair
// family, closed forms and polynomial solvers alike. sweep.hpp builds on this; circledist.hpp is
// this plus the swept shapes and the effects.
#pragma once

#include "primitives.hpp"
#include "query.hpp"
#include "point_circle.hpp"
#include "point_disk.hpp"
#include "linear_linear.hpp"
#include "line_circle.hpp"
#include "line_disk.hpp"
#include "circle_circle.hpp"
#include "circle_disk.hpp"
#include "disk_disk.hpp"
#include "bezier.hpp"
#include "bezier_point.hpp"
#include "bezier_linear.hpp"
#include "bezier_bezier.hpp"
#include "arc.hpp"
#include "annulus.hpp"
#include "bezier_arc.hpp"
