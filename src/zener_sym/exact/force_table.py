"""Fast force-free end of contact (the grains' reading of Eq. 10, :mod:`.force_end`):
Chebyshev tables in lambda and time, evaluated with numpy.

The tables (``generated/exact_force_table.py``, built offline by
:mod:`zener_sym.exact.force_table_build` from ``force_end.solve`` at rtol 1e-13) cover
``LAM_MIN <= lambda <= LAM_MAX`` (0 to 1000) for the summary and the history; they are never
extrapolated. Error bounds as the plate's (:mod:`.table`): ``SUMMARY_RTOL`` relative on every
summary field, ``HISTORY_ATOL`` of each history field's scale (delta_m, F_m, 1 for the velocity
and the impulse), against the mpmath path (``force_end.solve_mp``) between the nodes
(tests/test_exact_force_table.py).
"""
from __future__ import annotations

import functools
import importlib
from typing import TypedDict

import numpy as np
import numpy.typing as npt

from ..numerics.blocks import BLOCK, field_buffers
from ..numerics.cheb_table import (Index, SummaryTable, history_tables, line_coefficients,
                                   derivative_input, log_quantity_function,
                                   range_mask)
from ..numerics.chebyshev import horner_take_pair
from ..typing import FloatArray, RealArrayLike
from . import solver as _solver
from .force_table_layout import ForceLayout, recovery_z_end

__all__ = ["LAM_MIN", "LAM_MAX", "SUMMARY_RTOL", "HISTORY_ATOL", "in_range", "summary",
           "summary_derivative", "log_quantity", "history"]

#: LAM_MIN and LAM_MAX (the tables' range) are read from the generated table on first use
#: (``__getattr__``), the one source of the layout (as :mod:`.table`'s).
_RANGE = ("LAM_MIN", "LAM_MAX")
#: Documented (and tested) relative error bound of every summary field.
SUMMARY_RTOL = 1e-11
#: Documented (and tested) error bound of the history, relative to each field's scale.
HISTORY_ATOL = 1e-10
#: One time piece's history (``cheb_table.history_rows``).
_PieceLayout = tuple[list[FloatArray | None], int, int, npt.NDArray[np.int_]]


class _Tables(TypedDict):
    """The generated table, arranged for evaluation (``_tables``)."""

    layout: ForceLayout
    summary: SummaryTable
    history: dict[str, _PieceLayout]


def __getattr__(name: str) -> float:
    if name in _RANGE:
        s = _tables()["summary"]
        return s.lo if name == "LAM_MIN" else s.hi
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


@functools.cache
def _tables() -> _Tables:
    """The generated table, loaded on first use; its layout is read from it."""
    t = importlib.import_module("zener_sym.generated.exact_force_table")
    lay = ForceLayout.of(t)
    return {"layout": lay, "history": history_tables(t.HISTORY, lay.TIME_PIECES, lay.HISTORY_KEYS),
            "summary": SummaryTable.of(t, "force-end table",
                                       "; integrate instead (backend='scipy')")}


#: Boolean mask: lambda inside the tables' range [LAM_MIN, LAM_MAX].
in_range = range_mask(lambda: _tables()["summary"], __name__,
                      "the tables' range [LAM_MIN, LAM_MAX]")


def _core(lam: FloatArray) -> tuple[dict[str, FloatArray], Index, FloatArray, FloatArray]:
    """The stored series at lam (1-D) and the derived xi, e, tau_d; piece index, x and the
    Chebyshev basis."""
    v, i, x, tl = _tables()["summary"].values(lam)
    v["xi"] = lam * v["xi_over_lam"]
    v["e"] = _solver.restitution(v["xi"], np.exp(v["log_e"]))
    v["tau_d"] = np.exp(v["log_tau_d"])
    return v, i, x, tl


def summary(lam: RealArrayLike) -> dict[str, FloatArray]:
    """Every summary field of the force-free end (``models.SUMMARY_FIELDS``).

    xi from the solver's energy balance (never 1 - e^2), exactly 0 at lambda = 0;
    e = sqrt(1 - xi) while xi < 1/2 (``solver.restitution``).

    Parameters
    ----------
    lam : array_like
        lambda (Eq. 11) in [LAM_MIN, LAM_MAX].

    Returns
    -------
    dict of str to ndarray
        "lam" and the summary fields, each of lam's shape.

    Raises
    ------
    ValueError
        For lambda outside the tables' range.
    """
    lam_a = np.asarray(lam, dtype=float)
    shape = lam_a.shape
    lam1 = lam_a.reshape(-1)
    v, _, _, _ = _core(lam1)
    tau_dr = v["tau_d"] - v["tau_dc"]
    out = {"lam": lam1, "delta_m": v["delta_m"], "tau_dc": v["tau_dc"], "tau_d": v["tau_d"],
           "tau_dr": tau_dr, "eta": tau_dr / v["tau_dc"], "e": v["e"],
           "F_m": np.exp(v["log_F_m"]), "impulse": 1.0 + v["e"],
           "int_F2": np.exp(v["log_int_F2"]), "xi": v["xi"]}
    return {k: a.reshape(shape) for k, a in out.items()}


#: Summary fields :func:`summary_derivative` differentiates (as the plate table's).
DERIVATIVE_FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                     "int_F2", "xi")


def summary_derivative(lam: RealArrayLike, field: str = "e") -> FloatArray:
    """d(field)/d(lambda) of the tabulated force-end summary from the series' own derivative.

    ``table.summary_derivative`` documents the contract. lambda must be > 0: near 0 the fields
    have lambda^(3/2) terms and the tables' variable is sqrt(lambda).

    Parameters
    ----------
    lam : array_like
        lambda (Eq. 11) in (0, LAM_MAX].
    field : str
        One of ``DERIVATIVE_FIELDS``.

    Returns
    -------
    ndarray
        d(field)/d(lambda), lam's shape.

    Raises
    ------
    ValueError
        For an unknown field, lambda = 0, or lambda outside the range or not finite.
    """
    lam_in, lam1 = derivative_input(lam, field, DERIVATIVE_FIELDS)
    if np.any(lam1 == 0.0):
        raise ValueError("d/dlambda at lambda = 0 is not available for contact_end='force': the "
                         "tables' variable is sqrt(lambda) (the fields have lambda^(3/2) terms, "
                         "so their second derivative is infinite there); ask at lambda > 0")
    v, i, x, _ = _core(lam1)
    dv = _tables()["summary"].derivatives(lam1, i, x)
    dxi = v["xi_over_lam"] + lam1 * dv["xi_over_lam"]
    small = v["xi"] < 0.5
    de = np.where(small, -dxi / (2.0 * v["e"]), v["e"] * dv["log_e"])
    # where xi >= 1/2 the e route is the accurate one (xi' = -2 e e'), as the plate's
    dxi = np.where(small, dxi, -2.0 * v["e"] * de)
    tau_d = v["tau_d"]
    dtau_d = tau_d * dv["log_tau_d"]
    out: FloatArray = {"e": de, "impulse": de, "xi": dxi, "tau_d": dtau_d, "delta_m": dv["delta_m"],
           "tau_dc": dv["tau_dc"], "tau_dr": dtau_d - dv["tau_dc"],
           "eta": (dtau_d * v["tau_dc"] - tau_d * dv["tau_dc"]) / v["tau_dc"] ** 2,
           "F_m": np.exp(v["log_F_m"]) * dv["log_F_m"],
           "int_F2": np.exp(v["log_int_F2"]) * dv["log_int_F2"]}[field]
    return out.reshape(lam_in.shape)


#: (ln q, d ln q / d lambda) for the inverses: e and tau_d from their stored logs, xi =
#: lambda (xi / lambda)
log_quantity = log_quantity_function(lambda: _tables()["summary"], __name__,
                                     {"e": "log_e", "tau_d": "log_tau_d"},
                                     {"xi": ("xi_over_lam",
                                             lambda lam, s: np.log(lam) + np.log(s))})


def history(lam: RealArrayLike, tau: RealArrayLike) -> dict[str, FloatArray]:
    """delta, velocity delta', force F_c and impulse 1 - delta' of the force-free end's history.

    F_c = sqrt(delta) (delta + (3/2) lambda delta'). Past tau_d: delta and the force 0, the
    velocity -e, the impulse 1 + e (as ``force_end.ForceEndSolution.history``).

    Parameters
    ----------
    lam, tau : array_like
        lambda (Eq. 11) in [LAM_MIN, LAM_MAX] and times >= 0, broadcast together.

    Returns
    -------
    dict of str to ndarray
        "delta", "velocity", "force", "impulse", each of the broadcast shape.

    Raises
    ------
    ValueError
        For lambda outside the tables' range.
    """
    lam_b, tau_b = np.broadcast_arrays(np.asarray(lam, dtype=float), np.asarray(tau, dtype=float))
    shape = tau_b.shape
    if lam_b.ndim >= 1 and lam_b.shape[-1] > 1 and lam_b.strides[-1] == 0:
        # one lambda per line of tau (a broadcast column): sort the lines, not every point
        lu, line = np.unique(lam_b[..., 0].ravel(), return_inverse=True)
        inv = np.repeat(line, lam_b.shape[-1])
    else:
        lu, inv = np.unique(lam_b.ravel(), return_inverse=True)
    tau = tau_b.ravel()
    v, ip, _, tl = _core(lu)
    log = _tables()["summary"].pieces.kind["log"][ip]
    tau_dc, tau_d = v["tau_dc"], v["tau_d"]
    tau_p = np.where(log, np.inf, np.exp(v["log_tau_p"]))  # the plate's tau_d (builder)
    with np.errstate(invalid="ignore", divide="ignore"):
        # per line constants of the recovery map: y = a (1 - sqrt(b (tau_p - tau))) (sqrt
        # pieces) or y = (tau - tau_dc) / (tau_d - tau_dc)
        z_end = recovery_z_end(tau_dc, tau_d, tau_p)
        r_a = np.where(log, 1.0 / (tau_d - tau_dc), 1.0 / (1.0 - z_end))
        r_b = np.where(log, 0.0, 1.0 / (tau_p - tau_dc))
        c_a = 1.0 / tau_dc
    tables = _tables()["history"]
    coef: dict[str, tuple[npt.NDArray[np.complex128], int]] = {}
    for name in _tables()["layout"].TIME_PIECES:
        per, n_sub, deg, _ = tables[name]
        coef[name] = (line_coefficients(per, ip, tl, deg, n_sub), n_sub)
    out = field_buffers(("delta", "velocity", "force", "impulse"), tau.shape)
    lam_1 = 1.5 * lu
    e_end = v["e"]
    for s0 in range(0, tau.size, BLOCK):
        t = tau[s0:s0 + BLOCK]
        li = inv[s0:s0 + BLOCK]
        dc = tau_dc.take(li)
        dd = tau_d.take(li)
        delta = np.zeros(t.shape)
        vel = -e_end.take(li)
        comp = t <= dc
        rec = ~comp & (t < dd)
        for name, m in (("C", comp), ("R", rec)):
            if not m.any():
                continue
            at = np.flatnonzero(m)
            tt, ll = t[at], li[at]
            rows, k = coef[name]
            if name == "C":
                y = np.sqrt(tt * c_a.take(ll))
            else:
                lg = log.take(ll)
                # >= 0: at lambda = 0 tau_d and tau_P are the same time, each to rounding
                gap = np.maximum(tau_p.take(ll) - tt, 0.0)
                with np.errstate(invalid="ignore"):
                    y_s = r_a.take(ll) * (1.0 - np.sqrt(np.where(lg, 0.0, gap) * r_b.take(ll)))
                y = np.where(lg, (tt - dc[at]) * r_a.take(ll), y_s)
            z = y * k
            sub = np.minimum(np.maximum(z.astype(np.intp), 0), k - 1)
            x = 2.0 * (z - sub) - 1.0
            f, vv = horner_take_pair(rows, ll * k + sub, x)
            g = np.exp(f)
            if name == "C":
                g *= tt
            else:
                g *= np.where(lg, 1.0, gap)
            delta[at] = g
            vel[at] = vv
        sd = np.sqrt(delta)
        out["delta"][s0:s0 + BLOCK] = delta
        out["velocity"][s0:s0 + BLOCK] = vel
        out["force"][s0:s0 + BLOCK] = sd * (delta + lam_1.take(li) * vel)
        out["impulse"][s0:s0 + BLOCK] = 1.0 - vel
    return {key: a.reshape(shape) for key, a in out.items()}
