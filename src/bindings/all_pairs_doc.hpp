// The docstrings of the all-pairs queries, pairs_within and nearest (bound by all_pairs.cpp).
// NumPy-style; their examples run as doctests (tests/package/test_docstrings.py).
#pragma once

#include "arguments_doc.hpp"

#include <string>

namespace circledist::python::doc {

inline const char* const kAllPairsNotes = R"(Notes
-----
Each batch is indexed flat, in C order: element ``i`` of a batch of shape (2, 3) is the one at
``numpy.unravel_index(i, (2, 3))``; a single shape is a batch of one. Fields that broadcast
within a shape (one radius for many centers) count once per element.

A bounding-volume hierarchy (the C++ header ``circledist/broadphase.hpp``) culls the pairs that
cheap exact lower bounds (boxes, balls, the distance from a line to a ball) put beyond d plus a
margin of ``sqrt(eps) * (d + 2 * scale)`` (scale: how far the pair's two shapes reach from the
origin, the farther of them, so that a far or huge shape widens only its own pairs' margins;
float32's eps for float32 answers): no pair the exact distance puts within d is culled. Lines
and rays are tested against every ball. Each remaining pair is gathered into a batch and
answered by the kernel `distance` runs, with the GIL released, on `workers` threads.
)";

// progress= of the all-pairs queries, whose work runs in stages.
inline const char* const kAllPairsProgressParameter = R"(progress : bool or callable, optional
    Keyword only. None or False (the default): no report. True: a progress bar on stderr
    (tqdm's when it is installed), shown once the work has taken a second. A callable is called
    as ``progress(done, total)`` about every 0.1 s and once with ``(total, total)`` at the end.
    The work runs in stages (the search for candidate pairs, then their exact distances; twice
    for `nearest`), each counted as ``len(a)`` steps: total is 2 ``len(a)`` for `pairs_within`,
    4 ``len(a)`` for `nearest`, and done never decreases. An exception it raises stops the work
    and propagates.
)";

// max_pairs= of pairs_within (and Scene.pairs_within, whose docstring says the same).
inline const char* const kMaxPairsParameter = R"(max_pairs : int or None, default 100_000_000
    Keyword only. The most candidate pairs (pairs the culling keeps: within d of each other,
    or within the margin of it, by their bounds) the call holds, each about 16 bytes, more
    while they are sorted and answered. The candidates are counted while they are found, and
    once more than max_pairs are, the search stops and MemoryError is raised, instead of
    memory running out on a d that pairs nearly everything. None: no limit.
)";

inline const char* kPairsWithin() {
  static const std::string text =
      std::string() +
      "Every pair of a and b within distance d of each other, with its distance.\n\n"
      "Exactly the pairs ``(i, j)`` for which ``distance(a[i], b[j]) <= d``, as a brute-force double loop\n"
      "over `distance` finds them, with the same distances to the bit; far fewer pairs are evaluated.\n"
      "Like ``scipy.spatial.cKDTree.query_pairs`` (b None) and ``sparse_distance_matrix`` (with b), for\n"
      "shapes.\n\n"
      "Parameters\n----------\n" +
      R"(a : Shape or array_like
    A batch of shapes of any kind and batch shape, indexed flat (see Notes). An array of shape
    (..., 3) is a `Point` batch.
b : Shape, array_like or None
    A second batch, indexed flat; None pairs a with itself, i < j (no pair of an element with
    itself).
d : float
    Distance limit, finite and >= 0. Pairs at distance exactly d are included.
)" + kChoiceParameters +
      kAllPairsProgressParameter + kMaxPairsParameter + R"(
Returns
-------
i, j : numpy.ndarray of numpy.intp, shape (m,)
    Flat indices into a and into b (into a twice when b is None, i < j), sorted by (i, j).
distance : numpy.ndarray, shape (m,)
    ``distance(a[i], b[j])`` for each pair: dtype float64, float32 or longdouble, by precision.
    With float32 answers the comparison with d is made in double on the float32 value, as a
    loop over single `distance` calls (which return Python floats) makes it.

Raises
------
TypeError
    When d is not a real number, a or b is not a shape or an array of points, there is no
    query between the kinds of a and b (even when no pair is near), or `progress` is neither
    None, a bool nor a callable.
ValueError
    When d is negative, NaN or inf, for an unknown precision or solver, a worker count that
    is neither positive nor -1, or a negative max_pairs.
MemoryError
    When more than max_pairs pairs are candidates (raised as soon as the search has counted
    them, before more memory is taken).

See Also
--------
nearest : the k nearest shapes of b to each shape of a.
Scene.pairs_within : the same culling over a scene's named shapes.

)" + kAllPairsNotes +
      R"(
Examples
--------
>>> import numpy as np
>>> import circledist as cd
>>> rings = cd.Circle([[0, 0, 0], [3, 0, 0], [9, 0, 0]], [0, 0, 1], 1.0)
>>> sticks = cd.Segment([[0, 0, -1], [5, 0, 0]], [[0, 0, 1], [6, 0, 0]])
>>> i, j, dist = cd.pairs_within(rings, sticks, 1.0)
>>> i, j, dist
(array([0, 1]), array([0, 1]), array([1., 1.]))
>>> cd.pairs_within(rings, None, 1.0)  # rings 0 and 1 are 1 apart
(array([0]), array([1]), array([1.]))
>>> cd.pairs_within(rings, sticks, -1)
Traceback (most recent call last):
...
ValueError: pairs_within: d must be a finite number >= 0, got -1
)";
  return text.c_str();
}

inline const char* kNearest() {
  static const std::string text =
      std::string() +
      "The k shapes of b nearest to each shape of a, with their distances.\n\n"
      "The same as sorting every ``distance(a[i], b[j])`` by (distance, j) and keeping the first k,\n"
      "with the same distances to the bit; far fewer pairs are evaluated. Like\n"
      "``scipy.spatial.cKDTree.query(x, k)``, for shapes (but indices first, and always two-dimensional).\n\n"
      "Parameters\n----------\n" +
      R"(a : Shape or array_like
    The query shapes: a batch of any kind and batch shape, indexed flat (see Notes).
b : Shape or array_like
    The shapes to search: a batch of any kind, indexed flat.
k : int, default 1
    How many nearest shapes per query, >= 1.
)" + kChoiceParameters +
      kAllPairsProgressParameter + R"(
Returns
-------
indices : numpy.ndarray of numpy.intp, shape (len(a), k)
    Flat indices into b, nearest first (ties: the smaller index first). Where b holds fewer than
    k shapes, the missing places are -1 (as in cKDTree, where they are len(b)).
distances : numpy.ndarray, shape (len(a), k)
    The distances, ascending; inf in the missing places. Dtype float64, float32 or longdouble,
    by precision.

Raises
------
TypeError
    When k or `workers` is not an integer (a bool is not), a or b is not a shape or an array of
    points, there is no query between their kinds, or `progress` is neither None, a bool nor a
    callable.
ValueError
    When k < 1 or k >= 2**63, for an unknown precision or solver, or a worker count that is
    neither positive nor -1.
MemoryError
    When the answers, two arrays of shape (len(a), k), do not fit in memory (the columns past
    len(b) are only -1 and inf: a k beyond len(b) costs their memory, nothing more).

See Also
--------
pairs_within : every pair within a distance.
Scene.nearest : the nearest named shapes of a scene to one shape.

)" + kAllPairsNotes +
      R"(
Examples
--------
>>> import circledist as cd
>>> rings = cd.Circle([[0, 0, 0], [3, 0, 0], [9, 0, 0]], [0, 0, 1], 1.0)
>>> probes = cd.Point([[0, 0, 0], [8, 0, 0]])
>>> idx, dist = cd.nearest(probes, rings, k=2)
>>> idx
array([[0, 1],
       [2, 1]])
>>> dist
array([[1., 2.],
       [0., 4.]])
>>> cd.nearest(probes, rings, k=4)[0]  # b holds 3 rings: the fourth place is empty
array([[ 0,  1,  2, -1],
       [ 2,  1,  0, -1]])
>>> cd.nearest(probes, rings, k=0)
Traceback (most recent call last):
...
ValueError: nearest: k must be an integer >= 1, got 0
)";
  return text.c_str();
}

}  // namespace circledist::python::doc
