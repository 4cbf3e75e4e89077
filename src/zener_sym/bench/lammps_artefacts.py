"""The LAMMPS studies as committed artefacts (``zener-sym regen lammps-*``): their fresh texts,
their numeric comparison, and their charts.

- ``lammps-error-law``: ``src/zener_sym/data/lammps_error_law.json``, read by ``zener-sym lammps``;
- ``lammps-convergence``: ``docs/data/lammps_convergence.csv`` (the ladder),
  ``docs/data/lammps_orders.csv`` (observed orders, extrapolation) and the chart;
- ``lammps-stability``: ``docs/data/lammps_stability.csv`` and the chart.

LAMMPS's doubles depend on its build and the machine's libm only in the last bits, so a
committed file is stale when a number moves beyond ``RTOL`` (or ``ATOL`` near zero), or a text
cell (a status, a failure class) changes.
"""
from __future__ import annotations

import csv
import difflib
import io
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from . import lammps_verify as lv

__all__ = ["MPI_DECK", "MPI_SUMMARY", "MPI_CHART", "mpi_fresh", "mpi_same", "mpi_write",
           "LAW", "CONVERGENCE", "ORDERS", "STABILITY", "CONVERGENCE_CHART", "STABILITY_CHART",
           "law_fresh", "law_same", "convergence_fresh", "convergence_write", "stability_fresh",
           "stability_write", "csv_same", "RTOL", "ATOL"]

LAW = "src/zener_sym/data/lammps_error_law.json"
CONVERGENCE = "docs/data/lammps_convergence.csv"
ORDERS = "docs/data/lammps_orders.csv"
STABILITY = "docs/data/lammps_stability.csv"
CONVERGENCE_CHART = "docs/figures/lammps_convergence.png"
STABILITY_CHART = "docs/figures/lammps_stability.png"
MPI_DECK = "examples/lammps/in.impacts"
MPI_SUMMARY = "docs/data/lammps_mpi.csv"
MPI_CHART = "docs/figures/lammps_mpi.png"
#: Tolerances of the numeric comparison (errors are differences of e near 1: atol covers their
#: rounding; the law keeps 4 digits).
RTOL, ATOL = 2e-3, 1e-12

Texts = dict[str, str]


def _at(root: Path | None, rel: str) -> Path:
    """A docs/ file of the checkout (these artefacts need one)."""
    if root is None:
        raise ValueError(f"{rel} lives in the source checkout, and there is none")
    return Path(root) / rel


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


def law_fresh(root: Path | None) -> Texts:
    return {LAW: lv.error_law_json(lv.build_error_law())}


def law_same(rel: str, old: str, new: str) -> list[str]:
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


#: What each study's fresh text was made from, by (study, text): writing that text draws its
#: chart from it instead of running LAMMPS again.
_MADE: dict[tuple[str, str], Any] = {}


def convergence_fresh(root: Path | None) -> Texts:
    rows = lv.convergence()
    text = lv.convergence_csv(rows)
    _MADE[("convergence", text)] = rows
    return {CONVERGENCE: text, ORDERS: orders_csv(lv.order_rows(rows))}


def orders_csv(rows: list[dict[str, Any]]) -> str:
    """The observed orders and extrapolations as CSV text (6 digits; the order 4)."""
    def cell(c: str, x: Any) -> Any:
        return (f"{x:.4g}" if c == "order" else f"{x:.6g}") if isinstance(x, float) else x

    cols = ["geometry", "contact_end", "lambda", "steps_used", "order", "e_exact", "e_finest_err",
            "e_extrapolated_err", "resolution"]
    return lv.table_csv([{c: cell(c, r[c]) for c in cols} for r in rows], cols)


def _write(root: Path | None, texts: Texts) -> list[Path]:
    """Write every text to its file of the checkout."""
    out = []
    for rel, text in texts.items():
        p = _at(root, rel)
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text, encoding="utf-8")
        out.append(p)
    return out


def _charts() -> Any:
    from . import lammps_charts  # matplotlib: imported only to draw

    return lammps_charts


def _write_with_chart(root: Path | None, texts: Texts, study: str, key: str,
                      compute: Callable[[], Any], draw: Callable[[Any, Path], None],
                      rel: str) -> list[Path]:
    """Write a study's texts and draw its chart (``draw(made, path)``) from what the text
    ``texts[key]`` was made from (``compute()`` when it was not made in this process)."""
    out = _write(root, texts)
    made = _MADE.get((study, texts[key]))
    if made is None:
        made = compute()
    path = _at(root, rel)
    draw(made, path)
    return out + [path]


def convergence_write(root: Path | None, texts: Texts) -> list[Path]:
    return _write_with_chart(root, texts, "convergence", CONVERGENCE, lv.convergence,
                             lambda rows, path: _charts().convergence_chart(rows, path),
                             CONVERGENCE_CHART)


def stability_fresh(root: Path | None) -> Texts:
    rows = lv.stability()
    text = lv.stability_csv(rows)
    _MADE[("stability", text)] = rows
    return {STABILITY: text}


def stability_write(root: Path | None, texts: Texts) -> list[Path]:
    return _write_with_chart(root, texts, "stability", STABILITY, lv.stability,
                             lambda rows, path: _charts().stability_chart(rows, path),
                             STABILITY_CHART)


def mpi_fresh(root: Path | None) -> Texts:
    from . import lammps_mpi

    result = lammps_mpi.study()
    text = lammps_mpi.summary_csv(result)
    _MADE[("mpi", text)] = result
    return {MPI_DECK: str(result["in_impacts"]), MPI_SUMMARY: text}


def mpi_same(rel: str, old: str, new: str) -> list[str]:
    if rel == MPI_DECK:  # the deck is text: any change is a difference
        return list(difflib.unified_diff(old.splitlines(), new.splitlines(), f"{rel} (committed)",
                                         f"{rel} (fresh)", lineterm=""))
    return csv_same(rel, old, new)


def _mpi_study() -> dict[str, Any]:
    from . import lammps_mpi

    return lammps_mpi.study()


def _mpi_chart(result: dict[str, Any], path: Path) -> None:
    cmp = result["comparison"]
    _charts().mpi_chart(cmp.v, cmp.e_lammps, cmp.e_exact, path)


def mpi_write(root: Path | None, texts: Texts) -> list[Path]:
    return _write_with_chart(root, texts, "mpi", MPI_SUMMARY, _mpi_study, _mpi_chart, MPI_CHART)
