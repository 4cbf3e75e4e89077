"""Higher-order HAM series (issue 17): zener_sym.ham.higher, the model ``ham``, the derivation
modules ham_higher and ham_strained, and the freshness of docs/ham_convergence.md.

Independent routes: ham1 (closed forms + quadrature / its own series) for order 1; spectral
*differentiation* of each order (the solver integrates) against the forcings R_m that SymPy
derives in the derivation modules (the solver uses Miller's recurrence); the exact solver for the
errors; the momentum identity I(tau_d) = 1 + e, which an approximation meets only as well as it
solves Eq. (10).
"""
from __future__ import annotations

import math
import shutil

import numpy as np
import pytest
import sympy as sp

import zener_sym as zs
from zener_sym.bench import ham_convergence
from zener_sym.derivation import ham_higher, ham_strained
from zener_sym.ham import higher

from conftest import ROOT

_C = np.polynomial.chebyshev


# ------------------------------------------------------------------- order 1 is ham1
@pytest.mark.parametrize("lam", [0.0, 0.11, 1.01, 1.51, 1.99, 2.3])
def test_order1_paper_c0_minus1_is_ham1(lam):
    a = zs.summary(lam, model="ham", order=1, c0=-1.0)
    b = zs.summary(lam, model="ham1")
    for f in ("delta_m", "tau_dc", "tau_d", "e", "F_m", "impulse", "int_F2", "xi"):
        assert getattr(a, f) == pytest.approx(getattr(b, f), rel=1e-10, abs=1e-12), f
    assert a.c0 == -1.0
    tau = np.linspace(0.0, 1.1 * b.tau_d, 301)
    ha = zs.history(lam, tau, model="ham", order=1, c0=-1.0)
    hb = zs.history(lam, tau, model="ham1")
    for f in ("delta", "force", "impulse", "velocity"):
        np.testing.assert_allclose(getattr(ha, f), getattr(hb, f), rtol=0, atol=1e-10, err_msg=f)


# -------------------------------------------- each order solves its own linear problem
def _theta_derivs(values, lo=0.08, hi=0.92):
    """f, f_theta, f_thetathetha at the nodes with lo < t < hi, by differentiating the
    Chebyshev interpolant in t (theta = pi sin^2(pi t / 2))."""
    c = _C.chebfit(higher._X, values, higher.N_NODES - 1)
    sel = (higher._T > lo) & (higher._T < hi)
    x, t = higher._X[sel], higher._T[sel]
    f = _C.chebval(x, c)
    f_t = 2.0 * _C.chebval(x, _C.chebder(c))
    f_tt = 4.0 * _C.chebval(x, _C.chebder(c, 2))
    th_t = 0.5 * np.pi**2 * np.sin(np.pi * t)
    th_tt = 0.5 * np.pi**3 * np.cos(np.pi * t)
    return sel, f, f_t / th_t, f_tt / th_t**2 - f_t * th_tt / th_t**3


def _lambdified(R, syms):
    return sp.lambdify(syms, R, "numpy")


@pytest.fixture(scope="module")
def higher_ctx():
    return ham_higher.derive()


@pytest.fixture(scope="module")
def strained_ctx():
    return ham_strained.derive()


@pytest.fixture(scope="module")
def paper_R2(higher_ctx):
    """R_2 from SymPy (ham_higher), as a function of delta_j and their tau-derivatives."""
    ctx = higher_ctx
    R2 = ctx.expr["R_2"]
    tau, lam = ctx.symbols["tau"], ctx.symbols["lam"]
    fs = [sp.Function(f"delta_{j}")(tau) for j in range(2)]
    syms = [sp.Symbol(f"y{j}_{n}") for j in range(2) for n in range(3)]
    rep = {}
    for j in range(2):
        rep[fs[j].diff(tau, 2)] = syms[3 * j + 2]
        rep[fs[j].diff(tau)] = syms[3 * j + 1]
    for j in range(2):
        rep[fs[j]] = syms[3 * j]
    return ctx, _lambdified(R2.subs(rep), [lam] + syms)


@pytest.mark.parametrize("lam,c0", [(0.11, -1.0), (1.01, -0.9), (1.99, -1.3)])
def test_order2_paper_solves_its_linear_ode_and_initial_conditions(paper_R2, lam, c0):
    ctx, R2 = paper_R2
    sol = higher.HamSolution(lam, 2, c0, "paper")
    w, k = sol.omega0, sol.k
    (d0, *_), (d1, *_), (d2, d2p, _) = sol.orders
    # derivatives by spectral differentiation, in tau (d/dtau = omega0 d/dtheta)
    sel, f0, f0p, f0pp = _theta_derivs(d0)
    _, f1, f1p, f1pp = _theta_derivs(d1)
    _, f2, f2p, f2pp = _theta_derivs(d2)
    g = f2 - f1
    Lg = w**2 * f2pp - w**2 * f1pp + k * lam * w * (f2p - f1p) + k * g
    R = R2(lam, f0, w * f0p, w**2 * f0pp, f1, w * f1p, w**2 * f1pp)
    assert np.max(np.abs(Lg - c0 * R)) < 1e-8 * np.max(np.abs(R))
    # initial conditions delta_2(0) = delta_2'(0) = 0 from the interpolant at t = 0
    c = _C.chebfit(higher._X, d2, higher.N_NODES - 1)
    assert abs(_C.chebval(-1.0, c)) < 1e-13
    assert abs(_C.chebval(-1.0, _C.chebfit(higher._X, d2p, higher.N_NODES - 1))) < 1e-12


@pytest.fixture(scope="module")
def strained_R(strained_ctx):
    ctx = strained_ctx
    R = ctx.expr["strained_R"]
    lam = ctx.symbols["lam"]
    E = [[sp.Symbol(f"E{j}_{n}", positive=(j == 0 and n == 0)) for n in range(3)] for j in range(5)]
    Om = [sp.Symbol(f"Omega_{j}", positive=(j == 0)) for j in range(5)]
    syms = [lam] + [e for row in E for e in row] + Om
    return {m: sp.lambdify(syms, R[m], "numpy") for m in R}


@pytest.mark.parametrize("lam,c0", [(0.0, -1.0), (1.01, -1.2), (1.99, -1.4)])
def test_strained_orders_solve_their_linear_problems(strained_R, lam, c0):
    """Orders 1..4 against SymPy's R_m; every offered order: E_m(0) = E_m'(0) = 0 = E_m(pi)."""
    sol = higher.HamSolution(lam, higher.STRAINED_MAX_ORDER, c0, "strained")
    b = sol.b
    der = [_theta_derivs(E) for E, _, _ in sol.orders]
    sel = der[0][0]
    Om = list(sol.Omega) + [0.0] * 5
    for m in range(1, 5):
        args = [lam]
        for j in range(5):
            args += list(der[j][1:]) if j < m else [np.zeros(sel.sum())] * 3
        # Omega_j with j >= m do not occur in R_m (derivation); zeros are placeholders
        R = strained_R[m](*args, *[Om[j] if j < m else 0.0 for j in range(5)])
        _, f, fp, fpp = der[m]
        g, gp, gpp = (f, fp, fpp) if m == 1 else (f - der[m - 1][1], fp - der[m - 1][2],
                                                  fpp - der[m - 1][3])
        L = gpp + 2 * b * gp + (1 + b * b) * g
        assert np.max(np.abs(L - c0 * R)) < 1e-8 * np.max(np.abs(R)), m
    for m, (E, Ep, _) in enumerate(sol.orders):
        c = _C.chebfit(higher._X, E, higher.N_NODES - 1)
        scale = np.max(np.abs(E))
        assert abs(_C.chebval(1.0, c)) < 1e-10 * max(scale, 1e-3), m  # E_m(pi) = 0
        assert abs(_C.chebval(-1.0, c)) < 1e-13, m
        cp = _C.chebfit(higher._X, Ep, higher.N_NODES - 1)
        assert abs(_C.chebval(-1.0, cp) - (1.0 if m == 0 else 0.0)) < 1e-10, m


# ----------------------------------------------------------------------- convergence
@pytest.mark.parametrize("lam", [0.11, 1.01, 1.51])
def test_strained_residual_and_errors_fall_with_order(lam):
    """Where the study says the strained series converges (c0 = -1, every lambda but 1.99):
    the squared residual falls at every order, and the errors against exact fall."""
    ex = zs.summary(lam, model="exact")
    res, err = [], []
    for M in range(1, higher.STRAINED_MAX_ORDER + 1):
        sol = higher.HamSolution(lam, M, -1.0, "strained")
        res.append(sol.squared_residual())
        s = sol.summary()
        err.append(max(abs(s["tau_d"] / ex.tau_d - 1), abs(s["F_m"] / ex.F_m - 1)))
    assert all(b < a for a, b in zip(res, res[1:])), res
    assert err[-1] < 0.05 * err[0] and err[3] < err[0] and err[-1] < err[3], err


def test_paper_order2_residual_below_order1():
    for lam in ham_convergence.LAMBDAS:
        r = [higher.squared_residual(lam, M, -1.0, "paper") for M in (1, 2)]
        assert r[1] < r[0], (lam, r)


@pytest.mark.parametrize("lam", [0.11, 1.01])
def test_high_order_meets_momentum_identity(lam):
    """I(tau_d) = 1 + e holds for the exact solution; order 8 meets it a hundred times better than
    order 1, and to the size of its own error against exact (1e-5 at lambda = 1.01)."""
    gaps = []
    for M in (1, 8):
        s = zs.summary(lam, model="ham", order=M, formulation="strained", c0=-1.0)
        gaps.append(abs(s.impulse - 1.0 - s.e))
    assert gaps[1] < 0.01 * gaps[0] and gaps[1] < 2e-5


def test_optimal_c0_is_reported_and_minimises_the_residual():
    lam, M = 1.01, 3
    s = zs.summary(lam, model="ham", order=M, formulation="strained")
    assert s.c0 == higher.optimal_c0(lam, M, "strained")
    r = lambda c: higher.squared_residual(lam, M, c, "strained")  # noqa: E731
    assert r(s.c0) <= min(r(s.c0 - 0.01), r(s.c0 + 0.01), r(-1.0))
    h = zs.history(lam, np.linspace(0, 4, 9), model="ham", order=M, formulation="strained")
    hx = zs.history(lam, np.linspace(0, 4, 9), model="ham", order=M, formulation="strained", c0=s.c0)
    np.testing.assert_array_equal(h.force, hx.force)


def test_strained_lambda_bound_is_where_omega0_disappears():
    assert higher.strained_lam_bound() == pytest.approx(higher.STRAINED_LAM_BOUND, abs=2e-9)
    assert higher._has_omega0(higher.STRAINED_LAM_BOUND - 1e-6)
    assert not higher._has_omega0(higher.STRAINED_LAM_BOUND + 1e-6)


# ------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("opts,words", [
    (dict(order=3), ["order 3", "not integrable", "Allowed orders: 1, 2", "strained"]),
    (dict(order=0), ["positive integer", "1 to 2"]),
    (dict(order=-2), ["positive integer"]),
    (dict(order=1.5), ["positive integer"]),
    (dict(order=True), ["positive integer"]),
    (dict(order="2"), ["positive integer"]),
    (dict(order=9, formulation="strained"), ["1 to 8"]),
    (dict(c0=0.0), ["c0", "non-zero"]),
    (dict(c0=math.nan), ["c0", "finite"]),
    (dict(c0=math.inf), ["c0", "finite"]),
    (dict(c0="x"), ["c0"]),
    (dict(formulation="lindstedt"), ["'paper', 'strained'"]),
    (dict(backend="numpy"), ["allowed options"]),
])
def test_bad_options_raise_naming_allowed_values(opts, words):
    with pytest.raises(ValueError) as exc:
        zs.summary(1.0, model="ham", **opts)
    for w in words:
        assert w in str(exc.value), (w, str(exc.value))


@pytest.mark.parametrize("lam,opts,word", [
    (2.5, {}, "2.44243"), (-0.1, {}, ">= 0"), (math.nan, {}, "finite"),
    (2.1, dict(formulation="strained"), "2.032131391"),
])
def test_lambda_beyond_the_formulation_raises(lam, opts, word):
    with pytest.raises(ValueError, match=word.replace(".", r"\.").replace("(", r"\(")):
        zs.summary(lam, model="ham", **opts)
    with pytest.raises(ValueError):
        zs.history(lam, [0.0, 1.0], model="ham", **opts)


# ----------------------------------------------------------------------- derivations
def test_derivation_modules_pass(higher_ctx, strained_ctx):
    for ctx in (higher_ctx, strained_ctx):
        bad = [s for s in ctx.log.steps if not s.passed]
        assert not bad, bad
        assert len(ctx.log.steps) >= 13
    ctx = higher_ctx
    assert ctx.expr["higher_exponents"] == {1: 0, 2: sp.Rational(-1, 2), 3: sp.Rational(-3, 2),
                                            4: sp.Rational(-5, 2)}


def test_paper_order2_forcing_grows_like_inverse_sqrt_at_the_end():
    """Numerical face of the local exponent: R_2 ~ s^(-1/2) as tau -> pi/omega0 (lambda > 0)."""
    sol = higher.HamSolution(1.01, 1, -1.0, "paper")
    (d0, d0p, d0pp), (d1, d1p, d1pp) = sol.orders
    R2 = d1pp + 1.5 * np.sqrt(d0) * d1 + sol.lam * (0.75 * d0p * d1 / np.sqrt(d0) + 1.5 * np.sqrt(d0) * d1p)
    s = (np.pi - higher._TH) / sol.omega0
    tail = np.argsort(s)[:3]
    slope = np.polyfit(np.log(s[tail]), np.log(np.abs(R2[tail])), 1)[0]
    assert slope == pytest.approx(-0.5, abs=0.02)


# ------------------------------------------------------------------------- freshness
@pytest.fixture(scope="module")
def study_rows():
    return ham_convergence.study()


def test_freshness_forgives_only_a_last_digit_flip():
    """A number at a rounding boundary may print one unit apart on another processor; two
    units, another order of magnitude or changed text around the numbers are differences."""
    same = ham_convergence._same_to_last_digit
    row = "strained,1.01e+00,8,optimal,-1.22e+00,1.37e-12,4.38e-07,-1.30e-06,{},1.61e-06"
    assert same(row.format("2.72e-07"), row.format("2.73e-07"))
    assert same("| 0.125 |", "| 0.126 |")
    assert not same(row.format("2.72e-07"), row.format("2.74e-07"))
    assert not same(row.format("2.72e-07"), row.format("2.72e-06"))
    assert not same(row.format("2.72e-07"), row.format("2.72e-07").replace("optimal", "paper"))
    assert not same("| 0.125 |", "| 0.125 | 1 |")
    assert not same("| strained | 1.01 | 8 |", "| strained | 1.01 | 9 |")


def test_committed_convergence_table_is_fresh(study_rows):
    diffs = ham_convergence.check(root=ROOT, rows=study_rows)
    assert not diffs, "run 'zener-sym ham-convergence':\n" + "\n".join(diffs[:40])


def test_stale_table_gives_a_diff(study_rows, tmp_path):
    root = ROOT
    (tmp_path / "docs" / "data").mkdir(parents=True)
    md = (root / "docs" / "ham_convergence.md").read_text()
    (tmp_path / "docs" / "ham_convergence.md").write_text(md.replace("| strained | 1.01 | 8 |", "| strained | 1.01 | 9 |"))
    shutil.copy(root / "docs" / "data" / "ham_convergence.csv", tmp_path / "docs" / "data")
    diffs = ham_convergence.check(root=tmp_path, rows=study_rows)
    assert any(d.startswith("-| strained | 1.01 | 9 |") for d in diffs)
    assert any(d.startswith("+| strained | 1.01 | 8 |") for d in diffs)
