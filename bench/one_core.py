"""Imported before NumPy by every benchmark: one BLAS thread, as the targets are stated for one
core. NumPy's BLAS threads would otherwise spin beside the timed thread after any BLAS call (and
on a 2-core machine take the other core)."""

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")
