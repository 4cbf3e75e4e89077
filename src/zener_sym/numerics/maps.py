"""The smoothstep map v -> v^2 (3 - 2 v) of [0, 1] onto itself, its slope and its inverse.

Its slope 6 v (1 - v) vanishes at both ends, which turns endpoint behaviours such as
(tau - A)^{3/2} into analytic functions of v: integrals of the contact force over a mapped piece
converge geometrically (:mod:`.integrate`). Written with plain arithmetic, so the same functions
serve numpy arrays, floats and mpmath numbers.
"""
from __future__ import annotations

import numpy as np

__all__ = ["smoothstep", "smoothstep_slope", "smoothstep_inverse"]


def smoothstep(v):
    """v^2 (3 - 2 v)."""
    return v * v * (3.0 - 2.0 * v)


def smoothstep_slope(v):
    """d/dv smoothstep(v) = 6 v (1 - v)."""
    return 6.0 * v * (1.0 - v)


def smoothstep_inverse(x):
    """v in [0, 1] with v^2 (3 - 2 v) = x, for x in [0, 1] (clipped), float arrays."""
    return 0.5 - np.sin(np.arcsin(np.clip(1.0 - 2.0 * x, -1.0, 1.0)) / 3.0)
