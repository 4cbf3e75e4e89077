"""Error of the fast exact model (tables) against the mpmath reference on a dense lambda grid.

    python benchmarks/exact_fast_error.py            # 101 lambda, dps 20 (about a minute)
    python benchmarks/exact_fast_error.py --n 25     # quicker
    python benchmarks/exact_fast_error.py --n 0 --large 8   # the tables on (5, 300] only

The grid lambda = 5 (i + 1/2) / n, i = 0..n-1, plus 0 and 5, is not aligned with the table's
Chebyshev nodes. For each lambda the reference is ``exact_mp.solve(lam, dps)``; the summary error
is relative per field (absolute for xi at lambda = 0, where xi = 0), the history error is the
largest difference on 400 times in [0, 1.02 tau_d] divided by the field's scale (delta_m, F_m,
1, 1). These numbers back ``zener_sym.exact.table.SUMMARY_RTOL`` and ``HISTORY_ATOL``.

``--large M`` adds the summary and history tables on (5, 1000] at M lambda spread
geometrically over (5, LAM_MAX_LARGE] (default 300: the mpmath solve takes about 0.03 lambda s
at dps 20, minutes at 1000), shifted off the nodes.
"""
from __future__ import annotations

import argparse

import numpy as np

import zener_sym as zs
from zener_sym.exact import table as exact_fast, mp as exact_mp

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")


HISTORY = ("delta", "force", "impulse", "velocity")


def _worst(lams, dps, times) -> tuple:
    """Worst relative error per summary field (absolute where the reference is 0) and worst
    history error per field divided by its scale, of the tables against mpmath at ``lams``;
    ``times(r)`` gives the history times for the mpmath solution r."""
    s = zs.summary(lams, model="exact", backend="table")
    worst = {f: (0.0, 0.0) for f in FIELDS}
    hist = {f: (0.0, 0.0) for f in HISTORY}
    for i, x in enumerate(lams):
        r = exact_mp.solve(float(x), dps=dps)
        for f in FIELDS:
            ref = float(getattr(r, f))
            err = abs(getattr(s, f)[i] / ref - 1) if ref != 0 else abs(getattr(s, f)[i])
            if err > worst[f][0]:
                worst[f] = (err, x)
        tau = times(r)
        g = r.history(tau)
        h = zs.history(float(x), tau, model="exact", backend="table")
        scale = {"delta": float(r.delta_m), "force": float(r.F_m), "impulse": 1.0, "velocity": 1.0}
        for f, sc in scale.items():
            err = float(np.abs(getattr(h, f) - g[f]).max()) / sc
            if err > hist[f][0]:
                hist[f] = (err, x)
    return worst, hist


def measure(n: int = 101, dps: int = 20) -> dict:
    """The tables on [0, 5] at n lambda between the nodes, plus both ends; histories over 400
    times in [0, 1.02 tau_d]."""
    lams = np.concatenate([[0.0], 5.0 * (np.arange(n) + 0.5) / n, [5.0]])
    worst, hist = _worst(lams, dps, lambda r: np.linspace(0.0, 1.02 * float(r.tau_d), 400))
    return {"summary": worst, "history": hist, "n_lambda": len(lams)}


LAM_MAX_LARGE = 300.0


def measure_large(m: int, dps: int = 20, top: float = LAM_MAX_LARGE) -> dict:
    """The tables on (5, top] against mpmath, histories over 400 times in [0, 1.02 tau_d] and
    100 in [0, 3 tau_dc] (the short compression)."""
    lams = np.geomspace(5.0, top, m + 1)[1:] * 0.9937  # off the Chebyshev nodes in ln(lambda)
    worst, hist = _worst(lams, dps, lambda r: np.concatenate([
        np.linspace(0.0, 3 * float(r.tau_dc), 100), np.linspace(0.0, 1.02 * float(r.tau_d), 400)]))
    return {"summary": worst, "history": hist, "n_lambda": len(lams)}


def _report(title, m) -> bool:
    """Print one measurement as markdown tables; True when the documented bounds hold."""
    print(title)
    print("| summary field | worst rel. error | at lambda |\n|---|---|---|")
    for f, (e, x) in m["summary"].items():
        print(f"| {f} | {e:.1e} | {x:.4g} |")
    print("| history field | worst error / scale | at lambda |\n|---|---|---|")
    for f, (e, x) in m["history"].items():
        print(f"| {f} | {e:.1e} | {x:.4g} |")
    return (max(e for e, _ in m["summary"].values()) <= exact_fast.SUMMARY_RTOL
            and max(e for e, _ in m["history"].values()) <= exact_fast.HISTORY_ATOL)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=101)
    p.add_argument("--dps", type=int, default=20)
    p.add_argument("--large", type=int, default=0,
                   help="lambda values on (5, 300] (summary and history)")
    a = p.parse_args(argv)
    ok = True
    if a.large:
        ok = _report(f"{a.large} lambda in (5, {LAM_MAX_LARGE:g}], reference exact_mp dps {a.dps}",
                     measure_large(a.large, a.dps))
    if a.n > 0:
        m = measure(a.n, a.dps)
        ok = _report(f"{m['n_lambda']} lambda in [0, 5], reference exact_mp dps {a.dps}", m) and ok
    print(f"documented bounds (summary {exact_fast.SUMMARY_RTOL:g}, history "
          f"{exact_fast.HISTORY_ATOL:g}): {'hold' if ok else 'VIOLATED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
