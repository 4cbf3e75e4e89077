"""Vectorised root finding: the first zero of a function of (tau, lambda) for many lambda at once."""
from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..typing import FloatArray, RealArrayLike

__all__ = ["first_root"]


def first_root(fun: Callable[[FloatArray, FloatArray], FloatArray], lam: RealArrayLike,
               lo: RealArrayLike, hi: RealArrayLike, n_scan: int = 64,
               what: str = "root") -> FloatArray:
    """First zero of fun(tau, lam) in (lo, hi], per lambda, fun(lo) > 0 assumed.

    Scans about 2 n_scan cells (uniform and geometric from lo), then bisects the first cell
    where fun <= 0, all lambda values at once (no Python loop over points; the loop is over
    bisection steps), to a few ulps.

    Parameters
    ----------
    fun : callable
        fun(tau, lam) on arrays: tau of shape (L, cells) with lam (L, 1), or both (L,).
    lam, lo, hi : array_like
        1-D, one entry per lambda: the lambdas and the bracket's ends.
    n_scan : int
        Cells of each scan (uniform and geometric).
    what : str
        The root's name in the error message.

    Returns
    -------
    ndarray
        The first root per lambda.

    Raises
    ------
    ValueError
        If fun has no sign change in (lo, hi] for some lambda (the message names it).
    """
    lam_a = np.asarray(lam, dtype=float)
    lo_a = np.asarray(lo, dtype=float)
    hi_a = np.asarray(hi, dtype=float)
    # uniform cells plus geometric ones near lo: omega0 -> 0 stretches [lo, hi] to ~1/omega0
    # while the roots stay at tau = O(1)
    v = np.unique(np.concatenate([np.linspace(0.0, 1.0, n_scan + 1), np.geomspace(1e-10, 1.0, n_scan)]))
    grid = lo_a[:, None] + (hi_a - lo_a)[:, None] * v
    vals = fun(grid, lam_a[:, None])
    neg = vals <= 0.0
    neg[:, 0] = False
    found = neg.any(axis=1)
    if not found.all():
        bad = lam_a[~found][0]
        raise ValueError(f"no {what} found between tau = {lo_a[~found][0]:.6g} and "
                         f"{hi_a[~found][0]:.6g} at lambda = {bad!r}")
    j = np.argmax(neg, axis=1)
    rows = np.arange(lam_a.size)
    a, b = grid[rows, j - 1], grid[rows, j]
    for _ in range(200):
        mid = 0.5 * (a + b)
        done = (mid <= a) | (mid >= b)
        if done.all():
            break
        fm = fun(mid, lam_a)
        pos = fm > 0.0
        a = np.where(pos & ~done, mid, a)
        b = np.where(~pos & ~done, mid, b)
    root: FloatArray = 0.5 * (a + b)
    return root
