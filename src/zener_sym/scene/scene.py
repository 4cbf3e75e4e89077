"""Scenes in SI units: a sphere, a plate and a speed; dimensional results from any model.

    >>> import zener_sym as zs
    >>> sc = zs.Scene("table1-sphere", "table1-plate", radius=0.9e-3, thickness=0.5e-3, v0=1.0)
    >>> round(sc.lam, 4)
    0.163
    >>> r = zs.summary(sc, rtol=1e-3)        # cheapest model meeting rtol, with the reason
    >>> r.contact_duration                   # [s]  # doctest: +SKIP

Conventions: velocities are positive towards the plate; the sphere rebounds with velocity
V(t_d) = -e V0, and ``rebound_velocity`` is the rebound speed e V0 > 0. The plate deflection
w is positive in the direction of the impact. Scaling: see ``zener_sym.scaling``.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from . import checks, scaling
from .checks import ZenerWarning
from .materials import Material, check_positive, get_material

__all__ = ["Scene", "SceneResult", "SCENE_FIELDS"]

#: Dimensional summary fields of a SceneResult: (attribute, unit, description).
SCENE_FIELDS = (
    ("contact_duration", "s", "contact duration t_d"),
    ("max_force", "N", "maximum contact force F_m"),
    ("max_compression", "m", "maximum compression delta_m"),
    ("restitution", "-", "coefficient of restitution e"),
    ("energy_loss", "-", "energy-loss ratio xi = 1 - e^2"),
    ("rebound_velocity", "m/s", "rebound speed e V0"),
    ("final_deflection", "m", "plate deflection at the end of contact"),
)

#: The dimensionless summary field behind each dimensional one (the quantity select_model uses).
QUANTITY_OF = {"contact_duration": "tau_d", "max_force": "F_m", "max_compression": "delta_m",
               "restitution": "e", "energy_loss": "xi", "rebound_velocity": "e",
               "final_deflection": "impulse"}


class Scene:
    """A sphere of radius ``radius`` hitting a large plate of thickness ``thickness`` at ``v0``.

    Parameters
    ----------
    sphere, plate : Material or str
        Materials, or preset names (``zener_sym.PRESETS``: steel, glass, aluminium,
        table1-sphere, table1-plate).
    radius : float
        Sphere radius R [m], > 0.
    thickness : float
        Plate thickness H [m], > 0.
    v0 : float
        Impact speed V0 [m/s], > 0.
    plate_radius : float, optional
        Radius of a finite plate [m]; enables the finite-plate check.

    Notes
    -----
    The reduced mass is m* = m1: Zener's plate is infinite and its inertia is carried by the
    admittance alpha (see ``zener_sym.scaling``).
    """

    def __init__(self, sphere, plate, radius, thickness, v0, plate_radius=None):
        self.sphere: Material = get_material(sphere)
        self.plate: Material = get_material(plate)
        self.radius = check_positive(radius, "radius", "m", "sphere radius R")
        self.thickness = check_positive(thickness, "thickness", "m", "plate thickness H")
        self.v0 = check_positive(v0, "v0", "m/s", "impact speed")
        self.plate_radius = (None if plate_radius is None else
                             check_positive(plate_radius, "plate_radius", "m"))
        if self.plate_radius is not None and self.plate_radius <= self.radius:
            raise ValueError(f"plate_radius must exceed the sphere radius {self.radius:g} m, got "
                             f"{self.plate_radius:g} m")

    # -- derived properties (SI) ------------------------------------------------------------
    @property
    def m1(self) -> float:
        """Sphere mass [kg]."""
        return scaling.sphere_mass(self.radius, self.sphere.rho)

    @property
    def m_star(self) -> float:
        """Reduced mass of Eq. (7) [kg]: m1 (infinite plate)."""
        return self.m1

    @property
    def E_star(self) -> float:
        """Effective contact modulus E* [Pa]."""
        s, p = self.sphere, self.plate
        return scaling.effective_modulus(s.E, s.nu, p.E, p.nu)

    @property
    def alpha(self) -> float:
        """Plate point-load admittance alpha [s/kg] (below Eq. 7)."""
        p = self.plate
        return scaling.plate_admittance(p.E, p.nu, p.rho, self.thickness)

    @property
    def V_W(self) -> float:
        """Quasi-longitudinal plate-wave speed [m/s] (below Eq. 11)."""
        p = self.plate
        return scaling.plate_wave_speed(p.E, p.nu, p.rho)

    @property
    def D(self) -> float:
        """Flexural rigidity of the plate [N m]."""
        return scaling.flexural_rigidity(self.plate.E, self.plate.nu, self.thickness)

    @property
    def T(self) -> float:
        """Characteristic time T [s] (Eq. 9, derived exponent 2/5)."""
        return scaling.characteristic_time(self.m_star, self.E_star, self.radius, self.v0)

    @property
    def lam(self) -> float:
        """Zener's inelasticity parameter lambda = alpha m*/T (derived Eq. 11)."""
        return scaling.inelasticity(self.alpha, self.m_star, self.T)

    @property
    def chi(self) -> float:
        """chi [(s/m)^{1/5}] of Eq. (76), derived."""
        s, p = self.sphere, self.plate
        return scaling.chi(s.rho, self.E_star, p.rho, p.E, p.nu)

    @property
    def force_scale(self) -> float:
        """F / F_bar = m* V0 / T [N]."""
        return scaling.force_scale(self.m_star, self.v0, self.T)

    @property
    def length_scale(self) -> float:
        """delta / delta_bar = T V0 [m]."""
        return scaling.length_scale(self.T, self.v0)

    @property
    def warnings(self) -> list:
        """The checks that need only the inputs, as (code, message) pairs (no warning issued)."""
        return checks.static_checks(self)

    def __repr__(self):
        pr = "" if self.plate_radius is None else f", plate_radius={self.plate_radius!r}"
        return (f"Scene(sphere={self.sphere.name!r}, plate={self.plate.name!r}, "
                f"radius={self.radius!r}, thickness={self.thickness!r}, v0={self.v0!r}{pr})")

    # -- results ----------------------------------------------------------------------------
    def summary(self, model: str | None = None, rtol: float = 1e-3, quantity: str = "all",
                **options) -> "SceneResult":
        """The scene's dimensional result; ``zener_sym.summary(scene, ...)`` calls this.

        Same parameters as :meth:`result`.
        """
        return self.result(model=model, rtol=rtol, quantity=quantity, **options)

    def result(self, model: str | None = None, rtol: float = 1e-3, quantity: str = "all",
               warn: bool = True, **options) -> "SceneResult":
        """Dimensional results with ``model``, or with the cheapest model meeting ``rtol``.

        Parameters
        ----------
        model : str, optional
            A name in ``zener_sym.MODELS``. If omitted, ``select_model(self, quantity, rtol)``
            chooses.
        rtol : float
            Relative accuracy required when choosing the model.
        quantity : str
            The quantity the accuracy is asked for ("all" = every summary field reported).
        warn : bool
            Issue the checks as ``ZenerWarning`` (they are listed in the result either way).
        **options
            Passed to the model.
        """
        from ..api import summary as _summary
        from .select import select_model

        if model is None:
            sel = select_model(self, quantity, rtol)
            model, reason = sel.model, sel.reason
        else:
            reason = f"model {model!r} requested"
        s = _summary(self.lam, model=model, **options)
        T, L = self.T, self.length_scale
        # A model that cannot give a quantity leaves it None (shown as n/a); asking the
        # dimensionless summary for it raises FieldUnavailableError naming field and model.
        have = set(s.fields)
        get = lambda f, scale=1.0: scale * getattr(s, f) if f in have else None  # noqa: E731
        res = SceneResult(
            scene=self, model=model, reason=reason, lam=self.lam,
            contact_duration=get("tau_d", T), max_force=get("F_m", self.force_scale),
            max_compression=get("delta_m", L), restitution=get("e"), energy_loss=get("xi"),
            rebound_velocity=get("e", self.v0),
            final_deflection=get("impulse", self.alpha * self.m_star * self.v0),
            options=dict(options),
        )
        found = checks.static_checks(self)
        if None in (res.contact_duration, res.max_compression, res.max_force,
                    res.final_deflection):
            found.append(("not-checked", f"model {model!r} does not give every quantity the "
                          "plate and yield checks need; they were skipped"))
        else:
            found += checks.dynamic_checks(self, res.contact_duration, res.max_compression,
                                           res.max_force, s.impulse)
        res.warnings = found
        if warn:
            for code, msg in found:
                warnings.warn(f"[{code}] {msg}", ZenerWarning, stacklevel=3)
        return res


@dataclass
class SceneResult:
    """Dimensional results of one scene with one model (SI units; see ``SCENE_FIELDS``).

    A field the model cannot give is None (a model chosen by ``select_model`` with quantity
    "all" gives them all). ``warnings`` lists the validity checks as (code, message) pairs.
    """

    scene: Scene
    model: str
    reason: str
    lam: float
    contact_duration: float | None
    max_force: float | None
    max_compression: float | None
    restitution: float | None
    energy_loss: float | None
    rebound_velocity: float | None
    final_deflection: float | None
    options: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)

    def history(self, t, model: str | None = None) -> dict:
        """Histories at times ``t`` [s] (>= 0): force F [N], plate deflection w [m], sphere
        velocity V [m/s] (positive towards the plate), compression delta [m].

        Uses the result's model, or ``model`` if given.
        """
        from ..api import history as _history

        sc = self.scene
        t = np.asarray(t, dtype=float)
        if not np.all(np.isfinite(t)) or np.any(t < 0):
            raise ValueError("t must be finite times >= 0 in seconds")
        name = model or self.model
        h = _history(self.lam, t / sc.T, model=name,
                     **(self.options if name == self.model else {}))
        return {
            "t": t,
            "force": sc.force_scale * h.force,
            "deflection": sc.alpha * sc.m_star * sc.v0 * h.impulse,
            "velocity": sc.v0 * (1.0 - sc.m_star / sc.m1 * h.impulse),
            "compression": sc.length_scale * h.delta,
        }

    def force(self, t):
        """Contact force F(t) [N]."""
        return self.history(t)["force"]

    def deflection(self, t):
        """Plate centre deflection w(t) [m] (Eq. 65)."""
        return self.history(t)["deflection"]

    def velocity(self, t):
        """Sphere velocity V(t) [m/s] (Eq. 64), positive towards the plate."""
        return self.history(t)["velocity"]

    def table(self) -> list:
        """Rows (quantity, value, unit) of the inputs, the scalings and the results."""
        sc = self.scene
        rows = [
            ("sphere", f"{sc.sphere.name} (E {sc.sphere.E:.4g} Pa, nu {sc.sphere.nu:g}, "
                       f"rho {sc.sphere.rho:g} kg/m^3)", ""),
            ("plate", f"{sc.plate.name} (E {sc.plate.E:.4g} Pa, nu {sc.plate.nu:g}, "
                      f"rho {sc.plate.rho:g} kg/m^3)", ""),
            ("radius R", f"{sc.radius:.6g}", "m"), ("thickness H", f"{sc.thickness:.6g}", "m"),
            ("impact speed V0", f"{sc.v0:.6g}", "m/s"),
            ("sphere mass m1 (= m*)", f"{sc.m1:.6g}", "kg"), ("E*", f"{sc.E_star:.6g}", "Pa"),
            ("alpha", f"{sc.alpha:.6g}", "s/kg"), ("V_W", f"{sc.V_W:.6g}", "m/s"),
            ("T", f"{sc.T:.6g}", "s"), ("chi", f"{sc.chi:.6g}", "(s/m)^(1/5)"),
            ("lambda", f"{self.lam:.6g}", "-"),
            ("model", self.model, ""),
            ("why this model", self.reason, ""),
        ]
        for name, unit, desc in SCENE_FIELDS:
            v = getattr(self, name)
            rows.append((desc, f"n/a (not given by model {self.model!r})" if v is None
                         else f"{v:.6g}", unit if v is not None else ""))
        for code, msg in self.warnings:
            rows.append((f"WARNING {code}", msg, ""))
        return rows

    def to_markdown(self) -> str:
        lines = ["| quantity | value | unit |", "|---|---|---|"]
        lines += [f"| {a} | {b} | {c} |" for a, b, c in self.table()]
        return "\n".join(lines)

    def __str__(self):
        rows = self.table()
        w = max(len(r[0]) for r in rows)
        return "\n".join(f"{a:<{w}}  {b} {c}".rstrip() for a, b, c in rows)
