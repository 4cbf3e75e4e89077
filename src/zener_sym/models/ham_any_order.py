"""The model ``ham``: the homotopy series to a chosen order, with Liao's convergence control c0.

Options (``zs.summary(lam, model="ham", order=2)``, ``zs.history(lam, tau, model="ham", ...)``):

order : int, default 1
    Order of the series. The paper's formulation (14) has orders 1 and 2 only: its order-3
    forcing is not integrable at pi/omega0 (``zener_sym.derivation.ham_higher``), and asking for
    more raises ValueError saying so. The strained-time formulation has orders 1 to 8.
c0 : float or None, default None
    Liao's convergence-control parameter (the paper's homotopy is c0 = -1). None picks the
    minimiser of the averaged squared residual at that lambda and order
    (``zener_sym.ham.higher.optimal_c0``); the value used is reported on the summary as ``s.c0``
    (an extra attribute, not one of the summary fields).
formulation : "paper" (default) or "strained"
    The homotopy: the paper's (14), or the strained-time one of
    ``zener_sym.derivation.ham_strained`` (valid for lambda < 2.032131391).

``order=1, c0=-1`` (paper) is the first-order solution of ``ham1``. The continuation past
pi/omega0 in the paper's formulation is ham1's (zero force of the zeroth-order compression).
docs/ham_convergence.md measures both formulations against the exact solution.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..ham import higher
from ..typing import FloatArray
from .base import FieldValues, Model, computed_bound, register

_SUMMARY = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2",
            "xi")


def _opts(options: Mapping[str, Any]) -> tuple[int, float | None, str]:
    """The checked (order, c0, formulation); ValueError naming the allowed values."""
    formulation = higher.check_formulation(options.get("formulation", "paper"))
    order = higher.check_order(options.get("order", 1), formulation)
    c0 = options.get("c0")
    if c0 is not None:
        c0 = higher.check_c0(c0)
    return order, c0, formulation


class HamSeries(Model):
    """The model ``"ham"``: the HAM series to a chosen order (options: module docstring)."""

    name = "ham"
    description = ("HAM series to a chosen order with Liao's convergence control c0 (options "
                   "order, c0, formulation='paper' or 'strained'); spectral solution of each "
                   "order's linear problem")
    summary_fields = _SUMMARY
    history_fields = ("delta", "velocity", "force", "impulse")
    bound_reason = ("lam_crit = 2.44243892998...: omega0 of the auxiliary operator is real only "
                    "below it, Eq. (81); the strained formulation stops at 2.032131391")
    options = ("order", "c0", "formulation")
    # a family of models (order, c0, formulation) measured in docs/ham_convergence.md, and slow
    # with the default optimal c0: not a candidate of select_model
    in_envelopes = False

    @computed_bound
    def lam_bound(self) -> float:
        """lam_crit of the numpy runtime (emitted from the derivation), read when asked for."""
        from ..ham.runtime_numpy import LAM_CRIT

        bound: float = LAM_CRIT
        return bound

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        order, c0, formulation = _opts(options)
        rows = [higher.solve(float(x), order, c0, formulation) for x in lam]
        out = {f: np.array([r.summary()[f] for r in rows]) for f in
               ("delta_m", "tau_dc", "tau_d", "e", "F_m", "impulse", "int_F2")}
        out["tau_dr"] = out["tau_d"] - out["tau_dc"]
        out["eta"] = out["tau_dr"] / out["tau_dc"]
        out["xi"] = 2.0 * out["impulse"] - out["impulse"] ** 2
        out["c0"] = np.array([r.c0 for r in rows])  # reported: s.c0
        return out

    def _history(self, lam: FloatArray, tau: FloatArray, **options: Any) -> FieldValues:
        order, c0, formulation = _opts(options)
        out = {f: np.empty(tau.shape) for f in self.history_fields}
        for x in np.unique(lam):
            sel = lam == x
            h = higher.solve(float(x), order, c0, formulation).history(tau[sel])
            for f in out:
                out[f][sel] = h[f]
        return out


register(HamSeries())
