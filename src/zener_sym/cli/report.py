"""``zener-sym report``: the main job; every part of the project contributes one section
(:mod:`zener_sym.report.build`)."""
from __future__ import annotations

from ..report.build import SECTIONS, run
from ._types import Subparsers


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("report", help="the main job: every part of the project, summarised")
    p.add_argument("--out", default="zener-sym-report",
                   help="folder for the charts and tables (default: zener-sym-report)")
    p.add_argument("--skip", action="append", default=[], metavar="SECTION",
                   choices=[n for n, _ in SECTIONS],
                   help="leave out a section (repeatable): " + ", ".join(n for n, _ in SECTIONS))
    p.set_defaults(func=lambda args: run(out_dir=args.out, skip=tuple(args.skip)))
