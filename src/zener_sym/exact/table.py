"""Fast exact solution of Eq. (10): Chebyshev tables in lambda (and time), evaluated with numpy.

The tables (``generated/exact_table.py``, built offline by :mod:`zener_sym.exact.table_build` from
the scipy solver at rtol 1e-13) cover ``LAM_MIN <= lambda <= LAM_MAX`` for the summary (above
``HISTORY_LAM_MAX`` in the variable ln lambda, from the universal large-lambda orbit) and
``LAM_MIN <= lambda <= HISTORY_LAM_MAX`` for the history. They are never extrapolated:
:func:`in_range` and :func:`history_in_range` tell the caller which lambda must be integrated.

Documented error bounds: ``SUMMARY_RTOL`` relative on every summary field, ``HISTORY_ATOL`` on
delta/delta_m, force/F_m, impulse and velocity, both against the mpmath reference (``exact.mp``)
at lambda between the nodes: ``benchmarks/exact_fast_error.py`` measures them on [0, 5] and
docs/exact.md lists the numbers; ``tests/test_exact_fast.py`` and ``tests/test_exact_large.py``
check them between nodes on [0, 5] and on (5, 1000].

Note that near the end of contact the *pointwise relative* error of delta grows like
(error of tau_d) / (tau_d - tau): delta(tau) is ill-conditioned there for any method whose
tau_d is not exact.
"""
from __future__ import annotations

import functools
import importlib

import numpy as np

from ..ham.chebyshev import clenshaw_take
from . import table_build as _build

__all__ = ["LAM_MIN", "LAM_MAX", "HISTORY_LAM_MAX", "SUMMARY_RTOL", "HISTORY_ATOL", "in_range",
           "history_in_range", "summary", "history"]

LAM_MIN = float(_build.LAM_PIECES[0])
LAM_MAX = float(_build.LAM_PIECES[-1])
#: The history tables end here (the summary goes on to LAM_MAX).
HISTORY_LAM_MAX = float(_build.LOG_FROM)
#: Documented (and tested) relative error bound of every summary field.
SUMMARY_RTOL = 1e-11
#: Documented (and tested) error bound of the history, relative to each field's scale.
HISTORY_ATOL = 1e-10


def _stack(mats) -> np.ndarray:
    """One zero-padded array [lambda piece, time degree, lambda degree] (trimming varies)."""
    mats = [np.asarray(c, dtype=float) for c in mats]
    out = np.zeros((len(mats), max(c.shape[0] for c in mats), max(c.shape[1] for c in mats)))
    for i, c in enumerate(mats):
        out[i, : c.shape[0], : c.shape[1]] = c
    return out


def _pad_rows(rows) -> np.ndarray:
    """Zero-padded 2-D array from 1-D coefficient tuples of different lengths."""
    out = np.zeros((len(rows), max(len(r) for r in rows)))
    for i, r in enumerate(rows):
        out[i, : len(r)] = r
    return out


@functools.cache
def _tables():
    """The generated table, loaded on first use (parsing it costs ~0.1 s without a .pyc)."""
    t = importlib.import_module("zener_sym.generated.exact_table")
    if (tuple(t.LAM_PIECES) != tuple(_build.LAM_PIECES) or t.C_STRETCH != _build.C_STRETCH
            or getattr(t, "LOG_FROM", None) != _build.LOG_FROM):
        raise RuntimeError("generated/exact_table.py does not match zener_sym.exact.table_build (stale "
                           "table): run `zener-sym exact-table`")
    edges = np.asarray(t.LAM_PIECES, dtype=float)
    log = edges[:-1] >= t.LOG_FROM
    # per piece: the Chebyshev variable's ends (lambda, or ln lambda on the large pieces)
    with np.errstate(divide="ignore"):
        ga = np.where(log, np.log(np.where(log, edges[:-1], 1.0)), edges[:-1])
        gb = np.where(log, np.log(edges[1:]), edges[1:])
    return {"edges": edges, "log": log, "ga": ga, "gb": gb, "c": float(t.C_STRETCH),
            "summary_keys": tuple(t.SUMMARY),
            # [lambda piece, field, degree], zero-padded: all fields in one pass
            "summary": _stack([_pad_rows([v[p] for v in t.SUMMARY.values()])
                               for p in range(len(t.LAM_PIECES) - 1)]),
            "history": {k: _stack(v) for k, v in t.HISTORY.items()}}


def in_range(lam) -> np.ndarray:
    """Boolean mask: lambda inside the summary table's validated range [LAM_MIN, LAM_MAX]."""
    lam = np.asarray(lam, dtype=float)
    return (lam >= LAM_MIN) & (lam <= LAM_MAX)


def history_in_range(lam) -> np.ndarray:
    """Boolean mask: lambda inside the history table's range [LAM_MIN, HISTORY_LAM_MAX]."""
    lam = np.asarray(lam, dtype=float)
    return (lam >= LAM_MIN) & (lam <= HISTORY_LAM_MAX)


def _piece(lam: np.ndarray, history: bool = False):
    """Lambda piece index and the local Chebyshev variable x in [-1, 1] (``history``: among the
    pieces that carry a history table, so lambda = HISTORY_LAM_MAX is the end of the last)."""
    if not np.all(in_range(lam)):
        bad = float(lam[~in_range(lam)].ravel()[0])
        raise ValueError(f"lambda = {bad!r} is outside the exact table's range "
                         f"[{LAM_MIN:g}, {LAM_MAX:g}]; integrate instead (backend='scipy')")
    t = _tables()
    edges = t["edges"]
    last = int(np.count_nonzero(~t["log"])) - 1 if history else len(edges) - 2
    i = np.clip(np.searchsorted(edges, lam, side="right") - 1, 0, last)
    log = t["log"][i]
    with np.errstate(divide="ignore"):
        g = np.where(log, np.log(np.where(log, lam, 1.0)), lam)
    a, b = t["ga"][i], t["gb"][i]
    return i, np.clip((2.0 * g - a - b) / (b - a), -1.0, 1.0)


def _core(lam: np.ndarray, history: bool = False) -> dict:
    i, x = _piece(lam, history)
    t = _tables()
    c = t["summary"]
    tl = np.polynomial.chebyshev.chebvander(x, c.shape[2] - 1)  # [lambda, degree]
    # a plain sum in a fixed order: each lambda's value does not depend on how many others are
    # evaluated with it (einsum's blocking did, by an ulp), so summary and history agree on tau_d
    ci = c[i]
    vals = tl[:, :1] * ci[:, :, 0]
    for k in range(1, tl.shape[1]):
        vals += tl[:, k:k + 1] * ci[:, :, k]
    v = dict(zip(t["summary_keys"], vals.T))
    v["tau_d"] = np.exp(v["log_tau_d"])
    # e from the energy loss while xi < 1/2 (as the solver's end_velocity): never above 1 and
    # exactly 1 at lambda = 0, where exp(log_e) gave 1 + 1.2e-14
    xi = 2.0 * lam * v["int_F2"]
    v["e"] = np.where(xi < 0.5, np.sqrt(np.maximum(1.0 - xi, 0.0)), np.exp(v["log_e"]))
    v["tau_w0"] = v["tau_dc"] + lam * v["rest_over_lam"]
    return v, i, x


def summary(lam) -> dict:
    """Every summary field (see ``models.SUMMARY_FIELDS``) for lambda in [LAM_MIN, LAM_MAX].

    xi comes from the energy balance xi = 2 lambda int_F2 (exact for Eq. 10), which keeps its
    relative accuracy as lambda -> 0, where 1 - e^2 would cancel.
    """
    lam = np.asarray(lam, dtype=float)
    v, _, _ = _core(lam)
    tau_dr = v["tau_d"] - v["tau_dc"]
    return {"lam": lam, "delta_m": v["delta_m"], "tau_dc": v["tau_dc"], "tau_d": v["tau_d"],
            "tau_dr": tau_dr, "eta": tau_dr / v["tau_dc"], "e": v["e"],
            "F_m": v["delta_m"] ** 1.5, "impulse": 1.0 + v["e"], "int_F2": v["int_F2"],
            "xi": 2.0 * lam * v["int_F2"]}


def _time_coefficients(key, ip: np.ndarray, xl: np.ndarray) -> np.ndarray:
    """Chebyshev coefficients in time, one row per lambda: sum_k C[j, k] T_k(x_lambda).

    Plain broadcasting, no BLAS: the sizes are small and a threaded matmul only adds overhead.
    """
    c = _tables()["history"][key]
    tl = np.polynomial.chebyshev.chebvander(xl, c.shape[2] - 1)  # [lambda, k]
    return np.einsum("lk,ljk->lj", tl, c[ip], optimize=False)


def _clenshaw_rows(rows_coef, idx, x):
    """sum_j rows_coef[idx, j] T_j(x) pointwise (Clenshaw), each point taking its coefficient
    from its row by index: no (points x degree) temporaries (a Vandermonde matrix and gathered
    rows cost about 4x more here)."""
    return clenshaw_take(np.ascontiguousarray(rows_coef.T), idx, x)


def history(lam, tau) -> dict:
    """delta, impulse, velocity (1 - I) and force (delta^{3/2}) at (lam, tau), same shapes.

    lam and tau must already be broadcast to one shape; lambda in [LAM_MIN, HISTORY_LAM_MAX],
    tau >= 0.
    The lambda direction is contracted once per distinct lambda, then each time point costs one
    Chebyshev series in time per field (Clenshaw).
    """
    lam = np.asarray(lam, dtype=float)
    tau = np.asarray(tau, dtype=float)
    shape = tau.shape
    if lam.ndim >= 1 and lam.shape[-1] > 1 and np.array_equal(
            lam, np.broadcast_to(lam[..., :1], lam.shape)):
        # one lambda per line of tau (a broadcast column): sort the lines, not every point
        lu, inv = np.unique(lam[..., 0], return_inverse=True)
        inv = np.broadcast_to(inv.reshape(lam.shape[:-1] + (1,)), lam.shape).ravel()
    else:
        lu, inv = np.unique(lam.ravel(), return_inverse=True)
    if not np.all(history_in_range(lu)):
        bad = float(lu[~history_in_range(lu)][0])
        raise ValueError(f"lambda = {bad!r} is outside the exact history table's range "
                         f"[{LAM_MIN:g}, {HISTORY_LAM_MAX:g}]; integrate instead (backend='scipy')")
    tau = tau.ravel()
    v, ip, xl = _core(lu, history=True)
    tau_dc, tau_w0, tau_d = v["tau_dc"][inv], v["tau_w0"][inv], v["tau_d"][inv]
    delta = np.zeros(tau.shape)
    imp = (1.0 + v["e"])[inv]  # after the contact the impulse keeps its final value
    piece = np.full(tau.shape, -1)
    piece[tau <= tau_dc] = 0
    piece[(tau > tau_dc) & (tau < tau_w0)] = 1
    piece[(tau >= tau_w0) & (tau < tau_d)] = 2
    for n, name in enumerate(("C", "A", "B")):
        m = piece == n
        if not m.any():
            continue
        t, dc, w0, d = tau[m], tau_dc[m], tau_w0[m], tau_d[m]
        if name == "C":
            y = np.sqrt(t / dc)
        elif name == "A":  # only reached when tau_w0 > tau_dc, so beta > 0
            y = np.log1p((t - dc) / _tables()["c"]) / np.log1p((w0 - dc) / _tables()["c"])
        else:
            y = np.sqrt((d - t) / (d - w0))
        xt = np.clip(2.0 * y - 1.0, -1.0, 1.0)
        im = inv[m]
        f = _clenshaw_rows(_time_coefficients((name, "f"), ip, xl), im, xt)
        imp[m] = _clenshaw_rows(_time_coefficients((name, "I"), ip, xl), im, xt)
        if name == "C":
            delta[m] = t * np.exp(f)
        elif name == "A":
            delta[m] = np.exp(f)
        else:
            delta[m] = (d - t) * np.exp(f)
    delta = delta.reshape(shape)
    imp = imp.reshape(shape)
    return {"delta": delta, "impulse": imp, "velocity": 1.0 - imp, "force": delta**1.5}
