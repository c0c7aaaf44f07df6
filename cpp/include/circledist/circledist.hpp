// circledist: every query of the library. Include a family header alone to compile less.
#pragma once

#include "primitives.hpp"
#include "query.hpp"
#include "point_circle.hpp"
#include "point_disk.hpp"
#include "line_circle.hpp"
#include "line_disk.hpp"
#include "circle_circle.hpp"
#include "circle_disk.hpp"
#include "disk_disk.hpp"
#include "bezier.hpp"
