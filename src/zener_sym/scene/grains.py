"""Viscoelastic grains in SI units: two spheres, or a sphere on a wall.

Zener's Eq. (10) is, term for term, the viscoelastic Hertz contact of granular dynamics
(Kuwabara & Kono 1987; Brilliantov, Spahn, Hertzsch & Poeschel 1996):

    m_eff xi'' + rho (xi^{3/2} + A d/dt xi^{3/2}) = 0,   xi(0) = 0,  xi'(0) = v0,

with xi the mutual compression, m_eff = m1 m2/(m1 + m2) (m1 on a wall), rho = (4/3) E* sqrt(R_eff),
1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, R_eff = R1 R2/(R1 + R2) (R1 on a flat wall) and A the
material's dissipative constant. ``zener_sym.derivation.viscoelastic`` derives the mapping

    T = (m_eff/rho)^{2/5} v0^{-1/5},   xi = v0 T delta(t/T),   lambda = A/T = A (rho/m_eff)^{2/5} v0^{1/5},

and the force scale m_eff v0/T.

A, the dissipative constant, is a time in seconds: the ratio of the contact's viscous to its
elastic stiffness. For a viscoelastic solid with Young's modulus E, Poisson ratio nu and the
two viscous constants eta1, eta2 of the bulk, Brilliantov et al. (1996) give
A = (1/3) (3 eta2 - eta1)^2/(3 eta2 + 2 eta1) (1 - nu^2)(1 - 2 nu)/(E nu^2); in practice A is
fitted to measured coefficients of restitution: ``zener_sym.dissipation_for`` (one e at one
speed) and ``zener_sym.fit_dissipation`` (pairs (v0_i, e_i)), in :mod:`zener_sym.scene.calibrate`.

A sphere's inputs carry the names of :class:`~zener_sym.Scene`: ``sphere`` (its material),
``radius`` and ``mass``, and ``sphere2``, ``radius2``, ``mass2`` for a second sphere. The old
names (``R1``, ``m1``, ``material1``, ...) still work for one release, with a
``DeprecationWarning`` (:mod:`zener_sym.scene.legacy`).

The contact ends, by default, where the viscoelastic force vanishes (``contact_end="force"``, the
granular literature's criterion, Schwager & Poeschel 2008); ``contact_end="delta"`` ends it at
xi = 0 (the plate's criterion of Zener's problem). The result says which it used.
"""
from __future__ import annotations

import math
import numbers
import warnings
from dataclasses import dataclass, field
from typing import overload

import numpy as np

from ..api import history, summary
from ..exact.force_end import check_contact_end
from ..exact.solver import LAMBDA_MAX
from ..typing import FloatArray, RealArrayLike, RealLike
from .legacy import accepts_old_call
from .materials import Material, get_material
from .units import si_value

__all__ = ["lam_from_dissipation", "viscoelastic_lambda", "GrainImpact", "grain_impact",
           "GrainContact", "grain_contact"]


def _positive(value: object, field: str, unit: str, what: str) -> float:
    """``value`` as a float if it is a finite real > 0; ValueError naming ``field`` otherwise."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{field} ({what}) must be a real number in {unit}, got {value!r}; "
                         f"allowed: 0 < {field} < infinity")
    v = float(value)
    if not math.isfinite(v) or v <= 0.0:
        raise ValueError(f"{field} ({what}) must be finite and > 0 (in {unit}), got {value!r}; "
                         f"allowed: 0 < {field} < infinity")
    return v


def _pos_array(value: object, name: str, unit: str, what: str) -> FloatArray:
    """``value`` as a float array if every entry is a finite real > 0; ValueError otherwise."""
    arr = np.asarray(value, dtype=float) if not isinstance(value, (bool, str)) else None
    if arr is None or arr.dtype.kind not in "fiu":
        raise ValueError(f"{name} ({what}) must be a real number in {unit}, got {value!r}; "
                         f"allowed: 0 < {name} < infinity")
    bad = ~np.isfinite(arr) | (arr <= 0)
    if bad.any():
        raise ValueError(f"{name} ({what}) must be finite and > 0 (in {unit}), got "
                         f"{arr[bad].ravel()[0].item()!r}; allowed: 0 < {name} < infinity")
    return arr


@overload
def lam_from_dissipation(A: RealLike, rho: RealLike, m_eff: RealLike, v0: RealLike) -> float: ...


@overload
def lam_from_dissipation(A: RealArrayLike, rho: RealArrayLike, m_eff: RealArrayLike,
                         v0: RealArrayLike) -> float | FloatArray: ...


def lam_from_dissipation(A: RealArrayLike, rho: RealArrayLike, m_eff: RealArrayLike,
                         v0: RealArrayLike) -> float | FloatArray:
    """Zener's lambda of a viscoelastic grain contact from its dissipative constant A,
    lambda = A (rho/m_eff)^{2/5} v0^{1/5} (the forward map; ``zener_sym.lam_from_summary`` is
    the inverse of the solution, lambda from e, xi or tau_d).

    Derived in ``zener_sym.derivation.viscoelastic`` by mapping m_eff xi'' + rho (xi^{3/2} +
    A (xi^{3/2})') = 0 onto Eq. (10). Called ``viscoelastic_lambda`` before (that name still
    works, with a ``DeprecationWarning``).

    Parameters
    ----------
    A : float or array_like
        Dissipative constant [s], > 0.
    rho : float or array_like
        Hertz constant (4/3) E* sqrt(R_eff) [N/m^{3/2}], > 0.
    m_eff : float or array_like
        Effective mass [kg], > 0.
    v0 : float or array_like
        Normal impact speed [m/s], > 0.

    Returns
    -------
    float or numpy.ndarray
        lambda (dimensionless), broadcast over the inputs.

    Raises
    ------
    ValueError
        Naming the input that is not finite and > 0.

    Examples
    --------
    >>> import zener_sym as zs
    >>> round(zs.lam_from_dissipation(A=1e-6, rho=1e9, m_eff=1e-5, v0=1.0), 6)
    0.398107
    """
    A_ = _pos_array(A, "A", "s", "dissipative constant")
    r_ = _pos_array(rho, "rho", "N/m^(3/2)", "Hertz constant (4/3) E* sqrt(R_eff)")
    m_ = _pos_array(m_eff, "m_eff", "kg", "effective mass")
    v_ = _pos_array(v0, "v0", "m/s", "impact speed")
    lam: FloatArray = A_ * (r_ / m_) ** 0.4 * v_ ** 0.2
    return float(lam) if lam.ndim == 0 else lam


def viscoelastic_lambda(A: RealArrayLike, rho: RealArrayLike, m_eff: RealArrayLike,
                        v0: RealArrayLike) -> float | FloatArray:
    """The old name of :func:`lam_from_dissipation`, which said less about which lambda it gives:
    warns (``DeprecationWarning``) and delegates, until the next release removes it."""
    warnings.warn("viscoelastic_lambda is deprecated: use lam_from_dissipation (lambda from the "
                  "dissipative constant A; lam_from_summary is lambda from e, xi or tau_d)",
                  DeprecationWarning, stacklevel=2)
    return lam_from_dissipation(A, rho, m_eff, v0)


@dataclass
class GrainImpact:
    """Result of :func:`grain_impact` (SI units).

    Attributes
    ----------
    lam : float
        Zener's lambda of the contact.
    contact_end : str
        ``"force"`` (contact ends where the viscoelastic force vanishes) or ``"delta"`` (at xi = 0).
    criterion : str
        The end-of-contact criterion in words.
    e : float
        Coefficient of restitution (normal relative velocity after / before).
    contact_duration_s : float
        Duration of the contact [s].
    max_force_N : float
        Peak of the viscoelastic contact force rho (xi^{3/2} + A (xi^{3/2})') [N]; it comes
        before the end of compression, so it is the same for both criteria.
    max_compression_m : float
        Largest mutual compression xi [m].
    T, m_eff, rho, R_eff, E_star : float
        Time scale [s], effective mass [kg], Hertz constant [N/m^{3/2}], effective radius [m],
        effective modulus [Pa].
    t_s, force_N : numpy.ndarray
        History of the viscoelastic contact force [s], [N] at ``n_history`` times from 0 to the
        end of contact (with ``"delta"`` it turns negative, attractive, before the end).

    Field names follow :class:`~zener_sym.scene.scene.SceneResult`: dimensionless ones as in
    ``Summary``, SI ones with their unit in the name.

    Examples
    --------
    >>> import zener_sym as zs
    >>> r = zs.grain_impact("glass", "1 mm", 1e-5, A=1e-6, v0="1 m/s")
    >>> r.contact_end, round(r.lam, 4), round(r.e, 4)
    ('force', 0.6355, 0.4079)
    >>> f"{r.contact_duration_s * 1e6:.3f} us"
    '4.356 us'
    """

    lam: float
    contact_end: str
    criterion: str
    e: float
    contact_duration_s: float
    max_force_N: float
    max_compression_m: float
    T: float
    m_eff: float
    rho: float
    R_eff: float
    E_star: float
    t_s: FloatArray = field(repr=False)
    force_N: FloatArray = field(repr=False)


_CRITERIA = {"force": "contact ends where the viscoelastic force rho (xi^3/2 + A d/dt xi^3/2) "
                      "vanishes (grains separate; Schwager & Poeschel 2008)",
             "delta": "contact ends where the compression xi returns to 0 (plate criterion)"}


@dataclass(frozen=True)
class GrainContact:
    """The constants of a viscoelastic grain contact (SI): effective mass m_eff [kg], Hertz
    constant rho = (4/3) E* sqrt(R_eff) [N/m^{3/2}], effective radius R_eff [m] and modulus
    E* [Pa] (module docstring).

    Attributes
    ----------
    m_eff, rho, R_eff, E_star : float

    Examples
    --------
    >>> from zener_sym.scene.grains import grain_contact
    >>> c = grain_contact("glass", "1 mm", 1e-5, sphere2="glass", radius2="1 mm", mass2=1e-5)
    >>> c.m_eff, c.R_eff
    (5e-06, 0.0005)
    """

    m_eff: float
    rho: float
    R_eff: float
    E_star: float


@accepts_old_call(("R1", "m1", "material1"),
                  "grain_contact(sphere, radius, mass, sphere2=..., radius2=..., mass2=..., "
                  "wall=...)")
def grain_contact(sphere: Material | str, radius: float | str, mass: float, *,
                  sphere2: Material | str | None = None, radius2: float | str | None = None,
                  mass2: float | None = None,
                  wall: Material | str | None = None) -> GrainContact:
    """m_eff, rho, R_eff and E* of two spheres, or of a sphere on a wall (inputs as
    :func:`grain_impact`, which uses it, as do the inverse and the fit of
    :mod:`zener_sym.scene.calibrate`).

    Parameters
    ----------
    sphere, radius, mass, sphere2, radius2, mass2, wall
        As in :func:`grain_impact`.

    Returns
    -------
    GrainContact

    Raises
    ------
    ValueError
        For a non-positive or non-finite radius or mass, an unknown material, or a half-given
        sphere 2.
    """
    R1 = si_value(radius, "length", "radius")
    m1 = _positive(mass, "mass", "kg", "mass of the sphere")
    mat1 = get_material(sphere)
    given = [x is not None for x in (sphere2, radius2, mass2)]
    if any(given) and not all(given):
        raise ValueError("sphere 2 needs all of sphere2, radius2 and mass2 (leave all out for a "
                         "wall)")
    if all(given) and wall is not None:
        raise ValueError("give either sphere 2 (sphere2, radius2, mass2) or wall=, not both")
    inv_E = (1 - mat1.nu**2) / mat1.E
    if radius2 is not None and mass2 is not None and sphere2 is not None:
        r2 = si_value(radius2, "length", "radius2")
        m2 = _positive(mass2, "mass2", "kg", "mass of sphere 2")
        mat2 = get_material(sphere2)
        inv_E += (1 - mat2.nu**2) / mat2.E
        R_eff, m_eff = R1 * r2 / (R1 + r2), m1 * m2 / (m1 + m2)
    else:
        if wall is not None:
            w: Material = get_material(wall)
            inv_E += (1 - w.nu**2) / w.E
        R_eff, m_eff = R1, m1
    E_star = 1.0 / inv_E
    return GrainContact(m_eff=m_eff, rho=4.0 / 3.0 * E_star * math.sqrt(R_eff), R_eff=R_eff,
                        E_star=E_star)


@accepts_old_call(("R1", "m1", "material1", "A", "v0"),
                  "grain_impact(sphere, radius, mass, A=..., v0=..., ...)")
def grain_impact(sphere: Material | str, radius: float | str, mass: float, *, A: float,
                 v0: float | str, sphere2: Material | str | None = None,
                 radius2: float | str | None = None, mass2: float | None = None,
                 wall: Material | str | None = None, contact_end: str = "force",
                 n_history: int = 201) -> GrainImpact:
    """Two viscoelastic spheres, or a sphere on a wall, colliding head-on at speed ``v0``.

    Parameters
    ----------
    sphere : Material or str
        The sphere's elastic constants (``zener_sym.Material`` or a preset name; the density is
        not used, the mass is given).
    radius : float or str
        Its radius [m], or a string with a unit (e.g. ``"1 mm"``).
    mass : float
        Its mass [kg].
    A : float
        Dissipative constant of the contact [s] (module docstring); keyword-only.
    v0 : float or str
        Normal relative impact speed [m/s] (or a string with a unit); keyword-only.
    sphere2, radius2, mass2 : optional
        Sphere 2. Leave all three out for a wall.
    wall : Material or str, optional
        The wall's material for a sphere on a flat wall (infinite mass and radius); ``None``
        (and no sphere 2) is a rigid wall (E -> infinity).
    contact_end : {"force", "delta"}
        End-of-contact criterion (default the grains' force-free end).
    n_history : int
        Number of times in the force history (>= 2).

    Returns
    -------
    GrainImpact
        e, the contact duration, peak force and compression, the scales and the force history.

    Raises
    ------
    ValueError
        For a non-positive or non-finite radius, mass, A or speed, an unknown criterion or
        material, a half-given sphere 2, or a lambda outside the exact model's range.

    Examples
    --------
    >>> import zener_sym as zs
    >>> r = zs.grain_impact("steel", "1 mm", 1e-5, A=2e-6, v0="2 m/s", sphere2="steel",
    ...                     radius2="1 mm", mass2=1e-5)
    >>> r.criterion.startswith("contact ends where the viscoelastic force")
    True
    >>> lam = zs.lam_from_dissipation(2e-6, r.rho, r.m_eff, 2.0)
    >>> round(r.e, 4), round(r.lam, 4) == round(lam, 4)
    (0.1355, True)
    """
    contact_end = check_contact_end(contact_end)
    A = _positive(A, "A", "s", "dissipative constant")
    v0 = si_value(v0, "speed", "v0")
    if isinstance(n_history, bool) or not isinstance(n_history, int) or n_history < 2:
        raise ValueError(f"n_history must be an int >= 2, got {n_history!r}")
    c = grain_contact(sphere, radius, mass, sphere2=sphere2, radius2=radius2, mass2=mass2,
                      wall=wall)
    m_eff, rho, R_eff, E_star = c.m_eff, c.rho, c.R_eff, c.E_star
    lam = lam_from_dissipation(A, rho, m_eff, v0)
    if lam > LAMBDA_MAX:
        raise ValueError(f"A = {A!r} s, v0 = {v0!r} m/s with m_eff = {m_eff:.6g} kg and rho = {rho:.6g} "
                         f"N/m^(3/2) give lambda = {lam:.6g}; the exact model accepts "
                         f"0 <= lambda <= {LAMBDA_MAX:g}")
    T = (m_eff / rho) ** 0.4 * v0 ** -0.2
    s = summary(lam, model="exact", contact_end=contact_end)
    # the grains' force F_c peaks before the end of compression: F_m of the force-free reading
    F_m = s.F_m if contact_end == "force" else summary(lam, model="exact", contact_end="force").F_m
    tau = np.linspace(0.0, s.tau_d, n_history)
    h = history(lam, tau, model="exact", contact_end=contact_end)
    if contact_end == "force":
        fc = np.asarray(h.force)
    else:  # the plate reading's history gives delta and w = 1 - int delta^{3/2}; F_c from them
        d = np.asarray(h.delta)
        v = np.asarray(h.velocity) - lam * d**1.5
        fc = np.sqrt(d) * (d + 1.5 * lam * v)
    F_scale = m_eff * v0 / T
    return GrainImpact(lam=lam, contact_end=contact_end, criterion=_CRITERIA[contact_end], e=s.e,
                       contact_duration_s=T * s.tau_d, max_force_N=F_scale * F_m,
                       max_compression_m=v0 * T * s.delta_m, T=T, m_eff=m_eff, rho=rho,
                       R_eff=R_eff, E_star=E_star, t_s=T * tau, force_N=F_scale * fc)
