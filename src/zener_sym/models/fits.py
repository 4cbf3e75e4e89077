"""``fits``: the paper's explicit fits and interpolations, as one model.

* delta_m: Eq. (24), delta_m^{-3/2} = lambda + (5/4)^{-3/5} (the interpolation behind k, Eq. 25);
* tau_d: Eq. (55), tau_H exp(0.23 lambda^1.80), with the paper's tau_H = 3.214;
* e: Eq. (80), the zeroth-order restitution exp(-pi beta/omega0) with k of Eq. (25) (the printed
  (80) carries (5/4)^{-1/3} where the derivation gives (5/4)^{-3/5}: the corrected form is used,
  see AUDIT.md);
* xi: Eq. (70), 1 - exp(-2.755 lambda);
* int_F2: the quadratic of Sec. 3.5, 1.78 - 2.79 lambda + 2.36 lambda^2 (the polynomial behind
  Eq. 77, xi = 2 lambda 1.78 at small lambda).

The fitted numbers are the paper's (inputs of its fits, not derivable); the functions are in
``zener_sym.models.formulas``. Valid below the bound of Eq. (81) (lambda < 2.4419...), where
Eq. (80) is real. The audit checks the paper's claims about each fit (AUDIT.md, claims
``eq24_5pct``, ``eq70_10pct_1pct``, ``eq80_to_1.8``).
"""
from __future__ import annotations

from typing import Any

import numpy as np

from ..typing import FloatArray, RealArrayLike
from . import formulas as fm
from .base import FieldValues, Model, register

__all__ = ["INT_F2_POLY", "int_F2_fit"]

#: Coefficients of the paper's quadratic for int F^2 (Sec. 3.5), constant term first.
INT_F2_POLY: tuple[float, float, float] = (1.78, -2.79, 2.36)


def int_F2_fit(lam: RealArrayLike) -> FloatArray:
    """The paper's 1.78 - 2.79 lambda + 2.36 lambda^2 (Sec. 3.5).

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), >= 0 (not checked).

    Returns
    -------
    numpy.ndarray
        The fitted int F^2 dtau, of the shape of ``lam``.
    """
    lam = np.asarray(lam, dtype=float)
    c0, c1, c2 = INT_F2_POLY
    return c0 + lam * (c1 + lam * c2)


class Fits(Model):
    """The model ``"fits"``: the paper's explicit fits, Eqs. (24), (55), (70), (80), Sec. 3.5."""

    name = "fits"
    description = ("the paper's fits: delta_m Eq. (24), tau_d Eq. (55), e Eq. (80), xi Eq. (70), "
                   "int F^2 quadratic of Sec. 3.5")
    summary_fields = ("lam", "delta_m", "tau_d", "e", "xi", "int_F2")
    history_fields = ()
    lam_bound = fm.LAM_CRIT
    bound_reason = "Eq. (80) is real only while k lambda^2 < 4 (Eq. 81)"

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        return {"delta_m": fm.delta_m_fit_24(lam), "tau_d": fm.tau_d_fit_55(lam), "e": fm.e0(lam),
                "xi": fm.xi_fit_70(lam), "int_F2": int_F2_fit(lam)}


register(Fits())
