"""The finite-plate solver against scipy's DOP853 on the same modal system (issue 37, section 2).

DOP853 integrates the 2N + 2 first-order equations of :mod:`zener_sym.plate.modal`,

    x' = v,  v' = -F,  y_n' = u_n,  u_n' = -eta omega_n u_n - omega_n^2 y_n + c_n F,

with F = max(delta, 0)^{3/2} and delta = x - sum y_n - C_res F solved per call (Newton on
u = F^{1/3}). Events stop it at each contact's start (x - sum y_n rising through 0) and end
(falling through 0), so it never steps across the kink, and after each separation at the same
proved end as the fast solver (x < -sqrt(2 E_p C_N) moving away). Both solve the same plate to the
same end; the work-precision table gives each method's time against its error in e, measured
against the fast solver at rtol 1e-10 (which DOP853 at its tightest tolerance confirms to
about 6e-10).

Run ``python -m zener_sym.bench.plate [--quick] [--out DIR]``.
"""
from __future__ import annotations

import argparse
import csv
import functools
import math
import pathlib
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import i0e, i1e, j0, j1

from ..plate.modal import ModalPlate
from ..plate.solver import check_plate, solve
from ..typing import FloatArray
from .timing import timed

__all__ = ["dop853_impact", "clamped_circle", "measure", "write_chart", "main", "Dop853Impact",
           "targets", "TARGET_TOLS"]


@dataclass(frozen=True)
class Dop853Impact:
    """DOP853's answer: e, each contact's (start, end, speed after), and the work done."""

    e: float
    contacts: tuple[tuple[float, float, float], ...]
    nfev: int


def _force(d: float, a: float) -> float:
    """F with F = max(d - a F, 0)^{3/2}."""
    if d <= 0.0:
        return 0.0
    if a == 0.0:
        return d * math.sqrt(d)
    u = math.sqrt(d)
    for _ in range(60):
        du = (u * u * (1.0 + a * u) - d) / (u * (2.0 + 3.0 * a * u))
        u -= du
        if du <= 4e-16 * u:
            break
    return u * u * u


def dop853_impact(plate: ModalPlate, *, rtol: float, atol: float | None = None,
                  loss: float = 0.0, max_contacts: int = 100) -> Dop853Impact:
    """The impact by DOP853 with events (see the module docstring)."""
    omega, c, c_res = check_plate(plate)
    n = len(omega)
    atol = rtol * 1e-3 if atol is None else atol
    w2, damp = omega**2, loss * omega

    def rhs(t: float, z: FloatArray) -> FloatArray:
        y, u = z[2:2 + n], z[2 + n:]
        F = _force(z[0] - float(np.sum(y)), c_res)
        out = np.empty_like(z)
        out[0], out[1] = z[1], -F
        out[2:2 + n] = u
        out[2 + n:] = -damp * u - w2 * y + c * F
        return out

    def gap(t: float, z: FloatArray) -> float:
        return float(z[0] - np.sum(z[2:2 + n]))

    z = np.zeros(2 * n + 2)
    z[1] = 1.0
    t, nfev = 0.0, 0
    contacts: list[tuple[float, float, float]] = []
    while len(contacts) < max_contacts:
        t_s = t
        ev_end = _event(gap, -1.0)
        sol = solve_ivp(rhs, (t, t + 1e6), z, method="DOP853", rtol=rtol, atol=atol,
                        events=ev_end, first_step=min(1e-3, rtol ** 0.25))
        nfev += sol.nfev
        t, z = float(sol.t_events[0][0]), sol.y_events[0][0]
        contacts.append((t_s, t, -float(z[1])))
        y, u = z[2:2 + n], z[2 + n:]
        R = math.sqrt(2.0 * float(np.sum((u * u + w2 * y * y) / (2.0 * c)))
                      * float(np.sum(c / w2)))
        if z[1] < 0.0 and z[0] < -R:
            break
        ev_hit = _event(gap, 1.0)
        ev_out = _event(lambda t, z: float(z[0] + R), -1.0)
        sol = solve_ivp(rhs, (t, t + 1e6), z, method="DOP853", rtol=rtol, atol=atol,
                        events=[ev_hit, ev_out], first_step=1e-3)
        nfev += sol.nfev
        if len(sol.t_events[1]) and (not len(sol.t_events[0])
                                     or sol.t_events[1][0] < sol.t_events[0][0]):
            break
        t, z = float(sol.t_events[0][0]), sol.y_events[0][0]
    return Dop853Impact(e=contacts[-1][2], contacts=tuple(contacts), nfev=nfev)


def _event(fn: Callable[[float, FloatArray], float],
           direction: float) -> Callable[[float, FloatArray], float]:
    def ev(t: float, z: FloatArray) -> float:
        return fn(t, z)
    ev.terminal = True            # type: ignore[attr-defined]
    ev.direction = direction      # type: ignore[attr-defined]
    return ev


@functools.lru_cache(maxsize=4)
def _clamped_roots(n: int) -> FloatArray:
    """The first n roots x of J0(x) I1(x) + I0(x) J1(x) = 0 (the clamped circle's axisymmetric
    modes, x = k b), bracketed near n pi and refined by brentq."""

    def f(x: float) -> float:
        return float(j0(x) * i1e(x) / i0e(x) + j1(x))

    return np.array([brentq(f, (k + 1) * math.pi - 1.0, (k + 1) * math.pi + 1.0, xtol=1e-14)
                     for k in range(n)])


def clamped_circle(lam: float, beta: float, n_modes: int) -> ModalPlate:
    """The clamped circle struck at its centre, n_modes modes (for the benchmark and until
    :mod:`zener_sym.plate.modes` is merged): Omega_n = x_n^2, psi_n = phi_n(0)^2 / (2 pi J0(x_n)^2)
    with phi_n = J0(x_n r/b) - J0(x_n) I0(x_n r/b) / I0(x_n), and S = 1/(16 pi)."""
    x = _clamped_roots(n_modes)
    psi = (1.0 - j0(x) * np.exp(-x) / i0e(x)) ** 2 / (2.0 * math.pi * j0(x) ** 2)
    return ModalPlate(omega=beta * x**2, c=8.0 * lam * beta * psi,
                      static=8.0 * lam / beta / (16.0 * math.pi), support="clamped",
                      shape="circle")


#: The benchmark's cases: (name, lambda, beta, modes). "one collision": the paper's FEM plate
#: (table1 sphere R 0.9 mm on 0.5 mm table1 glass at 1 m/s, clamped at 150 mm); "five contacts":
#: issue 37's steel ball (R 2.5 mm, 1 m/s) on 1 mm glass clamped at 50 mm. The mode counts are
#: those that give e to 1e-6 of the whole plate (doubling them changes e by 1.2e-8 and 3.3e-8;
#: halving them by 7.4e-7 and 2.0e-6).
CASES = (("one collision", 0.16298219961216695, 7.31951524768407e-05, 400),
         ("five contacts", 2.2678187414945676, 0.00453106140411585, 80))


def measure(quick: bool = False, log: Callable[[str], object] = print) -> list[dict[str, object]]:
    """Rows (case, method, tol, error in e, seconds) for both methods on each case."""
    rows: list[dict[str, object]] = []
    for name, lam, beta, n in CASES:
        plate = clamped_circle(lam, beta, n)
        ref = solve(plate, rtol=1e-10).e
        fast_tols = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9) if not quick else (1e-4, 1e-6)
        dop_tols = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8) if not quick else (1e-5, 1e-7)
        for tol in fast_tols:
            res, sec = timed(lambda: solve(plate, rtol=tol), min_repeats=3 if not quick else 1)
            rows.append(dict(case=name, method="fast", tol=tol, error=abs(res.e - ref) / ref,
                             seconds=sec, contacts=res.n_contacts))
            log(f"{name}: fast rtol {tol:g}: err {abs(res.e - ref) / ref:.2e} in {sec:.4f} s")
        for tol in dop_tols:
            # a run under a second is timed three more times (median), as the fast solver's are
            res2, sec = timed(lambda: dop853_impact(plate, rtol=tol), min_repeats=3,
                              min_total=1.0, max_repeats=3)
            rows.append(dict(case=name, method="DOP853", tol=tol,
                             error=abs(res2.e - ref) / ref, seconds=sec,
                             contacts=len(res2.contacts)))
            log(f"{name}: DOP853 rtol {tol:g}: err {abs(res2.e - ref) / ref:.2e} in {sec:.3f} s "
                f"({res2.nfev} calls, {len(res2.contacts)} contacts)")
    return rows


#: The report's speed targets (:func:`targets`): per case, the tolerances of each method's
#: cheapest run to 1e-6 in e in the committed work-precision table (the solver's, DOP853's).
TARGET_TOLS = {"one collision": (1e-3, 1e-5), "five contacts": (1e-5, 1e-5)}


def targets(quick: bool = False) -> list[dict[str, Any]]:
    """Issue 37's promise as rows of the report's speed-target table: on each case, the solver
    against DOP853 at the tolerances of their cheapest runs to 1e-6 in e (:data:`TARGET_TOLS`),
    side by side, required 100x. A row whose runs miss 1e-6 (against the solver at rtol 1e-10)
    says so and is not met."""
    rows: list[dict[str, Any]] = []
    for name, lam, beta, n in CASES:
        plate = clamped_circle(lam, beta, n)
        ref = solve(plate, rtol=1e-10).e
        fast_tol, dop_tol = TARGET_TOLS[name]
        fast, t_fast = timed(lambda: solve(plate, rtol=fast_tol),
                             min_repeats=1 if quick else 5)
        dop, t_dop = timed(lambda: dop853_impact(plate, rtol=dop_tol),
                           min_repeats=1 if quick else 3, min_total=1.0, max_repeats=3)
        e_fast, e_dop = abs(fast.e - ref) / abs(ref), abs(dop.e - ref) / abs(ref)
        rows.append({"target": f"finite-plate solver vs DOP853 on the same modes, {name}",
                     "grid": f"{n} modes, rtol {fast_tol:g} vs {dop_tol:g}, errors in e "
                             f"{e_fast:.1e} and {e_dop:.1e}",
                     "fast_s": t_fast, "slow_s": t_dop, "ratio": t_dop / t_fast,
                     "required": 100.0,
                     "met": max(e_fast, e_dop) <= 1e-6 and t_dop / t_fast >= 100.0})
    return rows


def speedup_at(rows: Sequence[dict[str, object]], case: str, error: float) -> float:
    """DOP853's time over the fast solver's at the same error in e (log-log interpolation of
    each method's work-precision curve, the cheapest run at or below ``error``)."""
    out = []
    for method in ("fast", "DOP853"):
        pts = sorted((float(r["error"]), float(r["seconds"])) for r in rows  # type: ignore[arg-type]
                     if r["case"] == case and r["method"] == method)
        ok = [s for err, s in pts if err <= error]
        out.append(min(ok) if ok else float("nan"))
    return out[1] / out[0]


def write_chart(rows: Sequence[dict[str, object]], path: pathlib.Path) -> pathlib.Path:
    """The work-precision chart: seconds against the error in e, both methods, each case."""
    from ..plot import style

    with style.rc() as plt:
        fig, axes = plt.subplots(1, len(CASES), figsize=(style.PAGE_WIDTH, 2.8), sharey=True)
        for ax, (name, *_rest) in zip(np.atleast_1d(axes), CASES):
            colour, marker = style.METHOD_STYLES["DOP853"]
            for method, kw in (("fast", dict(style.style_for("finite-plate"),
                                             label="modal stepping (zener_sym.plate)")),
                               ("DOP853", dict(color=colour, marker=marker, linestyle="--",
                                               label="DOP853, same modal system"))):
                # each method's runs in the order of its tolerances (the work-precision path)
                pts = [(float(r["error"]), float(r["seconds"])) for r in rows  # type: ignore[arg-type]
                       if r["case"] == name and r["method"] == method]
                ax.loglog([max(p[0], 1e-13) for p in pts], [p[1] for p in pts], **kw)
            ax.set_title(name)
            ax.set_xlabel(r"relative error in $e$")
        np.atleast_1d(axes)[0].set_ylabel("time per impact (s)")
        style.legend_outside(fig, *np.atleast_1d(axes)[0].get_legend_handles_labels())
        style.save(fig, path)
        plt.close(fig)
    return path


def main(argv: Sequence[str] | None = None) -> int:
    """Command line: measure, print the table and the speedups, write the chart."""
    ap = argparse.ArgumentParser(prog="python -m zener_sym.bench.plate", description=__doc__)
    ap.add_argument("--quick", action="store_true", help="fewer tolerances, fewer repeats")
    ap.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."),
                    help="folder for plate_workprecision.png and .csv")
    args = ap.parse_args(argv)
    t0 = time.perf_counter()
    rows = measure(args.quick)
    for name, *_ in CASES:
        for err in (1e-5, 1e-6, 1e-7):
            print(f"{name}: DOP853 / fast at error {err:g} in e: "
                  f"{speedup_at(rows, name, err):.0f}x")
    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "plate_workprecision.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(write_chart(rows, args.out / "plate_workprecision.png"))
    print(f"total {time.perf_counter() - t0:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
