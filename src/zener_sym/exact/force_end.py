"""Eq. (10) read as the viscoelastic contact of two grains: the contact ends where the force vanishes.

Between viscoelastic grains (Kuwabara & Kono 1987; Brilliantov et al. 1996) the contact force is

    F_c = delta^{3/2} + lambda (delta^{3/2})' = sqrt(delta) (delta + (3/2) lambda delta') = -delta'',

which turns attractive in recovery before delta returns to 0. Grains cannot pull, so they separate
where F_c = 0 (Schwager & Poeschel 2008): ``contact_end="force"``, the first time after the end of
compression with delta + (3/2) lambda delta' = 0. The mapping to physical grains is derived in
``zener_sym.derivation.viscoelastic``. In this reading the fields are those of the grain contact:

- ``force`` is F_c (not the plate's Hertz force delta^{3/2}) and ``F_m`` its maximum, which lies
  before the end of compression (during loading at large lambda);
- ``velocity`` is the relative velocity delta' = 1 - impulse and ``impulse`` = int F_c dtau, so
  I(tau_d) = 1 + e with e = -delta'(tau_d);
- ``int_F2`` = int F_c^2 dtau over the contact and ``xi`` = 1 - e^2. This reading has no
  2 lambda int F^2 identity; its energy balance (``derivation/viscoelastic.py``) is

      xi = 1 - e^2 = 3 lambda int_0^tau_d sqrt(delta) delta'^2 dtau + (4/5) delta(tau_d)^{5/2},

  the dashpot's dissipation plus the elastic energy left in the grains at separation (which their
  bulk dissipates later). Both terms are positive, so xi is formed from them without the
  cancellation of 1 - e^2 when e -> 1 (small lambda): exactly 0 at lambda = 0, never negative;
- past tau_d the history has delta = 0, force 0 and the separation velocity.

Two independent paths, as for the plate:

:func:`solve` (scipy)
    the three phases of :mod:`.solver` (u = sqrt(delta) at both ends, tau in the middle) with the
    force-free end as a terminal event (phase 2 or 3), the peak of F_c as an event (phase 1 or 2),
    int F_c^2 as the third state and the dissipation int sqrt(delta) delta'^2 as the fourth (for
    xi). The solver module itself is untouched.
:func:`solve_mp` (mpmath)
    the plate's Taylor solution of :mod:`.mp`, cut at the force-free end: every step is a
    polynomial, so the end (a root of delta + (3/2) lambda v), the peak (a root of F_c') and
    int F_c^2 (a polynomial integral) come from the stored steps by Newton's method and exact
    integration; xi = 1 - e^2 is formed at the working precision (30 digits and guard digits by
    default), so its cancellation near e = 1 costs nothing a float reference could see.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath
import numpy as np
from scipy.integrate import solve_ivp

from .. import params
from . import mp as _mp
from .solver import (LAMBDA_MAX, ContactTimes, ExactSolution, _Budget, check_options,
                     restitution)
from .solver import solve as _solve_plate

__all__ = ["CONTACT_ENDS", "check_contact_end", "ForceEndSolution", "solve", "solve_mp"]

#: The accepted end-of-contact criteria.
CONTACT_ENDS = ("delta", "force")

_V_SWITCH = 0.5


def check_contact_end(contact_end) -> str:
    """Validate the end-of-contact criterion: ``"delta"`` (plate, delta = 0) or ``"force"`` (grains)."""
    if not isinstance(contact_end, str) or contact_end not in CONTACT_ENDS:
        raise ValueError(f"unknown contact_end {contact_end!r}; allowed: 'delta' (the plate: contact "
                         f"ends at delta = 0) or 'force' (viscoelastic grains: contact ends where "
                         f"delta^(3/2) + lambda (delta^(3/2))' = 0)")
    return contact_end


@dataclass
class ForceEndSolution(ContactTimes):
    """Solution of Eq. (10) ended at the force-free point (grain reading, module docstring).

    ``v_end`` is delta'(tau_d) (the separation velocity is -v_end = e); ``xi`` = 1 - e^2 formed
    without cancellation (module docstring). ``_base`` is the plate-style solution object cut at
    tau_d, used for the dense history of delta and w = 1 - int delta^{3/2}.
    """

    lam: float
    delta_m: float
    tau_dc: float
    tau_d: float
    v_end: float
    int_F2: float
    F_m: float
    xi: float
    _base: object = None

    @property
    def e(self):
        return -self.v_end

    @property
    def impulse(self):
        return 1 - self.v_end

    def history(self, tau) -> dict:
        """delta, velocity delta', force F_c and impulse 1 - delta' at ``tau`` (>= 0), float arrays."""
        tau = params.as_tau(tau)
        tau_d = float(self.tau_d)
        h = self._base.history(np.minimum(tau, np.nextafter(tau_d, 0.0)))
        lam = float(self.lam)
        d = np.maximum(np.asarray(h["delta"], dtype=float), 0.0)
        v = np.asarray(h["velocity"], dtype=float) - lam * d**1.5  # w - lambda delta^{3/2}
        fc = np.sqrt(d) * (d + 1.5 * lam * v)
        after = tau >= tau_d
        d, v, fc = np.where(after, 0.0, d), np.where(after, float(self.v_end), v), np.where(after, 0.0, fc)
        return {"tau": tau, "delta": d, "velocity": v, "force": fc, "impulse": 1.0 - v}


# --- scipy path ------------------------------------------------------------------------------

def _rhs_u(lam, budget):
    """u-form with J = int F_c^2 and D = int sqrt(delta) delta'^2: dtau/du = 2u/v,
    dw/du = -2u^4/v, dJ/du = 2u F_c^2/v, dD/du = 2u^2 v."""

    def f(u, y):
        budget.spend()
        v = y[1] - lam * u**3
        if abs(v) < 1e-300:
            v = 1e-300 if v >= 0 else -1e-300
        g = 2.0 * u / v
        fc = u**3 + 1.5 * lam * u * v
        return np.array([g, -g * u**3, g * fc * fc, 2.0 * u * u * v])

    return f


def _rhs_tau(lam, budget):
    """Middle phase in tau, state (delta, v, g, w, J, D): v = delta' and g = delta + (3/2) lam v
    (F_c = sqrt(delta) g) carried as their own states,

        v' = -sqrt(delta) (delta + (3/2) lam v)   (Eq. 10),   g' = v - (3/2) lam sqrt(delta) g.

    At large lambda the end of compression (v = 0) and the force-free end (g = 0, a short time
    later, where v is small) would otherwise be found on w - lam delta^{3/2} or on delta + (3/2)
    lam v, differences of nearly equal numbers: tau_dc was off by 1.7e-9 relative at lambda =
    1000 and tau_d by 7e-6 (w form) or 1.4e-10 at lambda = 300 (v form), since g crosses 0 with
    slope v = -delta / ((3/2) lam). Each event reads the state that vanishes there, which is
    relatively accurate near its zero (no absolute tolerance), and g's own equation damps errors
    fed in from v (rate (3/2) lam sqrt(delta))."""
    k = 1.5 * lam

    def f(t, y):
        budget.spend()
        d = y[0] if y[0] > 0.0 else 0.0
        s = np.sqrt(d)
        v, g = y[1], y[2]
        fc = s * (d + k * v)
        return np.array([v, -fc, v - k * s * g, -d * s, fc * fc, s * v * v])

    return f


class _Rows:
    """Dense output restricted to the rows (delta, w) that the plate's history reads."""

    def __init__(self, sol):
        self.sol = sol

    def __call__(self, t):
        return self.sol(t)[[0, 3]]


def solve(lam: float, rtol: float = 1e-13, atol: float = 1e-16, method: str = "DOP853") -> ForceEndSolution:
    """Integrate Eq. (10) for one lambda (0 <= lam <= LAMBDA_MAX, validated by the caller) to the
    force-free end.

    Options as in :func:`zener_sym.exact.solver.solve` (checked here before any work, with the
    same evaluation budget, so no option makes a call hang); the default tolerance is ten times
    tighter than the plate's. Measured against :func:`solve_mp` (``tests/test_viscoelastic.py``):
    every summary field within 5e-14 relative for 0 <= lambda <= 1000 with these defaults.
    """
    rtol, atol, method = check_options(rtol, atol, method)
    lam = float(lam)
    if lam == 0.0:  # F_c = delta^{3/2}: the force-free end is delta = 0
        s = _solve_plate(0.0, rtol=rtol, atol=atol, method=method)
        return ForceEndSolution(lam=0.0, delta_m=s.delta_m, tau_dc=s.tau_dc, tau_d=s.tau_d,
                                v_end=s.w_end, int_F2=s.int_F2, F_m=s.F_m, xi=0.0, _base=s)
    budget = _Budget(lam, method, rtol)
    atols = np.array([atol, 1e-300, atol, atol])
    k = 1.5 * lam
    u_cap = min(1.2, lam ** (-1.0 / 3.0))

    def v_half(u, y):
        return y[1] - lam * u**3 - _V_SWITCH

    v_half.terminal, v_half.direction = True, -1

    def peak_u(u, y):  # proportional to dF_c/du; F_c = u^3 + k u v
        v = y[1] - lam * u**3
        dv = -2.0 * u**4 / v - 3.0 * lam * u**2
        return 3.0 * u**2 + k * (v + u * dv)

    peak_u.direction = -1
    s1 = solve_ivp(_rhs_u(lam, budget), (0.0, u_cap), [0.0, 1.0, 0.0, 0.0], method=method, rtol=rtol, atol=atols,
                   events=[v_half, peak_u], dense_output=True)
    if s1.status != 1:
        raise RuntimeError(f"exact (force end): loading phase did not reach v = 1/2 at lambda = {lam}")
    u1 = float(s1.t_events[0][0])
    tau1, w1, J1, D1 = s1.y_events[0][0]
    F_m = None
    if len(s1.t_events[1]):
        up = float(s1.t_events[1][0])
        vp = s1.y_events[1][0][1] - lam * up**3
        F_m = up**3 + k * up * vp

    def v_zero(t, y):
        return y[1]

    v_zero.direction = -1

    def peak_t(t, y):  # proportional to dF_c/dtau: 2 delta v + lam v^2 - 2 lam delta F_c
        d = max(y[0], 0.0)
        v = y[1]
        return 2.0 * d * v + lam * v * v - 2.0 * lam * d * np.sqrt(d) * y[2]

    peak_t.direction = -1

    def hand_over(t, y):
        d = max(y[0], 0.0)
        return y[1] * y[1] - 2.0 * d * d * np.sqrt(d)

    hand_over.terminal, hand_over.direction = True, 1

    def free_t(t, y):  # force-free: g = delta + (3/2) lam v = 0
        return y[2]

    free_t.terminal, free_t.direction = True, -1
    t_cap = tau1 + 100.0 + 100.0 * lam
    v1 = w1 - lam * u1**3
    # v and g get no absolute tolerance: relative control down to their zeros (as the plate's
    # phase 2a)
    atols6 = np.array([atol, 1e-300, 1e-300, 1e-300, atol, atol])
    y1 = [u1 * u1, v1, u1 * u1 + k * v1, w1, J1, D1]
    s2 = solve_ivp(_rhs_tau(lam, budget), (tau1, t_cap), y1, method=method, rtol=rtol, atol=atols6, events=[v_zero, peak_t, hand_over, free_t],
                   dense_output=True)
    if s2.status != 1 or len(s2.t_events[0]) != 1:
        raise RuntimeError(f"exact (force end): middle phase failed at lambda = {lam}: {s2.message}")
    tau_dc = float(s2.t_events[0][0])
    delta_m = float(s2.y_events[0][0][0])
    if F_m is None:
        if not len(s2.t_events[1]):
            raise RuntimeError(f"exact (force end): no peak of the force found at lambda = {lam}")
        d, _, g = s2.y_events[1][0][:3]
        F_m = float(np.sqrt(d) * g)
    s3 = None
    if len(s2.t_events[3]):  # the force vanished in the middle phase (large lambda)
        tau_d = float(s2.t_events[3][0])
        d, v_end, _, w, J, D = s2.y_events[3][0]
        d_end = d
        tau2 = tau_d
    else:
        tau2 = float(s2.t_events[2][0])
        d2, _, _, w2, J2, D2 = s2.y_events[2][0]

        def free_u(u, y):
            return u * u + k * (y[1] - lam * u**3)

        free_u.terminal, free_u.direction = True, -1
        s3 = solve_ivp(_rhs_u(lam, budget), (np.sqrt(d2), 0.0), [tau2, w2, J2, D2], method=method, rtol=rtol,
                       atol=atols, events=free_u, dense_output=True)
        if s3.status != 1:
            raise RuntimeError(f"exact (force end): no force-free point before delta = 0 at lambda = {lam}")
        ue = float(s3.t_events[0][0])
        tau_d, w, J, D = s3.y_events[0][0]
        v_end = w - lam * ue**3
        d_end = ue * ue
    base = ExactSolution(
        lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=float(tau_d), w_end=float(w), int_F2=float(J),
        _load=s1.sol, _mid=_Rows(s2.sol), _unload=s3.sol if s3 is not None else None, _tau1=float(tau1),
        _tau2=float(tau2), _u_grid1=s1.t, _tau_grid1=s1.y[0],
        _u_grid3=s3.t if s3 is not None else None, _tau_grid3=s3.y[0] if s3 is not None else None)
    xi = float(3.0 * lam * D + 0.8 * max(d_end, 0.0) ** 2.5)
    return ForceEndSolution(lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=float(tau_d),
                            v_end=-float(restitution(xi, -float(v_end))), int_F2=float(J),
                            F_m=float(F_m), xi=xi, _base=base)


# --- mpmath path -----------------------------------------------------------------------------

def _deriv(c):
    return [k * c[k] for k in range(1, len(c))]


def _mul(a, b):
    out = [mpmath.mpf(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                out[i + j] += x * y
    return out


def _integral(c, s):
    """int_0^s sum c_k x^k dx."""
    return mpmath.fsum(ck * s ** (k + 1) / (k + 1) for k, ck in enumerate(c))


def _fc_poly(ph, st, lam):
    """F_c on one Taylor step as a polynomial in s, and dtau/ds (1 on tau steps)."""
    if ph.kind == "tau":  # F_c = -v'
        return [-x for x in _deriv(st.c[1])], [mpmath.mpf(1)]
    u = [st.x0, mpmath.mpf(1)]  # u = x0 + s
    u3 = _mul(_mul(u, u), u)
    fc = _mul(u, [mpmath.mpf(3) / 2 * lam * x for x in st.c[1]])
    fc = [(fc[i] if i < len(fc) else 0) + (u3[i] if i < len(u3) else 0) for i in range(max(len(fc), len(u3)))]
    return fc, _deriv(st.c[0])


def _root_in(poly, h):
    """Root of poly in [0, h] (a sign change between the ends) by bisection-safeguarded Newton."""
    dp = _deriv(poly)
    a, b = mpmath.mpf(0), h
    fa = _mp._horner(poly, a)
    s = h / 2
    for _ in range(200):
        f = _mp._horner(poly, s)
        if (f > 0) == (fa > 0):
            a, fa = s, f
        else:
            b = s
        d = _mp._horner(dp, s) if dp else 0
        nxt = s - f / d if d else (a + b) / 2
        if not (min(a, b) <= nxt <= max(a, b)):
            nxt = (a + b) / 2
        if abs(nxt - s) <= abs(h) * mpmath.mpf(2) ** (-mpmath.mp.prec + 6):
            return nxt
        s = nxt
    raise RuntimeError("exact (force end, mpmath): root search did not converge")


def solve_mp(lam, dps: int = 30) -> ForceEndSolution:
    """High-precision force-free end (mpmath); fields are mpf. Same arguments as
    :func:`zener_sym.exact.mp.solve`, which validates them."""
    sol = _mp.solve(lam, dps=dps)
    with mpmath.workdps(sol.dps + _mp._GUARD_WORK):
        L = sol.lam
        k = mpmath.mpf(3) / 2 * L
        if L == 0:
            return ForceEndSolution(lam=L, delta_m=sol.delta_m, tau_dc=sol.tau_dc, tau_d=sol.tau_d,
                                    v_end=sol.v_end, int_F2=sol.int_F2, F_m=sol.F_m,
                                    xi=mpmath.mpf(0), _base=sol)
        F_m = None
        J = mpmath.mpf(0)
        for ph in sol._phases:
            for i, st in enumerate(ph.steps):
                fc, dtau = _fc_poly(ph, st, L)
                t0 = ph.t_start[i]
                # peak of F_c: F_c' (in s) changes sign from + to -
                if F_m is None:
                    dfc = _deriv(fc)
                    if _mp._horner(dfc, st.h) <= 0:
                        s = _root_in(dfc, st.h) if _mp._horner(dfc, 0) > 0 else mpmath.mpf(0)
                        F_m = _mp._horner(fc, s)
                # force-free end, after the end of compression
                if ph.kind == "tau":
                    g = [st.c[0][j] + k * st.c[1][j] for j in range(len(st.c[0]))]
                else:
                    g = [k * x for x in st.c[1]]
                    g[0] += st.x0**2
                    g[1] += 2 * st.x0
                    g[2] += 1
                past_dc = t0 >= sol.tau_dc or _mp._horner(st.c[1], st.h) < 0
                if F_m is not None and past_dc and _mp._horner(g, st.h) <= 0:
                    s = _root_in(g, st.h)
                    J += _integral(_mul(_mul(fc, fc), dtau), s)
                    v_end = _mp._horner(st.c[1], s)
                    tau_d = t0 + s if ph.kind == "tau" else _mp._horner(st.c[0], s)
                    return ForceEndSolution(lam=L, delta_m=sol.delta_m, tau_dc=sol.tau_dc, tau_d=tau_d,
                                            v_end=v_end, int_F2=J, F_m=F_m, xi=1 - v_end**2,
                                            _base=sol)
                J += _integral(_mul(_mul(fc, fc), dtau), st.h)
    raise RuntimeError(f"exact (force end, mpmath): no force-free point found at lambda = {lam}")
