"""The LAMMPS studies as committed files: their fresh texts and charts (``zener-sym regen
lammps-*``, which runs LAMMPS), and the tables of docs/lammps.md made from them (``zener-sym
regen lammps-docs``, which does not).

Each :class:`Study` names its files once and says how they are made:

- :data:`ERROR_LAW` (``lammps-error-law``): ``src/zener_sym/data/lammps_error_law.json``, read by
  ``zener-sym lammps``;
- :data:`CONVERGENCE` (``lammps-convergence``): the ladder, the observed orders and
  extrapolations, and the chart;
- :data:`STABILITY` (``lammps-stability``): the stability limits and the chart;
- :data:`MPI` (``lammps-mpi``): the example deck of examples/lammps/, its summary and the chart.

:data:`STUDIES` lists them in build order; :mod:`zener_sym.artefacts` registers each.

LAMMPS's doubles depend on its build and the machine's libm only in the last bits, so a
committed file is stale when a number moves beyond ``RTOL`` (or ``ATOL`` near zero), or a text
cell (a status, a failure class) changes. The charts are drawn from what the texts were made
from, byte for byte the same when the texts are.

The docs tables (:func:`docs_fresh`), spliced between the page's marker lines:

- ``steps``: steps per contact for |e_LAMMPS - e| <= 1e-3 (and 1e-4), over lambda, both ends
  (from the error law, as ``zener-sym lammps`` reads it);
- ``orders``: the convergence study's observed order and extrapolation, per lambda (wall);
- ``stability``: the stability limit and how LAMMPS fails beyond it;
- ``mpi``: the 10 000-grain example.
"""
from __future__ import annotations

import csv
import difflib
import io
import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ...scene.lammps import ERROR_LAW_PATH, steps_required
from . import charts, mpi, studies

__all__ = ["Study", "STUDIES", "ERROR_LAW", "CONVERGENCE", "STABILITY", "MPI", "PAGE", "KEYS",
           "docs_tables", "docs_fresh", "splice", "csv_same", "law_same", "mpi_same",
           "orders_csv", "RTOL", "ATOL"]

#: Tolerances of the numeric comparison (errors are differences of e near 1: atol covers their
#: rounding; the law keeps 4 digits).
RTOL, ATOL = 2e-3, 1e-12

Texts = dict[str, str]


def _close(a: str, b: str) -> bool:
    try:
        x, y = float(a), float(b)
    except ValueError:
        return a == b
    if math.isnan(x) or math.isnan(y):
        return math.isnan(x) and math.isnan(y)
    return bool(np.isclose(x, y, rtol=RTOL, atol=ATOL))


def csv_same(rel: str, old: str, new: str) -> list[str]:
    """Cells that differ beyond the tolerance (text cells exactly)."""
    a = list(csv.reader(io.StringIO(old)))
    b = list(csv.reader(io.StringIO(new)))
    if len(a) != len(b) or (a and a[0] != b[0]):
        return [f"{rel}: {len(a)} rows committed, {len(b)} fresh (or another header)"]
    bad = []
    for i, (ra, rb) in enumerate(zip(a, b)):
        for j, (x, y) in enumerate(zip(ra, rb)):
            if not _close(x, y):
                bad.append(f"{rel} row {i + 1} {a[0][j]}: committed {x}, fresh {y}")
    return bad[:20]


def law_same(rel: str, old: str, new: str) -> list[str]:
    """Cells of the error law that differ beyond the tolerance (the grid exactly)."""
    o, n = json.loads(old), json.loads(new)
    grid = ("lambdas", "steps", "phases")
    if [o.get(k) for k in grid] != [n.get(k) for k in grid]:
        return [f"{rel}: another grid of lambdas, steps or phases"]
    bad = []
    for end in ("force", "delta"):
        for i, (ro, rn) in enumerate(zip(o["error"][end], n["error"][end])):
            for j, (x, y) in enumerate(zip(ro, rn)):
                if not _close("nan" if x is None else str(x), "nan" if y is None else str(y)):
                    bad.append(f"{rel} {end} lambda={o['lambdas'][i]} steps={o['steps'][j]}: "
                               f"committed {x}, fresh {y}")
    return bad[:20]


def mpi_same(rel: str, old: str, new: str) -> list[str]:
    """The deck's text diff; the summary's cells beyond the tolerance."""
    if rel.endswith(mpi.DECK):  # the deck is text: any change is a difference
        return list(difflib.unified_diff(old.splitlines(), new.splitlines(), f"{rel} (committed)",
                                         f"{rel} (fresh)", lineterm=""))
    return csv_same(rel, old, new)


def orders_csv(rows: list[dict[str, Any]]) -> str:
    """The observed orders and extrapolations as CSV text (6 digits; the order 4)."""
    def cell(c: str, x: Any) -> Any:
        return (f"{x:.4g}" if c == "order" else f"{x:.6g}") if isinstance(x, float) else x

    cols = ["geometry", "contact_end", "lambda", "steps_used", "order", "e_exact", "e_finest_err",
            "e_extrapolated_err", "resolution"]
    return studies.table_csv([{c: cell(c, r[c]) for c in cols} for r in rows], cols)


def _at(root: Path | None, rel: str) -> Path:
    """A file of the checkout (these studies write there)."""
    if root is None:
        raise ValueError(f"{rel} lives in the source checkout, and there is none")
    return Path(root) / rel


#: What each study's fresh texts were made from, by (study, texts): the chart of those texts is
#: drawn from it instead of running LAMMPS again.
_MADE: dict[tuple[str, tuple[str, ...]], Any] = {}


@dataclass(frozen=True)
class Study:
    """A LAMMPS study as committed files.

    Attributes
    ----------
    name : str
        Its artefact's name (``zener-sym regen NAME``).
    about : str
        What it is, one line.
    texts : tuple of str
        The committed text files it checks, relative to the checkout root.
    compute : callable() -> object
        Runs LAMMPS: what the texts and the chart are made from.
    render : callable(made) -> tuple of str
        The texts, in the order of ``texts``.
    same : callable(rel, committed, fresh) -> list of str
        The differences that make a committed text stale.
    chart : str, optional
        The chart it draws when rebuilt (not checked: drawn from the same data as the texts).
    draw : callable(made, path), optional
        Draws the chart.
    needs_checkout : bool
        Its files live in the repository, not in the installed package.
    """

    name: str
    about: str
    texts: tuple[str, ...]
    compute: Callable[[], Any]
    render: Callable[[Any], tuple[str, ...]]
    same: Callable[[str, str, str], list[str]]
    chart: str | None = None
    draw: Callable[[Any, Path], None] | None = None
    needs_checkout: bool = True

    @property
    def paths(self) -> tuple[str, ...]:
        """Every file it rebuilds: the texts, then the chart."""
        return self.texts + ((self.chart,) if self.chart else ())

    def fresh(self, root: Path | None) -> Texts:
        """Run the study: ``{path: fresh text}``."""
        made = self.compute()
        rendered = self.render(made)
        _MADE[(self.name, rendered)] = made
        return dict(zip(self.texts, rendered))

    def draw_chart(self, root: Path | None, texts: Texts) -> list[Path]:
        """Draw the chart (none: nothing) from what ``texts`` were made from, running the study
        again only when they were not made in this process; the texts themselves are written
        as every artefact's are (:mod:`zener_sym.artefacts`)."""
        if self.chart is None or self.draw is None:
            return []
        made = _MADE.get((self.name, tuple(texts[rel] for rel in self.texts)))
        if made is None:
            made = self.compute()
        path = _at(root, self.chart)
        self.draw(made, path)
        return [path]


def _convergence_texts(rows: list[dict[str, Any]]) -> tuple[str, ...]:
    return studies.convergence_csv(rows), orders_csv(studies.order_rows(rows))


def _mpi_texts(result: dict[str, Any]) -> tuple[str, ...]:
    return str(result["in_impacts"]), mpi.summary_csv(result)


def _mpi_chart(result: dict[str, Any], path: Path) -> None:
    cmp = result["comparison"]
    charts.mpi_chart(cmp.v, cmp.e_lammps, cmp.e_exact, path)


#: The example deck's folder (its README and run_impacts.py sit beside the deck).
EXAMPLE = "examples/lammps"

ERROR_LAW = Study(
    "lammps-error-law", "LAMMPS's measured e error over lambda and steps per contact "
    "(zener-sym lammps reads it; runs LAMMPS)",
    (f"src/zener_sym/data/{ERROR_LAW_PATH.name}",), studies.build_error_law,
    lambda law: (studies.error_law_json(law),), law_same, needs_checkout=False)
CONVERGENCE = Study(
    "lammps-convergence", "LAMMPS against the exact e: ladder of timesteps, observed order, "
    "extrapolation (runs LAMMPS)",
    ("docs/data/lammps_convergence.csv", "docs/data/lammps_orders.csv"), studies.convergence,
    _convergence_texts, csv_same, "docs/figures/lammps_convergence.png",
    charts.convergence_chart)
STABILITY = Study(
    "lammps-stability", "the timestep beyond which LAMMPS loses the collision, over lambda "
    "(runs LAMMPS)",
    ("docs/data/lammps_stability.csv",), studies.stability,
    lambda rows: (studies.stability_csv(rows),), csv_same, "docs/figures/lammps_stability.png",
    charts.stability_chart)
MPI = Study(
    "lammps-mpi", "the example deck of 10 000 grains on a wall, run with mpirun -np 2 (and 1): "
    "every grain's e against the exact e(v)",
    (f"{EXAMPLE}/{mpi.DECK}", "docs/data/lammps_mpi.csv"), mpi.study, _mpi_texts, mpi_same,
    "docs/figures/lammps_mpi.png", _mpi_chart)
#: The studies in build order (the docs tables read their files).
STUDIES = (ERROR_LAW, CONVERGENCE, STABILITY, MPI)


# --- the tables of docs/lammps.md (no LAMMPS run) ----------------------------------------------

PAGE = "docs/lammps.md"
KEYS = ("steps", "orders", "stability", "mpi")
_BEGIN = "<!-- lammps:{key}: generated by `zener-sym regen lammps-docs`, do not edit -->"
_END = "<!-- lammps:{key}: end -->"
#: The lambdas of the steps table.
STEP_LAMBDAS = (0.001, 0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 1000.0)


def _rows(path: Path) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))


def _steps_cell(n: float) -> str:
    if math.isnan(n):
        return "not measured"
    if math.isinf(n):
        return "> 100000"
    return f"{n:.0f}"


def _steps() -> str:
    out = ["| λ | force-free end, 1e-3 | force-free end, 1e-4 | δ = 0 end, 1e-3 "
           "| δ = 0 end, 1e-4 |",
           "|---|---|---|---|---|"]
    for lam in STEP_LAMBDAS:
        cells = [_steps_cell(steps_required(lam, end, tol)) for end in ("force", "delta")
                 for tol in (1e-3, 1e-4)]
        out.append(f"| {lam:g} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def _orders(root: Path) -> str:
    rows = [r for r in _rows(root / CONVERGENCE.texts[1]) if r["geometry"] == "wall"]
    out = ["| end | λ | rungs used | observed order | error at the finest rung | "
           "extrapolated error | extrapolation resolves |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['contact_end']} | {float(r['lambda']):g} | {r['steps_used']} | "
                   f"{float(r['order']):.3f} | {float(r['e_finest_err']):.2e} | "
                   f"{float(r['e_extrapolated_err']):.2e} | {float(r['resolution']):.2e} |")
    return "\n".join(out) + "\n"


def _g4(x: float) -> str:
    return "—" if math.isnan(x) else f"{x:.4g}"


def _stability(root: Path) -> str:
    rows = _rows(root / STABILITY.texts[0])
    out = ["| end | λ | exact e | steps per contact at the limit | LAMMPS's e there | "
           "one rung coarser |", "|---|---|---|---|---|---|"]
    for r in rows:
        lim = float(r["steps_at_limit"])
        out.append(f"| {r['contact_end']} | {float(r['lambda']):g} | {float(r['e_exact']):.4g} | "
                   f"{'above the ladder (50000)' if math.isnan(lim) else f'{lim:g}'} | "
                   f"{_g4(float(r['e_at_limit']))} | "
                   f"{r['failure_beyond']} |")
    return "\n".join(out) + "\n"


def _mpi(root: Path) -> str:
    rows = _rows(root / MPI.texts[1])
    out = ["| quantity | value |", "|---|---|"]
    out += [f"| {r['quantity']} | {r['value']} |" for r in rows]
    return "\n".join(out) + "\n"


def docs_tables(root: Path) -> dict[str, str]:
    """The four tables' markdown, from the committed files of the checkout ``root``."""
    return {"steps": _steps(), "orders": _orders(root), "stability": _stability(root),
            "mpi": _mpi(root)}


def splice(md: str, key: str, table: str) -> str:
    """``md`` with the text between ``key``'s marker lines replaced by ``table``."""
    begin, end = _BEGIN.format(key=key), _END.format(key=key)
    if begin not in md or end not in md:
        raise ValueError(f"{PAGE} lacks the marker lines {begin!r} / {end!r}")
    head, rest = md.split(begin, 1)
    _, tail = rest.split(end, 1)
    return f"{head}{begin}\n{table}{end}{tail}"


def docs_fresh(root: Path | None) -> Texts:
    """``{PAGE: the page with fresh tables}``."""
    if root is None:
        raise ValueError(f"{PAGE} lives in the source checkout, and there is none")
    md = (Path(root) / PAGE).read_text(encoding="utf-8")
    for key, table in docs_tables(Path(root)).items():
        md = splice(md, key, table)
    return {PAGE: md}
