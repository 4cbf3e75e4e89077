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
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt

from ..numerics.cheb_table import SummaryTable, derivative_input
from ..numerics.cheb_table_history import History, Index, Lines, TimeMaps
from ..typing import FloatArray, RealArrayLike
from . import solver as _solver
from .force_table_layout import recovery_z_end
from . import table_fields
from .table_fields import DERIVATIVE_FIELDS, field_derivative, summary_fields

__all__ = ["LAM_MIN", "LAM_MAX", "SUMMARY_RTOL", "HISTORY_ATOL", "in_range", "summary",
           "summary_derivative", "DERIVATIVE_FIELDS", "log_quantity", "history"]

#: Documented (and tested) relative error bound of every summary field.
SUMMARY_RTOL = 1e-11
#: Documented (and tested) error bound of the history, relative to each field's scale.
HISTORY_ATOL = 1e-10


class _Tables(NamedTuple):
    """The generated table, arranged for evaluation (``_tables``)."""

    #: The summary series (the engine's).
    summary: SummaryTable
    #: The history (the engine's), over the summary's range.
    history: History


@functools.cache
def _tables() -> _Tables:
    """The generated table, loaded on first use (its description is read from it)."""
    t = importlib.import_module("zener_sym.generated.exact_force_table")
    return _Tables(SummaryTable.of(t, "force-end table", "; integrate instead (backend='scipy')"),
                   History.of(t, "force-end table"))


def __getattr__(name: str) -> float:
    """LAM_MIN and LAM_MAX (the tables' range), read from the generated table on first use (as
    :mod:`.table`'s)."""
    if name == "LAM_MIN":
        return _tables().summary.lo
    if name == "LAM_MAX":
        return _tables().summary.hi
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def in_range(lam: RealArrayLike) -> npt.NDArray[np.bool_]:
    """Mask of lam's shape, True where lambda (Eq. 11) lies in the force-end tables' range
    [LAM_MIN, LAM_MAX] (summary and history alike)."""
    return _tables().summary.in_range(lam)


def _core(lam: FloatArray) -> tuple[dict[str, FloatArray], Index, FloatArray, FloatArray]:
    """The stored series at lam (1-D) and the derived xi, e, tau_d, F_m, int_F2; piece index,
    x and the Chebyshev basis (the history's, ``History.basis`` explains why)."""
    v, i, x, tl = _tables().summary.values(lam)
    v["xi"] = lam * v["xi_over_lam"]
    v["e"] = _solver.restitution(v["xi"], np.exp(v["log_e"]))
    v["tau_d"] = np.exp(v["log_tau_d"])
    v["F_m"] = np.exp(v["log_F_m"])
    v["int_F2"] = np.exp(v["log_int_F2"])
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
    lam1 = lam_a.reshape(-1)
    v, _, _, _ = _core(lam1)
    return {k: a.reshape(lam_a.shape) for k, a in summary_fields(lam1, v).items()}


def summary_derivative(lam: RealArrayLike, field: str = "e") -> FloatArray:
    """d(field)/d(lambda) of the tabulated force-end summary from the series' own derivative.

    ``table.summary_derivative`` documents the contract (the chain rule and the e/xi switch are
    ``table_fields.field_derivative``, shared). lambda must be > 0: near 0 the fields have
    lambda^(3/2) terms and the tables' variable is sqrt(lambda).

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
    dv = _tables().summary.derivatives(lam1, i, x)
    out = field_derivative(field, v, dv, v["xi_over_lam"] + lam1 * dv["xi_over_lam"],
                           v["F_m"] * dv["log_F_m"], v["int_F2"] * dv["log_int_F2"])
    return out.reshape(lam_in.shape)


def log_quantity(lam: RealArrayLike, quantity: str) -> tuple[FloatArray, FloatArray]:
    """(ln q, d ln q / d lambda) of q = e, tau_d or xi (xi = lambda (xi / lambda)) for :mod:`.inverse`, from the one
    series q needs: ``table_fields.log_quantity`` on this table (ValueError for another q or a
    lambda outside the range)."""
    return table_fields.log_quantity(_tables().summary, lam, quantity, "xi_over_lam",
                                     lambda lam1, s: np.log(lam1) + np.log(s))


class _Maps(TimeMaps):
    """The force-free end's time maps on the distinct lambdas of one ``history`` call: time
    pieces C (tau <= tau_dc), R (to tau_d), then past the contact; y = sqrt(tau / tau_dc) in C;
    in R y = a (1 - sqrt(b (tau_P - tau))) below the ln-lambda pieces, (tau - tau_dc) /
    (tau_d - tau_dc) on them; delta = tau exp(f) (C), (tau_P - tau) exp(f) or exp(f) (R), the
    velocity v = delta' stored as itself, F_c = sqrt(delta) (delta + (3/2) lambda v) and the
    impulse 1 - v."""

    fields = ("delta", "velocity", "force", "impulse")

    def __init__(self, lu: FloatArray, v: dict[str, FloatArray],
                 log: npt.NDArray[np.bool_]) -> None:
        self.log, self.tau_dc, self.tau_d = log, v["tau_dc"], v["tau_d"]
        self.tau_p = np.where(log, np.inf, np.exp(v["log_tau_p"]))  # the plate's tau_d (builder)
        with np.errstate(invalid="ignore", divide="ignore"):
            z_end = recovery_z_end(self.tau_dc, self.tau_d, self.tau_p)
            self.r_a = np.where(log, 1.0 / (self.tau_d - self.tau_dc), 1.0 / (1.0 - z_end))
            self.r_b = np.where(log, 0.0, 1.0 / (self.tau_p - self.tau_dc))
            self.c_a = 1.0 / self.tau_dc
        self.lam_1, self.e_end = 1.5 * lu, v["e"]

    def piece_of(self, lines: Lines) -> npt.NDArray[np.int8]:
        """0 C, 1 R, 2 after the contact: [tau > tau_dc] (1 + [tau >= tau_d])."""
        t2, (dc, dd) = lines.per_point((self.tau_dc, self.tau_d))
        piece = (t2 >= dd).view(np.int8)
        piece += 1
        piece *= t2 > dc
        return piece.ravel()

    def constants(self, name: str, k: int) -> int:
        return k  # the maps' per-line constants are the same for both pieces (made once)

    def reduced_time(self, name: str, m: Any, t: FloatArray,
                     li: Index) -> tuple[FloatArray, Any]:
        if name == "C":
            return np.sqrt(t * self.c_a.take(li)) * m, None
        lg = self.log.take(li)
        # >= 0: at lambda = 0 tau_d and tau_P are the same time, each to rounding
        gap = np.maximum(self.tau_p.take(li) - t, 0.0)
        with np.errstate(invalid="ignore"):
            y_s = self.r_a.take(li) * (1.0 - np.sqrt(np.where(lg, 0.0, gap) * self.r_b.take(li)))
        y = np.where(lg, (t - self.tau_dc.take(li)) * self.r_a.take(li), y_s)
        return y * m, (lg, gap)

    def store(self, name: str, f: FloatArray, g: FloatArray, t: FloatArray, li: Index, aux: Any,
              out: dict[str, FloatArray], at: Index) -> None:
        delta = np.exp(f)
        if name == "C":
            delta *= t
        else:
            lg, gap = aux
            delta *= np.where(lg, 1.0, gap)
        self._fields(out, at, li, delta, g)

    def after(self, out: dict[str, FloatArray], at: Index, li: Index) -> None:
        self._fields(out, at, li, np.zeros(at.shape), -self.e_end.take(li))

    def _fields(self, out: dict[str, FloatArray], at: Index, li: Index, delta: FloatArray,
                vel: FloatArray) -> None:
        out["delta"][at] = delta
        out["velocity"][at] = vel
        out["force"][at] = np.sqrt(delta) * (delta + self.lam_1.take(li) * vel)
        out["impulse"][at] = 1.0 - vel


def history(lam: RealArrayLike, tau: RealArrayLike) -> dict[str, FloatArray]:
    """delta, velocity delta', force F_c and impulse 1 - delta' of the force-free end's history.

    F_c = sqrt(delta) (delta + (3/2) lambda delta'). Past tau_d: delta and the force 0, the
    velocity -e, the impulse 1 + e (as ``force_end.ForceEndSolution.history``). The engine's
    history (``numerics.cheb_table_history.History.evaluate``) with this table's time maps
    (:class:`_Maps`).

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
        For lambda outside the tables' range, or a negative or NaN time.
    """
    t = _tables()
    lines = Lines.of(lam, tau)
    t.summary.check(lines.lam, t.history.hi, t.history.what)
    v, ip, _, tl = _core(lines.lam)
    out = t.history.evaluate(lines, ip, tl, _Maps(lines.lam, v, t.summary.pieces.kind["log"][ip]))
    return {key: a.reshape(lines.shape) for key, a in out.items()}
