"""The exact model's summary and history tables on (5, 1000] (issue 14, item 7) against the
mpmath path.

The large-lambda pieces are built from a universal orbit (``exact.table_build``); the reference
here is the mpmath Taylor integrator of the whole contact at each lambda (its own tau_dc by
Newton on v = delta', its own int F^2 and w states), at lambda values between the table's nodes.
lambda = 1000 (a minute of mpmath) is checked in the slow tests/test_exact_edges.py.
"""
import functools

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.exact import mp as exact_mp
from zener_sym.exact import table as exact_fast
from zener_sym.exact import table_build as build
from zener_sym.numerics import cheb_table_build as engine

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")


def _off_nodes():
    """One point midway (in ln lambda) between two nodes of each of the first large pieces."""
    pts = []
    for a, b in zip(build.LAM_PIECES[:-1], build.LAM_PIECES[1:]):
        if build.SPEC.kind_of(a) == "log" and b <= 80:
            x = np.sort(np.log(engine.piece_nodes("log", a, b, build.N_LAM)))
            k = len(x) // 3
            pts.append(float(np.exp((x[k] + x[k + 1]) / 2)))
    return pts


@functools.cache
def _reference(lam):
    return exact_mp.solve(lam, dps=25)


@pytest.mark.parametrize("lam", [5.0 + 1e-7] + _off_nodes())
def test_large_lambda_summary_against_mpmath(lam):
    r = _reference(lam)
    s = zs.summary(lam, model="exact")  # default backend: the tables
    for f in FIELDS:
        ref = float(getattr(r, f))
        assert abs(getattr(s, f) / ref - 1) <= exact_fast.SUMMARY_RTOL, (f, lam, getattr(s, f), ref)


@pytest.mark.parametrize("lam", [5.0 + 1e-7] + _off_nodes())
def test_large_lambda_history_against_mpmath(lam):
    """Every history field within HISTORY_ATOL of its scale (delta_m, F_m, 1, 1) of the mpmath
    path's own history, on times across the short compression, the long recovery (pieces A, M
    and B of the table) and past the end of contact."""
    r = _reference(lam)
    tau_d, tau_dc = float(r.tau_d), float(r.tau_dc)
    tau = np.concatenate([np.linspace(0.0, 3 * tau_dc, 40), np.geomspace(tau_dc, tau_d, 80),
                          np.linspace(0.0, 1.02 * tau_d, 120)[1:]])
    g = r.history(tau)
    h = zs.history(lam, tau, model="exact")  # default backend: the tables
    scale = {"delta": float(r.delta_m), "force": float(r.F_m), "impulse": 1.0, "velocity": 1.0}
    for f, sc in scale.items():
        err = np.abs(getattr(h, f) - g[f]).max() / sc
        assert err <= exact_fast.HISTORY_ATOL, (f, lam, err)


@pytest.mark.parametrize("lam", [117.0, pytest.param(433.0, marks=pytest.mark.slow)])
def test_large_lambda_history_against_the_integrator(lam):
    """Between the mpmath points, up to the top of the range: the history tables against the
    scipy path (rtol 1e-13; checked against mpmath to about 2e-12 at lambda = 100) at lambda in
    the pieces above 80, off the nodes (the integrator takes about 0.02 lambda seconds)."""
    s = zs.summary(lam, model="exact")
    tau = np.concatenate([np.linspace(0.0, 3 * s.tau_dc, 30),
                          np.linspace(0.0, 1.02 * s.tau_d, 200)[1:]])
    h = zs.history(lam, tau, model="exact")
    g = zs.history(lam, tau, model="exact", backend="scipy", rtol=1e-13)
    scale = {"delta": s.delta_m, "force": s.F_m, "impulse": 1.0, "velocity": 1.0}
    for f, sc in scale.items():
        err = np.abs(getattr(h, f) - getattr(g, f)).max() / sc
        assert err <= exact_fast.HISTORY_ATOL, (f, lam, err)


def test_table_and_integrator_agree_on_a_wide_grid():
    """Between the checked points: the tables against the scipy path (rtol 1e-12) at lambda
    spread over (5, 61] (the integrator costs about 0.02 lambda seconds). lambda = 1000
    is checked against mpmath in tests/test_exact_edges.py (slow)."""
    lams = np.array([5.3, 9.1, 17.0, 33.3, 61.0])
    t = zs.summary(lams, model="exact")
    g = zs.summary(lams, model="exact", backend="scipy", rtol=1e-12)
    for f in FIELDS:
        np.testing.assert_allclose(getattr(t, f), getattr(g, f), rtol=5e-11, err_msg=f)


def test_summary_and_history_every_lambda_from_the_table():
    """No accepted lambda integrates for a summary or a history: the scipy path is never
    called."""
    from zener_sym.models import exact as exact_model

    calls = []
    orig = exact_model.ExactModel._solutions
    exact_model.ExactModel._solutions = lambda *a, **k: calls.append(a) or orig(*a, **k)
    try:
        lams = np.array([0.0, 4.9, 5.0, 5.01, 77.0, 999.9, 1000.0])
        zs.summary(lams, model="exact")
        zs.history(lams[:, None], np.linspace(0.0, 3000.0, 7), model="exact")
    finally:
        exact_model.ExactModel._solutions = orig
    assert calls == []
