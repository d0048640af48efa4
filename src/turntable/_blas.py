"""One BLAS thread per process, for the command line and the benchmarks (Snakemake gives each
job as many as its rule's threads, one here).

Every matrix here is small (6x6, or a Jacobian of some thousand rows and ten columns): BLAS
threads only wait for each other, and on a busy machine of 2 cores a tracking takes twice as
long with two of them.  An explicit setting in the environment wins.
"""

from __future__ import annotations

import os

BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def one_blas_thread() -> None:
    """Limit this process's BLAS to one thread, unless the environment sets a number.

    With none of `BLAS_THREAD_VARIABLES` set, each is set to 1 (for the commands this process
    starts and for the libraries loaded later, which read them) and the BLAS libraries already
    loaded are limited to one thread (`threadpoolctl.threadpool_limits`, with the extra
    ``cli``); the limit holds until the process ends.
    """
    if any(var in os.environ for var in BLAS_THREAD_VARIABLES):
        return
    for var in BLAS_THREAD_VARIABLES:
        os.environ[var] = "1"
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # numpy alone: the variables hold for what is loaded later
        return
    threadpool_limits(limits=1, user_api="blas")
