"""``zener-sym bench [--quick] --out DIR``: work-precision tables and charts, stability map,
speed targets, and a BENCHMARKS.md summarising them (the work is in :mod:`zener_sym.bench`)."""
from __future__ import annotations

import argparse
import pathlib

from ..bench import reference
from ..bench.suite import run
from ._types import Subparsers


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("bench", help="work-precision charts, stability map and speed targets")
    p.add_argument("--quick", action="store_true", help="thin sweeps; finishes in under a minute")
    p.add_argument("--out", default="bench-out", help="output folder (default: bench-out)")
    p.add_argument("--markdown", default=None,
                   help="also write the summary here (e.g. BENCHMARKS.md), images linked to --out")
    p.add_argument("--build-reference", action="store_true",
                   help="recompute and cache the high-precision reference, then exit")

    def go(args: argparse.Namespace) -> int:
        if args.build_reference:
            reference.write_cache(reference.compute())
            print(f"wrote {reference.CACHE}")
            return 0
        run(pathlib.Path(args.out), quick=args.quick,
            markdown=pathlib.Path(args.markdown) if args.markdown else None)
        return 0

    p.set_defaults(func=go)
