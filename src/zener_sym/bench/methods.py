"""The catalogue of methods the benchmark compares.

A ``Method`` computes, for an array of lambda, some of the summary quantities and (optionally)
the force history on per-lambda time grids. Families group one method's tolerance sweep into one
line of a work-precision chart.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from ..exact import solver as exact
from ..models import REGISTRY, FieldUnavailableError
from ..typing import FloatArray
from .reference import QUANTITIES

#: lams -> {quantity: array over lams}
SummaryFn = Callable[[FloatArray], dict[str, FloatArray]]
#: (lams, one tau array per lambda) -> one force array per lambda
ForceFn = Callable[[FloatArray, Sequence[FloatArray]], Sequence[FloatArray]]

TOLERANCES = tuple(10.0**-k for k in range(3, 13))
QUICK_TOLERANCES = (1e-3, 1e-6, 1e-9)
IVP_METHODS = ("RK45", "DOP853", "LSODA", "Radau")


@dataclass
class Method:
    """One method under test: its label, the family (one chart line) and what it computes."""

    name: str
    family: str
    summary: SummaryFn | None = None
    force: ForceFn | None = None
    notes: str = ""
    #: "rtol" (a sweep's tolerance), "stride" (slow methods: every stride-th history point)
    extra: dict[str, Any] = field(default_factory=dict)


def _phases(method: str, rtol: float) -> Method:
    def solve_all(lams: FloatArray) -> list[exact.ExactSolution]:
        return [exact.solve(x, rtol=rtol, atol=rtol * 1e-3, method=method) for x in lams]

    def summary(lams: FloatArray) -> dict[str, FloatArray]:
        sols = solve_all(lams)
        return {q: np.array([getattr(s, q) for s in sols]) for q in QUANTITIES}

    def force(lams: FloatArray, taus: Sequence[FloatArray]) -> list[FloatArray]:
        return [s.history(t)["force"] for s, t in zip(solve_all(lams), taus)]

    return Method(f"exact {method} rtol={rtol:.0e}", f"exact, solve_ivp {method}", summary, force,
                  "three analytic phases (u, tau, u), scipy solve_ivp", {"rtol": rtol})


def naive_solve(lam: float, rtol: float, method: str = "DOP853",
                dense: bool = False) -> tuple[dict[str, float], Any]:
    """Eq. (10) integrated in tau from tau = 0 with a guarded right-hand side and an event at
    delta = 0 (direction -1): the textbook set-up, kept to show what the phases buy.

    Parameters
    ----------
    lam : float
        Zener's lambda (Eq. 11).
    rtol : float
        solve_ivp's rtol (atol = rtol / 1000).
    method : str
        solve_ivp's method.
    dense : bool
        Keep the dense output (``sol.sol``).

    Returns
    -------
    summary : dict of str to float
        F_m, tau_d, e, impulse.
    sol : scipy.integrate OdeResult
        solve_ivp's result.

    Raises
    ------
    RuntimeError
        When no end of contact is found.
    """

    def f(t: float, y: FloatArray) -> list[float]:
        d = max(y[0], 0.0)
        F = d * math.sqrt(d)
        return [y[1] - lam * F, -F]

    def top(t: float, y: FloatArray) -> float:
        d = max(y[0], 0.0)
        g: float = y[1] - lam * d * math.sqrt(d)
        return g

    def end(t: float, y: FloatArray) -> float:
        g: float = y[0]
        return g

    # solve_ivp reads these attributes off the event functions
    setattr(top, "direction", -1)
    setattr(end, "terminal", True)
    setattr(end, "direction", -1)
    sol = solve_ivp(f, (0.0, 100.0 + 100.0 * lam), [0.0, 1.0], method=method, rtol=rtol,
                    atol=rtol * 1e-3, events=[top, end], dense_output=dense)
    if len(sol.t_events[1]) == 0 or len(sol.t_events[0]) == 0:
        raise RuntimeError(f"naive {method}: no end of contact found at lambda = {lam}")
    dm = sol.y_events[0][0][0]
    w = sol.y_events[1][0][1]
    return {"F_m": dm**1.5, "tau_d": sol.t_events[1][0], "e": -w, "impulse": 1 - w}, sol


def _naive(method: str, rtol: float) -> Method:
    def summary(lams: FloatArray) -> dict[str, FloatArray]:
        rows = [naive_solve(x, rtol, method)[0] for x in lams]
        return {q: np.array([r[q] for r in rows]) for q in QUANTITIES}

    def force(lams: FloatArray, taus: Sequence[FloatArray]) -> list[FloatArray]:
        out = []
        for x, t in zip(lams, taus):
            s, sol = naive_solve(x, rtol, method, dense=True)
            d = np.maximum(sol.sol(np.minimum(t, s["tau_d"]))[0], 0.0)
            out.append(np.where(t < s["tau_d"], d**1.5, 0.0))
        return out

    return Method(f"naive {method} rtol={rtol:.0e}", f"naive solve_ivp {method}", summary, force,
                  "tau from 0, max(delta, 0) guard, event delta = 0", {"rtol": rtol})


def _registry_model(name: str, **options: Any) -> Method:
    model = REGISTRY[name]

    def summary(lams: FloatArray) -> dict[str, FloatArray]:
        import zener_sym as zs

        lams = np.asarray(lams, dtype=float)
        # a model valid only below some lambda is measured where it is valid; NaN elsewhere
        ok = model.valid(lams)
        s = zs.summary(lams[ok], model=name, **options)
        out: dict[str, FloatArray] = {}
        for q in QUANTITIES:
            try:
                v = np.full(lams.shape, np.nan)
                v[ok] = np.asarray(getattr(s, q))
                out[q] = v
            except FieldUnavailableError:
                pass
        return out

    def force(lams: FloatArray, taus: Sequence[FloatArray]) -> list[FloatArray]:
        import zener_sym as zs

        lam_col = np.asarray(lams, dtype=float)[:, None]
        grid = np.array(taus)
        return list(zs.history(lam_col, grid, model=name, **options).force)

    label = name + "".join(f" {k}={v}" for k, v in sorted(options.items()))
    has_force = "force" in model.history_fields
    # mpmath backends cost ~1 s per history point: they are measured on every 10th point
    extra = {"stride": 10} if options.get("backend") == "mpmath" else {}
    return Method(label, label, summary, force if has_force else None, model.description, extra)


def catalogue(quick: bool = False) -> list[Method]:
    """Every method the benchmark runs; ``quick`` thins the tolerance sweeps."""
    tols = QUICK_TOLERANCES if quick else TOLERANCES
    methods = []
    for m in IVP_METHODS:
        methods += [_phases(m, t) for t in tols]
    methods += [_naive("DOP853", t) for t in tols]
    for name, model in REGISTRY.items():
        if name.startswith("_"):
            continue
        methods.append(_registry_model(name))
        if "backend" in model.options and name != "exact" and not quick:
            methods.append(_registry_model(name, backend="mpmath"))
    if "exact" in REGISTRY and not quick:
        methods.append(_registry_model("exact", backend="mpmath", dps=20))
    return methods


def dop853_force_loop(lams: FloatArray, tau: FloatArray, rtol: float = 1e-6) -> FloatArray:
    """The comparator of the ham1 target: per lambda, a scipy DOP853 solve of Eq. (10) with dense
    output (tau from 0, guarded right-hand side, event delta = 0), force on that row of ``tau``.

    Parameters
    ----------
    lams : numpy.ndarray
        Lambda values, shape (m,).
    tau : numpy.ndarray
        Times, shape (m, k): row i for lams[i].
    rtol : float
        solve_ivp's rtol.

    Returns
    -------
    numpy.ndarray
        The force, of the shape of ``tau`` (0 past each contact's end).
    """
    out = np.empty_like(tau)
    for i, lam in enumerate(lams):
        summ, sol = naive_solve(lam, rtol, "DOP853", dense=True)
        t = tau[i]
        d = np.maximum(sol.sol(np.minimum(t, summ["tau_d"]))[0], 0.0)
        out[i] = np.where(t < summ["tau_d"], d**1.5, 0.0)
    return out
