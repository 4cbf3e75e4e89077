"""The exact model's summary table on (5, 1000] (issue 14, item 7) against the mpmath path.

The large-lambda pieces are built from a universal orbit (``exact.table_build``); the reference
here is the mpmath Taylor integrator of the whole contact at each lambda (its own tau_dc by
Newton on v = delta', its own int F^2 and w states), at lambda values between the table's nodes.
"""
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.exact import mp as exact_mp
from zener_sym.exact import table as exact_fast
from zener_sym.exact import table_build as build

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")


def _off_nodes():
    """One point midway (in ln lambda) between two nodes of each of the first large pieces."""
    pts = []
    for a, b in zip(build.LAM_PIECES[:-1], build.LAM_PIECES[1:]):
        if build.is_log_piece(a) and b <= 80:
            x = np.sort(np.log(build.piece_nodes(a, b)))
            k = len(x) // 3
            pts.append(float(np.exp((x[k] + x[k + 1]) / 2)))
    return pts


@pytest.mark.parametrize("lam", [5.0 + 1e-7] + _off_nodes())
def test_large_lambda_summary_against_mpmath(lam):
    r = exact_mp.solve(lam, dps=25)
    s = zs.summary(lam, model="exact")  # default backend: the tables
    for f in FIELDS:
        ref = float(getattr(r, f))
        assert abs(getattr(s, f) / ref - 1) <= exact_fast.SUMMARY_RTOL, (f, lam, getattr(s, f), ref)


def test_table_and_integrator_agree_on_a_wide_grid():
    """Between the checked points: the tables against the scipy path (rtol 1e-12) at lambda
    spread over (5, 61] (the integrator costs about 0.02 lambda seconds). lambda = 1000
    is checked against mpmath in tests/test_exact_edges.py (slow)."""
    lams = np.array([5.3, 9.1, 17.0, 33.3, 61.0])
    t = zs.summary(lams, model="exact")
    g = zs.summary(lams, model="exact", backend="scipy", rtol=1e-12)
    for f in FIELDS:
        np.testing.assert_allclose(getattr(t, f), getattr(g, f), rtol=5e-11, err_msg=f)


def test_summary_every_lambda_from_the_table():
    """No accepted lambda integrates for a summary: the scipy path is never called."""
    from zener_sym.models import exact as exact_model

    calls = []
    orig = exact_model.ExactModel._solutions
    exact_model.ExactModel._solutions = lambda *a, **k: calls.append(a) or orig(*a, **k)
    try:
        zs.summary(np.array([0.0, 4.9, 5.0, 5.01, 77.0, 999.9, 1000.0]), model="exact")
    finally:
        exact_model.ExactModel._solutions = orig
    assert calls == []
