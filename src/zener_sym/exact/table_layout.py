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
import numpy.typing as npt

from ..numerics.cheb_table import WrittenConstants, parse_array
from ..typing import FloatArray, RealArrayLike

__all__ = ["Layout", "lin_log", "parse_array"]  # parse_array: the engine's, named here too


@dataclasses.dataclass(frozen=True)
class Layout(WrittenConstants):
    """The constants that fix where each coefficient of the exact tables applies.

    Field names are the names the generated table module uses for them.
    """

    #: Breakpoints of the lambda pieces.
    LAM_PIECES: tuple[float, ...]
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
    N_SUB: dict[str, int]
    #: The time pieces, in the order of time (a point's piece index counts in this order).
    TIME_PIECES: tuple[str, ...] = ("C", "A", "M", "B")
    #: The tabulated history fields: f (delta's log-part) and the impulse I.
    HISTORY_KEYS: tuple[str, ...] = ("f", "I")

    def split_time(self, lam: RealArrayLike, log_piece: bool | npt.NDArray[np.bool_],
                   tau_dc: float | FloatArray, tau_w0: float | FloatArray) -> FloatArray:
        """tau_s, the end of time piece A and the start of piece M.

        tau_w0 for lambda <= LOG_FROM (no piece M), tau_dc + lambda (S_ORBIT + S_TRANSIENT
        lambda^(-5/3)) above.

        Parameters
        ----------
        lam : array_like
            lambda (Eq. 11).
        log_piece : bool or ndarray of bool
            Whether lambda lies on a ln-lambda piece (above LOG_FROM).
        tau_dc, tau_w0 : float or ndarray
            End of compression and the time where w = 1 - I vanishes.

        Returns
        -------
        ndarray
            tau_s, the broadcast shape.
        """
        lam_a = np.asarray(lam, dtype=float)
        with np.errstate(divide="ignore"):
            big = np.where(log_piece, lam_a, 1.0)
            return np.where(log_piece, tau_dc + big * (self.S_ORBIT + self.S_TRANSIENT
                                                       * big ** (-5.0 / 3.0)), tau_w0)

    def map_params(self, piece: str, lam: RealArrayLike, log_piece: bool | npt.NDArray[np.bool_],
                   tau_dc: float | FloatArray, tau_s: float | FloatArray,
                   tau_w0: float | FloatArray) -> tuple[float | FloatArray, ...]:
        """(start, end, c1, c2, c3) of the logarithmic-linear map ``lin_log`` of piece A or M.

        Parameters
        ----------
        piece : str
            "A" or "M" (any other name is taken as "M").
        lam : array_like
            lambda (Eq. 11).
        log_piece : bool or ndarray of bool
            Whether lambda lies on a ln-lambda piece.
        tau_dc, tau_s, tau_w0 : float or ndarray
            End of compression, ``split_time`` and the time where w vanishes.

        Returns
        -------
        tuple of float or ndarray
            The five arguments after tau of ``lin_log``.
        """
        lam_a = np.asarray(lam, dtype=float)
        inf = np.full(lam_a.shape, np.inf)
        if piece == "A":
            with np.errstate(divide="ignore"):
                c1 = self.C_STRETCH * np.where(
                    log_piece, (self.LOG_FROM / np.where(log_piece, lam_a, 1.0)) ** (2.0 / 3.0),
                    1.0)
            return tau_dc, tau_s, c1, np.where(log_piece, inf, self.C_END * (1.0 + lam_a)), inf
        return tau_s, tau_w0, inf, lam_a, lam_a


def lin_log(tau: float | FloatArray, start: float | FloatArray, end: float | FloatArray,
            c1: float | FloatArray, c2: float | FloatArray,
            c3: float | FloatArray) -> FloatArray:
    """Reduced time y in [0, 1] of time piece A or M on [start, end].

    u = ln(1 + (tau - start)/c1) + (tau - start)/c3 - ln(1 + (end - tau)/c2), normalised
    (c = inf drops a term). The logarithms resolve a fast start (the relaxation after tau_dc,
    scale c1) and a change of regime at the end (where w -> 0, scale c2); the linear term the
    orbit's steady decay (time scale c3 = lambda).

    Parameters
    ----------
    tau : float or ndarray
        Times in [start, end].
    start, end, c1, c2, c3 : float or ndarray
        The map's constants (``Layout.map_params``).

    Returns
    -------
    ndarray
        y, the broadcast shape.
    """
    span = end - start
    u0, u1 = -np.log1p(span / c2), np.log1p(span / c1) + span / c3
    u = np.log1p((tau - start) / c1) + (tau - start) / c3 - np.log1p((end - tau) / c2)
    y: FloatArray = (u - u0) / (u1 - u0)
    return y
