"""Speed target of the calibration (issue 24): fitting A to measured (v0, e) pairs on the
tables costs less than integrating the data's lambda values once.

``zener-sym bench`` reports :func:`run` among the speed targets.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from ..exact import solver as exact
from .timing import median_time


def fit_target(n: int = 20) -> dict[str, Any]:
    """``zs.fit_dissipation`` of n noisy pairs (glass bead on steel, A = 3e-7 s, v0 from 0.1 to
    10 m/s, noise 0.01 in e, plate end: tables) against one per-lambda scipy DOP853 solve
    (rtol 1e-10) of the same n lambda, the pre-table way to evaluate e at the data once; ratio =
    loop time / fit time (required >= 5)."""
    import zener_sym as zs
    from zener_sym.scene.grains import grain_contact

    v0 = np.geomspace(0.1, 10.0, n)
    c = grain_contact("glass", "1 mm", 1e-5, wall="steel")
    # an array for the array v0 (asarray: the signature says float or array)
    lam = np.asarray(zs.lam_from_dissipation(3e-7, c.rho, c.m_eff, v0), dtype=np.float64)
    e = zs.summary(lam, model="exact").e + np.random.default_rng(24).normal(0.0, 0.01, n)
    def fit() -> object:
        return zs.fit_dissipation("glass", "1 mm", 1e-5, v0=v0, e=e, wall="steel",
                                  contact_end="delta")

    fit()  # warm-up outside the timing: the first fit imports scipy.optimize and scipy.stats
    t_fit = median_time(fit, min_repeats=3, min_total=0.2)
    t_loop = median_time(lambda: [exact.solve(x, rtol=1e-10) for x in lam], min_repeats=1,
                         min_total=0.0)
    return {"target": "fit_dissipation of A (tables) vs one per-lambda scipy DOP853 pass over "
                      "the data's lambda, rtol 1e-10",
            "grid": f"{n} (v0, e) pairs", "fast_s": t_fit, "slow_s": t_loop,
            "ratio": t_loop / t_fit, "required": 5.0}


def run(quick: bool = False) -> list[dict[str, Any]]:
    rows = [fit_target()]
    for r in rows:
        r["met"] = r["ratio"] >= r["required"]
    return rows
