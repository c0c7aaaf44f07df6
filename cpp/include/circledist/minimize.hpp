// Forwards to detail/minimize.hpp: the candidate polishing now live there. Kept for one release;
// include the new headers instead.
#pragma once

#include "detail/minimize.hpp"
