"""Every model honours the Summary and History definitions (issue 14, item 6).

F_m is the maximum of the force history the model gives; delta and the force are exactly 0 at
and after the model's own tau_d, where the impulse keeps its summary value; the impulse histories
of ham0, hunter and reed are checked against mpmath quadrature of the model's own force (an
independent route: the models use closed forms or Chebyshev series); ``fields=`` is honoured.
"""
import mpmath
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.models import REGISTRY, formulas as fm

HISTORY_MODELS = ("exact", "hertz", "ham0", "ham1", "hunter", "reed")
LAMS = (0.0, 0.3, 1.7, 2.4)


@pytest.mark.parametrize("model", HISTORY_MODELS)
@pytest.mark.parametrize("lam", LAMS)
def test_F_m_is_the_maximum_of_the_force_history(model, lam):
    s = zs.summary(lam, model=model)
    tau = np.linspace(0.0, s.tau_d, 4001)
    # the maximum sits at tau_dc for every model: refine around it
    tau = np.concatenate([tau, s.tau_dc + np.linspace(-1e-3, 1e-3, 2001)])
    f = zs.history(lam, tau, model=model).force
    assert f.max() <= s.F_m * (1 + 1e-12)
    assert f.max() >= s.F_m * (1 - 1e-9), (model, lam, f.max(), s.F_m)


@pytest.mark.parametrize("model", HISTORY_MODELS)
@pytest.mark.parametrize("lam", LAMS)
def test_contact_over_at_and_after_tau_d(model, lam):
    s = zs.summary(lam, model=model)
    tau = s.tau_d * np.array([1.0, 1.0 + 1e-12, 1.001, 1.5, 10.0])
    h = zs.history(lam, tau, model=model)
    assert np.all(h.delta == 0.0), (model, lam, h.delta)
    assert np.all(h.force == 0.0), (model, lam, h.force)
    np.testing.assert_allclose(h.impulse, s.impulse, rtol=2e-12)
    np.testing.assert_allclose(h.velocity, 1.0 - s.impulse, rtol=0, atol=2e-12)


def _mp_impulse(force, t_end, pts):
    """int_0^t force for t in pts, by mpmath tanh-sinh quadrature (30 digits)."""
    with mpmath.workdps(30):
        return np.array([float(mpmath.quad(force, [0, min(t, t_end)])) for t in pts])


@pytest.mark.parametrize("lam", [0.0, 0.9, 2.0, 2.4])
def test_ham0_impulse_against_quadrature_of_its_force(lam):
    with mpmath.workdps(30):
        lam_mp = mpmath.mpf(lam)
        k = (lam_mp + mpmath.mpf(5) / 4 ** (-mpmath.mpf(3) / 5) * 0 + (mpmath.mpf(5) / 4) ** (
            -mpmath.mpf(3) / 5)) ** (-mpmath.mpf(1) / 3)
        beta = k * lam_mp / 2
        w0 = mpmath.sqrt(k - beta**2)  # Eq. (33), written from (25) and (32)

        def F(t):
            return (mpmath.exp(-beta * t) * mpmath.sin(w0 * t) / w0) ** 1.5

        td = mpmath.pi / w0
    s = zs.summary(lam, model="ham0")
    pts = float(td) * np.array([0.05, 0.3, 0.5, 0.77, 0.999, 1.2])
    ref = _mp_impulse(F, td, pts)
    h = zs.history(lam, pts, model="ham0")
    np.testing.assert_allclose(h.impulse, ref, rtol=2e-12, atol=1e-14)
    assert s.impulse == pytest.approx(float(ref[-1]), rel=2e-12)


@pytest.mark.parametrize("model", ["hunter", "reed"])
def test_pulse_impulse_against_quadrature_of_its_force(model):
    Om = fm.OMEGA_HUNTER
    td = mpmath.pi / Om
    if model == "hunter":
        def F(t):
            return fm.A_HUNTER * mpmath.sin(Om * t)
    else:
        def F(t):
            return fm.A_REED * mpmath.sin(Om * t) ** 1.5
    pts = float(td) * np.array([0.01, 0.25, 0.5, 0.5001, 0.9, 0.99999, 1.0, 2.0])
    ref = _mp_impulse(F, td, pts)
    h = zs.history(0.4, pts, model=model)
    np.testing.assert_allclose(h.impulse, ref, rtol=1e-13, atol=1e-15)
    # and the force itself is Eq. (52) / (53)
    np.testing.assert_allclose(h.force[:-2], [float(F(t)) for t in pts[:-2]], rtol=1e-13)


def test_reed_closed_form_integral():
    from zener_sym.numerics.sqrt_integrals import impulse_s

    x = np.array([0.0, 0.3, np.pi / 2, np.pi / 2 + 1e-4, 2.0, np.pi])
    with mpmath.workdps(30):
        ref = [float(mpmath.quad(lambda t: mpmath.sin(t) ** 1.5, [0, v])) for v in x]
    np.testing.assert_allclose(fm.int_sin32(x), ref, rtol=1e-14, atol=1e-16)
    # the series reed's history evaluates, against the closed form on a fine grid
    xs = np.linspace(0.0, np.pi, 2001)
    np.testing.assert_allclose(impulse_s(np.zeros_like(xs), xs), fm.int_sin32(xs), rtol=0,
                               atol=5e-14)


@pytest.mark.parametrize("model", ["ham0", "hunter", "reed"])
def test_fields_are_honoured(model):
    m = REGISTRY[model]
    lam = np.full((3, 4), 0.5)
    tau = np.linspace(0.0, 3.0, 12).reshape(3, 4)
    out = m.history_values(lam, tau, ("force",))
    assert set(out) == {"force"}
    raw = m._history(lam, tau, fields=("force",))
    assert not set(raw) & {"impulse", "velocity"}  # no impulse work for a force
    full = zs.history(lam, tau, model=model)
    np.testing.assert_array_equal(out["force"], full.force)


def test_ham0_series_impulse_matches_the_generated_kernel():
    from zener_sym.ham.runtime_numpy import ham0 as h0

    lam = np.linspace(0.0, 2.43, 40)[:, None]
    tau = np.linspace(0.0, 1.0, 50)[None, :] * h0.summary(lam)["tau_d"] * 1.1
    h = zs.history(lam, tau, model="ham0")
    ref = h0.impulse(np.broadcast_to(tau, h.impulse.shape), np.broadcast_to(lam, h.impulse.shape))
    np.testing.assert_allclose(h.impulse, ref, rtol=2e-12, atol=1e-14)


def test_line_blocks_cover_the_grid_once():
    from zener_sym.numerics.blocks import line_blocks

    for n_lines, n_col, size in ((7, 3, 8), (3, 20, 8), (1, 1, 8), (5, 8, 8)):
        hits = np.zeros((n_lines, n_col), dtype=int)
        for r0, r1, c0, c1 in line_blocks(n_lines, n_col, size):
            assert (r1 - r0) * (c1 - c0) <= size
            hits[r0:r1, c0:c1] += 1
        assert np.all(hits == 1)


@pytest.mark.parametrize("shape", [(1, 20000), (20000,), (3, 7)])
def test_ham0_history_by_blocks_matches_the_generated_kernels(shape):
    """ham0's block-by-block history (lines longer than a block, one lambda per point, a small
    grid) against the generated delta0 and impulse (quadrature) at every point."""
    from zener_sym.ham.runtime_numpy import ham0 as h0

    rng = np.random.default_rng(6)
    if len(shape) == 2 and shape[0] == 1:
        lam = np.full(shape, 1.3)
    else:
        lam = rng.uniform(0.0, 2.4, shape)
    tau = rng.uniform(0.0, 1.1, shape) * h0.summary(lam)["tau_d"]
    h = zs.history(lam, tau, model="ham0")
    on = tau < h0.summary(lam)["tau_d"]
    np.testing.assert_allclose(h.delta, np.where(on, np.maximum(h0.delta0(tau, lam), 0.0), 0.0),
                               rtol=1e-14, atol=1e-300)
    pick = (slice(None, None, 97),) * len(shape)  # the quadrature costs 64 nodes a point
    np.testing.assert_allclose(h.impulse[pick], h0.impulse(tau[pick], lam[pick]), rtol=2e-12,
                               atol=1e-14)


def test_computed_bounds_against_independent_routes_and_read_only():
    """The bounds known only at run time (``computed_bound``): ham0, ham1 and ham stop at the
    generated lam_crit, which the hand-written root of Eq. (81) (``formulas.LAM_CRIT``, brentq on
    lambda^6 = 64 (lambda + (5/4)^{-3/5})) must equal; oneway stops just above
    1 / (2 int F_Hertz^2), with int F_Hertz^2 in closed form (``linear.RAMAN_C1``, derived in
    ``derivation.linear``) against the exact model's tables (1e-11). Like the properties they
    replace, they cannot be set."""
    from zener_sym.models.linear import RAMAN_C1

    for name in ("ham0", "ham1", "ham"):
        assert REGISTRY[name].lam_bound == pytest.approx(fm.LAM_CRIT, rel=1e-15, abs=0.0)
    assert REGISTRY["oneway"].lam_bound == pytest.approx(1.0 / (2.0 * RAMAN_C1), rel=1e-10)
    for name in ("ham1", "oneway"):
        with pytest.raises(AttributeError, match="computed"):
            REGISTRY[name].lam_bound = 1.0
