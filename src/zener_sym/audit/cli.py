"""``zener-sym audit [--json] [--write] [--check]``: the paper audit as a table, JSON or AUDIT.md."""
from __future__ import annotations

import difflib
import functools
import json
import sys
from pathlib import Path

from .run import run_audit, summary_line

__all__ = ["add_parser", "markdown", "audit_md_path", "cached_results"]

_HEADER = """# Paper audit

Every numbered equation (1)-(81), the unnumbered definitions and the numeric claims of the paper
(transcription in shared/paper), checked against the derivation and the exact solution of Zener's
equation (10). Written by `zener-sym audit --write`; `zener-sym audit --check` fails when this file
is stale. Verdicts are computed, never typed in: see `src/zener_sym/audit/`.

- consistent: the printed form equals the derived one (symbolic identity, or 30-digit values at
  random points, or units plus the derived scale);
- typo: readable, but it disagrees (the evidence shows where); garbled: not readable as a formula;
- claim-holds / claim-fails: numeric claims, against the exact ODE (not the paper's FEM);
- not-checkable: no derived form or reference available (the evidence says why).
"""


@functools.lru_cache(maxsize=1)
def cached_results():
    """The audit of every item, computed once per process (the report and tests reuse it)."""
    return tuple(run_audit())


def _cell(s: str, limit: int = 400) -> str:
    s = " ".join(str(s).split()).replace("|", "\\|")
    return s if len(s) <= limit else s[: limit - 3] + "..."


def markdown(results) -> str:
    lines = [_HEADER, f"**Summary:** {summary_line(results)}", "",
             "| id | kind | verdict | printed | derived | evidence | note |",
             "|---|---|---|---|---|---|---|"]
    for r in results:
        lines.append("| " + " | ".join(_cell(c, lim) for c, lim in (
            (r.id, 40), (r.kind, 20), (r.verdict, 20), (r.printed, 300), (r.derived, 300),
            (r.evidence, 600), (r.note, 300))) + " |")
    return "\n".join(lines) + "\n"


def audit_md_path() -> Path:
    """AUDIT.md at the repository root (next to pyproject.toml); refuses outside a checkout."""
    root = Path(__file__).resolve().parents[3]
    if not (root / "pyproject.toml").exists():
        raise ValueError(f"AUDIT.md lives in a source checkout; no pyproject.toml at {root}")
    return root / "AUDIT.md"


def _run(args) -> int:
    results = cached_results()
    if args.json:
        print(json.dumps([r.as_dict() for r in results], indent=1))
        return 0
    text = markdown(results)
    if args.check:
        path = audit_md_path()
        old = path.read_text() if path.exists() else ""
        if old == text:
            print(f"{path.name} is up to date ({summary_line(results)})")
            return 0
        sys.stdout.writelines(difflib.unified_diff(
            old.splitlines(True), text.splitlines(True), f"{path.name} (committed)",
            f"{path.name} (regenerated)"))
        print(f"\n{path.name} is stale: run `zener-sym audit --write`", file=sys.stderr)
        return 1
    if args.write:
        path = audit_md_path()
        path.write_text(text)
        print(f"wrote {path} ({summary_line(results)})")
        return 0
    print(text)
    return 0


def add_parser(sub) -> None:
    p = sub.add_parser("audit", help="check the paper's printed equations and claims")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--json", action="store_true", help="print a JSON list of the items")
    g.add_argument("--write", action="store_true", help="write AUDIT.md at the repository root")
    g.add_argument("--check", action="store_true", help="fail with a diff if AUDIT.md is stale")
    p.set_defaults(func=_run)


def report_section() -> str:
    """One paragraph for `zener-sym report`: the audit's summary line."""
    results = cached_results()
    return ("## Paper audit\n\n" + summary_line(results) + " Details: `zener-sym audit` "
            "(AUDIT.md).")
