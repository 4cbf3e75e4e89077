"""select_model against hand-made envelope tables, and the committed table."""
import math

import pytest

import zener_sym as zs
from zener_sym.scene import envelopes
from zener_sym.models import REGISTRY

from _fake_models import Perturbed


def _table(models):
    q = list(envelopes.QUANTITIES)
    return {"schema": envelopes.SCHEMA, "intervals": [[0, 1], [1, 2], [2, 3]], "quantities": q,
            "models": {name: {"cost_rank": rank, "lam_bound": None,
                              "envelopes": {k: list(env) for k in q}}
                       for name, (rank, env) in models.items()}}


@pytest.fixture
def fakes(monkeypatch):
    monkeypatch.setitem(REGISTRY, "cheap", Perturbed("cheap", 1e-3))
    monkeypatch.setitem(REGISTRY, "mid", Perturbed("mid", 1e-6))
    return _table({"exact": (2, [1e-12] * 3), "cheap": (0, [1e-4, 1e-2, None]),
                   "mid": (1, [1e-6, 1e-6, 1e-6])})


@pytest.mark.parametrize("lam,rtol,expected", [
    (0.5, 1e-3, "cheap"),   # cheapest, within its envelope
    (0.5, 1e-5, "mid"),     # cheap too inaccurate
    (1.5, 1e-3, "mid"),     # cheap's envelope 1e-2 there
    (1.0, 1e-3, "mid"),     # at an edge both intervals count: max(1e-4, 1e-2)
    (2.5, 1e-1, "mid"),     # cheap not measured there
    (0.5, 1e-9, "exact"),   # only exact
    (3.5, 1e-1, "exact"),   # outside the table
])
def test_cheapest_qualifying_model(fakes, lam, rtol, expected):
    sel = zs.select_model(lam, "e", rtol, table=fakes)
    assert sel.model == expected
    model, reason = sel
    assert isinstance(reason, str) and reason


def test_reason_mentions_envelope_and_rejections(fakes):
    sel = zs.select_model(1.5, "e", 1e-3, table=fakes)
    assert "1e-06 <= rtol 0.001" in sel.reason and "cheap: envelope 0.01 > rtol" in sel.reason
    low = zs.select_model(0.5, "e", 1e-14, table=fakes)
    assert low.model == "exact" and "not reached" in low.reason
    out = zs.select_model(3.5, "e", 1e-1, table=fakes)
    assert "outside the measured range" in out.reason


def test_unregistered_and_out_of_bound_models_are_skipped(fakes, monkeypatch):
    monkeypatch.delitem(REGISTRY, "cheap")
    assert zs.select_model(0.5, "e", 1e-3, table=fakes).model == "mid"
    monkeypatch.setitem(REGISTRY, "mid", Perturbed("mid", 1e-6, lam_bound=0.4))
    sel = zs.select_model(0.5, "e", 1e-3, table=fakes)
    assert sel.model == "exact" and "beyond its bound" in sel.reason


def test_all_needs_every_quantity(fakes):
    fakes["models"]["mid"]["envelopes"]["xi"] = [None, None, None]
    assert zs.select_model(0.5, "all", 1e-3, table=fakes).model == "cheap"
    assert zs.select_model(0.5, "all", 1e-5, table=fakes).model == "exact"
    assert zs.select_model(0.5, "tau_d", 1e-5, table=fakes).model == "mid"


def test_aliases(fakes):
    assert zs.select_model(0.5, "e", 1e-5, table=fakes).model == "mid"
    assert zs.select_model(0.5, "force", 1e-3, table=fakes).model == "cheap"


@pytest.mark.parametrize("kw,msg", [
    (dict(rtol=0.0), "rtol must be"), (dict(rtol=math.nan), "rtol must be"),
    (dict(rtol=-1e-3), "rtol must be"), (dict(quantity="colour"), "unknown quantity"),
])
def test_bad_arguments(fakes, kw, msg):
    args = dict(quantity="e", rtol=1e-3, table=fakes)
    args.update(kw)
    with pytest.raises(ValueError, match=msg):
        zs.select_model(0.5, **args)


def test_bad_lambda(fakes):
    with pytest.raises(ValueError, match="lambda"):
        zs.select_model(-1.0, "e", 1e-3, table=fakes)
    with pytest.raises(ValueError, match="scalar"):
        zs.select_model([0.1, 0.2], "e", 1e-3, table=fakes)


def test_scene_summary_uses_the_selection(fakes, monkeypatch):
    monkeypatch.setattr(envelopes, "load", lambda where=None: fakes)
    sc = zs.Scene("table1-sphere", "table1-plate", 0.9e-3, 0.5e-3, 1.0)  # lambda 0.163
    loose = sc.result(rtol=1e-2)
    tight = sc.result(rtol=1e-5)
    assert (loose.model, tight.model) == ("cheap", "mid")
    assert "cheapest qualifying" in loose.reason
    # the perturbed model's error shows up in the dimensional result as constructed
    assert loose.contact_duration_s / tight.contact_duration_s == pytest.approx(
        (1 + 1e-3) / (1 + 1e-6), rel=1e-9)


def test_committed_table_is_well_formed():
    t = envelopes.load()
    assert t["schema"] == envelopes.SCHEMA
    assert "exact" in t["models"]
    assert set(t["quantities"]) == set(envelopes.QUANTITIES)
    ranks = sorted(m["cost_rank"] for m in t["models"].values())
    assert ranks == list(range(len(ranks)))
    for m in t["models"].values():
        for q, row in m["envelopes"].items():
            assert len(row) == len(t["intervals"])
    # exact's measured error is tiny on the whole table range
    ex = t["models"]["exact"]["envelopes"]
    assert max(max(r) for r in ex.values()) < 1e-5


def test_never_returns_a_model_that_refuses_the_lambda():
    from zener_sym.models import REGISTRY

    chosen = set()
    for lam in (0.0, 1e-5, 0.3, 2.44, 2.5, 9.9, 10.0, 50.0, 1000.0):
        for q in ("all", "e", "F_m", "xi", "force"):
            for rtol in (1e-12, 1e-3, 0.5):
                m = zs.select_model(lam, q, rtol).model
                bound = REGISTRY[m].lam_bound
                assert bound is None or lam < bound, (lam, q, rtol, m)
                chosen.add((lam, m))
    for lam, m in chosen:
        zs.summary(lam, model=m)  # accepted


def test_outside_every_range_is_an_error_that_says_the_range():
    with pytest.raises(ValueError, match=r"lambda = 2000 .*exact model's range \(0 <= lambda "
                                         r"<= 1000\)"):
        zs.select_model(2000, "e", 1e-3)


def test_rejection_says_what_a_model_lacks():
    sel = zs.select_model(0.05, "e", 1e-12)
    assert "reed: gives no e" in sel.reason and "no measured envelope" not in sel.reason


def test_thick_plate_xi_judged_by_absolute_error_lets_hertz_qualify():
    # Hertz neglects the loss: its xi is 0, a 100% relative error at every lambda > 0, but
    # an absolute error of xi_exact, tiny on a thick plate (lambda 1e-5)
    from zener_sym.scene import envelopes

    table = envelopes.load()
    no_exact = dict(table, models={k: v for k, v in table["models"].items() if k != "exact"})
    assert zs.select_model(1e-5, "xi", 1e-3, table=no_exact).model in ("hertz", "oneway")
    assert zs.select_model(1e-5, "all", 1e-3, table=no_exact).model == "hertz"
    assert zs.summary(1e-5).xi < 1e-3  # the claim the table records, from the exact model
