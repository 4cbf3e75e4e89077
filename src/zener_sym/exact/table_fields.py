"""The summary fields of the exact tables from their stored series, and their derivatives in
lambda: the physics both exact instances share (the plate's end of contact, :mod:`.table`, and
the force-free end, :mod:`.force_table`).

Each instance stores its own forms of the fields (ln tau_d, ln e, and int_F2 or its log, xi or
xi / lambda) and turns them into tau_d, e, F_m, int_F2 and xi (its ``_core``); what follows from
those is written here once: the summary's dict, d(field)/d(lambda) with the e/xi switch, and
the logarithmic quantities the inverses solve for.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping

import numpy as np

from ..numerics.cheb_table import SummaryTable
from ..typing import FloatArray, RealArrayLike

__all__ = ["DERIVATIVE_FIELDS", "QUANTITIES", "summary_fields", "field_derivative",
           "log_quantity"]

#: Summary fields the tables' ``summary_derivative`` differentiates.
DERIVATIVE_FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                     "int_F2", "xi")


def summary_fields(lam: FloatArray, v: Mapping[str, FloatArray]) -> dict[str, FloatArray]:
    """Every summary field (``models.SUMMARY_FIELDS``) from an instance's values.

    Parameters
    ----------
    lam : ndarray
        lambda (Eq. 11).
    v : mapping
        delta_m, tau_dc, tau_d, e, F_m, int_F2 and xi at lam (the instance's ``_core``).

    Returns
    -------
    dict of str to ndarray
        "lam" and the summary fields; tau_dr = tau_d - tau_dc, eta = tau_dr / tau_dc (Eq. 76)
        and the impulse 1 + e.
    """
    tau_dr = v["tau_d"] - v["tau_dc"]
    return {"lam": lam, "delta_m": v["delta_m"], "tau_dc": v["tau_dc"], "tau_d": v["tau_d"],
            "tau_dr": tau_dr, "eta": tau_dr / v["tau_dc"], "e": v["e"], "F_m": v["F_m"],
            "impulse": 1.0 + v["e"], "int_F2": v["int_F2"], "xi": v["xi"]}


def field_derivative(field: str, v: Mapping[str, FloatArray], dv: Mapping[str, FloatArray],
                     dxi_balance: FloatArray, dF_m: FloatArray,
                     dint_F2: FloatArray) -> FloatArray:
    """d(field)/d(lambda) from the stored series' derivatives and the chain rule.

    The e/xi switch: while xi < 1/2, xi' from the energy balance (``dxi_balance``: no
    cancellation as lambda -> 0) and e' = -xi' / (2 e); above, 2 int_F2 and 2 lambda int_F2'
    nearly cancel (by 1e4 at lambda = 3), so e' = e (ln e)' from ln e's series and
    xi' = -2 e e'. The same switch as the values' (``solver.restitution``).

    Parameters
    ----------
    field : str
        One of ``DERIVATIVE_FIELDS`` (checked by the caller).
    v : mapping
        The instance's values (``summary_fields``' input).
    dv : mapping
        d(stored series)/d(lambda): at least delta_m, tau_dc, log_tau_d and log_e.
    dxi_balance : ndarray
        xi' from the energy balance, in the instance's stored form of xi.
    dF_m, dint_F2 : ndarray
        F_m' and int_F2' in the instance's stored forms.

    Returns
    -------
    ndarray
        The derivative, lambda's shape.
    """
    small = v["xi"] < 0.5
    de = np.where(small, -dxi_balance / (2.0 * v["e"]), v["e"] * dv["log_e"])
    if field in ("e", "impulse"):
        return de
    if field == "xi":
        dxi: FloatArray = np.where(small, dxi_balance, -2.0 * v["e"] * de)
        return dxi
    dtau_d = v["tau_d"] * dv["log_tau_d"]
    if field == "tau_dr":
        return dtau_d - dv["tau_dc"]
    if field == "eta":
        eta: FloatArray = (dtau_d * v["tau_dc"] - v["tau_d"] * dv["tau_dc"]) / v["tau_dc"] ** 2
        return eta
    own = {"tau_d": dtau_d, "F_m": dF_m, "int_F2": dint_F2, "delta_m": dv["delta_m"],
           "tau_dc": dv["tau_dc"]}
    return own[field]


#: The quantities the inverses solve for (``exact.inverse``).
QUANTITIES = ("e", "tau_d", "xi")


def log_quantity(table: SummaryTable, lam: RealArrayLike, quantity: str, xi_series: str,
                 ln_xi: Callable[[FloatArray, FloatArray], FloatArray],
                 ) -> tuple[FloatArray, FloatArray]:
    """(ln q, d ln q / d lambda) from the one series q needs (:meth:`SummaryTable.one`), for
    :mod:`zener_sym.exact.inverse`: e and tau_d from the stored log_e and log_tau_d; xi =
    c lambda s(lambda) from its series s, so d ln xi / d lambda = 1 / lambda + s' / s.

    Parameters
    ----------
    table : SummaryTable
        An exact instance's summary.
    lam : array_like
        lambda (Eq. 11) in the table's range (> 0 for xi); flattened.
    quantity : str
        One of ``QUANTITIES``.
    xi_series : str
        The stored series s of xi.
    ln_xi : callable(lambda, s) -> ndarray
        ln xi in the form the table's numbers were made with.

    Returns
    -------
    tuple of ndarray
        ln q and d ln q / d lambda, 1-D.

    Raises
    ------
    ValueError
        For an unknown quantity or lambda outside the table's range.
    """
    lam1 = np.asarray(lam, dtype=float).reshape(-1)
    if quantity in ("e", "tau_d"):
        return table.one(lam1, f"log_{quantity}")
    if quantity != "xi":
        raise ValueError(f"unknown quantity {quantity!r}; allowed: {', '.join(QUANTITIES)}")
    s, ds = table.one(lam1, xi_series)
    return ln_xi(lam1, s), 1.0 / lam1 + ds / s
