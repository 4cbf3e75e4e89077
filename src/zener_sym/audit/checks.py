"""Every check of the audit, by topic; importing this module registers them all in :data:`CHECKS`.

Topics: :mod:`.forms_core` (the homotopy's printed forms), :mod:`.forms_zeroth` (the zeroth-order
closed forms in lambda), :mod:`.forms_first_order` (the first-order integrals), :mod:`.constants`
(forms with rounded printed constants), :mod:`.units` (the physical-unit equations),
:mod:`.claims` and :mod:`.claims_literature` (numeric claims). A check is ``fn(item_id)`` returning
a :class:`~.verdicts.Verdict`; the printed side always comes from :mod:`.printed`, so a changed
transcription changes the verdict.
"""
from __future__ import annotations

from . import claims, claims_literature, constants, forms_core, forms_first_order, forms_zeroth, units
from .registry import CHECKS

__all__ = ["CHECKS", "TOPICS"]

#: The topic modules, each registering its checks when imported.
TOPICS = (forms_core, forms_zeroth, forms_first_order, constants, units, claims, claims_literature)
