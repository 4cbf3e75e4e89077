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

The history at a requested τ inside phases 1 and 3 inverts the monotone τ(u) by Newton's method
on the dense output.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

__all__ = ["ExactSolution", "solve", "LAMBDA_MAX"]

#: Largest lambda the exact model accepts (tau_d is about 2300 at lambda = 100 and 34000 at
#: 1000; e falls as about 0.68 lambda^-5, below 1e-15 at 1000).
LAMBDA_MAX = 1000.0

_V_SWITCH = 0.5  # relative velocity at which loading hands over from u to tau


def _rhs_u(lam):
    """Loading/unloading in u = √δ; state (τ, w, J) with w = 1 − Ī, v = δ' = w − λu³."""

    def f(u, y):
        v = y[1] - lam * u**3
        # Trial steps may overshoot to v ~ 0; the error control rejects them, but keep them finite.
        if abs(v) < 1e-300:
            v = 1e-300 if v >= 0 else -1e-300
        g = 2.0 * u / v
        u3 = u**3
        return np.array([g, -g * u3, g * u3 * u3])

    return f


def _rhs_tau(lam):
    """Middle phase in τ; state (δ, w, J) with w = 1 − Ī, δ' = w − λδ^{3/2}."""

    def f(t, y):
        d = y[0] if y[0] > 0.0 else 0.0  # guard: contact force is zero for a negative trial δ
        F = d * np.sqrt(d)
        return np.array([y[1] - lam * F, -F, F * F])

    return f


@dataclass
class ExactSolution:
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
    _load: object  # OdeSolution in u, phase 1
    _mid: object  # OdeSolution in tau, phase 2
    _unload: object  # OdeSolution in u (decreasing), phase 3
    _tau1: float
    _tau2: float
    _u_grid1: np.ndarray
    _tau_grid1: np.ndarray
    _u_grid3: np.ndarray
    _tau_grid3: np.ndarray

    @property
    def impulse(self) -> float:
        return 1.0 - self.w_end

    @property
    def tau_dr(self) -> float:
        return self.tau_d - self.tau_dc

    @property
    def eta(self) -> float:
        return self.tau_dr / self.tau_dc

    @property
    def e(self) -> float:
        # e = −δ'(τ_d), and δ'(τ_d) = w(τ_d) since F̄(τ_d) = 0
        return -self.w_end

    @property
    def F_m(self) -> float:
        return self.delta_m**1.5  # F̄ = δ^{3/2} is monotone in δ, so F_m sits at δ_m

    @property
    def xi(self) -> float:
        return 1.0 - self.w_end**2  # = 2Ī − Ī², without the cancellation

    def _invert(self, sol, u_grid, tau_grid, tau):
        """u with τ(u) = tau on one u-phase: interpolate u² against τ, then Newton."""
        order = np.argsort(tau_grid)
        u = np.sqrt(np.interp(tau, tau_grid[order], (u_grid**2)[order]))
        lo, hi = min(u_grid[0], u_grid[-1]), max(u_grid[0], u_grid[-1])
        for _ in range(40):
            y = sol(u)
            v = y[1] - self.lam * u**3
            dtau = 2.0 * u / v
            resid = y[0] - tau
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(dtau != 0.0, resid / dtau, 0.0)
            u = np.clip(u - step, lo, hi)
            if np.all(np.abs(resid) <= 4e-16 * np.maximum(1.0, np.abs(tau))):
                break
        return u, sol(u)

    def history(self, tau) -> dict:
        """δ, Ī, sphere velocity 1 − Ī and force δ^{3/2} at the times ``tau`` (any shape, >= 0).

        Past the end of contact δ and the force are 0 and the impulse stays at Ī(τ_d).
        """
        tau = np.asarray(tau, dtype=float)
        flat = tau.ravel()
        delta = np.zeros_like(flat)
        w = np.full_like(flat, self.w_end)
        m1 = flat <= self._tau1
        m2 = (flat > self._tau1) & (flat < self._tau2)
        m3 = (flat >= self._tau2) & (flat < self.tau_d)
        if m1.any():
            u, y = self._invert(self._load, self._u_grid1, self._tau_grid1, flat[m1])
            delta[m1], w[m1] = u**2, y[1]
        if m2.any():
            y = self._mid(flat[m2])
            delta[m2], w[m2] = y[0], y[1]
        if m3.any():
            u, y = self._invert(self._unload, self._u_grid3, self._tau_grid3, flat[m3])
            delta[m3], w[m3] = u**2, y[1]
        delta = np.maximum(delta, 0.0).reshape(tau.shape)
        w = w.reshape(tau.shape)
        return {"tau": tau, "delta": delta, "impulse": 1.0 - w, "velocity": w,
                "force": delta**1.5}


def solve(lam: float, rtol: float = 1e-12, atol: float = 1e-15, method: str = "DOP853") -> ExactSolution:
    """Integrate Eq. (10) for one lambda to the end of contact.

    Parameters
    ----------
    lam : float
        Inelasticity parameter, 0 <= lam <= LAMBDA_MAX (validated by the caller).
    rtol, atol : float
        Tolerances passed to ``scipy.integrate.solve_ivp`` in every phase. The relative velocity
        w = 1 − Ī gets a vanishing absolute tolerance, so that e = −w(τ_d) is relatively accurate.
    method : str
        Explicit Runge-Kutta method of ``solve_ivp`` ("DOP853" default, "RK45").

    Returns
    -------
    ExactSolution
    """
    lam = float(lam)
    atols = np.array([atol, 1e-300, atol])
    # Phase 1: u from 0 until v = 1/2. δ_m^{3/2} < 1/λ bounds u; at λ = 0, δ_m < 1.1.
    u_cap = min(1.2, lam ** (-1.0 / 3.0)) if lam > 0 else 1.2

    def v_half(u, y):
        return y[1] - lam * u**3 - _V_SWITCH

    v_half.terminal, v_half.direction = True, -1
    s1 = solve_ivp(_rhs_u(lam), (0.0, u_cap), [0.0, 1.0, 0.0], method=method, rtol=rtol,
                   atol=atols, events=v_half, dense_output=True)
    if s1.status != 1:
        raise RuntimeError(f"exact solver: loading phase did not reach v = 1/2 at lambda = {lam}")
    u1 = float(s1.t_events[0][0])
    tau1, w1, J1 = s1.y_events[0][0]

    # Phase 2: τ from τ1. Events: v = 0 (end of compression); hand-over to u where the u-form is
    # not stiff, |∂(dw/du)/∂w|·u = 2u⁵/v² <= 1, i.e. v² >= 2δ^{5/2}. Before the end of compression
    # v² − 2δ^{5/2} only decreases, after it only increases, so the rising crossing is unique.
    def v_zero(t, y):
        d = max(y[0], 0.0)
        return y[1] - lam * d * np.sqrt(d)

    v_zero.direction = -1

    def hand_over(t, y):
        d = max(y[0], 0.0)
        v = y[1] - lam * d * np.sqrt(d)
        return v * v - 2.0 * d * d * np.sqrt(d)

    hand_over.terminal, hand_over.direction = True, 1
    t_cap = tau1 + 100.0 + 100.0 * lam
    s2 = solve_ivp(_rhs_tau(lam), (tau1, t_cap), [u1 * u1, w1, J1], method=method, rtol=rtol,
                   atol=atols, events=[v_zero, hand_over], dense_output=True)
    if s2.status != 1 or len(s2.t_events[0]) != 1:
        raise RuntimeError(f"exact solver: middle phase failed at lambda = {lam}: {s2.message}")
    tau_dc = float(s2.t_events[0][0])
    delta_m = float(s2.y_events[0][0][0])
    tau2 = float(s2.t_events[1][0])
    d2, w2, J2 = s2.y_events[1][0]

    # Phase 3: u from √δ2 down to 0; the end of contact is the endpoint u = 0.
    s3 = solve_ivp(_rhs_u(lam), (np.sqrt(d2), 0.0), [tau2, w2, J2], method=method, rtol=rtol,
                   atol=atols, dense_output=True)
    if s3.status != 0:
        raise RuntimeError(f"exact solver: unloading phase failed at lambda = {lam}: {s3.message}")
    tau_d, w_end, J_end = s3.y[:, -1]
    return ExactSolution(
        lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=float(tau_d), w_end=float(w_end),
        int_F2=float(J_end), _load=s1.sol, _mid=s2.sol, _unload=s3.sol, _tau1=float(tau1),
        _tau2=tau2, _u_grid1=s1.t, _tau_grid1=s1.y[0], _u_grid3=s3.t, _tau_grid3=s3.y[0],
    )
