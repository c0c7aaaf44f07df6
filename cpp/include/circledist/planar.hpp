// Forwards to detail/planar.hpp: the round seen from its own frame now live there. Kept for one
// release; include the new headers instead.
#pragma once

#include "detail/planar.hpp"
