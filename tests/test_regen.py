"""``zener-sym regen``: the registry of artefacts lists, checks and rebuilds every committed
artefact, and its check fails when any one of them is stale.

The staleness tests work on a temporary copy of an artefact's committed files: the artefact's
fresh texts are taken to be the committed ones (its builder is monkeypatched: no rebuild), the
check passes, then one number in the copy is changed and the same check must fail. The two
tables are checked against their real builders (the ham1 table builds in a second; the exact
table in a minute, marked slow).
"""
from __future__ import annotations

import re
import shutil

import numpy as np
import pytest

from zener_sym import artefacts, cli
from zener_sym.cli import regen

from conftest import ROOT

TABLES = ("exact-table", "exact-force-table", "ham1-table")
#: A number as the artefacts print them (decimal point or exponent).
_NUMBER = re.compile(r"(?<![\w.])\d+\.\d+(?:e[-+]?\d+)?|(?<![\w.])\d+e[-+]?\d+")


def _committed(art, root) -> dict:
    """The committed texts of the files ``art`` checks (its fresh texts' paths)."""
    out = {}
    for pattern in art.paths:
        if pattern.endswith(".png"):
            continue  # charts are written, not checked
        for p in sorted(root.glob(pattern)):
            out[str(p.relative_to(root))] = p.read_text(encoding="utf-8")
    return out


def _copy(art, tmp_path) -> dict:
    texts = _committed(art, ROOT)
    assert texts, f"{art.name}: no committed file matches {art.paths}"
    for rel, text in texts.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text, encoding="utf-8")
    return texts


def _perturb(text: str) -> str:
    """``text`` with its middle number x replaced by 10 x + 1 (beyond every tolerance of a
    check, also for values below a check's noise floor)."""
    found = list(_NUMBER.finditer(text))
    m = found[len(found) // 2]
    return text[:m.start()] + repr(float(m.group()) * 10 + 1) + text[m.end():]


def test_list_names_every_artefact(capsys):
    assert cli.main(["regen", "--list"]) == 0
    out = capsys.readouterr().out
    for a in artefacts.ARTEFACTS:
        assert a.name in out and a.paths[0] in out
    assert len(set(artefacts.names())) == len(artefacts.ARTEFACTS)


def test_kernels_artefact_lists_every_file_codegen_writes():
    from zener_sym import codegen

    assert set(artefacts.get("kernels").paths) == {f"generated/{n}" for n, _ in codegen.BUILDERS}


def test_unknown_name_is_a_usage_error(capsys):
    assert cli.main(["regen", "--check", "kernel"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "unknown artefact 'kernel'" in err and "kernels" in err


@pytest.mark.parametrize("name", [n for n in artefacts.names() if n not in TABLES])
def test_check_fails_when_the_artefact_is_stale(name, tmp_path, monkeypatch):
    art = artefacts.get(name)
    texts = _copy(art, tmp_path)
    fake = artefacts.Artefact(art.name, art.about, art.paths, lambda root: dict(texts), art.same,
                              art.write, art.needs_checkout, art.alias)
    assert artefacts.check(fake, tmp_path) == []
    rel = sorted(texts)[-1]
    (tmp_path / rel).write_text(_perturb(texts[rel]), encoding="utf-8")
    problems = artefacts.check(fake, tmp_path)
    assert problems, f"{name}: a changed number in {rel} went unnoticed"
    (tmp_path / rel).unlink()
    assert artefacts.check(fake, tmp_path) == [f"{rel} is missing"]


def _table_stale(name, tmp_path, capsys):
    art = artefacts.get(name)
    texts = _copy(art, tmp_path)
    assert artefacts.check(art, tmp_path) == []
    (rel, text), = texts.items()
    # a coefficient deep inside the table: the numeric comparison must see it
    (tmp_path / rel).write_text(_perturb(text), encoding="utf-8")
    assert artefacts.check(art, tmp_path)
    # the inputs hash alone (the builder's sources changed, the numbers did not)
    (tmp_path / rel).write_text(re.sub(r"INPUTS_HASH = '(\w+)'", "INPUTS_HASH = 'x'", text))
    assert any("inputs hash x" in p for p in artefacts.check(art, tmp_path))


def test_ham1_table_check_fails_when_stale(tmp_path, capsys):
    _table_stale("ham1-table", tmp_path, capsys)


def test_table_check_compares_the_text_too(tmp_path):
    """A table's check compares its rendered text, numbers masked: a text-only drift (a stale
    comment, as generated/exact_table.py once named ``table_build.parse_array`` after the
    function had moved) fails it; a number moved within the check's tolerance, or a series of
    another length (trimmed otherwise on another machine), does not."""
    art = artefacts.get("ham1-table")
    (rel, text), = _copy(art, tmp_path).items()
    assert artefacts.check(art, tmp_path) == []
    drifted = text.replace("#: field -> one tuple of Chebyshev",
                           "#: field -> one tuple of Legendre")
    assert drifted != text
    (tmp_path / rel).write_text(drifted, encoding="utf-8")
    problems = artefacts.check(art, tmp_path)
    assert problems[0] == f"{rel}: its text differs from a fresh rendering (numbers masked):"
    assert "-#: field -> one tuple of Legendre coefficients per lambda piece" in problems
    # within the tolerance: the last digit of one coefficient, and one trailing coefficient more
    m = re.search(r"\((-?\d\.\d{16})(\d)(, )", text)
    end = text.index(",)", m.end())
    nudged = (text[:m.start(2)] + str((int(m.group(2)) + 1) % 10) + text[m.end(2):end] + ", 0"
              + text[end:])
    (tmp_path / rel).write_text(nudged, encoding="utf-8")
    assert artefacts.check(art, tmp_path) == []
    assert artefacts.text_skeleton(nudged) == artefacts.text_skeleton(text)


def _builds(monkeypatch, hb, tables):
    """Make the ham1 table's builder (``hb.BUILDER``, which ``artefacts`` reads when it runs)
    build ``tables``, as a machine whose rebuild gives them."""
    import dataclasses

    from zener_sym.numerics.cheb_table_build import TableBuilder

    class Fixed(TableBuilder):
        def build(self):
            return tables

    b = hb.BUILDER
    monkeypatch.setattr(hb, "BUILDER", Fixed(**{f.name: getattr(b, f.name)
                                                 for f in dataclasses.fields(b)}))


def test_regen_keeps_committed_numbers_that_agree(tmp_path, monkeypatch):
    """``zener-sym regen TABLE`` on a machine whose rebuild differs from the committed numbers
    by rounding (another processor, another libm) writes the committed file byte for byte; a
    rebuild beyond the check's tolerance is written as built."""
    from zener_sym.ham import table_build as hb

    art = artefacts.get("ham1-table")
    (rel, text), = _copy(art, tmp_path).items()
    real = hb.build_tables()

    def nudged(by):
        return {**real, "summary": {k: [c * (1.0 + by) for c in v]
                                    for k, v in real["summary"].items()}}

    _builds(monkeypatch, hb, nudged(1e-13))
    assert artefacts.build(art, tmp_path) == []  # nothing written: the committed bytes stay
    assert (tmp_path / rel).read_text(encoding="utf-8") == text
    _builds(monkeypatch, hb, nudged(1e-9))
    assert artefacts.build(art, tmp_path) == [tmp_path / rel]
    assert (tmp_path / rel).read_text(encoding="utf-8") == hb.render(nudged(1e-9))
    assert artefacts.check(art, tmp_path) == []


@pytest.mark.parametrize("rebuild", ["this machine's", "the committed table's"])
def test_regen_keeps_the_committed_trimming(rebuild, tmp_path, monkeypatch):
    """A rebuild that trims a series at another length (a trailing coefficient near the trimming
    level falls on the other side of it on another processor: the force table's corner
    sub-piece once did on AVX-512 machines) still writes the committed file byte for byte: the
    comparison pads the shorter series with zeros, so the lengths differ by what the trimming
    level allows, within the check's tolerance.

    The lengths are set against the committed table, not against this machine's rebuild, so the
    precondition holds on every processor: one series a coefficient longer than committed (below
    the trimming level), two others a coefficient shorter (their committed last coefficient within
    the check's tolerance of zero). (It once chose the lengthened series to shorten, which undid
    the change wherever the rebuild equals the committed text, as on AMD EPYC machines: the second
    case starts from the committed numbers, the rebuild of a processor that reproduces them.)"""
    from zener_sym.generated import ham1_table
    from zener_sym.ham import table_build as hb

    art = artefacts.get("ham1-table")
    (rel, text), = _copy(art, tmp_path).items()
    committed = hb.as_tables(vars(ham1_table))["summary"]
    real = hb.build_tables() if rebuild == "this machine's" else hb.as_tables(vars(ham1_table))
    assert rebuild == "this machine's" or hb.render(real) == text

    def at_length(c, n):  # this machine's series at n coefficients (a missing one is trimmed: 0)
        c = np.asarray(c, dtype=float)
        return np.concatenate([c[:n], np.zeros(max(0, n - len(c)))])

    out = {k: [np.asarray(c, dtype=float) for c in v] for k, v in real["summary"].items()}
    first = next(iter(out))
    stored = np.asarray(committed[first][0], dtype=float)
    # one series a coefficient longer than committed (below the trimming level)
    out[first][0] = np.append(at_length(out[first][0], len(stored)),
                              0.5 * hb.TRIM * np.abs(stored).max())
    # others a coefficient shorter than committed: their committed last coefficient is within the
    # check's tolerance of zero (not the series lengthened above)
    shortened = [(k, p) for k, v in committed.items() for p, c in enumerate(v)
                 if (k, p) != (first, 0) and len(c) > 1
                 and abs(c[-1]) < 0.5 * hb.CHECK_RTOL * np.abs(np.asarray(c, dtype=float)).max()]
    assert shortened, "no committed series ends in a coefficient the check can drop"
    for k, p in shortened[:2]:
        out[k][p] = at_length(out[k][p], len(committed[k][p]) - 1)
    fresh = {**real, "summary": out}

    # the precondition, by construction: the lengths differ from the committed ones both ways
    assert len(fresh["summary"][first][0]) == len(stored) + 1
    assert all(len(fresh["summary"][k][p]) == len(committed[k][p]) - 1 for k, p in shortened[:2])
    assert hb.render(fresh) != text  # the rebuild's own text differs from the committed one
    _builds(monkeypatch, hb, fresh)
    assert artefacts.check(art, tmp_path) == []
    assert artefacts.build(art, tmp_path) == []
    assert (tmp_path / rel).read_text(encoding="utf-8") == text


def test_text_skeleton_masks_numbers_only():
    sk = artefacts.text_skeleton
    assert sk("X = (1.5, -2e-07, 3,)\n# scipy 1.17.1, hash 7b76e73fe6") == sk(
        "X = (2.5,)\n#   scipy 1.16.0, hash 7b76e73fe6")
    assert sk("X = (1.5,)  # ham.chebyshev") != sk("X = (1.5,)  # numerics.elementary")
    assert sk("'5 11 1e-3 0'") == sk("'4 2 7 8 9'") and sk("ham1 = 1") != sk("ham2 = 1")


@pytest.mark.slow
def test_exact_force_table_check_fails_when_stale(tmp_path, capsys):
    # the three exact/ham1 tables share one check (artefacts._table); the plate's table is not
    # rebuilt a second time here (70 s: test_exact_fast rebuilds it), the force end's (15 s) is
    _table_stale("exact-force-table", tmp_path, capsys)


def test_regen_command_reports_a_stale_artefact(tmp_path, monkeypatch, capsys):
    """The command's exit code and message for a stale artefact (the peers table, its builder
    monkeypatched to give the committed text with one number changed)."""
    art = artefacts.get("peers")
    doc = (ROOT / "docs" / "viscoelastic.md").read_text("utf-8")
    fake = artefacts.Artefact(art.name, art.about, art.paths,
                              lambda root: {"docs/viscoelastic.md": _perturb(doc)})
    monkeypatch.setattr(artefacts, "ARTEFACTS", (fake,))
    assert cli.main(["regen", "--check", "peers"]) == 1
    out = capsys.readouterr().out
    assert "peers: STALE" in out and "zener-sym regen peers" in out
    fake = artefacts.Artefact(art.name, art.about, art.paths,
                              lambda root: {"docs/viscoelastic.md": doc})
    monkeypatch.setattr(artefacts, "ARTEFACTS", (fake,))
    assert cli.main(["regen", "--check"]) == 0
    assert "peers: up to date" in capsys.readouterr().out


def test_regen_writes_what_the_builder_gives(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("ZENER_SYM_SOURCE", str(tmp_path))
    for d in ("derivation", "generated", "src/zener_sym"):
        (tmp_path / d).mkdir(parents=True)
    shutil.copy(ROOT / "pyproject.toml", tmp_path / "pyproject.toml")
    fake = artefacts.Artefact("demo", "a demo", ("docs/demo.txt",),
                              lambda root: {"docs/demo.txt": "x = 1\n"})
    monkeypatch.setattr(artefacts, "ARTEFACTS", (fake,))
    assert cli.main(["regen", "demo"]) == 0
    assert (tmp_path / "docs" / "demo.txt").read_text() == "x = 1\n"
    assert cli.main(["regen", "demo"]) == 0
    assert "all unchanged" in capsys.readouterr().out
    assert cli.main(["regen", "--check"]) == 0


#: Where the suite already checks an artefact's freshness (through the older commands or the
#: builders' own comparisons); those are not rebuilt a second time here.
FRESH_ELSEWHERE = {
    "kernels": "test_generate.py", "formulas": "test_generate.py",
    "exact-table": "test_exact_fast.py::test_table_rebuild_agrees_numerically",
    "exact-force-table": "test_exact_force_table.py::test_table_rebuild_agrees_numerically",
    "ham1-table": "test_ham_table.py", "lambda-series": "test_lambda_series.py",
    "envelopes": "test_envelopes.py::test_committed_table_is_up_to_date",
    "ham-convergence": "test_ham_higher.py", "peers": "test_viscoelastic.py",
    "figures": "test_figures.py", "audit": "test_audit.py",
    "plate-criterion": "test_plate_criterion.py::test_rebuilt_cell_matches_the_committed_table",
}


def test_every_artefact_has_a_freshness_test():
    assert set(FRESH_ELSEWHERE) | set(ONLY_HERE) == set(artefacts.names())


ONLY_HERE = [n for n in artefacts.names() if n not in FRESH_ELSEWHERE]


@pytest.mark.slow
@pytest.mark.parametrize("name", ONLY_HERE)
def test_committed_artefact_is_fresh(name):
    """``zener-sym regen --check NAME`` on the tree, for the artefacts no other test checks."""
    problems = artefacts.check(artefacts.get(name), ROOT)
    assert not problems, "\n".join(problems[:40])


def test_every_artefact_is_listed_once_and_can_be_found():
    for a in artefacts.ARTEFACTS:
        assert artefacts.get(a.name) is a
        assert a.paths and all(not p.startswith("/") for p in a.paths)
    with pytest.raises(ValueError, match="allowed: kernels, formulas"):
        artefacts.get("nope")
    assert regen.run(list_only=True, out=lambda *a: None) == 0


def test_artefacts_in_the_repository_need_a_checkout(monkeypatch, tmp_path, capsys):
    """From an installed copy (no checkout), naming an artefact that lives in the repository is a
    usage error said up front, before any work."""
    from zener_sym.cli import _checkout

    monkeypatch.delenv(_checkout.ENV)
    fake = tmp_path / "site-packages" / "zener_sym" / "cli" / "_checkout.py"
    fake.parent.mkdir(parents=True)
    monkeypatch.setattr(_checkout, "__file__", str(fake))
    for argv in (["regen", "--check", "kernels"], ["regen", "audit"], ["regen"]):
        assert cli.main(argv) == 2, argv
        err = capsys.readouterr().err
        assert "needs a source checkout" in err and err.count("\n") == 1, err
