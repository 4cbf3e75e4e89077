"""Run the audit: every printed item through its check, as Result rows in a fixed order."""
from __future__ import annotations

import time

from . import checks, claims, derived
from .printed import ITEMS, Printed, parse
from .verdicts import VERDICTS, Result

__all__ = ["audit_item", "run_audit", "summary_line"]


def _printed_text(item: Printed) -> str:
    if item.kind == "claim":
        return item.raw
    return item.parse if item.parse is not None else item.raw


def audit_item(item: Printed) -> Result:
    """The verdict for one printed item (never raises: an error is reported as not-checkable)."""
    if item.kind == "claim":
        fn = claims.CLAIMS.get(item.id)
    elif item.id in ("55", "70"):
        fn = lambda: claims._fit_claim(item.id)  # noqa: E731 (fits are checked as claims)
    elif item.parse is None and item.id not in checks.CHECKS:
        fn = None
    else:
        fn = checks.CHECKS.get(item.id)
    if item.parse is None and item.kind != "claim" and fn is None:
        return Result(item.id, item.kind, "garbled", item.raw, "", "the transcription cannot be "
                      "read as a formula", "")
    if fn is None:
        return Result(item.id, item.kind, "not-checkable", _printed_text(item), "",
                      "no check is defined for this item", "")
    try:
        if item.parse is not None:
            parse(item)  # a transcription that does not parse is a bug in printed.py
        verdict, der, evidence, note = fn()
    except derived.NotAvailable as exc:
        verdict, der, evidence, note = "not-checkable", "", str(exc), ""
    except Exception as exc:  # a failing check must not hide the others
        verdict, der, evidence, note = ("not-checkable", "", f"check failed: {type(exc).__name__}: "
                                        f"{exc}", "audit bug: please report")
    if item.kind == "claim":
        pass  # a claim's ``reads`` names its printed numbers; the note stays the check's
    elif item.reads and not note:
        note = item.reads
    elif item.reads:
        note = f"{item.reads}: {note}"
    return Result(item.id, item.kind, verdict, _printed_text(item), der, evidence, note)


def run_audit(ids=None) -> list[Result]:
    """All items (or those in ``ids``), in the order of :data:`printed.ITEMS`."""
    return [audit_item(it) for it in ITEMS if ids is None or it.id in ids]


def summary_line(results) -> str:
    counts = {v: sum(r.verdict == v for r in results) for v in VERDICTS}
    body = ", ".join(f"{n} {v}" for v, n in counts.items() if n)
    return f"{len(results)} items audited: {body}."


if __name__ == "__main__":  # pragma: no cover
    t0 = time.perf_counter()
    res = run_audit()
    for r in res:
        print(r.id, r.verdict, "|", r.evidence[:150], "|", r.note[:80])
    print(summary_line(res), f"{time.perf_counter() - t0:.1f} s")
