"""The ham0/ham1/hertz/hunter/reed/oneway models through the uniform API."""
import numpy as np
import pytest
from scipy.integrate import quad

import zener_sym as zs
from zener_sym.ham.runtime_numpy import ham1 as h1


def test_models_registered():
    for m in ("ham0", "ham1", "hertz", "hunter", "reed", "oneway"):
        assert m in zs.MODELS


def test_ham1_history_mpmath_backend_matches_numpy():
    tau = np.array([0.0, 0.3, 1.7, 3.9, 4.5, 6.0])
    a = zs.history(1.01, tau, model="ham1")
    b = zs.history(1.01, tau, model="ham1", backend="mpmath", dps=20)
    for f in ("delta", "force", "impulse", "velocity"):
        np.testing.assert_allclose(getattr(a, f), getattr(b, f), rtol=1e-10, atol=1e-12, err_msg=f)


def test_ham0_mpmath_backend_summary_and_history():
    a = zs.summary([0.0, 1.51], model="ham0")
    b = zs.summary([0.0, 1.51], model="ham0", backend="mpmath", dps=25)
    for f in a.fields:
        np.testing.assert_allclose(getattr(a, f), getattr(b, f), rtol=1e-12, err_msg=f)
    tau = np.array([0.1, 2.0, 5.0])
    ha = zs.history(1.51, tau, model="ham0")
    hb = zs.history(1.51, tau, model="ham0", backend="mpmath")
    for f in ("delta", "force", "impulse"):
        np.testing.assert_allclose(getattr(ha, f), getattr(hb, f), rtol=1e-10, atol=1e-12)


@pytest.mark.slow
def test_ham1_summary_mpmath_backend():
    a = zs.summary(1.51, model="ham1")
    b = zs.summary(1.51, model="ham1", backend="mpmath", dps=20)
    for f in a.fields:
        assert getattr(a, f) == pytest.approx(getattr(b, f), rel=1e-10), f


def test_ham1_impulse_against_scipy_quad_of_the_force():
    """Independent route: adaptive quadrature of the force history."""
    lam = 1.51
    s = zs.summary(lam, model="ham1")
    F = lambda t: float(h1.force(t, lam))  # noqa: E731  (the kernel; t <= tau_d below)
    tpi = float(np.pi / h1.params(lam)[2])
    for t in (0.8, 3.0, s.tau_d):
        pts = [p for p in (tpi,) if p < t]
        ref, _ = quad(F, 0, t, points=pts or None, epsabs=1e-13, epsrel=1e-12, limit=200)
        got = zs.history(lam, t, model="ham1").impulse
        assert got == pytest.approx(ref, rel=1e-9)
    assert s.impulse == pytest.approx(ref, rel=1e-9)


def test_after_contact_end_everything_is_frozen():
    lam = 0.5
    s = zs.summary(lam, model="ham1")
    tau = s.tau_d + np.array([0.0, 1e-9, 0.5, 3.0, 30.0])
    h = zs.history(lam, tau, model="ham1")
    assert np.all(h.delta == 0) and np.all(h.force == 0)
    np.testing.assert_allclose(h.impulse, s.impulse, rtol=1e-12)
    np.testing.assert_allclose(h.velocity, 1 - s.impulse, rtol=1e-12)


def test_ham1_delta_continuous_through_pi_over_omega0():
    """The continuation: delta and delta' have no jump at pi/omega0."""
    lam = 1.01
    tpi = float(np.pi / h1.params(lam)[2])
    eps = 1e-7
    d = h1.delta(np.array([tpi - eps, tpi, tpi + eps]), lam)
    v = h1.delta_dot(np.array([tpi - eps, tpi + eps]), lam)
    assert abs(d[2] - d[0]) < 2.1 * eps * abs(v[0])
    assert abs(v[1] - v[0]) < 1e-6  # O(eps delta''), no O(1) jump


def test_history_broadcasting_2d():
    lam = np.array([[0.0], [1.0], [2.0]])
    tau = np.linspace(0, 8, 50)[None, :]
    h = zs.history(lam, np.broadcast_to(tau, (3, 50)), model="ham1")
    assert h.force.shape == (3, 50)
    row = zs.history(1.0, tau[0], model="ham1")
    np.testing.assert_allclose(h.impulse[1], row.impulse, rtol=1e-14)


@pytest.mark.parametrize("model", ["ham0", "ham1"])
def test_ham_bound_is_lam_crit(model):
    with pytest.raises(ValueError, match=r"0 <= lambda < 2\.44243892998"):
        zs.summary(2.45, model=model)
    with pytest.raises(ValueError, match=r"0 <= lambda < 2\.44243892998"):
        zs.history(h1.LAM_CRIT, [1.0], model=model)


@pytest.mark.parametrize("opts,msg", [({"backend": "torch"}, "unknown backend"),
                                      ({"dps": 30}, "goes with backend='mpmath'"),
                                      ({"backend": "mpmath", "dps": 5}, "dps must be"),
                                      ({"rtol": 1e-3}, "takes no option")])
def test_bad_options(opts, msg):
    with pytest.raises(ValueError, match=msg):
        zs.summary(1.0, model="ham1", **opts)


def test_hertz_ignores_lambda_and_equals_exact_at_zero():
    ex = zs.summary(0.0, model="exact")
    for lam in (0.0, 1.5, 7.0):
        s = zs.summary(lam, model="hertz")
        for f in ("delta_m", "tau_d", "F_m", "impulse", "int_F2"):
            assert getattr(s, f) == getattr(ex, f)
    assert zs.history(2.0, [1.0], model="hertz").force[0] == zs.history(0.0, [1.0], model="exact").force[0]


@pytest.mark.parametrize("model", ["hunter", "reed"])
def test_pulses_give_no_restitution(model):
    s = zs.summary(0.3, model=model)
    with pytest.raises(zs.FieldUnavailableError, match=f"model '{model}' does not give"):
        s.e
    with pytest.raises(zs.FieldUnavailableError):
        s.xi
    h = zs.history(0.3, np.linspace(0, 4, 9), model=model)
    assert h.force[-1] == 0.0 and h.impulse[-1] == pytest.approx(s.impulse, rel=1e-12)
    assert s.eta == 1.0


def test_oneway_small_lambda_agrees_with_exact_to_first_order():
    """xi = 2 lambda int F_Hertz^2 is the first term of exact xi(lambda): the ratio -> 1 linearly."""
    for lam in (1e-3, 1e-2):
        o, ex = zs.summary(lam, model="oneway"), zs.summary(lam, model="exact")
        assert abs(o.xi / ex.xi - 1) < 3 * lam
        assert o.e == pytest.approx(np.sqrt(1 - o.xi), rel=1e-15)
    assert zs.summary(0.0, model="oneway").e == 1.0


def test_oneway_bound_and_missing_fields():
    J = zs.summary(0.0, model="hertz").int_F2
    lam_max = 1 / (2 * J)
    assert zs.summary(lam_max, model="oneway").e == pytest.approx(0.0, abs=1e-7)
    with pytest.raises(ValueError, match="outside the validity of model 'oneway'"):
        zs.summary(0.3, model="oneway")
    with pytest.raises(zs.FieldUnavailableError):
        zs.summary(0.1, model="oneway").tau_d
