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

import numpy as np

#: lambda values spanning [0, 2.4] (the HAM models' range), incl. the paper's figure values
LAMBDAS = (0.0, 0.11, 0.5, 1.01, 1.51, 1.99, 2.4)
#: points of the force history per lambda, evenly spread over [0, tau_d]
N_TAU = 101
QUANTITIES = ("F_m", "tau_d", "e", "impulse")

CACHE = pathlib.Path(__file__).resolve().parent.parent / "data" / "bench_reference.json"


#: The paths ``compute`` can take the reference from.
SOURCES = ("mpmath", "scipy")


def compute(lambdas=LAMBDAS, n_tau=N_TAU, dps=30, source: str = "mpmath") -> dict:
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
    """
    if source not in SOURCES:
        raise ValueError(f"unknown reference source {source!r}; allowed: 'mpmath', 'scipy'")
    out = {"lambdas": list(lambdas), "n_tau": n_tau, "summary": {}, "tau": {}, "force": {}}
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
            s = exact.solve(lam, rtol=1e-13, atol=1e-16)
            tau = np.linspace(0.0, s.tau_d, n_tau)
            out["summary"][repr(lam)] = {q: float(getattr(s, q)) for q in QUANTITIES}
            out["tau"][repr(lam)] = tau.tolist()
            out["force"][repr(lam)] = s.history(tau)["force"].tolist()
    return out


def load() -> dict:
    """The cached reference if present, else computed now."""
    if CACHE.exists():
        return json.loads(CACHE.read_text())
    return compute()


def dumps(ref: dict) -> str:
    """The reference as the cache's text (stable JSON)."""
    return json.dumps(ref, indent=1, sort_keys=True) + "\n"


def write_cache(ref: dict) -> None:
    CACHE.parent.mkdir(exist_ok=True)
    CACHE.write_text(dumps(ref))


#: Relative tolerance between two mpmath references of the same inputs: both carry 30 digits,
#: stored as float64 (one rounding each).
CHECK_RTOL = 1e-13


def compare(old: dict, new: dict, rtol: float = CHECK_RTOL) -> list[str]:
    """Differences that make the reference ``old`` stale relative to ``new``: other inputs or
    source, or a value beyond ``rtol`` (relative to the largest force for the history)."""
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
