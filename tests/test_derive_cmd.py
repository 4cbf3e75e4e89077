"""``zener-sym derive``, FORMULAS.md freshness and determinism, the report section, and the rule
that the runtime path never imports the derivation."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def test_runtime_path_does_not_import_derivation():
    code = ("import sys, zener_sym as zs; zs.summary(1.0, model='exact'); "
            "bad = [m for m in sys.modules if m.startswith('zener_sym.derivation')]; "
            "print(bad); sys.exit(1 if bad else 0)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def test_cli_has_derive():
    from zener_sym import cli

    assert cli.derive in cli.COMMANDS
    p = cli.build_parser()
    args = p.parse_args(["derive", "--check"])
    assert args.check and not args.markdown


def test_repo_root_refuses_outside_checkout(monkeypatch, tmp_path):
    from zener_sym.derivation import formulas

    fake = tmp_path / "site-packages" / "zener_sym" / "derivation" / "formulas.py"
    fake.parent.mkdir(parents=True)
    monkeypatch.setattr(formulas, "__file__", str(fake))
    with pytest.raises(RuntimeError, match="source checkout"):
        formulas.repo_root()


@pytest.mark.slow
def test_formulas_md_is_fresh():
    from zener_sym.derivation import formulas
    from zener_sym.derivation.registry import derive

    fresh, diff = formulas.check(derive(), ROOT)
    assert fresh, diff


@pytest.mark.slow
def test_stale_formulas_fails_with_diff(monkeypatch, tmp_path):
    from zener_sym.derivation import formulas
    from zener_sym.derivation.registry import derive

    stale = tmp_path / "FORMULAS.md"
    stale.write_text(formulas.render(derive()).replace("(35)", "(135)"))
    monkeypatch.setattr(formulas, "formulas_path", lambda root=None: stale)
    fresh, diff = formulas.check(derive(), ROOT)
    assert not fresh and "-### (135)" in diff and "+### (35)" in diff


@pytest.mark.slow
def test_cli_check_under_another_hash_seed():
    # determinism: a fresh process with a different PYTHONHASHSEED renders the same bytes
    env = dict(os.environ, PYTHONHASHSEED="4242")
    r = subprocess.run([sys.executable, "-m", "zener_sym", "derive", "--check"], capture_output=True,
                       text=True, env=env, cwd=ROOT)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    assert "FORMULAS.md is up to date" in r.stdout
    assert "[FAIL]" not in r.stdout


@pytest.mark.slow
def test_report_section(tmp_path):
    from zener_sym.report import build as report

    names = [n for n, _ in report.SECTIONS]
    assert "derivation" in names
    text = dict(report.SECTIONS)["derivation"](tmp_path)
    assert "every step passed" in text and "2.4424389" in text
