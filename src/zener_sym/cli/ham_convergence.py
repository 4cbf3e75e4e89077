"""``zener-sym ham-convergence [--check]``: the convergence study of the HAM series
(:mod:`zener_sym.bench.ham_convergence`): rewrite the table of docs/ham_convergence.md, its CSV
and chart, or check that the committed table and CSV are fresh. Deprecated and hidden from
``--help``: ``zener-sym regen ham-convergence`` does the same (:mod:`._deprecated`)."""
from __future__ import annotations

import argparse
import sys

from ..bench import ham_convergence
from ._checkout import CheckoutError, check_result, source_root
from ._deprecated import deprecated, hidden_parser
from ._types import Subparsers


def _run(args: argparse.Namespace) -> int:
    try:  # the table lives in the repository's docs/: say so before the study's work
        root = source_root(f"zener-sym ham-convergence{' --check' if args.check else ''}")
    except CheckoutError as exc:
        print(f"zener-sym ham-convergence: error: {exc}", file=sys.stderr)
        return 2
    if args.check:
        return check_result(
            ham_convergence.check(root=root),
            "docs/ham_convergence.md or its CSV is stale (run 'zener-sym regen "
            "ham-convergence'):",
            f"{root / 'docs' / 'ham_convergence.md'} is up to date")
    for p in ham_convergence.write(root=root, with_chart=not args.no_chart):
        print(f"wrote {p}")
    return 0


def add_parser(sub: Subparsers) -> None:
    p = hidden_parser(sub, "ham-convergence", "regen ham-convergence")
    p.add_argument("--check", action="store_true",
                   help="regenerate in memory; exit 1 with a diff if the committed table is stale")
    p.add_argument("--no-chart", action="store_true", help="skip the chart")
    p.set_defaults(func=deprecated(
        "ham-convergence", lambda args: f"regen{' --check' if args.check else ''} "
                                        "ham-convergence", _run))
