"""``zener-sym exact-table [--check] [--contact-end {delta,force}]``: build the fast exact
model's tables, or verify them: the plate's (:mod:`zener_sym.exact.table_build`) and the
force-free end's (:mod:`zener_sym.exact.force_table_build`), both unless one end is named (the
shared body is :mod:`._tables`). Deprecated and hidden from ``--help``: ``zener-sym regen
exact-table exact-force-table`` does the same (:mod:`._deprecated`)."""
from __future__ import annotations

import argparse
from types import ModuleType

from ..exact import force_table_build, table_build
from ._deprecated import deprecated, hidden_parser
from ._tables import run_table
from ._types import Subparsers

#: contact_end -> (builder, generated module, what its inputs hash covers)
TABLES: dict[str, tuple[ModuleType, str, str]] = {
    "delta": (table_build, "zener_sym.generated.exact_table", "the builder or the solver"),
    "force": (force_table_build, "zener_sym.generated.exact_force_table",
              "the builder, the solvers or the plate table"),
}


def run(check: bool = False, contact_end: str | None = None) -> int:
    """Build (or with ``check``, verify) the table of ``contact_end``, both by default; the
    worst exit code of the two."""
    ends = tuple(TABLES) if contact_end is None else (contact_end,)
    code = 0
    # the plate's first: the force-end table anchors its recovery map on the plate table
    for end in ends:
        builder, module, what = TABLES[end]
        code = max(code, run_table(builder, module, "exact-table", what, check))
    return code


#: contact_end -> the artefact of ``zener-sym regen`` that rebuilds its table
ARTEFACT = {"delta": "exact-table", "force": "exact-force-table"}


def _replacement(args: argparse.Namespace) -> str:
    names = [ARTEFACT[args.contact_end]] if args.contact_end else list(ARTEFACT.values())
    return f"regen{' --check' if args.check else ''} {' '.join(names)}"


def add_parser(sub: Subparsers) -> None:
    p = hidden_parser(sub, "exact-table", "regen exact-table exact-force-table")
    p.add_argument("--check", action="store_true",
                   help="rebuild in memory and fail if the committed table differs numerically")
    p.add_argument("--contact-end", choices=tuple(TABLES), default=None,
                   help="only this end of contact's table (default: both)")
    p.set_defaults(func=deprecated("exact-table", _replacement,
                                   lambda args: run(check=args.check,
                                                    contact_end=args.contact_end)))
