"""The time maps of the exact Chebyshev tables (the plate's end of contact).

The constants of the maps are shared by the offline builder (:mod:`zener_sym.exact.table_build`,
which fixes them and writes them into ``generated/exact_table.py``) and the runtime evaluator
(:mod:`zener_sym.exact.table`, which reads them back from that file with :meth:`Layout.of`): the
generated table is the single source of the constants the runtime uses, and the runtime never
imports the builder. The file describes its lambda pieces once, in ``TABLE_PIECES``
(``numerics.cheb_table.TableSpec``: the ln-lambda pieces start at its ``log_from``), and its
history once (``HISTORY_TO``, ``TIME_PIECES``, ``HISTORY_KEYS``, ``N_SUB``: the engine's
``numerics.cheb_table_history``); this class holds only the maps' own constants. The time
pieces and their maps are described in the builder's docstring.
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
    """The constants of the exact tables' time maps (beyond the description of their pieces).

    Field names are the names the generated table module uses for them.
    """

    #: Time scale of piece A's logarithmic stretch at tau_dc (see the builder).
    C_STRETCH: float
    #: lambda on a lambda piece: piece A's logarithmic stretch at tau_w0 has time scale
    #: C_END (1 + lambda).
    C_END: float
    #: lambda on a ln-lambda piece: tau_s = tau_dc + lambda (S_ORBIT + S_TRANSIENT lambda^(-5/3)).
    S_ORBIT: float
    S_TRANSIENT: float

    def split_time(self, lam: RealArrayLike, log_piece: bool | npt.NDArray[np.bool_],
                   tau_dc: float | FloatArray, tau_w0: float | FloatArray) -> FloatArray:
        """tau_s, the end of time piece A and the start of piece M.

        tau_w0 on the lambda pieces (no piece M), tau_dc + lambda (S_ORBIT + S_TRANSIENT
        lambda^(-5/3)) on the ln-lambda pieces.

        Parameters
        ----------
        lam : array_like
            lambda (Eq. 11).
        log_piece : bool or ndarray of bool
            Whether lambda lies on a ln-lambda piece.
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
                   tau_w0: float | FloatArray, log_from: float) -> tuple[float | FloatArray, ...]:
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
        log_from : float
            Where the ln-lambda pieces start (``TableSpec.log_from``): piece A's stretch there
            is C_STRETCH.

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
                    log_piece, (log_from / np.where(log_piece, lam_a, 1.0)) ** (2.0 / 3.0),
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
