"""Run the audit: every printed item through its check, as Result rows in a fixed order."""
from __future__ import annotations

import re
from collections.abc import Collection, Sequence

from . import derived
from .checks import CHECKS
from .printed import ITEMS, Printed, parse
from .texts import tex
from .titles import TITLES
from .verdicts import VERDICTS, Result, Verdict

__all__ = ["audit_item", "run_audit", "summary_line", "TEXT_DERIVED"]

#: Equations checked as claims (fits): their derived column is a measurement, not a formula.
TEXT_DERIVED = ("55", "70")


def _clean_raw(raw: str) -> str:
    """The transcription's LaTeX without its tag, its line breaks and its alignment marks."""
    t = re.sub(r"\\tag\{[^}]*\}|\\quad \(\d+\)\s*$", "", raw).strip()
    for a, b in ((r"\begin{cases}", ""), (r"\end{cases}", ""), (r"\begin{aligned}", ""),
                 (r"\end{aligned}", ""), ("&", ""), (r"\\", r",\quad ")):
        t = t.replace(a, b)
    return " ".join(t.split()).strip(" ,")


def _form(item_id: str) -> str:
    return TITLES.get(item_id, ("", "{}"))[1]


def _fill(form: str, body: str) -> str:
    return form.replace("{}", body, 1)


def _printed_text(item: Printed) -> str:
    """Claims: the quoted text (markdown with inline math). Equations and definitions: LaTeX of
    the transcription as the audit reads it (garbled ones: the transcription's own LaTeX)."""
    if item.kind == "claim":
        return item.raw
    if item.parse is None:
        return _clean_raw(item.raw)
    try:
        try:
            shown = parse(item, evaluate=False)
        except Exception:  # SymPy cannot keep this one unevaluated: show its evaluated form
            shown = parse(item)
    except Exception:  # unreadable: the check reports it; the raw text shows what was printed
        return _clean_raw(item.raw)
    return _fill(_form(item.id), tex(shown, item.id, literal=True))


def _derived_text(item: Printed, der: str) -> str:
    if not der or item.kind == "claim" or item.id in TEXT_DERIVED:
        return der
    return der if "=" in der or ">" in der else _fill(_form(item.id), der)


def audit_item(item: Printed) -> Result:
    """The verdict for one printed item (never raises: an error is reported as not-checkable)."""
    fn = CHECKS.get(item.id)
    if item.parse is None and item.kind != "claim" and fn is None:
        return Result(item.id, item.kind, "garbled", item.raw, "", "The transcription cannot be "
                      "read as a formula.", "")
    if fn is None:
        return Result(item.id, item.kind, "not-checkable", _printed_text(item), "",
                      "No check is defined for this item.", "")
    try:
        if item.parse is not None:
            parse(item)  # a transcription that does not parse is a bug in printed.py
        verdict = fn(item.id)
    except derived.NotAvailable as exc:
        verdict = Verdict("not-checkable", "", str(exc))
    except Exception as exc:  # a failing check must not hide the others
        verdict = Verdict("not-checkable", "", f"The check failed: {type(exc).__name__}: {exc}",
                          "audit bug: please report")
    # the item's ``reads`` is shown through its title and form (titles.py), not repeated here
    return Result(item.id, item.kind, verdict.verdict, _printed_text(item),
                  _derived_text(item, verdict.derived), verdict.evidence, verdict.note)


def run_audit(ids: Collection[str] | None = None) -> list[Result]:
    """All items (or those in ``ids``), in the order of :data:`printed.ITEMS`."""
    return [audit_item(it) for it in ITEMS if ids is None or it.id in ids]


def summary_line(results: Sequence[Result]) -> str:
    """'N items audited: n1 consistent, n2 typo, ...' (the verdicts that occur, in the order of
    :data:`.verdicts.VERDICTS`)."""
    counts = {v: sum(r.verdict == v for r in results) for v in VERDICTS}
    body = ", ".join(f"{n} {v}" for v, n in counts.items() if n)
    return f"{len(results)} items audited: {body}."

