"""The fast (table) path of the exact model against independent references.

References: the scipy integrator at rtol 1e-13 at lambda values that are NOT table nodes
(random points, piece edges, midpoints between nodes), Hertz's closed forms at lambda = 0, and the
identity I(tau_d) = 1 + e between the history table (I) and the summary table (e).
"""
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.codegen import inputs_hash
from zener_sym.exact import solver as exact, table as exact_fast
from zener_sym.exact import table_build as build
from zener_sym.exact import table_layout
from zener_sym.generated import exact_table
from zener_sym.numerics.blocks import BLOCK

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2")


def _between_nodes():
    """Midpoints between consecutive lambda nodes of every piece, plus edges and random points."""
    x = np.sort(build.cheb_nodes(build.N_LAM))
    mids = (x[:-1] + x[1:]) / 2
    pts = [0.0, 1e-9, 5.0, 5.0 - 1e-9]
    # the pieces in lambda, which carry the history too; the ln(lambda) pieces above LOG_FROM
    # are checked against mpmath in tests/test_exact_large.py
    for a, b in zip(build.LAM_PIECES[:-1], build.LAM_PIECES[1:]):
        if build.SPEC.kind_of(a) == "log":
            continue
        lam = a + (b - a) * (mids + 1) / 2
        pts += [lam[0], lam[len(lam) // 2], lam[-1], b]
    pts += list(np.random.default_rng(7).uniform(0, 5, 8))
    return np.unique(np.array(pts))


LAMS = _between_nodes()


@pytest.fixture(scope="module")
def refs():
    return [exact.solve(x, rtol=1e-13) for x in LAMS]


def test_summary_within_documented_bound(refs):
    s = zs.summary(LAMS, model="exact")  # default backend: the table
    for f in FIELDS:
        ref = np.array([getattr(r, f) for r in refs])
        rel = np.abs(getattr(s, f) - ref) / np.abs(ref)
        assert rel.max() <= exact_fast.SUMMARY_RTOL, (f, LAMS[rel.argmax()], rel.max())


def test_xi_against_energy_balance_and_restitution(refs):
    s = zs.summary(LAMS, model="exact")
    ref_J = np.array([r.int_F2 for r in refs])
    np.testing.assert_allclose(s.xi, 2 * LAMS * ref_J, rtol=exact_fast.SUMMARY_RTOL, atol=0)
    # 1 - e^2 from the integrator cancels for small lambda; compare where it does not
    big = LAMS > 0.1
    ref = np.array([1 - r.w_end**2 for r in refs])
    np.testing.assert_allclose(s.xi[big], ref[big], rtol=exact_fast.SUMMARY_RTOL)


def test_hertz_limit_closed_forms():
    s = zs.summary(0.0, model="exact")
    assert s.delta_m == pytest.approx(1.25**0.4, rel=1e-12)
    assert s.e == pytest.approx(1.0, rel=1e-12)
    assert s.eta == pytest.approx(1.0, rel=1e-12)
    assert s.xi == 0.0
    # tau_dc = int_0^dm d delta / sqrt(1 - 4/5 delta^{5/2}) = dm B(2/5, 1/2) / (5/2), from the
    # energy integral delta'^2 = 1 - (4/5) delta^{5/2}
    from scipy.special import beta
    assert s.tau_dc == pytest.approx(1.25**0.4 * beta(0.4, 0.5) / 2.5, rel=1e-12)


# 7.3 and 55.0 lie in log pieces of lambda (the maps of the fast evaluation there are checked
# against the integrator, not against a second reading of the same maps)
@pytest.mark.parametrize("lam", [0.0, 0.37, 1.5, 2.71, 4.44, 5.0, 7.3, 55.0])
def test_history_within_documented_bound(lam):
    r = exact.solve(lam, rtol=1e-13)
    tau = np.concatenate([np.linspace(0, r.tau_d * 1.05, 600), [r.tau_dc, 1e-6, r.tau_d * 0.999999]])
    h = zs.history(lam, tau, model="exact")
    g = r.history(tau)
    scale = {"delta": r.delta_m, "force": r.F_m, "impulse": 1.0, "velocity": 1.0}
    for f, sc in scale.items():
        err = np.abs(getattr(h, f) - g[f]).max() / sc
        assert err <= exact_fast.HISTORY_ATOL, (f, lam, err)
    # relative accuracy of delta in the interior of the contact
    inner = (tau > 0.01 * r.tau_d) & (tau < 0.99 * r.tau_d)
    rel = np.abs(h.delta[inner] / g["delta"][inner] - 1).max()
    assert rel <= 1e3 * exact_fast.HISTORY_ATOL


def test_history_identities():
    """The history table's impulse at tau_d against the summary table's e: two tables built
    separately, one identity (momentum: I(tau_d) = 1 + e)."""
    lam = np.array([[0.2], [1.3], [3.3], [4.9]])
    s = zs.summary(lam[:, 0], model="exact")
    # just before tau_d (from tau_d on, the history's impulse IS 1 + e by construction), where
    # I = 1 + e - O((1e-7 tau_d)^(5/2)) since F ~ (tau_d - tau)^(3/2)
    tau = np.stack([np.array([0.0, 0.5 * t, t * (1 - 1e-7), 2 * t]) for t in s.tau_d])
    h = zs.history(lam, tau, model="exact")
    np.testing.assert_allclose(h.impulse[:, 2], 1 + s.e, rtol=0, atol=1e-11)
    np.testing.assert_array_equal(h.delta[:, 3], 0.0)  # after the contact
    np.testing.assert_array_equal(h.delta[:, 0], 0.0)


def test_vectorised_equals_elementwise():
    lam = np.random.default_rng(3).uniform(0, 5, 50)
    s = zs.summary(lam, model="exact")
    for i in (0, 17, 49):
        one = zs.summary(lam[i], model="exact")
        # same numbers up to summation order (numpy may reorder sums for longer arrays)
        assert one.tau_d == pytest.approx(s.tau_d[i], rel=1e-14)
        assert one.e == pytest.approx(s.e[i], rel=1e-14)


def test_tables_cover_the_whole_range_never_extrapolate():
    """Summaries and histories come from the tables on [0, 1000] (all the model accepts); the
    table functions refuse anything outside it instead of extrapolating."""
    assert exact_fast.LAM_MAX == exact_fast.HISTORY_LAM_MAX == 1000.0
    h = zs.history(7.5, [0.5, 3.0], model="exact", backend="table")
    hi = zs.history(7.5, [0.5, 3.0], model="exact", backend="scipy")
    np.testing.assert_allclose(h.delta, hi.delta, rtol=1e-10)
    with pytest.raises(ValueError, match="outside the exact table's range"):
        exact_fast.summary(np.array([1000.5]))
    with pytest.raises(ValueError, match="outside the exact history table's range"):
        exact_fast.history(np.array([1000.5]), np.array([1.0]))


def test_integrator_options_force_integration():
    a = zs.summary(2.0, model="exact", rtol=1e-10)
    b = zs.summary(2.0, model="exact", backend="scipy", rtol=1e-10)
    assert a.e == b.e and a.tau_d == b.tau_d
    with pytest.raises(ValueError, match="does not go with backend='table'"):
        zs.summary(2.0, model="exact", backend="table", rtol=1e-10)
    with pytest.raises(ValueError, match="unknown backend"):
        zs.summary(2.0, model="exact", backend="chebyshev")


def test_table_is_fresh_hash():
    """The committed table was built from the current builder and solver sources."""
    assert exact_table.INPUTS_HASH == inputs_hash(build.input_files()), (
        "generated/exact_table.py is stale: run `zener-sym exact-table` and commit it")


def test_compare_detects_a_changed_coefficient():
    stored = {"summary": exact_table.SUMMARY, "history": exact_table.HISTORY}
    fresh = {"summary": {k: [np.asarray(c, float) for c in v] for k, v in stored["summary"].items()},
             "history": {k: [tuple(table_layout.parse_array(c) for c in subs) for subs in v]
                         for k, v in stored["history"].items()}}
    assert build.compare(stored, fresh) == []
    fresh["summary"]["log_e"][2] = fresh["summary"]["log_e"][2].copy()
    fresh["summary"]["log_e"][2][5] += 1e-8
    assert len(build.compare(stored, fresh)) == 1
    # a history coefficient (piece A, lambda piece 6, sub-piece 3) moved by 1e-6
    subs = list(fresh["history"][("A", "f")][6])
    subs[3] = subs[3].copy()
    subs[3][2, 1] += 1e-6
    fresh["history"][("A", "f")][6] = tuple(subs)
    assert len(build.compare(stored, fresh)) == 2


@pytest.mark.slow
def test_table_rebuild_agrees_numerically():
    """`zener-sym regen --check exact-table`: a rebuild agrees with the committed coefficients."""
    from zener_sym.cli import regen

    assert regen.run(["exact-table"], check=True) == 0


@pytest.mark.slow
@pytest.mark.parametrize("lam", [0.0123, 1.7771, 4.6543])
def test_against_mpmath_reference(lam):
    """Every summary field within the documented bound of the mpmath Taylor integrator (dps 20),
    and the history within its bound of the reference's own history."""
    from zener_sym.exact import mp as exact_mp

    r = exact_mp.solve(lam, dps=20)
    s = zs.summary(lam, model="exact", backend="table")
    for f in FIELDS + ("xi",):
        assert float(getattr(s, f)) == pytest.approx(float(getattr(r, f)),
                                                     rel=exact_fast.SUMMARY_RTOL, abs=0), f
    tau = np.linspace(0, 1.02 * float(r.tau_d), 300)
    g = r.history(tau)
    h = zs.history(lam, tau, model="exact", backend="table")
    assert np.abs(h.delta - g["delta"]).max() <= exact_fast.HISTORY_ATOL * float(r.delta_m)
    assert np.abs(h.impulse - g["impulse"]).max() <= exact_fast.HISTORY_ATOL


from hypothesis import given, settings, strategies as st  # noqa: E402


@settings(max_examples=40, deadline=None)
@given(lam=st.floats(0.0, 5.0), frac=st.lists(st.floats(0.0, 1.1), min_size=2, max_size=30))
def test_history_is_physical(lam, frac):
    """delta >= 0, the impulse never decreases (dI/dtau = F >= 0) and ends at 1 + e."""
    s = zs.summary(lam, model="exact")
    tau = np.sort(np.array(frac)) * s.tau_d
    h = zs.history(lam, tau, model="exact")
    assert np.all(h.delta >= 0)
    assert np.all(np.diff(h.impulse) >= -1e-12)
    assert np.all(h.impulse <= 1 + s.e + 1e-12)
    assert np.all(h.delta[tau >= s.tau_d] == 0)


def test_line_and_scattered_evaluation_agree():
    """A broadcast lambda column (one lambda per line, the piece found by broadcasting) and
    the same points scattered in any order give the same numbers."""
    lam = np.array([0.0, 0.3, 4.0, 5.0, 17.0, 999.0])
    s = zs.summary(lam, model="exact")
    tau = s.tau_d[:, None] * np.linspace(0.0, 1.1, 37)[None, :]
    grid = exact_fast.history(np.broadcast_to(lam[:, None], tau.shape), tau)
    perm = np.random.default_rng(5).permutation(tau.size)
    flat = exact_fast.history(np.broadcast_to(lam[:, None], tau.shape).ravel()[perm],
                              tau.ravel()[perm])
    for f in ("delta", "impulse", "force"):
        np.testing.assert_allclose(flat[f], grid[f].ravel()[perm], rtol=1e-14, atol=1e-300)


def test_blocks_do_not_change_the_numbers():
    """A grid of several blocks (``blocks.BLOCK`` points each) gives, point for point, what each
    of its lines gives alone (one block), to the ulp (the lambda contraction's matrix product
    may round differently for another number of lines)."""
    lam = np.array([0.0, 0.3, 4.0, 17.0, 999.0, 2.5])
    n = BLOCK // 2 + 17
    s = zs.summary(lam, model="exact")
    tau = s.tau_d[:, None] * np.linspace(0.0, 1.1, n)[None, :]
    grid = exact_fast.history(np.broadcast_to(lam[:, None], tau.shape), tau)
    for i, x in enumerate(lam):
        one = exact_fast.history(np.full(n, x), tau[i])
        for f in ("delta", "impulse", "force", "velocity"):
            np.testing.assert_allclose(grid[f][i], one[f], rtol=1e-15,
                                       atol=1e-15 * np.abs(one[f]).max())
