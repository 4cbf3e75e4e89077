"""generate --check: generated/ and FORMULAS.md are fresh, and a stale file is caught with a diff."""
import shutil

from zener_sym import codegen
from zener_sym.cli import generate as generate_cmd
from zener_sym.derivation import formulas

from conftest import ROOT


def test_generated_and_formulas_are_fresh(capsys):
    assert generate_cmd.run(check=True) == 0, capsys.readouterr().out


def test_stale_formulas_fail_with_a_diff(tmp_path, monkeypatch, capsys):
    stale = tmp_path / "FORMULAS.md"
    shutil.copy(formulas.formulas_path(ROOT), stale)
    stale.write_text(stale.read_text().replace("=", "==", 1))
    monkeypatch.setattr(formulas, "formulas_path", lambda root=None: stale)
    assert generate_cmd.run(check=True) == 1
    out = capsys.readouterr().out
    assert "FORMULAS.md is STALE" in out and "+++" in out


def test_stale_generated_file_fails_with_a_diff(fake_tree, monkeypatch, capsys):
    monkeypatch.setattr(codegen, "BUILDERS", [("demo.py", "tests.test_generate:_demo_builder")])
    (fake_tree / "generated" / "demo.py").write_text("x = 2\n")
    assert generate_cmd.run(check=True) == 1
    out = capsys.readouterr().out
    assert "-x = 2" in out and "+x = 1" in out and "STALE" in out


def _demo_builder():
    return "x = 1\n"


def test_check_names_the_tree_it_checked(capsys):
    from conftest import ROOT

    assert generate_cmd.run(check=True) == 0
    assert str(ROOT / "generated") in capsys.readouterr().out
