"""LAMMPS measured against the exact model: convergence in dt, the error law of e, and where
LAMMPS's integration loses the collision.

Every run is a head-on collision with the lines users paste (:mod:`zener_sym.bench.lammps.run`),
a glass sphere (radius 1 mm) on a steel wall or on a glass sphere, at 1 m/s, with the damping
coefficient that gives lambda (``zener_sym.scene.lammps``). The dimensionless answers (e, tau_d,
F_m of the viscoelastic force) are compared with the exact tables at the same end of contact.

- :func:`convergence`: per geometry, end of contact and lambda, a ladder of timesteps (20 to 5120
  steps per exact contact duration, doubling; finer rungs where the coarse ones are unstable),
  the errors, the observed order of convergence from the finest three rungs, and e extrapolated
  to dt -> 0 (Richardson with the observed order) against the exact e, with what the
  extrapolation resolves (the change of the extrapolate between the two finest triples).
- :func:`build_error_law`: |e_LAMMPS - e| over lambda and steps per contact, the worst of eight
  contact phases (where in its step the contact begins; two from ``LAW_FEW_PHASES`` steps on),
  on the wall; it is what
  ``zener-sym lammps`` reads for ``dt_max_s``.
- :func:`stability`: per lambda and end, the coarsest timestep on a descending ladder down to
  half a step per contact at which LAMMPS still gives the collision (ok: e within 10 % of the
  exact e, no energy gain, a contact, no blow-up), and how it fails one rung coarser.
"""
from __future__ import annotations

import csv
import io
import json
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from ...api import summary
from ...scene.lammps import E_TOLERANCE, LammpsContact, lammps_contact
from .run import Collision, Session, collide

__all__ = ["CONVERGENCE_LAMBDAS", "LADDER", "LAW_LAMBDAS", "LAW_STEPS", "PHASES",
           "STABILITY_LAMBDAS", "STABILITY_STEPS", "contacts", "run_lam", "convergence",
           "convergence_csv", "order_rows", "build_error_law", "error_law_json", "stability",
           "stability_csv", "table_csv"]

#: The lambdas of the convergence study (8, from 1e-3 to 30).
CONVERGENCE_LAMBDAS = (1e-3, 1e-2, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0)
#: Steps per contact of the convergence ladder (doubling).
LADDER = tuple(20 * 2**k for k in range(9))
#: Rungs the ladder may go on to where its coarse rungs are unstable (delta end, large lambda).
LADDER_EXTRA = tuple(20 * 2**k for k in range(9, 13))
#: The error law's lambdas and steps per contact.
LAW_LAMBDAS = (1e-3, 2e-3, 5e-3, 1e-2, 2e-2, 5e-2, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0,
               100.0, 200.0, 500.0, 1000.0)
LAW_STEPS = (10, 12, 14, 17, 20, 24, 30, 36, 43, 50, 60, 70, 85, 100, 120, 140, 170, 200, 250, 300,
             400, 500, 700, 1000, 1400, 2000, 3000, 5000, 10000, 20000, 50000, 100000)
#: From this many steps per contact on, the phase matters little: two phases are run, not eight.
LAW_FEW_PHASES = 1000
#: Where in its step the contact begins (the initial gap in steps of travel).
PHASES = tuple(k / 8 for k in range(8))
#: The stability study's lambdas and its descending ladder of steps per contact.
STABILITY_LAMBDAS = (1e-3, 1e-2, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0)
STABILITY_STEPS = (50000, 20000, 10000, 5000, 2000, 1000, 500, 350, 250, 180, 130, 100, 70, 50, 35,
                   25, 18, 13, 10, 7, 5, 3.5, 2.5, 1.8, 1.3, 1.0, 0.7, 0.5)
#: Impact speed of the studies [m/s].
SPEED = 1.0


def contacts() -> dict[str, LammpsContact]:
    """The studied contacts: a glass sphere (1 mm) on a steel wall, and on a glass sphere."""
    return {"wall": lammps_contact("glass", "1 mm", wall="steel"),
            "pair": lammps_contact("glass", "1 mm")}


@dataclass(frozen=True)
class Dimensionless:
    """A LAMMPS collision in the paper's scales: e, tau_d = t_c/T, F_m = F/(m_eff v/T)."""

    e: float
    tau_d: float
    F_m: float
    status: str
    seconds: float


def run_lam(session: Session, c: LammpsContact, lam: float, contact_end: str, steps: float,
            phase: float = 0.5, record: bool = True) -> Dimensionless:
    """One LAMMPS collision at lambda ``lam`` with ``steps`` steps per exact contact duration."""
    v = SPEED
    A = lam / float(c.rate(v))
    T = float(c.time_scale(v))
    s = summary(lam, model="exact", contact_end=contact_end)
    t_c = T * float(s.tau_d)
    r: Collision = collide(session, c, c.damping(A), contact_end, v, t_c / steps, t_c,
                           phase=phase, record=record, e_exact=float(s.e))
    return Dimensionless(r.e, r.contact_time_s / T, r.max_force_N * T / (c.m_eff * v),
                         r.status, r.seconds)


# --- convergence ---------------------------------------------------------------------------------

def convergence(lams: Sequence[float] = CONVERGENCE_LAMBDAS,
                ends: Sequence[str] = ("force", "delta"),
                geometries: Sequence[str] = ("wall", "pair"), ladder: Sequence[int] = LADDER,
                log: Callable[[str], object] = lambda s: None) -> list[dict[str, Any]]:
    """Rows (geometry, contact_end, lambda, steps, e, e_exact, e_err, tau_d_err, F_m_err,
    status) of the convergence ladder; see the module docstring."""
    cs = contacts()
    rows: list[dict[str, Any]] = []
    with Session() as ses:
        for geo in geometries:
            for end in ends:
                for lam in lams:
                    ex = summary(lam, model="exact", contact_end=end)
                    F_ref = float(summary(lam, model="exact", contact_end="force").F_m)
                    rungs = list(ladder)
                    extra = list(LADDER_EXTRA)
                    got: list[dict[str, Any]] = []
                    while rungs:
                        n = rungs.pop(0)
                        r = run_lam(ses, cs[geo], lam, end, n)
                        got.append({"geometry": geo, "contact_end": end, "lambda": lam, "steps": n,
                                    "e": r.e, "e_exact": float(ex.e), "e_err": r.e - float(ex.e),
                                    "tau_d_err": r.tau_d / float(ex.tau_d) - 1.0,
                                    "F_m_err": r.F_m / F_ref - 1.0, "status": r.status})
                        ok = [g for g in got if g["status"] == "ok"]
                        if not rungs and len(ok) < 4 and extra:
                            rungs.append(extra.pop(0))  # coarse rungs unstable: go finer
                    rows += got
                    log(f"  convergence {geo} {end} lambda={lam:g}: done")
    return rows


def _fmt(x: Any) -> str:
    if isinstance(x, float):
        return "nan" if not math.isfinite(x) else f"{x:.10g}"
    return str(x)


def table_csv(rows: Sequence[dict[str, Any]], cols: Sequence[str]) -> str:
    """``rows``' columns ``cols`` as CSV text (floats to 10 digits, NaN as nan)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(cols)
    for r in rows:
        w.writerow([_fmt(r[c]) for c in cols])
    return buf.getvalue()


def convergence_csv(rows: Sequence[dict[str, Any]]) -> str:
    """The ladder's rows as CSV text."""
    return table_csv(rows, ["geometry", "contact_end", "lambda", "steps", "e", "e_exact", "e_err",
                            "tau_d_err", "F_m_err", "status"])


def order_rows(rows: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per (geometry, end, lambda): the observed order p from the finest three ok rungs
    (log2 of the ratio of successive differences), the extrapolate e_inf = e_N + (e_N -
    e_{N/2})/(2^p - 1), its error against the exact e, and what the extrapolation resolves (the
    change of e_inf between the finest two triples)."""
    out: list[dict[str, Any]] = []
    keys = sorted({(r["geometry"], r["contact_end"], r["lambda"]) for r in rows},
                  key=lambda k: (k[0], k[1], k[2]))
    for geo, end, lam in keys:
        ok = [r for r in rows if (r["geometry"], r["contact_end"], r["lambda"]) == (geo, end, lam)
              and r["status"] == "ok"]
        ok.sort(key=lambda r: r["steps"])
        e = [r["e"] for r in ok]
        e_exact = ok[-1]["e_exact"] if ok else float("nan")

        def extrapolate(a: float, b: float, c: float) -> tuple[float, float]:
            # a, b, c at N/4, N/2, N: differences shrink by 2^p per doubling
            d1, d2 = b - a, c - b
            p = math.log2(abs(d1 / d2)) if d1 != 0 and d2 != 0 else float("nan")
            if not math.isfinite(p) or p <= 0:
                return p, float("nan")
            return p, c + d2 / (2.0**p - 1.0)

        p = e_inf = res = float("nan")
        if len(e) >= 3:
            p, e_inf = extrapolate(*e[-3:])
        if len(e) >= 4:
            _, prev = extrapolate(*e[-4:-1])
            res = abs(e_inf - prev)
        out.append({"geometry": geo, "contact_end": end, "lambda": lam, "order": p,
                    "steps_used": f"{ok[0]['steps']}-{ok[-1]['steps']}" if ok else "",
                    "e_exact": e_exact, "e_finest_err": (e[-1] - e_exact) if e else float("nan"),
                    "e_extrapolated_err": e_inf - e_exact, "resolution": res})
    return out


# --- the error law --------------------------------------------------------------------------------

def build_error_law(lams: Sequence[float] = LAW_LAMBDAS, steps: Sequence[int] = LAW_STEPS,
                    phases: Sequence[float] = PHASES,
                    log: Callable[[str], object] = lambda s: None) -> dict[str, Any]:
    """|e_LAMMPS - e| on the wall over ``lams`` x ``steps``, the worst of ``phases``; NaN where a
    phase's collision is not ``ok`` (LAMMPS lost it)."""
    c = contacts()["wall"]
    error: dict[str, list[list[float]]] = {}
    with Session() as ses:
        for end in ("force", "delta"):
            table = []
            for lam in lams:
                row = []
                for n in steps:
                    worst = 0.0
                    for ph in (phases if n < LAW_FEW_PHASES else phases[::len(phases) // 2]):
                        r = run_lam(ses, c, lam, end, n, phase=ph, record=False)
                        e_ex = float(summary(lam, model="exact", contact_end=end).e)
                        worst = float("nan") if r.status != "ok" or not math.isfinite(worst) \
                            else max(worst, abs(r.e - e_ex))
                    row.append(worst)
                table.append(row)
                log(f"  error law {end} lambda={lam:g}: done")
            error[end] = table
    return {"about": "|e_LAMMPS - e_exact| (absolute), the worst of the contact phases, for a "
                     "head-on collision on a wall with pair_style/fix wall/gran granular "
                     "hertz/material, damping viscoelastic; rows lambda, columns steps per exact "
                     "contact duration; null: LAMMPS lost the collision (see lammps_stability)",
            "lambdas": list(lams), "steps": list(steps), "phases": list(phases),
            "e_tolerance": E_TOLERANCE, "error": error}


def error_law_json(law: dict[str, Any]) -> str:
    """The error law as committed JSON text (NaN as null, 4 significant digits)."""
    def clean(x: Any) -> Any:
        if isinstance(x, float):
            return None if not math.isfinite(x) else float(f"{x:.4g}")
        if isinstance(x, list):
            return [clean(y) for y in x]
        if isinstance(x, dict):
            return {k: clean(v) for k, v in x.items()}
        return x

    return json.dumps(clean(law), indent=1, sort_keys=True) + "\n"


# --- stability -----------------------------------------------------------------------------------

def stability(lams: Sequence[float] = STABILITY_LAMBDAS, steps: Sequence[float] = STABILITY_STEPS,
              phases: Sequence[float] = (0.25, 0.5, 0.75),
              log: Callable[[str], object] = lambda s: None) -> list[dict[str, Any]]:
    """Per lambda and end (wall): the coarsest rung of ``steps`` (descending) down to which every
    rung and phase is ``ok``, its e, the exact e, and the first failure one rung coarser."""
    c = contacts()["wall"]
    rows: list[dict[str, Any]] = []
    with Session() as ses:
        for end in ("force", "delta"):
            for lam in lams:
                e_ex = float(summary(lam, model="exact", contact_end=end).e)
                limit = e_limit = e_fail = float("nan")
                failure = "none on the ladder"
                for n in steps:
                    runs = [run_lam(ses, c, lam, end, n, phase=ph, record=False) for ph in phases]
                    bad = [r for r in runs if r.status != "ok"]
                    if bad:
                        failure, e_fail = bad[0].status, bad[0].e
                        break
                    limit, e_limit = n, max((r.e for r in runs), key=lambda x: abs(x - e_ex))
                rows.append({"contact_end": end, "lambda": lam, "e_exact": e_ex,
                             "steps_at_limit": limit, "e_at_limit": e_limit,
                             "failure_beyond": failure, "e_beyond": e_fail})
                log(f"  stability {end} lambda={lam:g}: limit {limit} steps ({failure} beyond)")
    return rows


def stability_csv(rows: Sequence[dict[str, Any]]) -> str:
    """The stability rows as CSV text."""
    return table_csv(rows, ["contact_end", "lambda", "e_exact", "steps_at_limit", "e_at_limit",
                            "failure_beyond", "e_beyond"])

