"""One BLAS thread for the benchmarks of the closed forms.

Every matrix in these benchmarks is 6x6, and on a shared machine idle BLAS worker threads
left spinning by one method (Radau's LU) slow down the next one (batched expm) by up to
10x.  `one_blas_thread` is called only when a benchmark is run as a script, before numpy is
first imported; an explicit setting in the environment wins.
"""

from __future__ import annotations

import os

BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def one_blas_thread() -> None:
    """Set each of BLAS_THREAD_VARIABLES to 1 unless it is set already."""
    for var in BLAS_THREAD_VARIABLES:
        os.environ.setdefault(var, "1")
