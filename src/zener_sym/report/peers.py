"""Peers: the granular literature's e(v) forms and the Approx-ViscoElastic-CoR toolbox, measured
against the exact model with the end-of-contact criterion each one assumes.

In the literature the expansion variable is x = beta v^{1/5} with beta = (3/2) A (rho/m_eff)^{2/5}
(Schwager & Poeschel 2008; Mueller & Poeschel 2011), i.e. x = (3/2) lambda with Zener's
lambda = A (rho/m_eff)^{2/5} v^{1/5} (``zener_sym.derivation.viscoelastic``); the check is that
C1 x = c1 lambda with this package's c1 = (4/5)(5/4)^{8/5} B(8/5, 1/2) = 1.5 x 1.15344...

Each peer is measured by the relative error of e on lambda = 0.02, 0.04, ..., 5 (the grid of the
toolbox run) and, for the formulas, also on 40 geometric points from 1e-4 to 0.02; "holds to tol
up to lambda*" means every grid point with lambda <= lambda* is within tol. The table in
docs/viscoelastic.md is the artefact ``peers`` of ``zener-sym regen``.
"""
from __future__ import annotations

import csv
import io
from collections.abc import Callable
from dataclasses import dataclass
from importlib import resources

import numpy as np

from ..api import summary
from ..typing import FloatArray

__all__ = ["Peer", "PeerRow", "GRID", "TOLS", "peers", "measure", "markdown", "update_doc"]

#: The lambda grid of the comparison (the toolbox run uses the same).
GRID: FloatArray = np.round(np.arange(1, 251) * 0.02, 10)
#: Below it, for the peers that are formulas: 40 points from 1e-4 to 0.02 (geometric).
FINE: FloatArray = np.geomspace(1e-4, 0.02, 41)[:-1]
TOLS: tuple[float, ...] = (1e-2, 1e-3, 1e-6)

_C1_LIT, _C2_LIT = 1.15344, 0.79826  # Ramirez et al. 1999 (gamma_1, gamma_2 in x = beta v^(1/5))
_PADE_NUM = (1.0, 0.501086)  # Mueller & Poeschel 2011, [1/4] Pade in v* = sqrt(x)
_PADE_DEN = (1.0, 0.501086, 1.15345, 0.577977, 0.532178)


@dataclass
class Peer:
    """A published or shipped way to get e(lambda).

    ``criterion``: the end of contact the peer assumes ("delta": xi = 0, "force": force-free).
    ``e``: callable lambda array -> e array (None: this package's series model, measured by
    :func:`measure` itself). ``source``: where the formula or values come from.
    """

    name: str
    source: str
    criterion: str
    e: Callable[[FloatArray], FloatArray] | None
    table: bool = False  # values exist on GRID only (the toolbox run)


def _pade(lam: FloatArray) -> FloatArray:
    vs = np.sqrt(1.5 * lam)
    return np.polyval(_PADE_NUM[::-1], vs) / np.polyval(_PADE_DEN[::-1], vs)


def _toolbox_rows() -> dict[str, FloatArray]:
    text = (resources.files("zener_sym") / "data" / "peers_toolbox.csv").read_text("utf-8")
    rows = [r for r in csv.reader(io.StringIO(text)) if r and not r[0].startswith("#")]
    head = rows[0]
    data = np.array([[float(x) for x in r] for r in rows[1:]])
    return {h: data[:, i] for i, h in enumerate(head)}


def _from_table(col: str) -> Callable[[FloatArray], FloatArray]:
    def e(lam: FloatArray) -> FloatArray:
        t = _toolbox_rows()
        if not np.array_equal(np.round(t["lam"], 10), np.round(lam, 10)):
            raise ValueError("the toolbox values exist on the grid GRID only")
        return t[col]

    return e


_TB = ("Approx-ViscoElastic-CoR (Chatterjee, James & Brogliato 2021, github.com/ChattAbhi/"
       "Approx-ViscoElastic-CoR, commit 9a8f7b6) run with Octave by tools/peers/toolbox_cor.m")


def peers() -> list[Peer]:
    """The peers, literature first, then the toolbox (values from data/peers_toolbox.csv)."""
    return [
        Peer("first order 1 - C1 x", "Ramirez, Poeschel, Brilliantov & Schwager, PRE 60, 4465 (1999): "
             "C1 = 1.15344 (Raman's term)", "delta", lambda lam: 1 - _C1_LIT * 1.5 * lam),
        Peer("second order 1 - C1 x + C2 x^2", "Ramirez et al. (1999): C1 = 1.15344, C2 = 0.79826",
             "delta", lambda lam: 1 - _C1_LIT * 1.5 * lam + _C2_LIT * (1.5 * lam) ** 2),
        Peer("[1/4] Pade in v* = x^(1/2)", "Mueller & Poeschel, PRE 84, 021302 (2011), coefficients "
             "0.501086 / 0.501086, 1.15345, 0.577977, 0.532178 as reproduced in a public getA.py",
             "force", _pade),
        Peer("toolbox numericCOR", _TB + ": direct ode45 integration, default tolerances (its "
             "contact ends at u = 0)", "delta", _from_table("numeric"), True),
        Peer("toolbox ord1approx", _TB + ": 1 - gamma C0", "delta", _from_table("ord1"), True),
        Peer("toolbox ord2schw-pos", _TB + ": 1 - gamma C0 - gamma^2 C2, C2 from Schwager & "
             "Poeschel's 0.7982665553", "delta", _from_table("ord2sp"), True),
        Peer("toolbox ord2approx (default)", _TB + ": second-order expansion with approximated "
             "coefficient integrals", "delta", _from_table("ord2approx"), True),
        Peer("zener-sym series, rtol 1e-6", "this package: small-lambda series (17 terms) / "
             "asymptotics, refuses 0.39 < lambda < 40", "delta", None),
        Peer("zener-sym series, force end", "this package: series in lambda^(1/2) (20 terms), "
             "lambda <= 0.16", "force", None),
    ]


def _holds(err: FloatArray, grid: FloatArray, tol: float) -> tuple[float, bool]:
    """(largest lambda* with every grid point <= lambda* within tol, whether that is the whole grid)."""
    bad = np.nonzero(~(err <= tol))[0]
    if len(bad) == 0:
        return float(grid[-1]), True
    return (float(grid[bad[0] - 1]) if bad[0] > 0 else 0.0), False


#: One measured peer: (peer, {tol: (lambda*, whether that is the whole grid)}, largest error,
#: smallest lambda measured).
PeerRow = tuple[Peer, dict[float, tuple[float, bool]], float, float]


def measure() -> list[PeerRow]:
    """Rows ``(peer, {tol: (lambda*, whole_grid)}, max_err, smallest_lambda)`` against the exact
    model: formulas on FINE + GRID, the toolbox on GRID; the series model where it answers."""
    full = np.concatenate([FINE, GRID])
    ref = {end: np.asarray(summary(full, model="exact", contact_end=end).e) for end in ("delta", "force")}
    rows: list[PeerRow] = []
    for p in peers():
        sel = slice(len(FINE), None) if p.table else slice(None)
        grid = full[sel]
        if p.e is None:  # the series model, on its small-lambda range (it refuses beyond)
            end = "force" if "force" in p.name else "delta"
            grid = grid[grid <= (0.16 if end == "force" else 0.39)]
            e = np.asarray(summary(grid, model="series", contact_end=end).e)
        else:
            e = np.asarray(p.e(grid), dtype=float)
        err = np.abs(e / ref[p.criterion][sel][:len(grid)] - 1)
        holds = {tol: _holds(err, grid, tol) for tol in TOLS}
        rows.append((p, holds, float(np.max(err)), float(grid[0])))
    return rows


def _fmt(h: tuple[float, bool], first: float) -> str:
    lam, whole = h
    if lam == 0.0:
        return f"< {first:.2g}"
    return f"{lam:.3g}" + (" (all)" if whole else "")


def markdown(rows: list[PeerRow] | None = None) -> str:
    """The peers table as markdown (deterministic for fixed inputs)."""
    rows = measure() if rows is None else rows
    out = ["| peer | end of contact | holds to 1% for lambda up to | to 0.1% | to 1e-6 | largest error | measured on |",
           "|---|---|---|---|---|---|---|"]
    for p, holds, worst, first in rows:
        span = ("0.02..5 (toolbox grid)" if p.table else
                ("1e-4..0.39 (where it answers)" if p.e is None and "force" not in p.name else
                 "1e-4..0.16 (where it answers)" if p.e is None else "1e-4..5"))
        out.append(f"| {p.name} | {'force-free' if p.criterion == 'force' else 'delta = 0'} | "
                   + " | ".join(_fmt(holds[t], first) for t in TOLS) + f" | {worst:.2g} | {span} |")
    out.append("")
    out.append("Sources:")
    out.append("")
    for p, *_ in rows:
        out.append(f"- {p.name}: {p.source}.")
    return "\n".join(out) + "\n"


_BEGIN, _END = "<!-- peers:begin (zener-sym regen peers) -->", "<!-- peers:end -->"


def update_doc(text: str, table: str) -> str:
    """``text`` with the block between the peers markers replaced by ``table``."""
    i, j = text.index(_BEGIN) + len(_BEGIN), text.index(_END)
    return text[:i] + "\n" + table + text[j:]

