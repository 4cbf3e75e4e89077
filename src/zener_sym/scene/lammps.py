"""zener-sym for LAMMPS users: the viscoelastic Hertz contact of LAMMPS's GRANULAR package mapped
onto Zener's equation, and the input lines that give a chosen A or a measured e.

LAMMPS's ``hertz/material`` normal model with ``damping viscoelastic`` (``pair_style granular``
and ``fix wall/gran granular``) is the grain reading of Eq. (10): ``zener_sym.derivation.lammps``
derives, by substitution and by units,

    eta_n0 = 2 E* A / m_eff,   A = eta_n0 m_eff / (2 E*),   E_L = 2 (1 - nu_L^2) E*,

with eta_n0 the damping coefficient of the line [1/(s m)], E* the contact's effective modulus,
m_eff the effective mass (the sphere's own on a wall) and (E_L, nu_L) the modulus and Poisson
ratio written on a ``pair_coeff * *`` or wall line: LAMMPS forms E_L/(2 (1 - nu_L^2)) from one
line, for a type with itself and for a wall (which it takes to be of the particle's material),
so E_L = 2 (1 - nu_L^2) E* gives the E* of any pair of materials (E_L = E for one material).
``limit_damping`` (no attractive force) is the force-free end, ``contact_end="force"``; without
it contact lasts to delta = 0, ``"delta"``.

LAMMPS's damping is proportional to m_eff, so one eta_n0 is one A only for one m_eff: a
polydisperse LAMMPS system has A proportional to m_eff (the docs page says what follows).

The timestep column ``dt_max_s`` reads LAMMPS's measured error law (``data/lammps_error_law.json``,
rebuilt by ``zener-sym regen lammps-error-law`` from LAMMPS runs in
:mod:`zener_sym.bench.lammps.studies`).
"""
from __future__ import annotations

import functools
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..api import lam_from_summary, summary
from ..exact.force_end import check_contact_end
from ..exact.solver import LAMBDA_MAX
from ..typing import FloatArray
from .grains import grain_contact
from .materials import Material, get_material
from .scaling import sphere_mass
from .units import si_value

__all__ = ["LammpsContact", "lammps_contact", "LammpsSetup", "lammps_setup", "ERROR_LAW_PATH",
           "error_law", "steps_required", "input_lines", "E_TOLERANCE", "TANGENTIAL"]

#: The measured error law of LAMMPS's e (package data, ``zener-sym regen lammps-error-law``).
ERROR_LAW_PATH = Path(__file__).resolve().parent.parent / "data" / "lammps_error_law.json"
#: The accuracy in e that ``dt_max_s`` keeps (absolute).
E_TOLERANCE = 1e-3
#: ``dt_max_s`` aims at this fraction of the tolerance: the law samples eight contact phases and
#: a ladder of lambdas and steps, and a contact may begin between the sampled phases (where the
#: error was measured up to 11 % above the sampled worst) and at a lambda between the rows.
MARGIN = 0.7
#: The tangential model written on the lines: frictionless, so that the normal contact alone is
#: what zener-sym describes (head-on impacts do not load it; replace it for oblique impacts).
TANGENTIAL = "tangential linear_nohistory 0.0 0.0"


def _num(x: float) -> str:
    """A float as LAMMPS reads it back to the same double (shortest round-trip repr)."""
    return repr(float(x))


@dataclass(frozen=True)
class LammpsContact:
    """One contact as LAMMPS sees it: a pair of spheres or a sphere on a flat wall (SI units).

    Attributes
    ----------
    geometry : {"pair", "wall"}
    E_star, m_eff, R_eff, rho : float
        Effective modulus [Pa], effective mass [kg], effective radius [m], Hertz constant
        (4/3) E* sqrt(R_eff) [N/m^{3/2}], as :func:`zener_sym.scene.grains.grain_contact`.
    E_lammps, nu_lammps : float
        The E [Pa] and nu written on the ``pair_coeff * *`` or wall line: E_L = 2 (1 - nu_L^2) E*,
        nu_L the first sphere's.
    radius1, density1, mass1 : float
        Sphere 1 [m], [kg/m^3], [kg] (the mass as LAMMPS's ``set ... diameter ... density``).
    radius2, density2, mass2 : float or None
        Sphere 2 (None on a wall).
    """

    geometry: str
    E_star: float
    m_eff: float
    R_eff: float
    rho: float
    E_lammps: float
    nu_lammps: float
    radius1: float
    density1: float
    mass1: float
    radius2: float | None = None
    density2: float | None = None
    mass2: float | None = None

    def damping(self, A: float) -> float:
        """LAMMPS's damping coefficient eta_n0 = 2 E* A / m_eff [1/(s m)] (derivation L1)."""
        return 2.0 * self.E_star * A / self.m_eff

    def dissipation(self, eta_n0: float) -> float:
        """The dissipative constant A = eta_n0 m_eff / (2 E*) [s] of a damping coefficient (L2)."""
        return eta_n0 * self.m_eff / (2.0 * self.E_star)

    def rate(self, v: float | FloatArray) -> float | FloatArray:
        """lambda / A = (rho/m_eff)^{2/5} v^{1/5} [1/s] at normal speed ``v`` [m/s]."""
        r: FloatArray = (self.rho / self.m_eff) ** 0.4 * np.asarray(v, dtype=float) ** 0.2
        return float(r) if r.ndim == 0 else r

    def time_scale(self, v: float | FloatArray) -> float | FloatArray:
        """T = (m_eff/rho)^{2/5} v^{-1/5} [s]: tau = t/T."""
        r: FloatArray = (self.m_eff / self.rho) ** 0.4 * np.asarray(v, dtype=float) ** -0.2
        return float(r) if r.ndim == 0 else r

    def model_line(self, eta_n0: float, contact_end: str) -> str:
        """The model part of a ``pair_coeff`` or wall line (hertz/material ... [limit_damping])."""
        end = check_contact_end(contact_end)
        limit = " limit_damping" if end == "force" else ""
        return (f"hertz/material {_num(self.E_lammps)} {_num(eta_n0)} {_num(self.nu_lammps)} "
                f"{TANGENTIAL} damping viscoelastic{limit}")


def lammps_contact(sphere: Material | str, radius: float | str, *,
                   sphere2: Material | str | None = None, radius2: float | str | None = None,
                   wall: Material | str | None = None) -> LammpsContact:
    """The contact of two spheres (``sphere2``/``radius2`` default to the first), or of a sphere
    on a flat wall of material ``wall``, with masses from the materials' densities.

    Parameters
    ----------
    sphere : Material or str
        The (first) sphere's material, a ``zener_sym.Material`` or a preset name.
    radius : float or str
        Its radius [m] or a string with a unit (``"1 mm"``).
    sphere2, radius2 : optional
        The second sphere (default: the first one's material and radius).
    wall : Material or str, optional
        A flat wall's material; then no second sphere.

    Returns
    -------
    LammpsContact

    Raises
    ------
    ValueError
        For an unknown material, a radius without a unit or out of range, or both a wall and a
        second sphere.

    Examples
    --------
    >>> from zener_sym.scene.lammps import lammps_contact
    >>> c = lammps_contact("glass", "1 mm", wall="steel")
    >>> c.geometry, round(c.E_star / 1e9, 3), round(c.E_lammps / 1e9, 3)
    ('wall', 55.729, 105.953)
    """
    if wall is not None and (sphere2 is not None or radius2 is not None):
        raise ValueError("give either a wall or a second sphere (sphere2, radius2), not both")
    mat1 = get_material(sphere)
    R1 = si_value(radius, "length", "radius")
    m1 = sphere_mass(R1, mat1.rho)
    if wall is not None:
        c = grain_contact(mat1, R1, m1, wall=get_material(wall))
        R2 = rho2 = m2 = None
        geometry = "wall"
    else:
        mat2 = get_material(sphere2 if sphere2 is not None else mat1)
        R2 = si_value(radius2 if radius2 is not None else R1, "length", "radius2")
        rho2, m2 = mat2.rho, sphere_mass(R2, mat2.rho)
        c = grain_contact(mat1, R1, m1, sphere2=mat2, radius2=R2, mass2=m2)
        geometry = "pair"
    nu = mat1.nu
    return LammpsContact(geometry=geometry, E_star=c.E_star, m_eff=c.m_eff, R_eff=c.R_eff,
                         rho=c.rho, E_lammps=2.0 * (1.0 - nu**2) * c.E_star, nu_lammps=nu,
                         radius1=R1, density1=mat1.rho, mass1=m1, radius2=R2, density2=rho2,
                         mass2=m2)


# --- LAMMPS's measured error law ---------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def error_law() -> dict[str, Any]:
    """The committed error law: ``lambdas``, ``steps`` (per contact), and per end of contact the
    largest |e_LAMMPS - e| over the contact phases, shape (lambdas, steps), NaN where LAMMPS lost
    the collision."""
    data: dict[str, Any] = json.loads(ERROR_LAW_PATH.read_text(encoding="utf-8"))
    return data


def steps_required(lam: float, contact_end: str, tol: float = E_TOLERANCE) -> float:
    """Steps per contact (the exact contact duration over dt) that keep LAMMPS's e within ``tol``
    of the exact e, from the measured error law (aiming at ``MARGIN`` times ``tol``).

    The error at each ladder rung is interpolated in log lambda between the measured lambdas
    (below the smallest, its row: the error falls with lambda there); the answer is the coarsest
    rung from which on every finer rung meets ``tol``, refined by log-log interpolation towards
    the next coarser rung. ``inf`` when even the finest rung misses ``tol``; NaN above the
    largest measured lambda (not measured: no answer is guessed).
    """
    end = check_contact_end(contact_end)
    law = error_law()
    lams = np.asarray(law["lambdas"], dtype=float)
    steps = np.asarray(law["steps"], dtype=float)
    err = np.array([[np.inf if v is None else v for v in row] for row in law["error"][end]],
                   dtype=float)  # (lambdas, steps); null: LAMMPS lost the collision
    tol = MARGIN * tol
    if lam > lams[-1] * (1 + 1e-12):
        return math.nan
    x = math.log(max(lam, lams[0]))
    lx = np.log(lams)
    j = int(np.clip(np.searchsorted(lx, x) - 1, 0, len(lams) - 2))
    w = (x - lx[j]) / (lx[j + 1] - lx[j])
    with np.errstate(divide="ignore", invalid="ignore"):
        le = np.log(np.maximum(err, 1e-300))
        row = np.exp((1 - w) * le[j] + w * le[j + 1])
    ok = row <= tol
    if not ok[-1]:
        return math.inf
    k = len(steps) - 1
    while k > 0 and ok[k - 1]:
        k -= 1
    if k == 0:
        return float(steps[0])  # met on the whole ladder: its coarsest rung
    # between rung k-1 (misses) and k (meets): log-log interpolation of the error to tol
    e0, e1 = math.log(row[k - 1]), math.log(row[k])
    if not math.isfinite(e0):
        return float(steps[k])
    f = (e0 - math.log(tol)) / (e0 - e1)
    lo, hi = math.log(steps[k - 1]), math.log(steps[k])
    return float(math.exp(lo + f * (hi - lo)))


# --- from a target to the lines ----------------------------------------------------------------

@dataclass(frozen=True)
class LammpsSetup:
    """What :func:`lammps_setup` gives: the lines to paste and the table over speeds.

    Attributes
    ----------
    contact : LammpsContact
    A_s : float
        Dissipative constant [s].
    damping : float
        LAMMPS's damping coefficient eta_n0 [1/(s m)].
    contact_end : {"force", "delta"}
        ``"force"``: the lines carry ``limit_damping``.
    lines : dict of str
        ``pair_style`` and ``pair_coeff`` (two spheres) or ``fix_wall`` (a wall), and ``set``
        (the particle lines that give LAMMPS the masses used here).
    table : list of dict
        Per speed: ``v_m_s``, ``lambda``, ``e``, ``contact_time_s`` (first touch to the end of
        contact), ``max_force_N`` (peak of the viscoelastic force), ``dt_max_s`` (the largest
        timestep that keeps LAMMPS's e within ``E_TOLERANCE`` of ``e``, from the error law;
        None above the law's largest lambda, 0.0 where no measured timestep is fine enough).
    """

    contact: LammpsContact
    A_s: float
    damping: float
    contact_end: str
    lines: dict[str, str] = field(repr=False)
    table: list[dict[str, float | None]] = field(repr=False)

    def text(self) -> list[str]:
        """The text output of ``zener-sym lammps``: the lines to paste, then the table."""
        c = self.contact
        what = "two spheres" if c.geometry == "pair" else "a sphere on a flat wall at z = 0"
        end = (" (limit_damping: no attractive force)" if self.contact_end == "force" else
               " (delta = 0: the force turns attractive before)")
        out = [f"# LAMMPS (units si, atom_style sphere, comm_modify vel yes, fix nve/sphere): "
               f"{what}",
               f"# E* = {c.E_star:.6g} Pa, m_eff = {c.m_eff:.6g} kg, R_eff = {c.R_eff:.6g} m; "
               f"contact end: {self.contact_end}{end}", ""]
        out += [line for key in ("set", "pair_style", "pair_coeff", "fix_wall")
                if key in self.lines for line in self.lines[key].splitlines()]
        out += ["", f"A = {self.A_s:.6g} s   damping coefficient eta_n0 = {self.damping:.6g} "
                    f"1/(s m)", "",
                f"| v (m/s) | lambda | e | contact time (s) | peak force (N) | dt_max (s), "
                f"|e_LAMMPS - e| <= {E_TOLERANCE:g} |", "|---|---|---|---|---|---|"]
        for r in self.table:
            d = r["dt_max_s"]
            dt = ("— (lambda beyond the measured law)" if d is None
                  else "— (finer than the measured steps)" if d == 0.0 else f"{d:.3g}")
            out.append(f"| {r['v_m_s']:.4g} | {r['lambda']:.6g} | {r['e']:.6g} | "
                       f"{r['contact_time_s']:.6g} | {r['max_force_N']:.6g} | {dt} |")
        return out

    def to_json(self) -> dict[str, Any]:
        """The JSON object of ``zener-sym lammps --json``."""
        c = self.contact
        out: dict[str, Any] = {"geometry": c.geometry, **self.lines, "A_s": self.A_s,
                               "damping": self.damping, "contact_end": self.contact_end,
                               "E_star_Pa": c.E_star, "m_eff_kg": c.m_eff, "R_eff_m": c.R_eff,
                               "E_lammps_Pa": c.E_lammps, "nu_lammps": c.nu_lammps,
                               "e_tolerance": E_TOLERANCE, "table": self.table}
        return out


def input_lines(c: LammpsContact, eta: float, end: str) -> dict[str, str]:
    """The LAMMPS lines of contact ``c`` with damping coefficient ``eta`` and end of contact
    ``end``: ``pair_style``, ``pair_coeff`` (two spheres) or ``fix_wall`` (a wall at z = 0 under
    the grains, which the user moves), and ``set`` (type 1, and type 2 for the second sphere)."""
    model = c.model_line(eta, end)
    sets = [f"set type 1 diameter {_num(2 * c.radius1)} density {_num(c.density1)}"]
    if c.geometry == "wall":
        return {"fix_wall": f"fix wall all wall/gran granular {model} zplane 0.0 NULL",
                "set": sets[0]}
    assert c.radius2 is not None and c.density2 is not None
    sets.append(f"set type 2 diameter {_num(2 * c.radius2)} density {_num(c.density2)}")
    return {"pair_style": "pair_style granular", "pair_coeff": f"pair_coeff * * {model}",
            "set": "\n".join(sets)}


def _table(c: LammpsContact, A: float, speeds: FloatArray,
           end: str) -> list[dict[str, float | None]]:
    lam = A * np.asarray(c.rate(speeds))
    too_big = lam > LAMBDA_MAX
    if too_big.any():
        v = float(speeds[too_big][0])
        raise ValueError(f"A = {A:.6g} s at {v:g} m/s gives lambda = {float(lam[too_big][0]):.6g}; "
                         f"allowed: 0 <= lambda <= {LAMBDA_MAX:g} (lower the speeds or A)")
    s = summary(lam, model="exact", contact_end=end)
    # the grains' force peaks before the end of compression: the same for both ends
    F_m = np.asarray(summary(lam, model="exact", contact_end="force").F_m)
    T = np.asarray(c.time_scale(speeds))
    rows: list[dict[str, float | None]] = []
    for i, v in enumerate(speeds):
        t_c = float(T[i] * np.asarray(s.tau_d)[i])
        n = steps_required(float(lam[i]), end)
        dt: float | None = None if math.isnan(n) else (t_c / n if math.isfinite(n) else 0.0)
        rows.append({"v_m_s": float(v), "lambda": float(lam[i]), "e": float(np.asarray(s.e)[i]),
                     "contact_time_s": t_c, "max_force_N": float(c.m_eff * v / T[i] * F_m[i]),
                     "dt_max_s": dt})
    return rows


def lammps_setup(sphere: Material | str, radius: float | str, *,
                 sphere2: Material | str | None = None, radius2: float | str | None = None,
                 wall: Material | str | None = None, A: float | str | None = None,
                 e: float | None = None, at: float | str | None = None,
                 contact_end: str = "force",
                 speeds: FloatArray | list[float | str] | None = None) -> LammpsSetup:
    """LAMMPS input for a contact with dissipative constant ``A``, or with restitution ``e`` at
    speed ``at``, and the exact model's answers over ``speeds``.

    Parameters
    ----------
    sphere, radius, sphere2, radius2, wall
        As :func:`lammps_contact`.
    A : float or str, optional
        The dissipative constant [s] (or with a unit, ``"240 ns"``). Give it, or ``e`` and ``at``.
    e : float, optional
        A coefficient of restitution in (0, 1] to reach at speed ``at``.
    at : float or str, optional
        Its normal impact speed [m/s] (or with a unit); with ``A``, the centre of the default
        speeds (1 m/s when not given).
    contact_end : {"force", "delta"}
        ``"force"`` (default): the grains' force-free end, ``limit_damping`` on the line.
    speeds : array_like, optional
        Normal impact speeds of the table [m/s] (numbers, or strings with units); default nine
        speeds over a decade on each side of ``at``.

    Returns
    -------
    LammpsSetup

    Raises
    ------
    ValueError
        For an e unreachable at that speed, a lambda outside [0, 1000], a value without a unit,
        an unknown material, both a wall and a second sphere, or neither (or both) of ``A`` and
        ``e``.

    Examples
    --------
    >>> from zener_sym.scene.lammps import lammps_setup
    >>> s = lammps_setup("glass", "1 mm", wall="steel", e=0.8, at="1 m/s")
    >>> round(s.A_s * 1e9, 2), s.lines["fix_wall"].split()[:5]
    (240.93, ['fix', 'wall', 'all', 'wall/gran', 'granular'])
    """
    end = check_contact_end(contact_end)
    c = lammps_contact(sphere, radius, sphere2=sphere2, radius2=radius2, wall=wall)
    if (A is None) == (e is None):
        raise ValueError("give either A (the dissipative constant) or e with at (a restitution "
                         "at a speed), not both or neither")
    v_at = None if at is None else si_value(at, "speed", "at")
    if e is not None:
        if v_at is None:
            raise ValueError("e needs the speed it is measured at: give at (e.g. '1 m/s')")
        if isinstance(e, bool) or not isinstance(e, (int, float)) or not 0.0 < float(e) <= 1.0:
            raise ValueError(f"e (coefficient of restitution) must be a number in (0, 1], "
                             f"got {e!r}")
        lam_e = float(np.asarray(lam_from_summary(e=float(e), contact_end=end)))
        A_s = lam_e / float(c.rate(v_at))
    else:
        A_s = si_value(A, "time", "A") if A is not None else 0.0
    centre = v_at if v_at is not None else 1.0
    if speeds is None:
        v = centre * np.logspace(-1.0, 1.0, 9)
    else:
        v = np.array([si_value(x, "speed", "speeds") for x in speeds], dtype=float)
        if v.size == 0:
            raise ValueError("give at least one speed in speeds")
    eta = c.damping(A_s)
    return LammpsSetup(contact=c, A_s=A_s, damping=eta, contact_end=end,
                       lines=input_lines(c, eta, end),
                       table=_table(c, A_s, v, end))
