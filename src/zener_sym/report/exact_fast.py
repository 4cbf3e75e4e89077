"""Report section of the fast exact model: its range, bounds, a live check and a speed ratio."""
from __future__ import annotations

import time

import numpy as np


def section() -> str:
    """The report's markdown: range, documented bounds, a live check against the solver and
    the speed of 2000 summaries from the tables against one solve."""
    from ..exact import solver as exact, table as exact_fast
    from ..api import summary
    from .format import PAPER_LAMBDAS, fmt, markdown_table

    lams = np.array(PAPER_LAMBDAS + (3.3, 4.9))
    t0 = time.perf_counter()
    sols = [exact.solve(x, rtol=1e-13) for x in lams]
    t_int = (time.perf_counter() - t0) / len(lams)
    s = summary(lams, model="exact")
    rows: list[list[str]] = []
    for i, (x, r) in enumerate(zip(lams, sols)):
        errs = [abs(getattr(s, f)[i] / getattr(r, f) - 1)
                for f in ("delta_m", "tau_dc", "tau_d", "e", "int_F2")]
        rows.append([fmt(x, 4), fmt(s.tau_d[i]), fmt(s.e[i]), f"{max(errs):.1e}"])
    big = np.linspace(exact_fast.LAM_MIN, exact_fast.LAM_MAX, 2000)
    best = np.inf
    for _ in range(3):
        t0 = time.perf_counter()
        summary(big, model="exact")
        best = min(best, time.perf_counter() - t0)
    return (
        "## Fast exact model (Chebyshev tables)\n\n"
        f"Default of `model=\"exact\"`: summaries for {exact_fast.LAM_MIN:g} <= lambda <= "
        f"{exact_fast.LAM_MAX:g}, histories for lambda <= {exact_fast.HISTORY_LAM_MAX:g}"
        + (" (histories beyond are integrated)" if exact_fast.HISTORY_LAM_MAX < exact_fast.LAM_MAX
           else "") + ". Documented bounds: summary fields "
        f"{exact_fast.SUMMARY_RTOL:g} relative, history {exact_fast.HISTORY_ATOL:g} of each "
        "field's scale. Live check against the scipy solver at rtol 1e-13 (worst relative error "
        "of delta_m, tau_dc, tau_d, e, int_F2):\n\n"
        + markdown_table(["lambda", "tau_d", "e", "worst rel. error"], rows)
        + f"\n\n2000 lambda from the tables: {best * 1e3:.2f} ms; one scipy solve (rtol 1e-13) "
        f"took {t_int * 1e3:.1f} ms here, so about {t_int * 2000 / best:.0f}x (the side-by-side "
        "benchmark is `python benchmarks/bench_exact_fast.py`)."
    )
