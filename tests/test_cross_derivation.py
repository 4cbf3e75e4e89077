"""Two independent routes to the first-order solution: the derivation's closed form (its own 2F1
antiderivatives, (40)-(42)) against the generated mpmath kernels (J_m closed forms, convolution
form), at 30 digits; and the derivation's Hunter/Reed pulses against formulas.py."""
import mpmath
import numpy as np
import pytest
import sympy as sp


@pytest.fixture(scope="module")
def reg():
    from zener_sym.derivation.registry import derive

    return derive(checks=False)


@pytest.mark.slow
def test_delta_ham1_two_derivations_agree(reg):
    from zener_sym.ham.runtime_mpmath import ham1 as m1

    Y = reg.symbols
    f = sp.lambdify((Y["tau"], Y["lam"], Y["beta"], Y["omega0"]), reg.expr["delta_ham1"],
                    modules="mpmath")
    with mpmath.workdps(30):
        for lam in ("0", "0.5", "1.99", "2.43"):
            k, beta, omega0 = m1.params(lam)
            for frac in ("0.05", "0.5", "0.95"):
                tau = mpmath.mpf(frac) * mpmath.pi / omega0
                theirs = f(tau, mpmath.mpf(lam), beta, omega0)
                ours = m1.delta(tau, lam)
                assert abs(mpmath.re(theirs) - ours) < mpmath.mpf("1e-24") * abs(ours), (lam, frac)
                assert abs(mpmath.im(theirs)) < mpmath.mpf("1e-24")


@pytest.mark.slow
def test_hunter_reed_pulses_agree_with_formulas(reg):
    from zener_sym.models import formulas as fm

    tau_sym = reg.symbols["tau"]
    taus = np.linspace(0.05, 3.1, 7)
    for name, mine in (("F_hunter", fm.F_hunter), ("F_reed", fm.F_reed)):
        f = sp.lambdify(tau_sym, reg.expr[name], modules="numpy")
        theirs = np.array([float(sp.re(complex(f(t)))) for t in taus])
        np.testing.assert_allclose(mine(taus), theirs, rtol=1e-12, err_msg=name)
