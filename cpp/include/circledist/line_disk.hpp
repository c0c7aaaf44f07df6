// Forwards to linear_disk.hpp: the line, ray and segment against a disk now live there. Kept for
// one release; include the new headers instead.
#pragma once

#include "linear_disk.hpp"
