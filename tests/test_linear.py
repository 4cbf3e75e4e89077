"""The linear law (Mueller et al.), Raman's slope and the paper's fits as models.

Expected values come from independent routes: the damped oscillator integrated numerically here
(scipy), the derivation's SymPy constants, and the exact model's finite-difference slope.
"""
import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import zener_sym as zs
from zener_sym.derivation import linear as dlin
from zener_sym.models import formulas as fm
from zener_sym.models.base import FieldUnavailableError
from zener_sym.models.linear import RAMAN_C1, STIFFNESS, TAU_HERTZ


def _oscillator(lam, kappa):
    """delta'' + kappa lambda delta' + kappa delta = 0 integrated to delta = 0, with the impulse
    and int F^2 as extra states; returns tau_d, e, F_m, impulse, int_F2 and a dense solution."""

    def rhs(t, y):
        d, v, _, _ = y
        return [v, -kappa * lam * v - kappa * d, kappa * d, (kappa * d) ** 2]

    def end(t, y):
        return y[0]

    end.terminal, end.direction = True, -1

    def top(t, y):
        return y[1]

    top.direction = -1
    sol = solve_ivp(rhs, (0.0, 100.0), [0.0, 1.0, 0.0, 0.0], method="DOP853", rtol=1e-12,
                    atol=1e-14, events=(end, top), dense_output=True)
    td = sol.t_events[0][0]
    yd = sol.y_events[0][0]
    tdc = sol.t_events[1][0]
    return dict(tau_d=td, e=-yd[1], impulse=yd[2], int_F2=yd[3], tau_dc=tdc,
                F_m=kappa * sol.y_events[1][0][0], delta_m=sol.y_events[1][0][0]), sol


@pytest.mark.parametrize("stiffness", list(STIFFNESS))
@pytest.mark.parametrize("lam", [0.0, 0.3, 1.2])
def test_linear_against_integrated_oscillator(stiffness, lam):
    kappa = STIFFNESS[stiffness]
    if lam >= 2 / math.sqrt(kappa):
        pytest.skip("beyond this stiffness's bound")
    ref, sol = _oscillator(lam, kappa)
    s = zs.summary(lam, model="linear", stiffness=stiffness)
    for f in ("tau_d", "e", "F_m", "impulse", "int_F2", "tau_dc", "delta_m"):
        assert getattr(s, f) == pytest.approx(ref[f], rel=1e-9, abs=1e-12), f
    assert s.xi == pytest.approx(1 - ref["e"] ** 2, rel=1e-9, abs=1e-10)
    tau = np.linspace(0.0, 0.999 * ref["tau_d"], 50)
    h = zs.history(lam, tau, model="linear", stiffness=stiffness)
    y = sol.sol(tau)
    assert np.allclose(h.delta, y[0], atol=1e-10)
    assert np.allclose(h.force, kappa * y[0], atol=1e-10)
    assert np.allclose(h.impulse, y[2], atol=1e-10)
    after = zs.history(lam, [1.5 * ref["tau_d"]], model="linear", stiffness=stiffness)
    assert after.force[0] == 0.0 and after.impulse[0] == pytest.approx(1 + ref["e"], rel=1e-10)


def test_stiffness_constants_match_the_derivation():
    for name, kappa in STIFFNESS.items():
        assert kappa == pytest.approx(float(sp.N(dlin.STIFFNESS[name], 30)), rel=1e-14), name
    assert RAMAN_C1 == pytest.approx(float(sp.N(dlin.RAMAN_C1, 30)), rel=1e-15)
    assert TAU_HERTZ == pytest.approx(float(sp.N(dlin.TAU_HERTZ, 30)), rel=1e-15)
    # the Hertz duration is also the exact model's at lambda = 0
    assert zs.summary(0.0).tau_d == pytest.approx(TAU_HERTZ, rel=1e-9)


def test_linear_derivation_checks_pass():
    ctx = dlin.derive()
    failed = [s.what for s in ctx.log.steps if not s.passed]
    assert not failed and len(ctx.log.steps) >= 15


def test_linear_bad_input():
    kappa = STIFFNESS["force"]
    with pytest.raises(ValueError, match="2/sqrt"):
        zs.summary(2 / math.sqrt(kappa), model="linear", stiffness="force")
    with pytest.raises(ValueError, match="allowed: duration"):
        zs.summary(0.5, model="linear", stiffness="stiff")
    with pytest.raises(ValueError, match="lambda"):
        zs.summary(3.0, model="linear")


def test_raman_slope_is_the_exact_models_slope():
    """e = 1 - c1 lambda + O(lambda^2): the exact model's difference quotient, Richardson-
    extrapolated to remove the O(lambda) term, tends to -c1 (the error shrinks 4x per halving)."""
    def slope(h):
        return (zs.summary(h, backend="scipy", rtol=1e-13).e - 1.0) / h

    errs = []
    for h in (4e-4, 2e-4):
        errs.append(abs(2 * slope(h) - slope(2 * h) + RAMAN_C1))
    assert errs[-1] < 1e-6
    assert errs[1] < errs[0] / 3
    # and raman is that line
    lam = np.array([0.0, 0.1, 0.5])
    assert np.allclose(zs.summary(lam, model="raman").e, 1 - RAMAN_C1 * lam, rtol=0, atol=1e-15)


def test_raman_c1_is_the_hertz_int_F2():
    assert zs.summary(0.0).int_F2 == pytest.approx(RAMAN_C1, rel=1e-10)


def test_raman_refuses():
    with pytest.raises(FieldUnavailableError, match="F_m"):
        zs.summary(0.1, model="raman").F_m
    with pytest.raises(ValueError, match="lambda"):
        zs.summary(0.6, model="raman")
    with pytest.raises(ValueError):
        zs.history(0.1, [0.5], model="raman")


def test_fits_model():
    lam = np.linspace(0.0, 2.4, 7)
    s = zs.summary(lam, model="fits")
    # Eq. (24) from delta_m^{-3/2} = lambda + delta_mH^{-3/2}, written here from the Hertz value
    assert np.allclose(s.delta_m ** -1.5, lam + (1.25 ** 0.4) ** -1.5, rtol=1e-14)
    assert np.allclose(s.e, zs.summary(lam, model="ham0").e, rtol=1e-12)
    assert np.allclose(s.xi, 1 - np.exp(-2.755 * lam), rtol=1e-14)
    assert np.allclose(s.tau_d, fm.TAU_HERTZ_PAPER * np.exp(0.23 * lam ** 1.8), rtol=1e-14)
    with pytest.raises(FieldUnavailableError):
        s.F_m
    with pytest.raises(ValueError):
        zs.summary(2.5, model="fits")
