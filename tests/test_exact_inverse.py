"""The tables' derivative d(field)/d(lambda) and the inverse ``lam_from_summary`` against
independent routes.

References: Richardson-extrapolated central differences of mpmath solves (``exact.mp``, 20
digits, so the differences lose nothing a float could see), the small-lambda series of e and
tau_d differentiated term by term (``data/lambda_series.json``, derived independently by the
perturbation hierarchy), and the forward map ``summary`` for the round trip.
"""
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.exact import inverse, mp, table
from zener_sym.models import series

# fields of the mp solution (xi there is 2 lambda int_F2, formed at 20+ digits)
MP_FIELDS = {"e": lambda s: s.e, "tau_d": lambda s: s.tau_d, "tau_dc": lambda s: s.tau_dc,
             "delta_m": lambda s: s.delta_m, "int_F2": lambda s: s.int_F2,
             "xi": lambda s: 1 - s.e**2}


def _richardson(lam, h, fields):
    """d f / d lambda from central differences at steps h and h/2, extrapolated (error O(h^4))."""
    sols = {k: mp.solve(lam + k * h / 2, dps=20) for k in (-2, -1, 1, 2)}
    out = {}
    for f in fields:
        g = MP_FIELDS[f]
        d_h = (g(sols[2]) - g(sols[-2])) / (2 * h)
        d_h2 = (g(sols[1]) - g(sols[-1])) / h
        out[f] = float((4 * d_h2 - d_h) / 3)
    return out


@pytest.mark.parametrize("lam, h, fields", [
    (0.7, 2.0**-9, ("e", "tau_d", "tau_dc", "delta_m", "int_F2", "xi")),  # piece [0, 1]
    (3.0, 2.0**-9, ("e", "tau_d", "tau_dc", "delta_m", "int_F2")),  # piece [2, 3.5]
    (20.0, 2.0**-7, ("e", "tau_d", "tau_dc", "delta_m", "int_F2")),  # ln-lambda piece [10, 25]
])
def test_derivative_against_mpmath_richardson(lam, h, fields):
    ref = _richardson(lam, h, fields)
    for f in fields:
        d = table.summary_derivative(lam, f)
        assert abs(d - ref[f]) <= 5e-11 * abs(ref[f]), (f, d, ref[f])


def test_derivative_against_small_lambda_series():
    C = series.coefficients()["small"]
    ce, ct = C["e_delta"], C["tau_d_delta"]
    lam = np.array([0.0, 0.01, 0.05, 0.1])
    k = np.arange(1, len(ce))
    de = np.array([np.sum(k * ce[1:] * x ** (k - 1)) for x in lam])
    e = np.array([ce[0] + np.sum(ce[1:] * x**k) for x in lam])
    kt = np.arange(1, len(ct))
    dt = np.array([np.sum(kt * ct[1:] * x ** (kt - 1)) for x in lam])
    np.testing.assert_allclose(table.summary_derivative(lam, "e"), de, rtol=1e-12)
    np.testing.assert_allclose(table.summary_derivative(lam, "impulse"), de, rtol=1e-12)
    np.testing.assert_allclose(table.summary_derivative(lam, "xi"), -2 * e * de, rtol=1e-12)
    np.testing.assert_allclose(table.summary_derivative(lam, "tau_d"), dt, rtol=1e-10)


def test_derived_field_derivatives_follow_their_definitions():
    """tau_dr, eta, F_m from the stored fields' derivatives by the product/quotient rules,
    checked against central differences of the table itself (smooth inside a piece)."""
    lam = np.array([0.3, 1.7, 4.2, 60.0])
    h = 1e-5 * lam
    s_p, s_m = table.summary(lam + h), table.summary(lam - h)
    for f in ("tau_dr", "eta", "F_m", "delta_m", "tau_dc", "tau_d"):
        fd = (s_p[f] - s_m[f]) / (2 * h)
        np.testing.assert_allclose(table.summary_derivative(lam, f), fd, rtol=1e-6, err_msg=f)


def test_derivative_bad_input():
    with pytest.raises(ValueError, match="unknown summary field"):
        table.summary_derivative(1.0, "velocity")
    with pytest.raises(ValueError, match="outside"):
        table.summary_derivative(1001.0)
    with pytest.raises(ValueError, match="finite"):
        table.summary_derivative(np.nan)


def test_round_trip_e_within_1e12():
    e_min, e_max = inverse.reachable("e")
    assert e_max == 1.0
    rng = np.random.default_rng(3)
    x = np.concatenate([
        np.exp(rng.uniform(np.log(e_min), 0.0, 20000)),
        1.0 - np.geomspace(1e-16, 0.5, 400),  # e -> 1 (lambda -> 0)
        np.linspace(0.7, 0.72, 2001),  # around xi = 1/2, where the tables change their e form
        [e_min, 1.0],
    ])
    lam = zs.lam_from_summary(e=x)
    assert lam.shape == x.shape and np.all((lam >= 0) & (lam <= 1000))
    e = zs.summary(lam).e
    rel = np.abs(e - x) / x
    assert rel.max() <= 1e-12, (x[rel.argmax()], rel.max())
    assert zs.lam_from_summary(e=1.0) == 0.0
    # the piece edges of the table in lambda map onto themselves
    edges = np.array([1.0, 2.0, 3.5, 5.0, 10.0, 25.0, 80.0, 300.0])
    np.testing.assert_allclose(zs.lam_from_summary(e=zs.summary(edges).e), edges, rtol=1e-9)


def test_round_trip_xi_and_tau_d():
    x = np.concatenate([[0.0], np.geomspace(1e-18, 0.999999, 3000)])
    lam = zs.lam_from_summary(xi=x)
    xi = zs.summary(lam).xi
    assert np.all(np.abs(xi - x) <= 1e-12 * x)
    assert lam[0] == 0.0
    lo, hi = inverse.reachable("tau_d")
    t = np.linspace(lo, hi, 3001)
    lam = zs.lam_from_summary(tau_d=t)
    np.testing.assert_allclose(zs.summary(lam).tau_d, t, rtol=1e-12)


def test_plate_tau_d_monotone_over_the_table():
    # the sign of tau_d' on a fine grid (from the independent forward map) agrees with the
    # branch lam_from_summary inverts: all of [0, 1000], increasing
    lam = np.linspace(0.0, 1000.0, 100001)
    assert np.all(np.diff(table.summary(lam)["tau_d"]) > 0)
    assert inverse.tau_d_branch("delta") == (0.0, 1000.0, 1)


def test_lam_from_summary_shapes_and_scalar():
    assert isinstance(zs.lam_from_summary(e=0.5), float)
    out = zs.lam_from_summary(e=[[0.5, 0.6], [0.7, 0.8]])
    assert out.shape == (2, 2)
    assert np.all(np.diff(out.ravel()) < 0)  # e falls with lambda


@pytest.mark.parametrize("kw, match", [
    ({}, "exactly one"),
    ({"e": 0.5, "xi": 0.3}, "exactly one"),
    ({"e": 0.0}, r"\(0, 1\]"),
    ({"e": 1.5}, r"\(0, 1\]"),
    ({"e": 1e-20}, "reachable"),
    ({"e": np.nan}, "finite"),
    ({"e": "0.5"}, "real number"),
    ({"e": []}, "empty"),
    ({"xi": -0.1}, r"\[0, 1\)"),
    ({"xi": 1.0}, r"\[0, 1\)"),
    ({"tau_d": 1.0}, "reachable range"),
    ({"tau_d": 0.0}, "> 0"),
    ({"e": 0.5, "contact_end": "plate"}, "unknown contact_end"),
])
def test_lam_from_summary_bad_input(kw, match):
    with pytest.raises(ValueError, match=match):
        zs.lam_from_summary(**kw)
