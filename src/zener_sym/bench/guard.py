"""The speed guard CI runs (``zener-sym bench --guard``; issue 36, section 3).

Each entry of :mod:`zener_sym.bench.guard_measure` gives a ratio, guarded time / reference
time, measured side by side in one process. The guard compares it with the entry's committed
baseline (``data/speed_baseline.json``) and fails when it exceeds ``FAIL_AT`` times that
baseline. No absolute time is judged, so a slower or busier machine does not fail it; a
change that makes an operation slower against numpy does.

Noise: a measurement runs in a fresh process and keeps the fastest of its samples; an entry
that fails is measured again, in a new process, up to ``RETRIES`` times, and fails only if no
attempt passes (a slowed operation fails every attempt, a burst of load on a shared machine
does not last through them).

``--tree DIR`` measures another checkout (its ``src/``, ``generated/`` and ``derivation/``)
with this checkout's measurement, so that the guard can be pointed at an old commit; and
``--record`` writes the baselines (docs/benchmarks.md, "The speed guard").
"""
from __future__ import annotations

import datetime
import json
import os
import pathlib
import platform
import statistics
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from . import guard_measure

#: A ratio more than this many times its baseline fails the guard.
FAIL_AT = 1.5

#: Further measurements of a failing entry before it counts as failed.
RETRIES = 2

#: The measuring process's BLAS on one thread: a product that BLAS splits over two threads
#: waits, on a busy machine, for the second one to be scheduled (5-30 ms against 0.06 ms for
#: ``numerics.sqrt_integrals.KsSeries``'s before issue 36), which is load, not code.
ONE_THREAD = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}

#: Longest a measuring process may take, seconds (about 20 s on two busy cores).
TIMEOUT_S = 600

#: The committed baselines.
BASELINE = pathlib.Path(__file__).resolve().parents[1] / "data" / "speed_baseline.json"

#: A measurement: entry names -> {name: {"ratio": ...} or {"error": ...}}.
Measure = Callable[[Sequence[str]], dict[str, dict[str, Any]]]

# Run by path in a fresh interpreter: argv = [tree or "", script, names...]. With a tree, that
# tree's package (src/zener_sym, with generated/ and derivation/ mapped in as in pyproject.toml)
# is imported in place of the installed one.
_BOOT = """
import importlib.util, pathlib, runpy, sys
tree = sys.argv.pop(1)
if tree:
    root = pathlib.Path(tree)
    where = {"zener_sym": root / "src" / "zener_sym", "zener_sym.generated": root / "generated",
             "zener_sym.derivation": root / "derivation"}

    class TreeFinder:
        @classmethod
        def find_spec(cls, name, path=None, target=None):
            d = where.get(name)
            return None if d is None else importlib.util.spec_from_file_location(
                name, d / "__init__.py", submodule_search_locations=[str(d)])

    sys.meta_path.insert(0, TreeFinder)
runpy.run_path(sys.argv.pop(1), run_name="__main__")
"""


@dataclass(frozen=True)
class Verdict:
    """One entry judged: its measured ratio (None when it could not run), its baseline and the
    message to print."""

    name: str
    ratio: float | None
    baseline: float
    ok: bool
    message: str


def check_tree(tree: pathlib.Path | None) -> pathlib.Path | None:
    """``tree`` resolved, or a ValueError that says what a checkout must hold."""
    if tree is None:
        return None
    tree = tree.resolve()
    missing = [p for p in ("src/zener_sym/__init__.py", "generated/__init__.py")
               if not (tree / p).is_file()]
    if missing:
        raise ValueError(f"--tree {tree}: not a zener-sym checkout (no {', '.join(missing)})")
    return tree


def measure_tree(names: Sequence[str], tree: pathlib.Path | None = None,
                 rounds: int = guard_measure.ROUNDS) -> dict[str, dict[str, Any]]:
    """The named entries measured in a fresh process, of ``tree``'s package if given (else the
    one installed here), by this checkout's ``guard_measure``."""
    cmd = [sys.executable, "-c", _BOOT, str(tree or ""), guard_measure.__file__, str(rounds),
           *names]
    # an empty folder as the working directory: ``-c`` puts it first on the import path
    with tempfile.TemporaryDirectory(prefix="zs_guard_") as cwd:
        try:
            r = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd,
                               env={**os.environ, **ONE_THREAD}, timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            raise RuntimeError(f"the guard's measurement took more than {TIMEOUT_S} s"
                               + (f" in {tree}" if tree else "")) from None
    if r.returncode != 0:
        tail = r.stderr.strip().splitlines()[-1:] or ["no message"]
        raise RuntimeError(f"the guard's measurement failed{f' in {tree}' if tree else ''}: "
                           f"{tail[0]}")
    result: dict[str, dict[str, Any]] = json.loads(r.stdout.strip().splitlines()[-1])
    return result


def load_baseline(path: pathlib.Path = BASELINE) -> dict[str, dict[str, Any]]:
    """The baselines, entry name -> record (``ratio`` and how it was made); a ValueError that
    names the file and the fault if it cannot be read."""
    try:
        data = json.loads(path.read_text())
    except FileNotFoundError:
        raise ValueError(f"speed baseline {path} does not exist: record it with "
                         "'zener-sym bench --guard --record'") from None
    except json.JSONDecodeError as err:
        raise ValueError(f"speed baseline {path} is not JSON: {err}") from None
    entries = data.get("entries") if isinstance(data, dict) else None
    if not isinstance(entries, dict):
        raise ValueError(f"speed baseline {path}: no 'entries' object")
    for name, rec in entries.items():
        r = rec.get("ratio") if isinstance(rec, dict) else None
        if not isinstance(r, (int, float)) or isinstance(r, bool) or not r > 0:
            raise ValueError(f"speed baseline {path}: entry {name!r} has no positive 'ratio'")
    return entries


def judge(name: str, measured: dict[str, Any], base: dict[str, Any],
          fail_at: float = FAIL_AT) -> Verdict:
    """One entry's verdict: ``ok`` when its ratio is at most ``fail_at`` times the baseline."""
    b = float(base["ratio"])
    made = f"baseline {b:.3g} from {base.get('made_from', '?')}"
    if "error" in measured:
        return Verdict(name, None, b, False, f"{name}: could not be measured: {measured['error']}")
    r = float(measured["ratio"])
    ok = r <= fail_at * b
    what = measured.get("what", "")
    return Verdict(name, r, b, ok,
                   f"{name}: ratio {r:.3g}, {r / b:.2f}x its {made}, limit {fail_at:g}x"
                   + ("" if ok else f" ({fail_at * b:.3g}): SLOWER") + (f"  [{what}]" if what else ""))


def run_guard(baseline: dict[str, dict[str, Any]], measure: Measure,
              names: Sequence[str] | None = None, retries: int = RETRIES,
              log: Callable[[str], None] = print) -> list[Verdict]:
    """Every named entry (default: every one with a baseline) measured and judged; a failing
    entry is measured again up to ``retries`` times and its best attempt kept."""
    names = list(names or baseline)
    unknown = [n for n in names if n not in baseline]
    if unknown:
        raise ValueError(f"no baseline for {', '.join(unknown)}; entries with one: "
                         f"{', '.join(baseline)}")
    results = measure(names)
    verdicts = {n: judge(n, results[n], baseline[n]) for n in names}
    for attempt in range(retries):
        failing = [n for n, v in verdicts.items() if not v.ok and v.ratio is not None]
        if not failing:
            break
        log(f"speed guard: measuring again ({attempt + 2} of {retries + 1}): "
            f"{', '.join(failing)}")
        again = measure(failing)
        for n in failing:
            v = judge(n, again[n], baseline[n])
            if v.ratio is not None and (v.ok or v.ratio < (verdicts[n].ratio or float("inf"))):
                verdicts[n] = v
    return [verdicts[n] for n in names]


def summary_text(verdicts: Sequence[Verdict]) -> str:
    """The guard's report: one line an entry, then the verdict."""
    lines = [("ok    " if v.ok else "FAIL  ") + v.message for v in verdicts]
    bad = [v.name for v in verdicts if not v.ok]
    lines.append(f"speed guard: {len(verdicts) - len(bad)} of {len(verdicts)} entries within "
                 f"{FAIL_AT:g}x of their baselines" + ("" if not bad else
                                                        f"; FAILED: {', '.join(bad)}"))
    return "\n".join(lines)


def _machine() -> str:
    """The processor's model name (what the ratios were measured on)."""
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _commit(tree: pathlib.Path) -> str:
    r = subprocess.run(["git", "-C", str(tree), "rev-parse", "--short", "HEAD"],
                       capture_output=True, text=True)
    # a change to what is measured (the package, its generated code), not to the docs or to
    # the baseline file itself
    dirty = subprocess.run(["git", "-C", str(tree), "status", "--porcelain", "--untracked-files=no",
                            "--", "src", "generated", "derivation", f":!*/{BASELINE.name}"],
                           capture_output=True, text=True).stdout.strip()
    return (r.stdout.strip() or "unknown commit") + (" with local changes" if dirty else "")


def record(names: Sequence[str], measure: Measure, runs: int, made_from: str, command: str,
           path: pathlib.Path = BASELINE) -> dict[str, dict[str, Any]]:
    """The named entries measured ``runs`` times (each a fresh process) and their median ratios
    written to ``path`` as baselines, with how they were made; other entries are kept."""
    ratios: dict[str, list[float]] = {n: [] for n in names}
    whats: dict[str, str] = {}
    for _ in range(runs):
        for n, m in measure(names).items():
            if "error" in m:
                raise RuntimeError(f"{n} could not be measured: {m['error']}")
            ratios[n].append(float(m["ratio"]))
            whats[n] = m["what"]
    try:
        entries = load_baseline(path)
    except ValueError:
        entries = {}
    today = datetime.date.today().isoformat()
    for n, rs in ratios.items():
        entries[n] = {"ratio": round(statistics.median(rs), 4), "what": whats[n],
                      "made_from": made_from, "made_on": today, "machine": _machine(),
                      "runs": [round(r, 4) for r in rs], "command": command}
    path.write_text(json.dumps({"fail_at": FAIL_AT, "entries": dict(sorted(entries.items()))},
                               indent=1) + "\n")
    return entries


def main(tree: pathlib.Path | None = None, names: Sequence[str] | None = None,
         record_runs: int = 0, baseline_path: pathlib.Path = BASELINE) -> int:
    """``zener-sym bench --guard``: 0 when every entry passes, 1 when one fails; with
    ``record_runs``, the baselines recorded instead (0)."""
    tree = check_tree(tree)
    unknown = [n for n in names or () if n not in guard_measure.ENTRIES]
    if unknown:
        raise ValueError(f"unknown guard entries {', '.join(unknown)}; the entries are "
                         f"{', '.join(guard_measure.ENTRIES)}")

    def measure(ns: Sequence[str]) -> dict[str, dict[str, Any]]:
        return measure_tree(ns, tree)

    if record_runs:
        chosen = list(names or guard_measure.ENTRIES)
        root = tree or pathlib.Path(guard_measure.__file__).resolve().parents[3]
        made_from = _commit(root)
        # the checkout named by its commit, not by this machine's path to it
        command = ("zener-sym bench --guard --record " + f"--runs {record_runs}"
                   + (f" --tree <checkout of {made_from}>" if tree else "")
                   + f" --entries {','.join(chosen)}")
        entries = record(chosen, measure, record_runs, made_from, command, baseline_path)
        for n in chosen:
            print(f"{n}: baseline {entries[n]['ratio']} (runs {entries[n]['runs']})")
        print(f"wrote {baseline_path}")
        return 0
    verdicts = run_guard(load_baseline(baseline_path), measure, names)
    print(summary_text(verdicts))
    return 0 if all(v.ok for v in verdicts) else 1
