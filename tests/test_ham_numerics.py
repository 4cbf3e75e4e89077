"""The cumulative contact integral (one Chebyshev antiderivative per lambda) against the per-point
smoothstep Gauss-Legendre rule and against closed-form integrals."""
import numpy as np
import pytest

from zener_sym import ham_numerics as hn
from zener_sym.generated import ham1_numpy as k


def test_matches_per_point_quadrature_of_the_first_order_force():
    lam = np.linspace(0.0, 2.4, 13)[:, None] * np.ones((1, 60))
    tau = np.linspace(0.0, 6.0, 60)[None, :] * np.ones((13, 1))
    _, _, omega0 = k.params(lam)
    tpi = np.pi / omega0
    td = k.contact_end(lam[:, 0])[:, None] * np.ones((1, 60))
    end = np.minimum(tau, td)
    per_point = (hn.contact_integral(k.force, np.zeros_like(end), np.minimum(end, tpi), lam)
                 + hn.contact_integral(k.force, tpi, np.maximum(end, tpi), lam))
    cumulative = (hn.cumulative_integral(k.force, 0.0, np.minimum(td, tpi), lam, np.minimum(end, tpi))
                  + hn.cumulative_integral(k.force, tpi, np.maximum(td, tpi), lam, np.maximum(end, tpi)))
    np.testing.assert_allclose(cumulative, per_point, rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("p", [1.5, 3.0])
def test_closed_form_endpoint_singularities(p):
    # integral_0^x t^p (1 - t)^p dt has the endpoint behaviour of the force; compare with the
    # regularised incomplete beta function
    from scipy.special import beta, betainc

    x = np.linspace(0.0, 1.0, 41)
    got = hn.cumulative_integral(lambda t, lam: t**p * (1 - t) ** p, 0.0, 1.0, np.zeros_like(x), x)
    want = beta(p + 1, p + 1) * betainc(p + 1, p + 1, x)
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-16)
    assert abs(got[0]) < 1e-17


def test_empty_segment_is_zero():
    assert hn.cumulative_integral(lambda t, lam: 1.0 + 0 * t, 2.0, 2.0, 0.5, 2.0) == 0.0
