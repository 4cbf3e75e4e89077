"""High-precision reference values for the benchmark.

The reference comes from the exact model's mpmath path (``zener_sym.exact.mp``, 30 digits) and is
cached in ``zener_sym/data/bench_reference.json`` (built by ``zener-sym bench --build-reference``,
checked in tests against a fresh computation). ``compute(source="scipy")`` gives the scipy path
at rtol 1e-13 instead (fast, for tests that need a reference but not its digits); the source is
recorded in the output.
"""
from __future__ import annotations

import json
import pathlib
from collections.abc import Mapping, Sequence
from typing import Any, TypedDict

import numpy as np

#: lambda values spanning [0, 2.4] (the HAM models' range), incl. the paper's figure values
LAMBDAS = (0.0, 0.11, 0.5, 1.01, 1.51, 1.99, 2.4)
#: points of the force history per lambda, evenly spread over [0, tau_d]
N_TAU = 101
QUANTITIES: tuple[str, ...] = ("F_m", "tau_d", "e", "impulse")

CACHE = pathlib.Path(__file__).resolve().parent.parent / "data" / "bench_reference.json"


#: The paths ``compute`` can take the reference from.
SOURCES = ("mpmath", "scipy")


class Reference(TypedDict):
    """The reference, as ``compute`` gives it and the cache holds it (JSON). Per-lambda entries
    are keyed by ``repr(lambda)``."""

    lambdas: list[float]
    n_tau: int
    #: how the values were computed (method and precision)
    source: str
    #: repr(lambda) -> {quantity of ``QUANTITIES``: value}
    summary: dict[str, dict[str, float]]
    #: repr(lambda) -> the n_tau times, evenly spread over [0, tau_d]
    tau: dict[str, list[float]]
    #: repr(lambda) -> the force at those times
    force: dict[str, list[float]]


def compute(lambdas: Sequence[float] = LAMBDAS, n_tau: int = N_TAU, dps: int = 30,
            source: str = "mpmath") -> Reference:
    """Reference summary and force history.

    Parameters
    ----------
    lambdas : sequence of float
        The lambda values.
    n_tau : int
        Points of the force history per lambda, evenly spread over [0, tau_d].
    dps : int
        Decimal digits of the mpmath path.
    source : {"mpmath", "scipy"}
        ``"mpmath"`` (default): ``zener_sym.exact.mp`` at ``dps`` digits, what the committed
        cache holds. ``"scipy"``: the scipy path at rtol 1e-13 (fast; for tests).

    Returns
    -------
    Reference

    Raises
    ------
    ValueError
        For an unknown ``source`` (and from the solvers, for a bad lambda or dps).
    """
    if source not in SOURCES:
        raise ValueError(f"unknown reference source {source!r}; allowed: 'mpmath', 'scipy'")
    out: Reference = {"lambdas": list(lambdas), "n_tau": n_tau, "source": "", "summary": {},
                      "tau": {}, "force": {}}
    if source == "mpmath":
        from ..exact import mp as exact_mp

        out["source"] = f"zener_sym.exact.mp at dps={dps}"
        for lam in lambdas:
            s = exact_mp.solve(lam, dps=dps)
            tau = [float(s.tau_d) * j / (n_tau - 1) for j in range(n_tau)]
            h = s.history(np.array(tau))
            out["summary"][repr(lam)] = {q: float(getattr(s, q)) for q in QUANTITIES}
            out["tau"][repr(lam)] = tau
            out["force"][repr(lam)] = [float(x) for x in h["force"]]
    else:
        from ..exact import solver as exact

        out["source"] = "zener_sym.exact.solver (scipy DOP853) at rtol=1e-13"
        for lam in lambdas:
            sol = exact.solve(lam, rtol=1e-13, atol=1e-16)
            tau_grid = np.linspace(0.0, sol.tau_d, n_tau)
            out["summary"][repr(lam)] = {q: float(getattr(sol, q)) for q in QUANTITIES}
            out["tau"][repr(lam)] = tau_grid.tolist()
            out["force"][repr(lam)] = sol.history(tau_grid)["force"].tolist()
    return out


def load() -> Reference:
    """The cached reference if present, else computed now (``compute()``, minutes)."""
    if CACHE.exists():
        cached: Reference = json.loads(CACHE.read_text())
        return cached
    return compute()


def dumps(ref: Reference) -> str:
    """The reference as the cache's text (stable JSON)."""
    return json.dumps(ref, indent=1, sort_keys=True) + "\n"


def write_cache(ref: Reference) -> None:
    """Write ``ref`` to the cache file ``CACHE``."""
    CACHE.parent.mkdir(exist_ok=True)
    CACHE.write_text(dumps(ref))


#: Relative tolerance between two mpmath references of the same inputs: both carry 30 digits,
#: stored as float64 (one rounding each).
CHECK_RTOL = 1e-13


def compare(old: Mapping[str, Any], new: Mapping[str, Any], rtol: float = CHECK_RTOL) -> list[str]:
    """Differences that make the reference ``old`` stale relative to ``new``: other inputs or
    source, or a value beyond ``rtol`` (relative to the largest force for the history).

    Both are read as JSON gives them (``old`` may be any stale layout), hence plain mappings."""
    bad = [f"{k}: {old.get(k)!r} -> {new.get(k)!r}" for k in ("lambdas", "n_tau", "source")
           if old.get(k) != new.get(k)]
    if bad:
        return bad
    for lam in new["summary"]:
        for q in QUANTITIES:
            a, b = old["summary"].get(lam, {}).get(q), new["summary"][lam][q]
            if a is None or not abs(a - b) <= rtol * max(abs(b), 1e-300):
                bad.append(f"summary {lam} {q}: {a!r} -> {b!r}")
        for key in ("tau", "force"):
            a, b = np.asarray(old[key].get(lam, []), float), np.asarray(new[key][lam], float)
            if a.shape != b.shape or np.max(np.abs(a - b)) > rtol * np.max(np.abs(b)):
                bad.append(f"{key} {lam}: differs beyond {rtol:g}")
    return bad
