"""``zener-sym ham1-table [--check]``: build the ham1 summary's Chebyshev tables, or verify them
(:mod:`zener_sym.ham.table_build`; the shared body is :mod:`._tables`). Deprecated and hidden
from ``--help``: ``zener-sym regen ham1-table`` does the same (:mod:`._deprecated`)."""
from __future__ import annotations

from ..ham import table_build
from ._deprecated import deprecated, hidden_parser
from ._tables import run_table
from ._types import Subparsers


def run(check: bool = False) -> int:
    """Build (or with ``check``, verify) the ham1 summary's table; the exit code."""
    return run_table(table_build, "zener_sym.generated.ham1_table", "ham1-table",
                     "the builder, the ham1 series or the generated ham1 kernels", check)


def add_parser(sub: Subparsers) -> None:
    p = hidden_parser(sub, "ham1-table", "regen ham1-table")
    p.add_argument("--check", action="store_true",
                   help="rebuild in memory and fail if the committed table differs numerically")
    p.set_defaults(func=deprecated(
        "ham1-table", lambda args: f"regen{' --check' if args.check else ''} ham1-table",
        lambda args: run(check=args.check)))
