"""Build the paper's figures: ``figNN.csv`` (the data) and ``figNN.<format>`` (the chart).

Input is validated before anything is written, and every file is written into a temporary
folder inside ``out`` and moved into place only when the whole set succeeded: a failure leaves
``out`` as it was.
"""
from __future__ import annotations

import os
import shutil
import tempfile
import time
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from types import ModuleType

import numpy as np

from . import data as D

__all__ = ["FORMATS", "parse_only", "parse_formats", "check_out", "build", "compare_csv",
           "stale", "RTOL", "ATOL"]

#: Chart formats the command writes.
FORMATS = ("png", "pdf", "svg")
#: Freshness tolerance of the committed CSVs: |new - old| <= ATOL + RTOL |old| (the CSVs carry 10
#: significant digits; integration beyond the exact tables is reproducible to about 1e-11).
RTOL, ATOL = 1e-8, 1e-12


def parse_only(text: str | None) -> tuple[int, ...]:
    """Figure numbers from ``"5,15"`` (None: all); ValueError listing the allowed numbers."""
    if text is None:
        return D.NUMBERS
    allowed = f"allowed: {', '.join(str(n) for n in D.NUMBERS)} (comma-separated)"
    try:
        nums = [int(t) for t in str(text).split(",") if t.strip()]
    except ValueError:
        raise ValueError(f"--only {text!r} is not a list of figure numbers; {allowed}") from None
    bad = [n for n in nums if n not in D.FIGURES]
    if bad or not nums:
        raise ValueError(f"--only: no figure {bad[0] if bad else text!r}; {allowed}")
    return tuple(sorted(set(nums)))


def parse_formats(text: str) -> tuple[str, ...]:
    """Formats from ``"png,pdf"``; ValueError listing the allowed formats."""
    fmts = [t.strip().lower() for t in str(text).split(",") if t.strip()]
    bad = [f for f in fmts if f not in FORMATS]
    if bad or not fmts:
        raise ValueError(f"--format: unknown format {bad[0] if bad else text!r}; allowed: "
                         f"{', '.join(FORMATS)} (comma-separated)")
    return tuple(dict.fromkeys(fmts))


def check_out(out: str | os.PathLike[str]) -> Path:
    """``out`` as a Path that exists (created) and is writable; ValueError otherwise."""
    out = Path(out)
    try:
        out.mkdir(parents=True, exist_ok=True)
        fd, probe = tempfile.mkstemp(dir=out, prefix=".zener-sym-probe-")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise ValueError(f"--out {str(out)!r} is not a writable directory ({exc.strerror}); "
                         f"allowed: a directory you can write to") from None
    return out


def build(out: str | os.PathLike[str], only: Iterable[int] | None = None,
          formats: Sequence[str] = ("png",), csv_only: bool = False, coarse: bool = False,
          log: Callable[[str], object] = print) -> list[Path]:
    """Write figures ``only`` (numbers; default all) into ``out``; returns the written paths.

    Parameters
    ----------
    out : path-like
        Output directory (created if missing).
    only : sequence of int, optional
        Figure numbers among 3 to 15.
    formats : sequence of str
        Chart formats among ``FORMATS``.
    csv_only : bool
        Write the data only (no matplotlib needed).
    coarse : bool
        Coarse grids (tests).
    log : callable
        Receives one progress line per figure.
    """
    nums = D.NUMBERS if only is None else tuple(only)
    for n in nums:
        if n not in D.FIGURES:
            raise ValueError(f"no figure {n!r}; allowed: {', '.join(map(str, D.NUMBERS))}")
    for f in formats:
        if f not in FORMATS:
            raise ValueError(f"unknown format {f!r}; allowed: {', '.join(FORMATS)}")
    out = check_out(out)
    plt: ModuleType | None = None
    if not csv_only:
        from ..plot import style as st

        plt = st.pyplot(headless=True)
        from .draw import draw
    tmp = Path(tempfile.mkdtemp(dir=out, prefix=".figures-"))
    written: list[str] = []
    try:
        for n in nums:
            t0 = time.perf_counter()
            spec = D.FIGURES[n]
            rows = spec.compute(coarse)
            (tmp / f"{spec.name}.csv").write_text(D.to_csv(rows))
            names = [f"{spec.name}.csv"]
            if plt is not None:
                with plt.rc_context(st.RC):
                    fig = draw(spec, rows, plt)
                    names += [p.name for p in st.save(fig, tmp / spec.name, formats)]
                    plt.close(fig)
            log(f"{spec.name}: {', '.join(names)} ({time.perf_counter() - t0:.1f} s)")
            written += names
        final: list[Path] = []
        for name in written:
            os.replace(tmp / name, out / name)
            final.append(out / name)
        return final
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def compare_csv(old: str, new: str, rtol: float = RTOL, atol: float = ATOL) -> list[str]:
    """Differences between two figure CSV texts beyond the tolerance (empty: the same)."""
    a, b = D.from_csv(old), D.from_csv(new)
    if len(a) != len(b):
        return [f"{len(a)} rows committed, {len(b)} regenerated"]
    diffs = []
    for i, (ra, rb) in enumerate(zip(a, b)):
        if ra[:2] != rb[:2]:
            diffs.append(f"row {i + 2}: {ra[:2]} != {rb[:2]}")
            continue
        for col, va, vb in zip(D.COLUMNS[2:], ra[2:], rb[2:]):
            if (va is None) != (vb is None) or (
                    va is not None and vb is not None
                    and not np.isclose(vb, va, rtol=rtol, atol=atol)):
                diffs.append(f"row {i + 2} ({ra[0] or '-'}, {ra[1]}) {col}: committed {va!r}, "
                             f"now {vb!r}")
        if len(diffs) > 20:
            diffs.append("...")
            break
    return diffs


def stale(folder: str | os.PathLike[str],
          only: Iterable[int] | None = None) -> dict[str, list[str]]:
    """{figure name: differences} for the CSVs in ``folder`` that are stale or missing."""
    folder = Path(folder)
    bad: dict[str, list[str]] = {}
    for n in (D.NUMBERS if only is None else only):
        spec = D.FIGURES[n]
        p = folder / f"{spec.name}.csv"
        new = D.to_csv(spec.compute(False))
        if not p.exists():
            bad[spec.name] = [f"{p} is missing"]
            continue
        d = compare_csv(p.read_text(), new)
        if d:
            bad[spec.name] = d
    return bad
