"""The dissipative constant A from measured e: the one-point inverse, the least-squares fit, its
interval, its refusals, and the published ice law carried in the package.

Expected values come from the forward path (``grain_impact`` and ``Scene``, which compute e from
A, never from lambda(e)), from known A used to make synthetic data, and from the coverage of the
reported interval over random draws.
"""
from __future__ import annotations

import math
import runpy
from pathlib import Path

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.scene import calibrate as cal
from zener_sym.scene.grains import grain_contact

ROOT = Path(__file__).resolve().parents[1]
GRAINS = dict(sphere="glass", radius="1 mm", mass=1e-5)
WALL = dict(wall="steel")
A_TRUE = 3e-7
SPEEDS = np.array([0.2, 0.5, 1.0, 2.0, 4.0, 8.0, 12.0, 20.0])


def _lam(A, v0):
    c = grain_contact(**GRAINS, **WALL)
    return zs.lam_from_dissipation(A, c.rho, c.m_eff, v0)


def _e(A, v0, contact_end):
    """e from A by the forward path of the exact model."""
    return np.asarray(zs.summary(_lam(A, v0), model="exact", contact_end=contact_end).e)


# -- the one-point inverse --------------------------------------------------------------------

@pytest.mark.parametrize("contact_end", ["force", "delta"])
def test_dissipation_for_gives_back_the_measured_e(contact_end):
    for e, v0 in ((0.9, 0.3), (0.5, 2.0), (0.2, 5.0)):
        A = zs.dissipation_for(**GRAINS, v0=v0, e=e, **WALL, contact_end=contact_end)
        r = zs.grain_impact(**GRAINS, A=A, v0=v0, **WALL, contact_end=contact_end)
        assert r.e == pytest.approx(e, rel=1e-11)


def test_dissipation_for_two_spheres_and_arrays():
    e = np.array([0.95, 0.8, 0.6])
    v0 = np.array([0.1, 1.0, 3.0])
    A = zs.dissipation_for("steel", "2 mm", 3e-5, v0=v0, e=e, sphere2="glass", radius2="1 mm",
                           mass2=1e-5)
    assert A.shape == (3,)
    for a, x, v in zip(A, e, v0):
        r = zs.grain_impact("steel", "2 mm", 3e-5, A=a, v0=v, sphere2="glass", radius2="1 mm",
                            mass2=1e-5)
        assert r.e == pytest.approx(x, rel=1e-11)
    assert zs.dissipation_for(**GRAINS, v0=1.0, e=1.0) == 0.0


@pytest.mark.parametrize("e,v0,message", [
    (0.0, 1.0, "must lie in (0, 1]"),
    (1.2, 1.0, "must lie in (0, 1]"),
    (float("nan"), 1.0, "must lie in (0, 1]"),
    ("0.5", 1.0, "must be a number"),
    (0.5, -1.0, "v0 (impact speed) must be finite and > 0"),
])
def test_dissipation_for_refuses(e, v0, message):
    with pytest.raises(ValueError) as info:
        zs.dissipation_for(**GRAINS, v0=v0, e=e)
    assert message in str(info.value)


@pytest.mark.parametrize("contact_end", ["force", "delta"])
def test_dissipation_for_refuses_an_e_no_lambda_reaches(contact_end):
    floor = float(zs.summary(1000.0, model="exact", contact_end=contact_end).e)
    with pytest.raises(ValueError) as info:
        zs.dissipation_for(**GRAINS, v0=1.0, e=floor / 2, contact_end=contact_end)
    assert "1000" in str(info.value)


def test_thickness_for_gives_the_plate_that_gives_e():
    sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
    for e in (0.9, 0.5, 0.1):
        H = zs.thickness_for(sc, e)
        sc2 = zs.Scene("steel", "glass", radius="1 mm", thickness=H, v0="1 m/s")
        assert zs.summary(sc2.lam, model="exact").e == pytest.approx(e, rel=1e-11)
    with pytest.raises(ValueError, match="infinitely thick"):
        zs.thickness_for(sc, 1.0)
    with pytest.raises(ValueError, match="must be a zener_sym.Scene"):
        zs.thickness_for(0.5, 0.5)


@pytest.mark.parametrize("t_us", [10.0, 12.0, 25.0, 60.0])
def test_thickness_for_a_contact_time_gives_that_duration(t_us):
    """The thickness for a measured contact duration, forward-solved by the integrator
    (backend="scipy", not the tables the inverse uses): its contact lasts that long."""
    sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
    H = zs.thickness_for(sc, contact_time=f"{t_us} us")
    assert H == zs.thickness_for(sc, contact_time=t_us * 1e-6)
    sc2 = zs.Scene("steel", "glass", radius="1 mm", thickness=H, v0="1 m/s")
    r = sc2.result(model="exact", backend="scipy", rtol=1e-12, warn=False)
    assert r.contact_duration_s == pytest.approx(t_us * 1e-6, rel=1e-9)


def test_thickness_for_a_contact_time_grows_with_the_duration():
    sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
    H = [zs.thickness_for(sc, contact_time=t * 1e-6) for t in (10.0, 12.0, 25.0)]
    assert H[0] > H[1] > H[2]  # a longer contact needs a thinner, more compliant plate


def test_thickness_for_refuses_durations_no_plate_gives():
    sc = zs.Scene("steel", "glass", radius="1 mm", thickness="2 mm", v0="1 m/s")
    hertz = sc.result(model="hertz", warn=False).contact_duration_s  # rigid half-space
    with pytest.raises(ValueError, match="infinitely thick") as info:
        zs.thickness_for(sc, contact_time=0.999 * hertz)
    assert "contact_time <=" in str(info.value)
    longest = sc.T * float(zs.summary(1000.0).tau_d)
    with pytest.raises(ValueError, match="not reachable"):
        zs.thickness_for(sc, contact_time=1.01 * longest)
    assert zs.thickness_for(sc, contact_time=0.99 * longest) > 0
    with pytest.raises(ValueError, match="exactly one of e"):
        zs.thickness_for(sc, 0.5, contact_time="12 us")
    with pytest.raises(ValueError, match="exactly one of e"):
        zs.thickness_for(sc)
    with pytest.raises(ValueError, match="unknown time unit"):
        zs.thickness_for(sc, contact_time="12 uss")
    with pytest.raises(ValueError, match="give a unit"):
        zs.thickness_for(sc, contact_time="12")
    with pytest.raises(TypeError):
        zs.thickness_for(sc, None, 12e-6)  # contact_time is keyword-only


# -- the fit ----------------------------------------------------------------------------------

@pytest.mark.parametrize("contact_end", ["delta", "force"])
def test_fit_recovers_a_known_A_without_noise(contact_end):
    """Data from the integrator (backend="scipy"), the fit on the tables."""
    speeds = SPEEDS
    e = zs.summary(_lam(A_TRUE, speeds), model="exact", contact_end=contact_end,
                   backend="scipy").e
    fit = zs.fit_dissipation(**GRAINS, v0=speeds, e=e, **WALL, contact_end=contact_end)
    assert fit.A == pytest.approx(A_TRUE, rel=1e-9)
    assert np.max(np.abs(fit.residuals)) < 1e-10
    assert np.allclose(fit.lam, _lam(A_TRUE, speeds), rtol=1e-9)
    assert fit.A_se / fit.A < 1e-9  # no scatter, no uncertainty beyond the tables' own


@pytest.mark.parametrize("contact_end", ["force", "delta"])
def test_the_95_interval_covers_the_true_A_in_at_least_90_of_100_noisy_draws(contact_end):
    rng = np.random.default_rng(20261125)
    e0 = _e(A_TRUE, SPEEDS, contact_end)
    covered = 0
    for _ in range(100):
        e = e0 + rng.normal(0.0, 0.01, SPEEDS.size)
        fit = zs.fit_dissipation(**GRAINS, v0=SPEEDS, e=e, **WALL, contact_end=contact_end)
        covered += fit.A_ci[0] <= A_TRUE <= fit.A_ci[1]
    assert covered >= 90, covered


def test_given_sigma_weights_the_points_and_sets_the_interval():
    rng = np.random.default_rng(7)
    sigma = np.full(SPEEDS.size, 0.01)
    e0 = _e(A_TRUE, SPEEDS, "delta")
    covered = 0
    for _ in range(100):
        fit = zs.fit_dissipation(**GRAINS, v0=SPEEDS, e=e0 + rng.normal(0.0, 0.01, SPEEDS.size),
                                 **WALL, sigma=sigma, contact_end="delta")
        covered += fit.A_ci[0] <= A_TRUE <= fit.A_ci[1]
    assert covered >= 90, covered
    assert fit.sigma_from == "given"
    # the standard error of ln A with a known sigma is sigma / |J|, J_i = de_i/dln A: checked
    # here with central differences of the forward model (an independent route)
    h = 1e-6
    J = (_e(fit.A * math.exp(h), SPEEDS, "delta") - _e(fit.A * math.exp(-h), SPEEDS, "delta")) / (2 * h)
    assert fit.A_se / fit.A == pytest.approx(0.01 / math.sqrt(float(J @ J)), rel=1e-6)


def test_predict_matches_the_forward_path():
    e = _e(A_TRUE, SPEEDS, "force")[:3]
    fit = zs.fit_dissipation(**GRAINS, v0=SPEEDS[:3], e=e, **WALL)
    p = fit.predict(3.0)
    r = zs.grain_impact(**GRAINS, A=fit.A, v0=3.0, **WALL)
    assert p["e"] == pytest.approx(r.e, rel=1e-12)
    assert p["contact_duration_s"] == pytest.approx(r.contact_duration_s, rel=1e-12)
    assert p["e_low"] <= p["e"] <= p["e_high"]
    text = str(fit)
    assert "dissipative constant A =" in text and "95% confidence interval" in text


@pytest.mark.parametrize("v0,e,kw,message", [
    ([1.0, 2.0], [0.8], {}, "equal lengths"),
    ([1.0, 2.0], [0.8, 1.5], {}, "must lie in (0, 1]"),
    ([1.0, 0.0], [0.8, 0.7], {}, "must be finite and > 0"),
    ([1.0], [0.8], {}, "the fit needs at least 2"),
    ([1.0, 2.0], [1.0, 1.0], {}, "A = 0"),
    ([1.0, 2.0, 4.0], [0.6, 0.7, 0.8], {}, "e rises with speed"),
    ([1.0, 2.0], [1e-17, 1e-17], {}, "lower than lambda <= 1000 gives"),
    ([1.0, 2.0], [0.8, 0.7], {"sigma": [0.01, -1.0]}, "sigma"),
    ([1.0, 2.0], [0.8, 0.7], {"sigma": [0.01, 0.01, 0.01]}, "one per point"),
])
def test_fit_refuses_what_it_cannot_fit(v0, e, kw, message):
    with pytest.raises(ValueError) as info:
        zs.fit_dissipation(**GRAINS, v0=v0, e=e, **WALL, contact_end="delta", **kw)
    assert message in str(info.value)


def test_one_point_with_sigma_is_the_inverse():
    fit = zs.fit_dissipation(**GRAINS, v0=[2.0], e=[0.6], **WALL, sigma=0.01, contact_end="delta")
    A = zs.dissipation_for(**GRAINS, v0=2.0, e=0.6, **WALL, contact_end="delta")
    assert fit.A == pytest.approx(A, rel=1e-9)


def test_a_fit_that_does_not_converge_says_so(monkeypatch):
    import scipy.optimize

    real = scipy.optimize.least_squares

    def stalled(*args, **kwargs):
        sol = real(*args, **{**kwargs, "max_nfev": 1})
        sol.status = 0
        sol.message = "The maximum number of function evaluations is exceeded."
        return sol

    monkeypatch.setattr(scipy.optimize, "least_squares", stalled)
    with pytest.raises(ValueError, match="did not converge"):
        zs.fit_dissipation(**GRAINS, v0=SPEEDS, e=_e(A_TRUE, SPEEDS, "delta") * 0.99, **WALL,
                           contact_end="delta")


def test_fit_plot_draws_data_curve_and_residuals(tmp_path):
    pytest.importorskip("matplotlib")
    fit = zs.fit_dissipation(**GRAINS, v0=SPEEDS,
                             e=_e(A_TRUE, SPEEDS, "delta") + 0.003 * np.sin(SPEEDS), **WALL,
                             sigma=0.003, contact_end="delta")
    fig = fit.plot(tmp_path / "fit.png")
    assert (tmp_path / "fit.png").stat().st_size > 0
    top, bottom = fig.axes
    assert len(top.lines) >= 1 and top.collections  # fitted curve, band and error bars
    assert bottom.get_ylabel() == r"$e - e_{\rm fit}$"


# -- measurement files ------------------------------------------------------------------------

@pytest.mark.parametrize("header,factor", [("v0_m_s", 1.0), ("v0 [cm/s]", 1e-2),
                                           ("v (mm/s)", 1e-3), ("v0_km_h", 1 / 3.6)])
def test_read_measurements_units(header, factor):
    m = cal.read_measurements(f"# a comment\n{header},e,sigma_e\n2,0.8,0.01\n4,0.7,0.02\n")
    assert np.allclose(m.v0, np.array([2.0, 4.0]) * factor)
    assert list(m.e) == [0.8, 0.7] and list(m.sigma) == [0.01, 0.02]
    assert m.comments == ["a comment"]


@pytest.mark.parametrize("text,message", [
    ("v0,e\n1,0.8\n", "has no unit"),
    ("v0 [furlong/s],e\n1,0.8\n", "is not one of"),
    ("speed,e\n1,0.8\n", "no speed column"),
    ("v0_m_s,cor\n1,0.8\n", "no column 'e'"),
    ("v0_m_s,e\n1,x\n", "'x' is not a number"),
    ("v0_m_s,e\n", "no data rows"),
])
def test_read_measurements_refuses(text, message):
    with pytest.raises(ValueError) as info:
        cal.read_measurements(text)
    assert message in str(info.value)


def test_the_bridges_law_file_is_what_its_script_writes(tmp_path):
    tool = runpy.run_path(str(ROOT / "tools" / "calibration" / "bridges1984_law.py"))
    out = tool["main"](tmp_path / "law.csv")
    committed = Path(cal.__file__).resolve().parents[1] / "data" / "bridges1984_ice_law.csv"
    assert out.read_text() == committed.read_text()
    m = cal.read_measurements(committed)
    assert "NOT MEASURED POINTS" in "\n".join(m.comments)
    # the law itself, from its two published constants (v_c = 0.0077 cm/s, exponent 0.234)
    assert np.allclose(m.e, (m.v0 / 0.0077e-2) ** -0.234, atol=5e-5)


def test_docs_quote_the_committed_fit():
    """docs/viscoelastic.md quotes the fit that `zener-sym regen calibration` writes (its
    freshness is checked in test_regen): the quoted lines are the committed text's."""
    root = Path(__file__).resolve().parent.parent
    committed = (root / "docs" / "data" / "calibration_bridges1984.txt").read_text("utf-8")
    doc = (root / "docs" / "viscoelastic.md").read_text("utf-8")
    head = committed.splitlines()[:4]
    assert head[0].startswith("dissipative constant A = ")
    for line in head:
        assert "    " + line in doc, line
