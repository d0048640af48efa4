"""One BLAS thread for the benchmarks of the closed forms.

Every matrix in these benchmarks is 6x6, and on a shared machine idle BLAS worker threads
left spinning by one method (Radau's LU) slow down the next one (batched expm) by up to
10x.  `one_blas_thread` is called when a benchmark is run as a script, numpy imported or
not (threadpoolctl limits the BLAS libraries already loaded); an explicit setting in the
environment wins.
"""

from __future__ import annotations

import os

BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def one_blas_thread() -> None:
    """Limit this process's BLAS to one thread, unless the environment sets a number.

    With none of `BLAS_THREAD_VARIABLES` set, each is set to 1 (for the commands that a
    benchmark starts and for the libraries loaded later, which read them) and the BLAS
    libraries already loaded are limited to one thread (`threadpoolctl.threadpool_limits`);
    the limit holds until the process ends.
    """
    from threadpoolctl import threadpool_limits

    if any(var in os.environ for var in BLAS_THREAD_VARIABLES):
        return
    for var in BLAS_THREAD_VARIABLES:
        os.environ[var] = "1"
    threadpool_limits(limits=1, user_api="blas")
