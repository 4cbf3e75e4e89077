"""LAMMPS beside zener-sym in one run: the same N collisions, integrated by LAMMPS on two MPI
ranks, and answered by the exact tables (shown beside the speed targets, not judged)."""
from __future__ import annotations

import tempfile
import time
from typing import Any

import numpy as np

from ..api import summary
from .lammps_run import LammpsMissing, available


def run(quick: bool = False) -> list[dict[str, Any]]:
    """One row: LAMMPS's wall time for the example deck's N grains (``mpirun -np 2``, start-up
    included) against zener-sym's time for the same N values of e(v); none without LAMMPS."""
    if not available():
        return []
    from . import lammps_mpi

    n = 2000 if quick else lammps_mpi.N_GRAINS
    with tempfile.TemporaryDirectory() as tmp:
        deck = lammps_mpi.write_deck(tmp, n=n)
        try:
            t_lammps = lammps_mpi.run(tmp, ranks=2)
        except LammpsMissing:
            return []
    lam = deck.setup.A_s * np.asarray(deck.setup.contact.rate(deck.v))
    reps, t0 = 0, time.perf_counter()
    while True:  # the tables take ~1 ms for 10 000 lambdas: repeat for a steady time
        summary(lam, model="exact", contact_end="force").e
        reps += 1
        if time.perf_counter() - t0 > 0.2:
            break
    t_zs = (time.perf_counter() - t0) / reps
    return [{"target": f"LAMMPS, {n} grain-wall collisions on 2 MPI ranks (mpirun start-up "
                       f"included) vs zener-sym's e(v) of the same {n} speeds (exact tables)",
             "grid": f"{n} grains, {deck.steps} steps", "fast_s": t_zs, "slow_s": t_lammps,
             "ratio": t_lammps / t_zs, "required": None, "met": None}]
