"""``zener-sym exact-table [--check]``: build the fast exact model's tables, or verify them
(:mod:`zener_sym.exact.table_build`; the shared body is :mod:`._tables`)."""
from __future__ import annotations

from ..exact import table_build
from ._tables import run_table


def run(check: bool = False) -> int:
    return run_table(table_build, "zener_sym.generated.exact_table",
                     (("summary", "SUMMARY"), ("history", "HISTORY")), "exact-table",
                     "the builder or the solver", check)


def add_parser(sub) -> None:
    p = sub.add_parser("exact-table", help="build the Chebyshev tables of the fast exact model")
    p.add_argument("--check", action="store_true",
                   help="rebuild in memory and fail if the committed table differs numerically")
    p.set_defaults(func=lambda args: run(check=args.check))
