"""Paper audit: each printed item of the paper against the derivation and the exact solution.

    >>> from zener_sym.audit import run_audit, summary_line
    >>> rows = run_audit(["25"])          # one item; run_audit() does all of them
    >>> rows[0].verdict
    'typo'

Modules: ``printed`` (the transcriptions, data only), ``derived`` (registry access and the audit's
own short derivations), ``verdicts`` (comparison machinery, ``Verdict``), ``registry`` (``@check``),
the topics ``forms_core``, ``forms_zeroth``, ``forms_first_order``, ``constants``, ``units``,
``claims``, ``claims_literature`` (with ``reference``), ``checks`` (all of them), ``run``,
``markdown`` (AUDIT.md); docs/audit.md has the table.
"""
from .run import audit_item, run_audit, summary_line

__all__ = ["run_audit", "audit_item", "summary_line"]
