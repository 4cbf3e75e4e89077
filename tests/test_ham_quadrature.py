"""The numpy square-root integrals against two independent high-precision routes (mpmath.quad of
the integrand, and the 2F1 closed form the mpmath kernels use)."""
import mpmath
import numpy as np
import pytest

from zener_sym.numerics.sqrt_integrals import sqrt_integrals

G = {"cc": lambda t: mpmath.cos(t) ** 2, "sc": lambda t: mpmath.sin(t) * mpmath.cos(t),
     "ss": lambda t: mpmath.sin(t) ** 2, "s": mpmath.sin}


def _quad(name, a, theta):
    theta = min(mpmath.mpf(theta), mpmath.pi)
    f = lambda t: mpmath.exp(-a * t) * G[name](t) * mpmath.sqrt(mpmath.sin(t))  # noqa: E731
    pts = [0, theta] if theta <= 1 else [0, 1, theta]
    return mpmath.quad(f, pts)


@pytest.mark.parametrize("a", [0.0, 0.37, 4.0, 25.0, 300.0])
def test_against_mpmath_quad(a):
    thetas = [1e-8, 1e-3, 0.9, np.pi / 2, 2.2, np.pi - 1e-3, np.pi - 1e-8, np.pi, 4.0]
    got = sqrt_integrals(a, np.array(thetas), ("cc", "sc", "ss", "s"))
    with mpmath.workdps(30):
        for j, th in enumerate(thetas):
            for n in got:
                ref = float(_quad(n, mpmath.mpf(a), mpmath.mpf(th)))
                # relative 1e-13; absolute 1e-16 where the integral passes through zero (sc)
                assert abs(got[n][j] - ref) <= 1e-13 * abs(ref) + 1e-16, (a, th, n, got[n][j], ref)


def test_closed_form_matches_quadrature_at_30_digits():
    """The J_m 2F1 closed form of the mpmath kernels, checked against mpmath.quad (30 digits)."""
    from zener_sym.ham.runtime_mpmath import sqrt_integrals_mp

    with mpmath.workdps(30):
        for a in ("0", "0.4", "7"):
            for th in ("1e-8", "0.001", "1.3", "3.1", "3.14159264"):
                a_, th_ = mpmath.mpf(a), mpmath.mpf(th)
                K = sqrt_integrals_mp(("cc", "sc", "ss", "s"), a_, th_)
                for n, v in K.items():
                    with mpmath.workdps(50):  # the reference sums O(1) pieces to ~1e-20 near pi
                        ref = _quad(n, a_, th_)
                    # relative; absolute 1e-29 where K_sc(0, theta) passes through 0 at pi
                    assert abs(v - ref) <= mpmath.mpf("1e-27") * abs(ref) + mpmath.mpf("1e-29"), (a, th, n)


def test_frozen_past_pi_and_zero_at_zero():
    a = np.array([0.0, 1.0, 50.0])
    at_pi = sqrt_integrals(a, np.pi)
    later = sqrt_integrals(a, 3 * np.pi)
    zero = sqrt_integrals(a, 0.0)
    for n in at_pi:
        np.testing.assert_array_equal(at_pi[n], later[n])
        np.testing.assert_array_equal(zero[n], 0.0)


def test_broadcasting_and_blocks():
    a = np.linspace(0, 3, 5)[:, None]
    th = np.linspace(0, 4, 1000)[None, :]
    K = sqrt_integrals(a, th, ("cc",))["cc"]  # 5000 points: more than one block
    assert K.shape == (5, 1000)
    row = sqrt_integrals(a[2, 0], th[0], ("cc",))["cc"]
    np.testing.assert_array_equal(K[2], row)


@pytest.mark.parametrize("a,th", [(-1.0, 1.0), (np.nan, 1.0), (1.0, -0.1), (1.0, np.inf)])
def test_bad_input(a, th):
    with pytest.raises(ValueError, match="must be finite and >= 0"):
        sqrt_integrals(a, th)


def test_impulse_series_against_the_rule_on_lines_and_scattered():
    """K_s from the piecewise series (one rate per line, or scattered rates, some past the
    series' A_SERIES) against the Gauss-Jacobi rule, and bad input refused on either path."""
    from zener_sym.numerics.sqrt_integrals import A_SERIES, impulse_s, sqrt_integrals

    rates = np.array([0.0, 0.37, 2.9, 8.5, A_SERIES, 1.3 * A_SERIES])
    theta = np.linspace(0.0, 3.5, 157)  # past pi: K_s stays at K_s(a, pi)
    ref = sqrt_integrals(np.repeat(rates, theta.size), np.tile(np.minimum(theta, np.pi),
                                                               rates.size), ("s",))["s"]
    ref = ref.reshape(rates.size, theta.size)
    lines = impulse_s(np.broadcast_to(rates[:, None], ref.shape), np.broadcast_to(theta, ref.shape))
    scattered = impulse_s(np.repeat(rates, theta.size), np.tile(theta, rates.size))
    assert np.max(np.abs(lines - ref)) < 2e-14  # K_s is up to 1.1 here
    assert np.max(np.abs(scattered.reshape(ref.shape) - ref)) < 2e-14
    col = np.broadcast_to(np.array([[0.5], [np.nan]]), (2, 4))
    for a, th in ((col, np.ones((2, 4))), (-1.0, 1.0), (1.0, np.nan), (1.0, -0.1),
                  (1.0, np.inf)):
        with pytest.raises(ValueError, match="impulse_s"):
            impulse_s(a, th)


def test_ks_series_blocks_against_the_rule():
    """KsSeries.at, the block evaluator models call, at rates given per point in any order
    (past pi: K_s(a, pi)) against the Gauss-Jacobi rule; rates outside [0, A_SERIES] refused."""
    from zener_sym.numerics.sqrt_integrals import A_SERIES, KsSeries

    u = np.array([0.0, 1.7, 6.0, A_SERIES])
    rng = np.random.default_rng(5)
    iv = rng.integers(0, u.size, 500)
    th = rng.uniform(0.0, 1.2 * np.pi, 500)
    ref = sqrt_integrals(u[iv], np.minimum(th, np.pi), ("s",))["s"]
    assert np.max(np.abs(KsSeries(u).at(th, iv) - ref)) < 2e-14
    for bad in ([-0.1], [np.nan], [1.01 * A_SERIES]):
        with pytest.raises(ValueError, match="KsSeries"):
            KsSeries(bad)


def test_impulse_series_with_more_rates_than_one_group(monkeypatch):
    """Scattered rates (one per point) beyond the group size are contracted group by group:
    the same numbers as in one group up to the series' trimming (which depends on the rates at
    hand), and within the rule's tolerance."""
    from zener_sym.numerics import sqrt_integrals as q

    rng = np.random.default_rng(8)
    a = rng.uniform(0.0, q.A_SERIES, 300)
    th = rng.uniform(0.0, 3.3, 300)
    whole = q.impulse_s(a, th)
    monkeypatch.setattr(q, "_MAX_RATES", 7)
    grouped = q.impulse_s(a, th)
    assert np.max(np.abs(grouped - whole)) < 1e-14
    ref = sqrt_integrals(a[::30], np.minimum(th[::30], np.pi), ("s",))["s"]
    assert np.max(np.abs(grouped[::30] - ref)) < 2e-14
