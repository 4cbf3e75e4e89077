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

__all__ = ["ForceLayout", "piece_variable", "recovery_z_end", "time_of"]


@dataclasses.dataclass(frozen=True)
class ForceLayout:
    """The constants that fix where each coefficient of the force-end tables applies (named as
    in the generated module)."""

    #: Breakpoints of the lambda pieces (summary and history).
    LAM_PIECES: tuple
    #: Pieces starting at or above this lambda use ln(lambda) as their variable, below
    #: sqrt(lambda).
    LOG_FROM: float
    #: Sub-pieces (equal parts of the reduced time y) per time piece.
    N_SUB: dict
    #: The stored summary series, in order.
    SUMMARY_KEYS: tuple
    #: The time pieces, in the order of time.
    TIME_PIECES: tuple = ("C", "R")
    #: The tabulated history fields: f (delta's log-part) and v = delta'.
    HISTORY_KEYS: tuple = ("f", "v")

    @classmethod
    def of(cls, module) -> "ForceLayout":
        """The layout written into a generated table module (its upper-case names)."""
        return cls(**{f.name: getattr(module, f.name) for f in dataclasses.fields(cls)})

    def assignments(self) -> list[str]:
        """``NAME = value`` lines of a generated module, in field order (read back by ``of``)."""
        return [f"{f.name} = {getattr(self, f.name)!r}" for f in dataclasses.fields(self)]


def piece_variable(lam, log_piece):
    """The Chebyshev variable of a lambda piece: ln lambda (log pieces) or sqrt(lambda)."""
    lam = np.asarray(lam, dtype=float)
    with np.errstate(divide="ignore"):
        return np.where(log_piece, np.log(np.where(log_piece, lam, 1.0)), np.sqrt(lam))


def recovery_z_end(tau_dc, tau_d, tau_p):
    """z at tau_d of the recovery map tau = tau_P - (tau_P - tau_dc) z^2 (z = 1 at tau_dc)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        # clipped at 0: at lambda = 0 tau_d = tau_P, each to rounding
        return np.sqrt(np.maximum(tau_p - tau_d, 0.0) / (tau_p - tau_dc))


def time_of(piece: str, y, tau_dc, tau_d, tau_p, log_piece):
    """tau at the reduced time y in [0, 1] of time piece ``piece``: C, tau = tau_dc y^2; R on a
    log piece, tau linear in y from tau_dc to tau_d; R below, tau = tau_P - (tau_P - tau_dc) z^2
    with z linear in y from 1 to ``recovery_z_end``."""
    if piece == "C":
        return tau_dc * y * y
    if log_piece:
        return tau_dc + (tau_d - tau_dc) * y
    z = 1.0 - (1.0 - recovery_z_end(tau_dc, tau_d, tau_p)) * y
    return tau_p - (tau_p - tau_dc) * z * z
