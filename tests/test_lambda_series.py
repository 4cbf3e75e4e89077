"""Both ends of lambda: the derived series and asymptotics against the package's own solvers, and
the ``series`` model."""
import json
from importlib import resources

import mpmath
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.derivation import lambda_series as ls
from zener_sym.exact import force_end as fe
from zener_sym.models import series as series_model

DATA = json.loads((resources.files("zener_sym") / "data" / "lambda_series.json").read_text("utf-8"))


def _c(name):
    return [mpmath.mpf(x) for x in DATA["small"][name]["c"]]


def _fit(xs, ys, degrees):
    """Coefficients of sum_k a_k x^k (k in degrees) through the points (a square solve)."""
    A = mpmath.matrix([[x**k for k in degrees] for x in xs])
    return mpmath.lu_solve(A, mpmath.matrix(ys))


def test_first_coefficients_against_finite_differences_of_exact_mp():
    # An independent integrator (zener_sym.exact.mp, Taylor in tau and u, float lambda) at
    # lambda = j 2^-16: a 6-point fit of (e - 1) gives c1, c2 to > 20 digits, c3 to ~17.
    h = 2.0**-16
    with mpmath.workdps(45):
        sols = [fe.solve_mp(j * h, dps=35) for j in range(1, 7)]
        plate = _fit([j * h for j in range(1, 7)], [s._base.e - 1 for s in sols], range(1, 7))
        c = _c("e_delta")
        c1 = mpmath.mpf(str(ls.raman_c1().evalf(40)))
        assert abs(plate[0] + c1) < 1e-20 * c1  # e = 1 - c1 lambda: the closed form
        assert abs(plate[0] - c[1]) < 1e-20 * abs(c[1])
        assert abs(plate[1] - c[2]) < 1e-20 * abs(c[2])
        assert abs(plate[2] - c[3]) < 1e-15 * abs(c[3])


def test_grain_series_against_finite_differences_of_exact_mp():
    # e_force - e_delta = a5 lambda^(5/2) + ... from the force-free cut of the same Taylor steps
    h = 2.0**-20
    with mpmath.workdps(45):
        lams = [j * h for j in range(1, 5)]
        lams = [j * h for j in range(1, 6)]
        sols = [fe.solve_mp(x, dps=40) for x in lams]
        d = [(s.e - s._base.e) / mpmath.mpf(x) ** 2.5 for s, x in zip(sols, lams)]
        # (e_force - e_delta)/lambda^(5/2) = a5 + a7 mu^2 + a9 mu^4 + (a10 - c5) mu^5 + a11 mu^6 + ...
        fit = _fit([mpmath.sqrt(x) for x in lams], d, (0, 2, 4, 5, 6))
        a, c = _c("e_force"), _c("e_delta")
        assert abs(fit[0] - a[5]) < 1e-20 * abs(a[5])
        assert abs(fit[1] - a[7]) < 1e-12 * abs(a[7])
        assert abs(fit[3] - (a[10] - c[5])) < 1e-3 * abs(a[10] - c[5])


@pytest.mark.parametrize("end, lam", [("delta", 0.05), ("delta", 0.2), ("force", 0.01), ("force", 0.05)])
def test_series_sums_against_exact_mp(end, lam):
    with mpmath.workdps(45):
        x = mpmath.mpf(lam) if end == "delta" else mpmath.sqrt(mpmath.mpf(lam))
        s = fe.solve_mp(lam, dps=40)
        ref = {"e": s.e, "tau_d": s.tau_d} if end == "force" else {"e": s._base.e, "tau_d": s._base.tau_d}
        for f in ("e", "tau_d"):
            c = _c(f"{f}_{end}")
            got = mpmath.fsum(ck * x**k for k, ck in enumerate(c))
            # the truncation error is about the first omitted term
            bound = 10 * abs(c[-1]) * x ** len(c) + mpmath.mpf(10) ** -24
            assert abs(got - ref[f]) < bound * abs(ref[f]), (f, got, ref[f])


def test_large_lambda_plate_against_exact():
    L = DATA["large"]
    K, C, corr = float(L["K_delta"]), float(L["C_delta"]), float(L["tau_d_corr"])
    for lam in (5.0, 10.0, 40.0):
        s = zs.summary(lam, model="exact")
        assert abs(s.e * lam**5 / K - 1) < 1e-10  # exponentially small remainder
        r = (s.tau_d - lam * (5 * np.log(lam) + C)) * lam ** (2 / 3)
        assert abs(r - corr) < 1.1 * lam ** (-5 / 3)
        assert abs(s.delta_m * lam ** (2 / 3) - 1) < 0.4 / lam


def test_large_lambda_grains_against_exact():
    for lam in (30.0, 300.0):
        s = zs.summary(lam, model="exact", contact_end="force")
        assert abs(s.e * lam ** (5 / 3) - 2 / 3) < 3 / lam
        assert abs(s.F_m * lam ** (-2 / 3) / (9 / 8 * 4 ** (-1 / 3)) - 1) < 2 / lam


@pytest.mark.parametrize("rtol", series_model.RTOLS)
@pytest.mark.parametrize("end", ["delta", "force"])
def test_series_model_small_side_meets_rtol(rtol, end):
    lo, _ = series_model.CROSSOVERS[rtol][end]
    lam = np.linspace(0.0, lo, 41)
    s = zs.summary(lam, model="series", contact_end=end, rtol=rtol)
    ref = zs.summary(lam, model="exact", contact_end=end, rtol=1e-13)
    assert s.xi[0] == 0.0 and s.e[0] == 1.0  # lambda = 0: elastic (the reference has round-off there)
    for f in ("e", "tau_d", "impulse", "xi"):
        got, want = getattr(s, f)[1:], getattr(ref, f)[1:]
        err = np.abs(got / want - 1)
        assert np.max(err) <= rtol, (f, float(np.max(err)), lam[1 + np.argmax(err)])


@pytest.mark.slow
@pytest.mark.parametrize("rtol", series_model.RTOLS)
def test_series_model_large_side_meets_rtol(rtol):
    _, hi = series_model.CROSSOVERS[rtol]["delta"]
    lam = np.array([hi, 1.3 * hi, 2.0 * hi])
    lam = lam[lam <= 300.0]
    s = zs.summary(lam, model="series", rtol=rtol)
    ref = zs.summary(lam, model="exact")
    for f in ("e", "tau_d", "impulse", "xi"):
        got, want = getattr(s, f), getattr(ref, f)
        assert np.max(np.abs(got / want - 1)) <= rtol, f


def test_series_model_refuses_the_middle_and_bad_options():
    with pytest.raises(ValueError, match=r"lambda = 1\.0 is outside .* allowed \[0, 0\.39\] .* \[40, 1000\]"):
        zs.summary(1.0, model="series")
    with pytest.raises(ValueError, match="no large-lambda form for contact_end='force'"):
        zs.summary(50.0, model="series", contact_end="force")
    with pytest.raises(ValueError, match="allowed: 0.001, 1e-06, 1e-09"):
        zs.summary(0.1, model="series", rtol=1e-4)
    with pytest.raises(ValueError, match="contact_end"):
        zs.summary(0.1, model="series", contact_end="contact")
    with pytest.raises(ValueError, match="does not give"):
        zs.history(0.1, [0.0, 1.0], model="series")
    m = zs.models.get_model("series")
    assert list(m.valid(np.array([0.1, 1.0, 40.0, 1000.0]))) == [True, False, True, True]


def test_series_coefficients_are_read_only():
    """coefficients() hands every caller the same cached arrays: a write raises instead of
    changing every later answer, and replacing an entry of the returned dict changes nothing."""
    lam = np.array([0.1, 0.2])
    before = series_model.SeriesModel()._summary(lam)["e"].copy()
    c = series_model.coefficients()
    with pytest.raises(ValueError, match="read-only"):
        c["small"]["e_delta"][1] = 0.0
    c["small"]["e_delta"] = np.zeros(3)
    again = series_model.coefficients()["small"]["e_delta"]
    assert again[0] == 1.0 and again[1] == float(DATA["small"]["e_delta"]["c"][1])
    assert np.array_equal(series_model.SeriesModel()._summary(lam)["e"], before)


@pytest.mark.slow
def test_derivation_passes_and_committed_coefficients_are_fresh():
    """The committed data/lambda_series.json is what the derivation writes (regenerate:
    python -m zener_sym.derivation.lambda_series --write src/zener_sym/data/lambda_series.json)."""
    ctx = ls.derive()
    assert ctx.log.ok, [s for s in ctx.log.steps if not s.passed]
    fresh = ls.coefficients_json(ctx)
    committed = (resources.files("zener_sym") / "data" / "lambda_series.json").read_text("utf-8")
    if fresh != committed:
        import difflib

        diff = "".join(difflib.unified_diff(committed.splitlines(True), fresh.splitlines(True), "committed", "fresh", n=1))
        pytest.fail("data/lambda_series.json is stale:\n" + diff[:3000])


def test_raman_c1_agrees_with_the_linear_derivation():
    # derivation/linear.py derives the same slope from int F_Hertz^2 on its own route
    import sympy as sp

    from zener_sym.derivation import linear

    assert sp.simplify(sp.gammasimp(linear.RAMAN_C1 - ls.raman_c1())) == 0
