// Forwards to all_pairs.hpp: every pair header now live there. Kept for one release; include the
// new headers instead.
#pragma once

#include "all_pairs.hpp"
