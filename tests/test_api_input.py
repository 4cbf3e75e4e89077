"""Bad input gets a ValueError that says what was wrong and what is allowed."""
import math

import numpy as np
import pytest

import zener_sym as zs


@pytest.mark.parametrize(
    "lam, words",
    [
        (-0.1, ">= 0"),
        (math.nan, "finite"),
        (math.inf, "finite"),
        ("1.0", "real number"),
        (1 + 2j, "real"),
        ([0.1, -1.0], ">= 0"),
        ([], "empty"),
        (None, "real number"),
        (2000.0, "allowed 0 <= lambda <"),
    ],
)
def test_bad_lambda(lam, words):
    with pytest.raises(ValueError, match=words):
        zs.summary(lam, model="exact")


@pytest.mark.parametrize("tau, words", [(-1.0, ">= 0"), ([0.0, math.nan], "finite"), ("x", "real")])
def test_bad_tau(tau, words):
    with pytest.raises(ValueError, match=words):
        zs.history(0.5, tau, model="exact")


def test_unknown_model_lists_allowed():
    with pytest.raises(ValueError, match="unknown model 'nope'; allowed: .*exact"):
        zs.summary(0.5, model="nope")


def test_unknown_option():
    with pytest.raises(ValueError, match="takes no option 'tol'"):
        zs.summary(0.5, model="exact", tol=1e-3)


def test_shapes_that_do_not_broadcast():
    with pytest.raises(ValueError, match="does not broadcast"):
        zs.history(np.array([0.1, 0.2]), np.zeros(3), model="exact")


def test_models_tuple():
    assert "exact" in zs.MODELS
    assert isinstance(zs.MODELS, tuple)


def test_unavailable_field_error_names_field_and_model():
    from zener_sym.models.base import Model, REGISTRY, register

    class Partial(Model):
        name = "_partial_test"
        summary_fields = ("lam", "e")

        def _summary(self, lam, **o):
            return {"e": np.ones_like(lam)}

    register(Partial())
    try:
        s = zs.summary(0.3, model="_partial_test")
        assert s.e == 1.0
        with pytest.raises(ValueError, match="model '_partial_test' does not give the summary "
                                             "field 'tau_d'"):
            s.tau_d
    finally:
        del REGISTRY["_partial_test"]
