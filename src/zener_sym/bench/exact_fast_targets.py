"""Speed targets of the fast exact model (issue 8), measured side by side in one run.

``zener-sym bench`` reports ``run()``; ``benchmarks/bench_exact_fast.py`` calls the same two
functions with its own grid sizes and adds an accuracy check.
"""
from __future__ import annotations

import numpy as np

from ..exact import solver as exact
from .timing import median_time


def summary_target(n: int = 2000, quick: bool = False) -> dict:
    """Summaries of n lambda in [0, 5] from the tables against a per-lambda ``exact.solve`` loop
    (DOP853 with events) at rtol 1e-10; the loop is timed on every lambda, or in --quick on an
    evenly spread subset, per lambda."""
    import zener_sym as zs

    lams = np.linspace(0.0, 5.0, n)
    sub = lams if not quick else lams[::40]
    t_fast = median_time(lambda: zs.summary(lams, model="exact"), min_repeats=5, min_total=0.2)
    t_loop = median_time(lambda: [exact.solve(x, rtol=1e-10) for x in sub], min_repeats=1,
                         min_total=0.0) * len(lams) / len(sub)
    return {"target": "exact summary (tables) vs per-lambda scipy DOP853 with events, rtol 1e-10",
            "grid": f"{n} lambda in [0, 5] (loop timed on {len(sub)})", "fast_s": t_fast,
            "slow_s": t_loop, "ratio": t_loop / t_fast, "required": 50.0}


def history_target(m: int = 200, k: int = 200, quick: bool = False) -> dict:
    """Histories of m lambda in [0, 5] x k tau across each contact from the tables against a
    per-lambda ``exact.solve(...).history`` loop at rtol 1e-8 (in --quick on every 8th lambda)."""
    import zener_sym as zs

    hl = np.linspace(0.0, 5.0, m)
    tau_d = zs.summary(hl, model="exact").tau_d
    tau = tau_d[:, None] * np.linspace(0.0, 1.0, k)[None, :]
    hsub = np.arange(0, m, 1 if not quick else 8)
    t_fast = median_time(lambda: zs.history(hl[:, None], tau, model="exact").force, min_repeats=3,
                         min_total=0.2)
    t_loop = median_time(lambda: [exact.solve(hl[i], rtol=1e-8).history(tau[i]) for i in hsub],
                         min_repeats=1, min_total=0.0) * len(hl) / len(hsub)
    return {"target": "exact history (tables) vs per-lambda scipy DOP853 loop, rtol 1e-8",
            "grid": f"{m} lambda x {k} tau (loop timed on {len(hsub)} lambda)",
            "fast_s": t_fast, "slow_s": t_loop, "ratio": t_loop / t_fast, "required": 20.0}


def run(quick: bool = False) -> list[dict]:
    rows = [summary_target(quick=quick), history_target(quick=quick)]
    for r in rows:
        r["met"] = r["ratio"] >= r["required"]
    return rows
