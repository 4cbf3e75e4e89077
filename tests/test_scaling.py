"""The hand-written physical scaling against a SymPy nondimensionalisation of Eq. (7), a hand
computation for the paper's Table 1 pair, and a direct integration of Eq. (7) in SI units."""
import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import zener_sym as zs
from zener_sym.scene import scaling


def _sympy_scaling():
    """Nondimensionalise Eq. (7) with SymPy: returns (symbols, T, lambda) as expressions."""
    m, E, R, V0, alpha, T = sp.symbols("m E R V0 alpha T", positive=True)
    t, tau = sp.symbols("t tau", positive=True)
    db = sp.Function("db")
    K = sp.Rational(4, 3) * E * sp.sqrt(R)
    # delta(t) = T V0 db(t/T) in delta'' + F/m + alpha dF/dt = 0 with F = K delta^{3/2}
    delta = T * V0 * db(t / T)
    F = K * delta ** sp.Rational(3, 2)
    lhs = ((sp.diff(delta, t, 2) + F / m + alpha * sp.diff(F, t)) * T / V0).doit()
    lhs = lhs.subs(t, T * tau).doit()
    # Replace db'' -> 0, db' -> dd, db -> 1: what is left is c_el + c_dmp (3/2) dd
    dd = sp.Symbol("dd")
    d2 = [a for a in lhs.atoms(sp.Subs, sp.Derivative)]
    expr = lhs
    for a in sorted(d2, key=lambda a: -sp.count_ops(a)):
        order = sum(n for _, n in a.variable_count) if isinstance(a, sp.Derivative) else \
            sum(n for _, n in a.expr.variable_count)
        expr = expr.subs(a, 0 if order == 2 else dd)
    expr = sp.expand(expr.subs(db(tau), 1))
    c_el = sp.simplify(expr.subs(dd, 0))                          # coefficient of db^{3/2}
    c_dmp = sp.simplify(sp.diff(expr, dd) / sp.Rational(3, 2))    # of (3/2) db^{1/2} db'
    T_sol = [r for r in sp.solve(sp.Eq(c_el, 1), T) if r.is_positive]
    assert len(T_sol) == 1
    lam = sp.simplify(c_dmp.subs(T, T_sol[0]))
    return (m, E, R, V0, alpha), T_sol[0], lam


def test_T_and_lambda_match_sympy_nondimensionalisation():
    (m, E, R, V0, alpha), T_expr, lam_expr = _sympy_scaling()
    vals = {m: 2.7e-6, E: 1.1e10, R: 0.9e-3, V0: 3.0, alpha: 0.125}
    T_sym = float(T_expr.subs(vals))
    lam_sym = float(lam_expr.subs(vals))
    T_hand = scaling.characteristic_time(2.7e-6, 1.1e10, 0.9e-3, 3.0)
    assert T_hand == pytest.approx(T_sym, rel=1e-13)
    assert scaling.inelasticity(0.125, 2.7e-6, T_hand) == pytest.approx(lam_sym, rel=1e-13)
    # the exponent of T is 2/5 (the paper prints 2/3): T^(5/2) ~ m
    assert sp.simplify(sp.diff(sp.log(T_expr), m) * m) == sp.Rational(2, 5)


def test_table1_pair_by_hand():
    # Hand computation, R = 0.9 mm, H = 0.5 mm, V0 = 1 m/s, gamma-Al2O3 on glass (Table 1).
    E1, nu1, rho1, E2, nu2, rho2 = 12.23e9, 0.21, 879.0, 73e9, 0.21, 2500.0
    R, H, V0 = 0.9e-3, 0.5e-3, 1.0
    m1 = 4 / 3 * math.pi * R**3 * rho1                       # 2.684e-6 kg
    Es = 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)         # 1.0958e10 Pa
    D = E2 * H**3 / (12 * (1 - nu2**2))
    alpha = 1 / (8 * math.sqrt(D * rho2 * H))                # infinite plate admittance
    T = (m1 / (4 / 3 * Es * math.sqrt(R * V0))) ** 0.4
    lam = alpha * m1 / T
    sc = zs.Scene("table1-sphere", "table1-plate", R, H, V0)
    assert sc.m1 == pytest.approx(m1, rel=1e-14)
    assert sc.E_star == pytest.approx(Es, rel=1e-14)
    assert sc.alpha == pytest.approx(alpha, rel=1e-13)
    assert sc.T == pytest.approx(T, rel=1e-14)
    assert sc.lam == pytest.approx(lam, rel=1e-13)
    assert sc.lam == pytest.approx(0.16298, abs=5e-5)
    # V_W = sqrt(E2 / (rho2 (1 - nu2^2)))
    assert sc.V_W == pytest.approx(math.sqrt(73e9 / 2500 / (1 - 0.21**2)), rel=1e-14)


@pytest.mark.parametrize("R,H,V0", [(0.9e-3, 0.5e-3, 1.0), (1e-3, 2e-3, 7.0), (5e-3, 1e-3, 0.1)])
def test_eq11_closed_form_equals_alpha_m_over_T(R, H, V0):
    s, p = zs.STEEL, zs.GLASS
    sc = zs.Scene(s, p, R, H, V0)
    lam11 = scaling.inelasticity_eq11(R, H, V0, s.rho, s.E, s.nu, p.rho, p.E, p.nu)
    assert sc.lam == pytest.approx(lam11, rel=1e-13)
    # lambda ~ V0^{1/5} (R/H)^2
    sc2 = zs.Scene(s, p, R, H, 32 * V0)
    assert sc2.lam / sc.lam == pytest.approx(2.0, rel=1e-13)


def test_chi_reproduces_energy_balance():
    # Physical identity xi = 2 lambda int F^2 (energy balance) against xi = chi V0^{1/5}(R/H)^2 int F^2
    sc = zs.Scene("steel", "aluminium", 1e-3, 0.8e-3, 2.0)
    s = zs.summary(sc.lam, model="exact")
    xi_chi = sc.chi * sc.v0 ** 0.2 * (sc.radius / sc.thickness) ** 2 * s.int_F2
    assert xi_chi == pytest.approx(s.xi, rel=1e-9)


def test_scene_results_match_si_integration_of_eq7():
    """Integrate Eq. (7) in SI units (sphere velocity V, plate velocity alpha F) directly."""
    sc = zs.Scene("steel", "glass", 1e-3, 0.5e-3, 3.0)
    K = 4 / 3 * sc.E_star * math.sqrt(sc.radius)
    a, m = sc.alpha, sc.m1

    def rhs(t, y):
        d = max(y[0], 0.0)
        F = K * d**1.5
        return [y[1] - a * F, -F / m]

    def end(t, y):
        return y[0]

    end.terminal, end.direction = True, -1
    t_scale = sc.T
    sol = solve_ivp(rhs, (0, 100 * t_scale), [0.0, sc.v0], method="DOP853", rtol=1e-12,
                    atol=[1e-20, 1e-15], events=end, dense_output=True, max_step=t_scale / 50,
                    first_step=t_scale * 1e-6)
    t_d = sol.t_events[0][-1]
    V_end = sol.y_events[0][-1][1]
    tt = np.linspace(0, t_d, 4001)
    F = K * np.maximum(sol.sol(tt)[0], 0) ** 1.5
    res = sc.result(model="exact", warn=False)
    assert res.contact_duration_s == pytest.approx(t_d, rel=1e-6)
    assert res.rebound_speed_m_s == pytest.approx(-V_end, rel=1e-6)
    assert res.max_force_N == pytest.approx(F.max(), rel=1e-5)
    h = res.history(tt[::400])
    assert np.allclose(h["force_N"], F[::400], rtol=1e-5, atol=1e-6 * F.max())
