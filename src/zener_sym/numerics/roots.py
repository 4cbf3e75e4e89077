"""Vectorised root finding: the first zero of a function of (tau, lambda) for many lambda at once."""
from __future__ import annotations

import numpy as np

__all__ = ["first_root"]


def first_root(fun, lam, lo, hi, n_scan=64, what="root"):
    """First zero of fun(tau, lam) in (lo, hi], per lambda (1-D arrays), fun(lo) > 0 assumed.

    Scans about 2 n_scan cells (uniform and geometric from lo), then bisects the first cell
    where fun <= 0, all lambda values at once (no Python loop over points; the loop is over
    bisection steps), to a few ulps. Raises ValueError, naming lambda, if there is no sign
    change.
    """
    lam = np.asarray(lam, dtype=float)
    lo = np.asarray(lo, dtype=float)
    hi = np.asarray(hi, dtype=float)
    # uniform cells plus geometric ones near lo: omega0 -> 0 stretches [lo, hi] to ~1/omega0
    # while the roots stay at tau = O(1)
    v = np.unique(np.concatenate([np.linspace(0.0, 1.0, n_scan + 1), np.geomspace(1e-10, 1.0, n_scan)]))
    grid = lo[:, None] + (hi - lo)[:, None] * v
    vals = fun(grid, lam[:, None])
    neg = vals <= 0.0
    neg[:, 0] = False
    found = neg.any(axis=1)
    if not found.all():
        bad = lam[~found][0]
        raise ValueError(f"no {what} found between tau = {lo[~found][0]:.6g} and "
                         f"{hi[~found][0]:.6g} at lambda = {bad!r}")
    j = np.argmax(neg, axis=1)
    rows = np.arange(lam.size)
    a, b = grid[rows, j - 1], grid[rows, j]
    for _ in range(200):
        mid = 0.5 * (a + b)
        done = (mid <= a) | (mid >= b)
        if done.all():
            break
        fm = fun(mid, lam)
        pos = fm > 0.0
        a = np.where(pos & ~done, mid, a)
        b = np.where(~pos & ~done, mid, b)
    return 0.5 * (a + b)
