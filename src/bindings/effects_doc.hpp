// The docstrings of the effects (intersects, within, distance_if_within) and the work counters
// (stats, reset_stats), bound by effects.cpp. NumPy-style; their examples run as doctests
// (tests/package/test_docstrings.py).
#pragma once

#include "arguments_doc.hpp"

#include <string>

namespace circledist::python::doc {

inline const char* kIntersects() {
  static const std::string text = std::string() +
                                  "Whether a and b touch or overlap (sweeps included): ``within(a, b, 0)``.\n\n"
                                  "Cheap exact bounds decide first; the polynomial solver runs only where they "
                                  "cannot.\n\n"
                                  "Parameters\n----------\n" +
                                  kQueryParameters + kChoiceParameters + kProgressParameter + R"(
Returns
-------
bool or numpy.ndarray
    A bool for two single shapes, a bool array of the broadcast batch shape otherwise.

)" + kQueryRaises + R"(
Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> cd.intersects(ring, cd.Disk([0, 0, 0], [1, 0, 0], 2.0))  # the disk cuts through the ring
True
>>> cd.intersects(ring, [[0, 0, 0], [1, 0, 0]])
array([False,  True])
)";
  return text.c_str();
}

inline const char* kWithin() {
  static const std::string text = std::string() +
                                  "Whether distance(a, b) <= d.\n\n"
                                  "Up to a rounding tolerance of 64 eps times the pair's size. Cheap exact bounds "
                                  "decide first; the polynomial solver runs only where they cannot.\n\n"
                                  "Parameters\n----------\n" +
                                  kQueryParameters + kLimitParameter + +kChoiceParameters + kProgressParameter + R"(
Returns
-------
bool or numpy.ndarray
    A bool when a, b and d are single, otherwise a bool array of their broadcast shape.

)" + kQueryRaises + R"(    Also ValueError when d is negative, NaN, inf or not a real number.

Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> line = cd.Line([-3, 1, 0.5], [1, 0, 0])  # 0.5 from the ring
>>> cd.within(line, ring, 0.5)
True
>>> cd.within(line, ring, [0.4, 0.6])
array([False,  True])
)";
  return text.c_str();
}

inline const char* kDistanceIfWithin() {
  static const std::string text = std::string() +
                                  "``distance(a, b)`` where ``within(a, b, d)`` holds, inf elsewhere.\n\n"
                                  "The distance is only computed where the bounds cannot show that it exceeds d.\n\n"
                                  "Parameters\n----------\n" +
                                  kQueryParameters + kLimitParameter + kChoiceParameters + kProgressParameter + R"(
Returns
-------
float or numpy.ndarray
    As `distance`, with inf where the distance exceeds d.

)" + kQueryRaises + R"(    Also ValueError when d is negative, NaN, inf or not a real number.

Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> line = cd.Line([-3, 1, 0.5], [1, 0, 0])
>>> cd.distance_if_within(line, ring, [0.4, 0.6])
array([inf, 0.5])
)";
  return text.c_str();
}

inline const char* const kStats = R"(The calling thread's work counters since the last `reset_stats`.

Returns
-------
dict of str to int
    ``solves`` (polynomial solves), ``distances`` (exact distance evaluations),
    ``closest_points``, ``within`` (within and intersects pair tests), ``decided_by_bounds``
    (of those, decided by cheap bounds without an exact distance) and ``culled`` (pairs a
    `Scene`'s hierarchy skipped).

Examples
--------
>>> import circledist as cd
>>> ring = cd.Circle([0, 0, 0], [0, 0, 1], 1.0)
>>> cd.reset_stats()
>>> cd.intersects(ring, cd.Circle([5, 5, 5], [0, 0, 1], 1.0))  # far apart: the bounds decide
False
>>> cd.intersects(ring, cd.Circle([0.5, 0, 0], [0, 1, 1], 1.0))  # close: an octic is solved
False
>>> s = cd.stats()
>>> s["within"], s["decided_by_bounds"], s["distances"], s["solves"]
(2, 1, 1, 1)
)";

inline const char* const kResetStats = R"(Sets every counter of `stats` to 0 (the calling thread's).

Returns
-------
None

Examples
--------
>>> import circledist as cd
>>> _ = cd.distance([0, 0, 0], [1, 0, 0])
>>> cd.reset_stats()
>>> set(cd.stats().values())
{0}
)";

}  // namespace circledist::python::doc
