"""LAMMPS's runs live in one subpackage (``zener_sym.bench.lammps``): what remains of the flat
``bench/lammps_*.py`` modules is a deprecated forwarder each, the artefacts are the subpackage's
``Study`` objects, every file of a LAMMPS artefact is named once in the source, and no name is
built from a string."""
from __future__ import annotations

import ast
import pathlib

from conftest import ROOT
from zener_sym import artefacts
from zener_sym.bench.lammps import publish

SRC = ROOT / "src" / "zener_sym"


def _tree(path: pathlib.Path) -> ast.Module:
    return ast.parse(path.read_text(encoding="utf-8"))


def _literals(tree: ast.Module) -> list[str]:
    """The string constants of a module, docstrings left out (they may name files freely)."""
    docs = {id(n.body[0].value) for n in ast.walk(tree)
            if isinstance(n, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
            and n.body and isinstance(n.body[0], ast.Expr)
            and isinstance(n.body[0].value, ast.Constant)}
    return [n.value for n in ast.walk(tree) if isinstance(n, ast.Constant)
            and isinstance(n.value, str) and id(n) not in docs]


def test_the_flat_modules_only_forward():
    flat = sorted(SRC.glob("bench/lammps_*.py"))
    assert [p.name for p in flat] == ["lammps_charts.py", "lammps_mpi.py", "lammps_run.py",
                                      "lammps_verify.py"]
    for p in flat:
        body = [n for n in _tree(p).body if not (isinstance(n, ast.Expr)
                                                 and isinstance(n.value, ast.Constant))]
        assert len(body) == 2, p.name  # the import of moved() and __getattr__ = moved(...)
        assert ast.unparse(body[1]).startswith("__getattr__ = moved(__name__, 'zener_sym.bench"
                                               ".lammps."), p.name


def test_the_artefacts_are_the_studies():
    for study in publish.STUDIES:
        art = artefacts.get(study.name)
        assert art.paths == study.paths and art.needs_checkout == study.needs_checkout
        assert art.fresh == study.fresh and art.same == study.same
    assert artefacts.get("lammps-docs").paths == (publish.PAGE,)
    assert {a.name for a in artefacts.ARTEFACTS if a.name.startswith("lammps-")} == {
        *(s.name for s in publish.STUDIES), "lammps-docs"}


def _named_twice(names: set[str], modules: dict[str, ast.Module]) -> dict[str, list[str]]:
    """The names that more than one string literal of ``modules`` gives as a path (no
    whitespace: prose that mentions a file does not count), and where."""
    seen: dict[str, list[str]] = {n: [] for n in names}
    for where, tree in modules.items():
        for text in _literals(tree):
            for n in names:
                if n in text and not any(c.isspace() for c in text):
                    seen[n].append(where)
    return {n: where for n, where in seen.items() if len(where) > 1}


def _built_names(tree: ast.Module) -> list[str]:
    """``getattr(module, f"{study}_fresh")`` and the like: a name the reader cannot grep."""
    return [f"{n.lineno}: {ast.unparse(n)}" for n in ast.walk(tree)
            if isinstance(n, ast.Call) and isinstance(n.func, ast.Name)
            and n.func.id in ("getattr", "hasattr", "setattr") and len(n.args) >= 2
            and isinstance(n.args[1], (ast.JoinedStr, ast.BinOp))]


SOURCES = {str(p.relative_to(SRC)): _tree(p) for p in sorted(SRC.rglob("*.py"))}


def test_every_lammps_file_is_named_once():
    names = {pathlib.PurePosixPath(p).name for s in publish.STUDIES for p in s.paths}
    names.add(pathlib.PurePosixPath(publish.PAGE).name)
    assert len(names) == 10  # the law; 3 convergence, 2 stability, 3 mpi files; the page
    twice = _named_twice(names, SOURCES)
    assert not twice, twice


def test_no_attribute_name_is_built_from_a_string():
    built = {where: found for where, tree in SOURCES.items() if (found := _built_names(tree))}
    assert not built, built


def test_the_checks_can_fail():
    old = ast.parse('def fresh(study):\n    """docs/lammps.md"""\n'
                    '    return getattr(m, f"{study}_fresh")\n')
    assert _built_names(old) == ['3: getattr(m, f\'{study}_fresh\')']
    assert _built_names(ast.parse('getattr(m, "fresh")')) == []
    twice = ast.parse('"""docs/lammps.md"""\nPAGE = "docs/lammps.md"\n')
    again = ast.parse('open("docs/lammps.md")\nabout = "the tables of docs/lammps.md"\n')
    assert _named_twice({"lammps.md"}, {"a": twice}) == {}  # a docstring does not count
    assert _named_twice({"lammps.md"}, {"a": twice, "b": again}) == {"lammps.md": ["a", "b"]}
