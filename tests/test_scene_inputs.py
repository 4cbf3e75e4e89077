"""Bad input to materials and scenes: ValueError naming the field and the allowed range."""
import math

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.scene.units import parse_quantity

GOOD = dict(radius=1e-3, thickness=2e-3, v0=1.0)


@pytest.mark.parametrize("field", ["radius", "thickness", "v0"])
@pytest.mark.parametrize("bad", [0.0, -1e-3, math.nan, math.inf, -math.inf, "-1mm", "1 parsec",
                                 None, True, 1e300, 1e-300, "2.5"])
def test_scene_rejects_bad_geometry_and_speed(field, bad):
    kw = dict(GOOD, **{field: bad})
    if bad is None and field == "v0":  # no speed at all
        with pytest.raises(ValueError, match="exactly one of v0 .* and drop_height"):
            zs.Scene("steel", "glass", **kw)
        return
    with pytest.raises(ValueError, match=rf"^{field}\b.*(allowed|give a unit|unknown)"):
        zs.Scene("steel", "glass", **kw)


@pytest.mark.parametrize("kw,expect", [
    (dict(radius="1 mm", thickness="2mm", v0="1 m/s"), (1e-3, 2e-3, 1.0)),
    (dict(radius="0.1 cm", thickness=2e-3, v0="100 cm/s"), (1e-3, 2e-3, 1.0)),
    (dict(radius=1e-3, thickness="2000 um", v0="3.6 km/h"), (1e-3, 2e-3, 1.0)),
])
def test_scene_takes_units(kw, expect):
    sc = zs.Scene("steel", "glass", **kw)
    assert (sc.radius, sc.thickness, sc.v0) == pytest.approx(expect, rel=1e-15)


def test_drop_height_is_free_fall():
    # v0 = sqrt(2 g h) with standard gravity; h = v0^2 / (2 g) inverts it
    sc = zs.Scene("steel", "glass", radius="1mm", thickness="2mm", drop_height="0.5 m")
    assert sc.v0 == pytest.approx(math.sqrt(2 * 9.80665 * 0.5), rel=1e-15)
    same = zs.Scene("steel", "glass", radius="1mm", thickness="2mm", v0=sc.v0)
    assert same.lam == sc.lam
    with pytest.raises(ValueError, match="exactly one of v0"):
        zs.Scene("steel", "glass", radius="1mm", thickness="2mm", v0=1.0, drop_height=0.5)
    with pytest.raises(ValueError, match="drop_height"):
        zs.Scene("steel", "glass", radius="1mm", thickness="2mm", drop_height="-1 m")


def test_scene_result_says_where_old_names_went():
    r = zs.Scene("steel", "glass", radius="1mm", thickness="2mm", v0=1.0).result()
    with pytest.raises(AttributeError, match="restitution.* is now 'e'"):
        r.restitution
    assert r.e == r.summary.e and r.xi == r.summary.xi


@pytest.mark.parametrize("field", ["E", "rho"])
@pytest.mark.parametrize("bad", [0.0, -5.0, math.nan, math.inf])
def test_material_rejects_non_positive_modulus_and_density(field, bad):
    kw = dict(E=210e9, nu=0.3, rho=7850.0)
    kw[field] = bad
    with pytest.raises(ValueError, match=rf"^{field}\b.*allowed: .* <= {field} <= "):
        zs.Material(**kw)


def test_material_takes_units():
    m = zs.Material("210 GPa", 0.3, "7.85 g/cm^3", yield_strength="250 MPa")
    assert (m.E, m.rho, m.yield_strength) == pytest.approx((210e9, 7850.0, 250e6), rel=1e-15)
    with pytest.raises(ValueError, match="E 210: give a unit"):
        zs.Material("210", 0.3, 7850.0)


@pytest.mark.parametrize("nu", [-1.0, 0.5, 0.7, -1.5, math.nan, math.inf])
def test_material_rejects_poisson_ratio_outside_open_interval(nu):
    with pytest.raises(ValueError, match=r"nu \(Poisson's ratio\).*-1 < nu < 0.5"):
        zs.Material(210e9, nu, 7850.0)


@pytest.mark.parametrize("nu", [-0.99, 0.0, 0.49])
def test_material_accepts_poisson_ratio_inside(nu):
    assert zs.Material(1e9, nu, 1000.0).nu == nu


def test_plate_radius_validated():
    with pytest.raises(ValueError, match="plate_radius"):
        zs.Scene("steel", "glass", plate_radius=-1.0, **GOOD)
    with pytest.raises(ValueError, match="plate_radius must exceed"):
        zs.Scene("steel", "glass", plate_radius=0.5e-3, **GOOD)


def test_unknown_preset_lists_presets():
    with pytest.raises(ValueError, match="steel, glass"):
        zs.Scene("unobtainium", "glass", **GOOD)


def test_presets_have_sources_and_table1_is_as_printed():
    for m in (zs.STEEL, zs.GLASS, zs.ALUMINIUM, zs.TABLE1_SPHERE, zs.TABLE1_PLATE):
        assert m.source and m.name in zs.PRESETS
    # paper, Appendix, Table 1, as printed
    assert (zs.TABLE1_SPHERE.E, zs.TABLE1_SPHERE.nu, zs.TABLE1_SPHERE.rho) == (12.23e9, 0.21, 879)
    assert (zs.TABLE1_PLATE.E, zs.TABLE1_PLATE.nu, zs.TABLE1_PLATE.rho) == (73e9, 0.21, 2500)
    assert "Table 1" in zs.TABLE1_SPHERE.source


def test_numpy_scalars_accepted():
    sc = zs.Scene("steel", "glass", np.float64(1e-3), np.float32(2e-3), np.int64(1))
    assert sc.v0 == 1.0


@pytest.mark.parametrize("text,kind,value", [
    ("1mm", "length", 1e-3), ("0.5 mm", "length", 5e-4), ("2 m", "length", 2.0),
    ("150 um", "length", 150e-6), ("1m/s", "speed", 1.0), ("36 km/h", "speed", 10.0),
    ("250mm/s", "speed", 0.25), ("73GPa", "pressure", 73e9), ("1.5 gpa", "pressure", 1.5e9),
    ("250MPa", "pressure", 250e6), ("7.85 g/cm^3", "density", 7850.0),
    ("2500kg/m3", "density", 2500.0), ("1e-3 m", "length", 1e-3),
])
def test_parse_quantity(text, kind, value):
    assert parse_quantity(text, kind) == pytest.approx(value, rel=1e-15)


@pytest.mark.parametrize("text,kind,msg", [
    ("1mn", "length", "unknown length unit 'mn'"), ("1 m/s", "length", "unknown length unit"),
    ("fast", "speed", "not a number with a unit"), ("1mm", "colour", "unknown kind"),
    ("2", "length", r"2: give a unit, e.g. 1mm or 0.001m"),
])
def test_parse_quantity_rejects(text, kind, msg):
    with pytest.raises(ValueError, match=msg):
        parse_quantity(text, kind)
