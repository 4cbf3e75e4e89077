"""The force-free end's Chebyshev tables against the integrators they replace.

References: ``force_end.solve`` (scipy, rtol 1e-13) at lambda values that are NOT table nodes
(midpoints between nodes in each piece's variable, piece edges, random points, and lambda down to
1e-12), ``force_end.solve_mp`` (mpmath, the plate's Taylor solution cut at the force-free root)
at a few of them, the small-lambda series of e (``data/lambda_series.json``), Hertz at lambda = 0,
and the identities impulse = 1 + e (summary) and impulse = 1 - velocity, force = sqrt(delta)
(delta + 3/2 lambda delta') (history).
"""
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.exact import force_end, force_table, force_table_build as build, inverse, table
from zener_sym.generated import exact_force_table
from zener_sym.models import series
from zener_sym.numerics.chebyshev import cheb_nodes

SUMMARY = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")
SCALES = {"delta": "delta_m", "force": "F_m"}


def _between_nodes():
    x = np.sort(cheb_nodes(build.N_LAM))
    mids = (x[:-1] + x[1:]) / 2
    pts = [1e-12, 1e-8, 1e-4, 1000.0]
    for a, b in zip(build.LAM_PIECES[:-1], build.LAM_PIECES[1:]):
        m = mids[[0, len(mids) // 2, -1]]
        if build.SPEC.kind_of(a) == "log":
            pts += list(np.exp(np.log(a) + (np.log(b) - np.log(a)) * (m + 1) / 2))
        else:
            pts += list((np.sqrt(a) + (np.sqrt(b) - np.sqrt(a)) * (m + 1) / 2) ** 2)
        pts.append(b)
    pts += list(np.random.default_rng(11).uniform(0, 1000, 3))
    return np.unique(np.array(pts))


LAMS = _between_nodes()


@pytest.fixture(scope="module")
def refs():
    return [force_end.solve(x) for x in LAMS]


def test_summary_within_documented_bound(refs):
    s = zs.summary(LAMS, model="exact", contact_end="force")  # default backend: the tables
    for f in SUMMARY:
        ref = np.array([float(getattr(r, f)) for r in refs])
        rel = np.abs(getattr(s, f) - ref) / np.abs(ref)
        assert rel.max() <= force_table.SUMMARY_RTOL, (f, LAMS[rel.argmax()], rel.max())


def test_lambda_zero_is_hertz_and_xi_exact():
    s = zs.summary(0.0, contact_end="force")
    plate = zs.summary(0.0)
    assert s.xi == 0.0 and s.e == 1.0
    for f in ("delta_m", "tau_dc", "tau_d", "F_m"):
        assert getattr(s, f) == pytest.approx(getattr(plate, f), rel=1e-12), f
    # xi keeps its relative accuracy as lambda -> 0 (xi ~ a_1 sqrt(lambda)): against the
    # integrator's energy balance, which is independent of 1 - e^2
    lam = np.array([1e-14, 1e-12, 1e-10, 1e-6])
    ref = np.array([force_end.solve(x).xi for x in lam])
    np.testing.assert_allclose(zs.summary(lam, contact_end="force").xi, ref, rtol=1e-11)


def test_summary_identity_and_series():
    lam = np.array([1e-6, 1e-4, 0.003])
    s = force_table.summary(lam)
    np.testing.assert_array_equal(s["impulse"], 1 + s["e"])
    a = series.coefficients()["small"]["e_force"]
    r = np.sqrt(lam)
    e = np.array([a[0] + sum(a[j] * x**j for j in range(1, len(a))) for x in r])
    np.testing.assert_allclose(s["e"], e, rtol=1e-12)
    # the derivative of the series in s = sqrt(lambda): de/dlambda = (de/ds) / (2 s)
    de = np.array([sum(j * a[j] * x ** (j - 1) for j in range(1, len(a))) / (2 * x) for x in r])
    np.testing.assert_allclose(force_table.summary_derivative(lam, "e"), de, rtol=1e-10)
    np.testing.assert_allclose(table.summary_derivative(lam, "e", contact_end="force"),
                               de, rtol=1e-10)


@pytest.mark.parametrize("lam", [0.0, 1e-8, 0.0413, 0.61, 1.37, 3.3, 11.7, 97.0, 1000.0])
def test_history_within_documented_bound(lam):
    r = force_end.solve(lam)
    tau = np.concatenate([np.linspace(0.0, r.tau_d * 1.05, 900),
                          [r.tau_dc, 1e-9, r.tau_d * (1 - 1e-9), r.tau_d, r.tau_d * 2]])
    h = zs.history(lam, tau, model="exact", contact_end="force")
    g = r.history(tau)
    # delta and the force jump to 0 at tau_d (the grains separate with delta > 0): within the
    # tables' tau_d tolerance of it the two sides may disagree by the jump
    far = np.abs(tau - r.tau_d) > force_table.SUMMARY_RTOL * r.tau_d
    for f in ("delta", "velocity", "force", "impulse"):
        scale = getattr(r, SCALES[f]) if f in SCALES else 1.0
        err = np.abs(getattr(h, f) - g[f])[far].max() / scale
        assert err <= force_table.HISTORY_ATOL, (f, lam, err)
    # identities of the grain contact, and the state past the end of contact
    np.testing.assert_array_equal(h.impulse, 1.0 - h.velocity)
    past = tau >= r.tau_d * (1 + 1e-12)
    assert np.all(h.delta[past] == 0) and np.all(h.force[past] == 0)
    np.testing.assert_allclose(h.velocity[past], -r.e, rtol=1e-11)


def test_history_grid_and_column_shapes():
    lam = np.array([[0.2], [3.0], [300.0]])
    tau = np.linspace(0, 3.5, 50)
    h = zs.history(lam, tau, contact_end="force")
    assert h.delta.shape == (3, 50)
    for i, x in enumerate(lam[:, 0]):
        one = zs.history(float(x), tau, contact_end="force")
        np.testing.assert_array_equal(h.force[i], one.force)


def test_integrator_backends_stay_available():
    a = zs.summary(2.5, contact_end="force", backend="scipy")
    b = zs.summary(2.5, contact_end="force")
    assert a.e == pytest.approx(b.e, rel=force_table.SUMMARY_RTOL)
    with pytest.raises(ValueError, match="outside the force-end table"):
        force_table.summary(1001.0)


def test_round_trip_force_end():
    e_min, e_max = inverse.reachable("e", "force")
    assert e_max == 1.0 and 6e-6 < e_min < 7e-6  # e lambda^(5/3) -> 2/3 slowly
    rng = np.random.default_rng(5)
    x = np.concatenate([np.exp(rng.uniform(np.log(e_min), 0.0, 20000)),
                        1.0 - np.geomspace(1e-16, 0.5, 400), [e_min, 1.0]])
    lam = zs.lam_from_summary(e=x, contact_end="force")
    e = zs.summary(lam, contact_end="force").e
    assert np.max(np.abs(e - x) / x) <= 1e-12
    xi = np.concatenate([[0.0], np.geomspace(1e-16, inverse.reachable("xi", "force")[1], 2000)])
    lam = zs.lam_from_summary(xi=xi, contact_end="force")
    assert np.all(np.abs(zs.summary(lam, contact_end="force").xi - xi) <= 1e-12 * xi)
    lo, hi = inverse.reachable("tau_d", "force")
    t = np.linspace(lo, hi, 2001)
    lam = zs.lam_from_summary(tau_d=t, contact_end="force")
    np.testing.assert_allclose(zs.summary(lam, contact_end="force").tau_d, t, rtol=1e-12)


def test_force_tau_d_monotone_branch():
    """tau_d of the force-free end falls with lambda over the whole table (checked on the
    integrator at a few points and on a fine grid of the table), so lam_for inverts all of it."""
    lam = np.linspace(0.0, 1000.0, 100001)
    assert np.all(np.diff(force_table.summary(lam)["tau_d"]) < 0)
    assert inverse.tau_d_branch("force") == (0.0, 1000.0, -1)
    ref = [force_end.solve(x).tau_d for x in (0.0, 0.5, 5.0, 50.0, 500.0)]
    assert np.all(np.diff(ref) < 0)
    with pytest.raises(ValueError, match="reachable range"):
        zs.lam_from_summary(tau_d=3.3, contact_end="force")


def test_force_derivative_bad_input():
    with pytest.raises(ValueError, match="lambda > 0"):
        force_table.summary_derivative(0.0)
    with pytest.raises(ValueError, match="unknown summary field"):
        force_table.summary_derivative(1.0, "velocity")


def test_table_is_fresh_hash_and_small():
    from zener_sym.codegen import generated_dir, inputs_hash

    assert exact_force_table.INPUTS_HASH == inputs_hash(build.input_files()), (
        "generated/exact_force_table.py is stale: run `zener-sym exact-table` and commit it")
    path = generated_dir() / build.BUILDER.file.filename
    assert path.stat().st_size < 1_000_000


@pytest.mark.slow
def test_table_rebuild_agrees_numerically():
    from zener_sym.cli import exact_table as cmd

    assert cmd.run(check=True, contact_end="force") == 0


@pytest.mark.slow
@pytest.mark.parametrize("lam", [0.0413, 2.2, 13.0])
def test_against_mpmath_reference(lam):
    m = force_end.solve_mp(lam, dps=20)
    s = force_table.summary(np.array([lam]))
    for f in SUMMARY:
        ref = float(getattr(m, f)) if f not in ("tau_dr", "eta") else None
        if ref is None:
            continue
        assert abs(s[f][0] - ref) <= force_table.SUMMARY_RTOL * abs(ref), (f, s[f][0], ref)
    tau = np.linspace(0.0, float(m.tau_d) * 0.999999, 300)
    h = force_table.history(np.full(tau.shape, lam), tau)
    g = m.history(tau)
    for f in ("delta", "velocity", "force", "impulse"):
        scale = float(getattr(m, SCALES[f])) if f in SCALES else 1.0
        err = np.max(np.abs(h[f] - np.asarray(g[f], dtype=float))) / scale
        assert err <= force_table.HISTORY_ATOL, (f, err)
