"""Hunter's (1957) and Reed's (1985) stress-wave loss of a sphere on an elastic half-space.

The closed form is derived and checked in ``zener_sym.derivation.stress_waves`` (``python -m
zener_sym.derivation.stress_waves``); this module evaluates it in numpy/scipy:

    xi = W / (m1 V0^2 / 2) = k V0^{3/5},
    k = h(nu2) J / (pi rho2 c2^3) (4 E* / 3)^{6/5} (4 pi rho1 / 3)^{-1/5},

with W = h / (2 pi rho2 c2^3) int F'(t)^2 dt the energy a normal surface force F(t) radiates into
the half-space (Lamb; Miller & Pursey 1954), h(nu2) its dimensionless radiation constant (body
waves plus the Rayleigh pole), c2 = sqrt(E2 / (2 (1 + nu2) rho2)) the half-space's shear speed,
E* the effective modulus of both materials (Eq. 8), rho1 the sphere's density (its mass
m1 = (4/3) pi R^3 rho1; R drops out), and J = int (dF-bar/dtau)^2 dtau of the pulse in the
paper's scaling (Eq. 9):

* ``hunter``: Eq. (52), F-bar = A sin(Omega tau), J = (pi/2) A^2 Omega;
* ``reed``: Eq. (53) with the exponent 3/2 of Eq. (6), J = (3/2) A^2 Omega;
* ``hertz``: the exact Hertz pulse (lambda = 0), J = (9/5) (5/4)^{4/5} B(4/5, 3/2).

The half-space is the plate: its flexure (Zener's lambda) is not in this loss, and the loss does
not feed back on the pulse (one-way coupling, as in Hunter's and Reed's papers).
"""
from __future__ import annotations

import functools
import math
from typing import overload

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

from ..models import formulas as fm
from ..typing import FloatArray, RealArrayLike, RealLike
from .materials import Material

__all__ = ["PULSES", "radiation_constant", "stress_wave_k", "stress_wave_loss"]

#: J = int (dF-bar/dtau)^2 dtau of each pulse (derivation.stress_waves.PULSE_J).
_J = {
    "hunter": math.pi / 2.0 * fm.A_HUNTER**2 * fm.OMEGA_HUNTER,
    "reed": 1.5 * fm.A_REED**2 * fm.OMEGA_HUNTER,
    "hertz": 1.8 * 1.25**0.8 * math.gamma(0.8) * math.gamma(1.5) / math.gamma(2.3),
}
#: The force pulses the loss is computed for.
PULSES = tuple(_J)


def _D(s: float, k2: float) -> float:
    return 4 * s * s * math.sqrt(s * s - k2) * math.sqrt(s * s - 1) - (2 * s * s - 1) ** 2


@functools.lru_cache(maxsize=64)
def radiation_constant(nu: float) -> tuple[float, float]:
    """h(nu) of the half-space and its Rayleigh-wave share.

    Parameters
    ----------
    nu : float
        Poisson's ratio of the half-space, -1 < nu < 0.5.

    Returns
    -------
    (h, rayleigh) : tuple of float
        Im G(omega) = omega h / (2 pi rho c2^3) at the loaded point; ``rayleigh`` the fraction
        of the radiated energy carried by the Rayleigh wave (0.674 at nu = 1/4, Miller & Pursey).

    Raises
    ------
    ValueError
        If nu is not a finite number in (-1, 0.5).

    Examples
    --------
    >>> from zener_sym.scene.stress_waves import radiation_constant
    >>> h, rayleigh = radiation_constant(0.25)
    >>> round(h, 6), round(rayleigh, 3)
    (0.930753, 0.674)
    """
    if not isinstance(nu, (int, float)) or not math.isfinite(nu) or not -1.0 < nu < 0.5:
        raise ValueError(f"nu must be a finite number with -1 < nu < 0.5, got {nu!r}")
    k2 = (1 - 2 * nu) / (2 * (1 - nu))   # (c2 / c1)^2
    ka = math.sqrt(k2)

    def f1(s: float) -> float:  # both waves propagate (s < kappa): the outgoing branches make D real
        a, b = math.sqrt(max(k2 - s * s, 0.0)), math.sqrt(max(1 - s * s, 0.0))
        return s * a / ((2 * s * s - 1) ** 2 + 4 * s * s * a * b)

    def f2(s: float) -> float:  # only the shear wave propagates (kappa < s < 1)
        a2, b = max(s * s - k2, 0.0), math.sqrt(max(1 - s * s, 0.0))
        return 4 * s**3 * a2 * b / ((2 * s * s - 1) ** 4 + 16 * s**4 * a2 * b * b)

    i1 = float(quad(f1, 0.0, ka, epsabs=0.0, epsrel=1e-13, limit=200)[0])
    i2 = float(quad(f2, ka, 1.0, epsabs=0.0, epsrel=1e-13, limit=200)[0])
    sr: float = brentq(lambda s: _D(s, k2), 1.0 + 1e-15, 2.0, xtol=1e-16, rtol=4 * np.finfo(float).eps)
    al, be = math.sqrt(sr * sr - k2), math.sqrt(sr * sr - 1)
    dD = 8 * sr * al * be + 4 * sr**3 * (be / al + al / be) - 8 * sr * (2 * sr * sr - 1)
    ir = math.pi * sr * al / dD
    h = i1 + i2 + ir
    return h, ir / h


def _check_pulse(pulse: str) -> None:
    if pulse not in _J:
        raise ValueError(f"unknown pulse {pulse!r}; allowed: {', '.join(PULSES)}")


def stress_wave_k(sphere: Material, plate: Material, pulse: str = "hunter") -> float:
    """k of the half-space stress-wave loss xi = k V0^{3/5} (V0 in m/s).

    Parameters
    ----------
    sphere, plate : Material
        The sphere and the half-space (the plate, its flexure ignored).
    pulse : {"hunter", "reed", "hertz"}
        Hunter's sine (Eq. 52), Reed's sin^{3/2} (Eqs. 6, 53) or the exact Hertz pulse.

    Returns
    -------
    float
        k in (s/m)^{3/5}; independent of the sphere's radius.

    Raises
    ------
    ValueError
        For an unknown pulse or an argument that is not a Material.

    Examples
    --------
    >>> from zener_sym import TABLE1_SPHERE, TABLE1_PLATE
    >>> from zener_sym.scene.stress_waves import stress_wave_k
    >>> round(stress_wave_k(TABLE1_SPHERE, TABLE1_PLATE, "hunter"), 7)
    0.001531
    """
    _check_pulse(pulse)
    for name, m in (("sphere", sphere), ("plate", plate)):
        if not isinstance(m, Material):
            raise ValueError(f"{name} must be a Material, got {type(m).__name__}")
    es = 1.0 / ((1 - sphere.nu**2) / sphere.E + (1 - plate.nu**2) / plate.E)
    c2 = math.sqrt(plate.E / (2 * (1 + plate.nu) * plate.rho))
    h, _ = radiation_constant(float(plate.nu))
    return float(h * _J[pulse] / (math.pi * plate.rho * c2**3) * (4 * es / 3) ** 1.2
                 * (4 * math.pi * sphere.rho / 3) ** -0.2)


@overload
def stress_wave_loss(sphere: Material, plate: Material, v0: RealLike,
                     pulse: str = "hunter") -> float: ...


@overload
def stress_wave_loss(sphere: Material, plate: Material, v0: RealArrayLike,
                     pulse: str = "hunter") -> float | FloatArray: ...


def stress_wave_loss(sphere: Material, plate: Material, v0: RealArrayLike,
                     pulse: str = "hunter") -> float | FloatArray:
    """Hunter's/Reed's stress-wave loss xi = k V0^{3/5} at impact speeds v0 (m/s).

    Parameters
    ----------
    sphere, plate : Material
        The sphere and the half-space (the plate, its flexure ignored).
    v0 : float or array_like
        Impact speeds in m/s, finite and >= 0.
    pulse : {"hunter", "reed", "hertz"}
        The force pulse, as for :func:`stress_wave_k`.

    Returns
    -------
    float or numpy.ndarray
        xi with the shape of ``v0``.

    Raises
    ------
    ValueError
        For a negative or non-finite speed, an unknown pulse, or a non-Material.

    Examples
    --------
    >>> from zener_sym import TABLE1_SPHERE, TABLE1_PLATE
    >>> from zener_sym.scene.stress_waves import stress_wave_loss
    >>> round(float(stress_wave_loss(TABLE1_SPHERE, TABLE1_PLATE, 10.0, "reed")), 5)
    0.00699
    """
    v = np.asarray(v0, dtype=float)
    if not np.all(np.isfinite(v)) or np.any(v < 0):
        raise ValueError(f"v0 must be finite and >= 0 (m/s), got {v0!r}")
    xi: FloatArray = stress_wave_k(sphere, plate, pulse) * v**0.6
    return float(xi) if xi.ndim == 0 else xi
