"""The cumulative contact integral (one Chebyshev antiderivative per lambda) against the per-point
smoothstep Gauss-Legendre rule and against closed-form integrals."""
import math

import numpy as np
import pytest

from zener_sym.numerics import chebyshev, elementary, integrate
from zener_sym.ham.runtime_numpy import ham1 as k


def test_matches_per_point_quadrature_of_the_first_order_force():
    lam = np.linspace(0.0, 2.4, 13)[:, None] * np.ones((1, 60))
    tau = np.linspace(0.0, 6.0, 60)[None, :] * np.ones((13, 1))
    _, _, omega0 = k.params(lam)
    tpi = np.pi / omega0
    td = k.contact_end(lam[:, 0])[:, None] * np.ones((1, 60))
    end = np.minimum(tau, td)
    per_point = (integrate.contact_integral(k.force, np.zeros_like(end), np.minimum(end, tpi), lam)
                 + integrate.contact_integral(k.force, tpi, np.maximum(end, tpi), lam))
    cumulative = (integrate.cumulative_integral(k.force, 0.0, np.minimum(td, tpi), lam, np.minimum(end, tpi))
                  + integrate.cumulative_integral(k.force, tpi, np.maximum(td, tpi), lam, np.maximum(end, tpi)))
    np.testing.assert_allclose(cumulative, per_point, rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("p", [1.5, 3.0])
def test_closed_form_endpoint_singularities(p):
    # integral_0^x t^p (1 - t)^p dt has the endpoint behaviour of the force; compare with the
    # regularised incomplete beta function
    from scipy.special import beta, betainc

    x = np.linspace(0.0, 1.0, 41)
    got = integrate.cumulative_integral(lambda t, lam: t**p * (1 - t) ** p, 0.0, 1.0, np.zeros_like(x), x)
    want = beta(p + 1, p + 1) * betainc(p + 1, p + 1, x)
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-16)
    assert abs(got[0]) < 1e-17


def test_empty_segment_is_zero():
    assert integrate.cumulative_integral(lambda t, lam: 1.0 + 0 * t, 2.0, 2.0, 0.5, 2.0) == 0.0


def test_p3_against_mpmath_on_both_sides_of_the_series_switch():
    import mpmath

    x = np.concatenate([[0.0, 1e-9, 0.1, 0.4999999, 0.5, 0.5000001, 1.0, 3.0, np.pi, 9.0],
                        -np.array([0.2, 0.7])])
    with mpmath.workdps(50):
        ref = [mpmath.mpf(1) / 3 if v == 0 else
               (mpmath.sin(v) - v * mpmath.cos(v)) / mpmath.mpf(v) ** 3 for v in x]
        ref = np.array([float(r) for r in ref])
    got = elementary.p3(x.reshape(3, 4)).ravel()
    np.testing.assert_allclose(got, ref, rtol=2e-15, atol=0)
    assert elementary.p3(0.3).shape == () and elementary.p3(0.3) == elementary.p3(np.array([0.3]))[0]


def test_clenshaw_take_against_chebval_for_scattered_and_broadcast_rows():
    rng = np.random.default_rng(3)
    coef = rng.normal(size=(5, 9))  # 5 rows of 9 coefficients
    x = rng.uniform(-1.0, 1.0, (5, 7))
    ref = np.array([np.polynomial.chebyshev.chebval(x[i], coef[i]) for i in range(5)])
    cT = np.ascontiguousarray(coef.T)
    column = np.broadcast_to(np.arange(5)[:, None], x.shape)  # a broadcast view
    np.testing.assert_allclose(chebyshev.clenshaw_take(cT, column, x), ref, rtol=1e-13, atol=1e-13)
    np.testing.assert_array_equal(chebyshev.clenshaw_take(cT, column, x),
                                  chebyshev.clenshaw_take(cT, np.array(column), x))
    perm = rng.permutation(x.size)
    flat = chebyshev.clenshaw_take(cT, np.array(column).ravel()[perm], x.ravel()[perm])
    np.testing.assert_allclose(flat, ref.ravel()[perm], rtol=1e-13, atol=1e-13)


def test_horner_take_against_polyval_with_rows_by_index():
    rng = np.random.default_rng(3)
    rows = rng.normal(size=(9, 5))  # [power, row]
    idx = rng.integers(0, 5, 200)
    x = rng.uniform(-1, 1, 200)
    ref = np.array([np.polynomial.polynomial.polyval(xi, rows[:, r]) for xi, r in zip(x, idx)])
    np.testing.assert_allclose(chebyshev.horner_take(rows, idx, x), ref, rtol=1e-13, atol=1e-14)


def test_horner_take_pair_against_polyval_with_rows_by_index():
    """Both polynomials of the complex rows (real part, imaginary part) against polyval."""
    rng = np.random.default_rng(4)
    re, im = rng.normal(size=(2, 11, 7))  # [power, row] each
    idx = rng.integers(0, 7, 300)
    x = rng.uniform(-1, 1, 300)
    p, q = chebyshev.horner_take_pair(re + 1j * im, idx, x)
    for got, c in ((p, re), (q, im)):
        ref = np.array([np.polynomial.polynomial.polyval(xi, c[:, r]) for xi, r in zip(x, idx)])
        np.testing.assert_allclose(got, ref, rtol=1e-13, atol=1e-14)


def test_half_wave_sin_against_mpmath():
    """The vectorized half wave against mpmath's sine (3 ulp) on [0, pi], exactly 0 past pi, the
    low part of pi derived here, and negative or NaN phases refused."""
    import mpmath

    with mpmath.workdps(40):
        assert elementary._PI_LO == float(mpmath.pi - mpmath.mpf(math.pi))
        x = np.concatenate([np.random.default_rng(7).uniform(0.0, np.pi, 2000),
                            [0.0, 5e-324, 1e-8, np.pi / 2, np.nextafter(np.pi, 0), np.pi]])
        ref = np.array([float(mpmath.sin(mpmath.mpf(float(v)))) for v in x])
    got = elementary.half_wave_sin(x)
    assert np.all(np.abs(got - ref) <= 3 * np.spacing(ref))
    np.testing.assert_array_equal(elementary.half_wave_sin(np.array([np.nextafter(np.pi, 4), 4.0, 50.0])),
                                  0.0)
    for bad in (-1e-300, np.nan):
        with pytest.raises(ValueError, match="half_wave_sin"):
            elementary.half_wave_sin(np.array([1.0, bad]))
