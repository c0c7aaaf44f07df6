// Forwards to point_annulus.hpp, linear_annulus.hpp, circle_annulus.hpp, disk_annulus.hpp,
// arc_annulus.hpp, bezier_annulus.hpp, annulus_annulus.hpp: the annulus pairs now live there. Kept
// for one release; include the new headers instead.
#pragma once

#include "point_annulus.hpp"
#include "linear_annulus.hpp"
#include "circle_annulus.hpp"
#include "disk_annulus.hpp"
#include "arc_annulus.hpp"
#include "bezier_annulus.hpp"
#include "annulus_annulus.hpp"
