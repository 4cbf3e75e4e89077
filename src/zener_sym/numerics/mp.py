"""mpmath twins of the float64 primitives: P3 (``elementary.p3``) and the smoothstep-mapped contact
integral (``integrate.contact_integral``), for the mpmath HAM kernels."""
from __future__ import annotations

import mpmath

from .maps import smoothstep, smoothstep_slope

__all__ = ["p3_mp", "contact_integral_mp"]


def p3_mp(x):
    """P3 at the current mpmath precision (series for |x| < 1/2)."""
    x = mpmath.mpf(x)
    if abs(x) >= 0.5:
        return (mpmath.sin(x) - x * mpmath.cos(x)) / x**3
    tot, term, j = mpmath.mpf(0), None, 0
    eps = mpmath.eps
    while True:
        term = (-1) ** j * 2 * (j + 1) * x ** (2 * j) / mpmath.factorial(2 * j + 3)
        tot += term
        if abs(term) < eps * abs(tot):
            return tot
        j += 1


def contact_integral_mp(fun, A, B):
    """Same as ``contact_integral`` for mpmath scalars (mpmath.quad on the mapped variable)."""
    A, B = mpmath.mpf(A), mpmath.mpf(B)
    if B <= A:
        return mpmath.mpf(0)
    L = B - A
    return L * mpmath.quad(lambda v: fun(A + L * smoothstep(v)) * smoothstep_slope(v), [0, 1],
                           method="gauss-legendre")
