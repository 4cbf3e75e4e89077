"""Maps of [0, 1] whose slope vanishes at both ends.

* The smoothstep map v -> v^2 (3 - 2 v) of [0, 1] onto itself, its slope and its inverse. Its
  slope 6 v (1 - v) vanishes at both ends, which turns endpoint behaviours such as
  (tau - A)^{3/2} into analytic functions of v: integrals of the contact force over a mapped piece
  converge geometrically (:mod:`.integrate`). Written with plain arithmetic, so the same functions
  serve numpy arrays, floats and mpmath numbers.
* The HAM's phase map theta = pi sin^2(pi t / 2) of t in [0, 1] onto [0, pi] (``sine_squared``)
  and its inverse: quadratic at both ends, it makes the endpoint behaviours theta^{3/2} and
  (pi - theta)^{3/2} of the HAM's integrals analytic in t (:mod:`zener_sym.ham.spectral` and
  :mod:`zener_sym.ham.higher` share it).
"""
from __future__ import annotations

from typing import TypeVar

import numpy as np

from ..typing import FloatArray, RealArrayLike

__all__ = ["smoothstep", "smoothstep_slope", "smoothstep_inverse", "sine_squared",
           "sine_squared_inverse"]


#: A float or a float array (an mpmath number passes as well: mpmath is untyped).
_V = TypeVar("_V", float, FloatArray)


def smoothstep(v: _V) -> _V:
    """The smoothstep map v^2 (3 - 2 v).

    Parameters
    ----------
    v : float, ndarray or mpmath.mpf
        Points in [0, 1].

    Returns
    -------
    float, ndarray or mpmath.mpf
        The map at v, of v's type.
    """
    return v * v * (3.0 - 2.0 * v)


def smoothstep_slope(v: _V) -> _V:
    """The smoothstep map's slope, d/dv [v^2 (3 - 2 v)] = 6 v (1 - v).

    Parameters
    ----------
    v : float, ndarray or mpmath.mpf
        Points in [0, 1].

    Returns
    -------
    float, ndarray or mpmath.mpf
        The slope at v, of v's type.
    """
    return 6.0 * v * (1.0 - v)


def smoothstep_inverse(x: RealArrayLike) -> FloatArray:
    """v in [0, 1] with v^2 (3 - 2 v) = x.

    Parameters
    ----------
    x : array_like
        Values in [0, 1] (clipped to it).

    Returns
    -------
    ndarray
        v, x's shape.
    """
    c = np.clip(1.0 - 2.0 * np.asarray(x, dtype=float), -1.0, 1.0)
    v: FloatArray = 0.5 - np.sin(np.arcsin(c) / 3.0)
    return v


def sine_squared(t: RealArrayLike) -> tuple[FloatArray, FloatArray]:
    """The phase map theta = pi sin^2(pi t / 2) and its slope d theta / dt = (pi^2 / 2) sin(pi t).

    Parameters
    ----------
    t : array_like
        Points in [0, 1].

    Returns
    -------
    theta, dtheta_dt : ndarray
        The map and its slope at t, t's shape.
    """
    ta = np.asarray(t, dtype=float)
    s = np.sin(0.5 * np.pi * ta)
    theta: FloatArray = np.pi * s * s
    slope: FloatArray = 0.5 * np.pi * np.pi * np.sin(np.pi * ta)
    return theta, slope


def sine_squared_inverse(theta: RealArrayLike) -> FloatArray:
    """t in [0, 1] with pi sin^2(pi t / 2) = theta.

    Parameters
    ----------
    theta : array_like
        Values in [0, pi] (clipped to it).

    Returns
    -------
    ndarray
        t, theta's shape.
    """
    f = np.clip(np.asarray(theta, dtype=float) / np.pi, 0.0, 1.0)
    t: FloatArray = (2.0 / np.pi) * np.arcsin(np.sqrt(f))
    return t
