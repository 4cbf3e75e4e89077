"""Pulse models that ignore (hertz, hunter, reed) or one-way couple (oneway) the plate.

* ``hertz``: the rigid half-space, i.e. the exact solution of Eq. (10) at lambda = 0 whatever
  lambda is given (lambda is ignored; every field is the lambda = 0 value).
* ``hunter``: Hunter's sine, delta = delta_m sin(Omega tau), F = A sin(Omega tau) (Eq. 52);
  ``reed``: Reed's F = delta_m^{3/2} sin^{3/2}(Omega tau) (Eq. 53); constants derived in
  ``zener_sym.models.formulas``. Both are symmetric pulses of a rigid half-space: lambda is ignored, and
  they give no restitution (e, xi): the pulse alone does not say what energy is lost.
* ``oneway``: the Hertz pulse drives the plate without feeling it: xi = 2 lambda int F_Hertz^2
  (the work of Eq. 74 in the scaling of Eq. 10), e = sqrt(1 - xi). It gives e, xi and the Hertz
  pulse's int_F2; valid while xi <= 1, i.e. lambda <= 1 / (2 int F_Hertz^2) = 0.28899...
"""
from __future__ import annotations

import functools
from collections.abc import Collection
from typing import Any

import numpy as np

from . import formulas as fm
from ..numerics.sqrt_integrals import impulse_s
from ..typing import FloatArray
from .base import REGISTRY, FieldValues, Model, computed_bound, register


@functools.lru_cache(maxsize=1)
def _hertz_int_F2() -> float:
    """int F_Hertz^2 over the Hertz contact, from the exact model at lambda = 0 (as hertz gives it)."""
    return float(REGISTRY["exact"]._summary(np.zeros(1))["int_F2"][0])


class Hertz(Model):
    """The model ``"hertz"``: the exact lambda = 0 solution whatever lambda."""

    name = "hertz"
    description = "rigid half-space: the exact lambda = 0 solution (lambda ignored)"
    summary_fields = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                      "int_F2", "xi")
    history_fields = ("delta", "velocity", "force", "impulse")

    # The exact model at lambda = 0 (its fast tables when it has them), so hertz and exact agree.
    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        s = REGISTRY["exact"]._summary(np.zeros(1))
        return {f: np.full(lam.shape, float(s[f][0])) for f in self.summary_fields if f != "lam"}

    def _history(self, lam: FloatArray, tau: FloatArray, **options: Any) -> FieldValues:
        h = REGISTRY["exact"]._history(np.zeros(tau.shape), tau)
        return {f: np.asarray(h[f], dtype=float) for f in self.history_fields}


class _Sine(Model):
    summary_fields = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "F_m", "impulse",
                      "int_F2")
    history_fields = ("delta", "velocity", "force", "impulse")
    Omega: float = fm.OMEGA_HUNTER

    def _force(self, s: FloatArray) -> FloatArray:  # pragma: no cover - each pulse's own
        """The force at s = sin(Omega tau) on the contact."""
        raise NotImplementedError

    def _impulse(self, x: FloatArray) -> FloatArray:  # pragma: no cover - each pulse's own
        """The impulse at x = Omega tau on the contact, 0 <= x <= pi."""
        raise NotImplementedError

    def _common(self, lam: FloatArray) -> FieldValues:
        td = np.pi / self.Omega
        return {"delta_m": np.full(lam.shape, fm.DELTA_M_HERTZ), "tau_d": np.full(lam.shape, td),
                "tau_dc": np.full(lam.shape, td / 2), "tau_dr": np.full(lam.shape, td / 2),
                "eta": np.ones(lam.shape)}

    selects_fields = True

    def _history(self, lam: FloatArray, tau: FloatArray, fields: Collection[str] | None = None,
                 **options: Any) -> FieldValues:
        """delta, force, impulse (closed forms) on the contact 0 <= tau < tau_d = pi / Omega;
        from tau_d on delta and the force are exactly 0 and the impulse keeps its final value."""
        want = set(self.history_fields if fields is None else fields)
        td = np.pi / self.Omega  # the summary's tau_d, same expression
        on = tau < td
        x = self.Omega * np.minimum(tau, td)
        out: FieldValues = {}
        if want & {"delta", "force"}:
            # one sine for both; exactly 0 from tau_d on (sin(pi) would leave 1.2e-16)
            s = np.sin(x)
            s[~on] = 0.0
            out["delta"] = fm.DELTA_M_HERTZ * s
            out["force"] = self._force(s)
        if want & {"impulse", "velocity"}:
            imp = np.where(on, self._impulse(x), self._impulse_total())
            out["impulse"], out["velocity"] = imp, 1.0 - imp
        return out

    def _impulse_total(self) -> float:
        return float(self._summary(np.zeros(1))["impulse"][0])


class Hunter(_Sine):
    """The model ``"hunter"``: Hunter's sine pulse, Eq. (52)."""

    name = "hunter"
    description = "Hunter's sinusoidal force pulse, Eq. (52) (lambda ignored)"

    def _force(self, s: FloatArray) -> FloatArray:
        return fm.A_HUNTER * s  # Eq. (52), s = sin(Omega tau) on [0, pi]

    def _impulse(self, x: FloatArray) -> FloatArray:
        imp: FloatArray = fm.A_HUNTER / self.Omega * (1.0 - np.cos(x))
        return imp

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        out = self._common(lam)
        out["F_m"] = np.full(lam.shape, fm.A_HUNTER)
        out["impulse"] = np.full(lam.shape, 2.0 * fm.A_HUNTER / self.Omega)
        out["int_F2"] = np.full(lam.shape, fm.A_HUNTER**2 * np.pi / 2.0 / self.Omega)
        return out


class Reed(_Sine):
    """The model ``"reed"``: Reed's sin^{3/2} pulse, Eq. (53)."""

    name = "reed"
    description = "Reed's sin^(3/2) force pulse, Eq. (53) (lambda ignored)"

    def _force(self, s: FloatArray) -> FloatArray:
        return fm.A_REED * s * np.sqrt(s)  # Eq. (53), s = sin(Omega tau) on [0, pi]

    def _impulse(self, x: FloatArray) -> FloatArray:
        # int_0^x sin^{3/2} = K_s(0, x): the closed form is an incomplete beta function
        # (formulas.int_sin32, which the tests compare), but scipy's betainc costs about 1 us a
        # point; the Chebyshev series of K_s (numerics.sqrt_integrals.impulse_s) agree to 1e-14 at a
        # tenth of that
        # one rate (0), broadcast: impulse_s checks and sorts it once, not once per point
        imp: FloatArray = fm.A_REED / self.Omega * impulse_s(np.broadcast_to(0.0, x.shape), x)
        return imp

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        out = self._common(lam)
        out["F_m"] = np.full(lam.shape, fm.A_REED)
        out["impulse"] = np.full(lam.shape, fm.A_REED / self.Omega * fm._INT_SIN32)
        out["int_F2"] = np.full(lam.shape, fm.A_REED**2 * 4.0 / 3.0 / self.Omega)
        return out


class OneWay(Model):
    """The model ``"oneway"``: the Hertz pulse drives the plate, which does not act back."""

    name = "oneway"
    description = ("one-way coupling: the Hertz pulse drives the plate, xi = 2 lambda int F_Hertz^2, "
                   "e = sqrt(1 - xi)")
    summary_fields = ("lam", "e", "xi", "int_F2")
    history_fields = ()
    bound_reason = "xi = 2 lambda int F_Hertz^2 exceeds 1 beyond it (e = sqrt(1 - xi))"

    @computed_bound
    def lam_bound(self) -> float:
        """Just above 1 / (2 int F_Hertz^2) (computed on first use: the exact model's)."""
        bound: float = np.nextafter(1.0 / (2.0 * _hertz_int_F2()), np.inf)
        return bound

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        J = _hertz_int_F2()
        xi = 2.0 * lam * J
        if np.any(xi > 1.0):
            raise ValueError(f"oneway: xi = 2 lambda int F^2 > 1 at lambda = {lam[xi > 1][0]!r}; "
                             f"allowed 0 <= lambda <= {1.0 / (2.0 * J):.12g}")
        return {"e": np.sqrt(1.0 - xi), "xi": xi, "int_F2": np.full(lam.shape, J)}


register(Hertz())
register(Hunter())
register(Reed())
register(OneWay())
