"""The second method for the finite plate (issue 37): finite elements in r and an energy-conserving
implicit step, checked against independent routes only: the plate's closed-form static
compliance, the Bessel frequency equations (and published roots), the conservation of energy,
Zener's exact model in the large-plate limit, and the issue's glass-plate case with lambda and
beta computed here from the materials."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import iv, jv

import zener_sym as zs
from zener_sym.plate.reference_fd import hertz_secant, reference_impact, simulate
from zener_sym.plate.reference_fe import plate_fe


def _compliance_closed_form(support, nu):
    """Centre deflection under a unit centre load, unit D and radius (Timoshenko & Woinowsky-
    Krieger, Theory of Plates and Shells, Sec. 19): b^2/(16 pi D) clamped,
    (3 + nu) b^2 / (16 pi (1 + nu) D) simply supported."""
    if support == "clamped":
        return 1.0 / (16.0 * math.pi)
    return (3.0 + nu) / (16.0 * math.pi * (1.0 + nu))


@pytest.mark.parametrize("support,nu", [("clamped", 0.3), ("simply-supported", 0.3),
                                        ("simply-supported", 0.21)])
def test_static_compliance_converges_to_closed_form(support, nu):
    exact = _compliance_closed_form(support, nu)
    errs = [abs(plate_fe(support, nu, n).static_compliance() / exact - 1.0) for n in (10, 20, 40)]
    assert errs[2] < 5e-6
    # the graded mesh converges at least as h^3
    assert errs[1] < errs[0] / 8.0 and errs[2] < errs[1] / 8.0


def _bessel_roots(support, nu, count, k_max=15.0):
    """(k b)^2 of the axisymmetric modes, w = J0(k s) + c I0(k s): the frequency equations
    solved here. Clamped: w(1) = w'(1) = 0 gives J0 I1 + I0 J1 = 0. Simply supported: w(1) = 0
    and w'' + nu w' = 0 at s = 1."""
    def clamped(k):
        return jv(0, k) * iv(1, k) + iv(0, k) * jv(1, k)

    def simply(k):
        c = -jv(0, k) / iv(0, k)
        return (-k * k * jv(0, k) + (1 - nu) * k * jv(1, k)) \
            + c * (k * k * iv(0, k) - (1 - nu) * k * iv(1, k))
    f = clamped if support == "clamped" else simply
    ks = np.linspace(0.5, k_max, int(200 * k_max))
    vals = [f(k) for k in ks]
    roots = [brentq(f, a, b, xtol=1e-14) for a, b, fa, fb in zip(ks, ks[1:], vals, vals[1:]) if fa * fb < 0]
    return np.array(roots[:count]) ** 2


@pytest.mark.parametrize("support,nu,published", [
    ("clamped", 0.3, (10.2158, 39.771)),
    # Leissa, Vibration of Plates (NASA SP-160), Table 2.4 for nu = 0.3 (the values 4.977, 29.76
    # sometimes quoted belong to nu = 0.33)
    ("simply-supported", 0.3, (4.935, 29.72)),
    ("simply-supported", 0.21, None),
])
def test_lowest_frequencies(support, nu, published):
    roots = _bessel_roots(support, nu, 3)
    if published is not None:
        assert roots[:2] == pytest.approx(published, rel=2e-4)
    coarse = plate_fe(support, nu, 20, grading=1.0).frequencies(3)
    fine = plate_fe(support, nu, 40, grading=1.0).frequencies(3)
    assert fine == pytest.approx(roots, rel=2e-6)
    # convergence as h^4 where the coarse mesh is not already at the eigensolver's round-off
    visible = np.abs(coarse - roots) > 1e-6 * roots
    assert np.all(np.abs(fine - roots)[visible] < np.abs(coarse - roots)[visible] / 10.0)
    assert visible.sum() >= 2


def test_hertz_secant_is_the_potential_difference():
    phi = lambda d: 0.4 * max(d, 0.0) ** 2.5
    for a, b in [(0.3, 0.7), (-0.2, 0.5), (0.5, -0.1), (0.2, 0.2 + 1e-9), (-1.0, -0.5)]:
        if a == b:
            continue
        expected = (phi(b) - phi(a)) / (b - a) if abs(b - a) > 1e-6 else a**1.5
        assert hertz_secant(a, b) == pytest.approx(expected, rel=1e-6, abs=1e-300)


def _issue_case():
    """lambda and beta of the issue's case, from the materials: a steel ball (E = 210 GPa,
    nu = 0.30, rho = 7850 kg/m^3; the package's STEEL preset), radius 2.5 mm at 1 m/s, on a 1 mm
    soda-lime glass plate (73 GPa, 0.21, 2500 kg/m^3; GLASS) clamped at radius 50 mm."""
    R, v0, h, b = 2.5e-3, 1.0, 1e-3, 50e-3
    E1, nu1, rho1, E2, nu2, rho2 = 210e9, 0.30, 7850.0, 73e9, 0.21, 2500.0
    m = 4.0 / 3.0 * math.pi * R**3 * rho1
    e_star = 1.0 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)
    k = 4.0 / 3.0 * e_star * math.sqrt(R)  # F = k delta^{3/2}
    t0 = (m / (k * math.sqrt(v0))) ** 0.4  # m delta0/t0^2 = k delta0^{3/2}, delta0 = v0 t0
    D = E2 * h**3 / (12.0 * (1.0 - nu2**2))
    lam = m / (8.0 * t0 * math.sqrt(D * rho2 * h))
    beta = t0 * math.sqrt(D / (rho2 * h)) / b**2
    return lam, beta, t0, nu2


def test_issue_case_parameters():
    lam, beta, t0, _ = _issue_case()
    assert lam == pytest.approx(2.27, abs=0.01)  # the issue's "lambda = 2.3"
    assert 4e-3 < beta < 5e-3


def test_energy_is_conserved_through_several_contacts():
    lam, beta, _, nu = _issue_case()
    r = simulate(lam, beta, "clamped", nu, n_elements=60, dt=0.05, track_energy=True)
    assert len(r.contacts) >= 3
    assert r.energy_drift < 1e-9
    # what the ball lost is in the plate
    assert r.e**2 + r.plate_energy == pytest.approx(1.0, abs=1e-9)


def test_issue_case_five_contacts():
    lam, beta, t0, nu = _issue_case()
    r = simulate(lam, beta, "clamped", nu, n_elements=150, dt=0.025)
    assert r.complete and len(r.contacts) == 5
    assert r.e == pytest.approx(0.14, abs=0.005)
    # the issue: the first contact is shortened to 56 us (Zener: 76 us)
    first = r.contacts[0]
    assert (first.end - first.start) * t0 * 1e6 == pytest.approx(56.0, abs=1.5)
    speeds = [c.speed_after for c in r.contacts]
    assert np.all(np.diff(speeds) > 0)
    for c in r.contacts:
        assert c.impulse > 0 and c.max_force > 0 and c.end > c.start
    # contacts are disjoint and in order
    assert all(a.end < b.start for a, b in zip(r.contacts, r.contacts[1:]))
    # momentum: the impulses add up to the ball's change of velocity
    assert sum(c.impulse for c in r.contacts) == pytest.approx(1.0 + r.e, rel=1e-12)


def test_no_contact_after_the_proved_end():
    lam, beta, _, nu = _issue_case()
    ended = simulate(lam, beta, "clamped", nu, n_elements=60, dt=0.05)
    # beyond the end: three periods of the fundamental mode (2 pi / (beta 10.2158) each)
    longer = simulate(lam, beta, "clamped", nu, n_elements=60, dt=0.05,
                      linger=3 * 2 * math.pi / (beta * 10.2158))
    assert longer.contacts == ended.contacts and longer.e == ended.e


def test_large_plate_first_contact_is_zener():
    lam, beta = 0.5, 1e-3
    runs = [simulate(lam, beta, "clamped", n_elements=300, dt=dt, max_contacts=1)
            for dt in (0.01, 0.005)]
    assert not runs[0].complete
    zener = zs.summary(lam, model="exact")
    (c1,), (c2,) = runs[0].contacts, runs[1].contacts
    def extrapolated(field):
        return getattr(c2, field) + (getattr(c2, field) - getattr(c1, field)) / 3.0
    assert extrapolated("speed_after") == pytest.approx(zener.e, abs=2e-7)
    # the end converges more slowly (delta'' ~ sqrt(delta) as the contact opens): order ~2.5
    assert extrapolated("end") == pytest.approx(zener.tau_d, abs=3e-6)
    assert extrapolated("max_force") == pytest.approx(zener.F_m, abs=1e-6)
    assert extrapolated("impulse") == pytest.approx(zener.impulse, abs=2e-7)


def _hertz_with_spring(compliance):
    """Duration and peak force of the small-plate limit: Hertz in series with the plate's static
    spring, x'' = -F, F = max(x - C F, 0)^{3/2}, solved by DOP853 with an event."""
    from scipy.integrate import solve_ivp

    def force(x):
        if x <= 0.0:
            return 0.0
        return brentq(lambda f: f - (x - compliance * f) ** 1.5, 0.0, x**1.5, xtol=1e-15)

    def back(t, z):
        return z[0] if t > 0 else 1.0
    back.terminal, back.direction = True, -1
    sol = solve_ivp(lambda t, z: [z[1], -force(z[0])], (0.0, 50.0), [0.0, 1.0], events=back,
                    rtol=1e-12, atol=1e-14, method="DOP853", max_step=0.01)
    return sol.t_events[0][0], max(force(x) for x in sol.y[0])


@pytest.mark.parametrize("beta", [30.0, 100.0])
def test_small_stiff_plate_is_hertz_in_series_with_its_static_spring(beta):
    lam = 1.0
    duration, peak = _hertz_with_spring(8.0 * lam / beta / (16.0 * math.pi))
    r = simulate(lam, beta, "clamped", n_elements=40, dt=0.005)
    (c,) = r.contacts
    assert c.end == pytest.approx(duration, rel=1e-5)
    assert c.max_force == pytest.approx(peak, rel=2e-5)
    assert r.e == pytest.approx(1.0, abs=1e-8)  # the quasi-static plate gives its energy back


def test_simply_supported_plate_runs_to_the_end():
    r = simulate(1.0, 0.01, "simply-supported", 0.3, n_elements=60, dt=0.025,
                 track_energy=True)
    assert r.complete and len(r.contacts) >= 1
    assert r.energy_drift < 1e-9


@pytest.mark.parametrize("kwargs,match", [
    (dict(lam=0.0, beta=0.1, support="clamped"), "lam"),
    (dict(lam=1.0, beta=-1.0, support="clamped"), "beta"),
    (dict(lam=1.0, beta=0.1, support="free"), "support"),
    (dict(lam=1.0, beta=0.1, support="clamped", nu=0.5), "nu"),
    (dict(lam=float("nan"), beta=0.1, support="clamped"), "lam"),
])
def test_bad_input_is_refused(kwargs, match):
    with pytest.raises(ValueError, match=match):
        simulate(**kwargs)
    with pytest.raises(ValueError, match=match):
        reference_impact(**kwargs)


@pytest.mark.slow
def test_issue_case_converged_and_its_error_estimate_holds():
    lam, beta, _, nu = _issue_case()
    r = reference_impact(lam, beta, "clamped", nu, rtol=1e-4)
    assert r.complete and len(r.contacts) == 5
    assert r.error < 1e-4 * r.e
    # a check: the pair (r.dt, r.dt / 2), finer than any run of r, extrapolated the same way,
    # on the finer mesh; it must fall within the reported error
    pair = [simulate(lam, beta, "clamped", nu, n_elements=r.n_elements, dt=dt)
            for dt in (r.dt, r.dt / 2)]
    e_check = pair[1].e + (pair[1].e - pair[0].e) / 3.0
    assert e_check == pytest.approx(r.e, abs=r.error)
    assert e_check == pytest.approx(0.1416, abs=1e-4)


def _modal_e(lam, beta, n_modes):
    """e of the issue's clamped case from the plate's modes (a third route, independent of both
    this module and the package's modal solver): the clamped circle's axisymmetric modes
    phi = J0(k s) - (J0(k)/I0(k)) I0(k s) with k from J0 I1 + I0 J1 = 0, their participation
    psi = phi(0)^2 / int phi^2 dA, the static residual of the modes left out
    (8 lam/beta)(1/(16 pi) - sum psi/k^4), integrated by DOP853 at rtol 1e-11."""
    from scipy.integrate import quad, solve_ivp
    k = np.sqrt(_bessel_roots("clamped", 0.3, n_modes, k_max=(n_modes + 2) * math.pi))
    ratio = jv(0, k) / iv(0, k)
    mass = [quad(lambda s, kk=kk, c=c: (jv(0, kk * s) - c * iv(0, kk * s)) ** 2 * 2 * math.pi * s,
                 0.0, 1.0, limit=400, epsabs=1e-14)[0] for kk, c in zip(k, ratio)]
    psi = (1.0 - ratio) ** 2 / np.array(mass)
    omega, c = beta * k**2, 8.0 * lam * beta * psi
    c_res = 8.0 * lam / beta * (1.0 / (16.0 * math.pi) - np.sum(psi / k**4))

    def rhs(_, z):
        y = z[2:2 + n_modes]
        gap = z[0] - y.sum()
        force = 0.0 if gap <= 0 else brentq(lambda f: f - (gap - c_res * f) ** 1.5, 0.0, gap**1.5)
        return np.concatenate([[z[1], -force], z[2 + n_modes:], c * force - omega**2 * y])
    z0 = np.zeros(2 + 2 * n_modes)
    z0[1] = 1.0
    sol = solve_ivp(rhs, (0.0, 120.0), z0, method="DOP853", rtol=1e-11, atol=1e-13, max_step=0.05)
    return -sol.y[1, -1]


@pytest.mark.slow
def test_issue_case_agrees_with_a_modal_solution():
    lam, beta, _, nu = _issue_case()
    pair = [simulate(lam, beta, "clamped", nu, n_elements=223, dt=dt)
            for dt in (0.003125, 0.0015625)]
    e_fd = pair[1].e + (pair[1].e - pair[0].e) / 3.0
    # 60 modes: the modal truncation moved e by 3e-7 from 40 modes
    assert e_fd == pytest.approx(_modal_e(lam, beta, 60), abs=1e-6)
