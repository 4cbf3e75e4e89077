"""AUDIT.md: the audit's results rendered as markdown, and where the file lives."""
from __future__ import annotations

import functools
from pathlib import Path

from .run import run_audit, summary_line

__all__ = ["markdown", "audit_md_path", "cached_results"]

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


def audit_md_path(root: Path | None = None) -> Path:
    """AUDIT.md in ``root`` (default: the repository root next to pyproject.toml, when this
    package runs from a checkout); ValueError outside a checkout."""
    if root is not None:
        return Path(root) / "AUDIT.md"
    root = Path(__file__).resolve().parents[3]
    if not (root / "pyproject.toml").exists():
        raise ValueError(f"AUDIT.md lives in a source checkout; no pyproject.toml at {root}")
    return root / "AUDIT.md"
