"""Builds the finite-plate criterion's table: the ``finite-plate`` model against Zener's on a grid.

``zener-sym regen plate-criterion`` writes ``src/zener_sym/data/plate_criterion.json``: for each
support of the circle struck at its centre and each (lambda, beta) of :data:`LAMS` x
:data:`BETAS`, the ``finite-plate`` model (solver accuracy :data:`SOLVER_RTOL`) and Zener's exact
model, as

- ``difference``: per quantity of :data:`zener_sym.scene.plate_criterion.QUANTITIES`, the
  relative difference |q_plate / q_Zener - 1| (for xi the absolute one), rounded up to three
  significant digits;
- ``e_ratio``: e_plate / e_Zener (the regime map of docs/finite_plates.md);
- ``contacts``: the number of contacts.

The numbers come from an adaptive solver, so a rebuild on another machine may differ in the
last digits: :func:`compare` allows :data:`COMPARE_RTOL` (relative to the value, and an absolute
floor of the solver's accuracy) and requires the contact counts and the grid to be equal.
"""
from __future__ import annotations

import json
import math
import re
from typing import Any

import numpy as np

from .plate_criterion import QUANTITIES

__all__ = ["LAMS", "BETAS", "SUPPORTS", "SOLVER_RTOL", "COMPARE_RTOL", "build", "dumps",
           "compare"]

#: lambda grid (log-spaced, 1e-2 to 3, four points a decade; beyond 3 the later contacts
#: reach plates so large that the solver's proof of the end takes minutes).
LAMS: tuple[float, ...] = tuple(float(f"{x:.4g}") for x in np.geomspace(1e-2, 3.0, 11))
#: beta grid (log-spaced, 1e-5 to 1, three points a decade).
BETAS: tuple[float, ...] = tuple(float(f"{x:.4g}") for x in np.geomspace(1e-5, 1.0, 16))
#: The supports of the circle.
SUPPORTS: tuple[str, ...] = ("clamped", "simply-supported")
#: Poisson's ratio of the simply supported circle's plate (glass 0.21, steel 0.3: the larger
#: (3 + nu)/(1 + nu) static compliance of the smaller nu makes the plate softer).
NU = 0.21
#: The accuracy asked of the finite-plate solver (the criterion claims nothing finer than
#: ``plate_criterion.RESOLUTION`` times it).
SOLVER_RTOL = 1e-5
#: A rebuilt difference may move by this much (relative) before the table is stale.
COMPARE_RTOL = 0.05


def _up(x: float) -> float:
    """x rounded up to three significant digits (the criterion stays conservative)."""
    if x == 0.0 or not math.isfinite(x):
        return x
    e = math.floor(math.log10(x)) - 2
    return float(f"{math.ceil(x / 10.0**e)}e{e}")


def _differences(plate: Any, zener: Any, i: int) -> dict[str, float]:
    out = {}
    for q in QUANTITIES:
        a, b = float(getattr(plate, q)), float(getattr(zener, q)[i])
        out[q] = abs(a - b) if q == "xi" else abs(a / b - 1.0)
    return out


def build(lams: tuple[float, ...] = LAMS, betas: tuple[float, ...] = BETAS,
          supports: tuple[str, ...] = SUPPORTS, rtol: float = SOLVER_RTOL,
          log: Any = None) -> dict[str, Any]:
    """The criterion table (module docstring).

    Parameters
    ----------
    lams, betas : tuple of float
        The grid, ascending.
    supports : tuple of str
        The circle's supports.
    rtol : float
        The solver's accuracy.
    log : callable, optional
        Called with one line per support and lambda (progress).

    Returns
    -------
    dict
        ``lam``, ``beta``, ``nu``, ``solver_rtol`` and ``supports``: {support: {difference:
        {quantity: [[...]]}, e_ratio: [[...]], contacts: [[...]]}} indexed [lambda][beta].
    """
    from ..api import summary
    from ..models.finite_plate import impact

    zener = summary(np.array(lams), model="exact")
    table: dict[str, Any] = {"lam": list(lams), "beta": list(betas), "nu": NU,
                             "solver_rtol": rtol, "supports": {}}
    for support in supports:
        diff: dict[str, list[list[float]]] = {q: [] for q in QUANTITIES}
        ratio, contacts = [], []
        for i, lam in enumerate(lams):
            rows: dict[str, list[float]] = {q: [] for q in QUANTITIES}
            r_row, c_row = [], []
            for beta in betas:
                opts = dict(beta=beta, support=support, nu=NU, rtol=rtol)
                s = summary(lam, model="finite-plate", **opts)
                for q, v in _differences(s, zener, i).items():
                    rows[q].append(_up(v))
                r_row.append(float(f"{s.e / float(zener.e[i]):.6g}"))
                c_row.append(len(impact(lam, **opts).contacts))
            for q in QUANTITIES:
                diff[q].append(rows[q])
            ratio.append(r_row)
            contacts.append(c_row)
            if log is not None:
                log(f"plate-criterion: {support}, lambda = {lam:g} done")
        table["supports"][support] = {"difference": diff, "e_ratio": ratio,
                                      "contacts": contacts}
    return table


def dumps(table: dict[str, Any]) -> str:
    """The table as committed: JSON, one row of the grid per line."""
    text = json.dumps(table, indent=1, sort_keys=True)
    # a list of numbers on one line
    return re.sub(r"\[\s+([^\[\]{}]*?)\s+\]",
                  lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]",
                  text) + "\n"


def compare(old: dict[str, Any], new: dict[str, Any]) -> list[str]:
    """Why a committed table is stale against a rebuilt one (empty: fresh; module docstring)."""
    problems = []
    for key in ("lam", "beta", "nu", "solver_rtol"):
        if old.get(key) != new.get(key):
            problems.append(f"plate_criterion.json: {key} differs from the builder's")
    if problems or set(old["supports"]) != set(new["supports"]):
        return problems or ["plate_criterion.json: the supports differ from the builder's"]
    floor = 10.0 * float(new["solver_rtol"])
    for sup, n in new["supports"].items():
        o = old["supports"][sup]
        if o["contacts"] != n["contacts"]:
            problems.append(f"plate_criterion.json: {sup}: contact counts differ")
        pairs = [("e_ratio", o["e_ratio"], n["e_ratio"])]
        pairs += [(f"difference {q}", o["difference"][q], n["difference"][q]) for q in QUANTITIES]
        for what, a, b in pairs:
            x, y = np.asarray(a, float), np.asarray(b, float)
            if x.shape != y.shape or np.any(np.abs(x - y) > COMPARE_RTOL * np.abs(y) + floor):
                problems.append(f"plate_criterion.json: {sup}: {what} moved beyond "
                                f"{COMPARE_RTOL:g} relative")
    return problems
