"""Measured error envelopes of every model against the exact solution: ``data/envelopes.json``.

``build()`` MEASURES, for each model present in ``zener_sym.MODELS``, the relative error of each
quantity against a tight-tolerance exact reference on a lambda grid, and the model's cost (median
time of one ``summary`` call per lambda, stored as a rank only: the machines are noisy, the order
is what matters). ``zener-sym envelopes`` regenerates the committed table; ``--check`` rebuilds
in memory and fails when the committed table is stale beyond a tolerance.

Schema (version 1)::

    {
      "schema": "zener-sym/envelopes/1",
      "reference": "<how the reference was computed>",
      "error_definition": "<formula>",
      "intervals": [[lo, hi], ...],          # lambda intervals, closed, consecutive
      "points_per_interval": n,              # grid points per interval, ends included
      "quantities": ["delta_m", ..., "force_history", "impulse_history"],
      "models": {
        "<name>": {
          "cost_rank": 0,                    # 0 = cheapest
          "lam_bound": null or float,        # the model's exclusive validity bound
          "envelopes": {"<quantity>": [max_rel_err or null per interval]}
        }
      }
    }

An envelope entry is the maximum over the interval's grid points (ends included) of
|q_model - q_ref| / max(|q_ref|, 1e-6), except for xi: the energy loss is a fraction of the
impact energy and tends to 0 with lambda, so its entry is the absolute error |xi - xi_ref| (a
relative error would make every model that neglects a tiny loss, Hertz's on a thick plate,
look 100% wrong). The first intervals are decades (1e-4, 1e-3, 1e-2) so that a thick plate is
judged on its own lambda. For the histories it is the maximum over 64
times in [0, 1.05 tau_d] of |F - F_ref| / max F_ref (force) and |I - I_ref| / max I_ref (impulse,
hence also the deflection and the sphere velocity). null: the model cannot give the quantity or
is not valid on the whole interval.
"""
from __future__ import annotations

import json
import math
import time
from importlib import resources
from pathlib import Path

import numpy as np

__all__ = ["SCHEMA", "INTERVALS", "QUANTITIES", "ABSOLUTE_QUANTITIES", "build", "load", "save", "compare", "path"]

SCHEMA = "zener-sym/envelopes/1"
_EDGES = (0.0, 1e-4, 1e-3, 1e-2, 0.1, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 3.0, 4.0, 6.0, 10.0)
INTERVALS = tuple(zip(_EDGES[:-1], _EDGES[1:]))
SUMMARY_QUANTITIES = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                      "int_F2", "xi")
HISTORY_QUANTITIES = ("force_history", "impulse_history")
#: Quantities judged by their absolute error (fractions of the impact energy that tend to 0).
ABSOLUTE_QUANTITIES = ("xi",)
QUANTITIES = SUMMARY_QUANTITIES + HISTORY_QUANTITIES
_FLOOR = 1e-6
_N_TAU = 64
_REF_OPTIONS = {"rtol": 1e-13}
_REFERENCE = ("model 'exact' (scipy DOP853, analytic phases) at rtol 1e-13; the exact model "
              "itself is measured at its default rtol 1e-12")


def path() -> Path:
    """Location of the committed table."""
    return Path(str(resources.files("zener_sym") / "data" / "envelopes.json"))


def _grid(points_per_interval: int, intervals) -> np.ndarray:
    pts = [np.linspace(lo, hi, points_per_interval) for lo, hi in intervals]
    return np.unique(np.concatenate(pts))


def _rel(x, ref):
    return np.abs(np.asarray(x) - ref) / np.maximum(np.abs(ref), _FLOOR)


def _measure_model(model, lam, ref_summary, ref_hist, tau_grid):
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


def _cost(model, lams, repeats) -> float:
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


def build(models=None, intervals=INTERVALS, points_per_interval: int = 4, repeats: int = 3,
          cost_lams=(0.1, 0.8, 1.6)) -> dict:
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
    table = {
        "schema": SCHEMA, "reference": _REFERENCE,
        "error_definition": f"max over grid points of |q - q_ref| / max(|q_ref|, {_FLOOR:g}) "
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


def save(table: dict, where: Path | None = None) -> Path:
    """Write ``table`` as stable JSON (sorted keys, fixed indentation)."""
    where = Path(where) if where is not None else path()
    where.parent.mkdir(parents=True, exist_ok=True)
    where.write_text(json.dumps(table, indent=1, sort_keys=True) + "\n")
    return where


def load(where: Path | None = None) -> dict:
    """The committed table (or the one at ``where``), with its schema checked."""
    where = Path(where) if where is not None else path()
    try:
        table = json.loads(where.read_text())
    except FileNotFoundError:
        raise FileNotFoundError(f"no envelope table at {where}; run 'zener-sym envelopes'") \
            from None
    if table.get("schema") != SCHEMA:
        raise ValueError(f"{where}: schema {table.get('schema')!r}, expected {SCHEMA!r}")
    return table


def compare(old: dict, new: dict, decades: float = 0.5, noise: float = 1e-9) -> list[str]:
    """Differences that make ``old`` stale relative to ``new``: other models, intervals or
    quantities, availability, or an envelope differing by more than ``decades`` in log10
    (values below ``noise`` count as ``noise``: round-off is not staleness)."""
    diffs = []
    for key in ("intervals", "quantities", "points_per_interval"):
        if old.get(key) != new.get(key):
            diffs.append(f"{key} differ")
    if set(old["models"]) != set(new["models"]):
        diffs.append(f"models differ: committed {sorted(old['models'])}, now "
                     f"{sorted(new['models'])}")
    for name in sorted(set(old["models"]) & set(new["models"])):
        eo, en = old["models"][name]["envelopes"], new["models"][name]["envelopes"]
        for q in sorted(set(eo) & set(en)):
            for i, (a, b) in enumerate(zip(eo[q], en[q])):
                if (a is None) != (b is None):
                    diffs.append(f"{name}.{q}[{i}]: availability {a} -> {b}")
                elif a is not None and abs(math.log10(max(a, noise)) -
                                           math.log10(max(b, noise))) > decades:
                    diffs.append(f"{name}.{q}[{i}]: {a:.3g} -> {b:.3g}")
    return diffs
