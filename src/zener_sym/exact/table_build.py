"""Offline builder of the Chebyshev tables behind the fast exact model (``generated/exact_table.py``).

Every summary field of Eq. (10) is an analytic function of lambda, and the history, written in
suitable time variables, is analytic in (time variable, lambda). We sample the scipy exact solver
(:mod:`zener_sym.exact.solver`, rtol 1e-13) at Chebyshev points of the first kind on each lambda piece of
``LAM_PIECES`` and store Chebyshev coefficients (15 significant digits), trimmed where the
trailing ones fall below ``TRIM`` of the largest. :mod:`zener_sym.exact.table` evaluates them.

Time pieces of the history (y in [0, 1] maps to x = 2y - 1 in [-1, 1]):

``C`` compression, tau = tau_dc y^2: delta = tau exp(f), f analytic because delta is analytic in
    sqrt(tau) with delta ~ tau at the start and analytic in tau at the maximum.
``A`` recovery until the sphere is at rest (w = 1 - I = 0 at tau_w0), tau = tau_dc + c (e^{beta y} - 1)
    with beta = log(1 + (tau_w0 - tau_dc)/c): the exponential stretch resolves both the fast
    relaxation after tau_dc and the slow decay (time scale lambda) of large lambda. f = log delta.
``B`` the rest of the recovery, tau = tau_d - D y^2, D = tau_d - tau_w0: delta = (tau_d - tau) exp(f),
    analytic in sqrt(tau_d - tau) at the end of contact.

Splitting the recovery where w = 0 matters: for large lambda delta changes regime there (from the
quasi-static delta ~ (w/lambda)^{2/3} to the linear end e (tau_d - tau)); a single piece converges
slowly. The impulse I is tabulated directly on each piece (absolute accuracy).

Large lambda (pieces above ``LOG_FROM``, summary only; the Chebyshev variable is ln lambda).
With delta = lambda^-4 D, w = lambda^-5 W, tau = lambda T, Eq. (10) becomes the lambda = 1 system
D' = W - D^{3/2}, W' = -D^{3/2} started at W = lambda^5: every lambda runs along one universal
orbit of that system once its loading transient has died out (the orbit attracts at the rate
1.5 lambda delta^{1/2}). So a node integrates only the early part (``solver.solve_early``: to
tau_dc plus ``MATCH_DECAYS`` e-foldings of that transient), and the rest of its contact is read
off one solve at ``LAM_U`` (the orbit in that lambda's variables), matched at equal W:
tau_d = tau_M + (lambda / LAM_U) (tau_d,U - tau_U(W_M)). The same orbit gives e = C lambda^-5
with C = e_U LAM_U^5 (the end of the orbit; the review saw e lambda^5 settle above lambda = 3),
and the energy balance gives int_F2 = (1 - e^2) / (2 lambda). The build stays cheap: one long
solve instead of one per node.

The node values come from a floating-point integrator, so the text is not bit-reproducible across
machines: the table is NOT in ``codegen.BUILDERS``; ``zener-sym exact-table --check`` rebuilds it
and compares numerically (see ``CHECK_RTOL``).
"""
from __future__ import annotations

import functools
import hashlib
import pathlib

import numpy as np

#: Breakpoints of the lambda pieces: the summary table covers [0, 1000], the history [0, 5].
LAM_PIECES = (0.0, 1.0, 2.0, 3.5, 5.0, 10.0, 25.0, 80.0, 300.0, 1000.0)
#: Pieces starting at or above this lambda use ln(lambda) as their Chebyshev variable and carry
#: the summary only (their nodes come from the universal orbit, see the module docstring).
LOG_FROM = 5.0
#: lambda of the one long solve that gives the universal orbit (above LAM_PIECES[-1]: every
#: node's W_M = lambda^5 w_M must lie on the part of the orbit past its own transient).
LAM_U = 1050.0
#: e-foldings of the loading transient a large-lambda node integrates past tau_dc before matching.
MATCH_DECAYS = 40.0
#: Chebyshev points per lambda piece.
N_LAM = 22
#: Chebyshev points per time piece C, A, B.
N_TIME = {"C": 28, "A": 44, "B": 28}
#: Time scale of the exponential stretch of piece A.
C_STRETCH = 1.0
#: Tolerance of the scipy solves at the nodes (their accuracy is about 1e-12).
RTOL = 1e-13
#: Trailing coefficients below this fraction of an array's largest are dropped (noise level).
TRIM = 1e-14
#: ``--check`` passes when every rebuilt coefficient is within this of the stored one (relative
#: to the largest coefficient of its array).
CHECK_RTOL = 1e-10

SUMMARY_KEYS = ("delta_m", "tau_dc", "log_tau_d", "log_e", "int_F2", "rest_over_lam")
HISTORY_KEYS = ("f", "I")
TIME_PIECES = ("C", "A", "B")


def cheb_nodes(n: int) -> np.ndarray:
    """Chebyshev points of the first kind, x_k = cos(pi (k + 1/2) / n), k = 0..n-1."""
    return np.cos(np.pi * (np.arange(n) + 0.5) / n)


def cheb_coefficients(values: np.ndarray, axis: int = 0) -> np.ndarray:
    """Coefficients of the interpolant through values at ``cheb_nodes(n)`` along ``axis`` (DCT-II)."""
    values = np.moveaxis(np.asarray(values, dtype=float), axis, 0)
    n = values.shape[0]
    k = np.arange(n)
    m = np.cos(np.pi * np.outer(k, k + 0.5) / n) * (2.0 / n)
    m[0] *= 0.5
    return np.moveaxis(np.tensordot(m, values, axes=1), 0, axis)


def time_nodes(piece: str, y: np.ndarray, tau_dc: float, tau_w0: float, tau_d: float) -> np.ndarray:
    """tau at the reduced time y in [0, 1] of one time piece (see the module docstring)."""
    if piece == "C":
        return tau_dc * y * y
    if piece == "A":
        beta = np.log1p((tau_w0 - tau_dc) / C_STRETCH)
        return tau_dc + C_STRETCH * np.expm1(beta * y)
    return tau_d - (tau_d - tau_w0) * y * y


def _rest_time(sol) -> float:
    """tau_w0 in (tau_dc, tau_d) where the relative velocity w = 1 - I vanishes (w' = -F < 0)."""
    from scipy.optimize import brentq

    def w(t):
        return float(sol.history(np.array([t]))["velocity"][0])

    return brentq(w, sol.tau_dc, sol.tau_d, xtol=1e-15, rtol=1e-15, maxiter=200)


def is_log_piece(a: float) -> bool:
    """True for a lambda piece [a, b] tabulated in ln(lambda) (summary only)."""
    return a >= LOG_FROM


@functools.cache
def universal_orbit():
    """The universal orbit as the solution at LAM_U, its rest time and C = e lambda^5."""
    from . import solver as exact

    U = exact.solve(LAM_U, rtol=RTOL)
    return U, _rest_time(U), -U.w_end * LAM_U**5


def large_node(lam: float) -> dict:
    """Summary values of one large lambda from its early part and the universal orbit."""
    from scipy.optimize import brentq

    from . import solver as exact

    U, tau_w0_U, C = universal_orbit()
    rate = 1.5 * lam * lam ** (-1.0 / 3.0)  # 1.5 lambda delta^{1/2} with delta ~ lambda^{-2/3}
    r = exact.solve_early(lam, MATCH_DECAYS / rate, rtol=RTOL)
    target = (lam / LAM_U) ** 5 * r["w"]  # the same W = lambda^5 w on the orbit

    def w_U(t):
        return float(U.history(np.array([t]))["velocity"][0]) - target

    t_U = brentq(w_U, U.tau_dc, tau_w0_U, xtol=1e-14, rtol=8.9e-16, maxiter=300)
    scale = lam / LAM_U  # tau = lambda T
    tau_d = r["tau"] + scale * (U.tau_d - t_U)
    tau_w0 = r["tau"] + scale * (tau_w0_U - t_U)
    e = C / lam**5
    return {"delta_m": r["delta_m"], "tau_dc": r["tau_dc"], "log_tau_d": np.log(tau_d),
            "log_e": np.log(e), "int_F2": (1.0 - e * e) / (2.0 * lam),
            "rest_over_lam": (tau_w0 - r["tau_dc"]) / lam}


def piece_nodes(a: float, b: float) -> np.ndarray:
    """The lambda nodes of the piece [a, b] (Chebyshev points in lambda or in ln lambda)."""
    x = cheb_nodes(N_LAM)
    if is_log_piece(a):
        return np.exp(np.log(a) + (np.log(b) - np.log(a)) * (x + 1.0) / 2.0)
    return a + (b - a) * (x + 1.0) / 2.0


def node_data(lam: float) -> dict:
    """Summary values and history samples of one lambda (lambda > 0: nodes never include 0)."""
    from . import solver as exact

    s = exact.solve(lam, rtol=RTOL)
    tau_w0 = _rest_time(s)
    out = {"delta_m": s.delta_m, "tau_dc": s.tau_dc, "log_tau_d": np.log(s.tau_d),
           "log_e": np.log(-s.w_end), "int_F2": s.int_F2,
           "rest_over_lam": (tau_w0 - s.tau_dc) / lam}
    for piece in TIME_PIECES:
        y = (cheb_nodes(N_TIME[piece]) + 1.0) / 2.0
        tau = time_nodes(piece, y, s.tau_dc, tau_w0, s.tau_d)
        h = s.history(tau)
        d = h["delta"]
        if piece == "C":
            f = np.log(d / tau)
        elif piece == "A":
            f = np.log(d)
        else:
            f = np.log(d / ((s.tau_d - tau_w0) * y * y))
        out[(piece, "f")] = f
        out[(piece, "I")] = h["impulse"]
    return out


def _trim(c: np.ndarray) -> np.ndarray:
    """Drop trailing rows/columns whose coefficients are all below TRIM of the largest."""
    big = np.abs(c) > TRIM * np.abs(c).max()
    if c.ndim == 1:
        return c[: np.nonzero(big)[0].max() + 1]
    rows = np.nonzero(big.any(axis=1))[0].max() + 1
    cols = np.nonzero(big.any(axis=0))[0].max() + 1
    return c[:rows, :cols]


def build_tables() -> dict:
    """All coefficients: {"summary": {key: [1-D per lambda piece]}, "history": {(piece, key): [2-D]}}.

    2-D arrays are indexed [time degree, lambda degree].
    """
    summary = {k: [] for k in SUMMARY_KEYS}
    history = {(p, k): [] for p in TIME_PIECES for k in HISTORY_KEYS}
    for a, b in zip(LAM_PIECES[:-1], LAM_PIECES[1:]):
        lams = piece_nodes(a, b)
        node = large_node if is_log_piece(a) else node_data
        data = [node(float(x)) for x in lams]
        for k in SUMMARY_KEYS:
            summary[k].append(_trim(cheb_coefficients(np.array([d[k] for d in data]))))
        if is_log_piece(a):
            continue
        for key in history:
            vals = np.array([d[key] for d in data]).T  # [time node, lambda node]
            c = cheb_coefficients(cheb_coefficients(vals, axis=0), axis=1)
            history[key].append(_trim(c))
    return {"summary": summary, "history": history}


def inputs_hash() -> str:
    """SHA-256 (16 hex digits) of this builder and the solver it samples."""
    here = pathlib.Path(__file__).resolve().parent
    h = hashlib.sha256()
    for name in ("table_build.py", "solver.py"):
        h.update(name.encode())
        h.update((here / name).read_bytes().replace(b"\r\n", b"\n"))
    return h.hexdigest()[:16]


def _fmt(a: np.ndarray, indent: str) -> str:
    if a.ndim == 1:
        return "(" + ", ".join(f"{float(v):.15g}" for v in a) + ",)"
    rows = [indent + "    " + _fmt(r, "") + "," for r in a]
    return "(\n" + "\n".join(rows) + "\n" + indent + ")"


def render(tables: dict | None = None) -> str:
    """Text of ``generated/exact_table.py``."""
    import scipy

    t = build_tables() if tables is None else tables
    lines = [
        '"""Chebyshev tables of the exact solution of Eq. (10): summary for 0 <= lambda <= '
        f'{LAM_PIECES[-1]:g}, history for 0 <= lambda <= {LOG_FROM:g}.\n',
        "GENERATED by `zener-sym exact-table`: DO NOT EDIT. Built by zener_sym.exact.table_build from",
        f"scipy {scipy.__version__} solves at rtol {RTOL:g}; `zener-sym exact-table --check` rebuilds and",
        "compares numerically (the node values come from a floating-point integrator, so the bytes",
        "are not reproducible across machines).\n",
        f"Inputs hash: {inputs_hash()}",
        '"""',
        f"INPUTS_HASH = {inputs_hash()!r}",
        f"LAM_PIECES = {LAM_PIECES!r}",
        f"LOG_FROM = {LOG_FROM!r}",
        f"C_STRETCH = {C_STRETCH!r}",
        "",
        "#: field -> one tuple of Chebyshev coefficients per lambda piece",
        "SUMMARY = {",
    ]
    for k in SUMMARY_KEYS:
        lines.append(f"    {k!r}: (")
        for c in t["summary"][k]:
            lines.append("        " + _fmt(c, "        ") + ",")
        lines.append("    ),")
    lines += ["}", "",
              "#: (time piece, field) -> one coefficient matrix [time degree][lambda degree] per lambda piece",
              "#: up to LOG_FROM",
              "HISTORY = {"]
    for key in sorted(t["history"]):
        lines.append(f"    {key!r}: (")
        for c in t["history"][key]:
            lines.append("        " + _fmt(c, "        ") + ",")
        lines.append("    ),")
    lines += ["}", ""]
    return "\n".join(lines)


def table_path() -> pathlib.Path:
    from ..codegen import generated_dir

    return generated_dir() / "exact_table.py"


def compare(stored: dict, fresh: dict) -> list[str]:
    """Differences beyond CHECK_RTOL between two tables, as readable lines (empty: they agree)."""
    bad = []
    for kind in ("summary", "history"):
        for key in fresh[kind]:
            for i, (c_new, c_old) in enumerate(zip(fresh[kind][key], stored[kind][key])):
                c_old = np.asarray(c_old, dtype=float)
                shape = tuple(max(p, q) for p, q in zip(c_new.shape, c_old.shape))
                a, b = np.zeros(shape), np.zeros(shape)
                a[tuple(slice(0, n) for n in c_new.shape)] = c_new
                b[tuple(slice(0, n) for n in c_old.shape)] = c_old
                err = np.abs(a - b).max() / np.abs(a).max()
                if not err <= CHECK_RTOL:
                    bad.append(f"{kind} {key} lambda piece {i}: relative difference {err:.2e} "
                               f"> {CHECK_RTOL:g}")
    return bad
