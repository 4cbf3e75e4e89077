"""Every committed artefact the package rebuilds, in one list: ``zener-sym regen``.

An artefact is a set of committed files (kernels, tables, data, tables inside docs) that a
builder of some layer computes. Each entry of :data:`ARTEFACTS` says which files it rebuilds, how
to compute their fresh text (``fresh``), how to tell a committed file from a fresh one (``same``:
a text diff, or a numeric comparison for tables computed by floating-point solvers), and whether
it needs a source checkout. ``zener-sym regen --check`` compares them all; ``zener-sym regen
NAME`` rewrites one. The older commands (``generate``, ``exact-table``, ...) stay for one
release, hidden from ``--help`` and deprecated (``zener_sym.cli._deprecated``).

To add an artefact: write a ``fresh(root) -> {path: text}`` function (and a ``same`` when a text
diff is too strict), and add one :class:`Artefact` to :data:`ARTEFACTS`.

This module names builders of several layers (codegen, numerics, scene, bench, report, audit,
figures), so it sits in the report/bench/audit layer, below the command line that calls it.
"""
from __future__ import annotations

import difflib
import json
import math
import re
from dataclasses import dataclass
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

from .numerics.cheb_table_build import TableBuilder
# LAMMPS's studies name their own files (LAMMPS itself is imported only when one runs)
from .bench.lammps import publish as _lammps_publish

__all__ = ["Artefact", "ARTEFACTS", "names", "get", "locate", "check", "build",
           "text_diff", "text_skeleton", "text_drift", "Texts", "FreshFn", "SameFn", "WriteFn"]

#: ``{path relative to the checkout root: text}`` of an artefact's files.
Texts = dict[str, str]
#: ``fresh(root)``: the fresh texts of an artefact (``root`` None: the installed package).
FreshFn = Callable[[Path | None], Texts]
#: ``same(rel, committed, fresh)``: the differences that make a committed file stale.
SameFn = Callable[[str, str, str], list[str]]
#: ``write(root, texts)``: writes an artefact from its fresh texts; the files written.
WriteFn = Callable[[Path | None, Texts], list[Path]]

#: A path of a committed file relative to the checkout's root.
_PACKAGE = "src/zener_sym/"


def locate(root: Path | None, rel: str) -> Path:
    """The file ``rel`` (relative to the checkout root) in ``root``; without a checkout, package
    data (``src/zener_sym/...``) is found in the installed package."""
    if root is not None:
        return Path(root) / rel
    if rel.startswith(_PACKAGE):
        return Path(__file__).resolve().parent / rel[len(_PACKAGE):]
    raise ValueError(f"{rel} lives in the source checkout, and there is none")


def text_diff(rel: str, old: str, new: str) -> list[str]:
    """Unified diff lines committed -> fresh (empty when the texts are equal)."""
    if old == new:
        return []
    return list(difflib.unified_diff(old.splitlines(), new.splitlines(), f"{rel} (committed)",
                                     f"{rel} (fresh)", lineterm=""))


@dataclass(frozen=True)
class Artefact:
    """One rebuildable artefact.

    Attributes
    ----------
    name : str
        Its name on the command line (``zener-sym regen NAME``).
    about : str
        What it is, one line.
    paths : tuple of str
        The committed files it rebuilds, relative to the checkout root (a pattern with ``*`` for
        a family of files).
    fresh : callable(root) -> dict
        ``{path relative to root: fresh text}`` of every file it checks; the expensive part.
    same : callable(rel, committed, fresh) -> list of str
        The differences that make a committed file stale (empty when fresh); default a text diff.
    write : callable(root, texts) -> list of Path, optional
        Writes the artefact from the fresh texts; default writes each text (unchanged files are
        left alone). An artefact that writes more than it checks (charts) gives its own.
    needs_checkout : bool
        Its files live in the repository (docs/, generated/, the root), not in the installed
        package.
    alias : str
        The older command that does the same.
    """

    name: str
    about: str
    paths: tuple[str, ...]
    fresh: FreshFn
    same: SameFn = text_diff
    write: WriteFn | None = None
    needs_checkout: bool = True
    alias: str = ""


def _write_texts(root: Path | None, texts: Texts) -> list[Path]:
    written: list[Path] = []
    for rel, text in texts.items():
        p = locate(root, rel)
        if p.exists() and p.read_text(encoding="utf-8") == text:
            continue
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text, encoding="utf-8")
        written.append(p)
    return written


def check(art: Artefact, root: Path | None, texts: Texts | None = None) -> list[str]:
    """Why the committed files of ``art`` are stale (empty list: fresh). ``texts``: its fresh
    texts if already computed."""
    texts = art.fresh(root) if texts is None else texts
    problems: list[str] = []
    for rel, new in texts.items():
        p = locate(root, rel)
        if not p.exists():
            problems.append(f"{rel} is missing")
            continue
        problems += art.same(rel, p.read_text(encoding="utf-8"), new)
    return problems


def build(art: Artefact, root: Path | None) -> list[Path]:
    """Rebuild ``art``; the files written."""
    texts = art.fresh(root)
    return (art.write or _write_texts)(root, texts)


# --- the artefacts' fresh texts and comparisons -----------------------------------------------

def _kernels(root: Path | None) -> Texts:
    from . import codegen

    return {f"generated/{name}": text for name, text in codegen.render_all().items()}


def _formulas(root: Path | None) -> Texts:
    from .derivation import formulas, registry

    return {formulas.FILENAME: formulas.render(registry.derive(checks=False))}


def _table_module(text: str) -> dict[str, Any]:
    """The names a generated table file defines (it holds data only: literals)."""
    ns: dict[str, Any] = {}
    exec(compile(text, "<generated table>", "exec"), ns)  # noqa: S102 - our own generated data
    return ns


#: A number as the generated files print it: digits with an optional sign, decimal places,
#: exponent or further dotted parts (a version such as 1.17.1), not inside a word.
_NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)*(?:\.)?(?:[eE][-+]?\d+)?(?![\w])")
#: A run of masked numbers (a coefficient tuple or matrix string, whatever its length).
_RUN = re.compile(r"#(?:(?:, |,| )#)+")
#: The inputs hash (checked on its own).
_HASH = re.compile(r"(Inputs hash: |INPUTS_HASH = ')\w+")


def text_skeleton(text: str) -> str:
    """``text`` with every number masked (a run of numbers as one ``#``) and whitespace runs
    as one space: what must not change between a committed table and a fresh rendering of it
    (comments, names, layout) while its numbers are compared within the builder's tolerance."""
    return re.sub(r"\s+", " ", _masked(text)).strip()


def _masked(text: str) -> str:
    return _RUN.sub("#", _NUMBER.sub("#", _HASH.sub(r"\1#", text)))


def text_drift(rel: str, old: str, new: str) -> list[str]:
    """The lines (numbers masked) where a committed table's text differs from a fresh
    rendering's; empty when only numbers differ."""
    if text_skeleton(old) == text_skeleton(new):
        return []
    diff = difflib.unified_diff(_masked(old).splitlines(), _masked(new).splitlines(),
                                f"{rel} (committed)", f"{rel} (fresh)", lineterm="", n=0)
    return [f"{rel}: its text differs from a fresh rendering (numbers masked):",
            *[line for line in diff if not line.startswith(("---", "+++"))]]


def _table(builder: Callable[[], TableBuilder], what: str) -> tuple[FreshFn, SameFn, WriteFn]:
    """fresh/same/write of a Chebyshev table in generated/ (the node values come from
    floating-point solvers), from its builder (``builder()``: imported on first use, the
    solvers stay unloaded till then).

    ``same``: its numbers within the builder's tolerance (``TableBuilder.compare``), its text
    (the numbers masked: comments, names, layout) equal to a fresh rendering's, and its inputs
    hash. ``write``: where the committed numbers agree with the rebuild, the table is re-rendered
    with the committed numbers (a rebuild on another machine, or a change of text, moves no
    number); else the rebuilt table is written."""
    # fresh text -> the tables it was rendered from (what builder.compare reads)
    built: dict[str, Any] = {}

    def fresh(root: Path | None) -> Texts:
        b = builder()
        tables = b.build()
        text = b.render(tables)
        built.clear()
        built[text] = tables
        return {f"generated/{b.file.filename}": text}

    def same(rel: str, old: str, new: str) -> list[str]:
        b = builder()
        try:
            o = _table_module(old)
            stored = b.as_tables(o)
        except Exception as exc:  # a broken committed file is stale, not a crash
            return [f"{rel} does not load: {type(exc).__name__}: {exc}"]
        tables = built[new] if new in built else b.build()
        problems: list[str] = b.compare(stored, tables)
        problems += text_drift(rel, old, new)
        current = _table_module(new)["INPUTS_HASH"]
        if o.get("INPUTS_HASH") != current:
            problems.append(f"inputs hash {o.get('INPUTS_HASH')} != current {current} "
                            f"({what} changed)")
        return problems

    def write(root: Path | None, texts: Texts) -> list[Path]:
        b = builder()
        out: Texts = {}
        for rel, new in texts.items():
            p = locate(root, rel)
            out[rel] = new
            if p.exists():
                try:
                    ns = _table_module(p.read_text(encoding="utf-8"))
                except Exception:  # a broken committed file: write the rebuild
                    continue
                stored = b.as_tables(ns)
                tables = built[new] if new in built else b.build()
                if not b.compare(stored, tables):
                    out[rel] = b.render(stored)
        return _write_texts(root, out)

    return fresh, same, write


def _envelopes_fresh(root: Path | None) -> Texts:
    from .bench.envelopes import build

    return {"src/zener_sym/data/envelopes.json": json.dumps(build(), indent=1, sort_keys=True)
            + "\n"}


def _envelopes_same(rel: str, old: str, new: str) -> list[str]:
    from .scene.envelopes import compare

    return compare(json.loads(old), json.loads(new))


def _ham_convergence_fresh(root: Path | None) -> Texts:
    from .bench import ham_convergence

    return ham_convergence.fresh_texts(root)


def _ham_convergence_same(rel: str, old: str, new: str) -> list[str]:
    from .bench import ham_convergence

    return ham_convergence.diff(rel, old, new)


def _ham_convergence_write(root: Path | None, texts: Texts) -> list[Path]:
    from .bench import ham_convergence

    return ham_convergence.write(root=root, with_chart=True)


def _audit_fresh(root: Path | None) -> Texts:
    from .audit.markdown import cached_results, markdown

    return {"AUDIT.md": markdown(cached_results())}


def _figures_fresh(root: Path | None) -> Texts:
    from .figures import data as D

    return {f"docs/figures/{D.FIGURES[n].name}.csv": D.to_csv(D.FIGURES[n].compute(False))
            for n in D.NUMBERS}


def _figures_same(rel: str, old: str, new: str) -> list[str]:
    from .figures.make import compare_csv

    return [f"{rel}: {d}" for d in compare_csv(old, new)]


def _figures_write(root: Path | None, texts: Texts) -> list[Path]:
    from .figures import make

    make.build(locate(root, "docs/figures"), None, ("png",))
    return [locate(root, rel) for rel in texts]


def _calibration_fresh(root: Path | None) -> Texts:
    from .report import calibration

    return {calibration.TEXT: calibration.text()}


def _calibration_write(root: Path | None, texts: Texts) -> list[Path]:
    from .report import calibration

    text_path, chart = locate(root, calibration.TEXT), locate(root, calibration.CHART)
    text_path.parent.mkdir(parents=True, exist_ok=True)
    result = calibration.fit()
    text_path.write_text(calibration.text(result), encoding="utf-8")
    calibration.write_chart(chart, result)
    return [text_path, chart]


def _peers_fresh(root: Path | None) -> Texts:
    from .report import peers

    rel = "docs/viscoelastic.md"
    return {rel: peers.update_doc(locate(root, rel).read_text("utf-8"), peers.markdown())}


def _ham_envelopes_fresh(root: Path | None) -> Texts:
    from .report import ham_envelopes

    rel = "docs/ham.md"
    return {rel: ham_envelopes.update_doc(locate(root, rel).read_text("utf-8"),
                                          ham_envelopes.envelope_markdown())}


def _kernel_check_fresh(root: Path | None) -> Texts:
    from .ham import kernel_check

    worst = kernel_check.measure()[0]  # the wall-time ratio it also gives is no artefact
    lines = ["kernel,max_rel_error,max_abs_error"]
    lines += [f"{k},{r:.2g},{a:.2g}" for k, (r, a) in worst.items()]
    return {"docs/data/kernel_check.csv": "\n".join(lines) + "\n"}


def _kernel_check_same(rel: str, old: str, new: str) -> list[str]:
    """Worst errors near rounding differ between machines (libm, SIMD): stale only when one
    moves by more than a factor 4, or the kernels listed differ."""
    def rows(text: str) -> dict[str, tuple[float, float]]:
        out: dict[str, tuple[float, float]] = {}
        for line in text.splitlines()[1:]:
            k, rel_err, abs_err = line.split(",")
            out[k] = (float(rel_err), float(abs_err))
        return out

    try:
        o, n = rows(old), rows(new)
    except ValueError as exc:
        return [f"{rel} does not parse: {exc}"]
    if set(o) != set(n):
        return [f"{rel}: kernels {sorted(o)} != {sorted(n)}"]
    bad: list[str] = []
    for k in sorted(o):
        for what, a, b in zip(("relative", "absolute"), o[k], n[k]):
            if abs(math.log10(max(a, 1e-18)) - math.log10(max(b, 1e-18))) > math.log10(4):
                bad.append(f"{rel}: {k} max {what} error {a:.2g} -> {b:.2g}")
    return bad


def _bench_reference_fresh(root: Path | None) -> Texts:
    from .bench import reference

    return {"src/zener_sym/data/bench_reference.json": reference.dumps(reference.compute())}


def _bench_reference_same(rel: str, old: str, new: str) -> list[str]:
    from .bench import reference

    return reference.compare(json.loads(old), json.loads(new))


def _lambda_series_fresh(root: Path | None) -> Texts:
    from .derivation import lambda_series as ls

    ctx = ls.derive()
    if not ctx.log.ok:
        raise RuntimeError("derivation.lambda_series has failed steps: "
                           + "; ".join(str(s) for s in ctx.log.steps if not s.passed))
    return {"src/zener_sym/data/lambda_series.json": ls.coefficients_json(ctx)}


def _plate_criterion_fresh(root: Path | None) -> Texts:
    from .scene import plate_criterion_build as pcb

    return {"src/zener_sym/data/plate_criterion.json": pcb.dumps(pcb.build())}


def _plate_criterion_same(rel: str, old: str, new: str) -> list[str]:
    from .scene import plate_criterion_build as pcb

    return pcb.compare(json.loads(old), json.loads(new))


def _finite_plate_fresh(root: Path | None) -> Texts:
    from .report import finite_plate

    return {finite_plate.FORCE_CSV: finite_plate.force_csv()}


def _finite_plate_same(rel: str, old: str, new: str) -> list[str]:
    from .report import finite_plate

    return finite_plate.compare_csv(rel, old, new)


def _finite_plate_write(root: Path | None, texts: Texts) -> list[Path]:
    from .report import finite_plate

    paths = (locate(root, finite_plate.FORCE_CSV), locate(root, finite_plate.FORCE_CHART),
             locate(root, finite_plate.REGIME_CHART))
    return finite_plate.write_charts(paths, texts[finite_plate.FORCE_CSV])


def _lammps(study: _lammps_publish.Study) -> Artefact:
    """The artefact of a LAMMPS study (runs LAMMPS): its files, texts and chart as
    :mod:`zener_sym.bench.lammps.publish` describes them (one with a chart draws it too)."""
    def write(root: Path | None, texts: Texts) -> list[Path]:
        return _write_texts(root, texts) + study.draw_chart(root, texts)

    return Artefact(study.name, study.about, study.paths, study.fresh, study.same, write,
                    needs_checkout=study.needs_checkout)


def _exact_builder() -> TableBuilder:
    from .exact.table_build import BUILDER

    return BUILDER


def _force_builder() -> TableBuilder:
    from .exact.force_table_build import BUILDER

    return BUILDER


def _ham1_builder() -> TableBuilder:
    from .ham.table_build import BUILDER

    return BUILDER


_EXACT_FRESH, _EXACT_SAME, _EXACT_WRITE = _table(_exact_builder, "the builder or the solver")
_FORCE_FRESH, _FORCE_SAME, _FORCE_WRITE = _table(
    _force_builder, "the builder, the solvers or the plate table")
_HAM1_FRESH, _HAM1_SAME, _HAM1_WRITE = _table(
    _ham1_builder, "the builder, the ham1 series or the generated ham1 kernels")

#: Every artefact, in the order ``regen`` builds them (an artefact after those it reads: the
#: ham1 table hashes the generated kernels, the envelopes use the tables).
ARTEFACTS: tuple[Artefact, ...] = (
    Artefact("kernels", "the HAM and plate formulas (Python) and the C99 kernels emitted from "
             "the derivation",
             # codegen.BUILDERS' files (named here: importing codegen loads SymPy)
             ("generated/ham0.py", "generated/ham1.py", "generated/plate.py",
              "generated/c/zener_sym.h", "generated/c/zener_sym.c"),
             _kernels, alias="generate"),
    Artefact("formulas", "the derived equations in the paper's notation", ("FORMULAS.md",),
             _formulas, alias="generate, derive --markdown"),
    Artefact("exact-table", "Chebyshev tables of the fast exact model",
             ("generated/exact_table.py",), _EXACT_FRESH, _EXACT_SAME, _EXACT_WRITE,
             alias="exact-table"),
    Artefact("exact-force-table", "Chebyshev tables of the exact model's force-free end (grains)",
             ("generated/exact_force_table.py",), _FORCE_FRESH, _FORCE_SAME, _FORCE_WRITE,
             alias="exact-table --contact-end force"),
    Artefact("ham1-table", "Chebyshev tables of the ham1 summary", ("generated/ham1_table.py",),
             _HAM1_FRESH, _HAM1_SAME, _HAM1_WRITE, alias="ham1-table"),
    Artefact("lambda-series", "coefficients of the small- and large-lambda series",
             ("src/zener_sym/data/lambda_series.json",), _lambda_series_fresh,
             needs_checkout=False),
    Artefact("envelopes", "measured error envelopes that select_model reads",
             ("src/zener_sym/data/envelopes.json",), _envelopes_fresh, _envelopes_same,
             needs_checkout=False, alias="envelopes"),
    Artefact("plate-criterion", "the finite-plate model against Zener's on a (lambda, beta) "
             "grid: the criterion Scene.result chooses by",
             ("src/zener_sym/data/plate_criterion.json",), _plate_criterion_fresh,
             _plate_criterion_same, needs_checkout=False),
    Artefact("finite-plate-figures", "the finite plate's force history beside Zener's (data "
             "and chart) and the regime map from the criterion table (docs/finite_plates.md)",
             ("docs/data/finite_plate_force.csv", "docs/figures/finite_plate_force.png",
              "docs/figures/finite_plate_regime.png"), _finite_plate_fresh, _finite_plate_same,
             write=_finite_plate_write),
    Artefact("bench-reference", "the benchmark's mpmath reference",
             ("src/zener_sym/data/bench_reference.json",), _bench_reference_fresh,
             _bench_reference_same, needs_checkout=False, alias="bench --build-reference"),
    Artefact("kernel-check", "numpy kernels against the mpmath kernels (docs/ham.md)",
             ("docs/data/kernel_check.csv",), _kernel_check_fresh, _kernel_check_same),
    Artefact("ham-envelopes", "error envelopes of ham0 and ham1 (table in docs/ham.md)",
             ("docs/ham.md",), _ham_envelopes_fresh),
    Artefact("ham-convergence", "convergence study of the HAM series",
             ("docs/ham_convergence.md", "docs/data/ham_convergence.csv",
              "docs/figures/ham_convergence.png"), _ham_convergence_fresh,
             same=_ham_convergence_same, write=_ham_convergence_write, alias="ham-convergence"),
    Artefact("peers", "peers' e(v) against exact (table in docs/viscoelastic.md)",
             ("docs/viscoelastic.md",), _peers_fresh),
    Artefact("calibration", "the fit of A to the Bridges et al. ice law (docs/viscoelastic.md)",
             ("docs/data/calibration_bridges1984.txt",), _calibration_fresh,
             write=_calibration_write),
    Artefact("figures", "the paper's Figs. 3-15 against exact (data and charts)",
             ("docs/figures/fig*.csv", "docs/figures/fig*.png"), _figures_fresh, _figures_same,
             write=_figures_write, alias="figures --out docs/figures"),
    Artefact("audit", "the paper audit", ("AUDIT.md",), _audit_fresh,
             alias="audit --write"),
    *(_lammps(study) for study in _lammps_publish.STUDIES),
    Artefact("lammps-docs", "the tables of docs/lammps.md from the LAMMPS data above (no run)",
             (_lammps_publish.PAGE,), _lammps_publish.docs_fresh),
)


def names() -> list[str]:
    """The artefacts' names, in build order."""
    return [a.name for a in ARTEFACTS]


def get(name: str) -> Artefact:
    """The artefact called ``name``; ValueError listing the names otherwise."""
    for a in ARTEFACTS:
        if a.name == name:
            return a
    raise ValueError(f"unknown artefact {name!r}; allowed: {', '.join(names())}")
