"""mpmath twins of the float64 primitives: P3 (``elementary.p3``) and the smoothstep-mapped contact
integral (``integrate.contact_integral``), for the mpmath HAM kernels."""
from __future__ import annotations

from collections.abc import Callable
from typing import Any

import mpmath

from .maps import smoothstep, smoothstep_slope

__all__ = ["p3_mp", "contact_integral_mp"]


def p3_mp(x: Any) -> Any:
    """P3(x) = (sin x - x cos x)/x^3 at the current mpmath precision (series for |x| < 1/2).

    Parameters
    ----------
    x : mpmath.mpf, float or str
        The argument (anything ``mpmath.mpf`` takes).

    Returns
    -------
    mpmath.mpf
        P3(x).
    """
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


def contact_integral_mp(fun: Callable[[Any], Any], A: Any, B: Any) -> Any:
    """integral_A^B fun(tau) dtau at the current mpmath precision, through the smoothstep map.

    The mpmath twin of ``integrate.contact_integral`` (mpmath.quad, Gauss-Legendre, on the
    mapped variable v, tau = A + (B - A) v^2 (3 - 2 v)).

    Parameters
    ----------
    fun : callable
        The integrand, taking and returning mpmath numbers.
    A, B : mpmath.mpf, float or str
        The limits; B <= A gives 0.

    Returns
    -------
    mpmath.mpf
        The integral.
    """
    A, B = mpmath.mpf(A), mpmath.mpf(B)
    if B <= A:
        return mpmath.mpf(0)
    L = B - A
    return L * mpmath.quad(lambda v: fun(A + L * smoothstep(v)) * smoothstep_slope(v), [0, 1],
                           method="gauss-legendre")
