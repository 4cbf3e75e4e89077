"""Fast exact solution of Eq. (10): Chebyshev tables in lambda (and time), evaluated with numpy.

The tables (``generated/exact_table.py``, built offline by :mod:`zener_sym.exact.table_build` from
the scipy solver at rtol 1e-13) cover ``LAM_MIN <= lambda <= LAM_MAX`` (0 to 1000) for the
summary and the history (above ``LOG_FROM`` = 5 in the variable ln lambda, from the universal
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
from .table_layout import Layout

__all__ = ["LAM_MIN", "LAM_MAX", "HISTORY_LAM_MAX", "SUMMARY_RTOL", "HISTORY_ATOL", "in_range",
           "history_in_range", "summary", "summary_derivative", "DERIVATIVE_FIELDS", "history",
           "log_quantity"]

#: LAM_MIN, LAM_MAX (the summary tables' range) and HISTORY_LAM_MAX (where the history tables
#: end) are read from the generated table on first use (``__getattr__``): it is the one source of
#: the layout.
_RANGE = ("LAM_MIN", "LAM_MAX", "HISTORY_LAM_MAX")
#: Documented (and tested) relative error bound of every summary field.
SUMMARY_RTOL = 1e-11
#: Documented (and tested) error bound of the history, relative to each field's scale.
HISTORY_ATOL = 1e-10
#: Points per block of the history evaluation (``blocks.BLOCK``: a block's float temporaries,
#: 64 kB each, stay in cache and below the allocator's mmap threshold).
_BLOCK = BLOCK
#: Lambda-piece indices and row indices.
_Index = Index
#: One time piece's history (``cheb_table.history_rows``): per lambda piece the monomial
#: coefficients [time degree, lambda degree, 2 * sub-piece + field] (None without the piece),
#: the sub-piece count, the time degree and per lambda piece the degree its coefficients need.
_PieceLayout = tuple[list[FloatArray | None], int, int, npt.NDArray[np.int_]]
#: What one time piece's evaluation needs (``history``): the per-line map constants, the
#: complex coefficients per line, the sub-piece count and the degree.
_Prep = tuple[dict[str, FloatArray], npt.NDArray[np.complex128], int, int]


class _Tables(TypedDict):
    """The generated table, arranged for evaluation (``_tables``)."""

    layout: Layout
    summary: SummaryTable
    HISTORY_LAM_MAX: float
    history: dict[str, _PieceLayout]


@functools.cache
def _tables() -> _Tables:
    """The generated table, loaded on first use (importing it costs ~0.1 s without a .pyc)."""
    t = importlib.import_module("zener_sym.generated.exact_table")
    layout = Layout.of(t)  # the time pieces and maps; the lambda pieces are in TABLE_*
    return {"layout": layout, "HISTORY_LAM_MAX": float(layout.HISTORY_TO),
            "summary": SummaryTable.of(t, "exact table", "; integrate instead (backend='scipy')"),
            "history": history_tables(t.HISTORY, layout.TIME_PIECES, layout.HISTORY_KEYS)}


def __getattr__(name: str) -> float:
    if name in _RANGE:
        t = _tables()
        s = t["summary"]
        return {"LAM_MIN": s.lo, "LAM_MAX": s.hi, "HISTORY_LAM_MAX": t["HISTORY_LAM_MAX"]}[name]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: Boolean mask: lambda inside the summary table's validated range [LAM_MIN, LAM_MAX].
in_range = range_mask(lambda: _tables()["summary"], __name__,
                      "the summary table's validated range [LAM_MIN, LAM_MAX]")

#: Boolean mask: lambda inside the history table's range [LAM_MIN, HISTORY_LAM_MAX].
history_in_range = range_mask(lambda: _tables()["summary"], __name__,
                              "the history table's range [LAM_MIN, HISTORY_LAM_MAX]",
                              hi=lambda: _tables()["HISTORY_LAM_MAX"])


def _core(lam: FloatArray,
          history: bool = False) -> tuple[dict[str, FloatArray], _Index, FloatArray]:
    """The stored series at lam (1-D) and the derived tau_d, e, tau_w0; piece index and x
    (``history``: among the pieces with a history table)."""
    t = _tables()
    v, i, x, _ = t["summary"].values(lam, t["HISTORY_LAM_MAX"] if history else None)
    v["tau_d"] = np.exp(v["log_tau_d"])
    v["e"] = _solver.restitution(2.0 * lam * v["int_F2"], np.exp(v["log_e"]))
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
    tau_dr = v["tau_d"] - v["tau_dc"]
    return {"lam": lam_a, "delta_m": v["delta_m"], "tau_dc": v["tau_dc"], "tau_d": v["tau_d"],
            "tau_dr": tau_dr, "eta": tau_dr / v["tau_dc"], "e": v["e"],
            "F_m": v["delta_m"] ** 1.5, "impulse": 1.0 + v["e"], "int_F2": v["int_F2"],
            "xi": 2.0 * lam_a * v["int_F2"]}


#: Summary fields :func:`summary_derivative` differentiates.
DERIVATIVE_FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                     "int_F2", "xi")


def summary_derivative(lam: RealArrayLike, field: str = "e",
                       contact_end: str = "delta") -> FloatArray:
    """d(field)/d(lambda) of the tabulated summary, from the Chebyshev series themselves.

    Each stored series is differentiated term by term (``chebder``) and the chain rule applied
    through the piece's map (x linear in lambda, or in ln lambda above ``LOG_FROM``: dx/dlambda
    = 2 / ((b - a) lambda)) and through the stored transform (tau_d = exp(log_tau_d); e as
    :func:`summary` forms it: e = sqrt(1 - xi) while xi = 2 lambda int_F2 < 1/2, else
    exp(log_e); xi' = -2 e e' where xi >= 1/2, since there 2 int_F2 + 2 lambda int_F2' cancels).
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
    dv = _tables()["summary"].derivatives(lam1, i, x)  # d(stored series)/d(lambda)
    dv["tau_d"] = v["tau_d"] * dv["log_tau_d"]
    xi = 2.0 * lam1 * v["int_F2"]
    small = xi < 0.5
    # below xi = 1/2 from the energy balance xi = 2 lambda int_F2 (no cancellation as
    # lambda -> 0); above, 2 int_F2 and 2 lambda int_F2' nearly cancel (by 1e4 at lambda = 3),
    # so xi' = -2 e e' from ln e's series. e as _core forms it (solver.restitution).
    dxi_balance = 2.0 * v["int_F2"] + 2.0 * lam1 * dv["int_F2"]
    de = np.where(small, -dxi_balance / (2.0 * v["e"]), v["e"] * dv["log_e"])
    dxi = np.where(small, dxi_balance, -2.0 * v["e"] * de)
    out: FloatArray
    if field == "e" or field == "impulse":
        out = de
    elif field == "xi":
        out = dxi
    elif field == "F_m":
        out = 1.5 * np.sqrt(v["delta_m"]) * dv["delta_m"]
    elif field == "tau_dr":
        out = dv["tau_d"] - dv["tau_dc"]
    elif field == "eta":
        out = (dv["tau_d"] * v["tau_dc"] - v["tau_d"] * dv["tau_dc"]) / v["tau_dc"] ** 2
    else:
        out = dv[field]
    return out.reshape(lam_in.shape)


#: (ln q, d ln q / d lambda) for the inverses: e and tau_d from their stored logs, xi =
#: 2 lambda int_F2
log_quantity = log_quantity_function(lambda: _tables()["summary"], __name__,
                                     {"e": "log_e", "tau_d": "log_tau_d"},
                                     {"xi": ("int_F2",
                                             lambda lam, f: np.log(2.0 * lam * f))})


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
    params = _tables()["layout"].map_params(name, lu, log, v["tau_dc"], tau_s, v["tau_w0"])
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
                  li: _Index) -> tuple[FloatArray, FloatArray | None]:
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


def _piece_values(name: str, prep: _Prep, t: FloatArray, li: _Index,
                  lu: FloatArray) -> tuple[FloatArray, FloatArray]:
    """delta and the impulse at times t (all in time piece ``name``) on the lines li."""
    m, cT, k, nd = prep
    z, d = _reduced_time(name, m, t, li)
    sub = z.astype(np.intp)  # z >= 0: truncation is floor
    if sub.min() < 0:  # a NaN or a point outside its piece: never index a wrong row
        raise RuntimeError(f"exact history table: reduced time out of range in piece "
                           f"{name} (lambda {lu[li[sub < 0][0]]!r}); this is a bug")
    np.minimum(sub, k - 1, out=sub)
    x = z - sub
    x *= 2.0
    x -= 1.0
    sub += li * k  # the point's row: line, sub-piece
    f, i = horner_take_pair(cT[:nd], sub, x)
    g = np.ascontiguousarray(f)  # exp is vectorized on contiguous data only
    np.exp(g, out=g)
    if name == "C":
        g *= t
    elif name == "B":
        assert d is not None  # piece B's factor tau_d (_reduced_time)
        d -= t
        g *= d
    return g, i


def history(lam: RealArrayLike, tau: RealArrayLike) -> dict[str, FloatArray]:
    """delta, impulse, velocity (1 - I) and force (delta^{3/2}) at (lam, tau), same shapes.

    The lambda direction is contracted once per distinct lambda and time piece; each time point
    then costs its piece's map, one polynomial of degree <= 15 per field (Horner) and an
    exponential. The points of each time piece are evaluated in blocks of ``_BLOCK``: per-point
    temporaries as large as the grid cost more in fresh memory (page faults, and time that
    depends on how the allocator was last used) than in arithmetic. When lambda is a broadcast
    column (one lambda per line of tau), points are assigned to lines and pieces by
    broadcasting against each line's bounds, without a per-point sort.

    Parameters
    ----------
    lam, tau : array_like
        lambda (Eq. 11) in [LAM_MIN, HISTORY_LAM_MAX] and times >= 0, already broadcast to one
        shape.

    Returns
    -------
    dict of str to ndarray
        "delta", "impulse", "velocity", "force", each of that shape.

    Raises
    ------
    ValueError
        For lambda outside the history table's range.
    """
    lam_a = np.asarray(lam, dtype=float)
    tau_a = np.asarray(tau, dtype=float)
    shape = tau_a.shape
    n_col = None  # points per line of tau when lambda is one column (a line each)
    if lam_a.ndim >= 1 and lam_a.shape[-1] > 1 and np.array_equal(
            lam_a, np.broadcast_to(lam_a[..., :1], lam_a.shape)):
        # one lambda per line of tau (a broadcast column): sort the lines, not every point
        lu, line = np.unique(lam_a[..., 0].ravel(), return_inverse=True)
        n_col = lam_a.shape[-1]
    else:
        lu, inv = np.unique(lam_a.ravel(), return_inverse=True)
    _tables()["summary"].check(lu, _tables()["HISTORY_LAM_MAX"], "exact history table")
    tau_f = tau_a.ravel()
    v, ip, xl = _core(lu, history=True)
    log = _tables()["summary"].pieces.kind["log"][ip]
    lay = _tables()["layout"]
    tau_s = lay.split_time(lu, log, v["tau_dc"], v["tau_w0"])
    piece = _time_piece(tau_f, (tau_s, v["tau_w0"], v["tau_d"], v["tau_dc"]),
                        line if n_col is not None else inv, n_col)
    out = field_buffers(("delta", "impulse", "velocity", "force"), tau_f.shape)
    layout = _tables()["history"]
    k_max = max(c.shape[1] for per, *_ in layout.values() for c in per if c is not None)
    tl_all = np.asarray(np.polynomial.chebyshev.chebvander(xl, k_max - 1), dtype=float)
    imp_end = 1.0 + v["e"]  # after the contact the impulse keeps its final value
    prep: _Prep | None = None
    for n, name in enumerate((*lay.TIME_PIECES, None)):
        if name is not None:
            if not np.any(piece == n):
                continue
            per, k, deg, need = layout[name]
            prep = (_scaled_maps(name, k, lu, log, v, tau_s), line_coefficients(
                per, ip, tl_all, deg, k), k, int(need[ip].max()))
        # the piece's points, found chunk by chunk of the grid (no index array of the grid's
        # size: the call's peak memory decides whether glibc keeps it for the next call)
        for c0 in range(0, tau_f.size, 4 * _BLOCK):
            at_chunk = np.flatnonzero(piece[c0:c0 + 4 * _BLOCK] == n)
            at_chunk += c0
            for s in range(0, at_chunk.size, _BLOCK):
                at = at_chunk[s:s + _BLOCK]
                li = line.take(at // n_col, mode="clip") if n_col is not None else inv.take(
                    at, mode="clip")
                if name is None:
                    out["delta"][at] = 0.0
                    out["impulse"][at] = imp_end.take(li, mode="clip")
                else:
                    assert prep is not None  # made above for this piece
                    out["delta"][at], out["impulse"][at] = _piece_values(
                        name, prep, tau_f.take(at, mode="clip"), li, lu)
        prep = None  # freed before the next piece's coefficients are made
    _derived_fields(out)
    return {key: a.reshape(shape) for key, a in out.items()}


def _time_piece(tau: FloatArray, bounds: tuple[FloatArray, ...], index: _Index,
                n_col: int | None) -> npt.NDArray[np.int8]:
    """The time piece of each point (int8, flat): 0 C, 1 A, 2 M (empty for lambda <= LOG_FROM,
    tau_s = tau_w0), 3 B, 4 after the contact, from the bounds (tau_s, tau_w0, tau_d, tau_dc)
    per distinct lambda; ``index`` maps lines (when ``n_col`` points share a lambda per line)
    or points to their lambda."""
    if n_col is not None:  # per-line bounds broadcast along each line: no gather per point
        t2 = tau.reshape(len(index), n_col)
        b = [q[index, None] for q in bounds]
    else:
        t2 = tau
        b = [q.take(index, mode="clip") for q in bounds]
    # (1 + [tau >= tau_s] + [tau >= tau_w0] + [tau >= tau_d]) [tau > tau_dc]: the last factor
    # keeps tau = tau_dc in C where the pieces between are empty (lambda = 0: all bounds equal)
    piece = (t2 >= b[0]).view(np.int8)
    piece += t2 >= b[1]
    piece += t2 >= b[2]
    piece += 1
    piece *= t2 > b[3]
    return piece.ravel()


def _derived_fields(out: dict[str, FloatArray]) -> None:
    """force = delta^{3/2} and velocity = 1 - impulse, in place, block by block (per-point
    temporaries stay cache-sized, as in ``history``)."""
    for s in range(0, out["delta"].size, _BLOCK):
        d, f = out["delta"][s:s + _BLOCK], out["force"][s:s + _BLOCK]
        np.sqrt(d, out=f)
        f *= d
        np.subtract(1.0, out["impulse"][s:s + _BLOCK], out=out["velocity"][s:s + _BLOCK])
