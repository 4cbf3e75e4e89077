"""The layout of the force-free end's Chebyshev tables: lambda pieces, their variable and the
time maps of the history.

Shared by the offline builder (:mod:`zener_sym.exact.force_table_build`, which fixes the
constants and writes them into ``generated/exact_force_table.py``) and the runtime
(:mod:`zener_sym.exact.force_table`, which reads them back with :meth:`ForceLayout.of`), as
:mod:`.table_layout` is for the plate's; the maps are described in the builder's docstring.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from ..numerics.cheb_table import WrittenConstants
from ..typing import FloatArray

__all__ = ["ForceLayout", "recovery_z_end", "time_of"]


@dataclasses.dataclass(frozen=True)
class ForceLayout(WrittenConstants):
    """The constants that fix where each coefficient of the force-end tables applies (named as
    in the generated module)."""

    #: Breakpoints of the lambda pieces (summary and history).
    LAM_PIECES: tuple[float, ...]
    #: Pieces starting at or above this lambda use ln(lambda) as their variable, below
    #: sqrt(lambda).
    LOG_FROM: float
    #: Sub-pieces (equal parts of the reduced time y) per time piece.
    N_SUB: dict[str, int]
    #: The stored summary series, in order.
    SUMMARY_KEYS: tuple[str, ...]
    #: The time pieces, in the order of time.
    TIME_PIECES: tuple[str, ...] = ("C", "R")
    #: The tabulated history fields: f (delta's log-part) and v = delta'.
    HISTORY_KEYS: tuple[str, ...] = ("f", "v")


def recovery_z_end(tau_dc: float | FloatArray, tau_d: float | FloatArray,
                   tau_p: float | FloatArray) -> FloatArray:
    """z at tau_d of the recovery map tau = tau_P - (tau_P - tau_dc) z^2 (z = 1 at tau_dc).

    Parameters
    ----------
    tau_dc, tau_d : float or ndarray
        End of compression and the force-free end.
    tau_p : float or ndarray
        The plate's end of contact (delta = 0) of the same trajectory.

    Returns
    -------
    ndarray
        z at tau_d, in [0, 1].
    """
    with np.errstate(invalid="ignore", divide="ignore"):
        # clipped at 0: at lambda = 0 tau_d = tau_P, each to rounding
        z: FloatArray = np.sqrt(np.maximum(tau_p - tau_d, 0.0) / (tau_p - tau_dc))
        return z


def time_of(piece: str, y: FloatArray, tau_dc: float | FloatArray, tau_d: float | FloatArray,
            tau_p: float | FloatArray, log_piece: bool) -> FloatArray:
    """tau at the reduced time y in [0, 1] of time piece ``piece``.

    C: tau = tau_dc y^2; R on a log piece: tau linear in y from tau_dc to tau_d; R below:
    tau = tau_P - (tau_P - tau_dc) z^2 with z linear in y from 1 to ``recovery_z_end``.

    Parameters
    ----------
    piece : str
        "C" or "R".
    y : ndarray
        Reduced times in [0, 1].
    tau_dc, tau_d, tau_p : float or ndarray
        End of compression, force-free end and the plate's end of contact.
    log_piece : bool
        Whether lambda lies on a ln-lambda piece.

    Returns
    -------
    ndarray
        tau, y's shape.
    """
    if piece == "C":
        t: FloatArray = tau_dc * y * y
    elif log_piece:
        t = tau_dc + (tau_d - tau_dc) * y
    else:
        z = 1.0 - (1.0 - recovery_z_end(tau_dc, tau_d, tau_p)) * y
        t = tau_p - (tau_p - tau_dc) * z * z
    return t
