"""Generated numpy kernels against the generated mpmath kernels (2F1 closed forms at 30 digits),
the mpmath kernels against the first-order equations themselves, and the edges."""
import mpmath
import numpy as np
import pytest

from zener_sym.ham.runtime_mpmath import ham0 as m0
from zener_sym.ham.runtime_numpy import ham0 as h0
from zener_sym.ham.runtime_mpmath import ham1 as m1
from zener_sym.ham.runtime_numpy import ham1 as h1

LAMS = [0.0, 0.11, 1.01, 1.99, 2.3, 2.4399]


def _taus(lam):
    k, beta, omega0 = h1.params(lam)
    tpi = float(np.pi / omega0)
    return [0.0, 1e-8, 1e-3 * tpi, 0.25 * tpi, 0.5 * tpi, 0.9 * tpi, tpi - 1e-8, tpi], tpi


def _close(x, y, rel=1e-10, abs_=1e-12):
    return abs(x - y) <= rel * abs(y) + abs_


@pytest.mark.parametrize("lam", LAMS)
def test_numpy_matches_mpmath_on_contact(lam):
    taus, tpi = _taus(lam)
    taus = taus + [1.1 * tpi, 1.5 * tpi]  # the continuation, same in both backends
    with mpmath.workdps(30):
        for mod_np, mod_mp in ((h0, m0), (h1, m1)):
            for name in ("delta", "delta_dot", "force"):
                got = getattr(mod_np, name)(np.array(taus), lam)
                for t, g in zip(taus, got):
                    ref = float(getattr(mod_mp, name)(t, lam))
                    assert _close(g, ref), (mod_np.__name__, name, lam, t, g, ref)


@pytest.mark.parametrize("lam", [0.0, 1.01, 2.4399])
def test_ham0_impulse_against_closed_form_and_direct_quadrature(lam):
    taus, tpi = _taus(lam)
    got = h0.impulse(np.array(taus), lam)
    with mpmath.workdps(30):
        k, beta, omega0 = m0.params(lam)
        F = lambda t: m0.delta0(t, lam) ** 1.5  # noqa: E731
        for t, g in zip(taus, got):
            ref = m0.impulse(t, lam)
            assert _close(g, float(ref)), (lam, t, g, ref)
            if 0 < t <= 0.9 * tpi:  # independent route: quadrature of delta0^(3/2)
                assert abs(ref - mpmath.quad(F, [0, t])) < mpmath.mpf("1e-25")


@pytest.mark.parametrize("lam", [0.0, 0.5, 1.51, 2.4399])
def test_ham0_summary_numpy_vs_mpmath(lam):
    a = h0.summary(lam)
    b = m0.summary(lam, 30)
    for f in ("tau_d", "tau_dc", "tau_dr", "eta", "e", "delta_m", "F_m", "impulse", "int_F2"):
        assert _close(float(np.asarray(a[f]).ravel()[0]), float(b[f]), 1e-12, 1e-15), f
    # independent: int_F2 by quadrature of delta0^3 at 30 digits
    with mpmath.workdps(30):
        J = mpmath.quad(lambda t: m0.delta0(t, lam) ** 3, [0, b["tau_d"]])
    assert abs(J - b["int_F2"]) < mpmath.mpf("1e-25") * J


@pytest.mark.parametrize("lam", ["0", "1.01", "2.3"])
def test_mpmath_delta1_solves_first_order_problem(lam):
    """Eq. (30)-(31): delta1'' + k lam delta1' + k delta1 = -(N(delta0)), delta1(0) = delta1'(0) = 0,
    with the forcing built here from delta0 directly (not from the derivation's f)."""
    with mpmath.workdps(30):
        lam = mpmath.mpf(lam)
        k, beta, omega0 = m1.params(lam)
        d1 = lambda t: m1.delta1(t, lam)  # noqa: E731
        d0 = lambda t: mpmath.exp(-beta * t) * mpmath.sin(omega0 * t) / omega0  # noqa: E731
        for frac in ("0.01", "0.4", "0.97"):
            t = mpmath.mpf(frac) * mpmath.pi / omega0
            N0 = (mpmath.diff(d0, t, 2) + mpmath.mpf(1.5) * lam * mpmath.sqrt(d0(t)) * mpmath.diff(d0, t)
                  + d0(t) ** 1.5)
            lhs = mpmath.diff(d1, t, 2) + k * lam * mpmath.diff(d1, t) + k * d1(t)
            assert abs(lhs + N0) < mpmath.mpf("1e-24") * (1 + abs(N0)), (lam, frac)
        assert m1.delta1(0, lam) == 0
        assert abs(mpmath.diff(d1, mpmath.mpf("1e-25"))) < mpmath.mpf("1e-20")


@pytest.mark.slow
@pytest.mark.parametrize("lam", [0.0, 1.01, 2.3])
def test_first_order_contact_end_and_impulse_vs_mpmath(lam):
    s = h1.summary(lam)
    with mpmath.workdps(20):
        td = m1.contact_end(lam)
        tdc = m1.compression_end(lam)
        assert _close(s["tau_d"][0], float(td), 1e-12, 0)
        assert _close(s["tau_dc"][0], float(tdc), 1e-10, 0)
        assert m1.delta(td, lam) == pytest.approx(0, abs=1e-18)
        I = m1.impulse(td, lam, tau_d=td)
        assert _close(s["impulse"][0], float(I), 1e-10, 0)
        # an interior tau, before and after pi/omega0
        k, beta, omega0 = h1.params(lam)
        for t in (0.6 * float(td), 0.5 * (float(np.pi / omega0) + float(td))):
            t = min(t, 0.999 * float(td))
            g = h1.impulse(t, lam)
            assert _close(float(g), float(m1.impulse(t, lam, tau_d=td)), 1e-10, 1e-12)


def test_lambda_zero_is_the_hertz_limit():
    """(49)-(50): at lambda = 0, beta = 0 and omega0 = (5/4)^(1/10)."""
    k, beta, omega0 = h1.params(0.0)
    assert beta == 0.0
    assert omega0 == pytest.approx(1.25 ** 0.1, rel=1e-15)
    tau = np.linspace(0, 3, 7)
    np.testing.assert_allclose(h0.delta(tau, 0.0), np.sin(omega0 * tau) / omega0, rtol=1e-15,
                               atol=1e-16)
    assert np.all(np.isfinite(h1.delta(tau, 0.0)))


def test_near_critical_lambda_is_finite():
    lam = np.nextafter(h1.LAM_CRIT, 0)
    k, beta, omega0 = h1.params(lam)
    assert 0 < omega0 < 1e-6
    tau = np.array([0.0, 1e-8, 1.0, 10.0, 1e3, float(np.pi / omega0)])
    for f in (h1.delta, h1.delta_dot, h1.force, h0.delta, h0.impulse):
        assert np.all(np.isfinite(f(tau, lam)))
    s = h1.summary([lam])
    assert all(np.all(np.isfinite(v)) for v in s.values())


@pytest.mark.parametrize("mod", [h0, h1])
@pytest.mark.parametrize("lam", [2.4425, 3.0, -0.1, np.nan, np.inf])
def test_lambda_outside_range(mod, lam):
    with pytest.raises(ValueError, match="LAM_CRIT = 2.44243892998"):
        mod.delta(1.0, lam)


@pytest.mark.parametrize("mod", [m0, m1])
def test_mpmath_lambda_outside_range(mod):
    with pytest.raises(ValueError, match="LAM_CRIT = 2.44243892998"):
        mod.delta(1, "2.4425")


def test_negative_tau():
    with pytest.raises(ValueError, match="tau must be finite and >= 0"):
        h1.delta(-1e-3, 1.0)


def test_lam_crit_value():
    """omega0 = 0 at lam_crit: k lam^2 = 4, checked at 40 digits with mpmath."""
    with mpmath.workdps(45):
        lc = mpmath.mpf(h1.LAM_CRIT_DIGITS)
        k = (lc + mpmath.mpf(5) / 4 ** mpmath.mpf(-0.6)) if False else (lc + (mpmath.mpf(5) / 4) ** (-mpmath.mpf(3) / 5)) ** (-mpmath.mpf(1) / 3)
        assert abs(k * lc**2 - 4) < mpmath.mpf("1e-38")
    assert h1.LAM_CRIT == float(h1.LAM_CRIT_DIGITS)


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=40, deadline=None)
@given(lam=st.floats(0.0, 2.4424), frac=st.floats(0.0, 3.0))
def test_kernels_finite_and_force_consistent(lam, frac):
    """Anywhere in the range: finite values, force = max(delta, 0)^(3/2), impulse nondecreasing."""
    k, beta, omega0 = h1.params(lam)
    tau = np.array([0.5, 1.0]) * frac * float(np.pi / omega0)
    d = h1.delta(tau, lam)
    assert np.all(np.isfinite(d)) and np.all(np.isfinite(h1.delta_dot(tau, lam)))
    np.testing.assert_array_equal(h1.force(tau, lam), np.maximum(d, 0) ** 1.5)
    imp = h0.impulse(tau, lam)
    assert np.all(np.isfinite(imp)) and imp[1] >= imp[0] >= 0


def test_runtime_kernels_document_themselves():
    # the kernels wrap functools.partial objects of the generated formulas, whose __doc__ is
    # partial's own ("partial(func, *args, ...)"): each kernel names its formula and equation
    # and describes its own arguments (tau, lam[, dps]), not the formula's (xp, beta, ...)
    from zener_sym.ham import runtime_mpmath, runtime_numpy

    kernels = {"numpy ham1.delta": (runtime_numpy.ham1.delta, "delta0 + delta1 (42)"),
               "numpy ham1.delta_from_K": (runtime_numpy.ham1.delta_from_K, "(42)"),
               "numpy ham1.delta_dot_scaled": (runtime_numpy.ham1.delta_dot_scaled, "exp(beta tau)"),
               "mpmath delta0": (runtime_mpmath.delta0, "delta0 (35)"),
               "mpmath ham1.delta": (runtime_mpmath.ham1.delta, "(42)")}
    for name, (kernel, says) in kernels.items():
        doc = kernel.__doc__ or ""
        assert says in doc.splitlines()[0], name
        assert "partial(" not in doc and "xp : " not in doc, name
        assert "tau : " in doc and "lam : " in doc and "Returns" in doc, name


def test_delta_contact_takes_scalars():
    # a scalar tau and lambda used to raise TypeError from inside numpy (half_wave_sin's in-place
    # steps on a numpy scalar); a scalar gives the value of the one-element array, delta0 (35)
    # on the contact, 0 after it
    import numpy as np

    from zener_sym.ham.runtime_numpy import ham0

    k, beta, omega0 = ham0.params(1.0)
    for tau in (0.5, 0.99 * np.pi / omega0, 1.5 * np.pi / omega0):
        d = ham0.delta_contact(tau, 1.0)
        assert np.shape(d) == ()
        assert float(d) == float(ham0.delta_contact([tau], 1.0)[0])
        expect = max(float(ham0.delta0(tau, 1.0)), 0.0) if omega0 * tau <= np.pi else 0.0
        assert abs(float(d) - expect) <= 1e-15
