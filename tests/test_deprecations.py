"""The old names and call forms of issue 32 still work for one release, each with a
DeprecationWarning, and give what the new ones give.

Each old call is compared with the new call written out by hand (not with a translation of the
code under test), and each new call is checked not to warn.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.scene.grains import grain_contact

V0 = np.array([0.5, 1.0, 2.0, 4.0])
E = np.array([0.82, 0.80, 0.77, 0.74])


def _new(func, *args, **kwargs):
    """The new call: it must not warn."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        return func(*args, **kwargs)


# -- one argument order -----------------------------------------------------------------------

def test_dissipation_for_old_positional_order_warns_and_agrees():
    new = _new(zs.dissipation_for, "glass", "1 mm", 1e-5, v0=V0, e=E, wall="steel")
    with pytest.warns(DeprecationWarning, match=r"dissipation_for\(e, v0, R1, m1, material1"):
        old = zs.dissipation_for(E, V0, "1 mm", 1e-5, "glass", wall="steel")
    np.testing.assert_array_equal(old, new)


def test_fit_dissipation_old_positional_order_warns_and_agrees():
    new = _new(zs.fit_dissipation, "glass", "1 mm", 1e-5, v0=V0, e=E, wall="steel")
    with pytest.warns(DeprecationWarning, match=r"fit_dissipation\(v0, e, R1, m1, material1"):
        old = zs.fit_dissipation(V0, E, "1 mm", 1e-5, "glass", wall="steel")
    assert old.A == new.A and old.A_ci == new.A_ci


def test_the_two_arrays_are_keyword_only():
    """A swapped pair can no longer pass silently: the arrays are not positional."""
    with pytest.raises(TypeError):
        zs.dissipation_for("glass", "1 mm", 1e-5, 1.0, 0.8)
    with pytest.raises(TypeError):
        zs.fit_dissipation("glass", "1 mm", 1e-5, V0, E)
    # by keyword the order does not matter
    a = _new(zs.dissipation_for, "glass", "1 mm", 1e-5, e=0.8, v0=1.0)
    assert a == _new(zs.dissipation_for, "glass", "1 mm", 1e-5, v0=1.0, e=0.8)


def test_swapping_the_old_orders_is_what_the_new_form_prevents():
    """The old forms took the arrays in opposite orders: the same positional call gave
    different answers (here a refusal, e > 1 read as a speed's e)."""
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match="must lie in"):
        zs.dissipation_for([1.0, 2.0], [0.8, 0.7], "1 mm", 1e-5, "glass")


# -- a sphere's inputs carry the scene's names ------------------------------------------------

@pytest.mark.parametrize("old_kw", [
    dict(R1="1 mm", m1=1e-5, material1="glass"),
    dict(material1="glass", R1="1 mm", m1=1e-5, R2="2 mm", m2=3e-5, material2="steel"),
])
def test_grain_impact_old_names_warn_and_agree(old_kw):
    new_kw = {{"R1": "radius", "m1": "mass", "material1": "sphere", "R2": "radius2",
               "m2": "mass2", "material2": "sphere2"}[k]: v for k, v in old_kw.items()}
    new = _new(zs.grain_impact, **new_kw, A=3e-7, v0=2.0)
    with pytest.warns(DeprecationWarning, match="radius, mass, sphere"):
        old = zs.grain_impact(**old_kw, A=3e-7, v0=2.0)
    assert (old.e, old.contact_duration_s, old.max_force_N) == (
        new.e, new.contact_duration_s, new.max_force_N)


def test_grain_impact_and_contact_old_positional_forms():
    new = _new(zs.grain_impact, "glass", 1e-3, 1e-5, A=1e-7, v0=1.0, wall="steel")
    with pytest.warns(DeprecationWarning, match=r"grain_impact\(R1, m1, material1, A, v0"):
        old = zs.grain_impact(1e-3, 1e-5, "glass", 1e-7, 1.0, wall="steel")
    assert old.e == new.e
    with pytest.warns(DeprecationWarning):
        c_old = grain_contact("1 mm", 1e-5, "glass", R2="1 mm", m2=1e-5, material2="glass")
    assert c_old == _new(grain_contact, "glass", "1 mm", 1e-5, sphere2="glass",
                         radius2="1 mm", mass2=1e-5)


def test_old_and_new_name_of_one_input_together_is_refused():
    with pytest.raises(TypeError, match="old and its new name"):
        zs.grain_impact(R1="1 mm", radius="1 mm", m1=1e-5, material1="glass", A=1e-7, v0=1.0)


def test_scene_and_grains_share_the_names():
    import inspect

    scene = set(inspect.signature(zs.Scene).parameters)
    for f in (zs.grain_impact, zs.dissipation_for, zs.fit_dissipation):
        params = inspect.signature(f).parameters
        assert {"sphere", "radius"} <= set(params) & scene, f.__name__
        assert not {"R1", "m1", "material1", "R2", "m2", "material2"} & set(params)
        assert params["v0"].kind is inspect.Parameter.KEYWORD_ONLY


# -- one way to each result -------------------------------------------------------------------

SCENE = dict(radius="1 mm", thickness="2 mm", v0="1 m/s")


def test_scene_summary_is_a_deprecated_alias_of_result():
    sc = zs.Scene("steel", "glass", **SCENE)
    new = _new(sc.result, rtol=1e-3)
    with pytest.warns(DeprecationWarning, match=r"Scene.result\(\)"):
        old = sc.summary(rtol=1e-3)
    assert (old.model, old.e, old.contact_duration_s) == (new.model, new.e,
                                                          new.contact_duration_s)


def test_api_summary_of_a_scene_is_deprecated():
    sc = zs.Scene("steel", "glass", **SCENE)
    new = _new(sc.result, model="exact")
    with pytest.warns(DeprecationWarning, match=r"scene.result\(\.\.\.\)"):
        old = zs.summary(sc, model="exact")
    assert isinstance(old, zs.SceneResult) and old.max_force_N == new.max_force_N
    assert isinstance(_new(zs.summary, sc.lam), zs.Summary)  # a lambda: no warning


def test_lam_for_and_viscoelastic_lambda_are_deprecated_names():
    with pytest.warns(DeprecationWarning, match="lam_from_summary"):
        old = zs.lam_for(e=[0.9, 0.5], contact_end="force")
    np.testing.assert_array_equal(old, _new(zs.lam_from_summary, e=[0.9, 0.5],
                                            contact_end="force"))
    with pytest.warns(DeprecationWarning, match="lam_from_dissipation"):
        old = zs.viscoelastic_lambda(1e-6, 1e9, 1e-5, 1.0)
    assert old == _new(zs.lam_from_dissipation, 1e-6, 1e9, 1e-5, 1.0)
    assert "lam_for" not in zs.__all__ and "viscoelastic_lambda" not in zs.__all__


# -- the flat LAMMPS modules moved into bench/lammps/ (issue 36) --------------------------------

@pytest.mark.parametrize("old, new, name", [
    ("zener_sym.bench.lammps_run", "zener_sym.bench.lammps.run", "Session"),
    ("zener_sym.bench.lammps_run", "zener_sym.bench.lammps.run", "LammpsMissing"),
    ("zener_sym.bench.lammps_verify", "zener_sym.bench.lammps.studies", "convergence"),
    ("zener_sym.bench.lammps_mpi", "zener_sym.bench.lammps.mpi", "write_deck"),
    ("zener_sym.bench.lammps_charts", "zener_sym.bench.lammps.charts", "mpi_chart"),
])
def test_old_lammps_module_paths_warn_and_give_the_same_objects(old, new, name):
    import importlib

    new_obj = getattr(_new(importlib.import_module, new), name)
    module = importlib.import_module(old)
    with pytest.warns(DeprecationWarning, match=rf"{old} is deprecated: use {new}"):
        assert getattr(module, name) is new_obj
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        module.no_such_name
