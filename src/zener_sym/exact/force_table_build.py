"""Offline builder of the Chebyshev tables of the force-free end of contact
(``generated/exact_force_table.py``), the grains' reading of Eq. (10) (:mod:`.force_end`).

Built the way the plate's are (:mod:`.table_build`): the public results of
:func:`zener_sym.exact.force_end.solve` (rtol 1e-13: summary fields, and ``history`` at the time
nodes) are sampled at Chebyshev points of the first kind on each lambda piece of ``LAM_PIECES``
and stored as Chebyshev coefficients, evaluated by :mod:`zener_sym.exact.force_table`.

Lambda variable. The force-free end makes the summary go like powers of sqrt(lambda) near 0
(``models.series``: e = sum a_j lambda^(j/2)), so the pieces below ``LOG_FROM`` use
s = sqrt(lambda) as their Chebyshev variable (a series in lambda would converge like
sqrt at 0); above, ln lambda as the plate's. xi is stored as xi / lambda (xi = 3.46 lambda +
O(lambda^(3/2)) as lambda -> 0; stored as xi / sqrt(lambda) it lost its relative accuracy like
sqrt(lambda), 1e-10 at lambda = 1e-12): xi = lambda (xi / lambda) keeps its relative accuracy
down to lambda = 0, where it is exactly 0. xi comes from the solver's energy balance (never
1 - e^2); e = sqrt(1 - xi) while xi < 1/2, as ``solver.restitution`` forms it.

Time pieces of the history (the contact is the plate's trajectory cut at the force-free point
tau_d; ``K`` = ``N_SUB`` equal sub-pieces of the reduced time y, each mapped onto [-1, 1]):

``C`` compression, tau = tau_dc y^2 (as the plate's): delta = tau exp(f), v = delta'.
``R`` recovery, tau_dc to tau_d. Below ``LOG_FROM`` the trajectory, continued past tau_d, reaches
    delta = 0 at the plate's end of contact tau_P (``solver.solve``'s tau_d, stored as the
    series ``log_tau_p``: 0 on the ln-lambda pieces, which do not use it), where delta is
    analytic in sqrt(tau_P - tau); for small lambda tau_P lies only about 1.5 lambda past
    tau_d. So tau = tau_P - (tau_P - tau_dc) z^2 with z linear in y, and delta =
    (tau_P - tau) exp(f). Above, delta hardly recovers before the force vanishes (delta(tau_d)
    > 0.9 delta_m): tau linear in y and delta = exp(f).

The velocity v = delta' is tabulated itself (absolute accuracy); the force F_c =
sqrt(delta) (delta + (3/2) lambda v) and the impulse 1 - v follow from (delta, v).

A configuration of the one Chebyshev-table engine (:mod:`zener_sym.numerics.cheb_table_build`):
``SPEC`` and the node function below; the history's weights are the plate's
(``table_build.history_weight``).

The node values come from a floating-point integrator: ``zener-sym regen --check
exact-force-table`` rebuilds and compares numerically (``CHECK_RTOL``), as for the plate's.
"""
from __future__ import annotations

import dataclasses
import pathlib

import numpy as np

from ..numerics import cheb_table_build as engine
from ..numerics.cheb_table import TableSpec
from ..numerics.cheb_table_build import NodeData
from ..typing import FloatArray
from . import table_build as _tb
from .force_table_layout import time_of

__all__ = ["SPEC", "HISTORY", "BUILDER", "sample", "build_tables", "render", "compare",
           "as_tables", "input_files"]

#: Breakpoints of the lambda pieces (summary and history), [0, 1000].
LAM_PIECES = (0.0, 0.25, 1.0, 2.0, 3.5, 5.0, 25.0, 150.0, 1000.0)
#: Pieces starting at or above this lambda use ln(lambda) as their variable, below sqrt(lambda).
LOG_FROM = 5.0
#: Chebyshev points per lambda piece.
N_LAM = 22
#: Sub-pieces per time piece and Chebyshev points per sub-piece.
N_SUB = {"C": 12, "R": 12}
N_TIME = {"C": 10, "R": 12}
#: Tolerance of the scipy solves at the nodes (force_end's default).
RTOL = 1e-13
#: Trimming and rounding: the plate builder's (:mod:`.table_build`); ``--check``'s tolerance below.
TRIM = _tb.TRIM
#: ``--check``'s tolerance (as the plate's, ``table_build.CHECK_RTOL``, but wider). A rebuild
#: on an AVX-512 machine (2026-11-26, and again 2026-11-27) differs from the committed table
#: (built on an AVX2 one) by 1.93e-10 in one array, ('R', 'f') 11: lambda in [0, 0.25], the last
#: sub-piece of the recovery, whose corner lambda = 0, tau = tau_d degenerates (tau_P - tau_d ->
#: 0). Its coefficients are noise of the solves from degree 6 or so on, a plateau within a factor
#: 3 of the trimming level, so the two builds trim it differently (12 x 22 committed, 7 x 14
#: rebuilt); untrimmed, the rebuilt array still differs by the same 1.93e-10: it is the node
#: values, not the trimming rule, that differ, and no threshold on them can be free of their
#: last bits. ``zener-sym regen`` therefore keeps the committed numbers when a rebuild agrees
#: within this tolerance (``artefacts._table``): a rebuild writes the committed bytes on any
#: processor. On an 11 x 11 grid of the sub-piece f differs by 4.2e-9 at that corner, where
#: delta = (tau_P - tau) exp(f) vanishes, and by at most 3.3e-11 elsewhere (below the
#: documented history bound, ``force_table.HISTORY_ATOL`` = 1e-10); the committed table is
#: within 1.3e-12 of delta_m of the solver there. The plate's table rebuilds within 1e-10. A
#: changed builder moves coefficients far more.
CHECK_RTOL = 1e-9

SUMMARY_KEYS = ("delta_m", "tau_dc", "log_tau_d", "log_e", "xi_over_lam", "log_F_m", "log_int_F2",
                "log_tau_p")
#: The time pieces, in the order of time, and the tabulated history fields: f (delta's
#: log-part) and v = delta'.
TIME_PIECES = ("C", "R")
HISTORY_FIELDS = ("f", "v")
#: The table's description for the engine: sqrt(lambda) pieces below LOG_FROM, ln lambda above.
SPEC = TableSpec.on_edges(LAM_PIECES, "sqrt_lam", LOG_FROM, SUMMARY_KEYS, N_LAM, trim=TRIM,
                          check_rtol=CHECK_RTOL, digits=15)


def node_data(lam: float, log_piece: bool) -> NodeData:
    """Summary values and history samples of one lambda > 0, from ``force_end.solve``.

    Parameters
    ----------
    lam : float
        lambda (Eq. 11), > 0.
    log_piece : bool
        Whether lambda lies on a ln-lambda piece.

    Returns
    -------
    dict
        The node's data (``table_build.NodeData``).
    """
    from . import force_end, solver

    s = force_end.solve(lam, rtol=RTOL)
    # the plate's end of contact, the recovery map's anchor (unused on the ln-lambda pieces)
    tau_p = np.inf if log_piece else float(solver.solve(lam, rtol=RTOL).tau_d)
    out: NodeData = {"delta_m": s.delta_m, "tau_dc": s.tau_dc, "log_tau_d": np.log(s.tau_d),
           "log_e": np.log(s.e), "xi_over_lam": s.xi / lam, "log_F_m": np.log(s.F_m),
           "log_int_F2": np.log(s.int_F2), "log_tau_p": 0.0 if log_piece else np.log(tau_p)}
    for piece in TIME_PIECES:
        y = engine.sub_nodes(N_SUB[piece], N_TIME[piece])
        tau = time_of(piece, y, s.tau_dc, s.tau_d, tau_p, log_piece)
        h = s.history(tau.ravel())
        d = np.asarray(h["delta"], dtype=float).reshape(y.shape)
        v = np.asarray(h["velocity"], dtype=float).reshape(y.shape)
        if piece == "C":
            f = np.log(d / tau)
        elif log_piece:
            f = np.log(d)
        else:
            f = np.log(d / (tau_p - tau))
        out[(piece, "f")] = f
        out[(piece, "v")] = v
        out[(piece, "delta")] = d.max(axis=1)  # per sub-piece: the weight of f's coefficients
    return out


def sample(p: int, lams: FloatArray) -> list[NodeData]:
    """The builder's node function: per node of lambda piece ``p`` (``lams``) one ``NodeData``
    from ``force_end.solve`` (the ln-lambda pieces' recovery map without tau_P)."""
    return [node_data(float(x), SPEC.kind_of(LAM_PIECES[p]) == "log") for x in lams]


def input_files() -> list[pathlib.Path]:
    """The sources the table is built from (its inputs hash).

    Returns
    -------
    list of pathlib.Path
        This builder, the layout it writes, the solvers it samples and the table engine.
    """
    here = pathlib.Path(__file__).resolve().parent
    return [here / name for name in ("force_table_build.py", "force_table_layout.py",
                                     "force_end.py", "solver.py", "phases.py")] + _tb.engine_files()


def digest() -> str:
    """The table's inputs hash (``codegen.inputs_hash`` of :func:`input_files`)."""
    from ..codegen import inputs_hash

    return inputs_hash(input_files())


#: The history: (f, v) of both time pieces over the whole range, trimmed, weighed and rounded
#: as the plate's.
HISTORY = dataclasses.replace(
    _tb.HISTORY, time_pieces=TIME_PIECES, fields=HISTORY_FIELDS, n_sub=N_SUB, hi=LAM_PIECES[-1],
    note=("#: (time piece, field) -> per lambda piece, per sub-piece, one coefficient matrix",
          *_tb.HISTORY_NOTE[1:]))

#: The table: ``BUILDER.build()``, ``.render()``, ``.compare()`` (the engine's methods). The
#: anchor series ``log_tau_p``, stored as 0 on the ln-lambda pieces, is compared there by the
#: engine's rule for a series that is identically zero in both tables.
BUILDER = engine.TableBuilder(
    spec=SPEC,
    file=engine.TableFile(
        "exact_force_table.py", "exact-force-table",
        title=("Chebyshev tables of the force-free end of contact of Eq. (10) (the grains' "
               f"reading): summary and history for 0 <= lambda <= {LAM_PIECES[-1]:g}."),
        provenance=("Built by zener_sym.exact.force_table_build from scipy {scipy} "
                    f"solves (exact.force_end.solve) at rtol {RTOL:g}; `zener-sym regen --check "
                    "exact-force-table` rebuilds and compares numerically."),
        summary_note="stored series -> one tuple of Chebyshev coefficients per lambda piece"),
    sample=sample, digest=digest, history=HISTORY)

# the builder's methods under the names the table commands and tests call
build_tables, render, compare = BUILDER.build, BUILDER.render, BUILDER.compare
as_tables = BUILDER.as_tables
