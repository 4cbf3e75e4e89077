"""Speed targets, as ratios measured side by side in one run (issue 6, item 4).

A target is a row (a dict): ``target`` and ``grid`` (what is compared, on what), ``fast_s`` and
``slow_s`` (the two times, seconds), ``ratio`` (slow / fast, or budget / time), ``required`` (the
least ratio that meets it) and, once checked, ``met``.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from ..models import REGISTRY
from .methods import dop853_force_loop
from .timing import median_time


def ham1_vs_dop853(n_lam: int = 200, n_tau: int = 200,
                   quick: bool = False) -> dict[str, Any] | None:
    """ham1 (numpy) force history on n_lam x n_tau against a per-lambda scipy DOP853 solve with
    dense output at rtol 1e-6 (the textbook set-up: tau from 0, guarded RHS, event delta = 0).

    Both sides give the force and nothing else: ham1 is asked for ``fields="force"`` (its contact
    end and delta, from the per-lambda series of ``zener_sym.ham.spectral``), as the comparator
    computes no impulse."""
    if "ham1" not in REGISTRY:
        return None
    import zener_sym as zs

    lams = np.linspace(0.0, 2.4, n_lam)
    s = np.linspace(0.0, 1.0, n_tau)
    tau = zs.summary(lams, model="ham0").tau_d[:, None] * 1.6 * s  # covers the first-order contact

    def fast() -> object:
        return zs.history(lams[:, None], tau, model="ham1", fields="force").force

    def loop() -> object:
        return dop853_force_loop(lams, tau)

    t_fast = median_time(fast, min_repeats=3 if not quick else 1, min_total=0.2)
    t_loop = median_time(loop, min_repeats=1, min_total=0.0)
    return {"target": "ham1 numpy force history vs per-lambda scipy DOP853 (rtol 1e-6, dense)",
            "grid": f"{n_lam} lambda x {n_tau} tau", "fast_s": t_fast, "slow_s": t_loop,
            "ratio": t_loop / t_fast, "required": 50.0}


def ham1_numpy_vs_mpmath(quick: bool = False) -> dict[str, Any] | None:
    """Per-point time of ham1 numpy (on a 200 x 200 grid) against ham1 mpmath (a few points)."""
    if "ham1" not in REGISTRY or "backend" not in REGISTRY["ham1"].options:
        return None
    import zener_sym as zs

    lams = np.linspace(0.0, 2.4, 200)[:, None]
    tau = np.linspace(0.0, 3.0, 200)[None, :]
    t_np = median_time(lambda: zs.history(lams, tau, model="ham1").force, min_repeats=3,
                       min_total=0.2) / (200 * 200)
    pts = np.array([0.3, 1.1, 2.0])
    t_mp = median_time(lambda: zs.history(1.01, pts, model="ham1", backend="mpmath").force,
                       min_repeats=1, min_total=0.0) / len(pts)
    return {"target": "ham1 numpy vs ham1 mpmath, per point", "grid": "200 x 200 vs 3 points",
            "fast_s": t_np, "slow_s": t_mp, "ratio": t_mp / t_np, "required": 1000.0}


def run(quick: bool = False) -> list[dict[str, Any]]:
    """Every speed target of the package, each row with ``met`` set."""
    rows = []
    for fn in (ham1_vs_dop853, ham1_numpy_vs_mpmath):
        r = fn(quick=quick)
        if r is not None:
            r["met"] = r["ratio"] >= r["required"]
            rows.append(r)
    from . import exact_fast_targets, force_table_targets  # import this module: when run

    rows += exact_fast_targets.run(quick=quick)
    rows += force_table_targets.run(quick=quick)
    from . import c_targets, calibrate_targets  # the fit of A; the emitted C kernels (issue 25)

    rows += calibrate_targets.run(quick=quick)
    rows += c_targets.run(quick=quick)
    from .lammps import method as lammps_method  # LAMMPS beside the tables, when installed

    rows += lammps_method.targets(quick=quick)
    from . import plate  # the finite-plate solver against DOP853 (issue 37)

    rows += plate.targets(quick=quick)
    return rows
