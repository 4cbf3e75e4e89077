"""zs.compare: models side by side, errors against exact computed independently here."""
from __future__ import annotations

import math

import pytest

import zener_sym as zs


def test_rows_and_errors_match_separate_summaries():
    c = zs.compare(0.8)
    assert [r.model for r in c][0] == "exact"
    ex = zs.summary(0.8)
    for row in c:
        s = zs.summary(0.8, model=row.model)
        for q in c.quantities:
            if q in s.fields:
                assert getattr(row, q) == getattr(s, q)
                ref = getattr(ex, q)
                want = 0.0 if getattr(s, q) == ref else abs(getattr(s, q) / ref - 1)
                assert row.errors[q] == pytest.approx(want, rel=1e-12, abs=1e-300)
            else:  # absent, not an error
                assert q not in row.values
                with pytest.raises(AttributeError, match=f"gives no '{q}'"):
                    getattr(row, q)


def test_default_models_are_those_accepting_lambda():
    names = [r.model for r in zs.compare(1.0)]
    assert "oneway" not in names  # its bound is 0.289
    assert "oneway" in [r.model for r in zs.compare(0.1)]
    assert "ham1" not in [r.model for r in zs.compare(3.0)]


def test_scene_comparison_uses_si_fields():
    sc = zs.Scene("steel", "glass", radius="2.5 mm", thickness="2 mm", drop_height="0.5 m")
    c = zs.compare(sc, models=["ham1"], quantities=["contact_duration_s", "e"])
    ex = sc.result(model="exact")
    assert c["exact"].contact_duration_s == ex.contact_duration_s
    h = sc.result(model="ham1")
    assert c["ham1"].errors["e"] == pytest.approx(abs(h.e / ex.e - 1), rel=1e-12)
    assert "contact_duration_s [s]" in c.to_markdown()


def test_markdown_csv_and_pandas(tmp_path):
    c = zs.compare(0.1, models=["hunter"], quantities=["e", "F_m"])
    md = c.to_markdown()
    assert "| hunter | — |" in md  # hunter gives no e: shown absent
    path = c.to_csv(tmp_path / "c.csv")
    lines = path.read_text().splitlines()
    assert lines[0] == "model,e,e_rel_error,F_m,F_m_rel_error"
    assert lines[2].startswith("hunter,,,")
    pd = pytest.importorskip("pandas")
    df = c.to_pandas()
    assert list(df.index) == ["exact", "hunter"] and math.isnan(df.loc["hunter", "e"])
    assert isinstance(df, pd.DataFrame)


@pytest.mark.parametrize("bad,msg", [
    ([1.0, 2.0], "one lambda"), ("1", "one lambda"), (-1.0, ">= 0"), (math.nan, "finite"),
])
def test_bad_input(bad, msg):
    with pytest.raises(ValueError, match=msg):
        zs.compare(bad)


def test_unknown_names():
    with pytest.raises(ValueError, match="unknown quantity 'speed'; allowed: delta_m"):
        zs.compare(1.0, quantities=["speed"])
    with pytest.raises(ValueError, match="unknown model 'x'"):
        zs.compare(1.0, models="x")


def test_unwritable_csv_is_a_value_error(tmp_path):
    with pytest.raises(ValueError, match="cannot write"):
        zs.compare(0.5, models=["hertz"]).to_csv(tmp_path / "missing" / "c.csv")
