"""Scenes in SI units: a sphere, a plate and a speed; dimensional results from any model.

    >>> import zener_sym as zs
    >>> sc = zs.Scene("table1-sphere", "table1-plate", radius=0.9e-3, thickness=0.5e-3, v0=1.0)
    >>> round(sc.lam, 4)
    0.163
    >>> r = sc.result(rtol=1e-3)             # cheapest model meeting rtol, with the reason
    >>> r.model
    'exact'
    >>> round(r.contact_duration_s * 1e6, 3)   # t_d in microseconds
    6.857

Conventions: velocities are positive towards the plate; the sphere rebounds with velocity
V(t_d) = -e V0, and ``rebound_speed_m_s`` is the rebound speed e V0 > 0. The plate deflection
w is positive in the direction of the impact. Scaling: see ``zener_sym.scene.scaling``.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np

from ..api import Summary
from ..plate.solver import RTOL_MIN
from ..typing import FloatArray, RealArrayLike
from . import checks, scaling
from .checks import ZenerWarning
from .materials import Material, get_material
from .plate_geometry import PlateGeometry, check_loss, plate_geometry
from .units import si_value

#: The loosest accuracy the scene asks of the finite-plate solver (a decade below rtol = 1e-2).
PLATE_RTOL_MAX = 1e-3

__all__ = ["Scene", "SceneResult", "Contact", "SCENE_FIELDS"]

#: Standard gravity [m/s^2] (CGPM 1901), for ``drop_height``: v0 = sqrt(2 g h).
G_STANDARD = 9.80665

#: Fields of a SceneResult: (attribute, unit, description). Dimensionless quantities carry the
#: names of ``zener_sym.Summary``; SI quantities carry their unit in the name.
SCENE_FIELDS = (
    ("contact_duration_s", "s", "contact duration t_d"),
    ("max_force_N", "N", "maximum contact force F_m"),
    ("max_compression_m", "m", "maximum compression delta_m"),
    ("e", "-", "coefficient of restitution e"),
    ("xi", "-", "energy-loss ratio xi"),
    ("eta", "-", "asymmetry eta = t_dr / t_dc"),
    ("rebound_speed_m_s", "m/s", "rebound speed e V0"),
    ("final_deflection_m", "m", "plate deflection at the end of contact"),
)

#: The dimensionless summary field behind each scene field (the quantity select_model uses).
QUANTITY_OF = {"contact_duration_s": "tau_d", "max_force_N": "F_m", "max_compression_m": "delta_m",
               "e": "e", "xi": "xi", "eta": "eta", "rebound_speed_m_s": "e",
               "final_deflection_m": "impulse"}

#: Names of earlier releases, so that old code gets told the new name.
RENAMED = {"contact_duration": "contact_duration_s", "max_force": "max_force_N",
           "max_compression": "max_compression_m", "restitution": "e", "energy_loss": "xi",
           "rebound_velocity": "rebound_speed_m_s", "final_deflection": "final_deflection_m"}


class Scene:
    """A sphere of radius ``radius`` hitting a large plate of thickness ``thickness`` at ``v0``.

    Parameters
    ----------
    sphere, plate : Material or str
        Materials, or preset names (``zener_sym.PRESETS``: steel, glass, aluminium,
        table1-sphere, table1-plate).
    radius : float or str
        Sphere radius R: a number in metres, or a string with a unit (``"2.5 mm"``).
    thickness : float or str
        Plate thickness H: metres, or a string with a unit (``"2 mm"``).
    v0 : float or str, optional
        Impact speed V0: m/s, or a string with a unit (``"3 m/s"``).
    plate_radius : float or str, optional
        Radius b of a circular plate struck at its centre (metres or with a unit).
    drop_height : float or str, optional
        Instead of ``v0``: the height the sphere falls from rest, v0 = sqrt(2 g h) with
        g = 9.80665 m/s^2 (no air drag). Give exactly one of ``v0`` and ``drop_height``.
    plate_size : pair of float or str, optional
        Instead of ``plate_radius``: the sides (a, b) of a rectangular plate.
    impact_at : pair of float or str, optional
        The rectangle's impact point (x, y) from a corner (default the centre).
    support : {"clamped", "simply-supported"}, optional
        How the bounded plate is held at its edge (the rectangle: ``"simply-supported"``).
        There is no default: without it the answer is Zener's, with a ``finite-plate``
        warning when the criterion finds Zener off by more than rtol for any support.
    plate_loss : float, optional
        Modal loss factor of the bounded plate, 0 <= loss < 1 (default 0, undamped).

    Raises
    ------
    ValueError
        For an unknown material, a string without a unit, a value that is not finite and > 0 or
        outside the plausible range of ``zener_sym.scene.units.PLAUSIBLE``, both or neither of
        ``v0`` and ``drop_height``, a plate not larger than the sphere, an unknown support, an
        impact point outside the plate, or a loss factor outside [0, 1).

    Notes
    -----
    The reduced mass is m* = m1: Zener's plate is infinite and its inertia is carried by the
    admittance alpha (see ``zener_sym.scene.scaling``). A bounded plate with its support is
    solved by the ``finite-plate`` model when Zener's infinite plate does not meet the
    accuracy asked for (:mod:`zener_sym.scene.plate_criterion`, docs/finite_plates.md).

    Examples
    --------
    >>> import zener_sym as zs
    >>> sc = zs.Scene("steel", "glass", radius="2.5 mm", thickness="2 mm", drop_height="0.5 m")
    >>> round(sc.v0, 4)                  # sqrt(2 g h)
    3.1316
    >>> r = sc.result()
    >>> round(r.e, 3), round(r.contact_duration_s * 1e6, 2), round(r.max_force_N)
    (0.306, 21.99, 186)
    """

    def __init__(self, sphere: Material | str, plate: Material | str, radius: float | str,
                 thickness: float | str, v0: float | str | None = None,
                 plate_radius: float | str | None = None, *,
                 drop_height: float | str | None = None,
                 plate_size: tuple[float | str, float | str] | None = None,
                 impact_at: tuple[float | str, float | str] | None = None,
                 support: str | None = None, plate_loss: float = 0.0) -> None:
        self.sphere: Material = get_material(sphere)
        self.plate: Material = get_material(plate)
        self.radius: float = si_value(radius, "length", "radius")
        self.thickness: float = si_value(thickness, "length", "thickness")
        self.drop_height: float | None
        self.v0: float
        if (v0 is None) == (drop_height is None):
            raise ValueError("give exactly one of v0 (impact speed, e.g. '3 m/s') and "
                             f"drop_height (e.g. '0.5 m'), got v0={v0!r}, "
                             f"drop_height={drop_height!r}")
        if drop_height is not None:
            self.drop_height = si_value(drop_height, "length", "drop_height")
            self.v0 = math.sqrt(2.0 * G_STANDARD * self.drop_height)
        else:
            self.drop_height = None
            self.v0 = si_value(cast("float | str", v0), "speed", "v0")
        #: The bounded plate (None: Zener's infinite plate).
        self.geometry: PlateGeometry | None = plate_geometry(self.radius, plate_radius,
                                                             plate_size, impact_at, support)
        self.plate_radius: float | None = (self.geometry.size[0] if self.geometry is not None
                                           and self.geometry.shape == "circle" else None)
        self.plate_loss: float = check_loss(plate_loss)
        if not math.isfinite(self.lam):
            raise ValueError(f"this scene gives a non-finite lambda ({self.lam!r}): check the "
                             "sizes, speed and materials")

    # -- derived properties (SI) ------------------------------------------------------------
    @property
    def m1(self) -> float:
        """Sphere mass m1 = (4/3) pi R^3 rho1 [kg].

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> f"{sc.m1:.4g} kg"
        '3.288e-05 kg'
        """
        return scaling.sphere_mass(self.radius, self.sphere.rho)

    @property
    def m_star(self) -> float:
        """Reduced mass of Eq. (7) [kg]: m1 (infinite plate).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> sc.m_star == sc.m1
        True
        """
        return self.m1

    @property
    def E_star(self) -> float:
        """Effective contact modulus E* [Pa], 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Eq. 8).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> f"{sc.E_star / 1e9:.4g} GPa"
        '57.38 GPa'
        """
        s, p = self.sphere, self.plate
        return scaling.effective_modulus(s.E, s.nu, p.E, p.nu)

    @property
    def alpha(self) -> float:
        """Plate point-load admittance alpha [s/kg] (below Eq. 7).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> f"{sc.alpha:.4g} s/kg"
        '0.007835 s/kg'
        >>> round(sc.alpha * 8 * (sc.D * sc.plate.rho * sc.thickness) ** 0.5, 12)  # 1/(8 sqrt(D rho2 H))
        1.0
        """
        p = self.plate
        return scaling.plate_admittance(p.E, p.nu, p.rho, self.thickness)

    @property
    def V_W(self) -> float:
        """Quasi-longitudinal plate-wave speed V_W = sqrt(E2 / (rho2 (1 - nu2^2))) [m/s] (below
        Eq. 11).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> f"{sc.V_W:.4g} m/s"
        '5527 m/s'
        """
        p = self.plate
        return scaling.plate_wave_speed(p.E, p.nu, p.rho)

    @property
    def D(self) -> float:
        """Flexural rigidity of the plate D = E2 H^3 / (12 (1 - nu2^2)) [N m].

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> f"{sc.D:.4g} N m"
        '50.91 N m'
        """
        return scaling.flexural_rigidity(self.plate.E, self.plate.nu, self.thickness)

    @property
    def T(self) -> float:
        """Characteristic time T [s] (Eq. 9, derived exponent 2/5).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> f"{sc.T * 1e6:.4g} us"
        '2.84 us'
        """
        return scaling.characteristic_time(self.m_star, self.E_star, self.radius, self.v0)

    @property
    def lam(self) -> float:
        """Zener's inelasticity parameter lambda = alpha m*/T (derived Eq. 11).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> round(sc.lam, 5), round(sc.alpha * sc.m_star / sc.T, 5)
        (0.09071, 0.09071)
        """
        return scaling.inelasticity(self.alpha, self.m_star, self.T)

    @property
    def chi(self) -> float:
        """chi [(s/m)^{1/5}] of Eq. (76), derived: xi = chi V0^{1/5} (R/H)^2 int F^2 dtau.

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> round(sc.chi, 4)
        0.7257
        """
        s, p = self.sphere, self.plate
        return scaling.chi(s.rho, self.E_star, p.rho, p.E, p.nu)

    @property
    def force_scale(self) -> float:
        """The force unit F / F_bar = m* V0 / T [N] (Eq. 9).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> f"{sc.force_scale:.4g} N"
        '11.58 N'
        """
        return scaling.force_scale(self.m_star, self.v0, self.T)

    @property
    def length_scale(self) -> float:
        """The compression unit delta / delta_bar = T V0 [m] (Eq. 9).

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> sc.length_scale == sc.T * sc.v0
        True
        """
        return scaling.length_scale(self.T, self.v0)

    @property
    def warnings(self) -> list[tuple[str, str]]:
        """The checks that need only the inputs, as (code, message) pairs (no warning issued).

        Returns
        -------
        list of (str, str)
            The ``ham-bound`` and ``thick-plate`` checks that apply (``zener_sym.scene.checks``).

        Examples
        --------
        >>> import zener_sym as zs
        >>> zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").warnings
        []
        >>> sc = zs.Scene("steel", "steel", radius="5 mm", thickness="10 cm", v0="1 m/s")
        >>> [code for code, message in sc.warnings]
        ['thick-plate']
        """
        return checks.static_checks(self)

    def __repr__(self) -> str:
        g = self.geometry
        pr = "" if g is None else (f", plate_radius={g.size[0]!r}" if g.shape == "circle" else
                                   f", plate_size={g.size!r}, impact_at={g.impact_at!r}")
        if g is not None and g.support is not None:
            pr += f", support={g.support!r}"
        return (f"Scene(sphere={self.sphere.name!r}, plate={self.plate.name!r}, "
                f"radius={self.radius!r}, thickness={self.thickness!r}, v0={self.v0!r}{pr})")

    # -- the bounded plate ------------------------------------------------------------------
    @property
    def beta(self) -> float | None:
        """The plate-size parameter beta = T sqrt(D/(rho2 H)) / L^2 of a bounded plate (None for
        Zener's infinite plate); :mod:`zener_sym.scene.plate_geometry`.

        Returns
        -------
        float or None

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="2.5 mm", thickness="1 mm", v0="1 m/s",
        ...               plate_radius="50 mm", support="clamped")
        >>> round(sc.beta, 6), round(sc.lam, 4)
        (0.004531, 2.2678)
        """
        if self.geometry is None:
            return None
        return self.geometry.beta(self.T, self.D, self.plate.rho, self.thickness)

    def plate_options(self) -> dict[str, Any]:
        """The ``finite-plate`` model's options for this scene's bounded plate.

        Returns
        -------
        dict
            beta, shape, support, aspect, impact, nu (the plate's Poisson ratio) and loss.

        Raises
        ------
        ValueError
            When the scene has no bounded plate, or no support for it.

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "steel", radius="5 mm", thickness="2 mm", v0="1 m/s",
        ...               plate_size=("50 mm", "50 mm"), support="simply-supported")
        >>> o = sc.plate_options()
        >>> o["shape"], o["aspect"], o["impact"], o["nu"]
        ('rectangle', 1.0, (0.5, 0.5), 0.3)
        """
        g = self.geometry
        if g is None or g.support is None:
            raise ValueError("model 'finite-plate' needs the plate's size and support: give "
                             "plate_radius or plate_size, and support='clamped' or "
                             "'simply-supported'")
        return {"beta": self.beta, **g.options(self.plate.nu), "loss": self.plate_loss}

    def plate_verdict(self, quantity: str = "all", rtol: float = 1e-3) -> Any:
        """The finite-plate criterion's verdict on Zener's infinite plate (None without a
        bounded plate); :func:`zener_sym.scene.plate_criterion.judge`. Without a support, every
        support is judged; a rectangle is judged through its nearest edge.

        Parameters
        ----------
        quantity : str
            The quantity the accuracy is for (histories: every quantity).
        rtol : float
            The accuracy asked for.

        Returns
        -------
        zener_sym.scene.plate_criterion.Verdict or None

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="2.5 mm", thickness="1 mm", v0="1 m/s",
        ...               plate_radius="50 mm")
        >>> v = sc.plate_verdict(rtol=1e-3)           # no support given: both are judged
        >>> v.holds, v.supports
        (False, ('clamped', 'simply-supported'))
        """
        from . import plate_criterion as crit
        from .plate_geometry import SUPPORTS

        g = self.geometry
        if g is None:
            return None
        q = quantity if quantity in crit.KNOWN else "all"
        if g.shape == "circle":
            supports = (g.support,) if g.support else SUPPORTS
            return crit.judge(self.lam, cast(float, self.beta), supports, q, rtol)
        beta_eq = cast(float, self.beta) * (g.L / g.edge_distance) ** 2
        return crit.judge(self.lam, beta_eq, ("simply-supported",), q, rtol, shape="rectangle")

    def _plate_warning(self, verdict: Any) -> str:
        g = cast(PlateGeometry, self.geometry)
        tail = ("give support= for the finite-plate answer" if g.support is None else
                "model 'finite-plate' solves it")
        return f"{g.describe()}: {verdict.reason}; {tail}"

    def _contacts(self, res: SceneResult) -> list[Contact]:
        """One row per contact: Zener's one contact, or the finite plate's every contact."""
        m, v0, T, Fs = self.m_star, self.v0, self.T, self.force_scale
        if res.model == "finite-plate":
            from ..models.finite_plate import impact

            rows = impact(self.lam, **res.options).contacts
            return [Contact(c.start * T, c.end * T, c.max_force * Fs, c.impulse * m * v0,
                            c.speed_after * v0) for c in rows]
        if None in (res.contact_duration_s, res.max_force_N, res.e):
            return []
        s = res.summary
        impulse = float(s.impulse) if "impulse" in s.fields else 1.0 + float(s.e)
        return [Contact(0.0, cast(float, res.contact_duration_s), cast(float, res.max_force_N),
                        impulse * m * v0, float(s.e) * v0)]

    # -- results ----------------------------------------------------------------------------
    def summary(self, model: str | None = None, rtol: float = 1e-3, quantity: str = "all",
                **options: Any) -> SceneResult:
        """Deprecated alias of :meth:`result` (it warns, then calls it with ``warn=True``).

        Parameters
        ----------
        model, rtol, quantity, **options
            As :meth:`result`.

        Returns
        -------
        SceneResult
            As :meth:`result`.

        Raises
        ------
        ValueError
            As :meth:`result`.

        Warns
        -----
        DeprecationWarning
            Always: ``Scene.result`` is the one route from a scene to its result.

        Examples
        --------
        >>> import warnings, zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> with warnings.catch_warnings():
        ...     warnings.simplefilter("ignore", DeprecationWarning)
        ...     r = sc.summary(model="hertz")
        >>> r.model
        'hertz'
        """
        warnings.warn("Scene.summary() is deprecated: use Scene.result(), the one route from a "
                      "scene to its result", DeprecationWarning, stacklevel=2)
        return self.result(model=model, rtol=rtol, quantity=quantity, **options)

    def result(self, model: str | None = None, rtol: float = 1e-3, quantity: str = "all",
               warn: bool = True, **options: Any) -> SceneResult:
        """Dimensional results with ``model``, or with the cheapest model meeting ``rtol``: the
        one route from a scene to its result.

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

        Returns
        -------
        SceneResult
            SI and dimensionless results, the model used and why, and the validity checks.

        Raises
        ------
        ValueError
            For an unknown model, option or quantity, a bad ``rtol``, or a lambda outside the
            model's validity.

        Warns
        -----
        ZenerWarning
            For each validity check that fails, when ``warn`` is true.

        Examples
        --------
        >>> import zener_sym as zs
        >>> sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
        >>> r = sc.result(rtol=1e-6, quantity="e", warn=False)
        >>> r.model, round(r.e, 6)
        ('series', 0.856623)
        >>> r = sc.result(model="hertz")
        >>> r.model, r.reason, round(r.e, 3)
        ('hertz', "model 'hertz' requested", 1.0)
        >>> round(sc.result(model="exact").e, 6)
        0.856623
        """
        from ..api import summary as _summary
        from .select import select_model

        # the criterion: to choose, or to warn about Zener's answer
        verdict = None if model == "finite-plate" else self.plate_verdict(quantity, rtol)
        if model is None:
            if verdict is not None and not verdict.holds and self.geometry is not None \
                    and self.geometry.support is not None:
                model, reason = "finite-plate", verdict.reason
            else:
                sel = select_model(self, quantity, rtol)
                model, reason = sel.model, sel.reason
                if verdict is not None and verdict.holds:
                    reason += "; " + verdict.reason
        else:
            reason = f"model {model!r} requested"
        if model == "finite-plate":
            # the solver a decade finer than the accuracy asked of the answer (no finer: large
            # plates need many modes, and a 600 mm glass square at rtol 1e-5 needed more than
            # the solver's N_MAX)
            options = {**self.plate_options(),
                       "rtol": min(max(0.1 * rtol, RTOL_MIN), PLATE_RTOL_MAX), **options}
        try:
            s = _summary(self.lam, model=model, **options)
        except ValueError as exc:
            if model != "finite-plate" or "cannot solve" not in str(exc):
                raise
            # the model's message speaks of its own rtol; say what the scene's user can change
            why = (f"; chosen because {reason}" if reason.startswith("the finite-plate")
                   else "")
            raise ValueError(f"Scene.result(rtol={rtol:g}): {exc}{why}. Ask for a larger rtol "
                             "(the solver is asked for a tenth of it), or for the model "
                             "'exact' to take Zener's infinite plate as it is") from None
        T, L = self.T, self.length_scale
        # A model that cannot give a quantity leaves it None (shown as n/a); asking the
        # dimensionless summary for it raises FieldUnavailableError naming field and model.
        have = set(s.fields)

        def get(f: str, scale: float = 1.0) -> float | None:
            return scale * float(getattr(s, f)) if f in have else None

        res = SceneResult(
            scene=self, model=model, reason=reason, lam=self.lam, summary=s,
            contact_duration_s=get("tau_d", T), max_force_N=get("F_m", self.force_scale),
            max_compression_m=get("delta_m", L), e=get("e"), xi=get("xi"), eta=get("eta"),
            rebound_speed_m_s=get("e", self.v0),
            # w = alpha I: the infinite plate's (the bounded plate rings on after contact)
            final_deflection_m=(None if model == "finite-plate" else
                                get("impulse", self.alpha * self.m_star * self.v0)),
            options=dict(options),
        )
        res.contacts = self._contacts(res)
        found = checks.static_checks(self)
        t_d, d_m, F_m = res.contact_duration_s, res.max_compression_m, res.max_force_N
        if t_d is None or d_m is None or F_m is None or "impulse" not in have:
            found.append(("not-checked", f"model {model!r} does not give every quantity the "
                          "plate and yield checks need; they were skipped"))
        else:
            found += checks.dynamic_checks(self, t_d, d_m, F_m, float(s.impulse))
        if verdict is not None and not verdict.holds and model != "finite-plate":
            found.append(("finite-plate", self._plate_warning(verdict)))
        res.warnings = found
        if warn:
            for code, msg in found:
                warnings.warn(f"[{code}] {msg}", ZenerWarning, stacklevel=2)
        return res


@dataclass(frozen=True)
class Contact:
    """One contact of the ball with the plate, in SI units.

    Attributes
    ----------
    start_s, end_s : float
        When it starts and ends [s], from the first touch.
    max_force_N : float
        Its largest force [N].
    impulse_N_s : float
        The impulse the plate gives the ball during it [N s].
    speed_after_m_s : float
        The ball's speed after it [m/s], positive away from the plate.

    Examples
    --------
    >>> import zener_sym as zs
    >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
    >>> [c.speed_after_m_s == r.rebound_speed_m_s for c in r.contacts]   # Zener: one contact
    [True]
    """

    start_s: float
    end_s: float
    max_force_N: float
    impulse_N_s: float
    speed_after_m_s: float


@dataclass
class SceneResult:
    """Results of one scene with one model: dimensionless ones under the names of
    ``zener_sym.Summary`` (``lam``, ``e``, ``xi``, ``eta``), SI ones with their unit in the name.

    Attributes
    ----------
    scene : Scene
    model : str
        The model used.
    reason : str
        Why that model (the selection's sentence, or "requested").
    lam : float
        Zener's inelasticity parameter lambda of the scene.
    summary : Summary
        The model's dimensionless summary (every field it gives).
    contact_duration_s : float or None
        Contact duration t_d [s].
    max_force_N : float or None
        Maximum contact force F_m [N].
    max_compression_m : float or None
        Maximum compression delta_m [m].
    e, xi, eta : float or None
        Restitution, energy-loss ratio (xi = 2 I - I^2, Eq. 69; 1 - e^2 for the exact model,
        not for the approximate ones, whose impulse is not 1 + e) and asymmetry.
    rebound_speed_m_s : float or None
        Rebound speed e V0 [m/s].
    final_deflection_m : float or None
        Plate deflection at the end of contact [m].
    options : dict
        The model options used.
    warnings : list of (str, str)
        The validity checks as (code, message) pairs.
    contacts : list of Contact
        One row per contact (Zener's model: one; ``finite-plate``: every contact, ``e`` being
        the ball's after the last).

    A field the model cannot give is None (a model chosen by ``select_model`` with quantity
    "all" gives them all).

    Examples
    --------
    >>> import zener_sym as zs
    >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
    >>> r.e == r.summary.e, r.rebound_speed_m_s == r.e * r.scene.v0
    (True, True)
    >>> f"{r.contact_duration_s * 1e6:.3f} us"
    '9.294 us'
    """

    scene: Scene
    model: str
    reason: str
    lam: float
    summary: Summary
    contact_duration_s: float | None
    max_force_N: float | None
    max_compression_m: float | None
    e: float | None
    xi: float | None
    eta: float | None
    rebound_speed_m_s: float | None
    final_deflection_m: float | None
    options: dict[str, Any] = field(default_factory=dict)
    warnings: list[tuple[str, str]] = field(default_factory=list)
    contacts: list[Contact] = field(default_factory=list)

    def __getattr__(self, name: str) -> Any:
        if name in RENAMED:
            raise AttributeError(f"SceneResult.{name} is now {RENAMED[name]!r} (dimensionless "
                                 "fields carry Summary's names, SI fields their unit)")
        raise AttributeError(f"SceneResult has no field {name!r}; fields: "
                             f"{', '.join(f for f, _, _ in SCENE_FIELDS)}, lam, summary")

    def history(self, t: RealArrayLike, model: str | None = None) -> dict[str, FloatArray]:
        """Histories at times ``t`` [s] (>= 0): force, plate deflection, sphere velocity and
        compression in SI units (Eqs. 45, 47, 64-66).

        Parameters
        ----------
        t : float or array_like
            Times since first contact [s], finite and >= 0.
        model : str, optional
            A name in ``zener_sym.MODELS`` (default: the result's model, with its options).

        Returns
        -------
        dict of str to numpy.ndarray
            ``t_s``, ``force_N``, ``deflection_m`` (plate centre; not for ``finite-plate``),
            ``velocity_m_s`` (sphere, positive towards the plate) and ``compression_m``, each of
            the shape of ``t``.

        Raises
        ------
        ValueError
            For a time that is not finite and >= 0, or a model that cannot give the histories.

        Examples
        --------
        >>> import zener_sym as zs
        >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
        >>> h = r.history([0.0, 5e-6])
        >>> sorted(h)
        ['compression_m', 'deflection_m', 'force_N', 't_s', 'velocity_m_s']
        >>> [round(float(v), 4) for v in h["velocity_m_s"]]     # V0 at first contact
        [1.0, -0.1007]
        """
        from ..api import history as _history

        sc = self.scene
        ts = np.asarray(t, dtype=float)
        if not np.all(np.isfinite(ts)) or np.any(ts < 0):
            raise ValueError("t must be finite times >= 0 in seconds")
        name = model or self.model
        h = _history(self.lam, ts / sc.T, model=name,
                     **(self.options if name == self.model else {}))
        out = {
            "t_s": ts,
            "force_N": sc.force_scale * h.force,
            "deflection_m": sc.alpha * sc.m_star * sc.v0 * h.impulse,
            "velocity_m_s": sc.v0 * (1.0 - sc.m_star / sc.m1 * h.impulse),
            "compression_m": sc.length_scale * h.delta,
        }
        if name == "finite-plate":
            # w = alpha I is the infinite plate's; the bounded plate rings (not reported)
            del out["deflection_m"]
        return out

    def force(self, t: RealArrayLike) -> FloatArray:
        """Contact force F(t) [N] (Eq. 45) at times ``t`` [s], with the result's model.

        Parameters
        ----------
        t : float or array_like
            Times since first contact [s], finite and >= 0.

        Returns
        -------
        numpy.ndarray
            F [N], of the shape of ``t``; 0 after the end of contact.

        Examples
        --------
        >>> import zener_sym as zs
        >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
        >>> F = r.force([0.0, 1e-6, 1e-4])
        >>> [round(float(f), 2) for f in F]
        [0.0, 2.36, 0.0]
        """
        return self.history(t)["force_N"]

    def deflection(self, t: RealArrayLike) -> FloatArray:
        """Plate centre deflection w(t) [m] (Eq. 65) at times ``t`` [s].

        Parameters
        ----------
        t : float or array_like
            Times since first contact [s], finite and >= 0.

        Returns
        -------
        numpy.ndarray
            w [m], positive in the direction of the impact, of the shape of ``t``.

        Raises
        ------
        ValueError
            For a bad time, or the ``finite-plate`` model (its ringing plate's deflection is
            not reported).

        Examples
        --------
        >>> import zener_sym as zs
        >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
        >>> w_end = float(r.deflection(1e-4))                   # after the contact
        >>> round(w_end / r.final_deflection_m, 9)
        1.0
        """
        h = self.history(t)
        if "deflection_m" not in h:
            raise ValueError("the finite plate's deflection history is not reported (its "
                             "modes ring between contacts); force, velocity and compression are")
        return h["deflection_m"]

    def velocity(self, t: RealArrayLike) -> FloatArray:
        """Sphere velocity V(t) [m/s] (Eq. 64), positive towards the plate, at ``t`` [s].

        Parameters
        ----------
        t : float or array_like
            Times since first contact [s], finite and >= 0.

        Returns
        -------
        numpy.ndarray
            V [m/s], of the shape of ``t``.

        Examples
        --------
        >>> import zener_sym as zs
        >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
        >>> V = r.velocity([0.0, 1e-4])                # -e V0 after the contact
        >>> round(float(V[0]), 6), round(float(V[1]) + r.rebound_speed_m_s, 9)
        (1.0, 0.0)
        """
        return self.history(t)["velocity_m_s"]

    def table(self) -> list[tuple[str, str, str]]:
        """Rows (quantity, value, unit) of the inputs, the scalings and the results.

        Returns
        -------
        list of (str, str, str)
            The inputs, the scalings (m*, E*, alpha, V_W, T, chi, lambda), the model and why,
            every field of the result (``n/a`` where the model gives none) and the warnings.

        Examples
        --------
        >>> import zener_sym as zs
        >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
        >>> rows = r.table()
        >>> rows[2], rows[11]
        (('radius R', '0.001', 'm'), ('lambda', '0.0907127', '-'))
        """
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
        ]
        if sc.geometry is not None:
            rows += [("bounded plate", sc.geometry.describe(), ""),
                     ("beta (plate size)", f"{sc.beta:.6g}", "-")]
        rows += [("model", self.model, ""), ("why this model", self.reason, "")]
        for name, unit, desc in SCENE_FIELDS:
            v = getattr(self, name)
            rows.append((desc, f"n/a (not given by model {self.model!r})" if v is None
                         else f"{v:.6g}", unit if v is not None else ""))
        if self.e is not None and self.xi is not None and abs(self.xi - (1 - self.e**2)) > 1e-9:
            rows.append(("note", f"model {self.model!r} is approximate: its xi = 2I - I^2 "
                         f"(Eq. 69) differs from 1 - e^2 = {1 - self.e**2:.6g}; the exact "
                         "identity I(t_d) = 1 + e does not hold for it", ""))
        if len(self.contacts) > 1:
            for k, c in enumerate(self.contacts, 1):
                rows.append((f"contact {k}", f"{c.start_s * 1e6:.6g} to {c.end_s * 1e6:.6g} us, "
                             f"max force {c.max_force_N:.4g} N, impulse {c.impulse_N_s:.4g} N s, "
                             f"ball speed after {c.speed_after_m_s:.4g} m/s", ""))
        for code, msg in self.warnings:
            rows.append((f"WARNING {code}", msg, ""))
        return rows

    def as_dict(self) -> dict[str, Any]:
        """The result as plain data (what ``zener-sym scene --json`` prints).

        Returns
        -------
        dict
            ``model``, ``reason``, ``lam``, ``beta`` (None for Zener's infinite plate), every
            field of :data:`SCENE_FIELDS` (None where the model gives none), ``contacts`` (a
            list of dicts with the fields of :class:`Contact`) and ``warnings`` (a list of
            {code, message}).

        Examples
        --------
        >>> import json, zener_sym as zs
        >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
        >>> d = r.as_dict()
        >>> d["model"], len(d["contacts"]), round(d["contacts"][0]["end_s"] * 1e6, 3)
        ('exact', 1, 9.294)
        >>> json.loads(json.dumps(d)) == d
        True
        """
        import dataclasses

        out: dict[str, Any] = {"model": self.model, "reason": self.reason, "lam": self.lam,
                               "beta": self.scene.beta}
        out.update({name: getattr(self, name) for name, _, _ in SCENE_FIELDS})
        out["contacts"] = [dataclasses.asdict(c) for c in self.contacts]
        out["warnings"] = [{"code": c, "message": m} for c, m in self.warnings]
        return out

    def to_markdown(self) -> str:
        """:meth:`table` as a markdown table (quantity, value, unit).

        Returns
        -------
        str

        Examples
        --------
        >>> import zener_sym as zs
        >>> r = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s").result()
        >>> for line in r.to_markdown().splitlines()[:3]:
        ...     print(line)
        | quantity | value | unit |
        |---|---|---|
        | sphere | steel (E 2.1e+11 Pa, nu 0.3, rho 7850 kg/m^3) |  |
        """
        lines = ["| quantity | value | unit |", "|---|---|---|"]
        lines += [f"| {a} | {b} | {c} |" for a, b, c in self.table()]
        return "\n".join(lines)

    def __str__(self) -> str:
        rows = self.table()
        w = max(len(r[0]) for r in rows)
        return "\n".join(f"{a:<{w}}  {b} {c}".rstrip() for a, b, c in rows)
