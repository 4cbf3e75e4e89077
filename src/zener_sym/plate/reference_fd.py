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
from typing import Callable

from .reference_fd_march import hertz_secant, march
from .reference_fe import plate_fe

__all__ = ["ReferenceContact", "ReferenceImpact", "simulate", "reference_impact",
           "default_mesh", "hertz_secant"]


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
        The largest relative change of the total energy seen during the run(s) (0 when not
        tracked).
    n_elements : int
        The (finest) mesh used.
    dt : float
        The (finest) step used.
    complete : bool
        True when the run reached the proved end (no contact can follow); False when it was
        stopped after ``max_contacts`` contacts, and ``e`` is the speed after the last of them.
    contact_errors : tuple of ReferenceContact
        The estimated absolute error of every field of every contact, estimated as ``error``
        (empty for a single run).
    """

    contacts: tuple[ReferenceContact, ...]
    e: float
    plate_energy: float
    error: float
    energy_drift: float
    n_elements: int
    dt: float
    complete: bool = True
    contact_errors: tuple[ReferenceContact, ...] = ()


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
             track_energy: bool = False, max_contacts: int = 0,
             linger: float = 0.0) -> ReferenceImpact:
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
    max_contacts : int
        Stop after this many contacts (0: run to the proved end).
    linger : float
        Keep stepping this long (in tau) past the proved end: a test of the proof, after which
        no contact may follow.

    Returns
    -------
    ReferenceImpact
        With ``error`` 0: a single run has no error estimate.

    Raises
    ------
    ValueError
        For a bad lambda, beta, support, nu, dt or mesh.
    RuntimeError
        If the ball has not left for good by ``t_max``.

    Examples
    --------
    >>> from zener_sym.plate.reference_fd import simulate
    >>> r = simulate(0.5, 0.05, "clamped", n_elements=40, dt=0.02)
    >>> len(r.contacts), round(r.e, 3), r.complete
    (1, 0.463, True)
    """
    _check(lam, beta, support, nu)
    if not (math.isfinite(dt) and dt > 0.0):
        raise ValueError(f"dt must be a finite number > 0, got {dt!r}")
    fe = plate_fe(support, nu, n_elements, grading)
    raw, p_final, e_plate, complete, drift = march(fe, float(lam), float(beta), dt, t_max,
                                                   int(max_contacts), track_energy,
                                                   float(linger))
    return ReferenceImpact(tuple(ReferenceContact(*map(float, c)) for c in raw), float(-p_final),
                           float(e_plate / 0.5), 0.0, float(drift), int(n_elements), float(dt),
                           complete)


_FIELDS = ("start", "end", "max_force", "impulse", "speed_after")


def _richardson(fine: ReferenceImpact, coarse: ReferenceImpact) -> ReferenceImpact:
    """Richardson's extrapolation for a second-order step (dt halved): x + (x - x_coarse) / 3,
    field by field and contact by contact (the runs must have the same contacts)."""
    def ex(a: float, b: float) -> float:
        return float(a + (a - b) / 3.0)
    contacts = tuple(ReferenceContact(*(ex(getattr(f, k), getattr(c, k)) for k in _FIELDS))
                     for f, c in zip(fine.contacts, coarse.contacts))
    return dataclasses.replace(fine, contacts=contacts, e=ex(fine.e, coarse.e),
                               plate_energy=ex(fine.plate_energy, coarse.plate_energy))


def _shift(a: ReferenceImpact, fine: ReferenceImpact, coarse: ReferenceImpact) -> ReferenceImpact:
    """a plus the change from ``coarse`` to ``fine`` (the mesh correction), field by field."""
    def sh(x: float, f: float, c: float) -> float:
        return float(x + (f - c))
    contacts = tuple(ReferenceContact(*(sh(getattr(x, k), getattr(f, k), getattr(c, k))
                                        for k in _FIELDS))
                     for x, f, c in zip(a.contacts, fine.contacts, coarse.contacts))
    return dataclasses.replace(a, contacts=contacts, e=sh(a.e, fine.e, coarse.e),
                               plate_energy=sh(a.plate_energy, fine.plate_energy,
                                               coarse.plate_energy))


def _same_contacts(runs: list[ReferenceImpact]) -> bool:
    return len({len(r.contacts) for r in runs}) == 1


def default_mesh(beta: float) -> int:
    """The number of elements for beta: the flexural wavenumber at the frequencies of a contact
    scales as beta^(-1/2) (omega = beta (k b)^2), so the mesh does too; at least 40 elements."""
    return max(40, int(math.ceil(15.0 / math.sqrt(beta))))


def reference_impact(lam: float, beta: float, support: str, nu: float = 0.3, *,
                     rtol: float = 1e-5, dt: float | None = None, n_elements: int | None = None,
                     max_halvings: int = 6, t_max: float = 1e5) -> ReferenceImpact:
    """The impact on the bounded circular plate, converged in step and mesh, with an error
    estimate: the second method of issue 37 (no modal expansion).

    The step is halved from ``dt`` and each pair of runs extrapolated (Richardson, order 2) until
    three successive extrapolations of e agree to ``rtol * e`` (two agreeing ones can be a
    coincidence before the error's expansion in the step settles); the mesh correction is the
    change of every quantity from ``n_elements`` to twice as many elements at the coarsest step.

    Parameters
    ----------
    lam, beta, support, nu : float, float, str, float
        As in :func:`simulate`.
    rtol : float
        Requested relative accuracy of e, in (0, 0.1).
    dt : float, optional
        The coarsest step in tau (default 0.0125 (rtol / 1e-5)^{1/2}, at most 0.05).
    n_elements : int, optional
        The mesh (default :func:`default_mesh`).
    max_halvings : int
        At most this many halvings of the step (RuntimeError if rtol is not met by then).
    t_max : float
        Passed to :func:`simulate`.

    Returns
    -------
    ReferenceImpact
        The extrapolated contacts and e; ``error`` is the larger of the last two differences of
        successive extrapolations of e, plus the size of the mesh correction (absolute).

    Raises
    ------
    ValueError
        For a bad lambda, beta, support, nu or rtol.
    RuntimeError
        If rtol is not reached within ``max_halvings``, or the runs' contacts never agree.

    Examples
    --------
    >>> from zener_sym.plate.reference_fd import reference_impact
    >>> r = reference_impact(0.5, 0.05, "clamped", rtol=1e-3)
    >>> f"{r.e:.4f}", r.error < 1e-3 * r.e
    ('0.4626', True)
    """
    _check(lam, beta, support, nu)
    if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) or not 0.0 < rtol < 0.1:
        raise ValueError(f"rtol must be a number in (0, 0.1), got {rtol!r}")
    n = default_mesh(beta) if n_elements is None else int(n_elements)
    dt0 = min(0.05, 0.0125 * math.sqrt(rtol / 1e-5)) if dt is None else float(dt)
    def run(n_el: int, step: float) -> ReferenceImpact:
        return simulate(lam, beta, support, nu, n_elements=n_el, dt=step, t_max=t_max)
    base, ex = _converge_in_step(run, n, dt0, rtol, max_halvings)
    finer = run(2 * n, base.dt)
    if not _same_contacts([finer, base]):
        raise RuntimeError("the mesh refinement changed the number of contacts; pass a finer "
                           "n_elements")
    best = _shift(ex[-1], finer, base)

    def err(get: Callable[[ReferenceImpact], float]) -> float:
        return float(max(abs(get(a) - get(b)) for a, b in zip(ex[-3:], ex[-2:]))
                     + abs(get(finer) - get(base)))

    def field(i: int, k: str) -> Callable[[ReferenceImpact], float]:
        return lambda r: float(getattr(r.contacts[i], k))
    contact_errors = tuple(ReferenceContact(*(err(field(i, k)) for k in _FIELDS))
                           for i in range(len(best.contacts)))
    return dataclasses.replace(best, error=err(lambda r: r.e), contact_errors=contact_errors,
                               n_elements=2 * n)


def _converge_in_step(run: Callable[[int, float], ReferenceImpact], n: int, dt0: float,
                      rtol: float, max_halvings: int) -> tuple[ReferenceImpact,
                                                                list[ReferenceImpact]]:
    """Halve the step until three successive Richardson extrapolations of e agree to rtol;
    returns the coarsest run of the final streak of runs with the same contacts (where the mesh
    correction is measured) and the extrapolations of that streak."""
    runs = [run(n, dt0)]
    base = runs[0]
    ex: list[ReferenceImpact] = []
    for k in range(1, max_halvings + 1):
        runs.append(run(n, dt0 / 2**k))
        if not _same_contacts(runs[-2:]):  # a grazing contact came or went: start again
            base, ex = runs[-1], []
            continue
        ex.append(_richardson(runs[-1], runs[-2]))
        if len(ex) >= 3 and max(abs(a.e - b.e) for a, b in zip(ex[-3:], ex[-2:])) \
                <= rtol * abs(ex[-1].e):
            return base, ex
    raise RuntimeError(f"the second method did not reach rtol = {rtol:g} in e with "
                       f"{max_halvings} halvings of dt = {dt0:g}; the last runs gave "
                       f"e = {[float(r.e) for r in runs[-3:]]}")
