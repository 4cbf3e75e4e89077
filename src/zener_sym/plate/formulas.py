"""The plate's mode formulas bound to a math namespace, and the rectangle's static series.

``zener_sym.generated.plate`` prints each formula once (from ``zener_sym.derivation.plate``), with
the math namespace ``xp`` as first argument: ``XP_NUMPY`` (float64, scipy's Bessel functions)
or ``XP_MPMATH`` (at the working precision). ``NUMPY`` and ``MPMATH`` are the formulas with the
namespace given. :func:`S_rectangle` sums the simply supported rectangle's static compliance at
the impact point, a series (no closed form).
"""
from __future__ import annotations

import math
import types

import mpmath
import numpy as np
from scipy import special

from ..generated import plate as _plate
from ..ham.xp import bind

__all__ = ["XP_NUMPY", "XP_MPMATH", "NUMPY", "MPMATH", "S_rectangle"]

#: float64: numpy, and scipy's Bessel functions (i0e, i1e: e^{-x} I0, e^{-x} I1).
XP_NUMPY = types.SimpleNamespace(
    exp=np.exp, sin=np.sin, cos=np.cos, sqrt=np.sqrt, pi=np.pi, rational=lambda p, q: p / q,
    j0=special.j0, j1=special.j1, i0e=special.i0e, i1e=special.i1e, zeta=special.zeta)


class _Mpmath(types.SimpleNamespace):
    """mpmath at the caller's working precision (pi read when used)."""

    @property
    def pi(self) -> mpmath.mpf:
        return +mpmath.pi


#: mpmath, at the working precision of the call.
XP_MPMATH = _Mpmath(
    exp=mpmath.exp, sin=mpmath.sin, cos=mpmath.cos, sqrt=mpmath.sqrt,
    rational=lambda p, q: mpmath.mpf(p) / q,
    j0=lambda x: mpmath.besselj(0, x), j1=lambda x: mpmath.besselj(1, x),
    i0e=lambda x: mpmath.besseli(0, x) * mpmath.exp(-x),
    i1e=lambda x: mpmath.besseli(1, x) * mpmath.exp(-x), zeta=mpmath.zeta)

#: The formulas in float64.
NUMPY = bind(_plate, XP_NUMPY)
#: The formulas in mpmath.
MPMATH = bind(_plate, XP_MPMATH)


def S_rectangle(s: float, xi: float, eta: float) -> float:
    """S = C_s D / (a b) of the simply supported a x b rectangle at (x/a, y/b) = (xi, eta).

    The sum over one mode number is in closed form (``zener_sym.derivation.plate``): an
    algebraic part with zeta(3) and Cl_3(2 pi xi) = Re Li_3(exp(2 pi i xi)), and terms in m that
    fall as exp(-2 pi m min(eta, 1 - eta) / s), summed to below rounding. The sum runs over the
    longer side's modes (S(s, xi, eta) = S(1/s, eta, xi)), so that s <= 1 and they fall fast.

    Parameters
    ----------
    s : float
        The aspect a/b > 0.
    xi, eta : float
        The impact point, each in (0, 1).

    Returns
    -------
    float
        S, so that C_s = S a b / D.

    Examples
    --------
    >>> from zener_sym.plate.formulas import S_rectangle
    >>> round(S_rectangle(1.0, 0.5, 0.5), 5)  # Timoshenko: 0.01160 at a square's centre
    0.0116
    """
    if s > 1.0:
        s, xi, eta = 1.0 / s, eta, xi
    cl3 = float(mpmath.re(mpmath.polylog(3, mpmath.expjpi(2 * xi))))
    total = float(NUMPY.S_rect_algebraic(s, cl3))
    decay = 2 * math.pi * min(eta, 1 - eta) / s  # per m, >= 2 pi min(eta, 1 - eta)
    m = np.arange(1, int(40.0 / decay) + 3, dtype=float)
    return total + math.fsum(NUMPY.S_rect_term(m, s, xi, eta))
