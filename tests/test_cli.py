"""The command line refuses what it cannot mean: one line on stderr, exit code 2."""
from __future__ import annotations

import subprocess
import sys

import pytest

import zener_sym as zs
from zener_sym import cli
from zener_sym.cli import _checkout

SCENE = ["scene", "--sphere", "steel", "--plate", "glass", "--radius", "1mm", "--thickness",
         "2mm", "--v0", "1m/s"]


def _with(argv, option, value):
    out = list(argv)
    i = out.index(option)
    out[i + 1] = value
    return out


def test_version(capsys):
    assert cli.main(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"zener-sym {zs.__version__}"


def test_version_matches_the_distribution():
    from importlib.metadata import version

    assert version("zener-sym") == zs.__version__


@pytest.mark.parametrize("option,value,message", [
    ("--radius", "1", "--radius 1: give a unit, e.g. 1mm or 0.001m"),
    ("--thickness", "2", "--thickness 2: give a unit"),
    ("--v0", "3", "--v0 3: give a unit, e.g. 3m/s"),
    ("--radius", "-1mm", "--radius must be finite and > 0"),
    ("--radius", "-.5mm", "--radius must be finite and > 0"),
    ("--radius", "1e300m", "outside the plausible range"),
    ("--radius", "1e-300m", "outside the plausible range"),
    ("--radius", "1 parsec", "unknown length unit 'parsec'"),
])
def test_scene_options_need_units_and_sane_values(capsys, option, value, message):
    assert cli.main(_with(SCENE, option, value)) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1, err


def test_yield_without_unit_is_refused(capsys):
    assert cli.main(SCENE + ["--plate-yield", "250"]) == 2
    assert "--plate-yield 250: give a unit" in capsys.readouterr().err


def test_drop_height_gives_the_free_fall_speed(capsys):
    argv = [a for a in SCENE if a not in ("--v0", "1m/s")] + ["--drop-height", "0.5m"]
    assert cli.main(argv) == 0
    assert "3.13156 m/s" in capsys.readouterr().out  # sqrt(2 * 9.80665 * 0.5)
    assert cli.main(SCENE + ["--drop-height", "0.5m"]) == 2  # both
    assert "not allowed with argument" in capsys.readouterr().err


@pytest.mark.parametrize("path,message", [
    ("/nonexistent-folder/f.png", "does not exist or is not writable"),
    ("force.bmpx", "give a file name ending in .png, .pdf, .svg"),
])
def test_bad_plot_path_refused_before_work(capsys, path, message):
    assert cli.main(SCENE + ["--plot", path]) == 2
    assert message in capsys.readouterr().err


def test_unknown_enumerated_value_lists_the_allowed(capsys):
    assert cli.main(["report", "--skip", "benchmark"]) == 2
    err = capsys.readouterr().err
    assert "invalid choice: 'benchmark'" in err and "'bench'" in err and err.count("\n") == 1


def test_commands_needing_a_checkout_say_so_up_front(monkeypatch, tmp_path, capsys):
    monkeypatch.delenv(_checkout.ENV)
    fake = tmp_path / "site-packages" / "zener_sym" / "cli" / "_checkout.py"
    fake.parent.mkdir(parents=True)
    monkeypatch.setattr(_checkout, "__file__", str(fake))
    for argv in (["audit", "--check"], ["derive", "--check"], ["regen", "kernels"],
                 ["regen", "--check", "kernels"], ["regen", "--check", "ham-convergence"],
                 ["regen", "exact-table"], ["regen", "ham1-table"], ["regen", "audit"]):
        assert cli.main(argv) == 2, argv
        err = capsys.readouterr().err
        assert "needs a source checkout" in err and "pip install -e ." in err, err


def test_checkout_named_by_environment_must_be_one(monkeypatch, tmp_path, capsys):
    monkeypatch.setenv(_checkout.ENV, str(tmp_path))
    assert cli.main(["regen", "--check", "kernels"]) == 2
    assert "is not a zener-sym source checkout" in capsys.readouterr().err


#: The older rebuild commands -> the regen call that replaces them (hidden, deprecated).
ALIASES = {("generate",): "regen kernels formulas",
           ("generate", "--check"): "regen --check kernels formulas",
           ("exact-table",): "regen exact-table exact-force-table",
           ("exact-table", "--check", "--contact-end", "force"): "regen --check exact-force-table",
           ("ham1-table", "--check"): "regen --check ham1-table",
           ("envelopes",): "regen envelopes",
           ("ham-convergence", "--check"): "regen --check ham-convergence",
           ("audit", "--write"): "regen audit"}


def test_regen_is_the_one_rebuild_command_in_the_help(capsys):
    assert cli.main(["--help"]) == 0
    out = capsys.readouterr().out
    assert "  regen " in out
    for name in ("generate", "exact-table", "ham1-table", "envelopes", "ham-convergence"):
        assert f"  {name} " not in out and f"  {name}\n" not in out, name
    assert cli.main(["audit", "--help"]) == 0
    out = capsys.readouterr().out
    assert "--check" in out and "--write" not in out


#: command -> (its module in zener_sym.cli, the body its parser calls)
BODIES = {"generate": ("generate", "run"), "exact-table": ("exact_table", "run"),
          "ham1-table": ("ham1_table", "run"), "envelopes": ("envelopes", "_run"),
          "ham-convergence": ("ham_convergence", "_run")}


@pytest.mark.parametrize("argv", list(ALIASES), ids=" ".join)
def test_the_older_commands_say_which_regen_call_replaces_them(argv, monkeypatch, tmp_path,
                                                                capsys):
    """Each prints the note on stderr, then runs its own body (stubbed here: the real work is
    regen's, tested there; audit --write stops at once without a checkout)."""
    import importlib

    called = []
    if argv[0] in BODIES:
        module, body = BODIES[argv[0]]
        monkeypatch.setattr(importlib.import_module(f"zener_sym.cli.{module}"), body,
                            lambda *a, **k: called.append((a, k)) or 0)
        assert cli.main(list(argv)) == 0 and len(called) == 1
    else:
        monkeypatch.delenv(_checkout.ENV)
        fake = tmp_path / "site-packages" / "zener_sym" / "cli" / "_checkout.py"
        fake.parent.mkdir(parents=True)
        monkeypatch.setattr(_checkout, "__file__", str(fake))
        assert cli.main(list(argv)) == 2
    err = capsys.readouterr().err
    name = "audit --write" if argv[0] == "audit" else argv[0]
    assert err.startswith(f"zener-sym {name}: deprecated, use `zener-sym {ALIASES[argv]}` "
                          "instead"), err


def test_the_readme_command_table_is_the_help(capsys):
    """README's command table lists the commands --help lists, no hidden one."""
    import re

    from conftest import ROOT

    assert cli.main(["--help"]) == 0
    listed = set(re.findall(r"^    ([a-z][a-z0-9-]*)", capsys.readouterr().out, re.MULTILINE))
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    table = readme.split("## Command line", 1)[1].split("\n\n", 2)[2].split("\n\n", 1)[0]
    rows = set(re.findall(r"^\| `([a-z][a-z0-9-]*)", table, re.MULTILINE))
    assert rows == listed


def test_an_older_command_still_works(capsys):
    """ham1-table --check (a second's rebuild) on the committed table: 0, as regen gives."""
    assert cli.main(["ham1-table", "--check"]) == 0
    captured = capsys.readouterr()
    assert "deprecated, use `zener-sym regen --check ham1-table`" in captured.err
    assert "is up to date" in captured.out


def test_compare_command(capsys, tmp_path):
    out = tmp_path / "c.csv"
    assert cli.main(["compare", "--lam", "0.5", "--models", "ham1,hertz", "--quantities",
                     "e,tau_d", "--csv", str(out)]) == 0
    text = capsys.readouterr().out
    assert "| exact |" in text and "| ham1 |" in text and "| hertz |" in text
    assert out.read_text().splitlines()[0] == "model,e,e_rel_error,tau_d,tau_d_rel_error"
    assert cli.main(["compare", "--lam", "-1"]) == 2
    assert "lambda must be >= 0" in capsys.readouterr().err
    assert cli.main(["compare", "--lam", "1", "--models", "nope"]) == 2
    assert "unknown model 'nope'; allowed:" in capsys.readouterr().err


def test_python_m_entry_point():
    r = subprocess.run([sys.executable, "-m", "zener_sym", "--version"], capture_output=True,
                       text=True)
    assert r.returncode == 0 and r.stdout.strip() == f"zener-sym {zs.__version__}"
