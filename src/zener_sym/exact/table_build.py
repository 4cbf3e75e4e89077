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

The table is a configuration of the package's one Chebyshev-table engine
(:mod:`zener_sym.numerics.cheb_table_build`): ``SPEC`` describes its lambda pieces, and this module
gives the node function (the solves above) and the history's weights.

The node values come from a floating-point integrator, so the text is not bit-reproducible across
machines: the table is NOT in ``codegen.BUILDERS``; ``zener-sym regen --check exact-table``
rebuilds it and compares numerically (see ``CHECK_RTOL``).
"""
from __future__ import annotations

import functools
import pathlib
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import numpy as np

from ..numerics import cheb_table_build as engine
from ..numerics.cheb_table import TableSpec
from ..numerics.cheb_table_build import NodeData, Tables
from ..numerics.chebyshev import cheb_nodes  # noqa: F401 - tests place points between the nodes
from ..typing import FloatArray, RealArrayLike
from .table_layout import Layout, lin_log

if TYPE_CHECKING:  # the solver is imported where a table is built (scipy stays unloaded till then)
    from .phases import Leg
    from .solver import ExactSolution

__all__ = ["SPEC", "LAYOUT", "HISTORY", "BUILDER", "NodeData", "Tables", "sample", "build_tables",
           "render", "compare", "as_tables", "input_files", "history_weight"]

#: (delta, w) of a solution at an array of times.
HistoryFunction = Callable[[FloatArray], tuple[FloatArray, FloatArray]]

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
#: pieces only (see ``Layout.split_time``). Written into the file by the engine (``HISTORY``).
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
#: The comment above the history in the generated table.
HISTORY_NOTE = (
    "#: (time piece, field) -> per lambda piece up to HISTORY_TO, per sub-piece, one",
    "#: coefficient matrix [time degree][lambda degree] as the string \"rows cols values...\"",
    "#: (zener_sym.numerics.cheb_table.parse_array)")
#: The time maps' constants the runtime reads back from the generated table
#: (``table_layout.Layout.of``); the pieces are the description's (``SPEC``, ``HISTORY``).
LAYOUT = Layout(C_STRETCH=C_STRETCH, C_END=C_END, S_ORBIT=S_ORBIT, S_TRANSIENT=S_TRANSIENT)
#: The time pieces, in the order of time (a point's piece index counts in this order).
TIME_PIECES = ("C", "A", "M", "B")
#: The tabulated history fields: f (delta's log-part) and the impulse I.
HISTORY_FIELDS = ("f", "I")
#: The table's description for the engine: lambda pieces (in lambda below LOG_FROM, in ln lambda
#: above), the stored series, points per piece, trimming and ``--check`` tolerance.
SPEC = TableSpec.on_edges(LAM_PIECES, "lam", LOG_FROM, SUMMARY_KEYS, N_LAM, trim=TRIM,
                          check_rtol=CHECK_RTOL, digits=15)


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
    return engine.sub_nodes(N_SUB[piece], N_TIME[piece])


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


def _history_samples(hist: HistoryFunction, tau_dc: float, tau_w0: float, tau_d: float,
                     lam: float, log_piece: bool) -> NodeData:
    """{(piece, "f"/"I"): [sub, point]} from hist(tau) -> (delta, w) at the sub-pieces' nodes."""
    tau_s = float(LAYOUT.split_time(lam, log_piece, tau_dc, tau_w0))
    out: NodeData = {}
    for piece in TIME_PIECES:
        if piece == "M" and not log_piece:
            continue
        params = tuple(float(c) for c in LAYOUT.map_params(piece, lam, log_piece, tau_dc, tau_s,
                                                           tau_w0, LOG_FROM))
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


def history_weight(data: Sequence[NodeData], key: tuple[str, str]) -> FloatArray:
    """Per sub-piece, the scale a history coefficient of ``key`` moves its field by: a
    coefficient c of f moves delta by c delta, so it is weighed by the sub-piece's largest
    delta / delta_m over the piece's nodes; the other field is absolute (weight 1). Shared by
    the plate's and the force-free end's tables.

    Parameters
    ----------
    data : sequence of dict
        The lambda piece's node data (``NodeData``).
    key : tuple of str
        (time piece, field).

    Returns
    -------
    ndarray
        One weight per sub-piece.
    """
    if key[1] == "f":
        wt: FloatArray = np.max([d[(key[0], "delta")] / d["delta_m"] for d in data], axis=0)
        return wt
    return np.ones(np.shape(data[0][key])[0])


def sample(p: int, lams: FloatArray) -> list[NodeData]:
    """The nodes' data of lambda piece ``p`` (the builder's node function): the universal orbit
    on the ln-lambda pieces, a solve per node below.

    Parameters
    ----------
    p : int
        The lambda piece.
    lams : ndarray
        Its nodes.

    Returns
    -------
    list of dict
        One ``NodeData`` per node.
    """
    a, b = LAM_PIECES[p], LAM_PIECES[p + 1]
    if SPEC.kind_of(a) == "log":
        return [large_node(float(x), history=b <= HISTORY_TO) for x in lams]
    return [node_data(float(x)) for x in lams]


def input_files() -> list[pathlib.Path]:
    """The sources the table is built from (its inputs hash).

    Returns
    -------
    list of pathlib.Path
        This builder, the layout it writes, the solver it samples (with its phase driver) and
        the table engine.
    """
    here = pathlib.Path(__file__).resolve().parent
    return [here / name for name in ("table_build.py", "table_layout.py", "solver.py",
                                     "phases.py")] + engine_files()


def digest() -> str:
    """The table's inputs hash (``codegen.inputs_hash`` of :func:`input_files`)."""
    from ..codegen import inputs_hash

    return inputs_hash(input_files())


def engine_files() -> list[pathlib.Path]:
    """The table engine's sources (its fitting, trimming and text), inputs of every table.

    Returns
    -------
    list of pathlib.Path
        ``numerics/cheb_table.py``, ``numerics/cheb_table_build.py`` and
        ``numerics/cheb_table_history.py``.
    """
    numerics = pathlib.Path(engine.__file__).resolve().parent
    return [numerics / "cheb_table.py", numerics / "cheb_table_build.py",
            numerics / "cheb_table_history.py"]


def _layout_lines(spec: TableSpec) -> list[str]:
    """The file's lines before its description: the time maps' constants."""
    return ["#: the time maps' constants (zener_sym.exact.table_layout.Layout reads them back)",
            *LAYOUT.assignments()]


#: The history: both fields of every time piece up to HISTORY_TO, trimmed and rounded on the
#: field's scale.
HISTORY = engine.HistorySettings(
    time_pieces=TIME_PIECES, fields=HISTORY_FIELDS, n_sub=N_SUB, hi=HISTORY_TO,
    trim=HISTORY_TRIM, quantum=HISTORY_QUANTUM, weight=history_weight, note=HISTORY_NOTE)

#: The table: ``BUILDER.build()``, ``.render()``, ``.compare()`` (the engine's methods).
BUILDER = engine.TableBuilder(
    spec=SPEC,
    file=engine.TableFile(
        "exact_table.py", "exact-table",
        title=("Chebyshev tables of the exact solution of Eq. (10): summary for 0 <= lambda <= "
               f"{LAM_PIECES[-1]:g}, history for 0 <= lambda <= {HISTORY_TO:g}."),
        provenance=("Built by zener_sym.exact.table_build from scipy {scipy} solves at "
                    f"rtol {RTOL:g}; `zener-sym regen --check exact-table` rebuilds and compares "
                    "numerically (the node values come from a floating-point integrator, so the "
                    "bytes are not reproducible across machines).")),
    sample=sample, digest=digest, history=HISTORY, head=_layout_lines)

# the builder's methods under the names the table commands and tests call
build_tables, render, compare = BUILDER.build, BUILDER.render, BUILDER.compare
as_tables = BUILDER.as_tables
