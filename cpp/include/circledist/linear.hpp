// Forwards to detail/linear.hpp: the linear pieces and their round machinery now live there. Kept
// for one release; include the new headers instead.
#pragma once

#include "detail/linear.hpp"
