"""Offline builder of the Chebyshev tables behind the fast exact model (``generated/exact_table.py``).

Every summary field of Eq. (10) is an analytic function of lambda, and the history, written in
suitable time variables, is analytic in (time variable, lambda). We sample the scipy exact solver
(:mod:`zener_sym.exact.solver`, rtol 1e-13) at Chebyshev points of the first kind on each lambda piece of
``LAM_PIECES`` and store Chebyshev coefficients (15 significant digits), trimmed where the
trailing ones fall below ``TRIM`` of the largest. :mod:`zener_sym.exact.table` evaluates them.

Time pieces of the history, each cut into ``N_SUB`` equal parts of its reduced time y (y in
[j/K, (j+1)/K] maps to x in [-1, 1]), so that each sub-piece needs a low degree (``N_TIME``):

``C`` compression, tau = tau_dc y^2: delta = tau exp(f), f analytic because delta is analytic in
    sqrt(tau) with delta ~ tau at the start and analytic in tau at the maximum.
``A`` recovery from tau_dc to tau_s, y from ``lin_log`` (logarithmic in tau - tau_dc at scale c1:
    resolves the fast relaxation after tau_dc). f = log delta. For lambda <= LOG_FROM tau_s is
    tau_w0, where the sphere is at rest (w = 1 - I = 0), and the map is logarithmic in
    tau_w0 - tau too (scale C_END (1 + lambda)); above, tau_s = tau_dc + lambda (S_ORBIT + ...),
    just past the loading transient.
``M`` (lambda > LOG_FROM only) from tau_s to tau_w0: the slow decay along the universal orbit
    (time scale lambda: linear in T = tau / lambda) and the change of regime at tau_w0
    (logarithmic, scale lambda). f = log delta. One logarithmic map over the whole recovery
    crams T in [1, 30] into a few percent of y at lambda = 1000 (coefficients stall at 1e-9).
``B`` the rest of the recovery, tau = tau_d - D y^2, D = tau_d - tau_w0: delta = (tau_d - tau) exp(f),
    analytic in sqrt(tau_d - tau) at the end of contact.

Splitting the recovery where w = 0 matters: for large lambda delta changes regime there (from the
quasi-static delta ~ (w/lambda)^{2/3} to the linear end e (tau_d - tau)); a single piece converges
slowly. The impulse I is tabulated directly on each piece (absolute accuracy). History arrays
are trimmed and rounded on the field's scale (``HISTORY_TRIM``, ``HISTORY_QUANTUM``): a
coefficient c of f moves delta by c delta, so it is weighed by the sub-piece's largest
delta / delta_m (at large lambda delta is 1e-10 delta_m and less in pieces M and B).

Large lambda (pieces above ``LOG_FROM``; the Chebyshev variable is ln lambda).
With delta = lambda^-4 D, w = lambda^-5 W, tau = lambda T, Eq. (10) becomes the lambda = 1 system
D' = W - D^{3/2}, W' = -D^{3/2} started at W = lambda^5: every lambda runs along one universal
orbit of that system once its loading transient has died out (the orbit attracts at the rate
1.5 lambda delta^{1/2}). So a node integrates only the early part (``solver.solve_early``: to
tau_dc plus ``MATCH_DECAYS`` e-foldings of that transient), and the rest of its contact is read
off one solve at ``LAM_U`` (the orbit in that lambda's variables), matched at equal W:
tau_d = tau_M + (lambda / LAM_U) (tau_d,U - tau_U(W_M)). The same orbit gives e = C lambda^-5
with C = e_U LAM_U^5 (the end of the orbit; the review saw e lambda^5 settle above lambda = 3),
and the energy balance gives int_F2 = (1 - e^2) / (2 lambda). The history after tau_M is the
orbit's too: delta = (LAM_U / lambda)^4 delta_U, w = (LAM_U / lambda)^5 w_U at
tau_U = t_U + (LAM_U / lambda)(tau - tau_M). The build stays cheap: one long solve instead of
one per node. History samples in the stiff tau-phases are integrated afresh from the solver's
accepted steps (``_from_steps``), not read off its dense output.

The node values come from a floating-point integrator, so the text is not bit-reproducible across
machines: the table is NOT in ``codegen.BUILDERS``; ``zener-sym exact-table --check`` rebuilds it
and compares numerically (see ``CHECK_RTOL``).
"""
from __future__ import annotations

import functools
import pathlib
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypedDict

import numpy as np

from ..codegen import inputs_hash
from ..codegen.tables import float_tuple, table_module
from ..numerics.chebyshev import (cheb_coefficients, cheb_nodes, coefficient_difference,
                                  trim_trailing)
from ..typing import FloatArray, RealArrayLike
from .table_layout import Layout, lin_log, parse_array

if TYPE_CHECKING:  # the solver is imported where a table is built (scipy stays unloaded till then)
    from .phases import Leg
    from .solver import ExactSolution

#: One lambda node's data: summary values by name, and per (time piece, field) the history
#: samples [sub-piece, point] (with (piece, "delta") the sub-pieces' largest delta).
NodeData = dict[str | tuple[str, str], Any]
#: (delta, w) of a solution at an array of times.
HistoryFunction = Callable[[FloatArray], tuple[FloatArray, FloatArray]]


class Tables(TypedDict):
    """What ``build_tables`` returns (and ``render`` writes)."""

    #: key -> per lambda piece one 1-D Chebyshev series
    summary: dict[str, list[FloatArray]]
    #: (time piece, field) -> per lambda piece one [time degree, lambda degree] matrix per
    #: sub-piece (an empty tuple where the piece has no such time piece)
    history: dict[tuple[str, str], list[tuple[FloatArray, ...]]]
    #: the same keys: per lambda piece the sub-pieces' weights
    weights: dict[tuple[str, str], list[tuple[float, ...]]]

#: Breakpoints of the lambda pieces: the summary and history tables cover [0, 1000].
LAM_PIECES = (0.0, 1.0, 2.0, 3.5, 5.0, 10.0, 25.0, 80.0, 300.0, 1000.0)
#: Pieces starting at or above this lambda use ln(lambda) as their Chebyshev variable (their
#: nodes come from the universal orbit, see the module docstring).
LOG_FROM = 5.0
#: The history tables end here (as the summary's).
HISTORY_TO = 1000.0
#: lambda of the one long solve that gives the universal orbit (above LAM_PIECES[-1]: every
#: node's W_M = lambda^5 w_M must lie on the part of the orbit past its own transient).
LAM_U = 1050.0
#: Tolerance of that one solve: tighter than RTOL, because every large-lambda history reads
#: the orbit off it far into its integration, where its error has accumulated (at RTOL 1e-13
#: delta was 1e-10 off relative at lambda = 107, early in piece M).
U_RTOL = 3e-14
#: e-foldings of the loading transient a large-lambda node integrates past tau_dc before matching.
MATCH_DECAYS = 40.0
#: Chebyshev points per lambda piece.
N_LAM = 22
#: Sub-pieces (equal parts of the reduced time y) per time piece; piece M exists on the ln-lambda
#: pieces only (see ``Layout.split_time``).
N_SUB = {"C": 12, "A": 16, "M": 16, "B": 12}
#: Chebyshev points per sub-piece of each time piece: low degrees keep the evaluation cheap
#: (each degree costs one pass over the points), more sub-pieces keep the accuracy.
N_TIME = {"C": 10, "A": 12, "M": 16, "B": 10}
#: Time scale of the logarithmic stretch of piece A at its start (tau_dc), for lambda <= LOG_FROM;
#: above, C_STRETCH (LOG_FROM / lambda)^(2/3), the relaxation time 1 / (1.5 lambda delta^{1/2})
#: of the loading transient (delta ~ lambda^(-2/3)).
C_STRETCH = 1.0
#: lambda <= LOG_FROM: time scale of the logarithmic stretch of piece A at its end (tau_w0),
#: C_END (1 + lambda), the time scale of the slow decay where delta changes regime.
C_END = 0.5
#: lambda > LOG_FROM: piece A ends at tau_s = tau_dc + lambda (S_ORBIT + S_TRANSIENT lambda^(-5/3)),
#: past the loading transient (40 e-foldings take 27 lambda^(-5/3) in T = tau / lambda); piece M
#: runs from there to tau_w0, linear in T with a logarithmic end of scale lambda.
S_ORBIT = 0.3
S_TRANSIENT = 10.0
#: Tolerance of the scipy solves at the nodes (their accuracy is about 1e-12).
RTOL = 1e-13
#: Trailing coefficients below this fraction of an array's largest are dropped (noise level).
TRIM = 1e-14
#: History arrays: a trailing row or column is dropped when each of its coefficients changes its
#: field by less than this (relative to delta_m for f, whose coefficient c changes delta by
#: c delta, so c is weighed by the sub-piece's largest delta / delta_m; absolute for I).
HISTORY_TRIM = 3e-13
#: History coefficients are written rounded to this, on the same scale (keeps the file small:
#: most coefficients are small or weigh little).
HISTORY_QUANTUM = 1e-15
#: ``--check`` passes when every rebuilt coefficient is within this of the stored one (relative
#: to the largest coefficient of its array).
CHECK_RTOL = 1e-10

SUMMARY_KEYS = ("delta_m", "tau_dc", "log_tau_d", "log_e", "int_F2", "rest_over_lam")
#: The layout the runtime reads back from the generated table (``table_layout.Layout.of``).
LAYOUT = Layout(LAM_PIECES=LAM_PIECES, LOG_FROM=LOG_FROM, HISTORY_TO=HISTORY_TO,
                C_STRETCH=C_STRETCH, C_END=C_END, S_ORBIT=S_ORBIT, S_TRANSIENT=S_TRANSIENT,
                N_SUB=N_SUB)
HISTORY_KEYS = LAYOUT.HISTORY_KEYS
TIME_PIECES = LAYOUT.TIME_PIECES


def time_nodes(piece: str, y: FloatArray, tau_dc: float, tau_w0: float, tau_d: float,
               params: Sequence[float] | None = None) -> FloatArray:
    """tau at the reduced time y in [0, 1] of one time piece (see the module docstring).

    Pieces A and M invert ``lin_log`` (``params`` from ``Layout.map_params``) by bisection
    (monotone).

    Parameters
    ----------
    piece : str
        "C", "A", "M" or "B".
    y : ndarray
        Reduced times in [0, 1].
    tau_dc, tau_w0, tau_d : float
        End of compression, rest time (w = 0) and end of contact.
    params : sequence of float, optional
        (start, end, c1, c2, c3) of ``lin_log``; needed for pieces A and M.

    Returns
    -------
    ndarray
        tau, y's shape.

    Raises
    ------
    ValueError
        For piece A or M without ``params``.
    """
    if piece == "C":
        return tau_dc * y * y
    if piece == "B":
        return tau_d - (tau_d - tau_w0) * y * y
    if params is None:
        raise ValueError(f"time_nodes: piece {piece!r} needs the map's params (Layout.map_params)")
    start, end = params[0], params[1]
    lo, hi = np.full(y.shape, start), np.full(y.shape, end)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if np.all((mid <= lo) | (mid >= hi)):
            break
        below = lin_log(mid, *params) < y
        lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
    tau: FloatArray = 0.5 * (lo + hi)
    return tau


def sub_nodes(piece: str) -> FloatArray:
    """Reduced times y of the Chebyshev points of every sub-piece of a time piece.

    Parameters
    ----------
    piece : str
        A key of ``N_SUB``.

    Returns
    -------
    ndarray
        [sub-piece, point].
    """
    k, x = N_SUB[piece], cheb_nodes(N_TIME[piece])
    return (np.arange(k)[:, None] + (x[None, :] + 1.0) / 2.0) / k


def _rest_time(sol: ExactSolution) -> float:
    """tau_w0 in (tau_dc, tau_d) where the relative velocity w = 1 - I vanishes (w' = -F < 0)."""
    from scipy.optimize import brentq

    def w(t: float) -> float:
        return float(sol.history(np.array([t]))["velocity"][0])

    tau_w0: float = brentq(w, sol.tau_dc, sol.tau_d, xtol=1e-15, rtol=1e-15, maxiter=200)
    return tau_w0


def _from_steps(leg: Leg, t: FloatArray) -> FloatArray:
    """States of a tau-phase (a ``phases.Leg``) at the times t, integrated afresh with the phase's
    own equations from the last accepted step before each t (all points at once, DOP853 at RTOL
    in s = (t - t_k) / (t_k+1 - t_k)).

    Not ``sol(t)``: at large lambda the phase is stiff (rate 1.5 lambda delta^{1/2}), its steps sit
    at the stability limit and DOP853's dense output between steps is off by up to 7e-9 relative
    in delta (at lambda = 100 matched to the orbit at LAM_U), while the step states are not."""
    from scipy.integrate import solve_ivp

    sol, terms = leg.sol, leg.form.terms
    ts = sol.ts
    k = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, len(ts) - 2)
    y0 = np.atleast_2d(sol(ts[k]))  # [state, point]: a step's own state (interpolant at its start)
    dt = t - ts[k]
    n = y0.shape[0]

    def f(x: float, y: FloatArray) -> FloatArray:
        rates: FloatArray = (np.stack(terms(x, y.reshape(n, -1))) * dt).ravel()
        return rates

    r = solve_ivp(f, (0.0, 1.0), y0.ravel(), method="DOP853", rtol=RTOL, atol=1e-300)
    if r.status != 0:
        raise RuntimeError(f"table build: re-integration from the steps failed at lambda = "
                           f"{leg.form.lam}")
    states: FloatArray = r.y[:, -1].reshape(n, -1)
    return states


def node_history(s: ExactSolution, tau: RealArrayLike) -> tuple[FloatArray, FloatArray]:
    """(delta, w) of a solution at tau, the tau-phases from their steps (``_from_steps``).

    Parameters
    ----------
    s : ExactSolution
        From ``solver.solve`` or ``solve_early``; the u-phases are read from ``s.history``.
    tau : array_like
        Times inside the solution.

    Returns
    -------
    tuple of ndarray
        delta and w = 1 - I, tau's shape.
    """
    t = np.asarray(tau, dtype=float)
    delta, w = np.empty(t.shape), np.empty(t.shape)
    where = s.leg_of(t)
    rest = np.ones(t.shape, dtype=bool)
    for i, leg in enumerate(s.legs):
        m = where == i
        if leg.form.kind == "tau" and m.any():
            y = _from_steps(leg, t[m])
            delta[m], w[m] = y[0], y[leg.form.w_row]
            rest &= ~m
    if rest.any():
        h = s.history(t[rest])
        delta[rest], w[rest] = h["delta"], h["velocity"]
    return delta, w


def is_log_piece(a: float) -> bool:
    """True for a lambda piece [a, b] tabulated in ln(lambda).

    Parameters
    ----------
    a : float
        The piece's lower end.

    Returns
    -------
    bool
    """
    return a >= LOG_FROM


@functools.cache
def universal_orbit() -> tuple[ExactSolution, float, float]:
    """The universal orbit as the solution at LAM_U, its rest time and C = e lambda^5.

    Returns
    -------
    tuple
        (the ``ExactSolution`` at LAM_U, its tau_w0, C).
    """
    from . import solver as exact

    U = exact.solve(LAM_U, rtol=U_RTOL)
    return U, _rest_time(U), -U.w_end * LAM_U**5


def large_node(lam: float, history: bool = True) -> NodeData:
    """Summary values (and history samples) of one large lambda from its early part and the
    universal orbit.

    Before tau_M = tau_dc + MATCH_DECAYS / rate its own solve, after it the orbit,
    delta = (LAM_U / lambda)^4 delta_U and w = (LAM_U / lambda)^5 w_U at
    tau_U = t_U + (LAM_U / lambda) (tau - tau_M).

    Parameters
    ----------
    lam : float
        lambda (Eq. 11) above LOG_FROM.
    history : bool
        Whether to sample the history too.

    Returns
    -------
    dict
        The node's data (``NodeData``).
    """
    from scipy.optimize import brentq

    from . import solver as exact

    U, tau_w0_U, C = universal_orbit()
    rate = 1.5 * lam * lam ** (-1.0 / 3.0)  # 1.5 lambda delta^{1/2} with delta ~ lambda^{-2/3}
    r = exact.solve_early(lam, MATCH_DECAYS / rate, rtol=RTOL)
    target = (lam / LAM_U) ** 5 * r["w"]  # the same W = lambda^5 w on the orbit

    def w_U(t: float) -> float:
        return float(U.history(np.array([t]))["velocity"][0]) - target

    t_U: float = brentq(w_U, U.tau_dc, tau_w0_U, xtol=1e-14, rtol=8.9e-16, maxiter=300)
    scale = lam / LAM_U  # tau = lambda T
    tau_d = r["tau"] + scale * (U.tau_d - t_U)
    tau_w0 = r["tau"] + scale * (tau_w0_U - t_U)
    e = C / lam**5
    out: NodeData = {"delta_m": r["delta_m"], "tau_dc": r["tau_dc"], "log_tau_d": np.log(tau_d),
           "log_e": np.log(e), "int_F2": (1.0 - e * e) / (2.0 * lam),
           "rest_over_lam": (tau_w0 - r["tau_dc"]) / lam}
    if history:
        early = r["solution"]

        def hist(tau: FloatArray) -> tuple[FloatArray, FloatArray]:
            delta, w = np.empty(tau.shape), np.empty(tau.shape)
            m = tau < r["tau"]
            if m.any():
                delta[m], w[m] = node_history(early, tau[m])
            if (~m).any():
                d_U, w_U = node_history(U, t_U + (tau[~m] - r["tau"]) / scale)
                delta[~m], w[~m] = d_U * scale**-4, w_U * scale**-5
            return delta, w

        out.update(_history_samples(hist, r["tau_dc"], tau_w0, tau_d, lam, True))
    return out


def piece_nodes(a: float, b: float) -> FloatArray:
    """The lambda nodes of the piece [a, b] (Chebyshev points in lambda or in ln lambda).

    Parameters
    ----------
    a, b : float
        The piece's ends.

    Returns
    -------
    ndarray
        N_LAM nodes.
    """
    x = cheb_nodes(N_LAM)
    if is_log_piece(a):
        nodes: FloatArray = np.exp(np.log(a) + (np.log(b) - np.log(a)) * (x + 1.0) / 2.0)
        return nodes
    return a + (b - a) * (x + 1.0) / 2.0


def _history_samples(hist: HistoryFunction, tau_dc: float, tau_w0: float, tau_d: float,
                     lam: float, log_piece: bool) -> NodeData:
    """{(piece, "f"/"I"): [sub, point]} from hist(tau) -> (delta, w) at the sub-pieces' nodes."""
    tau_s = float(LAYOUT.split_time(lam, log_piece, tau_dc, tau_w0))
    out: NodeData = {}
    for piece in TIME_PIECES:
        if piece == "M" and not log_piece:
            continue
        params = tuple(float(c) for c in LAYOUT.map_params(piece, lam, log_piece, tau_dc, tau_s,
                                                           tau_w0))
        y = sub_nodes(piece)
        tau = time_nodes(piece, y, tau_dc, tau_w0, tau_d, params)
        d, w = hist(tau.ravel())
        d, w = d.reshape(y.shape), w.reshape(y.shape)
        if piece == "C":
            f = np.log(d / tau)
        elif piece == "B":
            f = np.log(d / ((tau_d - tau_w0) * y * y))
        else:
            f = np.log(d)
        out[(piece, "f")] = f
        out[(piece, "I")] = 1.0 - w
        out[(piece, "delta")] = d.max(axis=1)  # per sub-piece: the weight of f's coefficients
    return out


def node_data(lam: float) -> NodeData:
    """Summary values and history samples of one lambda (lambda > 0: nodes never include 0).

    Parameters
    ----------
    lam : float
        lambda (Eq. 11), 0 < lam <= LOG_FROM.

    Returns
    -------
    dict
        The node's data (``NodeData``).
    """
    from . import solver as exact

    s = exact.solve(lam, rtol=RTOL)
    tau_w0 = _rest_time(s)
    out: NodeData = {"delta_m": s.delta_m, "tau_dc": s.tau_dc, "log_tau_d": np.log(s.tau_d),
           "log_e": np.log(-s.w_end), "int_F2": s.int_F2,
           "rest_over_lam": (tau_w0 - s.tau_dc) / lam}
    out.update(_history_samples(lambda t: node_history(s, t), s.tau_dc, tau_w0, s.tau_d, lam,
                                False))
    return out


def build_tables() -> Tables:
    """All coefficients: {"summary": {key: [1-D per lambda piece]}, "history": {(piece, key): [2-D]}}.

    history[(piece, key)] holds, per lambda piece up to HISTORY_TO, one 2-D array per sub-piece
    indexed [time degree, lambda degree].

    Returns
    -------
    Tables
        summary, history and the history's weights.
    """
    summary: dict[str, list[FloatArray]] = {k: [] for k in SUMMARY_KEYS}
    history: dict[tuple[str, str], list[tuple[FloatArray, ...]]] = {
        (p, k): [] for p in TIME_PIECES for k in HISTORY_KEYS}
    # per lambda piece, per sub-piece
    weights: dict[tuple[str, str], list[tuple[float, ...]]] = {key: [] for key in history}
    for a, b in zip(LAM_PIECES[:-1], LAM_PIECES[1:]):
        lams = piece_nodes(a, b)
        if is_log_piece(a):
            data = [large_node(float(x), history=b <= HISTORY_TO) for x in lams]
        else:
            data = [node_data(float(x)) for x in lams]
        for k in SUMMARY_KEYS:
            c = cheb_coefficients(np.array([d[k] for d in data]))
            summary[k].append(trim_trailing(c, np.abs(c) > TRIM * np.abs(c).max()))
        if b > HISTORY_TO:
            continue
        for key in history:
            if key not in data[0]:  # piece M below LOG_FROM
                history[key].append(())
                weights[key].append(())
                continue
            mats, wts = history_coefficients(data, key)
            history[key].append(mats)
            weights[key].append(wts)
    return {"summary": summary, "history": history, "weights": weights}


def history_coefficients(data: Sequence[NodeData], key: tuple[str, str]
                         ) -> tuple[tuple[FloatArray, ...], tuple[float, ...]]:
    """One lambda piece's history series of ``key`` = (time piece, field) from its node data.

    Shared by the plate's and the force-free end's tables.

    Parameters
    ----------
    data : sequence of dict
        The piece's node data (``NodeData``), one per lambda node.
    key : tuple of str
        (time piece, field).

    Returns
    -------
    tuple
        Per sub-piece one [time degree, lambda degree] Chebyshev matrix, trimmed where it moves
        the field by less than HISTORY_TRIM, and the sub-pieces' weights.
    """
    vals = np.array([d[key] for d in data])  # [lambda node, sub, time node]
    c = cheb_coefficients(cheb_coefficients(vals, axis=2), axis=0)
    if key[1] == "f":  # c moves delta by c delta: weighed by delta / delta_m
        wt: FloatArray = np.max([d[(key[0], "delta")] / d["delta_m"] for d in data], axis=0)
    else:
        wt = np.ones(c.shape[1])
    mats = tuple(trim_trailing(c[:, j, :].T, np.abs(c[:, j, :].T) * wt[j] > HISTORY_TRIM)
                 for j in range(c.shape[1]))
    return mats, tuple(float(x) for x in wt)


def input_files() -> list[pathlib.Path]:
    """The sources the table is built from (its inputs hash).

    Returns
    -------
    list of pathlib.Path
        This builder, the layout it writes and the solver it samples (with its phase driver).
    """
    here = pathlib.Path(__file__).resolve().parent
    return [here / name for name in ("table_build.py", "table_layout.py", "solver.py",
                                     "phases.py")]


def _fmt_q(a: FloatArray, quantum: float) -> str:
    """A 2-D array as the string "rows cols v v ...", each number with the digits that resolve
    ``quantum`` (at most 16). A string rather than a tuple literal: Python compiles a module of
    80 000 float literals in about a second (every process, where bytecode is not cached),
    numpy parses the strings in milliseconds (``parse_array``)."""
    def one(value: float) -> str:
        v = float(value)
        if abs(v) < quantum:
            return "0"
        n = int(np.clip(np.floor(np.log10(abs(v))) - np.floor(np.log10(quantum)) + 1, 1, 16))
        return f"{v:.{n}g}"

    return f"{a.shape[0]} {a.shape[1]} " + " ".join(one(v) for v in a.ravel())


def _fmt(a: FloatArray, indent: str) -> str:
    if a.ndim == 1:
        text: str = float_tuple(a, 15)
        return text
    rows = [indent + "    " + _fmt(r, "") + "," for r in a]
    return "(\n" + "\n".join(rows) + "\n" + indent + ")"


def table_lines(t: Mapping[str, Any], summary_keys: Sequence[str],
                history_comment: Sequence[str]) -> list[str]:
    """The SUMMARY and HISTORY assignments of a generated exact table.

    Shared by the plate's and the force-free end's: summary series per lambda piece, history
    matrices per lambda piece and sub-piece, quantised by their weights.

    Parameters
    ----------
    t : mapping
        The tables (``Tables``: summary, history, weights).
    summary_keys : sequence of str
        The summary series, in order.
    history_comment : sequence of str
        Comment lines written before HISTORY.

    Returns
    -------
    list of str
        The lines, from the SUMMARY entries to HISTORY's closing brace.
    """
    lines = []
    for k in summary_keys:
        lines.append(f"    {k!r}: (")
        for c in t["summary"][k]:
            lines.append("        " + _fmt(c, "        ") + ",")
        lines.append("    ),")
    lines += ["}", "", *history_comment, "HISTORY = {"]
    for key in sorted(t["history"]):
        lines.append(f"    {key!r}: (")
        for subs, wts in zip(t["history"][key], t["weights"][key]):
            lines.append("        (")
            for c, wt in zip(subs, wts):
                lines.append(f"            {_fmt_q(c, HISTORY_QUANTUM / wt)!r},")
            lines.append("        ),")
        lines.append("    ),")
    return lines + ["}"]


def render(tables: Tables | None = None) -> str:
    """Text of ``generated/exact_table.py``.

    Parameters
    ----------
    tables : Tables, optional
        Built tables (``build_tables``, which is called without them).

    Returns
    -------
    str
        The module's text.
    """
    import scipy

    t = build_tables() if tables is None else tables
    lines = ["#: the tables' layout (zener_sym.exact.table_layout.Layout reads it back)",
             *LAYOUT.assignments(), "",
             "#: field -> one tuple of Chebyshev coefficients per lambda piece",
             "SUMMARY = {"]
    lines += table_lines(t, SUMMARY_KEYS, (
        "#: (time piece, field) -> per lambda piece up to HISTORY_TO, per sub-piece, one",
        "#: coefficient matrix [time degree][lambda degree] as the string \"rows cols values...\"",
        "#: (table_layout.parse_array)"))
    title = ("Chebyshev tables of the exact solution of Eq. (10): summary for 0 <= lambda <= "
             f"{LAM_PIECES[-1]:g}, history for 0 <= lambda <= {HISTORY_TO:g}.")
    provenance = (f"Built by zener_sym.exact.table_build from scipy {scipy.__version__} solves at "
                  f"rtol {RTOL:g}; `zener-sym exact-table --check` rebuilds and compares "
                  "numerically (the node values come from a floating-point integrator, so the "
                  "bytes are not reproducible across machines).")
    text: str = table_module(title, "exact-table", provenance, inputs_hash(input_files()), lines)
    return text


def table_path() -> pathlib.Path:
    """Where the generated table lives.

    Returns
    -------
    pathlib.Path
        ``generated/exact_table.py``.
    """
    from ..codegen import generated_dir

    path: pathlib.Path = generated_dir() / "exact_table.py"
    return path


def compare(stored: Mapping[str, Any], fresh: Mapping[str, Any],
            rtol: float = CHECK_RTOL) -> list[str]:
    """Differences beyond ``rtol`` (default CHECK_RTOL) between two tables.

    Parameters
    ----------
    stored : mapping
        The generated module's SUMMARY and HISTORY (history as strings), as "summary" and
        "history".
    fresh : mapping
        Rebuilt tables (``Tables``).
    rtol : float
        Largest coefficient difference, relative to its array's largest coefficient.

    Returns
    -------
    list of str
        Readable lines, one per difference (empty: they agree).
    """
    bad = []

    def flat(arrays: Sequence[Any]) -> list[FloatArray]:
        # summary: one array per lambda piece; history: one per (piece, sub-piece)
        out: list[FloatArray] = []
        for c in arrays:
            if isinstance(c, tuple) and not c:  # no piece M below LOG_FROM
                continue
            if isinstance(c, tuple) and isinstance(c[0], str):
                out.extend(parse_array(x) for x in c)
            elif isinstance(c, tuple) and not np.isscalar(c[0]) and np.ndim(c[0]) == 2:
                out.extend(c)
            else:
                out.append(c)
        return out

    def flat_w(weights: Sequence[Sequence[float]]) -> list[float]:
        return [w for subs in weights for w in subs]

    for kind in ("summary", "history"):
        for key in fresh[kind]:
            new, old = flat(fresh[kind][key]), flat(stored[kind][key])
            quanta = ([HISTORY_QUANTUM / w for w in flat_w(fresh["weights"][key])]
                      if kind == "history" and "weights" in fresh else [0.0] * len(new))
            if len(new) != len(old):
                bad.append(f"{kind} {key}: {len(new)} arrays, the stored table has {len(old)}")
                continue
            for i, (c_new, c_old, q) in enumerate(zip(new, old, quanta)):
                # history: a change that moves the field by less than HISTORY_TRIM of its scale
                # (the trimming and rounding level) passes too
                floor = q * HISTORY_TRIM / HISTORY_QUANTUM
                err = coefficient_difference(c_new, c_old, floor / rtol)
                if not err <= rtol:
                    bad.append(f"{kind} {key} array {i}: relative difference {err:.2e} "
                               f"> {rtol:g}")
    return bad
