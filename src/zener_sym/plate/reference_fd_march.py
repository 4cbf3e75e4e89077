r"""The time march of the second method (:mod:`.reference_fd`): the sphere and the finite-element
plate, stepped by the implicit midpoint rule with the Hertz force as a discrete gradient, every
contact's start and end landed on exactly by a shortened step.

One step of length h from (u, v, x, p), with the plate M w'' + beta^2 K w = 8 lambda beta F e_0
and the ball x'' = -F:

    u+ - u = h (v + v+)/2,       M (v+ - v) = h (-beta^2 K (u + u+)/2 + 8 lambda beta G e_0),
    x+ - x = h (p + p+)/2,       p+ - p = -h G,
    G = (Phi(delta+) - Phi(delta)) / (delta+ - delta),   Phi(d) = (2/5) max(d, 0)^{5/2}.

The plate's update is du = du_free + G g, g = A^-1 (8 lambda beta e_0), A = (2/h^2) M +
(beta^2/2) K (factorised once per step length), so delta+ = delta* - s G with s = h^2/2 + g_0,
a scalar equation whose left side delta+ + s G(delta, delta+) increases strictly: one root.
Summing the four equations, E = p^2/2 + Phi(delta) + (v^T M v + beta^2 u^T K u)/(16 lambda beta)
is conserved exactly by every step, whatever h.

Events. The force F = max(delta, 0)^{3/2} is not smooth where a contact starts or ends; a step
across such a point has a local error that depends on where in the step the point falls. So a
step that would cross delta = 0 is replaced by the shorter step that lands on delta = 0 (its
length found by the Illinois variant of regula falsi, each trial step with its own
factorisation), and the march goes on with the regular step from there; the contact's start and
end are then times the march reaches, not interpolations. (Measured on the issue's glass plate:
this moved the step-extrapolated e by about 1e-7; what remains irregular in the step at the 1e-6
level is the pre-asymptotic range of the coarsest steps, see ``reference_impact``.)
"""
from __future__ import annotations

import math
import numpy as np
import scipy.linalg
from scipy.linalg.blas import dsbmv
from scipy.linalg.lapack import dpbtrs

from ..typing import FloatArray
from .reference_fe import AxisymmetricPlateFE, upper_band

__all__ = ["hertz_secant", "march", "RawContact"]

#: (start, end, max_force, impulse, speed_after) of one contact, in Zener's scales.
RawContact = tuple[float, float, float, float, float]


def hertz_secant(a: float, b: float) -> float:
    """The discrete gradient (Phi(b) - Phi(a)) / (b - a) of Phi = (2/5) max(d, 0)^{5/2}, free of
    cancellation (Phi'(a) = max(a, 0)^{3/2} when a == b)."""
    if a <= 0.0 and b <= 0.0:
        return 0.0
    if a <= 0.0 or b <= 0.0:
        hi, lo = (a, b) if a > b else (b, a)
        return 0.4 * math.pow(hi, 2.5) / (hi - lo)
    p, q = math.sqrt(a), math.sqrt(b)
    # (q^5 - p^5) / (q^2 - p^2) with the common factor (q - p) divided out
    return 0.4 * (q**4 + q**3 * p + q**2 * p**2 + q * p**3 + p**4) / (q + p)


def _secant_slope(a: float, b: float) -> float:
    """d/db of :func:`hertz_secant` (a, b) (Newton's slope for delta_{n+1} = b)."""
    if b <= 0.0:
        return 0.0 if a <= 0.0 else 0.4 * a**2.5 / (a - b) ** 2
    if a <= 0.0:
        return 0.4 * (2.5 * math.pow(b, 1.5) * (b - a) - math.pow(b, 2.5)) / (b - a) ** 2
    p, q = math.sqrt(a), math.sqrt(b)
    num = q**4 + q**3 * p + q**2 * p**2 + q * p**3 + p**4
    dnum = 4 * q**3 + 3 * q**2 * p + 2 * q * p**2 + p**3
    return 0.4 * (dnum * (q + p) - num) / ((q + p) ** 2 * 2.0 * q)


def _solve_contact(d_n: float, d_star: float, s: float) -> float:
    """delta_{n+1} from delta_{n+1} + s G(delta_n, delta_{n+1}) = d_star, G the Hertz secant:
    the root is bracketed by [d_star - s max(d_n, d_star, 0)^{3/2}, d_star]; Newton, safeguarded
    by bisection."""
    if d_n <= 0.0 and d_star <= 0.0:
        return d_star
    lo, hi = d_star - s * math.pow(max(d_n, d_star, 0.0), 1.5), d_star
    d = 0.5 * (lo + hi)
    for _ in range(200):
        f = d + s * hertz_secant(d_n, d) - d_star
        if f == 0.0:
            return d
        if f > 0.0:
            hi = d
        else:
            lo = d
        step = d - f / (1.0 + s * _secant_slope(d_n, d))
        d_next = step if lo < step < hi else 0.5 * (lo + hi)
        if d_next == d or hi - lo <= 2e-16 * max(abs(lo), abs(hi)):
            return d_next
        d = d_next
    return d


class _Factor:
    """A = (2/h^2) M + (beta^2/2) K factorised for one step length h, with g = A^-1 (8 lam beta
    e_0) and s = h^2/2 + g_0."""

    def __init__(self, fe: AxisymmetricPlateFE, lam: float, beta: float, h: float) -> None:
        a = (2.0 / h**2) * fe.mass + (0.5 * beta**2) * fe.stiffness
        # Fortran order: the LAPACK wrapper would otherwise copy the band at every solve
        self.h = h
        self.chol = np.asfortranarray(scipy.linalg.cholesky_banded(upper_band(a)))
        load = np.zeros(fe.n_dof)
        load[0] = 8.0 * lam * beta
        self.g = self.solve(load)
        self.s = 0.5 * h**2 + float(self.g[0])

    def solve(self, rhs: FloatArray) -> FloatArray:
        x, info = dpbtrs(self.chol, rhs, lower=0)
        if info != 0:
            raise RuntimeError(f"banded solve failed (LAPACK info {info})")
        return np.asarray(x)


class _State:
    """The march's state: plate (u, v), ball (x, p), delta = x - u_0, time t; with the steps."""

    def __init__(self, fe: AxisymmetricPlateFE, lam: float, beta: float) -> None:
        self.fe, self.lam, self.beta = fe, lam, beta
        self.mass_band = np.asfortranarray(upper_band(fe.mass))
        self.stiff_band = np.asfortranarray(upper_band(fe.stiffness))
        self.u, self.v = np.zeros(fe.n_dof), np.zeros(fe.n_dof)
        self.x, self.p, self.delta, self.t = 0.0, 1.0, 0.0, 0.0

    def trial(self, fac: _Factor, contact: bool = True) -> tuple[FloatArray, float, float]:
        """One step of length fac.h, not taken: (du, G, delta+). contact=False: free flight."""
        h = fac.h
        rhs = dsbmv(3, 2.0 / h, self.mass_band, self.v, lower=0)
        rhs = dsbmv(3, -self.beta**2, self.stiff_band, self.u, beta=1.0, y=rhs, lower=0)
        du = fac.solve(rhs)
        d_star = float(self.x + h * self.p - self.u[0] - du[0])
        force = 0.0
        if contact:
            # G from the root, and delta+ from G: the energy balance needs G to be the secant
            # (its error then is the root's, not the root's divided by s)
            force = hertz_secant(self.delta, _solve_contact(self.delta, d_star, fac.s))
        d_new = d_star - fac.s * force
        if force != 0.0:
            du += force * fac.g
        return du, force, d_new

    def commit(self, h: float, du: FloatArray, force: float, d_new: float) -> None:
        self.v = (2.0 / h) * du - self.v
        self.u = self.u + du
        self.x += h * self.p - 0.5 * h * h * force
        self.p -= h * force
        self.delta, self.t = d_new, self.t + h

    def plate_energy(self) -> float:
        """E_p = (v^T M v + beta^2 u^T K u) / (16 lambda beta)."""
        mv = dsbmv(3, 1.0, self.mass_band, self.v, lower=0)
        ku = dsbmv(3, self.beta**2, self.stiff_band, self.u, lower=0)
        return float((self.v @ mv + self.u @ ku) / (16.0 * self.lam * self.beta))

    def energy(self) -> float:
        return 0.5 * self.p**2 + 0.4 * math.pow(max(self.delta, 0.0), 2.5) + self.plate_energy()


def _land(state: _State, dt: float, contact: bool) -> float:
    """The step length h in (0, dt) after which delta = 0 (to round-off), taken: regula falsi
    (Illinois) on h -> delta+(h), with delta+(0) = delta and delta+(dt) of the other sign."""
    def delta_after(h: float) -> tuple[float, tuple[FloatArray, float, float]]:
        step = state.trial(_Factor(state.fe, state.lam, state.beta, h), contact)
        return step[2], step
    a, fa = 0.0, state.delta
    if abs(fa) <= 1e-14:  # already there
        return 0.0
    b, (fb, best) = dt, delta_after(dt)
    hb, side = dt, 0
    for _ in range(60):
        h = (a * fb - b * fa) / (fb - fa)
        fh, step = delta_after(h)
        best, hb = step, h
        if abs(fh) <= 1e-14 or b - a <= 1e-15 * dt:
            break
        if (fh > 0.0) == (fb > 0.0):
            b, fb = h, fh
            fa, side = (fa * 0.5, 1) if side == 1 else (fa, 1)
        else:
            a, fa = h, fh
            fb, side = (fb * 0.5, -1) if side == -1 else (fb, -1)
    du, force, d_new = best
    state.commit(hb, du, force, d_new)
    return hb


def _peak(samples: list[tuple[float, float]]) -> float:
    """The contact's peak force from the vertex of the parabola through the largest delta sample
    and its neighbours (times need not be equally spaced)."""
    i = max(range(len(samples)), key=lambda k: samples[k][1])
    if 0 < i < len(samples) - 1:
        (t0, d0), (t1, d1), (t2, d2) = samples[i - 1:i + 2]
        c = ((d2 - d1) / (t2 - t1) - (d1 - d0) / (t1 - t0)) / (t2 - t0)
        if c < 0.0:
            slope = (d1 - d0) / (t1 - t0) + c * (t1 - t0)  # derivative at t1
            return float(max(d1 - slope**2 / (4.0 * c), 0.0) ** 1.5)
    return float(max(samples[i][1], 0.0) ** 1.5)


def march(fe: AxisymmetricPlateFE, lam: float, beta: float, dt: float, t_max: float,
          max_contacts: int = 0,
          track_energy: bool = False,
          linger: float = 0.0) -> tuple[list[RawContact], float, float, bool, float]:
    """Step from the first touch (tau = 0) to the proved end, or to the end of contact number
    ``max_contacts`` (if > 0). Returns the contacts, the ball's final velocity, the plate's
    energy, whether the proved end was reached, and (with ``track_energy``) the largest relative
    change of the total energy after any step (else 0). ``linger`` > 0 keeps stepping that long
    past the proved end (a test of the proof: no contact may follow)."""
    state, regular = _State(fe, lam, beta), _Factor(fe, lam, beta, dt)
    compliance = 8.0 * lam / beta * fe.static_compliance()
    contacts: list[RawContact] = []
    start, p_before, samples, bound, drift = 0.0, 1.0, [(0.0, 0.0)], math.inf, 0.0
    stop_at = math.inf
    while state.t < t_max:
        du, force, d_new = state.trial(regular)
        if samples and d_new <= 0.0:  # the contact ends within this step: land on its end
            _land(state, dt, contact=True)
            samples.append((state.t, 0.0))
            contacts.append((start, state.t, _peak(samples), p_before - state.p, -state.p))
            samples = []
            bound = math.sqrt(2.0 * state.plate_energy() * compliance)
        elif not samples and d_new > 0.0:  # a contact starts within this step: land on it
            _land(state, dt, contact=False)
            start, p_before, samples = state.t, state.p, [(state.t, 0.0)]
        else:
            state.commit(dt, du, force, d_new)
            if samples:
                samples.append((state.t, d_new))
        if track_energy:  # the initial energy is the ball's, 1/2
            drift = max(drift, abs(state.energy() - 0.5) / 0.5)
        if not samples and state.p < 0.0 and state.x < -bound:
            stop_at = min(stop_at, state.t + linger)
        if state.t >= stop_at:
            return contacts, state.p, state.plate_energy(), True, drift
        if max_contacts and len(contacts) == max_contacts:
            return contacts, state.p, state.plate_energy(), False, drift
    raise RuntimeError(f"the ball had not left the plate for good by tau = {t_max:g}; "
                       f"raise t_max")
