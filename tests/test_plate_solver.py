"""The finite-plate impact solver (zener_sym.plate.solver, issue 37 sections 2 and 4).

Expected values come from independent routes: the modes are built here (the clamped circle's
roots by brentq, its modal mass by quadrature; the simply supported rectangle's Navier modes in
closed form, its static compliance by a double sum checked against Timoshenko's coefficient),
the large-plate limit is the exact Zener solver, the small-plate limit is Hertz in series with a
spring integrated here by solve_ivp, energy is a physical identity, and DOP853 on the same modal
system is a second integrator.
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq
from scipy.special import i0, i0e, i1e, j0, j1

import zener_sym as zs
from zener_sym.plate.modal import ModalPlate
from zener_sym.plate.solver import choose_modes, solve


# --- the modes, built here ------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def clamped_roots(n: int) -> np.ndarray:
    """Roots of J0(x) I1(x) + I0(x) J1(x) = 0 (clamped edge: w = w_r = 0 at r = b for
    w = J0(kr) - J0(kb) I0(kr) / I0(kb)); scanned, then refined by brentq."""
    def f(x):
        return j0(x) * i1e(x) / i0e(x) + j1(x)

    grid = np.linspace(0.5, (n + 2) * math.pi, 40 * (n + 2))
    v = f(grid)
    idx = np.nonzero(np.sign(v[:-1]) != np.sign(v[1:]))[0][:n]
    return np.array([brentq(f, grid[i], grid[i + 1], xtol=1e-14) for i in idx])


def clamped_psi(x: np.ndarray) -> np.ndarray:
    """psi_n = phi(0)^2 rho h b^2 / M_n with M_n = 2 pi rho h int_0^b phi^2 r dr = 2 pi rho h b^2
    J0(x)^2 (checked by quadrature in test_clamped_circle_modes)."""
    return (1.0 - j0(x) * np.exp(-x) / i0e(x)) ** 2 / (2.0 * math.pi * j0(x) ** 2)


def clamped_circle(lam: float, beta: float, n: int) -> ModalPlate:
    x = clamped_roots(n)
    return ModalPlate(omega=beta * x**2, c=8.0 * lam * beta * clamped_psi(x),
                      static=8.0 * lam / beta / (16.0 * math.pi), support="clamped",
                      shape="circle")


@functools.lru_cache(maxsize=None)
def ss_square_static(m_max: int = 4001) -> float:
    """S = sum psi_mn / Omega_mn^2 for the simply supported square struck at its centre."""
    m = np.arange(1, m_max + 1, 2, dtype=float)
    M, N = np.meshgrid(m, m)
    return float(np.sum(4.0 / (math.pi**4 * (M**2 + N**2) ** 2)))


def ss_square(lam: float, beta: float, n: int) -> ModalPlate:
    """The n lowest Navier modes of the simply supported square with nonzero participation at its
    centre (m, n odd): Omega = pi^2 (m^2 + n^2), psi = 4 sin^2(m pi/2) sin^2(n pi/2) = 4."""
    k = np.arange(1, 2 * int(math.isqrt(4 * n)) + 40, 2, dtype=float)
    M, N = np.meshgrid(k, k)
    om = np.sort((math.pi**2 * (M**2 + N**2)).ravel())[:n]
    return ModalPlate(omega=beta * om, c=8.0 * lam * beta * 4.0 * np.ones(n),
                      static=8.0 * lam / beta * ss_square_static(), support="simply-supported",
                      shape="rectangle")


def scene_beta(sc, b: float) -> float:
    """beta = t0 sqrt(D / (rho h)) / L^2 of a scene's plate of size L."""
    return sc.T * math.sqrt(sc.D / (sc.plate.rho * sc.thickness)) / b**2


def test_clamped_circle_modes():
    x = clamped_roots(400)
    for xn in x[:4]:
        phi = lambda r: j0(xn * r) - j0(xn) / i0(xn) * i0(xn * r)  # noqa: E731
        assert quad(lambda r: phi(r) ** 2 * r, 0, 1, limit=200)[0] == pytest.approx(
            j0(xn) ** 2, rel=1e-10)
        assert clamped_psi(np.array([xn]))[0] == pytest.approx(phi(0) ** 2 / (2 * math.pi *
                                                                              j0(xn) ** 2))
    # the modal sum reproduces the clamped circle's static compliance b^2 / (16 pi D)
    # (the tail: x_n -> n pi, psi_n -> x_n / 2, so sum_{n > N} 1 / (2 (n pi)^3) ~ 1 / (4 pi^3 N^2))
    S = np.sum(clamped_psi(x) / x**4) + 1.0 / (4.0 * math.pi**3 * (len(x) + 0.5) ** 2)
    assert S == pytest.approx(1.0 / (16.0 * math.pi), rel=1e-7)


def test_ss_square_static_is_timoshenkos():
    # Timoshenko & Woinowsky-Krieger, Table 23: centre deflection 0.01160 P a^2 / D
    assert ss_square_static() == pytest.approx(0.01160, abs=5e-6)


# --- the physics ----------------------------------------------------------------------------

GLASS50 = dict(lam=2.2678187414945676, beta=0.00453106140411585)


def test_energy_is_kept_through_every_contact():
    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 30)
    res = solve(plate, rtol=1e-10)
    assert res.n_contacts == 5
    for c in res.contacts:
        # ball (v^2/2) + plate, over the initial 1/2; F = 0 at the end: no contact energy
        assert c.speed_after**2 + c.plate_energy == pytest.approx(1.0, rel=1e-9, abs=0)


def test_energy_inside_a_contact():
    """Ball + modes + residual spring + Hertz potential (2/5) delta^{5/2} at nodes inside the
    first contact: the scheme's drift falls as h^2 then h^{5/2} (the (tau - tau_s)^{3/2} start),
    and extrapolated in both it is below 1e-9 of the initial energy."""
    from zener_sym.plate.kernels import Kernel, Rates
    from zener_sym.plate.stepping import step_contact

    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 30)
    omega, c = np.asarray(plate.omega), np.asarray(plate.c)
    r, c_res = Rates(omega, c, 0.0), plate.residual
    for t_node in (1.2, 4.0):                    # near the peak, and in recovery
        drifts = []
        for h in (0.01, 0.005, 0.0025):
            K = Kernel(r, h)
            B0 = np.zeros(len(omega), complex)
            F = step_contact(K, c_res, 0.0, 1.0, B0, 10**6).F
            j = int(round(t_node / h))
            B = K.state(B0, F[:j + 1])
            y, u = B.real, (r.s * B).real
            v = 1.0 - h * np.sum(F[1:j]) - 0.5 * h * F[j]
            delta = F[j] ** (2.0 / 3.0)
            E = (0.5 * v * v + np.sum((u * u + omega**2 * y * y) / (2 * c))
                 + 0.5 * c_res * F[j] ** 2 + 0.4 * delta**2.5)
            drifts.append(E / 0.5 - 1.0)
        d = np.array(drifts)
        assert d[1] / d[2] == pytest.approx(4.0, abs=0.15)
        R = (4.0 * d[1:] - d[:-1]) / 3.0
        assert R[0] / R[1] == pytest.approx(2**2.5, rel=0.05)
        assert abs((2**2.5 * R[1] - R[0]) / (2**2.5 - 1)) < 1e-9


@pytest.mark.parametrize("rtol", [1e-4, 1e-6, 1e-8])
def test_error_estimate_bounds_the_true_error(rtol):
    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 20)
    ref = solve(plate, rtol=1e-10)
    res = solve(plate, rtol=rtol)
    assert res.n_contacts == ref.n_contacts == 5
    true = abs(res.e - ref.e)
    assert true <= res.error + 1e-12
    assert res.error <= rtol * abs(res.e)
    for c, cr, err in zip(res.contacts, ref.contacts, res.errors):
        assert abs(c.impulse - cr.impulse) <= max(err["impulse"], 1e-12) * 10


def test_error_estimate_over_a_sample_of_steps():
    """Whatever the grid's phase against the contacts' ends, the estimate bounds the error, up
    to the coarsest first step the solver takes (0.2)."""
    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 20)
    ref = solve(plate, rtol=1e-10).e
    for h in np.exp(np.random.default_rng(7).uniform(np.log(0.01), np.log(0.2), 10)):
        res = solve(plate, rtol=1e-2, h=h)           # rtol 1e-2: the first three levels only
        assert abs(res.e - ref) <= res.error
    # 80 modes at h = 0.16: the difference of the extrapolations of e alone was 1/60 of e's
    # error there (a coincidence); the other contacts' differences are not that small
    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 80)
    ref = solve(plate, rtol=1e-10).e
    res = solve(plate, rtol=1e-2, h=0.16)
    assert abs(res.e - ref) <= res.error


def test_error_estimate_when_contacts_are_refined():
    """A first step so coarse that a contact has fewer than N_MIN nodes is re-run on a finer
    grid; the levels must stay h, h/2, h/4 apart there, else the estimate (the levels'
    disagreement) claims accuracy they did not show (once 0 against a true error of 1.5e-3)."""
    fem = clamped_circle(0.16298219961216695, 7.31951524768407e-05, 400)   # one collision
    glass = clamped_circle(GLASS50["lam"], GLASS50["beta"], 20)            # five contacts
    for plate in (fem, glass):
        ref = solve(plate, rtol=1e-10).e
        for h in (0.8, 0.5, 0.3):
            res = solve(plate, rtol=1e-2, h=h)
            assert 0.0 < abs(res.e - ref) <= res.error


def test_force_history_carries_the_momentum():
    """The force history on the result (the finest grid): piecewise linear, 0 at every start and
    end, and its integral is the ball's change of momentum 1 + e (units m v_0)."""
    res = solve(clamped_circle(GLASS50["lam"], GLASS50["beta"], 20), rtol=1e-6)
    t, f = res.force_time, res.force
    assert t.shape == f.shape and np.all(np.diff(t) >= 0.0) and np.all(f >= 0.0)
    assert np.count_nonzero(f == 0.0) == 2 * res.n_contacts
    assert t[0] == res.contacts[0].start and t[-1] == pytest.approx(res.contacts[-1].end, rel=1e-4)
    assert np.trapezoid(f, t) == pytest.approx(1.0 + res.e, rel=1e-4)


def test_second_method_dop853():
    """DOP853 on the same modal system (events at each contact's start and end) agrees."""
    from zener_sym.bench.plate import dop853_impact

    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 20)
    res = solve(plate, rtol=1e-10)
    d = dop853_impact(plate, rtol=1e-9)
    assert len(d.contacts) == res.n_contacts == 5
    assert d.e == pytest.approx(res.e, rel=1e-7)
    for (t0, t1, v), c in zip(d.contacts, res.contacts):
        assert (t0, t1, v) == pytest.approx((c.start, c.end, c.speed_after), rel=1e-6, abs=1e-8)


def test_mode_count_converges():
    make = functools.partial(clamped_circle, GLASS50["lam"], GLASS50["beta"])
    plate, res = choose_modes(make, rtol=1e-6, n_start=4)
    big = solve(make(200), rtol=1e-9)
    assert res.n_contacts == big.n_contacts
    assert abs(res.e - big.e) <= 1e-6 * big.e
    assert len(plate.omega) < 200


def test_issue_cases_clamped_glass():
    """Issue 37: steel ball R 2.5 mm at 1 m/s on 1 mm glass, clamped at b = 50 mm: five
    contacts, e = 0.14, the first contact 56 us (Zener 76 us); at b = 100 mm e = 0.047."""
    sc = zs.Scene("steel", "glass", radius="2.5 mm", thickness="1 mm", v0="1 m/s")
    res = solve(clamped_circle(sc.lam, scene_beta(sc, 0.05), 40), rtol=1e-6)
    assert res.n_contacts == 5
    assert res.e == pytest.approx(0.14, abs=0.005)
    first_us = (res.contacts[0].end - res.contacts[0].start) * sc.T * 1e6
    assert first_us == pytest.approx(56, abs=1.5)
    # (Zener's 76 us in the issue; these presets give lambda = 2.27 and 74 us)
    assert zs.summary(sc.lam, model="exact").tau_d * sc.T * 1e6 == pytest.approx(76, abs=2.5)
    res100 = solve(clamped_circle(sc.lam, scene_beta(sc, 0.10), 80), rtol=1e-6)
    assert res100.e == pytest.approx(0.047, abs=0.0015)
    first = res100.contacts[0]
    z = zs.summary(sc.lam, model="exact")
    assert first.end - first.start == pytest.approx(z.tau_d, rel=0.03)


def test_issue_case_ss_square_steel():
    """Issue 37: a 10 mm steel ball (read as diameter, R = 5 mm, as Scene reads radius) at 1 m/s
    on a 2 mm steel plate simply supported on a 50 mm square: e about 22 % above Zener's."""
    sc = zs.Scene("steel", "steel", radius="5 mm", thickness="2 mm", v0="1 m/s")
    res = solve(ss_square(sc.lam, scene_beta(sc, 0.05), 60), rtol=1e-6)
    ez = zs.summary(sc.lam, model="exact").e
    assert res.e / ez - 1.0 == pytest.approx(0.22, abs=0.02)


def test_large_plate_limit_is_zener():
    """The paper's FEM plate (table1 sphere R 0.9 mm, 0.5 mm table1 glass, 1 m/s, b = 150 mm):
    the first contact's e, duration and peak force agree with exact Zener within 1e-5, and the
    agreement improves as the plate grows (beta -> 0 with modes up to the same frequency)."""
    sc = zs.Scene("table1-sphere", "table1-plate", radius="0.9 mm", thickness="0.5 mm",
                  v0="1 m/s")
    z = zs.summary(sc.lam, model="exact", rtol=1e-12)
    devs = []
    for b, n in ((0.005, 40), (0.01, 60), (0.02, 100), (0.15, 400)):
        c = solve(clamped_circle(sc.lam, scene_beta(sc, b), n), rtol=1e-8).contacts[0]
        devs.append(max(abs(c.speed_after / z.e - 1), abs((c.end - c.start) / z.tau_d - 1),
                        abs(c.max_force / z.F_m - 1)))
    assert devs[0] > 1e-3                    # a 5 mm plate is not Zener's
    assert devs[0] > 10 * devs[1] > 100 * devs[2]
    assert devs[3] < 1e-5


def hertz_series_spring(C: float) -> tuple[float, float]:
    """(duration, peak force) of x'' = -F, F = max(x - C F, 0)^{3/2}, x(0) = 0, x'(0) = 1,
    integrated by solve_ivp; F from a scalar root at each call."""
    def force(x):
        if x <= 0:
            return 0.0
        return brentq(lambda f: f - max(x - C * f, 0.0) ** 1.5, 0.0, x**1.5, xtol=1e-15,
                      rtol=1e-15)

    def rhs(t, z):
        return [z[1], -force(z[0])]

    def back(t, z):
        return z[0]
    back.terminal, back.direction = True, -1
    sol = solve_ivp(rhs, (0, 50), [0.0, 1.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=back, dense_output=True, first_step=1e-4)
    t_d = float(sol.t_events[0][0])
    t = np.linspace(0, t_d, 4001)
    fm = max(force(x) for x in sol.sol(t)[0])
    return t_d, fm


def test_small_stiff_plate_limit_is_hertz_with_a_spring():
    """beta -> infinity (omega_1 >> 1): Hertz in series with the static spring C_s."""
    lam = 1.0
    devs = []
    for beta in (2.0, 20.0):
        plate = clamped_circle(lam, beta, 40)
        res = solve(plate, rtol=1e-8)
        t_d, fm = hertz_series_spring(plate.static)
        c = res.contacts[0]
        devs.append(max(abs((c.end - c.start) / t_d - 1), abs(c.max_force / fm - 1),
                        abs(res.e - 1.0)))
    assert devs[1] < 2e-3
    assert devs[1] < devs[0] / 10


def test_loss_factor_damps_and_is_checked():
    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 20)
    undamped = solve(plate, rtol=1e-6)
    damped = solve(plate, rtol=1e-6, loss=0.05)
    assert damped.e != pytest.approx(undamped.e, rel=1e-3)
    # with losses the energy after each contact is below the initial kinetic energy
    for c in damped.contacts:
        assert c.speed_after**2 + c.plate_energy < 1.0
    for bad in (-0.1, 1.0, 1.5, float("nan")):
        with pytest.raises(ValueError, match="loss"):
            solve(plate, loss=bad)


@pytest.mark.parametrize("change, match", [
    (dict(omega=np.array([1.0, np.nan])), "omega"),
    (dict(omega=np.array([1.0, -2.0])), "omega"),
    (dict(c=np.array([1.0, -1.0])), "plate.c"),
    (dict(c=np.array([1.0])), "same nonzero length"),
    (dict(static=0.0), "static"),
    (dict(static=1e-9), "C_res must be >= 0"),
    (dict(c=np.array([0.0, 0.0])), "node"),
])
def test_bad_plates_are_refused(change, match):
    good = dict(omega=np.array([1.0, 3.0]), c=np.array([0.1, 0.1]), static=1.0,
                support="clamped", shape="circle")
    with pytest.raises(ValueError, match=match):
        solve(ModalPlate(**{**good, **change}))


def test_bad_options_are_refused():
    plate = clamped_circle(1.0, 0.01, 5)
    with pytest.raises(ValueError, match="rtol"):
        solve(plate, rtol=0.5)
    with pytest.raises(ValueError, match="plate must be"):
        solve("plate")  # type: ignore[arg-type]


def test_a_contact_beyond_the_work_limit_is_refused_not_run():
    """200 000 modes at h = 1e-4: a contact of some 3.2 / h nodes would take 6e9 mode-steps
    (minutes); it is refused once it passes MAX_WORK, with what to change."""
    from zener_sym.plate.stepping import MAX_WORK

    n = 200_000
    omega = np.linspace(1.0, 1e4, n)
    plate = ModalPlate(omega=omega, c=np.full(n, 1e-9), static=1.0, support="clamped",
                       shape="circle")
    assert n * 3.2 / 1e-4 > MAX_WORK
    with pytest.raises(RuntimeError, match="mode-steps.*fewer modes or a looser rtol"):
        solve(plate, h=1e-4)


def test_a_tolerance_below_the_rounding_floor_is_refused_not_searched():
    """rtol below RTOL_MIN = 1e-10 is refused up front (issue 37's five-contact plate meets the
    estimate's rounding floor near 1e-11, where halving ran for minutes); and an estimate that
    stops falling ends the search with a RuntimeError after a halving or two, not after
    max_halvings ever finer runs."""
    import zener_sym.plate.solver as solver

    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 20)
    with pytest.raises(ValueError, match=r"rtol must be in \[1e-10, 0.01\]"):
        solve(plate, rtol=1e-11)
    calls = []

    def stuck(rows, errs):   # an estimate at a floor: the same relative 1e-9 at every step
        calls.append(1)
        return 1e-9 * abs(rows[-1]["speed_after"])

    mp = pytest.MonkeyPatch()
    mp.setattr(solver, "_e_error", stuck)
    try:
        with pytest.raises(RuntimeError, match="stopped falling"):
            solve(plate, rtol=1e-10, h=0.1)
    finally:
        mp.undo()
    assert len(calls) == 3     # the first estimate, then two that did not fall


def test_an_estimate_that_rises_far_from_the_floor_does_not_stop_the_search():
    """Above the rounding zone the estimate may rise between halvings (the 100 mm plate of the
    gallery example rose at 9e-6 relative and was wrongly refused): the search goes on and
    meets rtol."""
    import zener_sym.plate.solver as solver

    plate = clamped_circle(GLASS50["lam"], GLASS50["beta"], 20)
    values = iter([3e-5, 9e-5, 2e-5, 1e-7])   # relative: up, then down below rtol 1e-6

    def bumpy(rows, errs):
        return next(values) * abs(rows[-1]["speed_after"])

    mp = pytest.MonkeyPatch()
    mp.setattr(solver, "_e_error", bumpy)
    try:
        r = solve(plate, rtol=1e-6, h=0.1)
    finally:
        mp.undo()
    assert r.error == pytest.approx(1e-7 * abs(r.e), rel=1e-12)


@pytest.mark.parametrize("loss", [0.0, 0.3])
def test_one_step_of_a_mode_is_the_integral_of_its_impulse_response(loss):
    """The compiled step's coefficients (B <- E B + P F_k + Q F_{k+1}) against mpmath's
    quadrature (30 digits) of the impulse response against the two half hats, on both sides of the series' switch at
    |s h| = 0.25 and for stiff modes (|s h| up to 50)."""
    from zener_sym.plate.kernels import Kernel, Rates

    omega = np.array([1e-4, 0.3, 2.4, 7.0, 60.0, 500.0])
    c = np.array([0.5, 1.0, 2.0, 0.1, 3.0, 0.7])
    r, h = Rates(omega, c, loss), 0.1
    K = Kernel(r, h)
    for n in range(len(omega)):
        s, cw = complex(r.s[n]), c[n] / r.wd[n]

        def integral(weight):
            with mpmath.workdps(30):
                sm = mpmath.mpc(s.real, s.imag)
                return complex(mpmath.quad(lambda v: mpmath.exp(sm * v) * weight(v),
                                           [0, h / 2, h]))

        # the force falling from node k (weight (h - u)/h at time u) is seen at u' = h - u later
        P = -1j * cw * integral(lambda v: v / h)
        Q = -1j * cw * integral(lambda v: (h - v) / h)
        assert abs(K.E[n] - np.exp(s * h)) <= 1e-15
        assert abs(K.P[n] - P) <= 1e-12 * abs(P)
        assert abs(K.Q[n] - Q) <= 1e-12 * abs(Q)


@pytest.mark.slow
def test_the_report_targets_run_both_methods_to_the_promised_accuracy():
    """The report's rows for issue 37's 100x: both methods, at the tolerances the rows use, meet
    1e-6 in e against the solver at rtol 1e-10 (itself checked against DOP853 at rtol 1e-9 in
    test_second_method_dop853). The speed is the report's to judge, not a unit test's."""
    import re

    from zener_sym.bench.plate import targets

    rows = targets(quick=True)
    assert [r["target"].rsplit(", ", 1)[1] for r in rows] == ["one collision", "five contacts"]
    for r in rows:
        errs = [float(x) for x in re.findall(r"([0-9.]+e[-+][0-9]+)", r["grid"].split("in e")[1])]
        assert len(errs) == 2 and max(errs) <= 1e-6, r["grid"]
        assert r["required"] == 100.0 and r["fast_s"] > 0 and r["slow_s"] > 0
