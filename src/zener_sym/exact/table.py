"""Fast exact solution of Eq. (10): Chebyshev tables in lambda (and time), evaluated with numpy.

The tables (``generated/exact_table.py``, built offline by :mod:`zener_sym.exact.table_build` from
the scipy solver at rtol 1e-13) cover ``LAM_MIN <= lambda <= LAM_MAX`` (0 to 1000) for the
summary and the history (from lambda = 5 on in the variable ln lambda, from the universal
large-lambda orbit; ``HISTORY_LAM_MAX`` = ``LAM_MAX``). They are never extrapolated:
:func:`in_range` and :func:`history_in_range` tell the caller which lambda must be integrated.

Documented error bounds: ``SUMMARY_RTOL`` relative on every summary field, ``HISTORY_ATOL`` on
delta/delta_m, force/F_m, impulse and velocity, both against the mpmath reference (``exact.mp``)
at lambda between the nodes: ``benchmarks/exact_fast_error.py`` measures them and docs/exact.md
lists the numbers; ``tests/test_exact_fast.py`` and ``tests/test_exact_large.py`` (and the slow
lambda = 1000 test in ``tests/test_exact_edges.py``) check them between nodes on [0, 5] and on
(5, 1000].

Note that near the end of contact the *pointwise relative* error of delta grows like
(error of tau_d) / (tau_d - tau): delta(tau) is ill-conditioned there for any method whose
tau_d is not exact.
"""
from __future__ import annotations

import functools
import importlib
from collections.abc import Mapping
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt

from ..numerics.cheb_table import SummaryTable, derivative_input, spec_of
from ..numerics.cheb_table_history import History, Index, Lines, TimeMaps
from ..typing import FloatArray, RealArrayLike
from . import solver as _solver
from . import table_fields
from .table_fields import DERIVATIVE_FIELDS, field_derivative, summary_fields
from .table_layout import Layout

__all__ = ["LAM_MIN", "LAM_MAX", "HISTORY_LAM_MAX", "SUMMARY_RTOL", "HISTORY_ATOL", "in_range",
           "history_in_range", "summary", "summary_derivative", "DERIVATIVE_FIELDS", "history",
           "log_quantity"]

#: Documented (and tested) relative error bound of every summary field.
SUMMARY_RTOL = 1e-11
#: Documented (and tested) error bound of the history, relative to each field's scale.
HISTORY_ATOL = 1e-10


class _Tables(NamedTuple):
    """The generated table, arranged for evaluation (``_tables``)."""

    #: The time maps' constants.
    layout: Layout
    #: The summary series (the engine's).
    summary: SummaryTable
    #: The history (the engine's); it ends at ``history.hi``, HISTORY_LAM_MAX.
    history: History
    #: Where the ln-lambda pieces start.
    log_from: float


@functools.cache
def _tables() -> _Tables:
    """The generated table, loaded on first use (importing it costs ~0.1 s without a .pyc)."""
    t = importlib.import_module("zener_sym.generated.exact_table")
    return _Tables(Layout.of(t),
                   SummaryTable.of(t, "exact table", "; integrate instead (backend='scipy')"),
                   History.of(t, "exact history table"), spec_of(t).log_from)


def __getattr__(name: str) -> float:
    """LAM_MIN, LAM_MAX (the summary's range) and HISTORY_LAM_MAX (where the history ends),
    read from the generated table on first use: it is their one source."""
    if name == "LAM_MIN":
        return _tables().summary.lo
    if name == "LAM_MAX":
        return _tables().summary.hi
    if name == "HISTORY_LAM_MAX":
        return _tables().history.hi
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def in_range(lam: RealArrayLike) -> npt.NDArray[np.bool_]:
    """Boolean mask of lam's shape: lambda (Eq. 11) inside the summary table's validated range
    [LAM_MIN, LAM_MAX]."""
    return _tables().summary.in_range(lam)


def history_in_range(lam: RealArrayLike) -> npt.NDArray[np.bool_]:
    """Boolean mask of lam's shape: lambda (Eq. 11) inside the history table's range
    [LAM_MIN, HISTORY_LAM_MAX]."""
    t = _tables()
    return t.summary.in_range(lam, t.history.hi)


def _core(lam: FloatArray,
          history: bool = False) -> tuple[dict[str, FloatArray], Index, FloatArray]:
    """The stored series at lam (1-D) and the derived tau_d, xi, e, F_m, tau_w0; piece index and
    x (``history``: among the pieces with a history table)."""
    t = _tables()
    v, i, x, _ = t.summary.values(lam, t.history.hi if history else None)
    v["tau_d"] = np.exp(v["log_tau_d"])
    v["xi"] = 2.0 * lam * v["int_F2"]
    v["e"] = _solver.restitution(v["xi"], np.exp(v["log_e"]))
    v["F_m"] = v["delta_m"] ** 1.5
    v["tau_w0"] = v["tau_dc"] + lam * v["rest_over_lam"]
    return v, i, x


def summary(lam: RealArrayLike) -> dict[str, FloatArray]:
    """Every summary field (see ``models.SUMMARY_FIELDS``) for lambda in [LAM_MIN, LAM_MAX].

    xi comes from the energy balance xi = 2 lambda int_F2 (exact for Eq. 10), which keeps its
    relative accuracy as lambda -> 0, where 1 - e^2 would cancel.

    Parameters
    ----------
    lam : array_like
        lambda (Eq. 11), 1-D or scalar, in [LAM_MIN, LAM_MAX].

    Returns
    -------
    dict of str to ndarray
        "lam" and the summary fields (delta_m, tau_dc, tau_d, tau_dr, eta, e, F_m, impulse,
        int_F2, xi).

    Raises
    ------
    ValueError
        For lambda outside the table's range.
    """
    lam_a = np.asarray(lam, dtype=float)
    v, _, _ = _core(lam_a)
    return summary_fields(lam_a, v)


def summary_derivative(lam: RealArrayLike, field: str = "e",
                       contact_end: str = "delta") -> FloatArray:
    """d(field)/d(lambda) of the tabulated summary, from the Chebyshev series themselves.

    Each stored series is differentiated term by term (``chebder``) and the chain rule applied
    through the piece's map (x linear in lambda, or in ln lambda on the ln-lambda pieces:
    dx/dlambda = 2 / ((b - a) lambda)) and through the stored transform (tau_d = exp(log_tau_d); e as
    :func:`summary` forms it: e = sqrt(1 - xi) while xi = 2 lambda int_F2 < 1/2, else
    exp(log_e); xi' = -2 e e' where xi >= 1/2, since there 2 int_F2 + 2 lambda int_F2' cancels:
    ``table_fields.field_derivative``, shared with the force-free end).
    No finite differences. Measured against Richardson-extrapolated central differences of
    mpmath solves and against the small-lambda series (tests/test_exact_inverse.py): about
    1e-11 relative.

    Parameters
    ----------
    lam : float or array_like
        lambda in [LAM_MIN, LAM_MAX] (Eq. 11).
    field : str
        One of ``DERIVATIVE_FIELDS`` (Eqs. 23-24, 61, 69, 76 for their definitions).
    contact_end : str
        ``"delta"`` (the plate end of contact) or ``"force"`` (the force-free end,
        :func:`zener_sym.exact.force_table.summary_derivative`; lambda > 0 there).

    Returns
    -------
    numpy.ndarray
        d(field)/d(lambda), float array of lambda's shape.

    Raises
    ------
    ValueError
        For an unknown field or contact end, or lambda outside [LAM_MIN, LAM_MAX] or not finite.
    """
    if contact_end == "force":
        from . import force_table

        return force_table.summary_derivative(lam, field)
    if contact_end != "delta":
        raise ValueError(f"unknown contact_end {contact_end!r}; allowed: 'delta' (the plate) or "
                         f"'force' (the grains' force-free end)")
    lam_in, lam1 = derivative_input(lam, field, DERIVATIVE_FIELDS)
    v, i, x = _core(lam1)
    dv = _tables().summary.derivatives(lam1, i, x)  # d(stored series)/d(lambda)
    dxi_balance = 2.0 * v["int_F2"] + 2.0 * lam1 * dv["int_F2"]
    out = field_derivative(field, v, dv, dxi_balance,
                           1.5 * np.sqrt(v["delta_m"]) * dv["delta_m"], dv["int_F2"])
    return out.reshape(lam_in.shape)


def log_quantity(lam: RealArrayLike, quantity: str) -> tuple[FloatArray, FloatArray]:
    """(ln q, d ln q / d lambda) of q = e, tau_d or xi (xi = 2 lambda int_F2) for :mod:`.inverse`, from the one
    series q needs: ``table_fields.log_quantity`` on this table (ValueError for another q or a
    lambda outside the range)."""
    return table_fields.log_quantity(_tables().summary, lam, quantity, "int_F2",
                                     lambda lam1, s: np.log(2.0 * lam1 * s))


def _scaled_maps(name: str, k: int, lu: FloatArray, log: npt.NDArray[np.bool_],
                 v: Mapping[str, FloatArray], tau_s: FloatArray) -> dict[str, FloatArray]:
    """Per-line constants of piece ``name``'s reduced time times k, z = k y (``table_layout``:
    C z = sqrt(a t); B z = sqrt(a (tau_d - t)); A and M z = a (u(t) - u0) with
    u = ln(1 + (t - s) i1) + (t - s) i3 - ln(1 + (e - t) i2) from ``lin_log``, i = 1/c (0 for an
    infinite c: the term vanishes; a term that vanishes on every line is skipped))."""
    if name == "C":
        return {"a": k * k / v["tau_dc"]}
    if name == "B":
        return {"a": k * k / (v["tau_d"] - v["tau_w0"]), "d": v["tau_d"]}
    t = _tables()
    params = t.layout.map_params(name, lu, log, v["tau_dc"], tau_s, v["tau_w0"], t.log_from)
    start, end, c1, c2, c3 = (np.broadcast_to(np.asarray(q, dtype=float), lu.shape)
                              for q in params)
    with np.errstate(invalid="ignore", divide="ignore"):  # lines without this piece: unused
        span = end - start
        u0 = -np.log1p(span / c2)
        u1 = np.log1p(span / c1) + span / c3
        out = {"a": k / (u1 - u0), "u0": u0, "s": start, "e": end}
        for key, c in (("i1", c1), ("i2", c2), ("i3", c3)):
            if not np.isinf(c).all():
                out[key] = 1.0 / c
    return out


def _reduced_time(name: str, m: Mapping[str, FloatArray], t: FloatArray,
                  li: Index) -> tuple[FloatArray, FloatArray | None]:
    """z = k y, the reduced time of piece ``name`` times its sub-piece count, at times t on the
    lines li (``_scaled_maps``' constants gathered per point), and d = tau_d on the lines (piece
    B's factor, None elsewhere)."""
    if name == "C":
        z = t * m["a"].take(li, mode="clip")
        return np.sqrt(z, out=z), None
    if name == "B":
        d = m["d"].take(li, mode="clip")
        z = d - t
        z *= m["a"].take(li, mode="clip")
        return np.sqrt(z, out=z), d
    ts = t - m["s"].take(li, mode="clip")
    z = -m["u0"].take(li, mode="clip")
    if "i3" in m:  # the linear term first: ts is scaled in place below
        z += ts * m["i3"].take(li, mode="clip")
    if "i1" in m:
        ts *= m["i1"].take(li, mode="clip")
        z += np.log1p(ts, out=ts)
    if "i2" in m:
        te = m["e"].take(li, mode="clip")
        te -= t
        te *= m["i2"].take(li, mode="clip")
        z -= np.log1p(te, out=te)
    z *= m["a"].take(li, mode="clip")
    return z, None


class _Maps(TimeMaps):
    """The plate's time maps on the distinct lambdas of one ``history`` call (``lu``: their
    summary ``v``, ln-lambda flags ``log`` and tau_s): the time pieces (C, A, M, B, then past
    the contact), each piece's reduced time and the back-transform delta = tau exp(f) (C),
    exp(f) (A, M), (tau_d - tau) exp(f) (B), with the impulse I stored as itself."""

    fields = ("delta", "impulse", "velocity", "force")

    def __init__(self, lu: FloatArray, v: dict[str, FloatArray], log: npt.NDArray[np.bool_],
                 tau_s: FloatArray) -> None:
        self.lu, self.v, self.log, self.tau_s = lu, v, log, tau_s
        self.imp_end = 1.0 + v["e"]  # after the contact the impulse keeps its final value

    def piece_of(self, lines: Lines) -> npt.NDArray[np.int8]:
        """0 C, 1 A, 2 M (empty on the lambda pieces, tau_s = tau_w0), 3 B, 4 after the contact:
        (1 + [tau >= tau_s] + [tau >= tau_w0] + [tau >= tau_d]) [tau > tau_dc], the last factor
        keeping tau = tau_dc in C where the pieces between are empty (lambda = 0: all bounds
        equal)."""
        v = self.v
        t2, b = lines.per_point((self.tau_s, v["tau_w0"], v["tau_d"], v["tau_dc"]))
        piece = (t2 >= b[0]).view(np.int8)
        piece += t2 >= b[1]
        piece += t2 >= b[2]
        piece += 1
        piece *= t2 > b[3]
        return piece.ravel()

    def constants(self, name: str, k: int) -> dict[str, FloatArray]:
        return _scaled_maps(name, k, self.lu, self.log, self.v, self.tau_s)

    def reduced_time(self, name: str, m: Any, t: FloatArray,
                     li: Index) -> tuple[FloatArray, FloatArray | None]:
        return _reduced_time(name, m, t, li)

    def store(self, name: str, f: FloatArray, g: FloatArray, t: FloatArray, li: Index, aux: Any,
              out: dict[str, FloatArray], at: Index) -> None:
        d = np.ascontiguousarray(f)  # exp is vectorized on contiguous data only
        np.exp(d, out=d)
        if name == "C":
            d *= t
        elif name == "B":
            aux -= t  # piece B's factor tau_d - tau (_reduced_time's d, a temporary)
            d *= aux
        out["delta"][at] = d
        out["impulse"][at] = g
        force = np.sqrt(d)
        force *= d
        out["force"][at] = force
        out["velocity"][at] = 1.0 - g

    def after(self, out: dict[str, FloatArray], at: Index, li: Index) -> None:
        imp = self.imp_end.take(li, mode="clip")
        out["delta"][at] = 0.0
        out["force"][at] = 0.0
        out["impulse"][at] = imp
        out["velocity"][at] = 1.0 - imp


def history(lam: RealArrayLike, tau: RealArrayLike) -> dict[str, FloatArray]:
    """delta, impulse, velocity (1 - I) and force (delta^{3/2}) at (lam, tau), same shapes.

    The engine's history (``numerics.cheb_table_history.History.evaluate``: distinct lambdas,
    the lambda contraction once per distinct lambda and time piece, blocks of points, the
    sub-piece lookup and Horner's rule, one polynomial of degree <= 15 per field) with this
    table's time maps (:class:`_Maps`): each time point costs its piece's map, the two
    polynomials and an exponential.

    Parameters
    ----------
    lam, tau : array_like
        lambda (Eq. 11) in [LAM_MIN, HISTORY_LAM_MAX] and times >= 0, broadcast together.

    Returns
    -------
    dict of str to ndarray
        "delta", "impulse", "velocity", "force", each of the broadcast shape.

    Raises
    ------
    ValueError
        For lambda outside the history table's range, or a negative or NaN time.
    """
    t = _tables()
    lines = Lines.of(lam, tau)
    t.summary.check(lines.lam, t.history.hi, t.history.what)
    v, ip, xl = _core(lines.lam, history=True)
    log = t.summary.pieces.kind["log"][ip]
    tau_s = t.layout.split_time(lines.lam, log, v["tau_dc"], v["tau_w0"])
    out = t.history.evaluate(lines, ip, t.history.basis(xl), _Maps(lines.lam, v, log, tau_s))
    return {key: a.reshape(lines.shape) for key, a in out.items()}
