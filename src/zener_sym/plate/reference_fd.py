r"""The second method: a Hertz sphere striking the centre of a bounded circular Kirchhoff plate,
solved directly in space and time (finite elements in r, an energy-conserving implicit step), with
no modal expansion, to check the modal solver independently (issue 37, section 4).

Dimensionless problem. With s = r/b, Zener's scales (tau = t/t_0, delta-bar = delta/delta_0,
F-bar = F/(k delta_0^{3/2}), m delta_0/t_0^2 = k delta_0^{3/2}) and w-bar = w/delta_0, the plate
D nabla^4 w + rho h w_tt = F delta(r) (w positive along the ball's approach) becomes, divided by
rho h delta_0 / t_0^2,

    w_tautau + beta^2 nabla_s^4 w = 8 lambda beta F delta(s),   beta = t_0 sqrt(D/(rho h)) / b^2,

since D t_0^2 / (rho h b^4) = beta^2 and m / (rho h b^2) = 8 lambda beta with Zener's lambda =
m / (8 t_0 sqrt(D rho h)) (Eq. 11). The sphere obeys x'' = -F, F = max(delta, 0)^{3/2},
delta = x - w(0), x(0) = 0, x'(0) = 1, plate at rest.

Space: :mod:`.reference_fe` gives M w'' + beta^2 K w = 8 lambda beta F e_0 on the unit disc.
Energy: E = x'^2/2 + (2/5) max(delta, 0)^{5/2} + E_p with
E_p = (w'^T M w' + beta^2 w^T K w) / (16 lambda beta), conserved.

Time: the implicit midpoint rule (Newmark's average acceleration) for the ball and the plate, with
the contact force taken as the discrete gradient G = (Phi(delta_{n+1}) - Phi(delta_n)) /
(delta_{n+1} - delta_n) of the Hertz potential Phi = (2/5) max(delta, 0)^{5/2}. Then E is conserved
exactly (to round-off) through every contact, and the step is second order. The plate's update is
linear in G: du = du_free + G g with g = A^-1 (8 lambda beta e_0) and A = (2/dt^2) M + (beta^2/2) K
factorised once, so each step is one banded solve and a scalar, monotone equation for delta_{n+1}.

The end. After a contact the plate's energy E_p stays constant, and its centre deflection obeys
|w(0)| <= sqrt(2 E_p C_s) with C_s = (8 lambda / beta) e_0^T K^-1 e_0 the static centre
compliance (Cauchy-Schwarz in the energy norm). Once the ball moves away (x' < 0) below
x = -sqrt(2 E_p C_s), no further contact is possible: the run stops there.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import scipy.linalg
from scipy.linalg.blas import dsbmv
from scipy.linalg.lapack import dpbtrs

from ..typing import FloatArray
from .reference_fe import AxisymmetricPlateFE, plate_fe, upper_band

__all__ = ["ReferenceContact", "ReferenceImpact", "simulate", "reference_impact",
           "hertz_secant"]


@dataclasses.dataclass(frozen=True)
class ReferenceContact:
    """One contact, in Zener's scales.

    Attributes
    ----------
    start, end : float
        Times tau at which delta rises through 0 and falls back through 0.
    max_force : float
        The contact's peak force F-bar.
    impulse : float
        Its impulse, the integral of F-bar over the contact (the ball's momentum change).
    speed_after : float
        The ball's speed after the contact, positive away from the plate.
    """

    start: float
    end: float
    max_force: float
    impulse: float
    speed_after: float


@dataclasses.dataclass(frozen=True)
class ReferenceImpact:
    """The impact on the bounded plate by the second method.

    Attributes
    ----------
    contacts : tuple of ReferenceContact
        Every contact, in time order.
    e : float
        The coefficient of restitution, the ball's speed after the last contact (over v_0).
    plate_energy : float
        The energy left in the plate, over the ball's initial kinetic energy.
    error : float
        The estimated absolute error of ``e`` (0 for a single run: see :func:`simulate`).
    energy_drift : float
        The largest relative change of the total energy seen during the run(s).
    n_elements, dt : int, float
        The (finest) mesh and step used.
    """

    contacts: tuple[ReferenceContact, ...]
    e: float
    plate_energy: float
    error: float
    energy_drift: float
    n_elements: int
    dt: float


def hertz_secant(a: float, b: float) -> float:
    """The discrete gradient (Phi(b) - Phi(a)) / (b - a) of Phi = (2/5) max(d, 0)^{5/2}, free of
    cancellation (Phi'(a) = max(a, 0)^{3/2} when a == b)."""
    if a <= 0.0 and b <= 0.0:
        return 0.0
    if a <= 0.0 or b <= 0.0:
        hi, lo = (a, b) if a > b else (b, a)
        return 0.4 * hi**2.5 / (hi - lo)
    p, q = math.sqrt(a), math.sqrt(b)
    # (q^5 - p^5) / (q^2 - p^2) with the common factor (q - p) divided out
    return 0.4 * (q**4 + q**3 * p + q**2 * p**2 + q * p**3 + p**4) / (q + p)


def _secant_slope(a: float, b: float) -> float:
    """d/db of :func:`hertz_secant` (a, b) (Newton's slope for delta_{n+1} = b)."""
    if b <= 0.0:
        return 0.0 if a <= 0.0 else 0.4 * a**2.5 / (a - b) ** 2
    if a <= 0.0:
        return 0.4 * (2.5 * b**1.5 * (b - a) - b**2.5) / (b - a) ** 2
    p, q = math.sqrt(a), math.sqrt(b)
    num = q**4 + q**3 * p + q**2 * p**2 + q * p**3 + p**4
    dnum = 4 * q**3 + 3 * q**2 * p + 2 * q * p**2 + p**3
    return 0.4 * (dnum * (q + p) - num) / ((q + p) ** 2 * 2.0 * q)


def _solve_contact(d_n: float, d_star: float, s: float) -> float:
    """delta_{n+1} from delta_{n+1} + s G(delta_n, delta_{n+1}) = d_star, G the Hertz secant:
    the left side increases strictly, so the root is unique and bracketed by
    [d_star - s max(d_n, d_star, 0)^{3/2}, d_star]; Newton, safeguarded by bisection."""
    if d_n <= 0.0 and d_star <= 0.0:
        return d_star
    lo, hi = d_star - s * max(d_n, d_star, 0.0) ** 1.5, d_star
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


def _hermite_root(t0: float, dt: float, d0: float, d1: float, s0: float, s1: float) -> float:
    """The time in [t0, t0 + dt] where the cubic Hermite interpolant of delta (values d0, d1,
    slopes s0, s1) crosses zero, by bisection (d0 and d1 of opposite signs, or zero)."""
    def cubic(x: float) -> float:
        h00, h10 = 1 - 3 * x**2 + 2 * x**3, x - 2 * x**2 + x**3
        h01, h11 = 3 * x**2 - 2 * x**3, -x**2 + x**3
        return h00 * d0 + h10 * dt * s0 + h01 * d1 + h11 * dt * s1
    lo, hi = 0.0, 1.0
    sign_lo = d0 > 0.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if (cubic(mid) > 0.0) == sign_lo:
            lo = mid
        else:
            hi = mid
    return t0 + dt * 0.5 * (lo + hi)


def _peak(deltas: list[float]) -> float:
    """The peak of delta from its three samples around the largest one (parabola), as a force."""
    d = max(deltas[1], 0.0)
    if deltas[0] is not None and deltas[2] is not None:
        a, b, c = deltas
        curv = a - 2 * b + c
        if curv < 0.0:
            d = b - 0.125 * (c - a) ** 2 / curv
    return float(d**1.5)


class _Plate:
    """The factorised plate of one run: A = (2/dt^2) M + (beta^2/2) K and the unit response g."""

    def __init__(self, fe: AxisymmetricPlateFE, lam: float, beta: float, dt: float) -> None:
        self.fe, self.lam, self.beta, self.dt = fe, lam, beta, dt
        a = (2.0 / dt**2) * fe.mass + (0.5 * beta**2) * fe.stiffness
        # Fortran order: the LAPACK/BLAS wrappers would otherwise copy the bands at every call
        self.chol = np.asfortranarray(scipy.linalg.cholesky_banded(upper_band(a)))
        self.mass_band = np.asfortranarray(upper_band(fe.mass))
        self.stiff_band = np.asfortranarray(upper_band(fe.stiffness))
        load = np.zeros(fe.n_dof)
        load[0] = 8.0 * lam * beta
        self.g = self.solve(load)
        self.compliance = 8.0 * lam / beta * fe.static_compliance()

    def solve(self, rhs: FloatArray) -> FloatArray:
        x, info = dpbtrs(self.chol, rhs, lower=0)
        if info != 0:
            raise RuntimeError(f"banded solve failed (LAPACK info {info})")
        return np.asarray(x)

    def rhs(self, u: FloatArray, v: FloatArray) -> FloatArray:
        """(2/dt) M v - beta^2 K u, by BLAS band products (the step's right-hand side)."""
        mv = dsbmv(3, 2.0 / self.dt, self.mass_band, v, lower=0)
        return np.asarray(dsbmv(3, -self.beta**2, self.stiff_band, u, beta=1.0, y=mv, lower=0))

    def energy(self, u: FloatArray, v: FloatArray) -> float:
        """E_p = (v^T M v + beta^2 u^T K u) / (16 lambda beta)."""
        mv = dsbmv(3, 1.0, self.mass_band, v, lower=0)
        ku = dsbmv(3, self.beta**2, self.stiff_band, u, lower=0)
        return float((v @ mv + u @ ku) / (16.0 * self.lam * self.beta))


class _Contacts:
    """Bookkeeping of the contacts along the march: start and end by Hermite interpolation of
    delta, the peak by a parabola through the samples, the impulse from the ball's momentum."""

    def __init__(self) -> None:
        self.done: list[ReferenceContact] = []
        self.active = False
        self.start = self.p_before = 0.0
        self.best = -math.inf
        self.window: list[float | None] = [None, None, None]
        self.prev: float | None = None

    def step(self, t: float, dt: float, old: tuple[float, float, float],
             new: tuple[float, float, float], touched: bool) -> bool:
        """Record the step from t to t + dt (states (delta, delta', p) before and after; touched:
        the contact force was nonzero). Returns True when a contact ended in this step."""
        (d0, s0, p0), (d1, s1, p1) = old, new
        if touched and not self.active:
            self.active, self.p_before, self.best = True, p0, -math.inf
            self.start = t if d0 >= 0.0 else _hermite_root(t, dt, d0, d1, s0, s1)
            self.window, self.prev = [None, None, None], d0
        if not self.active:
            return False
        if self.window[1] is not None and self.window[2] is None:
            self.window[2] = d1
        if d1 > self.best:
            self.best, self.window = d1, [self.prev, d1, None]
        self.prev = d1
        if d1 > 0.0:
            return False
        end = _hermite_root(t, dt, d0, d1, s0, s1)
        self.done.append(ReferenceContact(self.start, end, _peak(self.window),
                                          self.p_before - p1, -p1))
        self.active = False
        return True


def _march(plate: _Plate, t_max: float, track_energy: bool) -> tuple[list[ReferenceContact], float,
                                                                   float, float]:
    """Step from the first touch (tau = 0) to the proved end; returns the contacts, the ball's
    final velocity, the plate's energy and the largest relative energy drift seen."""
    dt, fe = plate.dt, plate.fe
    g, g0 = plate.g, float(plate.g[0])
    s = 0.5 * dt**2 + g0
    u, v = np.zeros(fe.n_dof), np.zeros(fe.n_dof)
    x, p, t, delta = 0.0, 1.0, 0.0, 0.0
    contacts, e0, drift = _Contacts(), 0.5, 0.0
    bound, n_steps = math.inf, int(math.ceil(t_max / dt))
    for _ in range(n_steps):
        old = (delta, p - v[0], p)
        du = plate.solve(plate.rhs(u, v))
        d_star = x + dt * p - u[0] - du[0]
        d_new = _solve_contact(delta, d_star, s)
        force = (d_star - d_new) / s
        if force != 0.0:
            du += force * g
        v = (2.0 / dt) * du - v
        u = u + du
        x, p_new = x + dt * p - 0.5 * dt**2 * force, p - dt * force
        ended = contacts.step(t, dt, old, (d_new, p_new - v[0], p_new), force > 0.0)
        delta, p, t = d_new, p_new, t + dt
        if ended:
            bound = math.sqrt(2.0 * plate.energy(u, v) * plate.compliance)
        if track_energy:
            total = 0.5 * p**2 + 0.4 * max(delta, 0.0) ** 2.5 + plate.energy(u, v)
            drift = max(drift, abs(total - e0) / e0)
        if not contacts.active and p < 0.0 and x < -bound:
            return contacts.done, p, plate.energy(u, v), drift
    raise RuntimeError(f"the ball had not left the plate for good by tau = {t_max:g} "
                       f"({n_steps} steps); raise t_max")


def _check(lam: float, beta: float, support: str, nu: float) -> None:
    for name, value in (("lam", lam), ("beta", beta)):
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not math.isfinite(value) or value <= 0.0:
            raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    if support not in ("clamped", "simply-supported"):
        raise ValueError(f"unknown support {support!r}; allowed: clamped, simply-supported")
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu (Poisson's ratio) must satisfy -1 < nu < 0.5, got {nu!r}")


def simulate(lam: float, beta: float, support: str, nu: float = 0.3, *, n_elements: int = 200,
             dt: float = 0.01, grading: float = 2.0, t_max: float = 1e5,
             track_energy: bool = False) -> ReferenceImpact:
    """One run of the second method on one mesh with one step (no extrapolation).

    Parameters
    ----------
    lam : float
        Zener's inelasticity parameter lambda > 0 (Eq. 11).
    beta : float
        The plate-size parameter t_0 sqrt(D/(rho h)) / b^2 > 0.
    support : {"clamped", "simply-supported"}
        The edge support.
    nu : float
        The plate's Poisson's ratio (enters the simply supported edge).
    n_elements : int
        Number of radial Hermite elements (:func:`.reference_fe.graded_nodes`).
    dt : float
        The time step in tau.
    grading : float
        The mesh's centre refinement exponent.
    t_max : float
        Give up (RuntimeError) if the ball has not left for good by this tau.
    track_energy : bool
        Evaluate the total energy after every step and report its largest relative drift.

    Returns
    -------
    ReferenceImpact
        With ``error`` 0: a single run has no error estimate.
    """
    _check(lam, beta, support, nu)
    if not (math.isfinite(dt) and dt > 0.0):
        raise ValueError(f"dt must be a finite number > 0, got {dt!r}")
    plate = _Plate(plate_fe(support, nu, n_elements, grading), float(lam), float(beta), dt)
    contacts, p_final, e_plate, drift = _march(plate, t_max, track_energy)
    return ReferenceImpact(tuple(contacts), -p_final, e_plate / 0.5, 0.0, drift,
                           int(n_elements), dt)
