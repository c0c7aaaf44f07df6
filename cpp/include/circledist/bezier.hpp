// Forwards to bezier_circle.hpp, bezier_disk.hpp: Bezier-circle and Bezier-disk now live there.
// Kept for one release; include the new headers instead.
#pragma once

#include "bezier_circle.hpp"
#include "bezier_disk.hpp"
