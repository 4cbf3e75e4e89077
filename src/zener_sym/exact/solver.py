"""Direct integration of Zener's impact equation, Eq. (10), to the end of contact (scipy path).

The equation  δ'' + (1 + λ d/dτ) δ^{3/2} = 0,  δ(0) = 0,  δ'(0) = 1  integrates once to

    δ' = w − λ δ^{3/2},     w' = −δ^{3/2}  (w = 1 − Ī, Ī the impulse),     J' = δ^3  (∫F̄² dτ),

because F̄(0) = 0; w is also the sphere's velocity (Eq. 64). The right-hand side is not smooth
where δ = 0 (δ ≈ τ at the start, so δ^{1/2} has no Taylor series in τ), which costs an ordinary integrator its order and makes the
end-of-contact event inaccurate. We therefore integrate in three phases, each in a variable in
which the solution is analytic:

1. loading, ``u = √δ`` as the independent variable, state (τ, w, J):
   dτ/du = 2u/v, dw/du = −2u⁴/v, dJ/du = 2u⁷/v, with v = δ' = w − λu³. This is analytic at
   u = 0 (exact start, no series needed) and stops at v = 1/2, well before v = 0.
2. middle, τ as the independent variable, state (δ, w, J): analytic while δ > 0. The end of
   compression is the event v = 0; the phase stops, in recovery, where the u-form is no longer
   stiff (v² >= 2δ^{5/2}).
3. unloading, u again, down to u = 0: the end of contact is the fixed endpoint u = 0, so τ_d and the terminal state come out of the integration, not out of an event search.

The phases are run by the driver of :mod:`.phases`; this module gives it the plate's equations
(``plate_contact``). The history at a requested τ inside phases 1 and 3 inverts the monotone τ(u)
by Newton's method on the dense output.
"""
from __future__ import annotations

import numbers
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypedDict

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray, RealArrayLike
from .phases import Contact, Form, Leg, Settings, Terms, Value, integrate, positive
from .phases import eval_budget  # noqa: F401 (re-exported: part of this module's API)

__all__ = ["ExactSolution", "solve", "restitution", "solve_early", "check_options", "eval_budget",
           "plate_contact", "LAMBDA_MAX", "METHODS", "RTOL_MIN", "RTOL_MAX"]

#: Largest lambda the exact model accepts (tau_d is about 2300 at lambda = 100 and 34000 at
#: 1000; e falls as about 0.68 lambda^-5, below 1e-15 at 1000).
LAMBDA_MAX = 1000.0

#: ``solve_ivp`` methods the solver accepts (all support events and dense output).
METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")
#: Smallest rtol: scipy raises any smaller rtol to 100 machine epsilons (with a warning), so a
#: smaller one would not be honoured; we refuse it instead.
RTOL_MIN = 100 * np.finfo(float).eps
#: Largest rtol: looser tolerances give no correct digit (rtol 0.1 gives e = -0.87 at lambda 20).
RTOL_MAX = 1e-3


def _u_terms(lam: float) -> Terms:
    """Loading/unloading in u = √δ; state (τ, w, J) with w = 1 − Ī, v = δ' = w − λu³."""

    def f(u: float, y: FloatArray) -> tuple[Value, ...]:
        v = y[1] - lam * u**3
        # Trial steps may overshoot to v ~ 0; the error control rejects them, but keep them finite.
        if abs(v) < 1e-300:
            v = 1e-300 if v >= 0 else -1e-300
        g = 2.0 * u / v
        u3 = u**3
        return g, -g * u3, g * u3 * u3

    return f


def _tau_terms(lam: float) -> Terms:
    """Middle phase in τ after the end of compression; state (δ, w, J) with w = 1 − Ī,
    δ' = w − λδ^{3/2}."""

    def f(t: float, y: FloatArray) -> tuple[Value, ...]:
        d = positive(y[0])
        F = d * np.sqrt(d)
        return y[1] - lam * F, -F, F * F

    return f


def _tau_v_terms(lam: float) -> Terms:
    """Middle phase in τ up to the end of compression; state (δ, v, w, J) with v = δ'.

    v is carried as its own state, v' = −F − (3/2)λδ^{1/2} v (Eq. 10 itself), rather than formed
    as w − λδ^{3/2}: near the end of compression that difference of two nearly equal numbers
    (both about λF̄_m ~ 1 at large λ) carries δ's relative error times λ into v, hence into τ_dc
    (relative 3e-9 at λ = 1000). The state v is small there and relatively accurate. After τ_dc
    the three-state form takes over: it keeps the first integral v = w − λF̄ exactly, which the
    four-state form would let drift (the drift is not damped, and e ~ 0.68 λ^-5 cannot afford it).
    """

    def f(t: float, y: FloatArray) -> tuple[Value, ...]:
        d = positive(y[0])
        sd = np.sqrt(d)
        F = d * sd
        return y[1], -F - 1.5 * lam * sd * y[1], -F, F * F

    return f


def plate_contact(lam: float) -> Contact:
    """The plate's contact (Eq. 10 to δ = 0) for the phase driver.

    Loading and unloading in u, the middle in (δ, v, w, J) up to the end of compression and in
    (δ, w, J) after it.

    Parameters
    ----------
    lam : float
        lambda (Eq. 11), >= 0.

    Returns
    -------
    Contact
    """

    def v_tau(t: float, y: FloatArray) -> Value:
        d = positive(y[0])
        v: Value = y[1] - lam * d * np.sqrt(d)
        return v

    u_form = Form("u", ("tau", "w", "J"), _u_terms(lam), lambda u, y: y[1] - lam * u**3, lam)
    compression = Form("tau", ("delta", "v", "w", "J"), _tau_v_terms(lam), lambda t, y: y[1], lam)
    recovery = Form("tau", ("delta", "w", "J"), _tau_terms(lam), v_tau, lam)
    return Contact(u_form, (compression, recovery))


def _rhs_u(lam: float) -> Callable[[float, FloatArray], FloatArray]:
    """The loading u-form's right-hand side alone (``audit.claims.delta_m_exact``)."""
    return plate_contact(lam).u_form.rhs()


def _rhs_tau(lam: float) -> Callable[[float, FloatArray], FloatArray]:
    """The (δ, w, J) τ-form's right-hand side alone (``audit.claims.delta_m_exact``)."""
    return plate_contact(lam).middle[1].rhs()


class ContactTimes:
    """tau_dr and eta from tau_d and tau_dc, shared by every solution object (floats or mpf)."""

    # set by the dataclass subclasses (float, or mpmath.mpf in the mpmath solutions)
    tau_d: Any
    tau_dc: Any

    @property
    def tau_dr(self) -> Any:
        """Recovery time tau_d - tau_dc."""
        return self.tau_d - self.tau_dc

    @property
    def eta(self) -> Any:
        """Ratio of recovery to compression time, tau_dr / tau_dc."""
        return self.tau_dr / self.tau_dc


@dataclass
class ExactSolution(ContactTimes):
    """Solution of Eq. (10) for one lambda, with summary fields and a dense history.

    ``w_end`` is the relative velocity 1 − Ī at the end of contact, kept as its own state so that
    e = −w_end keeps its relative accuracy when e is tiny (large lambda).
    """

    lam: float
    delta_m: float
    tau_dc: float
    tau_d: float
    w_end: float
    int_F2: float
    legs: tuple[Leg, ...]  # the integrated phases in order

    @property
    def impulse(self) -> float:
        """Ī(τ_d) = 1 − w_end (= 1 + e, Eq. 64)."""
        return 1.0 - self.w_end

    @property
    def e(self) -> float:
        """Coefficient of restitution e = −δ'(τ_d)."""
        # e = −δ'(τ_d), and δ'(τ_d) = w(τ_d) since F̄(τ_d) = 0
        return -self.w_end

    @property
    def F_m(self) -> float:
        """Largest force F̄_m = δ_m^{3/2}."""
        F_m: float = self.delta_m**1.5  # F̄ = δ^{3/2} is monotone in δ, so F_m sits at δ_m
        return F_m

    @property
    def xi(self) -> float:
        """Energy-loss ratio from the energy balance xi = 1 − e² = 2λ∫F̄² dτ (Eqs. 69, 74).

        Not 1 − w_end²: that cancels as λ → 0 (relative error 1e-7 at λ = 1e-6, a negative
        xi at λ = 0). 2λJ is a product of positive numbers, exactly 0 at λ = 0, and as relatively
        accurate as J.
        """
        return 2.0 * self.lam * self.int_F2

    def leg_of(self, tau: RealArrayLike) -> npt.NDArray[np.int_]:
        """Index into ``legs`` of the phase that holds each time (−1 at and after τ_d).

        A u-phase holds its starting time, a τ-phase only the times after its start (the
        loading phase holds τ <= 0 too).

        Parameters
        ----------
        tau : array_like
            Times.

        Returns
        -------
        ndarray of int
            The leg of each time, tau's shape.
        """
        t = np.asarray(tau, dtype=float)
        where = np.zeros(t.shape, dtype=int)
        for i, leg in enumerate(self.legs[1:], 1):
            t0 = leg.tau_start
            where[(t >= t0) if leg.form.kind == "u" else (t > t0)] = i
        where[t >= self.tau_d] = -1
        return where

    def history(self, tau: RealArrayLike) -> dict[str, FloatArray]:
        """δ, Ī, sphere velocity 1 − Ī and force δ^{3/2} at the times ``tau`` (any shape, >= 0).

        Past the end of contact δ and the force are 0 and the impulse stays at Ī(τ_d).

        Parameters
        ----------
        tau : array_like
            Times, >= 0.

        Returns
        -------
        dict of str to ndarray
            "tau", "delta", "impulse", "velocity", "force", each of tau's shape.
        """
        t: FloatArray = np.asarray(tau, dtype=float)
        flat = t.ravel()
        d_flat = np.zeros_like(flat)
        w_flat = np.full_like(flat, self.w_end)
        where = self.leg_of(flat)
        for i, leg in enumerate(self.legs):
            m = where == i
            if m.any():
                d_flat[m], w_flat[m] = leg.delta_w(flat[m])
        delta = np.maximum(d_flat, 0.0).reshape(t.shape)
        w = w_flat.reshape(t.shape)
        return {"tau": t, "delta": delta, "impulse": 1.0 - w, "velocity": w,
                "force": delta**1.5}


def _check_tol(name: str, value: object, low: float, high: float, text: str) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number in {text}, got {value!r}")
    x = float(value)
    if not (np.isfinite(x) and low <= x <= high):
        raise ValueError(f"{name} must be a finite number in {text}, got {value!r}")
    return x


def check_options(rtol: object = 1e-12, atol: object = 1e-15,
                  method: object = "DOP853") -> tuple[float, float, str]:
    """Validate the integrator options before any work.

    Parameters
    ----------
    rtol : float
        In [RTOL_MIN, RTOL_MAX], a finite real number (not bool, str or None).
    atol : float
        In (0, 1), a finite real number.
    method : str
        One of ``METHODS``.

    Returns
    -------
    tuple
        (rtol, atol, method) as float, float, str.

    Raises
    ------
    ValueError
        For an option outside the above, naming the allowed values.
    """
    rtol_f = _check_tol("rtol", rtol, RTOL_MIN, RTOL_MAX,
                      f"[{RTOL_MIN:.3g}, {RTOL_MAX:g}] (scipy's smallest rtol is 100 machine "
                      "epsilons; looser gives no correct digit)")
    if isinstance(atol, bool) or not isinstance(atol, numbers.Real) or not (
            np.isfinite(float(atol)) and 0.0 < float(atol) < 1.0):
        raise ValueError(f"atol must be a finite real number in (0, 1), got {atol!r}")
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(METHODS)}; got {method!r}")
    return rtol_f, float(atol), method


def solve(lam: float, rtol: float = 1e-12, atol: float = 1e-15, method: str = "DOP853") -> ExactSolution:
    """Integrate Eq. (10) for one lambda to the end of contact.

    Parameters
    ----------
    lam : float
        Inelasticity parameter, 0 <= lam <= LAMBDA_MAX (validated by the caller).
    rtol, atol : float
        Tolerances passed to ``scipy.integrate.solve_ivp`` in every phase, rtol in
        [RTOL_MIN, RTOL_MAX], atol in (0, 1) (``check_options``). The relative velocities w = 1 − Ī and
        v = δ' get a vanishing absolute tolerance, so that e = −w(τ_d) and τ_dc (v = 0) are
        relatively accurate.
    method : str
        Method of ``solve_ivp``, one of ``METHODS`` ("DOP853" default).

    Returns
    -------
    ExactSolution

    Raises
    ------
    ValueError
        For an option outside the ranges above (checked before any work).
    RuntimeError
        When a phase fails or the solve needs more than ``eval_budget(lam)`` right-hand-side
        evaluations (a slow method at a tight rtol; never a hang).
    """
    rtol, atol, method = check_options(rtol=rtol, atol=atol, method=method)
    lam = float(lam)
    legs = integrate(plate_contact(lam), Settings(lam, rtol, atol, method))
    tau_dc, delta_m = _compression_end(legs)
    end = legs[-1].end
    J_end = float(end["J"])
    return ExactSolution(
        lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=float(end["tau"]),
        w_end=-float(restitution(2.0 * lam * J_end, -float(end["w"]))), int_F2=J_end, legs=legs)


def _compression_end(legs: tuple[Leg, ...]) -> tuple[float, float]:
    """(τ_dc, δ_m) from the middle phase's event v = 0."""
    hit = legs[1].hit("end of compression")
    if hit is None:  # phases.integrate refuses a middle without it
        raise RuntimeError("exact solver: no end of compression in the middle phase")
    return float(hit["tau"]), float(hit["delta"])


def restitution(xi: RealArrayLike, e_direct: RealArrayLike) -> FloatArray:
    """e from the energy loss xi where that is the better route, else ``e_direct``.

    While xi < 1/2, e = sqrt(1 - xi) with xi formed without cancellation: as accurate as the
    directly computed e, never above 1 and exactly 1 at lambda = 0 (the integrated end velocity
    and the tables' exp(log e) gave 1 + 1.2e-14 there). Above, 1 - xi cancels as e -> 0 and
    ``e_direct`` (relatively accurate) is kept. The scipy solvers, the force-free end and the
    tables all take e from here.

    Parameters
    ----------
    xi : array_like
        Energy-loss ratio xi = 1 - e^2 (Eq. 69), formed without cancellation.
    e_direct : array_like
        e computed directly (relatively accurate as e -> 0).

    Returns
    -------
    ndarray
        e, the broadcast shape (0-d for scalars).
    """
    xi_a = np.asarray(xi, dtype=float)
    return np.where(xi_a < 0.5, np.sqrt(np.maximum(1.0 - xi_a, 0.0)),
                    np.asarray(e_direct, dtype=float))


class EarlyPart(TypedDict):
    """What :func:`solve_early` returns."""

    tau_dc: float
    delta_m: float
    tau: float
    delta: float
    w: float
    J: float
    solution: ExactSolution


def solve_early(lam: float, span: float, rtol: float = 1e-13, atol: float = 1e-15) -> EarlyPart:
    """Integrate Eq. (10) from the impact to ``span`` past the end of compression (DOP853).

    For large lambda the rest of the contact follows one universal orbit (see
    ``zener_sym.exact.table_build``), so the tables need only this early part per lambda: phase 1,
    phase 2a up to τ_dc and phase 2b for ``span`` more.

    Parameters
    ----------
    lam : float
        lambda (Eq. 11), validated by the caller.
    span : float
        Time integrated past the end of compression, > 0.
    rtol, atol : float
        Tolerances (``check_options``).

    Returns
    -------
    EarlyPart
        tau_dc, delta_m, the state (tau, delta, w, J) at tau_dc + span, and ``solution``: an
        ``ExactSolution`` of that early part (its ``history`` valid for 0 <= tau < tau_dc +
        span; its tau_d, w_end, int_F2 are the end state's, not the contact's).

    Raises
    ------
    ValueError
        For a bad option.
    RuntimeError
        When a phase fails.
    """
    rtol, atol, method = check_options(rtol=rtol, atol=atol, method="DOP853")
    lam = float(lam)
    legs = integrate(plate_contact(lam), Settings(lam, rtol, atol, method), span=span)
    tau_dc, delta_m = _compression_end(legs)
    end = legs[-1].end
    tau_m = float(end["tau"])
    delta, w, J = (float(end[k]) for k in ("delta", "w", "J"))
    early = ExactSolution(lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=tau_m, w_end=w,
                          int_F2=J, legs=legs)
    return {"tau_dc": tau_dc, "delta_m": delta_m, "tau": tau_m, "delta": delta, "w": w, "J": J,
            "solution": early}
