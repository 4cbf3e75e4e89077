"""High-precision (mpmath) solution of Zener's impact equation, Eq. (10), by a Taylor-series method.

The equation  δ'' + (1 + λ d/dτ) δ^{3/2} = 0,  δ(0) = 0,  δ'(0) = 1  is integrated in its
second-order form with four states,

    δ' = v,   v' = −F − (3/2) λ δ^{1/2} v,   w' = −F,   J' = F²,     F = δ^{3/2},

where v = δ' is the relative velocity, w = 1 − Ī the sphere velocity (Eq. 64) and J = ∫F̄² dτ.
v and w are carried separately (the first integral v = w − λF is not used), so the identities
Ī(τ_d) = 1 + e (with e = −v(τ_d)) and 1 − e² = 2λ∫F̄² dτ are checks of the integration, not
consequences of its construction.

Like the scipy path (:mod:`zener_sym.exact.solver`) the contact is split into three phases, each in a
variable in which the solution is analytic:

1. loading in u = √δ from the exact start u = 0, state (τ, v, w, J):
   dτ/du = 2u/v, dv/du = −2u⁴/v − 3λu², dw/du = −2u⁴/v, dJ/du = 2u⁷/v; up to v = 1/2;
2. middle in τ, state (δ, v, w, J), while δ > 0 (guarded); the end of compression v = 0 is found
   by Newton's method on the local Taylor polynomial; the phase hands over, in recovery, where
   v² >= 2δ^{5/2} (the criterion of the scipy path);
3. unloading in u again, down to the fixed endpoint u = 0 (the end of contact is no event).

Each step computes the Taylor coefficients of the state to order N by automatic-differentiation
(jet) recurrences: Cauchy products, the reciprocal 1/v and the square root √δ of a series. Only
1/v (phases 1 and 3) and √δ, δ√δ, √δ·v, F² (phase 2) need full convolutions.

Order and step (Jorba & Zou, Exp. Math. 14 (2005) 99): with the per-step absolute tolerance
ε = 10^−(dps+8), the order is N = ⌈−ln(ε)/2⌉ + 1 (the cost-optimal order for a cost ∝ N² per
step), the radius of convergence is estimated as ρ = min over states i and orders
j = N−5..N of |c_ij|^{−1/j} (six orders, because at u = 0 the series have only every fifth
coefficient nonzero at λ = 0), and the step is h = ρ e^{−2} e^{−0.7/(N−1)}, so that the first
neglected term is about |c_N| h^N <= e^{−2N} <= ε. The arithmetic runs at dps + 15 digits.
All states are O(1) or smaller except τ, so the tolerance is absolute; e = −v(τ_d) is then
accurate to about 10^−(dps+8) / e relative, i.e. dps digits for λ up to about 100 (e ≈ 1e−9).
"""
from __future__ import annotations

import bisect
import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np

from .. import params
from ..numerics.taylor import horner, root
from ..typing import FloatArray, RealArrayLike, RealLike
from .solver import LAMBDA_MAX, ContactTimes

__all__ = ["MpSolution", "solve", "check_dps", "DPS_MIN", "DPS_MAX"]

#: Smallest accepted number of decimal digits.
DPS_MIN = 15
#: Largest accepted number of decimal digits (the cost grows about as dps^3; at dps 30 lambda =
#: 1000 already takes about two minutes).
DPS_MAX = 100
_GUARD_TOL = 8  # digits by which the per-step tolerance is tighter than the requested dps
GUARD_WORK = 15  # extra digits of the working precision
_MAX_STEPS = 200_000  # per phase; far above what lambda <= LAMBDA_MAX needs
_V_SWITCH = mpmath.mpf(1) / 2  # relative velocity at which loading hands over from u to tau


@dataclass
class _Step:
    """One Taylor step: the polynomial  y_i(x0 + s) = Σ_k c[i][k] s^k  for s between 0 and h."""

    x0: Any  # mpf, as are h and the coefficients
    h: Any
    c: list[list[Any]]  # c[i][k]


@dataclass
class _Phase:
    kind: str  # "u" (states tau, v, w, J) or "tau" (states delta, v, w, J)
    steps: list[_Step] = field(default_factory=list)
    t_start: list[Any] = field(default_factory=list)  # tau (mpf) at each step's start, increasing
    # float copies for the vectorised history, built on demand
    _flt: tuple[FloatArray, FloatArray, FloatArray, FloatArray] | None = None

    def floats(self) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
        """Per-step arrays of x0, h, τ at start, and scaled coefficients c_k h^k as floats."""
        if self._flt is None:
            x0 = np.array([float(st.x0) for st in self.steps])
            h = np.array([float(st.h) for st in self.steps])
            rows = []
            for st in self.steps:
                hp = [mpmath.mpf(1)]
                for _ in range(len(st.c[0]) - 1):
                    hp.append(hp[-1] * st.h)
                rows.append([[float(ck * hk) for ck, hk in zip(ci, hp)] for ci in st.c])
            cs = np.array(rows)  # (steps, states, N+1): coefficients of σ = s/h in [0, 1]
            self._flt = (x0, h, np.array([float(t) for t in self.t_start]), cs)
        return self._flt


def _order(dps: int) -> int:
    return int(math.ceil((dps + _GUARD_TOL) * math.log(10) / 2)) + 1


def _step_size(c: list[list[Any]], N: int) -> Any:
    """h = ρ e^{-2} e^{-0.7/(N-1)} with ρ = min_ij |c_ij|^{-1/j}, j = N-5..N (module docstring)."""
    rho = None
    for ci in c:
        for j in range(max(1, N - 5), N + 1):
            a = abs(ci[j])
            if a:
                r = a ** (-mpmath.mpf(1) / j)
                rho = r if rho is None or r < rho else rho
    if rho is None:  # all tail coefficients vanish: the series is a short polynomial
        return mpmath.mpf(1)
    return rho * mpmath.exp(-2 - mpmath.mpf(0.7) / (N - 1))


def _jets_u(u0: Any, y0: Sequence[Any], lam: Any, N: int) -> list[list[Any]]:
    """Taylor coefficients in s = u − u0 of (τ, v, w, J) of the u-form (phases 1 and 3)."""
    tau, v, w, J = ([y] for y in y0)
    binom = mpmath.binomial
    P1 = [2 * u0, mpmath.mpf(2)]  # 2u
    P2 = [3 * lam * u0**2, 6 * lam * u0, 3 * lam]  # 3λu²
    P4 = [2 * binom(4, k) * u0 ** (4 - k) for k in range(5)]  # 2u⁴
    P7 = [2 * binom(7, k) * u0 ** (7 - k) for k in range(8)]  # 2u⁷
    q: list[Any] = []  # 1/v
    inv_v0 = 1 / v[0]
    fdot = mpmath.fdot
    for k in range(N):
        if k == 0:
            q.append(inv_v0)
        else:
            q.append(-fdot(v[1:k + 1], q[k - 1::-1]) * inv_v0)
        dtau = fdot(P1[:k + 1], q[k::-1][:2])
        A = fdot(P4[:k + 1], q[k::-1][:5])
        B = fdot(P7[:k + 1], q[k::-1][:8])
        dv = -A - (P2[k] if k < 3 else 0)
        tau.append(dtau / (k + 1))
        v.append(dv / (k + 1))
        w.append(-A / (k + 1))
        J.append(B / (k + 1))
    return [tau, v, w, J]


def _jets_tau(y0: Sequence[Any], lam: Any, N: int) -> list[list[Any]]:
    """Taylor coefficients in s = τ − τ0 of (δ, v, w, J) of the τ-form (phase 2)."""
    d, v, w, J = ([y] for y in y0)
    if not d[0] > 0:
        raise RuntimeError(f"exact.mp: delta = {d[0]} <= 0 inside the tau phase (guard)")
    sq = [mpmath.sqrt(d[0])]  # √δ
    two_s0 = 2 * sq[0]
    F: list[Any] = []
    c15 = mpmath.mpf(3) / 2 * lam
    fdot = mpmath.fdot
    for k in range(N):
        if k > 0:
            sq.append((d[k] - fdot(sq[1:k], sq[k - 1:0:-1])) / two_s0)
        F.append(fdot(d[:k + 1], sq[k::-1]))
        G = fdot(sq[:k + 1], v[k::-1])
        F2 = fdot(F[:k + 1], F[k::-1])
        d.append(v[k] / (k + 1))
        v.append((-F[k] - c15 * G) / (k + 1))
        w.append(-F[k] / (k + 1))
        J.append(F2 / (k + 1))
    return [d, v, w, J]


@dataclass
class MpSolution(ContactTimes):
    """High-precision solution of Eq. (10) for one lambda (all summary fields are ``mpf``).

    ``v_end`` = δ'(τ_d) and ``w_end`` = 1 − Ī(τ_d) are separate states; at the end of contact
    they agree (F̄ = 0 there), which the identity Ī = 1 + e checks.
    """

    # mpmath.mpf (untyped)
    lam: Any
    dps: int
    delta_m: Any
    tau_dc: Any
    tau_d: Any
    v_end: Any
    w_end: Any
    int_F2: Any
    n_steps: tuple[int, int, int]
    phases: list[_Phase] = field(repr=False)  # the Taylor steps (dense output), too long to print

    @property
    def e(self) -> Any:
        """Coefficient of restitution e = −δ'(τ_d) (mpf)."""
        return -self.v_end

    @property
    def F_m(self) -> Any:
        """Largest force F̄_m = δ_m^{3/2} (mpf)."""
        return self.delta_m * mpmath.sqrt(self.delta_m)  # F̄ = δ^{3/2} is monotone in δ

    @property
    def impulse(self) -> Any:
        """Ī(τ_d) = 1 − w_end (mpf)."""
        return 1 - self.w_end

    @property
    def xi(self) -> Any:
        """xi = 2λ∫F̄² dτ (energy balance, = 1 − e²): exactly 0 at λ = 0 and never negative,
        where 1 − w_end² would be a rounding-level number of either sign."""
        return 2 * self.lam * self.int_F2

    # --- history -------------------------------------------------------------------------

    def _locate(self, t: Any) -> tuple[_Phase, int]:
        """(phase, step index) holding the time t < τ_d."""
        for ph in reversed(self.phases):
            if t >= ph.t_start[0]:
                return ph, bisect.bisect_right(ph.t_start, t) - 1
        return self.phases[0], 0

    def history_mp(self, taus: Any) -> dict[str, list[Any]]:
        """δ, Ī, sphere velocity 1 − Ī and force δ^{3/2} as lists of mpf at the times ``taus``.

        Past the end of contact δ and the force are 0 and the impulse keeps its final value.

        Parameters
        ----------
        taus : mpf, float, str or a sequence of them
            Times, >= 0 (anything ``mpmath.mpf`` takes).

        Returns
        -------
        dict of str to list of mpf
            "tau", "delta", "impulse", "velocity", "force".

        Raises
        ------
        ValueError
            For a negative time.
        """
        times = [mpmath.mpf(t) for t in np.atleast_1d(np.asarray(taus, dtype=object)).ravel()]
        out: dict[str, list[Any]] = {k: [] for k in ("tau", "delta", "impulse", "velocity",
                                                     "force")}
        with mpmath.workdps(self.dps + GUARD_WORK):
            for t in times:
                if t < 0:
                    raise ValueError(f"tau must be >= 0 (contact starts at tau = 0), got {t}")
                if t >= self.tau_d:
                    d, w = mpmath.mpf(0), self.w_end
                else:
                    ph, i = self._locate(t)
                    st = ph.steps[i]
                    if ph.kind == "tau":
                        s = t - st.x0
                        d, w = horner(st.c[0], s), horner(st.c[2], s)
                    else:
                        s = root(st.c[0], t, st.h) if t != st.c[0][0] else mpmath.mpf(0)
                        u = st.x0 + s
                        d, w = u * u, horner(st.c[2], s)
                    d = max(d, mpmath.mpf(0))
                out["tau"].append(t)
                out["delta"].append(+d)
                out["impulse"].append(1 - w)
                out["velocity"].append(+w)
                out["force"].append(d * mpmath.sqrt(d))
        return out

    def history(self, tau: RealArrayLike) -> dict[str, FloatArray]:
        """Float arrays tau, delta, impulse, velocity (1 − Ī) and force at ``tau`` (>= 0).

        Evaluates the stored Taylor polynomials in double precision (the u-phases invert τ(u)
        by Newton's method), so the error is a few ulps of each field's scale.

        Parameters
        ----------
        tau : array_like
            Times, finite and >= 0.

        Returns
        -------
        dict of str to ndarray
            "tau", "delta", "impulse", "velocity", "force", each of tau's shape.

        Raises
        ------
        ValueError
            For a negative or non-finite time.
        """
        t_arr: FloatArray = params.as_tau(tau)
        flat = t_arr.ravel()
        d_flat = np.zeros_like(flat)
        w_flat = np.full_like(flat, float(self.w_end))
        for ph in self.phases:
            x0, h, t0, cs = ph.floats()
            idx = np.nonzero((flat >= t0[0]) & (flat < float(self.tau_d)))[0]
            if ph is not self.phases[-1]:
                nxt = self.phases[self.phases.index(ph) + 1].t_start[0]
                idx = idx[flat[idx] < float(nxt)]
            if idx.size == 0:
                continue
            k = np.clip(np.searchsorted(t0, flat[idx], side="right") - 1, 0, len(t0) - 1)
            C = cs[k]  # (m, states, N+1), coefficients of σ = s/h in [0, 1]
            if ph.kind == "tau":
                sig = (flat[idx] - t0[k]) / h[k]
                d = horner(C[:, 0].T, sig)
            else:
                sig = _invert_np(C[:, 0], flat[idx])
                u = x0[k] + sig * h[k]
                d = u * u
            d_flat[idx] = d
            w_flat[idx] = horner(C[:, 2].T, sig)
        delta = np.maximum(d_flat, 0.0).reshape(t_arr.shape)
        w = w_flat.reshape(t_arr.shape)
        return {"tau": t_arr, "delta": delta, "impulse": 1.0 - w, "velocity": w,
                "force": delta**1.5}


def _invert_np(C: FloatArray, t: FloatArray) -> FloatArray:
    """σ in [0, 1] with Σ_k C_k σ^k = t (τ monotone along a u-step), by Newton from a √-guess."""
    t_a, t_b = C[:, 0], C.sum(axis=1)
    frac = np.clip((t - t_a) / (t_b - t_a), 0.0, 1.0)
    sig: FloatArray = frac.copy()
    dC = C[:, 1:] * np.arange(1, C.shape[1])
    for _ in range(60):
        p, dp = horner(C.T, sig), horner(dC.T, sig)
        with np.errstate(divide="ignore", invalid="ignore"):
            ds = np.where(dp != 0.0, (p - t) / dp, 0.0)
        sig = np.clip(sig - ds, 0.0, 1.0)
        if np.all(np.abs(ds) <= 1e-15):
            break
    return sig


def check_dps(dps: object) -> int:
    """Validate the number of decimal digits of the mpmath solution.

    Parameters
    ----------
    dps : int
        An integer (not bool) in [DPS_MIN, DPS_MAX].

    Returns
    -------
    int
        dps.

    Raises
    ------
    ValueError
        If dps is not an integer or outside [DPS_MIN, DPS_MAX].
    """
    if isinstance(dps, bool) or not isinstance(dps, numbers.Integral):
        raise ValueError(f"dps must be an integer in [{DPS_MIN}, {DPS_MAX}] (decimal digits), "
                         f"got {dps!r}")
    n = int(dps)
    if not DPS_MIN <= n <= DPS_MAX:
        raise ValueError(f"dps must be in [{DPS_MIN}, {DPS_MAX}] (decimal digits), got {dps}")
    return n


_check_dps = check_dps


def solve(lam: RealLike, dps: int = 30) -> MpSolution:
    """Integrate Eq. (10) for one lambda to the end of contact with about ``dps`` correct digits.

    Parameters
    ----------
    lam : float
        Inelasticity parameter (Eq. 11), 0 <= lam <= LAMBDA_MAX; converted exactly from the
        float to mpf.
    dps : int
        Decimal digits wanted, DPS_MIN <= dps <= DPS_MAX (15 to 100). The work runs at dps + 15 digits with the per-step
        tolerance 10^-(dps+8) (see the module docstring for the order and step rule).

    Returns
    -------
    MpSolution

    Raises
    ------
    ValueError
        For a bad lambda (not a finite scalar in [0, LAMBDA_MAX]) or a bad dps.
    """
    arr = params.as_lambda(lam)
    if arr.size != 1:
        raise ValueError(f"lambda must be a single number for exact_mp.solve, got shape {arr.shape}")
    params.check_lambda_bound(arr, np.nextafter(LAMBDA_MAX, np.inf), "exact (mpmath)",
                              "the range over which the integrator is tested")
    dps = _check_dps(dps)
    N = _order(dps)
    with mpmath.workdps(dps + GUARD_WORK):
        lam_mp = mpmath.mpf(float(arr.reshape(-1)[0]))
        return _integrate(lam_mp, dps, N)


def _integrate(lam: Any, dps: int, N: int) -> MpSolution:
    zero, one = mpmath.mpf(0), mpmath.mpf(1)

    # Phase 1: u from 0, state (τ, v, w, J), until v = 1/2.
    p1 = _Phase("u")
    u, y = zero, [zero, one, one, zero]
    for _ in range(_MAX_STEPS):
        c = _jets_u(u, y, lam, N)
        h = _step_size(c, N)
        done = horner(c[1], h) <= _V_SWITCH
        if done:
            h = root(c[1], _V_SWITCH, h)
        p1.steps.append(_Step(u, h, c))
        p1.t_start.append(y[0])
        y = [horner(ci, h) for ci in c]
        u = u + h
        if done:
            break
    else:
        raise RuntimeError(f"exact.mp: loading phase did not reach v = 1/2 at lambda = {lam}")

    # Phase 2: τ, state (δ, v, w, J). Events: v = 0 (end of compression) by Newton on the
    # local polynomial; hand-over to u at the end of the first recovery step with v² >= 2δ^{5/2}.
    p2 = _Phase("tau")
    t = y[0]
    y = [u * u, y[1], y[2], y[3]]
    tau_dc = delta_m = None
    for _ in range(_MAX_STEPS):
        c = _jets_tau(y, lam, N)
        h = _step_size(c, N)
        y_new = [horner(ci, h) for ci in c]
        if not y_new[0] > 0:  # guard: never step to δ <= 0 in the τ-form
            raise RuntimeError(f"exact.mp: tau phase stepped to delta <= 0 at lambda = {lam}")
        p2.steps.append(_Step(t, h, c))
        p2.t_start.append(t)
        if tau_dc is None and y_new[1] <= 0:
            s = root(c[1], zero, h)
            tau_dc, delta_m = t + s, horner(c[0], s)
        t, y = t + h, y_new
        if tau_dc is not None and y[1] < 0 and y[1] ** 2 >= 2 * y[0] ** 2 * mpmath.sqrt(y[0]):
            break
    else:
        raise RuntimeError(f"exact.mp: tau phase did not hand over at lambda = {lam}")

    # Phase 3: u from √δ down to the fixed endpoint u = 0, state (τ, v, w, J).
    p3 = _Phase("u")
    u = mpmath.sqrt(y[0])
    y = [t, y[1], y[2], y[3]]
    for _ in range(_MAX_STEPS):
        c = _jets_u(u, y, lam, N)
        h = -min(_step_size(c, N), u)
        last = -h >= u
        p3.steps.append(_Step(u, h, c))
        p3.t_start.append(y[0])
        y = [horner(ci, h) for ci in c]
        u = zero if last else u + h
        if last:
            break
    else:
        raise RuntimeError(f"exact.mp: unloading phase did not reach u = 0 at lambda = {lam}")

    tau_d, v_end, w_end, J_end = y
    return MpSolution(lam=lam, dps=dps, delta_m=delta_m, tau_dc=tau_dc, tau_d=tau_d,
                      v_end=v_end, w_end=w_end, int_F2=J_end,
                      n_steps=(len(p1.steps), len(p2.steps), len(p3.steps)),
                      phases=[p1, p2, p3])
