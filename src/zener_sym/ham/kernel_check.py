"""Measure the generated numpy kernels against the generated mpmath kernels on a grid.

``measure()`` gives, per kernel, the largest relative error where
|mpmath value| >= 1e-3 and the largest absolute error where it is smaller (near zeros), over lambda in {0, 0.05, ..., 2.4, 2.4399} and tau at
40 points of [0, pi/omega0] (1e-8 from both ends included) plus 5 points of the continuation, and
the wall-time ratio mpmath / numpy for the whole grid measured in the same run.
"""
from __future__ import annotations

import time

import mpmath
import numpy as np

from ..typing import FloatArray


def grid() -> list[tuple[float, FloatArray]]:
    """The measurement grid: (lambda, its times) per lambda (module docstring).

    Returns
    -------
    list of (float, ndarray)
        lambda and the 45 tau values measured at it.
    """
    from .runtime_numpy import ham1 as h1

    lams = np.concatenate([np.round(np.arange(0, 2.41, 0.2), 10), [2.4399]])
    rows = []
    for lam in lams:
        tpi = float(np.pi / h1.params(lam)[2])
        taus = np.concatenate([[0.0, 1e-8], np.linspace(0, 1, 38)[1:-1] * tpi,
                               [tpi - 1e-8, tpi], tpi * np.array([1.05, 1.2, 1.4, 1.7, 2.0])])
        rows.append((float(lam), taus))
    return rows


def measure(dps: int = 30) -> tuple[dict[str, tuple[float, float]], float, int]:
    """The numpy kernels against the mpmath kernels on :func:`grid` (module docstring).

    Parameters
    ----------
    dps : int
        Working digits of the mpmath kernels.

    Returns
    -------
    errors : dict of str to (float, float)
        ``"ham0.delta"``, ... -> (largest relative error where |value| >= 1e-3, largest
        absolute error elsewhere).
    ratio : float
        Wall time of the mpmath kernels over the numpy kernels' on the whole grid.
    points : int
        Number of (lambda, tau) points per kernel.
    """
    from .runtime_mpmath import ham0 as m0
    from .runtime_mpmath import ham1 as m1
    from .runtime_numpy import ham0 as h0
    from .runtime_numpy import ham1 as h1

    kernels = [("ham0", "delta", h0, m0), ("ham0", "delta_dot", h0, m0), ("ham0", "impulse", h0, m0),
               ("ham1", "delta", h1, m1), ("ham1", "delta_dot", h1, m1), ("ham1", "force", h1, m1)]
    out: dict[str, tuple[float, float]] = {}
    t_np = t_mp = 0.0
    pts = grid()
    for order, name, hn, hm in kernels:
        worst_rel = worst_abs = 0.0
        for lam, taus in pts:
            t0 = time.perf_counter()
            a = getattr(hn, name)(taus, lam)
            t1 = time.perf_counter()
            with mpmath.workdps(dps):
                b = np.array([float(getattr(hm, name)(t, lam)) for t in taus])
            t2 = time.perf_counter()
            t_np += t1 - t0
            t_mp += t2 - t1
            big = np.abs(b) >= 1e-3
            err = np.abs(a - b)
            if big.any():
                worst_rel = max(worst_rel, float(np.max(err[big] / np.abs(b[big]))))
            if (~big).any():
                worst_abs = max(worst_abs, float(np.max(err[~big])))
        out[f"{order}.{name}"] = (worst_rel, worst_abs)
    return out, t_mp / t_np, sum(len(t) for _, t in pts)

