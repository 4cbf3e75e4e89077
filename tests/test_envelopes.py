"""bench.envelopes.build measures what it claims: known perturbations come out as their size;
scene.envelopes reads and compares the table."""
import pytest

from zener_sym.bench.envelopes import build
from zener_sym.scene import envelopes
from zener_sym.models import REGISTRY

from _fake_models import Perturbed

SMALL = [(0.0, 0.5), (0.5, 1.0), (1.0, 2.5)]


@pytest.fixture
def built(monkeypatch):
    monkeypatch.setitem(REGISTRY, "slowfake", Perturbed("slowfake", 2e-4, lam_bound=2.0,
                                                        sleep=0.02))
    return build(models=["exact", "slowfake"], intervals=SMALL, points_per_interval=2,
                           repeats=1, cost_lams=(0.1, 1.0))


def test_known_error_is_measured(built):
    env = built["models"]["slowfake"]["envelopes"]
    for q in ("tau_d", "F_m", "delta_m", "e", "force_history", "impulse_history"):
        assert env[q][:2] == [pytest.approx(2e-4, rel=1e-6)] * 2, q
    # not valid on the whole last interval (bound 2.0 < 2.5): not measured there
    assert all(env[q][2] is None for q in env)
    ex = built["models"]["exact"]["envelopes"]
    assert max(v for row in ex.values() for v in row) < 1e-6


def test_cost_rank_is_measured(built):
    # the stand-in is exact plus a 20 ms sleep per call: it must rank after exact
    assert built["models"]["exact"]["cost_rank"] == 0
    assert built["models"]["slowfake"]["cost_rank"] == 1


def test_compare_detects_stale_tables(built, tmp_path):
    assert envelopes.compare(built, built) == []
    import copy

    old = copy.deepcopy(built)
    old["models"]["slowfake"]["envelopes"]["tau_d"][0] = 2e-2
    assert any("slowfake.tau_d[0]" in d for d in envelopes.compare(old, built))
    del old["models"]["slowfake"]
    assert any("models differ" in d for d in envelopes.compare(old, built))
    p = envelopes.save(built, tmp_path / "e.json")
    assert envelopes.load(p) == built


@pytest.mark.slow
def test_committed_table_is_up_to_date():
    """The committed table matches a fresh measurement (regenerate: zener-sym envelopes)."""
    assert envelopes.compare(envelopes.load(), build()) == []
