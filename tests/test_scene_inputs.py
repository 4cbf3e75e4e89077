"""Bad input to materials and scenes: ValueError naming the field and the allowed range."""
import math

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.scene.units import parse_quantity

GOOD = dict(radius=1e-3, thickness=2e-3, v0=1.0)


@pytest.mark.parametrize("field", ["radius", "thickness", "v0"])
@pytest.mark.parametrize("bad", [0.0, -1e-3, math.nan, math.inf, -math.inf, "1mm", None, True])
def test_scene_rejects_bad_geometry_and_speed(field, bad):
    kw = dict(GOOD, **{field: bad})
    with pytest.raises(ValueError, match=rf"^{field}\b.*0 < {field} < infinity"):
        zs.Scene("steel", "glass", **kw)


@pytest.mark.parametrize("field", ["E", "rho"])
@pytest.mark.parametrize("bad", [0.0, -5.0, math.nan, math.inf])
def test_material_rejects_non_positive_modulus_and_density(field, bad):
    kw = dict(E=210e9, nu=0.3, rho=7850.0)
    kw[field] = bad
    with pytest.raises(ValueError, match=rf"^{field}\b.*0 < {field} < infinity"):
        zs.Material(**kw)


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
    ("1mm", "length", 1e-3), ("0.5 mm", "length", 5e-4), ("2", "length", 2.0),
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
])
def test_parse_quantity_rejects(text, kind, msg):
    with pytest.raises(ValueError, match=msg):
        parse_quantity(text, kind)
