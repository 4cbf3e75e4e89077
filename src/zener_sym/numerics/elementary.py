"""Elementary functions evaluated without loss of digits where the direct formula loses them.

* ``p3(x) = (sin x - x cos x) / x^3``: the elementary part of the first-order HAM correction
  delta1 is written with it, so that tau -> 0 and omega0 -> 0 lose no digits. Series below
  |x| < 1/2 (evaluated only at the points that need it), direct formula above.
* ``half_wave_sin``: the sine's first half wave, vectorized (numpy's float64 sine is a scalar
  loop on this build: about 8 ns a point against about 3).
"""
from __future__ import annotations

import math

import numpy as np

from ..typing import FloatArray, RealArrayLike
from .taylor import horner

__all__ = ["p3", "half_wave_sin"]

# Taylor coefficients of P3: sum_j (-1)^j 2 (j + 1) x^{2j} / (2j + 3)!
_P3_COEF = [(-1) ** j * 2.0 * (j + 1) / math.factorial(2 * j + 3) for j in range(12)]


def p3(x: RealArrayLike) -> FloatArray:
    """P3(x) = (sin x - x cos x)/x^3, accurate to rounding (P3(0) = 1/3).

    Parameters
    ----------
    x : array_like
        Real arguments (omega0 tau in delta1).

    Returns
    -------
    ndarray
        P3 at x, x's shape.
    """
    xa = np.asarray(x, dtype=float)
    shape = xa.shape
    x = xa.reshape(-1)
    small = np.abs(x) < 0.5
    xs = np.where(small, 1.0, x)
    out: FloatArray = (np.sin(xs) - xs * np.cos(xs)) / (xs * xs * xs)
    if small.any():  # the series only where it is needed: most points of a history are not small
        x2 = x[small] ** 2
        out[small] = horner(_P3_COEF, x2)  # in x^2; 12 terms reach 1e-19 at |x| = 1/2
    return out.reshape(shape)


# Taylor coefficients of sin(y) / y in s = y^2, (-1)^k / (2k + 1)!: on |y| <= pi/2 the first one
# dropped (k = 11) weighs (pi/2)^22 / 23! < 1e-18.
_SIN_COEF = [(-1) ** k / math.factorial(2 * k + 1) for k in range(11)]
# pi = _PI_HI + _PI_LO: _PI_HI - theta is exact for theta in [pi/2, pi] (Sterbenz), so
# pi - theta keeps its relative accuracy up to theta = pi
_PI_HI = math.pi
_PI_LO = 1.2246467991473532e-16  # pi - math.pi; tests derive it with mpmath


def half_wave_sin(theta: RealArrayLike) -> FloatArray:
    """sin(theta) for 0 <= theta <= pi and 0 beyond: the sine's first half wave.

    That is where the zeroth-order HAM compression delta0 (35) is positive (its contact ends at
    omega0 tau = pi, Eq. 54). Vectorized: y = min(theta, pi - theta) in [0, pi/2] (pi in two
    parts), clipped at 0 past pi, then y (1 + s P(s)) with s = y^2 by Horner's rule on the
    Taylor coefficients. Within 3 ulp of the correctly rounded sine on [0, pi]
    (tests/test_ham_chebyshev.py, against mpmath).

    Parameters
    ----------
    theta : array_like
        Phases omega0 tau, >= 0.

    Returns
    -------
    ndarray
        The half wave at theta, theta's shape.

    Raises
    ------
    ValueError
        If a theta is negative or NaN.
    """
    shape = np.shape(theta)
    th = np.asarray(theta, dtype=float).reshape(-1)  # the in-place steps need an array, not a 0-d
    if th.size and not th.min() >= 0:  # a NaN fails too
        raise ValueError("half_wave_sin: theta must be >= 0 (and not NaN)")
    y: FloatArray = _PI_HI - th
    y += _PI_LO
    np.minimum(y, th, out=y)
    np.maximum(y, 0.0, out=y)  # past pi: 0
    s = y * y
    p = np.full_like(s, _SIN_COEF[-1])
    for c in _SIN_COEF[-2::-1]:
        p *= s
        p += c
    p *= y
    return p.reshape(shape)
