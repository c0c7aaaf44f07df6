"""circledist's shared test and benchmark cases, and the references they are checked against.

Not part of the installed package (neither the wheel nor the sdist holds it): the tests import it
through pytest's ``pythonpath`` (pyproject.toml), the benchmarks and tools run from the
repository's root as modules (``python -m bench.accuracy_vs_time``, ``python -m tools.differential``).

    scenes           hard and random linear-round scenes of the accuracy and validation tests
    accuracy         every query kind's value layout, placement, hard scenes and random cases, and
                     their 50-digit references (bench/accuracy_vs_time.py, the stability sweeps)
    sweeps           the stability sweeps: one-parameter families walking toward a degeneracy
    reference        50-digit references of linear shapes against circles and disks (mpmath)
    reference_round  50-digit references of circle, disk and Bezier kinds (mpmath)
    differential     the differential test's case families, fast screen and checker
    shapes           random shapes of every kind, from the module's table of fields
"""
