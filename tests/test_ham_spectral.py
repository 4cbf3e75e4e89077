"""The per-lambda Chebyshev series of ham1 (zener_sym.ham.spectral) against the quadrature
kernels (Gauss-Jacobi square-root integrals, scan-and-bisect roots), the mpmath kernels (2F1 closed
forms), and its own fallback."""
import mpmath
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.ham import spectral as hs
from zener_sym.ham.runtime_mpmath import ham1 as m1
from zener_sym.ham.runtime_numpy import ham1 as h1
from zener_sym.models import FieldUnavailableError

# spans both ways the contact ends: after pi/omega0 (most lambda) and before it (lambda >~ 2.3)
LAMS = np.array([0.0, 1e-3, 0.3, 1.01, 1.7, 2.2, 2.35, 2.4, 2.41])


@pytest.fixture(scope="module")
def series():
    return hs.Ham1Series(LAMS)


def test_every_row_passes_its_check_up_to_2_41(series):
    assert series.ok.all()
    tpi = series.tpi
    assert (series.tau_d > tpi).any() and (series.tau_d < tpi).any()  # both branches exercised


def test_contact_end_matches_the_quadrature_kernel(series):
    ref = h1.contact_end(LAMS)
    np.testing.assert_allclose(series.tau_d, ref, rtol=2e-14, atol=0)


def test_delta_matches_the_quadrature_kernel(series):
    rng = np.random.default_rng(7)
    td = h1.contact_end(LAMS)
    tau = np.sort(rng.uniform(0.0, 1.2, (LAMS.size, 300)), axis=1) * td[:, None]
    rows = np.broadcast_to(np.arange(LAMS.size)[:, None], tau.shape)
    got = series.delta(rows, tau)
    ref = np.where(tau < td[:, None], np.maximum(h1.delta(tau, LAMS[:, None]), 0.0), 0.0)
    scale = np.max(ref, axis=1, keepdims=True)
    assert np.max(np.abs(got - ref) / scale) < 5e-14


def test_delta_matches_the_mpmath_closed_forms(series):
    """An independent route: delta0 + delta1 with K from 2F1 at 30 digits."""
    for i in (2, 4, 7):
        lam = float(LAMS[i])
        for frac in (0.05, 0.4, 0.9, 0.99):
            tau = frac * float(series.tau_d[i])
            with mpmath.workdps(30):
                ref = float(m1.delta(tau, lam))
            got = float(series.delta(np.array([i]), np.array([tau]))[0])
            assert abs(got - ref) < 5e-14 * float(h1.summary(lam)["delta_m"][0]), (lam, frac)


def test_impulse_matches_the_quadrature_kernel(series):
    td = series.tau_d
    tau = np.linspace(0.0, 1.3, 40)[None, :] * td[:, None]
    rows = np.broadcast_to(np.arange(LAMS.size)[:, None], tau.shape)
    got = series.impulse(rows, tau)
    ref = h1.impulse(tau, LAMS[:, None], tau_d=np.broadcast_to(td[:, None], tau.shape))
    np.testing.assert_allclose(got, ref, rtol=0, atol=2e-14)


def test_a_row_does_not_depend_on_its_neighbours(series):
    """Batched matmuls, not one blocked BLAS product: the same digits alone or in a batch."""
    alone = hs.Ham1Series(LAMS[3:4])
    assert alone.tau_d[0] == series.tau_d[3]
    tau = np.linspace(0.0, 1.1 * alone.tau_d[0], 57)
    np.testing.assert_array_equal(alone.delta(np.zeros(57, int), tau),
                                  series.delta(np.full(57, 3), tau))


def test_rows_of_handles_columns_and_scattered_lambda():
    lam = np.array([[2.0], [0.5], [2.0]]) * np.ones((1, 4))
    u, rows = hs.rows_of(lam)
    np.testing.assert_array_equal(u, [0.5, 2.0])
    np.testing.assert_array_equal(u[rows], lam)
    scattered = np.array([1.0, 0.2, 1.0, 0.7])
    u, rows = hs.rows_of(scattered)
    np.testing.assert_array_equal(u[rows], scattered)


def test_history_is_the_same_for_a_grid_and_for_scattered_points():
    lam = np.array([0.4, 1.9, 2.38])
    tau = np.linspace(0.0, 9.0, 31)
    grid = zs.history(lam[:, None], tau[None, :], model="ham1")
    flat_lam = np.repeat(lam, tau.size)[::-1].copy()
    flat_tau = np.tile(tau, lam.size)[::-1].copy()
    flat = zs.history(flat_lam, flat_tau, model="ham1")
    for f in ("delta", "force", "impulse"):
        np.testing.assert_array_equal(getattr(flat, f)[::-1].reshape(grid.delta.shape),
                                      getattr(grid, f), err_msg=f)


def test_near_the_critical_lambda_the_series_step_aside():
    s = hs.Ham1Series(np.array([1.0, 2.42, 2.44, 2.4424]))
    assert s.ok.tolist() == [True, False, False, False]
    assert np.isnan(s.tau_d[1:]).all()


def test_history_falls_back_to_quadrature_where_the_series_fail(monkeypatch):
    """Rows that fail their check go through the quadrature kernels: force a failure everywhere
    (an impossible tolerance) and compare with a history computed from the kernels directly."""
    lam = np.array([0.6, 2.1])[:, None]
    tau = np.linspace(0.0, 8.0, 25)[None, :]
    fast = zs.history(lam, tau, model="ham1")
    monkeypatch.setattr(hs, "TAIL_TOL", 0.0)
    assert not hs.Ham1Series(lam.ravel()).ok.any()
    slow = zs.history(lam, tau, model="ham1")
    td = h1.contact_end(lam.ravel())[:, None]
    ref = np.where(tau < td, np.maximum(h1.delta(tau, lam), 0.0), 0.0)
    np.testing.assert_array_equal(slow.delta, ref)
    for f in ("delta", "force", "impulse", "velocity"):
        np.testing.assert_allclose(getattr(slow, f), getattr(fast, f), rtol=0, atol=5e-14)


def test_history_near_the_critical_lambda_matches_the_kernels():
    lam = np.array([1.0, 2.441])[:, None]
    tau = np.linspace(0.0, 40.0, 30)[None, :]
    h = zs.history(lam, tau, model="ham1")
    td = h1.contact_end(lam.ravel())[:, None]
    ref = np.where(tau < td, np.maximum(h1.delta(tau, lam), 0.0), 0.0)
    np.testing.assert_allclose(h.delta, ref, rtol=0, atol=5e-14)


# ----------------------------------------------------------------------------- fields=
def test_force_only_history_equals_the_full_one():
    lam = np.linspace(0.0, 2.4, 7)[:, None]
    tau = np.linspace(0.0, 6.0, 50)[None, :]
    full = zs.history(lam, tau, model="ham1")
    part = zs.history(lam, tau, model="ham1", fields="force")
    np.testing.assert_array_equal(part.force, full.force)
    assert part.fields == ("tau", "force")
    with pytest.raises(AttributeError, match=r"'impulse' was not computed.*fields=\('force',\)"):
        part.impulse


def test_fields_on_models_that_compute_everything():
    h = zs.history(0.5, [0.1, 1.0], model="hunter", fields=["impulse", "delta"])
    assert h.fields == ("tau", "delta", "impulse")  # table order
    np.testing.assert_array_equal(h.impulse, zs.history(0.5, [0.1, 1.0], model="hunter").impulse)


@pytest.mark.parametrize("bad, match", [("speed", "unknown history field 'speed'"),
                                        ((), "fields is empty"),
                                        (3, "fields must be a field name")])
def test_bad_fields_are_clear_errors(bad, match):
    with pytest.raises(ValueError, match=match):
        zs.history(1.0, [0.5], model="ham1", fields=bad)


def test_a_field_the_model_does_not_give():
    no_history = [m for m in zs.MODELS if "force" not in zs.models.get_model(m).history_fields]
    if not no_history:
        pytest.skip("every registered model gives a force history")
    with pytest.raises(FieldUnavailableError):
        zs.history(0.1, [0.5], model=no_history[0], fields="force")


# ---------------------------------------------------------------------------- summary
def test_summary_matches_the_quadrature_kernels(series):
    got = series.summary()
    ref = h1.summary(LAMS)
    for f in ("tau_dc", "delta_m", "tau_d", "F_m", "impulse", "int_F2"):
        np.testing.assert_allclose(got[f], ref[f], rtol=2e-13, err_msg=f)
    # e = -delta'(tau_d) is small at large lambda: compare against the scale of delta'
    np.testing.assert_allclose(got["e"], ref["e"], rtol=0, atol=2e-14)


def test_summary_through_the_api_matches_the_kernels_up_to_the_critical_lambda():
    """The api's summary (the ham1 tables, built from this module's series and, from 2.414 on,
    the kernels) against the quadrature kernels, also where the series fall back."""
    lam = np.array([0.5, 2.3, 2.43, 2.442])
    s = zs.summary(lam, model="ham1")
    ref = h1.summary(lam)
    for f in ("tau_dc", "delta_m", "tau_d", "e", "impulse", "int_F2"):
        np.testing.assert_allclose(getattr(s, f), ref[f], rtol=2e-13, atol=1e-15, err_msg=f)
    assert zs.summary(2.3, model="ham1").tau_d == s.tau_d[1]


def test_series_serve_every_lambda_up_to_2_413():
    """The fallback is for the last 1% below lam_crit only, and the fixed span past pi/omega0
    holds every first-order contact end."""
    lam = np.linspace(0.0, 2.413, 400)
    s = hs.Ham1Series(lam)
    assert s.ok.all()
    assert np.max(s.tau_d / s.tpi) < 1.0 + hs.SPAN_PAST
