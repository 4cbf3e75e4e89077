"""Eq. (10) as the viscoelastic grain contact: the mapping, the force-free end, the grain front end."""
import math

import mpmath
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.derivation import viscoelastic as dv
from zener_sym.exact import force_end as fe

SUMMARY = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")


def test_mapping_derivation_passes():
    ctx = dv.derive()
    assert ctx.log.ok, [s for s in ctx.log.steps if not s.passed]
    assert len(ctx.log.steps) >= 8


@pytest.mark.parametrize("lam", [0.0, 0.01, 0.3, 1.0, 2.5, 5.0])
def test_force_end_scipy_against_mpmath(lam):
    a, b = fe.solve(lam), fe.solve_mp(lam, dps=30)
    for f in SUMMARY:
        ref = float(getattr(b, f))
        got = float(getattr(a, f))
        if f == "xi" and lam <= 0.01 or abs(ref) < 1e-12:
            # xi = 1 - e^2 cancels when e ~ 1, eta ~ 0 at lambda = 0: absolute
            assert abs(got - ref) < 1e-13, (f, got, ref)
        else:
            assert abs(got - ref) <= 1e-11 * abs(ref), (f, got, ref)


@pytest.mark.parametrize("lam, e_issue", [(0.5, 0.4788), (1.0, 0.2811), (2.0, 0.1337)])
def test_force_end_restitution_matches_independent_integration(lam, e_issue):
    # values measured with an independent integration, quoted in issue 18 to 4 digits
    assert abs(zs.summary(lam, model="exact", contact_end="force").e - e_issue) < 6e-5


def test_force_end_is_force_free_and_after_compression():
    lam = 0.8
    s = fe.solve_mp(lam, dps=30)
    # The plate's Taylor solution at tau_d (the grains' end) has delta + 1.5 lam delta' = 0 and the
    # grains' force, evaluated from its own history just before the end, vanishes.
    with mpmath.workdps(45):
        h = s._base.history_mp([s.tau_d])
        d = h["delta"][0]
        v = h["velocity"][0] - lam * d * mpmath.sqrt(d)
        assert abs(d + mpmath.mpf(3) / 2 * lam * v) < 1e-25
    assert -v == s.e and s.tau_d > s.tau_dc
    plate = zs.summary(lam, model="exact")
    assert s.tau_d < plate.tau_d and float(s.e) > plate.e  # separates earlier, faster


def test_force_end_grain_energy_balance():
    # 1 - e^2 = 2 int (3/2) lam sqrt(delta) delta'^2 dtau + (4/5) delta(tau_d)^(5/2): the dashpot's
    # dissipation plus the elastic energy left at separation (derivation/viscoelastic.py).
    lam = 0.7
    s = fe.solve(lam)
    x, w = np.polynomial.legendre.leggauss(80)
    edges = np.linspace(0.0, s.tau_d, 41)
    diss = 0.0
    for a, b in zip(edges[:-1], edges[1:]):
        t = 0.5 * (b - a) * x + 0.5 * (a + b)
        h = s.history(t)
        diss += 0.5 * (b - a) * np.sum(w * 1.5 * lam * np.sqrt(h["delta"]) * h["velocity"] ** 2)
    d_end = s._base.history(np.nextafter(s.tau_d, 0))["delta"]
    assert abs(2 * diss + 0.8 * float(d_end) ** 2.5 - s.xi) < 1e-8


def test_force_end_history_scipy_against_mpmath():
    lam = 1.3
    tau = np.linspace(0.0, 3.0, 61)
    a = zs.history(lam, tau, model="exact", contact_end="force")
    b = zs.history(lam, tau, model="exact", contact_end="force", backend="mpmath")
    for f in ("delta", "velocity", "force", "impulse"):
        assert np.max(np.abs(getattr(a, f) - getattr(b, f))) < 1e-10, f
    s = zs.summary(lam, model="exact", contact_end="force")
    past = tau >= s.tau_d
    assert past.any() and np.all(a.force[past] == 0) and np.allclose(a.impulse[past], 1 + s.e, atol=1e-14)


def test_contact_end_bad_input():
    with pytest.raises(ValueError, match="contact_end.*allowed: 'delta'"):
        zs.summary(1.0, model="exact", contact_end="touch")
    with pytest.raises(ValueError, match="no tables"):
        zs.summary(1.0, model="exact", contact_end="force", backend="table")
    with pytest.raises(ValueError, match="outside the validity"):
        zs.summary(1500.0, model="exact", contact_end="force")
