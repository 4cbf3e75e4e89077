"""The plate's mode formulas, bound to a math namespace, and the rectangle's static series.

``NUMPY`` and ``MPMATH`` hold the formulas (frequency equations and their derivatives, Omega_n,
psi_n, the static compliances) with their math namespace given. :func:`S_rectangle` sums the
simply supported rectangle's static compliance at the impact point (a series: no closed form).
"""
from __future__ import annotations

import math
import types

import mpmath
import numpy as np
from scipy import special

__all__ = ["NUMPY", "MPMATH", "S_rectangle"]


def _xp_numpy() -> types.SimpleNamespace:
    return types.SimpleNamespace(
        exp=np.exp, sin=np.sin, cos=np.cos, sqrt=np.sqrt, pi=np.pi, rational=lambda p, q: p / q,
        j0=special.j0, j1=special.j1, i0e=special.i0e, i1e=special.i1e, zeta=special.zeta)


# hand-written stand-ins, replaced by zener_sym.generated.plate (printed from the derivation)
def _formulas(xp: types.SimpleNamespace) -> types.SimpleNamespace:
    def freq_clamped(x):
        return xp.j0(x) * xp.i1e(x) + xp.j1(x) * xp.i0e(x)

    def freq_clamped_dx(x):
        g = freq_clamped(x)
        return 2 * xp.j0(x) * xp.i0e(x) - g / x - g

    def freq_ss(x, nu):
        j0, j1, i0, i1 = xp.j0(x), xp.j1(x), xp.i0e(x), xp.i1e(x)
        return (1 - nu) * (j1 * i0 + j0 * i1) - 2 * x * j0 * i0

    def freq_ss_dx(x, nu):
        j0, j1, i0, i1 = xp.j0(x), xp.j1(x), xp.i0e(x), xp.i1e(x)
        s = j0 * i1 + j1 * i0
        return ((1 - nu) * (2 * j0 * i0 - s / x) - 2 * j0 * i0 - 2 * x * (j0 * i1 - j1 * i0)
                - freq_ss(x, nu))

    def psi_circle(x):
        j0, j1, i0, i1 = xp.j0(x), xp.j1(x), xp.i0e(x), xp.i1e(x)
        tj, ti = j1 / j0, i1 / i0
        return (1 / j0 - xp.exp(-x) / i0) ** 2 / (xp.pi * (2 + tj**2 - ti**2 - 2 * (tj + ti) / x))

    return types.SimpleNamespace(
        freq_clamped=freq_clamped, freq_clamped_dx=freq_clamped_dx, freq_ss=freq_ss,
        freq_ss_dx=freq_ss_dx, Omega_circle=lambda x: x**2, psi_circle=psi_circle,
        Omega_rect=lambda m, k, s: xp.pi**2 * (m**2 / s + k**2 * s),
        psi_rect=lambda u, v: 4 * xp.sin(xp.pi * u) ** 2 * xp.sin(xp.pi * v) ** 2,
        S_circle_clamped=lambda: 1 / (16 * xp.pi),
        S_circle_ss=lambda nu: (3 + nu) / (16 * xp.pi * (1 + nu)),
        S_rect_algebraic=lambda s, cl3: s * (xp.zeta(3) - cl3) / (4 * xp.pi**3),
        S_rect_term=_rect_term(xp))


def _rect_term(xp):
    def term(m, s, xi, eta):
        c = m / s
        e1, ea, eb = (xp.exp(-2 * xp.pi * c * t) for t in (1, eta, 1 - eta))
        N, Dn = ea + eb - 2 * e1, 1 - e1
        dN, dDn = -2 * xp.pi * (eta * ea + (1 - eta) * eb - 2 * e1), 2 * xp.pi * e1
        g = xp.pi / (2 * c) * N / Dn
        dg = -g / c + xp.pi / (2 * c) * (dN * Dn - N * dDn) / Dn**2
        return xp.sin(xp.pi * m * xi) ** 2 / (xp.pi**4 * s**2 * c) * dg
    return term


NUMPY = _formulas(_xp_numpy())
MPMATH = None


def S_rectangle(s: float, xi: float, eta: float) -> float:
    """S = C_s D / (a b) of the simply supported a x b rectangle (s = a/b) at (xi, eta) = (x/a,
    y/b): the algebraic part in closed form (zeta(3) and Re Li_3), the rest a series in m whose
    terms fall as exp(-2 pi m min(eta, 1 - eta) / s)."""
    if s > 1.0:  # the same sum with the sides swapped: S(s, xi, eta) = S(1/s, eta, xi)
        s, xi, eta = 1.0 / s, eta, xi
    cl3 = float(mpmath.re(mpmath.polylog(3, mpmath.expjpi(2 * xi))))
    total = float(NUMPY.S_rect_algebraic(s, cl3))
    decay = 2 * math.pi * min(eta, 1 - eta) / s
    m_max = int(40.0 / decay) + 2
    m = np.arange(1, m_max + 1, dtype=float)
    return total + float(np.sum(NUMPY.S_rect_term(m, s, xi, eta)))
