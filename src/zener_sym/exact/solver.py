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

import numbers
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

__all__ = ["ExactSolution", "solve", "restitution", "solve_early", "check_options", "eval_budget", "LAMBDA_MAX", "METHODS",
           "RTOL_MIN", "RTOL_MAX"]

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


def eval_budget(lam: float) -> int:
    """Most right-hand-side evaluations one solve may spend before it gives up (RuntimeError).

    DOP853 at rtol 1e-13 needs about 2000 + 2000 lambda; the budget is a few times that, so a
    slow combination of options (RK23 at the smallest rtol at lambda = 1000) ends in seconds
    with an error instead of running for hours.
    """
    return int(500_000 + 2500 * lam)


class _Budget:
    """Counts right-hand-side evaluations against ``eval_budget``."""

    def __init__(self, lam, method, rtol):
        self.left, self.lam, self.method, self.rtol = eval_budget(lam), lam, method, rtol

    def spend(self):
        self.left -= 1
        if self.left < 0:
            raise RuntimeError(
                f"exact solver: more than {eval_budget(self.lam)} right-hand-side evaluations at "
                f"lambda = {self.lam} with method={self.method!r}, rtol={self.rtol:g}; use the "
                f"default method (DOP853), LSODA, or a looser rtol")

_V_SWITCH = 0.5  # relative velocity at which loading hands over from u to tau


def _rhs_u(lam, budget=None):
    """Loading/unloading in u = √δ; state (τ, w, J) with w = 1 − Ī, v = δ' = w − λu³."""

    def f(u, y):
        if budget is not None:
            budget.spend()
        v = y[1] - lam * u**3
        # Trial steps may overshoot to v ~ 0; the error control rejects them, but keep them finite.
        if abs(v) < 1e-300:
            v = 1e-300 if v >= 0 else -1e-300
        g = 2.0 * u / v
        u3 = u**3
        return np.array([g, -g * u3, g * u3 * u3])

    return f


def _rhs_tau(lam, budget=None):
    """Middle phase in τ after the end of compression; state (δ, w, J) with w = 1 − Ī,
    δ' = w − λδ^{3/2}."""

    def f(t, y):
        if budget is not None:
            budget.spend()
        d = y[0] if y[0] > 0.0 else 0.0  # guard: contact force is zero for a negative trial δ
        F = d * np.sqrt(d)
        return np.array([y[1] - lam * F, -F, F * F])

    return f


def _rhs_tau_v(lam, budget=None):
    """Middle phase in τ up to the end of compression; state (δ, v, w, J) with v = δ'.

    v is carried as its own state, v' = −F − (3/2)λδ^{1/2} v (Eq. 10 itself), rather than formed
    as w − λδ^{3/2}: near the end of compression that difference of two nearly equal numbers
    (both about λF̄_m ~ 1 at large λ) carries δ's relative error times λ into v, hence into τ_dc
    (relative 3e-9 at λ = 1000). The state v is small there and relatively accurate. After τ_dc
    the three-state form takes over: it keeps the first integral v = w − λF̄ exactly, which the
    four-state form would let drift (the drift is not damped, and e ~ 0.68 λ^-5 cannot afford it).
    """

    def f(t, y):
        if budget is not None:
            budget.spend()
        d = y[0] if y[0] > 0.0 else 0.0
        sd = np.sqrt(d)
        F = d * sd
        return np.array([y[1], -F - 1.5 * lam * sd * y[1], -F, F * F])

    return f


class _TwoPieces:
    """Dense output of the middle phase: (δ, w) rows from the four-state piece before τ_dc and
    the three-state piece after it."""

    def __init__(self, before, after, tau_dc):
        self.before, self.after, self.tau_dc = before, after, tau_dc

    @property
    def after_solution(self):
        """The phase-2b result itself (``solve_early`` passes the solve_ivp result here)."""
        return self.after

    def __call__(self, t):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.empty((2, t.size))
        m = t <= self.tau_dc
        if m.any():
            out[:, m] = self.before(t[m])[[0, 2]]
        if (~m).any():
            out[:, ~m] = self.after(t[~m])[[0, 1]]
        return out


class ContactTimes:
    """tau_dr and eta from tau_d and tau_dc, shared by every solution object (floats or mpf)."""

    @property
    def tau_dr(self):
        """Recovery time tau_d - tau_dc."""
        return self.tau_d - self.tau_dc

    @property
    def eta(self):
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
    _load: object  # OdeSolution in u, phase 1
    _mid: object  # (δ, w) in tau, phase 2 (before and after τ_dc)
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
    def e(self) -> float:
        # e = −δ'(τ_d), and δ'(τ_d) = w(τ_d) since F̄(τ_d) = 0
        return -self.w_end

    @property
    def F_m(self) -> float:
        return self.delta_m**1.5  # F̄ = δ^{3/2} is monotone in δ, so F_m sits at δ_m

    @property
    def xi(self) -> float:
        """Energy-loss ratio from the energy balance xi = 1 − e² = 2λ∫F̄² dτ (Eqs. 69, 74).

        Not 1 − w_end²: that cancels as λ → 0 (relative error 1e-7 at λ = 1e-6, a negative
        xi at λ = 0). 2λJ is a product of positive numbers, exactly 0 at λ = 0, and as relatively
        accurate as J.
        """
        return 2.0 * self.lam * self.int_F2

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


def _check_tol(name, value, low, high, text):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number in {text}, got {value!r}")
    x = float(value)
    if not (np.isfinite(x) and low <= x <= high):
        raise ValueError(f"{name} must be a finite number in {text}, got {value!r}")
    return x


def check_options(rtol=1e-12, atol=1e-15, method="DOP853") -> tuple:
    """Validate the integrator options before any work; ValueError naming the allowed values.

    rtol in [RTOL_MIN, RTOL_MAX], atol in (0, 1), both finite real numbers (not bool, str or None);
    method one of ``METHODS``. Returns (rtol, atol, method) as float, float, str.
    """
    rtol = _check_tol("rtol", rtol, RTOL_MIN, RTOL_MAX,
                      f"[{RTOL_MIN:.3g}, {RTOL_MAX:g}] (scipy's smallest rtol is 100 machine "
                      "epsilons; looser gives no correct digit)")
    if isinstance(atol, bool) or not isinstance(atol, numbers.Real) or not (
            np.isfinite(float(atol)) and 0.0 < float(atol) < 1.0):
        raise ValueError(f"atol must be a finite real number in (0, 1), got {atol!r}")
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(METHODS)}; got {method!r}")
    return rtol, float(atol), method


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
    atols = np.array([atol, 1e-300, atol])
    budget = _Budget(lam, method, rtol)
    try:
        s1, u1, (tau1, w1, J1) = _loading(lam, rtol, atols, method, budget)
        mid, tau_dc, delta_m, tau2, (d2, w2, J2) = _middle(lam, rtol, atol, method, tau1, u1, w1,
                                                           J1, budget)
        s3 = _unloading(lam, rtol, atols, method, tau2, d2, w2, J2, budget)
    except (ValueError, ZeroDivisionError, FloatingPointError) as exc:
        # scipy's own failures (e.g. LSODA's dense output on repeated times) are not input errors
        raise RuntimeError(f"exact solver: scipy {method} failed at lambda = {lam}, rtol = "
                           f"{rtol:g}: {exc}; the default method DOP853 does not") from exc
    tau_d, w_end, J_end = s3.y[:, -1]
    return ExactSolution(
        lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=float(tau_d),
        w_end=-float(restitution(2.0 * lam * float(J_end), -float(w_end))),
        int_F2=float(J_end), _load=s1.sol, _mid=mid, _unload=s3.sol, _tau1=float(tau1),
        _tau2=tau2, _u_grid1=s1.t, _tau_grid1=s1.y[0], _u_grid3=s3.t, _tau_grid3=s3.y[0],
    )


def restitution(xi, e_direct):
    """e from the energy loss xi where that is the better route, else ``e_direct``.

    While xi < 1/2, e = sqrt(1 - xi) with xi formed without cancellation: as accurate as the
    directly computed e, never above 1 and exactly 1 at lambda = 0 (the integrated end velocity
    and the tables' exp(log e) gave 1 + 1.2e-14 there). Above, 1 - xi cancels as e -> 0 and
    ``e_direct`` (relatively accurate) is kept. Scalars or arrays; the scipy solvers, the
    force-free end and the tables all take e from here.
    """
    xi = np.asarray(xi, dtype=float)
    return np.where(xi < 0.5, np.sqrt(np.maximum(1.0 - xi, 0.0)), e_direct)


def _loading(lam, rtol, atols, method, budget=None):
    """Phase 1: u from 0 until v = 1/2; returns (solution, u1, (τ1, w1, J1))."""
    # δ_m^{3/2} < 1/λ bounds u; at λ = 0, δ_m < 1.1.
    u_cap = min(1.2, lam ** (-1.0 / 3.0)) if lam > 0 else 1.2

    def v_half(u, y):
        return y[1] - lam * u**3 - _V_SWITCH

    v_half.terminal, v_half.direction = True, -1
    s1 = solve_ivp(_rhs_u(lam, budget), (0.0, u_cap), [0.0, 1.0, 0.0], method=method, rtol=rtol,
                   atol=atols, events=v_half, dense_output=True)
    if s1.status != 1:
        raise RuntimeError(f"exact solver: loading phase did not reach v = 1/2 at lambda = {lam}")
    return s1, float(s1.t_events[0][0]), tuple(s1.y_events[0][0])


def _middle(lam, rtol, atol, method, tau1, u1, w1, J1, budget=None, t_stop=None):
    """Phase 2 in τ from τ1; returns (dense (δ, w), τ_dc, δ_m, τ2, (δ2, w2, J2)).

    2a, state (δ, v, w, J) up to the end of compression, the event v = 0 on the state v (which
    gets no absolute tolerance: relative control down to its zero). 2b, state (δ, w, J) from
    τ_dc to the hand-over to u where the u-form is not stiff, |∂(dw/du)/∂w|·u = 2u⁵/v² <= 1,
    i.e. v² >= 2δ^{5/2}; after the end of compression v² − 2δ^{5/2} only increases, so the rising
    crossing is unique. With ``t_stop``, 2b runs for t_stop past τ_dc instead (no hand-over;
    the returned τ2 and state are then None).
    """

    def v_zero(t, y):
        return y[1]

    v_zero.terminal, v_zero.direction = True, -1
    t_cap = tau1 + 100.0 + 100.0 * lam
    v1 = w1 - lam * u1**3
    sa = solve_ivp(_rhs_tau_v(lam, budget), (tau1, t_cap), [u1 * u1, v1, w1, J1], method=method,
                   rtol=rtol, atol=np.array([atol, 1e-300, 1e-300, atol]), events=v_zero,
                   dense_output=True)
    if sa.status != 1:
        raise RuntimeError(f"exact solver: no end of compression at lambda = {lam}: {sa.message}")
    tau_dc = float(sa.t_events[0][0])
    delta_m, _, w_dc, J_dc = (float(x) for x in sa.y_events[0][0])

    def hand_over(t, y):
        d = max(y[0], 0.0)
        v = y[1] - lam * d * np.sqrt(d)
        return v * v - 2.0 * d * d * np.sqrt(d)

    hand_over.terminal, hand_over.direction = True, 1
    if t_stop is not None:
        # dense output does not change the steps: the end state is the one without it
        sb = solve_ivp(_rhs_tau(lam, budget), (tau_dc, tau_dc + t_stop), [delta_m, w_dc, J_dc],
                       method=method, rtol=rtol, atol=np.array([atol, 1e-300, atol]),
                       first_step=1e-3 * tau_dc, dense_output=True)
        return _TwoPieces(sa.sol, sb, tau_dc), tau_dc, delta_m, None, None
    # first_step: LSODA's own first step from this state (δ' = 0) can have zero length, which its
    # dense output refuses; the other methods' error control corrects any first step
    sb = solve_ivp(_rhs_tau(lam, budget), (tau_dc, t_cap), [delta_m, w_dc, J_dc], method=method,
                   rtol=rtol, atol=np.array([atol, 1e-300, atol]), events=hand_over,
                   dense_output=True, first_step=1e-3 * tau_dc)
    if sb.status != 1:
        raise RuntimeError(f"exact solver: middle phase failed at lambda = {lam}: {sb.message}")
    d2, w2, J2 = sb.y_events[0][0]
    return (_TwoPieces(sa.sol, sb.sol, tau_dc), tau_dc, delta_m, float(sb.t_events[0][0]),
            (d2, w2, J2))


def _unloading(lam, rtol, atols, method, tau2, d2, w2, J2, budget=None):
    """Phase 3: u from √δ2 down to 0; the end of contact is the endpoint u = 0."""
    s3 = solve_ivp(_rhs_u(lam, budget), (np.sqrt(d2), 0.0), [tau2, w2, J2], method=method, rtol=rtol,
                   atol=atols, dense_output=True)
    if s3.status != 0:
        raise RuntimeError(f"exact solver: unloading phase failed at lambda = {lam}: {s3.message}")
    return s3


def solve_early(lam: float, span: float, rtol: float = 1e-13, atol: float = 1e-15) -> dict:
    """Integrate Eq. (10) from the impact to ``span`` past the end of compression (DOP853).

    For large lambda the rest of the contact follows one universal orbit (see
    ``zener_sym.exact.table_build``), so the tables need only this early part per lambda: phase 1,
    phase 2a up to τ_dc and phase 2b for ``span`` more. Returns tau_dc, delta_m, the state
    (tau, delta, w, J) at tau_dc + span, and ``solution``: an ``ExactSolution`` of that early part
    (its ``history`` valid for 0 <= tau < tau_dc + span; its tau_d, w_end, int_F2 are the end
    state's, not the contact's).
    """
    rtol, atol, method = check_options(rtol=rtol, atol=atol, method="DOP853")
    lam = float(lam)
    atols = np.array([atol, 1e-300, atol])
    budget = _Budget(lam, method, rtol)
    s1, u1, (tau1, w1, J1) = _loading(lam, rtol, atols, method, budget)
    mid, tau_dc, delta_m, _, _ = _middle(lam, rtol, atol, method, tau1, u1, w1, J1, budget,
                                         t_stop=None if span is None else span)
    sb = mid.after_solution
    tau_m = float(sb.t[-1])
    mid.after = sb.sol  # (delta, w) rows as in a full solve's middle phase
    early = ExactSolution(
        lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=tau_m, w_end=float(sb.y[1, -1]),
        int_F2=float(sb.y[2, -1]), _load=s1.sol, _mid=mid, _unload=None, _tau1=float(tau1),
        _tau2=tau_m, _u_grid1=s1.t, _tau_grid1=s1.y[0], _u_grid3=None, _tau_grid3=None)
    return {"tau_dc": tau_dc, "delta_m": delta_m, "tau": tau_m,
            "delta": float(sb.y[0, -1]), "w": float(sb.y[1, -1]), "J": float(sb.y[2, -1]),
            "solution": early}
