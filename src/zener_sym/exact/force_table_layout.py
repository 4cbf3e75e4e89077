"""The time maps of the force-free end's Chebyshev tables.

Shared by the offline builder (:mod:`zener_sym.exact.force_table_build`) and the runtime
(:mod:`zener_sym.exact.force_table`). The maps have no constants of their own: the generated
file describes its lambda pieces once (``TABLE_PIECES``, ``numerics.cheb_table.TableSpec``) and
its history once (``TIME_PIECES``, ``HISTORY_KEYS``, ``N_SUB``, ``HISTORY_TO``, written by the
engine), so no layout class repeats them. The maps are described in the builder's docstring.
"""
from __future__ import annotations

import numpy as np

from ..typing import FloatArray

__all__ = ["recovery_z_end", "time_of"]


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
