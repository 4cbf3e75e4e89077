"""LAMMPS as a method of the benchmark: Zener's plate problem (contact to delta = 0) integrated by
LAMMPS's ``hertz/material`` + ``damping viscoelastic`` contact, a sphere on a wall, with a fixed
number of steps per contact (the exact contact duration over dt).

Its summary gives e, tau_d and F_m = delta_m^{3/2} (the plate reading's peak Hertz force, from
the largest overlap LAMMPS reached); its force history is F = delta(tau)^{3/2} from LAMMPS's
overlap, interpolated linearly between steps. Time per lambda is one collision through LAMMPS's
Python interface (clear, read the deck, run, read back).
"""
from __future__ import annotations

import functools
from collections.abc import Sequence

import numpy as np

from ..api import summary as exact_summary
from ..typing import FloatArray
from .lammps_run import Session, available, collide
from .lammps_verify import SPEED, contacts
from .methods import Method

__all__ = ["STEPS", "MAP_STEPS", "methods"]

#: The sweep of steps per contact (one line of the work-precision chart).
STEPS = (20, 50, 200, 1000, 5000)
#: The member of the sweep drawn in the error map.
MAP_STEPS = 200

@functools.cache
def _session() -> Session:
    """One LAMMPS instance for the benchmark's runs (each run clears it)."""
    return Session()


def _run(lam: float, steps: int) -> tuple[float, float, float, FloatArray, FloatArray]:
    """(e, tau_d, F_m, tau of each step, F at each step) of one LAMMPS run, dimensionless."""
    c = contacts()["wall"]
    v = SPEED
    T = float(c.time_scale(v))
    X = v * T
    t_c = T * float(exact_summary(lam, model="exact").tau_d)
    dt = t_c / steps
    ses = _session()
    r = collide(ses, c, c.damping(lam / float(c.rate(v))), "delta", v, dt, t_c, phase=0.0,
                record=True)
    n = r.steps
    d = np.array([ses.lmp.extract_fix("rec", 0, 2, i, 0) for i in range(n)])
    tau: FloatArray = (np.arange(n, dtype=float) + 1.0) * (dt / T)
    F: FloatArray = np.clip(d / X, 0.0, None) ** 1.5
    return r.e, r.contact_time_s / T, float(F.max(initial=0.0)), tau, F


def _method(steps: int) -> Method:
    def summary(lams: FloatArray) -> dict[str, FloatArray]:
        out = np.array([_run(float(x), steps)[:3] for x in np.atleast_1d(lams)])
        return {"e": out[:, 0], "tau_d": out[:, 1], "F_m": out[:, 2]}

    def force(lams: FloatArray, taus: Sequence[FloatArray]) -> list[FloatArray]:
        res = []
        for lam, t in zip(np.atleast_1d(lams), taus):
            _, _, _, tau, F = _run(float(lam), steps)
            # the overlap starts at tau = 0 (phase 0); before the first step it is 0
            res.append(np.interp(np.asarray(t, dtype=float), np.concatenate(([0.0], tau)),
                                 np.concatenate(([0.0], F)), right=0.0))
        return res

    extra = {"steps": steps, "representative": steps == MAP_STEPS}
    return Method(f"lammps steps={steps}", "lammps", summary, force,
                  "LAMMPS hertz/material + damping viscoelastic, sphere on a wall, velocity "
                  f"Verlet, {steps} steps per contact", extra)


def methods(quick: bool = False) -> list[Method]:
    """The LAMMPS sweep (thinned with ``quick``), or nothing when LAMMPS is not installed."""
    if not available():
        return []
    return [_method(n) for n in (STEPS[::2] if quick else STEPS)]
