"""The systems the paper compares with besides its own: Mueller's linear law and Raman's slope.

* ``linear``: Mueller et al.'s (2015) linearization, the Hertz force delta^{3/2} of Eq. (10)
  replaced by kappa delta. Eq. (10) becomes the damped oscillator
  delta'' + kappa lambda delta' + kappa delta = 0, whose closed forms are derived and checked in
  ``zener_sym.derivation.linear`` (``python -m zener_sym.derivation.linear``):
  beta = kappa lambda / 2, omega = sqrt(kappa - beta^2), delta = exp(-beta tau) sin(omega tau)/omega,
  tau_d = pi/omega, tau_dc = atan2(omega, beta)/omega, delta_m = exp(-beta tau_dc)/sqrt(kappa),
  F = kappa delta, e = exp(-pi beta/omega), I(tau) = 1 - delta' - lambda kappa delta,
  int F^2 = kappa (1 - e^2) / (4 beta). The stiffness kappa is a choice (option ``stiffness``,
  see ``STIFFNESS``); the contact never ends once kappa lambda^2 >= 4, so lambda >= 2/sqrt(kappa)
  is refused.
* ``raman``: Raman's (1920) small-lambda restitution e = 1 - c1 lambda, with
  c1 = int F_Hertz^2 dtau = (5/4)^{3/5} sqrt(pi) Gamma(8/5) / Gamma(21/10) = 1.7301732871...
  derived (not fitted) in ``zener_sym.derivation.linear`` from the exact energy balance
  1 - e^2 = 2 lambda int F^2. It gives e only; it is refused beyond lambda = 1/c1, where e < 0.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..typing import FloatArray, RealArrayLike
from .base import FieldValues, Model, register

__all__ = ["STIFFNESS", "DEFAULT_STIFFNESS", "RAMAN_C1", "TAU_HERTZ", "linear_summary",
           "linear_history"]

_DM: float = 1.25 ** 0.4  # Hertz's delta_m, Eq. (23)
#: Hertz's contact duration (4/5)(5/4)^{2/5} Gamma(2/5) sqrt(pi) / Gamma(9/10) (derivation.linear).
TAU_HERTZ: float = 0.8 * _DM * math.gamma(0.4) * math.sqrt(math.pi) / math.gamma(0.9)
#: Raman's slope c1 = (5/4)^{3/5} sqrt(pi) Gamma(8/5) / Gamma(21/10) (derivation.linear).
RAMAN_C1: float = 1.25 ** 0.6 * math.sqrt(math.pi) * math.gamma(1.6) / math.gamma(2.1)

#: The linear law's stiffness choices, each matching one property of the Hertz impact
#: (lambda = 0); the derivation module states and checks each.
STIFFNESS: dict[str, float] = {
    "duration": (math.pi / TAU_HERTZ) ** 2,  # pi / sqrt(kappa) = tau_H
    "compression": _DM**-2,                  # 1 / sqrt(kappa) = delta_mH (= the stored energy)
    "force": _DM**3,                         # sqrt(kappa) = F_mH = delta_mH^{3/2}
    "secant": math.sqrt(_DM),                # kappa = delta_mH^{1/2}, the HAM's k at lambda = 0
    "unit": 1.0,                             # F-bar = delta-bar in Zener's scaling
    "dissipation": (2.0 * RAMAN_C1 / math.pi) ** 2,  # small-lambda slope of e equal to c1
}
#: The choice the registered ``linear`` model uses by default (see docs/figures.md: of the
#: natural choices it is the one whose F_m errors have the paper's sign everywhere, "always
#: underestimates"; none reproduces the paper's quoted magnitudes).
DEFAULT_STIFFNESS = "compression"


def _kappa(stiffness: object) -> float:
    """kappa of a ``STIFFNESS`` name; ValueError naming the allowed ones otherwise."""
    if isinstance(stiffness, str) and stiffness in STIFFNESS:
        return STIFFNESS[stiffness]
    raise ValueError(f"unknown stiffness {stiffness!r} for model 'linear'; allowed: "
                     f"{', '.join(STIFFNESS)}")


def _omega(lam: FloatArray, kappa: float) -> FloatArray:
    """omega = sqrt(kappa - beta^2) = sqrt(kappa (1 - s)(1 + s)), s = lambda sqrt(kappa) / 2
    (factored, so it stays accurate close to the bound)."""
    s = lam * math.sqrt(kappa) / 2.0
    return np.sqrt(kappa * (1.0 - s) * (1.0 + s))


def _check_bound(lam: FloatArray, kappa: float, stiffness: str) -> None:
    """ValueError for a lambda at or beyond 2/sqrt(kappa), where the contact does not end."""
    bound = 2.0 / math.sqrt(kappa)
    # also refuse a lambda that rounds onto the bound (omega = 0: no end of contact)
    bad_mask = (lam >= bound) | ~(_omega(lam, kappa) > 0)
    if np.any(bad_mask):
        bad = float(np.asarray(lam)[bad_mask].ravel()[0])
        raise ValueError(f"model 'linear' (stiffness {stiffness!r}): lambda = {bad!r} is not "
                         f"below 2/sqrt(kappa) = {bound:.12g}, where the linear contact stops "
                         f"ending (overdamped); allowed: 0 <= lambda < {bound:.12g}")


def linear_summary(lam: RealArrayLike, stiffness: str = DEFAULT_STIFFNESS) -> FieldValues:
    """Closed-form summary of the linear law for lambda below 2/sqrt(kappa).

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), 0 <= lambda < 2/sqrt(kappa).
    stiffness : str
        One of ``STIFFNESS`` (default ``DEFAULT_STIFFNESS``): the choice of kappa.

    Returns
    -------
    dict of str to numpy.ndarray
        delta_m, tau_dc, tau_d, tau_dr, eta, e, F_m, impulse, int_F2, xi, each of the shape of
        ``lam``.

    Raises
    ------
    ValueError
        For an unknown stiffness, or a lambda at or beyond 2/sqrt(kappa).
    """
    kappa = _kappa(stiffness)
    lam_a: FloatArray = np.asarray(lam, dtype=float)
    _check_bound(lam_a, kappa, stiffness)
    b = kappa * lam_a / 2.0
    w = _omega(lam_a, kappa)
    tau_d = np.pi / w
    tau_dc = np.arctan2(w, b) / w
    delta_m = np.exp(-b * tau_dc) / math.sqrt(kappa)
    x = np.pi * b / w
    e = np.exp(-x)
    # int F^2 = kappa (1 - e^2) / (4 beta) = kappa (pi / (2 omega)) (1 - exp(-2x)) / (2x), regular at 0
    with np.errstate(invalid="ignore", divide="ignore"):
        g = np.where(x > 0, -np.expm1(-2.0 * x) / (2.0 * np.where(x > 0, x, 1.0)), 1.0)
    int_F2 = kappa * np.pi / (2.0 * w) * g
    return {"delta_m": delta_m, "tau_dc": tau_dc, "tau_d": tau_d, "tau_dr": tau_d - tau_dc,
            "eta": (tau_d - tau_dc) / tau_dc, "e": e, "F_m": kappa * delta_m, "impulse": 1.0 + e,
            "int_F2": int_F2, "xi": -np.expm1(-2.0 * x)}


def linear_history(lam: RealArrayLike, tau: RealArrayLike,
                   stiffness: str = DEFAULT_STIFFNESS) -> FieldValues:
    """Closed-form histories of the linear law; after tau_d the force is 0 and the impulse keeps
    1 + e.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), 0 <= lambda < 2/sqrt(kappa).
    tau : float or array_like
        Dimensionless times (Eq. 9), broadcast against ``lam``.
    stiffness : str
        One of ``STIFFNESS`` (default ``DEFAULT_STIFFNESS``).

    Returns
    -------
    dict of str to numpy.ndarray
        delta, force, impulse, velocity, of the broadcast shape.

    Raises
    ------
    ValueError
        For an unknown stiffness, or a lambda at or beyond 2/sqrt(kappa).
    """
    kappa = _kappa(stiffness)
    lam_b: FloatArray
    tau_b: FloatArray
    lam_b, tau_b = np.broadcast_arrays(np.asarray(lam, float), np.asarray(tau, float))
    _check_bound(lam_b, kappa, stiffness)
    b = kappa * lam_b / 2.0
    w = _omega(lam_b, kappa)
    on = tau_b < np.pi / w
    t = np.where(on, tau_b, np.pi / w)  # the closed forms at tau_d hold the final values
    decay = np.exp(-b * t)
    delta = np.where(on, decay * np.sin(w * t) / w, 0.0)
    ddot = decay * (np.cos(w * t) - b / w * np.sin(w * t))
    impulse = 1.0 - ddot - lam_b * kappa * delta
    return {"delta": delta, "force": kappa * delta, "impulse": impulse, "velocity": 1.0 - impulse}


class Linear(Model):
    """The model ``"linear"``: Mueller et al.'s F = kappa delta in Eq. (10), in closed form."""

    name = "linear"
    description = ("Mueller et al.'s linearized contact law: F = kappa delta in Eq. (10), a damped "
                   "oscillator in closed form (option stiffness: " + ", ".join(STIFFNESS) + ")")
    summary_fields = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                      "int_F2", "xi")
    history_fields = ("delta", "velocity", "force", "impulse")
    options = ("stiffness",)
    lam_bound = 2.0 / math.sqrt(STIFFNESS[DEFAULT_STIFFNESS])
    bound_reason = ("the linear contact does not end for kappa lambda^2 >= 4 (overdamped); "
                    f"bound for the default stiffness {DEFAULT_STIFFNESS!r}")

    def _summary(self, lam: FloatArray, stiffness: str = DEFAULT_STIFFNESS) -> FieldValues:
        return linear_summary(lam, stiffness)

    def _history(self, lam: FloatArray, tau: FloatArray,
                 stiffness: str = DEFAULT_STIFFNESS) -> FieldValues:
        return linear_history(lam, tau, stiffness)


class Raman(Model):
    """The model ``"raman"``: Raman's e = 1 - c1 lambda (c1 derived)."""

    name = "raman"
    description = ("Raman's small-lambda restitution e = 1 - c1 lambda, c1 = int F_Hertz^2 = "
                   f"{RAMAN_C1:.10f} (derived)")
    summary_fields = ("lam", "e")
    history_fields = ()
    lam_bound = np.nextafter(1.0 / RAMAN_C1, np.inf)
    bound_reason = "e = 1 - c1 lambda is negative beyond lambda = 1/c1"

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        return {"e": 1.0 - RAMAN_C1 * lam}


register(Linear())
register(Raman())
