"""Validity warnings of scenes: HAM bound, thick/thin plate, finite plate, yield."""
import math
import warnings

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.scene import checks


def _codes(res):
    return {c for c, _ in res.warnings}


def test_zener_warning_is_a_user_warning():
    assert issubclass(zs.ZenerWarning, UserWarning)


def test_ham_bound_is_the_root_of_the_derived_condition():
    # lambda^2 k = 4 with k = (lambda + (5/4)^{-3/5})^{-1/3}: lambda^6 - 64 lambda - 64 c0 = 0;
    # independent route: the polynomial's real positive root by numpy.
    c0 = 1.25 ** -0.6
    roots = np.roots([1, 0, 0, 0, 0, -64, -64 * c0])
    real = [r.real for r in roots if abs(r.imag) < 1e-12 and r.real > 0]
    assert len(real) == 1
    assert checks.HAM_LAMBDA_BOUND == pytest.approx(real[0], rel=1e-13)
    # k at lambda = 0 is sqrt(delta_m) of Hertz, delta_m = (5/4)^{2/5}
    assert checks.ham_k(0.0) == pytest.approx(math.sqrt(1.25 ** 0.4), rel=1e-15)


def test_paper_fem_scene_has_no_warnings():
    sc = zs.Scene("table1-sphere", "table1-plate", 0.9e-3, 0.5e-3, 1.0, plate_radius=0.15)
    with warnings.catch_warnings():
        warnings.simplefilter("error", zs.ZenerWarning)
        res = sc.result(model="exact")
    assert res.warnings == []


def test_ham_bound_warning_issued_and_listed():
    sc = zs.Scene("steel", "glass", 1e-3, 0.25e-3, 5.0)  # lambda ~ 7
    assert sc.lam > checks.HAM_LAMBDA_BOUND
    assert "ham-bound" in {c for c, _ in sc.warnings}
    with pytest.warns(zs.ZenerWarning, match=r"\[ham-bound\]"):
        res = sc.result(rtol=1e-3)
    assert "ham-bound" in _codes(res)
    assert any(r[0] == "WARNING ham-bound" for r in res.table())
    assert res.model == "exact"


def test_thick_plate_warning_below_koller_kolsky_ratio():
    thick = zs.Scene("steel", "steel", 0.5e-3, 6e-3, 1.0)   # 2R/H = 0.167
    ok = zs.Scene("steel", "steel", 0.7e-3, 6e-3, 1.0)      # 2R/H = 0.233
    assert "thick-plate" in {c for c, _ in thick.warnings}
    assert "thick-plate" not in {c for c, _ in ok.warnings}


def test_kirchhoff_warning_for_short_pulse_on_thick_plate():
    # k H at omega = pi/t_d, recomputed here from c_phase = sqrt(omega)(D/(rho H))^{1/4}
    sc = zs.Scene("steel", "steel", 1e-3, 20e-3, 5.0)
    with pytest.warns(zs.ZenerWarning):
        res = sc.result(model="exact")
    omega = math.pi / res.contact_duration_s
    kH = math.sqrt(omega) / (sc.D / (sc.plate.rho * sc.thickness)) ** 0.25 * sc.thickness
    assert kH > 1.0
    assert "kirchhoff" in _codes(res)


def test_thin_plate_and_large_deflection_warnings():
    rubber = zs.Material(10e6, 0.45, 1100.0, "rubber-like")  # soft sphere: large contact
    sc = zs.Scene(rubber, "steel", 5e-3, 0.2e-3, 5.0)
    with pytest.warns(zs.ZenerWarning):
        res = sc.result(model="exact")
    a = math.sqrt(sc.radius * res.max_compression_m)
    assert a > sc.thickness and "thin-plate" in _codes(res)
    assert res.final_deflection_m > sc.thickness / 2 and "large-deflection" in _codes(res)


def test_finite_plate_warning_from_the_criterion():
    # a plate radius without a support: Zener's answer, warned about when the criterion finds
    # it off by more than rtol for either support. Checked here against the finite-plate model
    # itself: far (0.2 m) both supports agree with Zener within rtol, near (10 mm) one does not.
    base = dict(radius=1e-3, thickness=1e-3, v0=1.0)
    rtol = 1e-3

    def worst(sc):
        z = zs.summary(sc.lam)
        out = 0.0
        for support in ("clamped", "simply-supported"):
            s = zs.summary(sc.lam, model="finite-plate", beta=sc.beta, support=support,
                           nu=sc.plate.nu, rtol=1e-6)
            out = max(out, *(abs(getattr(s, q) / getattr(z, q) - 1) for q in ("e", "tau_d")))
        return out

    far_sc = zs.Scene("steel", "glass", plate_radius=0.2, **base)
    far = far_sc.result(model="exact", rtol=rtol, warn=False)
    assert "finite-plate" not in _codes(far) and worst(far_sc) <= rtol
    near_sc = zs.Scene("steel", "glass", plate_radius=0.01, **base)
    near = near_sc.result(model="exact", rtol=rtol, warn=False)
    assert "finite-plate" in _codes(near) and worst(near_sc) > rtol
    assert "clamped or simply-supported" in dict(near.warnings)["finite-plate"]


def test_yield_warning_against_hertz_pressure():
    base = dict(radius=1e-3, thickness=2e-3, v0=1.0)
    res = zs.Scene("steel", "glass", **base).result(model="exact", warn=False)
    # Hertz: p0 = 3F/(2 pi a^2), a^3 = 3 F R / (4 E*)
    a = (3 * res.max_force_N * 1e-3 / (4 * res.scene.E_star)) ** (1 / 3)
    p0 = 3 * res.max_force_N / (2 * math.pi * a**2)
    weak = zs.STEEL.with_yield(0.9 * p0 / 1.6)
    strong = zs.STEEL.with_yield(1.1 * p0 / 1.6)
    r1 = zs.Scene(weak, "glass", **base).result(model="exact", warn=False)
    r2 = zs.Scene(strong, "glass", **base).result(model="exact", warn=False)
    assert "yield" in _codes(r1) and "sphere" in dict(r1.warnings)["yield"]
    assert "yield" not in _codes(r2)


@pytest.mark.parametrize("H", [0.18e-3, 0.75e-3])
@pytest.mark.parametrize("v0", [1.0, 20.0])
def test_paper_fem_range_raises_no_warning(H, v0):
    # The paper's FEM (Appendix) agrees with Zener's model over this range: no check may fire.
    sc = zs.Scene("table1-sphere", "table1-plate", 0.9e-3, H, v0, plate_radius=0.15)
    assert sc.result(model="exact", warn=False).warnings == []
