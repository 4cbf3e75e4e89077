"""Speed targets of the fast exact model (issue 8), measured side by side in one run."""
from __future__ import annotations

import numpy as np

from .. import exact
from .timing import median_time


def run(quick: bool = False) -> list[dict]:
    import zener_sym as zs

    rows = []
    lams = np.linspace(0.0, 5.0, 2000)
    # the loop is timed on every lambda, or in --quick on an evenly spread subset, per lambda
    sub = lams if not quick else lams[::40]
    t_fast = median_time(lambda: zs.summary(lams, model="exact"), min_repeats=5, min_total=0.2)
    t_loop = median_time(lambda: [exact.solve(x, rtol=1e-10) for x in sub], min_repeats=1,
                         min_total=0.0) * len(lams) / len(sub)
    rows.append({"target": "exact summary (tables) vs per-lambda scipy DOP853 with events, rtol 1e-10",
                 "grid": f"2000 lambda in [0, 5] (loop timed on {len(sub)})", "fast_s": t_fast,
                 "slow_s": t_loop, "ratio": t_loop / t_fast, "required": 50.0})
    hl = np.linspace(0.0, 5.0, 200)
    tau_d = zs.summary(hl, model="exact").tau_d
    tau = tau_d[:, None] * np.linspace(0.0, 1.0, 200)[None, :]
    hsub = np.arange(0, 200, 1 if not quick else 8)
    t_fast = median_time(lambda: zs.history(hl[:, None], tau, model="exact").force, min_repeats=3,
                         min_total=0.2)
    t_loop = median_time(lambda: [exact.solve(hl[i], rtol=1e-8).history(tau[i]) for i in hsub],
                         min_repeats=1, min_total=0.0) * len(hl) / len(hsub)
    rows.append({"target": "exact history (tables) vs per-lambda scipy DOP853 loop, rtol 1e-8",
                 "grid": f"200 lambda x 200 tau (loop timed on {len(hsub)} lambda)",
                 "fast_s": t_fast, "slow_s": t_loop, "ratio": t_loop / t_fast, "required": 20.0})
    for r in rows:
        r["met"] = r["ratio"] >= r["required"]
    return rows
