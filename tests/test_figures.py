"""The paper's Figs. 3-15: each builds, its data agrees with the API, the committed CSVs are
fresh, and bad input is refused with nothing written."""
from pathlib import Path

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.cli import main
from zener_sym.figures import data as D
from zener_sym.figures import make

DOCS = Path(__file__).resolve().parents[1] / "docs" / "figures"

#: figure -> {panel: summary field} for the figures that plot a summary quantity against lambda
SUMMARY_FIELDS = {6: {"": "F_m"}, 7: {"": "tau_d"}, 8: {"compression": "tau_dc",
                  "recovery": "tau_dr"}, 9: {"": "impulse"}, 12: {"": "xi"}, 13: {"": "int_F2"},
                  15: {"": "e"}}
HISTORY_FIELDS = {4: "force", 5: "force", 10: "velocity", 11: "impulse"}


@pytest.fixture(scope="module")
def coarse_rows():
    return {n: D.from_csv(D.to_csv(spec.compute(True))) for n, spec in D.FIGURES.items()}


def _by_series(rows):
    out = {}
    for p, s, x, y, e in rows:
        out.setdefault((p, s), []).append((x, y, e))
    return {k: np.array([(x, y, np.nan if e is None else e) for x, y, e in v]) for k, v in out.items()}


def test_every_figure_builds_on_a_coarse_grid(tmp_path):
    pytest.importorskip("matplotlib")
    lines = []
    written = make.build(tmp_path, formats=("png",), coarse=True, log=lines.append)
    assert len(lines) == len(D.NUMBERS) == 13
    for n in D.NUMBERS:
        for ext in ("csv", "png"):
            p = tmp_path / f"fig{n:02d}.{ext}"
            assert p in written and p.stat().st_size > 300
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no temp left


@pytest.mark.parametrize("number", sorted(SUMMARY_FIELDS))
def test_summary_csv_agrees_with_the_api(coarse_rows, number):
    for (panel, series), arr in _by_series(coarse_rows[number]).items():
        x, y, err = arr.T
        api = getattr(zs.summary(x, model=series), SUMMARY_FIELDS[number][panel])
        assert np.allclose(y, api, rtol=1e-9, atol=1e-12), (panel, series)
        if series != "exact":
            ref = getattr(zs.summary(x), SUMMARY_FIELDS[number][panel])
            assert np.allclose(err, np.abs(api - ref) / np.abs(ref), rtol=1e-6, atol=1e-12)


@pytest.mark.parametrize("number", sorted(HISTORY_FIELDS))
def test_history_csv_agrees_with_the_api(coarse_rows, number):
    lams = dict(zip(D.FIGURES[number].panels, D.HISTORY_LAMS)) if number != 4 else {"": 0.0}
    for (panel, series), arr in _by_series(coarse_rows[number]).items():
        tau, y, _ = arr.T
        h = zs.history(lams[panel], tau, model=series)
        # tau is written with 10 digits: the history at the written tau agrees to about 1e-10
        assert np.allclose(y, getattr(h, HISTORY_FIELDS[number]), rtol=1e-8, atol=1e-9)


def test_fig03_and_fig14_against_their_sources(coarse_rows):
    s = _by_series(coarse_rows[3])
    x, y, _ = s[("", "exact")].T
    assert np.allclose(y, zs.summary(x).delta_m ** -1.5, rtol=1e-9)
    assert x.max() == 100.0
    x, y, _ = s[("", "fits")].T
    assert np.allclose(y, x + 1.25 ** -0.6, rtol=1e-9)  # Eq. (24)
    for H in D.FIG14_THICKNESS:
        rows = _by_series(coarse_rows[14])
        panel = f"H={H * 1e3:.3g} mm"
        v0, xi, _ = rows[(panel, "exact")].T
        lam = [zs.Scene(zs.TABLE1_SPHERE, zs.TABLE1_PLATE, D.TABLE1_RADIUS, H, v).lam for v in v0]
        assert np.allclose(xi, zs.summary(np.array(lam)).xi, rtol=1e-9)
        # energy balance: xi = 2 lambda int F^2 (an identity of Eq. 10)
        assert np.allclose(xi, 2 * np.array(lam) * zs.summary(np.array(lam)).int_F2, rtol=1e-8)


def test_committed_csvs_are_fresh():
    """Regenerates every figure's data and compares it with docs/figures/*.csv within
    make.RTOL (1e-8) / make.ATOL; run 'zener-sym figures --out docs/figures' to refresh."""
    bad = make.stale(DOCS)
    assert not bad, "\n".join(f"{k}: {v[:5]}" for k, v in bad.items())


def test_compare_csv_reports_a_change():
    rows = D.FIGURES[15].compute(True)
    text = D.to_csv(rows)
    assert make.compare_csv(text, text) == []
    changed = [r if i != 3 else (r[0], r[1], r[2], r[3] * (1 + 1e-6), r[4]) for i, r in enumerate(rows)]
    assert make.compare_csv(text, D.to_csv(changed))


@pytest.mark.parametrize("argv, says", [
    (["--only", "99"], "allowed: 3, 4, 5"),
    (["--only", "five"], "allowed: 3, 4, 5"),
    (["--format", "gif"], "allowed: png, pdf, svg"),
])
def test_bad_input_exits_2_with_one_line(tmp_path, capsys, argv, says):
    out = tmp_path / "out"
    assert main(["figures", "--out", str(out), *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert says in err and "\n" not in err
    assert not out.exists() or not list(out.iterdir())


def test_cli_writes_the_formats_asked_for(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    assert main(["figures", "--out", str(tmp_path), "--only", "15", "--format", "svg,pdf"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig15.csv", "fig15.pdf", "fig15.svg"]
    assert "fig15" in capsys.readouterr().out


def test_unwritable_out_exits_2(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    assert main(["figures", "--out", str(blocker / "sub"), "--only", "15"]) == 2
    err = capsys.readouterr().err.strip()
    assert "not a writable directory" in err and "\n" not in err


def test_failure_midway_leaves_nothing(tmp_path, monkeypatch):
    calls = []

    def boom(coarse):
        calls.append(1)
        raise RuntimeError("boom")

    monkeypatch.setattr(D.FIGURES[6], "compute", boom)
    with pytest.raises(RuntimeError):
        make.build(tmp_path, only=(3, 6), csv_only=True, coarse=True, log=lambda s: None)
    assert calls and list(tmp_path.iterdir()) == []
