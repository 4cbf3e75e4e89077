"""The layout of the exact Chebyshev tables: lambda pieces, time pieces and their time maps.

One description shared by the offline builder (:mod:`zener_sym.exact.table_build`, which fixes
the constants and writes them into ``generated/exact_table.py``) and the runtime evaluator
(:mod:`zener_sym.exact.table`, which reads them back from that file with :meth:`Layout.of`): the
generated table is the single source of the constants the runtime uses, and the runtime never
imports the builder. The time pieces and their maps are described in the builder's docstring.
"""
from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["Layout", "lin_log", "parse_array"]


@dataclasses.dataclass(frozen=True)
class Layout:
    """The constants that fix where each coefficient of the exact tables applies.

    Field names are the names the generated table module uses for them.
    """

    #: Breakpoints of the lambda pieces.
    LAM_PIECES: tuple
    #: Pieces starting at or above this lambda use ln(lambda) as their Chebyshev variable.
    LOG_FROM: float
    #: The history tables end here.
    HISTORY_TO: float
    #: Time scale of piece A's logarithmic stretch at tau_dc (see the builder).
    C_STRETCH: float
    #: lambda <= LOG_FROM: piece A's logarithmic stretch at tau_w0 has time scale C_END (1 + lambda).
    C_END: float
    #: lambda > LOG_FROM: tau_s = tau_dc + lambda (S_ORBIT + S_TRANSIENT lambda^(-5/3)).
    S_ORBIT: float
    S_TRANSIENT: float
    #: Sub-pieces (equal parts of the reduced time y) per time piece.
    N_SUB: dict
    #: The time pieces, in the order of time (a point's piece index counts in this order).
    TIME_PIECES: tuple = ("C", "A", "M", "B")
    #: The tabulated history fields: f (delta's log-part) and the impulse I.
    HISTORY_KEYS: tuple = ("f", "I")

    @classmethod
    def of(cls, module) -> "Layout":
        """The layout written into a generated table module (its upper-case names)."""
        return cls(**{f.name: getattr(module, f.name) for f in dataclasses.fields(cls)})

    def assignments(self) -> list[str]:
        """``NAME = value`` lines of a generated module, in field order (read back by ``of``)."""
        return [f"{f.name} = {getattr(self, f.name)!r}" for f in dataclasses.fields(self)]

    def split_time(self, lam, log_piece, tau_dc, tau_w0):
        """tau_s, the end of piece A and start of piece M: tau_w0 for lambda <= LOG_FROM (no
        piece M), tau_dc + lambda (S_ORBIT + S_TRANSIENT lambda^(-5/3)) above."""
        lam = np.asarray(lam, dtype=float)
        with np.errstate(divide="ignore"):
            big = np.where(log_piece, lam, 1.0)
            return np.where(log_piece, tau_dc + big * (self.S_ORBIT + self.S_TRANSIENT
                                                       * big ** (-5.0 / 3.0)), tau_w0)

    def map_params(self, piece, lam, log_piece, tau_dc, tau_s, tau_w0):
        """(start, end, c1, c2, c3) of the logarithmic-linear map ``lin_log`` of piece A or M."""
        lam = np.asarray(lam, dtype=float)
        inf = np.full(lam.shape, np.inf)
        if piece == "A":
            with np.errstate(divide="ignore"):
                c1 = self.C_STRETCH * np.where(
                    log_piece, (self.LOG_FROM / np.where(log_piece, lam, 1.0)) ** (2.0 / 3.0), 1.0)
            return tau_dc, tau_s, c1, np.where(log_piece, inf, self.C_END * (1.0 + lam)), inf
        return tau_s, tau_w0, inf, lam, lam


def lin_log(tau, start, end, c1, c2, c3):
    """Reduced time y in [0, 1] on [start, end]: u = ln(1 + (tau - start)/c1) + (tau - start)/c3
    - ln(1 + (end - tau)/c2), normalised (c = inf drops a term). The logarithms resolve a
    fast start (the relaxation after tau_dc, scale c1) and a change of regime at the end (where
    w -> 0, scale c2); the linear term the orbit's steady decay (time scale c3 = lambda)."""
    span = end - start
    u0, u1 = -np.log1p(span / c2), np.log1p(span / c1) + span / c3
    u = np.log1p((tau - start) / c1) + (tau - start) / c3 - np.log1p((end - tau) / c2)
    return (u - u0) / (u1 - u0)


def parse_array(text: str) -> np.ndarray:
    """The 2-D array written as the string "rows cols v v ..." (the history coefficients)."""
    v = np.array(text.split(), dtype=float)
    return v[2:].reshape(int(v[0]), int(v[1]))
