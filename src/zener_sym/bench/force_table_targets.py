"""Speed targets of the force-free end's tables and the inverse (issue 24), measured side by
side in one run: the force-free end against the plate end on the same grids, and the lookup
table and ``lam_from_summary`` against a one-second budget (the issue's "well under a second",
read as at most half of it)."""
from __future__ import annotations

from typing import Any

import numpy as np

from .timing import alternating_median_times, median_time

#: The budget of the absolute targets, seconds; ratio = budget / time, required >= 2.
BUDGET_S = 1.0


def summary_force_vs_plate(n: int = 2000) -> dict[str, Any]:
    """Summaries of n lambda over [0, 1000] (half linear on [0, 5], half geometric above) from
    the force-end tables against the plate's; ratio = plate time / force time (within 2x:
    required >= 0.5)."""
    import zener_sym as zs

    lams = np.concatenate([np.linspace(0.0, 5.0, n // 2), np.geomspace(5.0, 1000.0, n - n // 2)])
    t_plate, t_force = alternating_median_times(
        [lambda: zs.summary(lams), lambda: zs.summary(lams, contact_end="force")])
    return {"target": "exact summary, force-free end vs plate end (tables)",
            "grid": f"{n} lambda in [0, 1000]", "fast_s": t_force, "slow_s": t_plate,
            "ratio": t_plate / t_force, "required": 0.5}


def history_force_vs_plate(m: int = 200, k: int = 500) -> dict[str, Any]:
    """Histories of m lambda in [0, 5] x k tau over 1.05 of each end's own contact, force-free
    end against the plate end; ratio = plate time / force time (required >= 0.5)."""
    import zener_sym as zs

    lams = np.linspace(0.0, 5.0, m)
    s = np.linspace(0.0, 1.05, k)
    tau_p = zs.summary(lams).tau_d[:, None] * s
    tau_f = zs.summary(lams, contact_end="force").tau_d[:, None] * s
    t_plate, t_force = alternating_median_times(
        [lambda: zs.history(lams[:, None], tau_p),
         lambda: zs.history(lams[:, None], tau_f, contact_end="force")])
    return {"target": "exact history (every field), force-free end vs plate end (tables)",
            "grid": f"{m} lambda x {k} tau", "fast_s": t_force, "slow_s": t_plate,
            "ratio": t_plate / t_force, "required": 0.5}


def lookup_table_force(n: int = 1001) -> dict[str, Any]:
    """``zener-sym table --contact-end force`` (its ``lookup_table`` and CSV text) for n lambda
    on [0, 5] against the budget; ratio = budget / time (required >= 2)."""
    from ..scene.lookup import lookup_csv, lookup_table

    def run() -> str:
        return lookup_csv(lookup_table(("e", "tau_d", "F_m"), f"0:5:{n}", contact_end="force"))

    t = median_time(run, min_repeats=3, min_total=0.2)
    return {"target": "zener-sym table --contact-end force (e, tau_d, F_m; CSV)",
            "grid": f"{n} lambda", "fast_s": t, "slow_s": BUDGET_S, "ratio": BUDGET_S / t,
            "required": 2.0}


def lam_for_target(n: int = 100_000, quick: bool = False) -> list[dict[str, Any]]:
    """``lam_from_summary(e=...)`` on n restitution values spread over each end's reachable
    range, against the budget; ratio = budget / time (required >= 2)."""
    import zener_sym as zs
    from ..exact import inverse

    rows = []
    for end in ("delta", "force"):
        lo = inverse.reachable("e", end)[0]
        e = np.exp(np.random.default_rng(24).uniform(np.log(lo), 0.0, n))
        t = median_time(lambda: zs.lam_from_summary(e=e, contact_end=end),
                        min_repeats=1 if quick else 3, min_total=0.0 if quick else 0.2)
        rows.append({"target": f"lam_from_summary(e=...), contact_end={end!r}",
                     "grid": f"{n} values",
                     "fast_s": t, "slow_s": BUDGET_S, "ratio": BUDGET_S / t, "required": 2.0})
    return rows


def run(quick: bool = False) -> list[dict[str, Any]]:
    rows = [summary_force_vs_plate(), history_force_vs_plate(), lookup_table_force(),
            *lam_for_target(quick=quick)]
    for r in rows:
        r["met"] = r["ratio"] >= r["required"]
    return rows
