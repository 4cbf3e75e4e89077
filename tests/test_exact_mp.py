"""The mpmath Taylor-series path of the exact model, and the scipy path measured against it.

Expected values come from independent routes: the Hertz closed forms at lambda = 0 (derived here
from the energy integral), the exact identities of Eq. (10), a second precision (dps 45 vs 30),
and, for the scipy path, the mpmath path itself.
"""
from functools import lru_cache

import mpmath
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.exact import solver as exact, mp as exact_mp

SUMMARY = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")
LAMS = (0.0, 0.1, 0.3, 0.6, 1.01, 2.0, 3.5, 5.0, 7.5, 10.0)


@lru_cache(maxsize=None)
def mp_sol(lam, dps=30):
    return exact_mp.solve(lam, dps=dps)


def hertz_closed_forms():
    """lambda = 0: energy v²/2 + (2/5)δ^{5/2} = 1/2 gives δ_m = (5/4)^{2/5} and
    τ(δ) = ∫_0^δ (1 − (4/5)x^{5/2})^{-1/2} dx = δ 2F1(2/5, 1/2; 7/5; (4/5)δ^{5/2}) on loading;
    with x = δ_m t^{2/5}, τ_d = 2 τ(δ_m) = (4/5) δ_m B(2/5, 1/2)."""
    f = mpmath.mpf
    dm = (f(5) / 4) ** (f(2) / 5)
    td = f(4) / 5 * dm * mpmath.beta(f(2) / 5, f(1) / 2)
    return dm, td


def test_lambda0_closed_forms():
    s = mp_sol(0.0)
    with mpmath.workdps(50):
        dm, td = hertz_closed_forms()
        assert abs(s.delta_m / dm - 1) < 1e-25
        assert abs(s.F_m / dm**1.5 - 1) < 1e-25
        assert abs(s.tau_d / td - 1) < 1e-25
        assert abs(s.tau_dc / (td / 2) - 1) < 1e-25
        assert abs(s.e - 1) < 1e-25
        assert abs(s.impulse - 2) < 1e-25


def test_lambda0_implicit_loading_branch():
    s = mp_sol(0.0)
    with mpmath.workdps(50):
        dm, td = hertz_closed_forms()
        # loading branch is τ in [0, τ_d/2]; the points cover the u-phase, the τ-phase and the
        # compression maximum (where δ(τ) is flat, so compare τ(δ), not δ(τ))
        taus = [td / 2 * k / 24 for k in range(1, 24)] + [mpmath.mpf("1e-6"), mpmath.mpf("0.3")]
        h = s.history_mp(taus)
        a, b, c = mpmath.mpf(2) / 5, mpmath.mpf(1) / 2, mpmath.mpf(7) / 5
        for t, d in zip(taus, h["delta"]):
            tau_of_d = d * mpmath.hyp2f1(a, b, c, mpmath.mpf(4) / 5 * d ** mpmath.mpf(2.5))
            # near δ_m, dτ/dδ = 1/v is unbounded: compare the δ error v·(τ(δ) − τ) there
            v = mpmath.sqrt(1 - mpmath.mpf(4) / 5 * d ** mpmath.mpf(2.5))
            assert abs(tau_of_d - t) * min(1, v) < 1e-25 * max(1, t), (t, tau_of_d)
        # near the top, δ(τ) = δ_m − (δ_m^{3/2}/2)(τ − τ_dc)² + ...: a check of δ itself
        eps = mpmath.mpf("1e-4")
        d = s.history_mp([td / 2 - eps])["delta"][0]
        # δ'' = −δ^{3/2}, δ''' = 0 and δ'''' = (3/2)δ_m² at the top (v = 0); next term is O(eps⁶)
        expect = dm - dm**1.5 / 2 * eps**2 + dm**2 / 16 * eps**4
        assert abs(d - expect) < 1e-22


@pytest.mark.parametrize("lam", [0.5, 3.5, 10.0])
def test_self_consistency_dps30_vs_dps45(lam):
    a, b = mp_sol(lam, 30), mp_sol(lam, 45)
    with mpmath.workdps(60):
        for f in SUMMARY:
            x, y = getattr(a, f), getattr(b, f)
            assert abs(x - y) <= 1e-25 * abs(y), (f, x, y)


@pytest.mark.parametrize("lam", [0.0, 0.3, 1.01, 5.0, 10.0])
def test_identities(lam):
    s = mp_sol(lam)
    with mpmath.workdps(50):
        # Ī(τ_d) = 1 + e, with Ī from w and e from v, two separate states
        assert abs(s.impulse - (1 + s.e)) < 1e-25
        # energy: 1 − e² = 2λ ∫F̄² dτ
        assert abs((1 - s.e**2) - 2 * s.lam * s.int_F2) < 1e-25
        assert abs(s.xi - (1 - s.e**2)) < 1e-25


@pytest.mark.parametrize("lam", [0.0, 1.01, 10.0])
def test_history_float_matches_mp(lam):
    s = mp_sol(lam)
    taus = np.concatenate([[0.0, 1e-9, 1e-3], np.linspace(0.01, float(s.tau_d) * 1.2, 60)])
    hf = s.history(taus)
    hm = s.history_mp(list(taus))
    for k in ("delta", "impulse", "velocity", "force"):
        ref = np.array([float(x) for x in hm[k]])
        assert np.max(np.abs(hf[k] - ref)) < 1e-14 * max(1.0, np.max(np.abs(ref))), k
    past = taus > float(s.tau_d)
    assert past.any()
    assert np.all(hf["delta"][past] == 0) and np.all(hf["force"][past] == 0)
    assert np.allclose(hf["impulse"][past], float(s.impulse), rtol=0, atol=1e-15)
    assert np.allclose(hf["velocity"], 1 - hf["impulse"], rtol=0, atol=1e-15)


@pytest.mark.parametrize("lam", LAMS)
def test_scipy_summary_within_1e9_of_mpmath(lam):
    ref = mp_sol(lam)
    got = exact.solve(lam)
    for f in SUMMARY:
        r = float(getattr(ref, f))
        g = float(getattr(got, f))
        if abs(r) < 1e-12:  # xi at lambda = 0 (and eta ~ 0 there): absolute, since it is ~0
            assert abs(g - r) < 1e-9, (f, g, r)
        else:
            assert abs(g / r - 1) < 1e-9, (f, g, r)


@pytest.mark.parametrize("lam", [0.0, 1.01, 10.0])
def test_scipy_history_within_1e9_of_mpmath(lam):
    ref = mp_sol(lam)
    taus = np.linspace(0.0, float(ref.tau_d) * 1.05, 50)
    hm = ref.history_mp(list(taus))
    hs = exact.solve(lam).history(taus)
    for k in ("delta", "impulse", "velocity", "force"):
        r = np.array([float(x) for x in hm[k]])
        assert np.max(np.abs(hs[k] - r)) < 1e-9 * np.max(np.abs(r)), k


def test_api_backend_mpmath():
    s = zs.summary([0.0, 2.0], model="exact", backend="mpmath", dps=30)
    for i, lam in enumerate((0.0, 2.0)):
        assert s.tau_d[i] == float(mp_sol(lam).tau_d)
        assert s.e[i] == float(mp_sol(lam).e)
    h = zs.history(2.0, [0.5, 1.0, 100.0], model="exact", backend="mpmath")
    assert h.delta[-1] == 0 and h.impulse[-1] == pytest.approx(1 + float(mp_sol(2.0).e))


@pytest.mark.parametrize("dps", [14, 30.0, True, "30", None])
def test_bad_dps(dps):
    with pytest.raises(ValueError, match="dps"):
        exact_mp.solve(1.0, dps=dps)


@pytest.mark.parametrize("lam", [-1.0, float("nan"), float("inf"), [1.0, 2.0], 1001.0, "1"])
def test_bad_lambda(lam):
    with pytest.raises(ValueError, match="lambda"):
        exact_mp.solve(lam)


def test_bad_history_tau():
    with pytest.raises(ValueError, match="tau"):
        mp_sol(0.0).history([-1.0])
    with pytest.raises(ValueError, match="tau"):
        mp_sol(0.0).history_mp([-1.0])
