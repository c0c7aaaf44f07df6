// Forwards to linear_circle.hpp: the line, ray and segment against a circle now live there. Kept
// for one release; include the new headers instead.
#pragma once

#include "linear_circle.hpp"
