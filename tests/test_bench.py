"""The benchmark harness (speed is never asserted here; see `zener-sym bench`)."""
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.bench import methods, reference, stability, workprecision
from zener_sym.models import REGISTRY


@pytest.mark.parametrize("name", [n for n in REGISTRY if not n.startswith("_")])
def test_every_model_fails_loudly_or_not_at_all(name):
    """Pins the stability map's rule: over lambda in [0, 10] and tau across the contact, a model
    either answers with finite numbers or raises a ValueError that names the bound; it never
    returns NaN and never raises anything else."""
    for lam in np.linspace(0.0, 10.0, 11):
        tau = np.linspace(0.0, 1.2 * zs.summary(lam, model="exact").tau_d, 25)
        for call in (lambda: zs.summary(lam, model=name).as_dict(),
                     lambda: zs.history(lam, tau, model=name).as_dict()):
            try:
                out = call()
            except ValueError as exc:
                assert "lambda" in str(exc) or "does not give" in str(exc)
                continue
            for k, v in out.items():
                assert np.all(np.isfinite(v)), (name, lam, k)


def test_measure_ranks_tolerances():
    small = {k: v for k, v in reference.compute(lambdas=(0.0, 1.01), n_tau=11,
                                                   source="scipy").items()}
    cat = [methods._phases("DOP853", 1e-3), methods._phases("DOP853", 1e-10), methods._naive("DOP853", 1e-8)]
    rows = workprecision.measure(cat, small, quick=True, log=lambda *a: None)
    err = {(r["method"], r["quantity"]): r["max_rel_error"] for r in rows}
    assert all(r["status"] == "ok" for r in rows)
    assert err[("exact DOP853 rtol=1e-10", "tau_d")] < 1e-8
    assert err[("exact DOP853 rtol=1e-10", "force_history")] < 1e-7
    assert err[("exact DOP853 rtol=1e-10", "e")] < err[("exact DOP853 rtol=1e-03", "e")]
    assert all(r["seconds_per_lambda"] > 0 for r in rows)


def test_reference_build_takes_the_mpmath_path():
    """``zener-sym bench --build-reference`` writes what ``compute()`` returns by default: it must
    come from exact.mp (it once looked for the module under an old name and silently wrote a
    scipy reference labelled by nothing but its source field). One lambda at 15 digits, checked
    against the scipy path, an independent integrator."""
    ref = reference.compute(lambdas=(0.5,), n_tau=3, dps=15)
    assert ref["source"] == "zener_sym.exact.mp at dps=15"
    sci = reference.compute(lambdas=(0.5,), n_tau=3, source="scipy")
    assert "scipy" in sci["source"]
    for q in reference.QUANTITIES:
        assert ref["summary"]["0.5"][q] == pytest.approx(sci["summary"]["0.5"][q], rel=1e-10), q
    with pytest.raises(ValueError, match="allowed: 'mpmath', 'scipy'"):
        reference.compute(source="exact_mp")


def test_stability_classes():
    err = np.array([0.0, 0.005, 0.05, 0.5, np.nan])
    assert list(stability.classify(err)) == ["ok", "ok", ">1%", ">10%", "nan"]


def test_cached_reference_matches_a_fresh_mpmath_solve():
    ref = reference.load()
    assert "exact.mp" in ref["source"]
    from zener_sym.exact import mp as exact_mp

    lam = 1.01
    s = exact_mp.solve(lam, dps=30)
    row = ref["summary"][repr(lam)]
    for q in reference.QUANTITIES:
        assert row[q] == pytest.approx(float(getattr(s, q)), rel=1e-14), q
    tau = np.array(ref["tau"][repr(lam)][::20])
    np.testing.assert_allclose(s.history(tau)["force"], ref["force"][repr(lam)][::20], rtol=1e-13,
                               atol=1e-15)


def test_error_map_marks_small_forces_and_lists_quiet_methods(tmp_path):
    """The error map: errors on a log scale, cells where the exact force is below SMALL_FORCE
    F_m marked (the contact's ends, s = 0 and s = 1), methods with nothing to show (error below
    QUIET everywhere) listed instead of drawn."""
    pytest.importorskip("matplotlib")
    cat = [methods._registry_model("exact"), methods._registry_model("hunter")]
    result, lams, s, errors, small = stability.run(cat, quick=True)
    assert small[:, 0].all() and small[:, -1].all()
    assert not small[0, 1:-1].any()  # at lambda = 0 the Hertz pulse is small only at its ends
    assert small[-1, -2]  # at lambda = 10 the long recovery tail carries a small force
    assert stability.quiet_methods(result, errors) == ["exact"]
    assert np.nanmax(errors["hunter"]) > 0.5  # a symmetric pulse is far off at large lambda
    stability.write_csv(result, lams, s, tmp_path / "map.csv", errors, small)
    header = (tmp_path / "map.csv").read_text().splitlines()[0]
    assert header.endswith("force_error,exact_force_small")
    stability.chart(result, lams, s, tmp_path / "map.png", errors, small)
    assert (tmp_path / "map.png").stat().st_size > 1000
