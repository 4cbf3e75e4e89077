"""Measuring the error envelopes of every model against the exact solution (a benchmark).

``build()`` MEASURES, for each model present in ``zener_sym.MODELS``, the relative error of each
quantity against a tight-tolerance exact reference on a lambda grid, and the model's cost (median
time of one ``summary`` call per lambda, stored as a rank only: the machines are noisy, the order
is what matters). The table's schema and its reader are :mod:`zener_sym.scene.envelopes`;
``zener-sym regen envelopes`` writes it.
"""
from __future__ import annotations

import math
import time
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ..models.base import Model
from ..scene.envelopes import (ABSOLUTE_QUANTITIES, FLOOR, INTERVALS, QUANTITIES, SCHEMA,
                               SUMMARY_QUANTITIES)
from ..typing import FloatArray

if TYPE_CHECKING:
    from ..api import History, Summary

__all__ = ["build"]

_N_TAU = 64
_REF_OPTIONS: dict[str, Any] = {"rtol": 1e-13}  # the exact model's options
_REFERENCE = ("model 'exact' (scipy DOP853, analytic phases) at rtol 1e-13; the exact model "
              "itself is measured at its default rtol 1e-12")


def _grid(points_per_interval: int, intervals: Iterable[tuple[float, float]]) -> FloatArray:
    pts = [np.linspace(lo, hi, points_per_interval) for lo, hi in intervals]
    return np.unique(np.concatenate(pts))


def _rel(x: FloatArray, ref: FloatArray) -> FloatArray:
    rel: FloatArray = np.abs(np.asarray(x) - ref) / np.maximum(np.abs(ref), FLOOR)
    return rel


def _measure_model(model: Model, lam: FloatArray, ref_summary: Summary, ref_hist: History,
                   tau_grid: FloatArray) -> dict[str, FloatArray]:
    """Per-lambda relative errors {quantity: array over lam} (NaN where not measurable)."""
    from ..api import history, summary

    out = {q: np.full(lam.shape, np.nan) for q in QUANTITIES}
    ok = model.valid(lam)
    if not ok.any():
        return out
    s = summary(lam[ok], model=model.name)
    for q in SUMMARY_QUANTITIES:
        if q in model.summary_fields:
            ref = getattr(ref_summary, q)[ok]
            out[q][ok] = (np.abs(s.xi - ref) if q in ABSOLUTE_QUANTITIES
                          else _rel(getattr(s, q), ref))
    if "force" in model.history_fields and "impulse" in model.history_fields:
        idx = np.flatnonzero(ok)
        h = history(lam[ok][:, None], tau_grid[ok], model=model.name)
        fr, ir = ref_hist.force[ok], ref_hist.impulse[ok]
        out["force_history"][idx] = (np.max(np.abs(h.force - fr), axis=1)
                                     / np.max(fr, axis=1))
        out["impulse_history"][idx] = (np.max(np.abs(h.impulse - ir), axis=1)
                                       / np.max(ir, axis=1))
    return out


def _cost(model: Model, lams: Iterable[float], repeats: int) -> float:
    """Median over repeats and lambdas of the time of one scalar ``summary`` call [s]."""
    from ..api import summary

    times = []
    for x in lams:
        if not model.valid(x):
            continue
        summary(x, model=model.name)  # warm-up (imports, caches)
        for _ in range(repeats):
            t0 = time.perf_counter()
            summary(x, model=model.name)
            times.append(time.perf_counter() - t0)
    return float(np.median(times)) if times else math.inf


def build(models: Iterable[str] | None = None,
          intervals: Iterable[tuple[float, float]] = INTERVALS, points_per_interval: int = 4,
          repeats: int = 3, cost_lams: Sequence[float] = (0.1, 0.8, 1.6)) -> dict[str, Any]:
    """Measure the envelope table for ``models`` (default: every registered model).

    Parameters
    ----------
    models : iterable of str, optional
        Model names; default ``zener_sym.MODELS`` at call time, less the models whose
        ``in_envelopes`` is False.
    intervals : sequence of (lo, hi)
        Lambda intervals.
    points_per_interval : int
        Grid points per interval, ends included (>= 2).
    repeats : int
        Timing repeats per lambda for the cost rank.
    cost_lams : sequence of float
        Lambdas at which the cost is timed.

    Returns
    -------
    dict
        The table (see the module docstring for the schema).
    """
    from ..api import history, summary
    from ..models import REGISTRY, get_model

    # models that declare ``in_envelopes = False`` (families with options measured elsewhere, e.g.
    # "ham", docs/ham_convergence.md) are no candidates of select_model
    names = ([n for n, m in REGISTRY.items() if getattr(m, "in_envelopes", True)]
             if models is None else list(models))
    ms = [get_model(n) for n in names]
    if points_per_interval < 2:
        raise ValueError(f"points_per_interval must be >= 2, got {points_per_interval}")
    intervals = [(float(lo), float(hi)) for lo, hi in intervals]
    lam = _grid(points_per_interval, intervals)
    ref = summary(lam, model="exact", **_REF_OPTIONS)
    tau_grid = np.linspace(0.0, 1.0, _N_TAU)[None, :] * (1.05 * ref.tau_d[:, None])
    ref_hist = history(lam[:, None], tau_grid, model="exact", **_REF_OPTIONS)
    costs = {m.name: _cost(m, cost_lams, repeats) for m in ms}
    order = sorted(costs, key=lambda n: (costs[n], n))
    table: dict[str, Any] = {
        "schema": SCHEMA, "reference": _REFERENCE,
        "error_definition": f"max over grid points of |q - q_ref| / max(|q_ref|, {FLOOR:g}) "
                            f"({', '.join(ABSOLUTE_QUANTITIES)}: |q - q_ref|); "
                            f"histories: max over {_N_TAU} times in [0, 1.05 tau_d] of the error "
                            "over the reference's maximum",
        "intervals": [list(iv) for iv in intervals], "points_per_interval": points_per_interval,
        "quantities": list(QUANTITIES), "models": {},
    }
    for m in ms:
        err = _measure_model(m, lam, ref, ref_hist, tau_grid)
        env = {}
        for q in QUANTITIES:
            row = []
            for lo, hi in intervals:
                sel = (lam >= lo) & (lam <= hi)
                vals = err[q][sel]
                row.append(None if np.isnan(vals).any() else float(f"{vals.max():.3g}"))
            env[q] = row
        table["models"][m.name] = {
            "cost_rank": order.index(m.name),
            "lam_bound": None if m.lam_bound is None else float(m.lam_bound),
            "envelopes": env,
        }
    return table
