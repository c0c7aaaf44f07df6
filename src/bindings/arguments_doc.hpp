// The docstrings' parameter sections shared by the query functions (queries_doc.hpp,
// effects_doc.hpp, all_pairs_doc.hpp): the two shapes, the limit d, the arithmetic (precision,
// solver, workers), progress, and the errors every query raises.
#pragma once

namespace circledist::python::doc {

inline const char* const kQueryParameters = R"(a, b : Shape or array_like
    The two shapes (sweeps included). An array of shape (3,) or (..., 3) is a `Point`. Their
    batch shapes broadcast like NumPy's.
)";
inline const char* const kLimitParameter = R"(d : array_like
    Finite distance limits >= 0, a scalar or an array broadcasting with the batch shapes of a
    and b.
)";
inline const char* const kChoiceParameters = R"(precision : {None, 'float32', 'float64', 'longdouble'}, optional
    Keyword only. The arithmetic of the query. None follows the inputs: long double when any
    field was given as ``numpy.longdouble``, float32 when every one was float32, float64
    otherwise. 'float32' rounds the inputs to float32 (a value beyond its range is a
    ValueError), solves in double and rounds the answer to float32; 'longdouble' reads
    ``numpy.longdouble`` fields unrounded. ('float', 'double', 'long double' and 'float128'
    are accepted as aliases.)
solver : {None, 'default', 'bracketing', 'companion', 'polished', 'eigen'}, optional
    Keyword only. The polynomial root policy: 'bracketing' (the default, also None and
    'default') isolates real roots by derivative bracketing; 'companion' solves the balanced
    companion matrix (Eigen's scheme without eigenvectors); 'polished' adds Newton steps and a
    bracketed minimization to it; 'eigen' is Eigen's PolynomialSolver as it is. Closed-form
    pairs give the same answer with every solver.
workers : int, optional
    Keyword only. Threads that answer a batch, in chunks, the GIL released (SciPy's
    convention): a positive count (an int or a NumPy integer; not a bool), or -1 for every
    core; default 1. The answers are the same bits for any count, and stats() counts every
    thread's work. Ctrl-C stops a long batch (KeyboardInterrupt).
)";
inline const char* const kProgressParameter = R"(progress : bool or callable, optional
    Keyword only. None or False (the default): no report. True: a progress bar on stderr
    (tqdm's when it is installed), shown once the work has taken a second. A callable is called
    as ``progress(done, total)`` with the elements answered so far, about every 0.1 s while a
    batch runs and once with ``(total, total)`` at the end (``(1, 1)`` for two single shapes);
    an exception it raises stops the work and propagates.
)";
inline const char* const kQueryRaises = R"(Raises
------
ValueError
    For an unknown precision or solver, batch shapes that do not broadcast, an invalid
    array-like given as a point, (float32) an input beyond float32's range, or a worker count
    that is neither positive nor -1.
TypeError
    When there is no query between the two kinds (every pair of this module's kinds has one),
    or `progress` is neither None, a bool nor a callable.
)";

}  // namespace circledist::python::doc
