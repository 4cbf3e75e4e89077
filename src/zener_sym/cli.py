"""Command line: ``zener-sym`` (also ``python -m zener_sym``)."""
from __future__ import annotations

import argparse
import sys


def _cmd_report(args) -> int:
    from . import report

    return report.run()


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="zener-sym",
        description="Zener's sphere-plate impact: exact solution, homotopy-analysis models, "
        "derivation, generated kernels and paper audit.",
    )
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    r = sub.add_parser("report", help="the main job: every part of the project, summarised")
    r.set_defaults(func=_cmd_report)
    return p


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    return int(args.func(args) or 0)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
