"""``zener-sym figures [--out DIR] [--only 5,15] [--format png,pdf,svg] [--csv-only] [--check]``:
the paper's Figs. 3-15 against the exact solution (:mod:`zener_sym.figures`)."""
from __future__ import annotations

import argparse
import sys

from ._types import Subparsers


def _run(args: argparse.Namespace) -> int:
    from ..figures import make as B

    try:
        only = B.parse_only(args.only)
        formats = B.parse_formats(args.format)
        if args.check:
            bad = B.stale(args.out, only)
            for name, diffs in bad.items():
                print(f"{name}: stale (run 'zener-sym figures --out {args.out}')")
                for d in diffs[:10]:
                    print("  " + d)
            if not bad:
                print(f"figure data in {args.out} up to date ({len(only)} figures)")
            return 1 if bad else 0
        B.check_out(args.out)
    except ValueError as exc:
        print(f"zener-sym figures: error: {exc}", file=sys.stderr)
        return 2
    try:
        B.build(args.out, only, formats, csv_only=args.csv_only)
    except ImportError as exc:
        print(f"zener-sym figures: error: {exc}", file=sys.stderr)
        return 2
    return 0


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("figures", help="the paper's Figs. 3-15 against the exact solution "
                       "(figNN.png and figNN.csv)")
    p.add_argument("--out", default="figures", metavar="DIR",
                   help="output directory (default ./figures; created if missing)")
    p.add_argument("--only", default=None, metavar="N,N",
                   help="comma-separated figure numbers among 3-15 (default: all)")
    p.add_argument("--format", default="png", metavar="FMT,FMT",
                   help="chart formats among png, pdf, svg (default png)")
    p.add_argument("--csv-only", action="store_true", help="write the data only (no charts)")
    p.add_argument("--check", action="store_true",
                   help="regenerate the CSVs in memory and exit 1 if those in --out are stale")
    p.set_defaults(func=_run)
