"""All benchmarks of the closed forms in `turntable`, one topic per script.

``eigenvalues`` (benchmarks/eigenvalues.py)
    Worst relative error of alpha1, alpha2 and beta over a (mu0, k) grid, for
    `turntable.eigenvalues`, numpy's eigensolver and the textbook double-precision form,
    against a high-precision evaluation of (2.4).
``solution`` (benchmarks/solution.py)
    Worst error of `turntable.solve` against the mpmath matrix exponential; robustness
    over mu0 in [1e-12, 1e12] and t in [0, 1000]; `modal_terms` against `solve`.
``speed`` (benchmarks/speed.py)
    Run time of `turntable.solve` against scipy's solve_ivp and expm, with their errors.
``fit`` (benchmarks/fit.py)
    Time of one fit of a film (`turntable.fit`, the command ``turntable fit``); coverage of
    the reported standard errors and accuracy of the model selection over random films.

The build time of the workflow is measured separately by ``benchmarks/pipeline.py``.
The references are those of `turntable.reference`.

Run ``python benchmarks/run.py`` (``make bench`` runs it, then ``pipeline.py``);
``--quick`` uses smaller grids, ``--sections`` runs some of the topics.  A table is
printed and the sections are merged into the JSON file given by ``--out`` (other
top-level keys in it are kept).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _common
import eigenvalues
import fit
import solution
import speed
from turntable._blas import one_blas_thread

#: The topics, in the order they run.
TOPICS = (eigenvalues, solution, speed, fit)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the benchmarks; return 0 (the pass/fail verdicts are in the output)."""
    argv = sys.argv[1:] if argv is None else argv
    return _common.main(TOPICS, __file__, __doc__.splitlines()[0], argv)


if __name__ == "__main__":
    one_blas_thread()
    sys.exit(main())
