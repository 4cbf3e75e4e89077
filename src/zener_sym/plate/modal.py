"""The dimensionless modal plate: the one object the plate's modes hand to the impact solver.

In Zener's scales (tau = t/t_0, delta-bar = delta/delta_0, F-bar = F/(k delta_0^{3/2}), with
m delta_0 / t_0^2 = k delta_0^{3/2} and delta_0 = v_0 t_0) the sphere and the plate's modes obey

    x'' = -F,   y_n'' + omega_n^2 y_n = c_n F,   w = sum_n y_n + C_res F,
    delta = x - w,   F = max(delta, 0)^{3/2},   x(0) = 0, x'(0) = 1, y_n(0) = y_n'(0) = 0,

with omega_n = omega_n^SI t_0, c_n = m phi_n(impact)^2 / M_n (sphere mass over modal mass, the
mode normalised at will) and C_res = C_s - sum_{n <= N} c_n / omega_n^2, where C_s = m C_s^SI /
t_0^2 is the whole plate's static compliance at the impact point. Zener's lambda (Eq. 11) is
m / (8 t_0 sqrt(D rho h)); the plate-size parameter is beta = t_0 sqrt(D / (rho h)) / L^2 (L the
circle's radius b, or sqrt(a b) for an a x b rectangle), so omega_n = beta Omega_n and
c_n = 8 lambda beta psi_n with Omega_n, psi_n numbers of the plate's shape and support alone.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from ..typing import FloatArray

__all__ = ["ModalPlate"]


@dataclasses.dataclass(frozen=True)
class ModalPlate:
    """N modes of a bounded plate seen from the impact point, in Zener's scales.

    Attributes
    ----------
    omega : ndarray, shape (N,)
        The modes' angular frequencies omega_n t_0, ascending, > 0.
    c : ndarray, shape (N,)
        Their participations c_n = m phi_n(impact)^2 / M_n, >= 0.
    static : float
        The whole plate's static compliance at the impact point, C_s m / t_0^2 (all modes).
    support : str
        ``"clamped"`` or ``"simply-supported"``.
    shape : str
        ``"circle"`` or ``"rectangle"``.
    """

    omega: FloatArray
    c: FloatArray
    static: float
    support: str
    shape: str

    @property
    def residual(self) -> float:
        """C_res = C_s - sum_n c_n / omega_n^2: the quasi-static compliance of the modes left out."""
        return float(self.static - np.sum(self.c / self.omega**2))
