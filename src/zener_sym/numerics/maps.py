"""The smoothstep map v -> v^2 (3 - 2 v) of [0, 1] onto itself, its slope and its inverse.

Its slope 6 v (1 - v) vanishes at both ends, which turns endpoint behaviours such as
(tau - A)^{3/2} into analytic functions of v: integrals of the contact force over a mapped piece
converge geometrically (:mod:`.integrate`). Written with plain arithmetic, so the same functions
serve numpy arrays, floats and mpmath numbers.
"""
from __future__ import annotations

from typing import TypeVar

import numpy as np

from ..typing import FloatArray, RealArrayLike

__all__ = ["smoothstep", "smoothstep_slope", "smoothstep_inverse"]


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
