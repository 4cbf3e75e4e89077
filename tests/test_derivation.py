"""The SymPy derivation: every step passes, and its results agree with independent routes.

Expected values here never come from the derivation itself: they come from direct numerical
integration (scipy), root finding on the defining equation, mpmath quadrature, or the paper's
printed rounded constants where those are right.
"""
import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

pytestmark = pytest.mark.slow  # the derivation takes ~30 s once per process (cached)

C = (5 / 4) ** (-3 / 5)


@pytest.fixture(scope="module")
def d():
    from zener_sym.derivation.registry import derive

    return derive()


def k_of(lam):
    return (lam + C) ** (-1 / 3)


def f_of(expr, d, *names):
    return sp.lambdify([d.symbols[n] for n in names], expr, "mpmath")


def test_every_step_passes(d):
    failed = [s for s in d.steps if not s.passed]
    assert not failed, "\n".join(f"({s.eq}) {s.what}: {s.detail}" for s in failed)
    assert len(d.steps) >= 50


def test_required_names_and_symbols(d):
    from zener_sym.derivation.registry import REQUIRED

    assert set(REQUIRED) <= set(d.expr)
    for n in ("lam", "tau", "k", "beta", "omega0", "p", "E1", "nu1", "rho1", "E2", "nu2", "rho2",
              "R", "H", "V0"):
        assert n in d.symbols
    lam = d.symbols["lam"]
    for n in ("k_of_lam", "beta_of_lam", "omega0_of_lam", "tau_d0_of_lam", "tau_dc0_of_lam",
              "tau_dr0_of_lam", "eta0_of_lam", "e0_of_lam"):
        assert d.expr[n].free_symbols == {lam}, n
    assert d.expr["forcing"] == d.expr["forcing_elem"] + d.expr["forcing_sqrt"]
    # forcing_elem has no fractional powers, forcing_sqrt has one in every term
    for t in sp.Add.make_args(d.expr["forcing_elem"]):
        assert all(p.exp.is_integer for p in t.atoms(sp.Pow) if isinstance(p.base, sp.sin))
    for t in sp.Add.make_args(d.expr["forcing_sqrt"]):
        assert any(not p.exp.is_integer for p in t.atoms(sp.Pow) if isinstance(p.base, sp.sin))
    assert d.expr["C11_hyp"].has(sp.hyper) and d.expr["C12_hyp"].has(sp.hyper)
    assert d.expr["C11_0"].has(sp.gamma)


def test_lam_crit_by_root_finding(d):
    # independent: the root of 4k - k^2 lambda^2 = 0 by bracketing
    root = brentq(lambda x: 4 * k_of(x) - k_of(x) ** 2 * x**2, 2.0, 3.0, xtol=1e-15)
    assert float(d.expr["lam_crit"]) == pytest.approx(root, rel=1e-13)
    assert round(root, 3) == 2.442  # the paper's printed bound


@pytest.mark.parametrize("lam", [0.0, 0.11, 1.01, 1.99, 2.4])
def test_zeroth_order_against_integration_of_eq28(d, lam):
    # independent: integrate (28) numerically and read off the durations and e
    k = k_of(lam)

    def rhs(t, y):
        return [y[1], -k * lam * y[1] - k * y[0]]

    vel0 = lambda t, y: y[1]  # noqa: E731
    vel0.direction = -1
    back = lambda t, y: y[0]  # noqa: E731
    back.direction = -1
    back.terminal = True
    sol = solve_ivp(rhs, (0, 100), [0, 1], events=[vel0, back], rtol=1e-12, atol=1e-14)
    tau_dc, tau_d = sol.t_events[0][0], sol.t_events[1][0]
    e = -sol.y_events[1][0][1]
    ev = lambda n: float(d.expr[n].subs(d.symbols["lam"], lam))  # noqa: E731
    assert ev("tau_d0_of_lam") == pytest.approx(tau_d, rel=1e-7)
    assert ev("tau_dc0_of_lam") == pytest.approx(tau_dc, rel=1e-7)
    assert ev("tau_dr0_of_lam") == pytest.approx(tau_d - tau_dc, rel=1e-7)
    assert ev("eta0_of_lam") == pytest.approx((tau_d - tau_dc) / tau_dc, rel=1e-7)
    assert ev("e0_of_lam") == pytest.approx(e, rel=1e-7)


@pytest.mark.parametrize("lam", [0.0, 1.01, 2.42])
def test_first_order_against_integration_of_eq30(d, lam):
    # independent: integrate (30) with the forcing written out here from delta0 = e^{-bt} sin/w
    k = k_of(lam)
    b, w = k * lam / 2, math.sqrt(4 * k - k**2 * lam**2) / 2

    def forcing(t):
        s, c, ex = math.sin(w * t), math.cos(w * t), math.exp(-b * t)
        d0 = ex * s / w
        d0p = ex * (c - b / w * s)
        d0pp = ex * (-2 * b * c + (b * b - w * w) / w * s)
        return -(d0pp + 1.5 * lam * math.sqrt(max(d0, 0.0)) * d0p + max(d0, 0.0) ** 1.5)

    sol = solve_ivp(lambda t, y: [y[1], forcing(t) - k * lam * y[1] - k * y[0]],
                    (0, 0.999 * math.pi / w), [0, 0], rtol=1e-12, atol=1e-14, dense_output=True)
    f = f_of(d.expr["delta1"], d, "lam", "beta", "omega0", "tau")
    for frac in (0.1, 0.37, 0.5, 0.81, 0.99):
        t = frac * math.pi / w
        got = float(mpmath.re(f(lam, b, w, t)))
        assert got == pytest.approx(sol.sol(t)[0], abs=1e-8 * max(1, abs(sol.sol(t)[0])))


def test_first_order_improves_on_zeroth(d):
    # physical sanity against the exact solver: delta_ham1 is closer to Eq. (10) than delta0
    import zener_sym as zs

    lam = 1.01
    k = k_of(lam)
    b, w = k * lam / 2, math.sqrt(4 * k - k**2 * lam**2) / 2
    ts = np.linspace(0.05, 0.95 * math.pi / w, 25)
    exact = zs.history(lam, ts, model="exact").delta
    f1 = f_of(d.expr["delta_ham1"], d, "lam", "beta", "omega0", "tau")
    f0 = f_of(d.expr["delta0"], d, "beta", "omega0", "tau")
    e1 = max(abs(float(mpmath.re(f1(lam, b, w, t))) - x) for t, x in zip(ts, exact))
    e0 = max(abs(float(f0(b, w, t)) - x) for t, x in zip(ts, exact))
    assert e1 < 0.5 * e0


def test_constants_by_quadrature(d):
    # independent: C11(tau) - C11(0) = integral of C11' from 0 by mpmath quadrature
    lam = 0.7
    k = k_of(lam)
    b, w = k * lam / 2, math.sqrt(4 * k - k**2 * lam**2) / 2
    names = ("lam", "beta", "omega0", "tau")
    for C, Cp, C0 in (("C11_elem", "C11_prime", "C11_0"), ("C12_elem", "C12_prime", "C12_0")):
        hyp = C.replace("elem", "hyp")
        F = f_of(d.expr[C] + d.expr[hyp] - d.expr[C0], d, *names)
        g = f_of(d.expr[Cp], d, *names)
        with mpmath.workdps(30):
            # mpf inputs, so that no arithmetic inside the lambdified code happens in doubles
            lv, bv, wv = mpmath.mpf(lam), mpmath.mpf(b), mpmath.mpf(w)
            t = 2 / wv
            q = mpmath.quad(lambda x: g(lv, bv, wv, x), [0, t])
            assert abs(mpmath.re(F(lv, bv, wv, t)) - q) < 1e-25


def test_wrong_antiderivative_fails_the_check(d):
    from zener_sym.derivation.first_order import check_antiderivative

    S = d.symbols
    syms = (S["lam"], S["beta"], S["omega0"], S["tau"])
    E = sp.exp(-S["beta"] * S["tau"] / 2)
    g = E * sp.sin(S["omega0"] * S["tau"]) ** sp.Rational(5, 2)
    good = d.expr["C124"]
    lbw = [(mpmath.mpf(0), mpmath.mpf(0), mpmath.mpf("1.0226")),
           (mpmath.mpf("1.5"), mpmath.mpf("0.6"), mpmath.mpf("0.7"))]
    ok, detail = check_antiderivative(good, g, syms, lbw, n=20)
    assert ok, detail
    # change one coefficient of the reduction formula: 15 -> 14
    bad = good.subs(15 * S["omega0"] ** 2, 14 * S["omega0"] ** 2)
    assert bad != good
    ok, detail = check_antiderivative(bad, g, syms, lbw, n=20)
    assert not ok, detail
    # a wrong hypergeometric parameter (c = a + 2 instead of a + 1) must fail as well
    bad2 = good.replace(sp.hyper, lambda ap, bq, z: sp.hyper(ap, [bq[0] + 1], z))
    assert bad2 != good
    ok, detail = check_antiderivative(bad2, g, syms, lbw, n=20)
    assert not ok, detail


def test_hunter_reed_constants(d):
    tau = d.symbols["tau"]
    # the paper's rounded constants (52)-(53) are reproduced; (53) is sin^(3/2), not sin^3
    fh, fr = d.expr["F_hunter"], d.expr["F_reed"]
    dm = 1.25**0.4
    assert float(fh.subs(tau, math.pi / 2 / (1.068 / dm))) == pytest.approx(1.043, abs=5e-4)
    assert float(fr.subs(tau, math.pi / 2 / (1.068 / dm))) == pytest.approx(1.143, abs=5e-4)
    assert float(fr.subs(tau, 1.0)) == pytest.approx(dm**1.5 * math.sin(1.068 / dm) ** 1.5, rel=1e-14)
    assert 1.068 / dm == pytest.approx(0.977, abs=5e-4)


def test_lambda_phys_numerically(d):
    # independent: lambda = alpha m1 / T computed numerically from the definitions of (7)-(9)
    P = {"E1": 12.23e9, "nu1": 0.21, "rho1": 879.0, "E2": 73e9, "nu2": 0.21, "rho2": 2500.0,
         "R": 0.9e-3, "H": 0.4e-3, "V0": 3.0}
    Es = 1 / ((1 - P["nu1"] ** 2) / P["E1"] + (1 - P["nu2"] ** 2) / P["E2"])
    m1 = 4 / 3 * math.pi * P["R"] ** 3 * P["rho1"]
    alpha = math.sqrt(3 * P["rho2"] * (1 - P["nu2"] ** 2) / P["E2"]) / (4 * P["rho2"] * P["H"] ** 2)
    T = (m1 / (4 / 3 * Es * math.sqrt(P["R"] * P["V0"]))) ** 0.4
    sub = {d.symbols[n]: v for n, v in P.items()}
    assert float(d.expr["lam_phys"].subs(sub)) == pytest.approx(alpha * m1 / T, rel=1e-12)
    assert float(d.expr["T"].subs(sub).subs(d.symbols["m"], m1).subs(d.symbols["Estar"], Es)) \
        == pytest.approx(T, rel=1e-12)
    # xi = chi V0^(1/5) (R/H)^2 int F^2 equals 2 lambda int F^2 (energy balance of Eq. 10)
    I2 = d.symbols["int_F2"]
    xi = float(d.expr["xi_energy"].subs(sub).subs(I2, 1))
    assert xi == pytest.approx(2 * alpha * m1 / T, rel=1e-12)
