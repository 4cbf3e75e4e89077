"""The sphere on a modal plate, solved with every contact to the proved end (issue 37, section 2).

The equations are those of :mod:`.modal` (Zener's scales), with an optional modal loss factor eta:

    x'' = -F,   y_n'' + eta omega_n y_n' + omega_n^2 y_n = c_n F,   delta = x - sum y_n - C_res F,
    F = max(delta, 0)^{3/2},   x(0) = 0, x'(0) = 1, y_n(0) = y_n'(0) = 0.

Contacts are stepped on a uniform grid with the force piecewise linear and solved implicitly at
each node (:mod:`.stepping`); the modes are propagated exactly (:mod:`.kernels`), so no mode limits
the step. Between contacts the motion is known in closed form and the next contact, or the proved
end, is found by :mod:`.flight`. The whole impact is run at steps 4h, 2h and h; Richardson's
extrapolation (order 2) of the last two pairs gives two estimates whose difference is the
reported error (times a safety factor 2; for e, the largest over the contacts' speeds, see
SAFETY), and h is halved until that error is below rtol |e|. The impulse that linear pieces miss
where the force starts and ends as a 3/2 power (Navot's extension of Euler-Maclaurin,
:func:`.stepping.end_defect`) is added at each start and end, so the error's leading terms are
smooth in h and the extrapolation works.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..typing import FloatArray
from .flight import Flight, end_bound, next_contact
from .kernels import ComplexArray, Kernel, Rates
from .modal import ModalPlate
from .result import CONTACT_FIELDS, PlateContact, PlateImpact
from .stepping import ContactRun, end_of_contact, start_kick, step_contact

__all__ = ["solve", "choose_modes", "check_plate", "warm_up", "RTOL_MIN", "RTOL_MAX", "N_MAX"]

#: The finest rtol: below it the error estimate meets its rounding floor on plates with several
#: contacts (near 1e-11 relative on issue 37's five-contact plate, where halving then only adds
#: work), so finer requests are refused up front rather than searched for.
RTOL_MIN = 1e-10
RTOL_MAX = 1e-2
#: A contact is stepped with at least this many nodes (shorter ones are re-run on a finer grid).
N_MIN = 16
#: The reported error of a field is SAFETY |R1 - R2|: the difference of the extrapolations from
#: (4h, 2h) and (2h, h). It mostly overstates the finer one's error several times (their error
#: falls as about h^3), but the error is not smooth in h (each contact's end falls anywhere
#: between two nodes), and on several contacts the difference in e alone can vanish by
#: coincidence (once 1/60 of the true error at h = 0.16). The error of e is therefore the largest
#: of every contact's speed difference, relative to that speed or e (:func:`_e_error`): over 100
#: first steps from 0.02 to 0.2 it was at least 2.2 times the true error on the benchmark's five
#: contacts, and at least 1.2 times on its one collision.
SAFETY = 2.0
#: The coarsest first step (a Hertz contact, 3.2 long, then has 16 nodes).
H_MAX = 0.2
#: Below FLOOR_ZONE (relative) a halving whose estimate is above STALL times the last one did
#: not reduce it (it should fall by about 2^2.5 = 5.7); two in a row, or one that grew, end the
#: search (the rounding floor, near 1e-11 on issue 37's five contacts: :func:`solve`). Above it
#: the estimate may rise between halvings (on the 100 mm plate at 9e-6) and the search goes on.
STALL = 0.5
FLOOR_ZONE = 1e-8
#: Absolute floor of the error target on e, relative to rtol (e can be nearly 0).
E_FLOOR = 1e-3
#: The most modes :func:`choose_modes` tries by default: a 600 mm glass square struck at its
#: centre by a steel ball (lambda 2.27, beta 3.1e-5) needs 16384 for rtol 1e-4 in e, and the
#: count needed grows as 1/beta; was 4096, when a solve with 16384 modes took ten times longer.
N_MAX = 65536


def check_plate(plate: ModalPlate) -> tuple[FloatArray, FloatArray, float]:
    """(omega, c, C_res) of a valid ModalPlate; ValueError saying what is wrong otherwise."""
    if not isinstance(plate, ModalPlate):
        raise ValueError(f"plate must be a zener_sym.plate.ModalPlate, got {type(plate).__name__}")
    omega = np.asarray(plate.omega, dtype=float)
    c = np.asarray(plate.c, dtype=float)
    if omega.ndim != 1 or c.shape != omega.shape or omega.size == 0:
        raise ValueError(f"plate.omega and plate.c must be 1-D arrays of the same nonzero length, "
                         f"got shapes {omega.shape} and {c.shape}")
    if not (np.all(np.isfinite(omega)) and np.all(omega > 0.0)):
        raise ValueError("plate.omega must be finite and > 0 (the modes' frequencies omega_n t_0)")
    if not (np.all(np.isfinite(c)) and np.all(c >= 0.0)):
        raise ValueError("plate.c must be finite and >= 0 (the modes' participations)")
    static = plate.static
    if not (isinstance(static, (int, float, np.floating)) and math.isfinite(static)
            and static > 0.0):
        raise ValueError(f"plate.static (the static compliance C_s m / t_0^2) must be a finite "
                         f"number > 0, got {static!r}")
    keep = c > 0.0       # a mode the ball cannot excite never moves
    if not np.any(keep):
        raise ValueError("plate.c is 0 for every mode: the impact point is a node of them all")
    res = plate.residual
    if res < -1e-9 * static:
        raise ValueError(f"plate.static = {static!r} is below the modes' own static compliance "
                         f"sum c_n / omega_n^2 = {static - res!r}: C_res must be >= 0")
    return omega[keep], c[keep], max(res, 0.0)


def first_step(rtol: float) -> float:
    """The coarsest step tried for rtol: the reported error of e fell about as h^{3.5} and was
    near rtol |e| at h = 0.2 (rtol / 2e-3)^{1/3.5} on the benchmark's plates (five contacts; one
    collision's was lower). Shorter contacts than Zener's are refined."""
    return float(min(H_MAX, 0.2 * (rtol / 2e-3) ** (1.0 / 3.5)))


def _check_options(rtol: float, loss: float) -> None:
    for name, val in (("rtol", rtol), ("loss", loss)):
        if isinstance(val, bool) or not isinstance(val, (int, float, np.floating)) \
                or not math.isfinite(val):
            raise ValueError(f"{name} must be a finite real number, got {val!r}")
    if not RTOL_MIN <= rtol <= RTOL_MAX:
        raise ValueError(f"rtol must be in [{RTOL_MIN:g}, {RTOL_MAX:g}], got {rtol!r}")
    if not 0.0 <= loss < 1.0:
        raise ValueError(f"loss (the modal loss factor eta) must be in [0, 1), got {loss!r}")


@dataclass
class _Run:
    """One whole impact at one step: its contacts and the proved end."""

    contacts: list[ContactRun]
    end_time: float


def _contact(r: Rates, c_res: float, h: float, kernels: dict[float, Kernel], t_s: float,
             x_s: float, v_s: float, B_s: ComplexArray, max_steps: int, q: int) -> ContactRun:
    """One contact at step h / 2^q, re-run on a finer grid when it has fewer than N_MIN nodes
    (the run's ``h`` says which grid it ended on)."""
    h = h / 2.0**q
    for _ in range(40):
        if h not in kernels:
            kernels[h] = Kernel(r, h)
        v_k, B_k, dI = start_kick(r, h, v_s, B_s)
        nodes = step_contact(kernels[h], c_res, x_s, v_k, B_k, max_steps)
        k = len(nodes.F) - 1
        if k >= N_MIN:
            break
        h = h / 2.0 ** math.ceil(math.log2(N_MIN / max(k - 1, 0.5)))
    else:
        raise RuntimeError(f"a contact at tau = {t_s:.6g} does not resolve (a graze?)")
    run = end_of_contact(kernels[h], t_s, nodes)
    run.defect += dI
    return run


def _run(r: Rates, c_res: float, h: float, max_contacts: int, max_steps: int,
         refine: list[int], kernels: dict[float, Kernel]) -> _Run:
    """The whole impact at step h. ``refine[j]``: contact j is stepped at h / 2^refine[j] (a
    short contact's finer grid, found on the coarsest level and kept on the finer ones, so that
    every contact's steps stay in the ratio 2 from level to level); grown here as needed.
    ``kernels``: the kernels by step, shared by the levels of one solve."""
    fl = Flight(0.0, 0.0, 1.0, np.zeros(len(r.s), dtype=complex))
    t_s: float | None = 0.0
    runs: list[ContactRun] = []
    while t_s is not None:
        if len(runs) >= max_contacts:
            raise RuntimeError(f"more than max_contacts = {max_contacts} contacts")
        x_s, B_s = fl.advanced(r, t_s)
        j = len(runs)
        if j == len(refine):
            refine.append(0)
        run = _contact(r, c_res, h, kernels, t_s, x_s, fl.v, B_s, max_steps, refine[j])
        refine[j] = max(refine[j], round(math.log2(h / run.h)))
        runs.append(run)
        fl = Flight(run.t_e, run.x_e, run.v_e, run.B_e)
        t_s = next_contact(r, fl, 1.0)
    end = fl.t_r + max(0.0, (fl.x_r + end_bound(r, fl.B)) / -fl.v) if fl.v < 0 else fl.t_r
    return _Run(runs, end)


def _comparable(levels: list[_Run]) -> bool:
    """Whether the levels have the same contacts, each stepped twice as finely as on the level
    before: otherwise their differences say nothing of the error (two levels on the same grid
    agree exactly, whatever their error)."""
    if len({len(lv.contacts) for lv in levels}) != 1:
        return False
    return all(math.isclose(a.h, 2.0 * b.h, rel_tol=1e-12)
               for lo, hi in zip(levels, levels[1:]) for a, b in zip(lo.contacts, hi.contacts))


def _fields(r: Rates, run: _Run) -> list[dict[str, float]]:
    rows = []
    for cr in run.contacts:
        tp, fp = cr.peak
        rows.append(dict(start=cr.t_s, end=cr.t_e, max_force_time=tp, max_force=fp,
                         impulse=cr.impulse, speed_after=-cr.v_e,
                         plate_energy=2.0 * r.energy(cr.B_e)))
    return rows


def _richardson(coarse: list[dict[str, float]], fine: list[dict[str, float]]) -> list[dict[str, float]]:
    return [{f: (4.0 * b[f] - a[f]) / 3.0 for f in CONTACT_FIELDS} for a, b in zip(coarse, fine)]


def solve(plate: ModalPlate, *, rtol: float = 1e-6, loss: float = 0.0, h: float | None = None,
          max_contacts: int = 1000, max_steps: int = 2_000_000,
          max_halvings: int = 12) -> PlateImpact:
    """The sphere's impact on a modal plate, with every contact to the proved end.

    Parameters
    ----------
    plate : ModalPlate
        The plate's modes seen from the impact point, in Zener's scales (:mod:`.modal`).
    rtol : float
        Relative tolerance on e (with an absolute floor of 1e-3 rtol), in [RTOL_MIN, RTOL_MAX]
        = [1e-10, 1e-2].
    loss : float
        Modal loss factor eta in [0, 1) (each mode: y'' + eta omega y' + omega^2 y = c F);
        0 (default) is the undamped plate.
    h : float, optional
        The first (coarsest) step tried; by default chosen from rtol.
    max_contacts, max_steps : int
        Refuse (RuntimeError) impacts with more contacts, or contacts with more steps.
    max_halvings : int
        How many times h may be halved to meet rtol (RuntimeError beyond).

    Returns
    -------
    PlateImpact

    Raises
    ------
    ValueError
        For an invalid plate, rtol or loss.
    """
    _check_options(rtol, loss)
    omega, c, c_res = check_plate(plate)
    r = Rates(omega, c, float(loss))
    h0 = float(h) if h is not None else first_step(rtol)
    if not (math.isfinite(h0) and h0 > 0.0):
        raise ValueError(f"h must be a finite step > 0, got {h!r}")
    refine: list[int] = []
    kernels: dict[float, Kernel] = {}
    levels = [_run(r, c_res, h0 / 2.0**i, max_contacts, max_steps, refine, kernels)
              for i in range(3)]
    hk = h0 / 4.0
    last, stalls = math.inf, 0
    for _ in range(max_halvings + 1):
        rows = [_fields(r, lv) for lv in levels]
        if _comparable(levels):
            r1, r2 = _richardson(rows[0], rows[1]), _richardson(rows[1], rows[2])
            errs = [{f: SAFETY * abs(b[f] - a[f]) for f in CONTACT_FIELDS} for a, b in zip(r1, r2)]
            e = r2[-1]["speed_after"]
            err = _e_error(r2, errs)
            if err <= rtol * max(abs(e), E_FLOOR):
                return _result(r2, errs, err, levels[2], hk, len(omega), loss, rtol)
            # near the rounding floor (below FLOOR_ZONE relative) an estimate that stops falling
            # has met it, and each further halving would only double the work; above it the
            # estimate need not fall monotonically (each contact's end moves between nodes)
            near = err <= FLOOR_ZONE * max(abs(e), E_FLOOR)
            stalls = stalls + 1 if near and err > STALL * last else 0
            if stalls >= 2 or (near and err > last):
                raise RuntimeError(
                    f"e's error estimate stopped falling at {err / max(abs(e), E_FLOOR):.2g} "
                    f"(relative) by h = {hk:.3g}: rtol = {rtol:g} is below the accuracy rounding "
                    "allows on this plate; ask for a looser rtol")
            last = err
        hk /= 2.0
        levels = [levels[1], levels[2], _run(r, c_res, hk, max_contacts, max_steps, refine,
                                                    kernels)]
    raise RuntimeError(f"e did not reach rtol = {rtol:g} by h = {hk:.3g} (contacts per level: "
                       f"{[len(lv.contacts) for lv in levels]})")


def _e_error(rows: list[dict[str, float]], errs: list[dict[str, float]]) -> float:
    """The reported error of e: the largest error of a contact's speed, relative to the larger of
    that speed and e, times e (an error in a slow rebound is not amplified: rounding alone would
    then exceed tight tolerances)."""
    e = abs(rows[-1]["speed_after"])
    return max(er["speed_after"] * e / max(abs(row["speed_after"]), e, 1e-300)
               for row, er in zip(rows, errs))


def _result(rows: list[dict[str, float]], errs: list[dict[str, float]], err: float, run: _Run,
            h: float, n: int, loss: float, rtol: float) -> PlateImpact:
    contacts = tuple(PlateContact(**row) for row in rows)
    t = [cr.t_s + cr.h * np.arange(len(cr.F)) for cr in run.contacts]
    f = [cr.F for cr in run.contacts]
    ends = [np.array([cr.t_e]) for cr in run.contacts]
    zero = np.zeros(1)
    return PlateImpact(contacts=contacts, e=rows[-1]["speed_after"],
                       plate_energy=rows[-1]["plate_energy"], error=err,
                       errors=tuple(errs), end_time=run.end_time, h=h, n_modes=n,
                       loss=float(loss), rtol=rtol,
                       force_time=np.concatenate([a for pair in zip(t, ends) for a in pair]),
                       force=np.concatenate([a for fk in f for a in (fk, zero)]))


def choose_modes(make: Callable[[int], ModalPlate], *, rtol: float = 1e-6, loss: float = 0.0,
                 n_start: int = 8, n_max: int = N_MAX) -> tuple[ModalPlate, PlateImpact]:
    """The plate with enough modes for rtol in e, and its impact.

    Doubles the mode count from ``n_start`` until e changes by less than rtol |e| (the modes left
    out respond quasi-statically and are in C_res), and returns the larger model and its result.

    Parameters
    ----------
    make : callable
        n -> ModalPlate with the n lowest modes (e.g. ``functools.partial(modal_plate, lam,
        beta, shape=..., support=...)`` with ``n_modes`` as the one left free).
    rtol, loss : float
        As for :func:`solve`.
    n_start, n_max : int
        The first mode count and the largest allowed (RuntimeError beyond).

    Returns
    -------
    (ModalPlate, PlateImpact)
    """
    _check_options(rtol, loss)
    n = int(n_start)
    if n < 1 or n_max < n:
        raise ValueError(f"need 1 <= n_start <= n_max, got {n_start!r}, {n_max!r}")
    plate = make(n)
    inner = max(rtol / 4.0, RTOL_MIN)   # each solve a little finer, within solve's range
    res = solve(plate, rtol=inner, loss=loss)
    while 2 * n <= n_max:
        plate2 = make(2 * n)
        res2 = solve(plate2, rtol=inner, loss=loss)
        if len(res2.contacts) == len(res.contacts) and \
                abs(res2.e - res.e) <= 0.5 * rtol * max(abs(res2.e), E_FLOOR):
            return plate2, res2
        n, plate, res = 2 * n, plate2, res2
    raise RuntimeError(f"e did not converge in the mode count up to n_max = {n_max}")


def warm_up() -> float:
    """Seconds to load the compiled loops (:mod:`.loops`), or to compile them on an
    installation's first solve: one solve of issue 37's five contacts with 12 modes, which calls
    every loop the solver uses. A caller that times solves calls this first."""
    import time

    from .modes import modal_plate

    t0 = time.perf_counter()
    solve(modal_plate(2.27, 4.5e-3, shape="circle", support="clamped", n_modes=12), rtol=1e-3)
    return time.perf_counter() - t0
