"""Command line: ``zener-sym`` (also ``python -m zener_sym``).

Each subcommand lives in the module that does the work; the module exposes
``add_parser(subparsers)``, which registers the subcommand and sets ``func``. To add a command,
add its module to ``COMMAND_MODULES``.
"""
from __future__ import annotations

import argparse
import importlib
import sys

#: Modules (relative to zener_sym) that each contribute one subcommand.
COMMAND_MODULES = [
    "report",
    "generate_cmd",
    "derive_cmd",
]


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="zener-sym",
        description="Zener's sphere-plate impact: exact solution, homotopy-analysis models, "
        "derivation, generated kernels and paper audit.",
    )
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    for name in COMMAND_MODULES:
        importlib.import_module(f"zener_sym.{name}").add_parser(sub)
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
