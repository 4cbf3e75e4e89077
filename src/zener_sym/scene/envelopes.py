"""Measured error envelopes of every model against the exact solution: ``data/envelopes.json``.

The scene layer only reads the table (``load``; ``select_model`` picks the cheapest model whose
envelope meets a tolerance). The measuring is a benchmark and lives in
:mod:`zener_sym.bench.envelopes`; ``zener-sym regen envelopes`` (alias ``zener-sym envelopes``)
rewrites the committed table, ``zener-sym regen --check`` fails when it is stale beyond a
tolerance (``compare``).

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
from importlib import resources
from pathlib import Path
from typing import Any

__all__ = ["SCHEMA", "INTERVALS", "QUANTITIES", "SUMMARY_QUANTITIES", "HISTORY_QUANTITIES",
           "ABSOLUTE_QUANTITIES", "FLOOR", "load", "save", "compare", "path"]

SCHEMA = "zener-sym/envelopes/1"
_EDGES = (0.0, 1e-4, 1e-3, 1e-2, 0.1, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 3.0, 4.0, 6.0, 10.0)
INTERVALS = tuple(zip(_EDGES[:-1], _EDGES[1:]))
SUMMARY_QUANTITIES = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                      "int_F2", "xi")
HISTORY_QUANTITIES = ("force_history", "impulse_history")
#: Quantities judged by their absolute error (fractions of the impact energy that tend to 0).
ABSOLUTE_QUANTITIES = ("xi",)
QUANTITIES = SUMMARY_QUANTITIES + HISTORY_QUANTITIES
#: Smallest |q_ref| a relative error divides by.
FLOOR = 1e-6


def path() -> Path:
    """Location of the committed table."""
    return Path(str(resources.files("zener_sym") / "data" / "envelopes.json"))


def save(table: dict[str, Any], where: Path | None = None) -> Path:
    """Write ``table`` as stable JSON (sorted keys, fixed indentation)."""
    where = Path(where) if where is not None else path()
    where.parent.mkdir(parents=True, exist_ok=True)
    where.write_text(json.dumps(table, indent=1, sort_keys=True) + "\n")
    return where


def load(where: Path | None = None) -> dict[str, Any]:
    """The committed table (or the one at ``where``), with its schema checked."""
    where = Path(where) if where is not None else path()
    try:
        table: dict[str, Any] = json.loads(where.read_text())
    except FileNotFoundError:
        raise FileNotFoundError(f"no envelope table at {where}; run 'zener-sym regen envelopes'") \
            from None
    if table.get("schema") != SCHEMA:
        raise ValueError(f"{where}: schema {table.get('schema')!r}, expected {SCHEMA!r}")
    return table


def compare(old: dict[str, Any], new: dict[str, Any], decades: float = 0.5,
            noise: float = 1e-9) -> list[str]:
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
