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


# --- shapes: every history field has the broadcast shape of lambda and tau ------------------
@pytest.mark.parametrize("lam_shape,tau_shape", [
    ((), ()), ((), (5,)), ((3,), ()), ((3, 1), (5,)), ((2, 1, 1), (1, 3, 4)), ((2, 3, 4), ()),
])
def test_history_fields_have_the_broadcast_shape(lam_shape, tau_shape):
    lam = np.full(lam_shape, 0.7)
    tau = np.full(tau_shape, 1.3)
    want = np.broadcast_shapes(lam_shape, tau_shape)
    h = zs.history(lam, tau)
    for f in ("tau", "delta", "velocity", "force", "impulse"):
        assert np.shape(getattr(h, f)) == want, f
    # every entry is the scalar answer (same lambda and tau everywhere)
    one = zs.history(0.7, 1.3)
    np.testing.assert_allclose(h.force, one.force, rtol=1e-14)


def test_summary_takes_lambda_of_any_rank():
    lam = np.array([0.2, 0.9]).reshape(2, 1, 1)
    s = zs.summary(lam)
    assert s.e.shape == (2, 1, 1) and s.e[1, 0, 0] == pytest.approx(zs.summary(0.9).e, rel=1e-14)


def test_history_default_model_is_exact():
    assert zs.history(1.0, 2.0).model == "exact" == zs.summary(1.0).model


def test_bound_messages_print_the_bound_the_check_uses():
    import re

    for model in ("exact", "ham1", "oneway"):
        with pytest.raises(ValueError) as info:
            zs.summary(5000.0, model=model)
        m = re.search(r"allowed 0 <= lambda (<=|<) ([0-9.e+]+)", str(info.value))
        assert m, str(info.value)
        op, bound = m.group(1), float(m.group(2))
        # the printed bound is judged as printed: accepted with <=, refused with <
        if op == "<=":
            zs.summary(bound, model=model)
        else:
            with pytest.raises(ValueError):
                zs.summary(bound, model=model)
            zs.summary(np.nextafter(bound, 0), model=model)


def test_history_tau_is_its_own_writeable_copy():
    """History.tau is the api's copy of tau (never the caller's array, whatever the shapes) and
    writeable after the call, though the model saw it read-only."""
    tau = np.linspace(0.0, 3.0, 7)
    for lam in (1.0, np.array([[0.5], [1.5]]), np.full(7, 0.3)):
        h = zs.history(lam, tau)
        tau_before = h.tau.copy()
        tau[:] += 1.0  # the caller changes its array afterwards
        np.testing.assert_array_equal(h.tau, tau_before)
        assert h.tau.flags.writeable
        tau[:] -= 1.0
