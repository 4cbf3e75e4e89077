"""AUDIT.md: the audit's results for a reader, and where the file lives.

The file opens with a summary table (item, kind, verdict, one-line note; each item links to its
section), then one section per item: the printed form and the derived form as display math (LaTeX
in the paper's notation, :mod:`.texts`), the verdict and the evidence with the numbers that decide
it. Nothing is cut. Garbled transcriptions are shown as their LaTeX source in a code block, since
they cannot be read as formulas.
"""
from __future__ import annotations

import functools
import re
from collections.abc import Sequence
from pathlib import Path

from .printed import by_id
from .run import TEXT_DERIVED, run_audit, summary_line
from .titles import CLAIM_TITLES, TITLES
from .verdicts import Result

__all__ = ["markdown", "audit_md_path", "cached_results", "slug", "heading", "PAPER_TITLE"]

#: The paper, named by its title (the transcription the audit reads is not part of the repository).
PAPER_TITLE = "Elastic impact of sphere on large plate"

_HEADER = f"""# Paper audit

Every numbered equation (1) to (81), the unnumbered definitions and the numeric claims of the paper
*{PAPER_TITLE}*, checked against this project's derivation (FORMULAS.md) and the exact solution of
Zener's equation (10). Written by `zener-sym regen audit`; `zener-sym regen --check audit` fails
when this file is stale. Verdicts are computed, never typed in (`src/zener_sym/audit/`).

Each section shows what the paper prints (as the audit reads the transcription, exponents and
constants exactly as printed), what the derivation gives, the verdict and the evidence:

- consistent: the printed form equals the derived one (SymPy simplifies the difference to 0, or
  30-digit values agree at random points, or the units agree and the derived scale matches);
- typo: readable, but it disagrees (the evidence shows where); garbled: not readable as a formula;
- claim-holds, claim-fails: numeric claims, measured against the exact ODE (not the paper's FEM);
- not-checkable: no derived form or reference is available (the evidence says why).
"""

_CLAIMS_INTRO = """How a printed bound is read. A claim "the error is less than 2.90%" is checked strictly:
the largest error, measured to more digits than printed (2.905%), must be below the printed
figure; this reading gives the verdict. The second reading asks whether the printed figure is the
measurement rounded to its printed digits (2.905% prints as 2.90% or 2.91%); where the two readings
differ, the evidence gives both. The measurements are against the exact ODE on the grids named in
each section; the paper measured against FEM.
"""


@functools.lru_cache(maxsize=1)
def cached_results() -> tuple[Result, ...]:
    """The audit of every item, computed once per process (the report and tests reuse it)."""
    return tuple(run_audit())


def slug(text: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    s = re.sub(r"[^\w\- ]", "", text.strip().lower())
    return s.replace(" ", "-")


def heading(r: Result) -> str:
    """The section heading of a result (plain words, so that its anchor is predictable)."""
    if r.kind == "claim":
        eq, title = CLAIM_TITLES.get(r.id, ("", r.id.split(":", 1)[1]))
        return f"Claim on {eq}: {title}" if eq else f"Claim: {title}"
    title = TITLES.get(r.id, (by_id(r.id).reads or r.id, "{}"))[0]
    if r.kind == "equation":
        return f"({r.id}) {title}"
    return title


def _one_line(s: str) -> str:
    return " ".join(str(s).split())


def _table_note(r: Result) -> str:
    if r.kind == "claim" or r.id in TEXT_DERIVED:
        note = r.derived or r.note
    else:
        note = r.note or {"consistent": "agrees with the derivation"}.get(r.verdict, "")
    return _one_line(note).replace("|", r"\vert ")


def _display(latex: str) -> list[str]:
    return ["$$", latex, "$$", ""]


def _section(r: Result) -> list[str]:
    out = [f"### {heading(r)}", ""]
    verdict = f"Verdict: {r.verdict}." + (f" {_capital(r.note)}." if r.note else "")
    if r.kind == "claim":
        out += ["The paper:", "", "> " + _one_line(r.printed), "", verdict, ""]
        if r.derived:
            out += [f"Measured: {_one_line(r.derived)}.", ""]
        out += [f"Evidence: {_one_line(r.evidence)}", ""]
        return out
    out += [verdict, ""]
    if r.verdict == "garbled" and _unreadable(r.id):
        out += ["Printed (the transcription's LaTeX source; it cannot be read as a formula):", "",
                "```latex", r.printed, "```", ""]
    else:
        out += ["Printed:", ""] + _display(r.printed)
    if r.derived:
        if r.id in TEXT_DERIVED:
            out += [f"Measured: {_one_line(r.derived)}.", ""]
        else:
            out += ["Derived:", ""] + _display(r.derived)
    out += [f"Evidence: {_one_line(r.evidence)}", ""]
    return out


def _unreadable(item_id: str) -> bool:
    return by_id(item_id).parse is None


def _capital(s: str) -> str:
    s = _one_line(s).rstrip(".")
    return s[:1].upper() + s[1:]


def markdown(results: Sequence[Result]) -> str:
    """AUDIT.md for a list of :class:`~.verdicts.Result` (deterministic)."""
    groups = [("Equations", [r for r in results if r.kind == "equation"]),
              ("Definitions", [r for r in results if r.kind == "definition"]),
              ("Claims", [r for r in results if r.kind == "claim"])]
    lines = [_HEADER, f"Summary: {summary_line(results)}", "",
             "Contents: " + ", ".join(f"[{name}](#{slug(name)})" for name, _ in groups)
             + ", and the summary table below.", "",
             "| item | kind | verdict | note |", "|---|---|---|---|"]
    for r in results:
        h = heading(r)
        label = h.split(" ", 1)[0] if r.kind == "equation" else (
            ("claim " + CLAIM_TITLES.get(r.id, ("", ""))[0]).strip() if r.kind == "claim" else h)
        lines.append(f"| [{label}](#{slug(h)}) | {r.kind} | {r.verdict} | {_table_note(r)} |")
    lines.append("")
    for name, rs in groups:
        if not rs:
            continue
        lines += [f"## {name}", ""]
        if name == "Claims":
            lines += [_CLAIMS_INTRO]
        for r in rs:
            lines += _section(r)
    return "\n".join(lines).rstrip("\n") + "\n"


def audit_md_path(root: Path | None = None) -> Path:
    """AUDIT.md in ``root`` (default: the repository root next to pyproject.toml, when this
    package runs from a checkout); ValueError outside a checkout."""
    if root is not None:
        return Path(root) / "AUDIT.md"
    root = Path(__file__).resolve().parents[3]
    if not (root / "pyproject.toml").exists():
        raise ValueError(f"AUDIT.md lives in a source checkout; no pyproject.toml at {root}")
    return root / "AUDIT.md"
