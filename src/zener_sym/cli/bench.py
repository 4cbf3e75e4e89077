"""``zener-sym bench [--quick] --out DIR``: work-precision tables and charts, stability map,
speed targets, and a BENCHMARKS.md summarising them (the work is in :mod:`zener_sym.bench`);
``zener-sym bench --guard``: the speed guard CI runs (:mod:`zener_sym.bench.guard`)."""
from __future__ import annotations

import argparse
import pathlib
import sys

from ..bench import guard, reference
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
    g = p.add_argument_group("speed guard", "ratios to numpy against committed baselines; exit "
                             "code 1 when one is more than 1.5x its baseline")
    g.add_argument("--guard", action="store_true", help="run the speed guard, then exit")
    g.add_argument("--tree", default=None, type=pathlib.Path,
                   help="measure this checkout's package instead of the installed one")
    g.add_argument("--entries", default=None,
                   help="comma-separated guard entries (default: every one)")
    g.add_argument("--record", action="store_true",
                   help="with --guard: write the baselines of --entries instead of checking")
    g.add_argument("--runs", type=int, default=5,
                   help="with --record: measurements per entry, the median kept (default 5)")

    def go(args: argparse.Namespace) -> int:
        if args.guard:
            try:
                if args.runs < 1:
                    raise ValueError(f"--runs must be at least 1, not {args.runs}")
                return guard.main(args.tree, args.entries.split(",") if args.entries else None,
                                  record_runs=args.runs if args.record else 0)
            except ValueError as err:
                print(f"zener-sym bench: error: {err}", file=sys.stderr)
                return 2
            except RuntimeError as err:  # the measurement itself failed: the guard fails
                print(f"zener-sym bench: {err}", file=sys.stderr)
                return 1
        if args.build_reference:
            reference.write_cache(reference.compute())
            print(f"wrote {reference.CACHE}")
            return 0
        run(pathlib.Path(args.out), quick=args.quick,
            markdown=pathlib.Path(args.markdown) if args.markdown else None)
        return 0

    p.set_defaults(func=go)
