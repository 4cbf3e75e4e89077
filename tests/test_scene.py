"""Dimensional results of scenes: physical identities, histories, CLI and report section."""
import warnings

import numpy as np
import pytest

import zener_sym as zs
from zener_sym import cli
from zener_sym.report import build as report


@pytest.fixture(scope="module")
def res():
    sc = zs.Scene("steel", "aluminium", 1e-3, 1e-3, 2.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", zs.ZenerWarning)  # a plain scene raises none
        return sc.result(rtol=1e-3)


@pytest.fixture(scope="module")
def res_scipy():
    """The same scene integrated (backend "scipy"), where e and xi are separate states."""
    return zs.Scene("steel", "aluminium", 1e-3, 1e-3, 2.0).result(model="exact", backend="scipy")


def test_identities(res_scipy):
    """The SI scaling, on the scipy path. Dimensionless, F_m = delta_m^{3/2} and impulse = 1 + e
    hold by construction on every path (each forms F_m from delta_m and the impulse from the end
    velocity), so the two asserts below check the scene's scales K and alpha m1 V0. The energy
    balance compares separate states: here xi >= 1/2, where e is the integrated end velocity and
    xi = 2 lambda int F^2 (on the tables' path and below xi = 1/2, e comes from xi)."""
    res = res_scipy
    sc = res.scene
    assert res.xi >= 0.5
    assert res.xi == pytest.approx(1 - res.e**2, rel=1e-10)
    # Hertz: F_m = K delta_m^{3/2} with K = (4/3) E* sqrt(R)
    K = 4 / 3 * sc.E_star * np.sqrt(sc.radius)
    assert res.max_force_N == pytest.approx(K * res.max_compression_m**1.5, rel=1e-12)
    # final deflection w = alpha * impulse, and impulse = m1 (V0 + e V0) (momentum balance)
    assert res.final_deflection_m == pytest.approx(sc.alpha * sc.m1 * sc.v0 * (1 + res.e),
                                                 rel=1e-10)


def test_histories(res):
    sc = res.scene
    t = np.linspace(0, 1.2 * res.contact_duration_s, 241)
    h = res.history(t)
    assert h["force_N"][0] == 0 and h["velocity_m_s"][0] == pytest.approx(sc.v0, rel=1e-15)
    after = t > res.contact_duration_s
    assert np.all(h["force_N"][after] == 0)
    assert np.allclose(h["velocity_m_s"][after], -res.rebound_speed_m_s, rtol=1e-9)
    assert np.allclose(h["deflection_m"][after], res.final_deflection_m, rtol=1e-9)
    assert h["force_N"].max() <= res.max_force_N * (1 + 1e-12)
    # momentum: m1 (V0 - V(t)) = int_0^t F dt (trapezoid on a fine grid)
    tf = np.linspace(0, res.contact_duration_s, 4001)
    F = res.force(tf)
    J = np.concatenate([[0], np.cumsum(0.5 * (F[1:] + F[:-1]) * np.diff(tf))])
    assert np.allclose(sc.m1 * (sc.v0 - res.velocity(tf)), J, atol=2e-6 * J[-1])
    assert np.allclose(res.deflection(tf), sc.alpha * J, atol=2e-6 * sc.alpha * J[-1])
    with pytest.raises(ValueError, match="t must be"):
        res.history([-1.0])


def test_result_with_explicit_model_and_lambda_path_unchanged():
    sc = zs.Scene("glass", "glass", 1e-3, 1e-3, 1.0)
    r = sc.result(model="exact")
    assert r.model == "exact" and "requested" in r.reason
    s = zs.summary(sc.lam)  # the lambda path still gives the dimensionless Summary
    assert r.contact_duration_s == pytest.approx(s.tau_d * sc.T, rel=1e-15)


def test_cli_scene(capsys, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "f.png"
    rc = cli.main(["scene", "--sphere", "steel", "--plate", "glass", "--radius", "1mm",
                   "--thickness", "2mm", "--v0", "1m/s", "--rtol", "1e-3", "--plot", str(out)])
    text = capsys.readouterr().out
    assert rc == 0
    assert "contact duration t_d" in text and "lambda" in text and "why this model" in text
    assert out.exists() and out.stat().st_size > 1000
    lam = zs.Scene("steel", "glass", 1e-3, 2e-3, 1.0).lam
    assert f"{lam:.6g}" in text


@pytest.mark.parametrize("args,msg", [
    (["--radius=-1mm"], "radius"), (["--v0", "nan"], "v0"), (["--thickness", "2 parsecs"],
                                                            "thickness"),
    (["--plate", "70GPa,0.6,2700kg/m^3"], "nu"), (["--sphere", "cheese"], "preset"),
])
def test_cli_scene_bad_input(capsys, args, msg):
    base = {"--sphere": "steel", "--plate": "glass", "--radius": "1mm", "--thickness": "2mm",
            "--v0": "1m/s"}
    for a in args:
        key = a.split("=")[0]
        base.pop(key, None)
    argv = ["scene"] + [x for kv in base.items() for x in kv] + args
    assert cli.main(argv) == 2
    assert msg in capsys.readouterr().err


def test_cli_lists_warnings_in_table(capsys):
    rc = cli.main(["scene", "--sphere", "steel", "--plate", "glass", "--radius", "1mm",
                   "--thickness", "0.25mm", "--v0", "5m/s", "--plate-radius", "2mm"])
    text = capsys.readouterr().out
    assert rc == 0 and "WARNING ham-bound" in text and "WARNING finite-plate" in text


def test_report_has_scene_section(tmp_path):
    names = [n for n, _ in report.SECTIONS]
    assert "scene" in names
    md = dict(report.SECTIONS)["scene"](tmp_path)
    assert "0.162982" in md  # lambda of the Table 1 pair, R 0.9 mm, H 0.5 mm, 1 m/s


def test_model_without_some_fields(monkeypatch):
    from zener_sym.models import REGISTRY

    from _fake_models import Perturbed

    partial = Perturbed("partial", 0.0)
    partial.summary_fields = ("lam", "tau_d", "delta_m", "F_m")
    orig = partial._summary
    partial._summary = lambda lam, **o: {k: v for k, v in orig(lam).items()
                                         if k in partial.summary_fields}
    monkeypatch.setitem(REGISTRY, "partial", partial)
    sc = zs.Scene("steel", "glass", 1e-3, 2e-3, 1.0)
    with pytest.warns(zs.ZenerWarning, match="not-checked"):
        r = sc.result(model="partial")
    ex = sc.result(model="exact")
    assert r.e is None and r.xi is None and r.final_deflection_m is None
    assert r.contact_duration_s == pytest.approx(ex.contact_duration_s, rel=1e-15)
    assert "n/a (not given by model 'partial')" in str(r)
