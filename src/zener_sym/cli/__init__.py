"""Command line: ``zener-sym`` (also ``python -m zener_sym``).

One module per subcommand in this package; each exposes ``add_parser(subparsers)``, which
registers the subcommand and sets ``func``, and leaves the work to the layer that owns it. To add
a command, add its module here and to ``COMMANDS``.
"""
from __future__ import annotations

import argparse
import sys

from . import audit, bench, derive, envelopes, exact_table, generate, report, scene

#: The subcommand modules, in the order ``--help`` lists them.
COMMANDS = (report, generate, bench, scene, envelopes, exact_table, derive, audit)


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="zener-sym",
        description="Zener's sphere-plate impact: exact solution, homotopy-analysis models, "
        "derivation, generated kernels and paper audit.",
    )
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    for module in COMMANDS:
        module.add_parser(sub)
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
