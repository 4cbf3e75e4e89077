"""Command line: ``zener-sym`` (also ``python -m zener_sym``).

One module per subcommand in this package; each exposes ``add_parser(subparsers)``, which
registers the subcommand and sets ``func``, and leaves the work to the layer that owns it. To add
a command, add its module here and to ``COMMANDS``.

Errors of the command line are one line on stderr and exit code 2.
"""
from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Sequence
from types import ModuleType
from typing import NoReturn

from . import (audit, bench, compare, derive, envelopes, exact_table, figures, fit, generate,
               ham1_table, ham_convergence, lammps, regen, report, scene, table)

#: The subcommand modules, in the order ``--help`` lists them.
COMMANDS: tuple[ModuleType, ...] = (report, scene, compare, fit, lammps, figures, table, regen, generate,
                                    derive, audit, bench, envelopes, exact_table, ham1_table,
                                    ham_convergence)

#: A value that starts like a negative number ("-1mm", "-.5"), which argparse would take for an
#: option; it is joined to its option so that the range checks see it and say what is allowed.
_NEGATIVE = re.compile(r"^-(\d|\.\d)")


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors: ``zener-sym COMMAND: error: ...`` and exit code 2."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message}\n")


def _join_negative_values(argv: list[str]) -> list[str]:
    out: list[str] = []
    for token in argv:
        if out and _NEGATIVE.match(token) and out[-1].startswith("--") and "=" not in out[-1]:
            out[-1] = f"{out[-1]}={token}"
        else:
            out.append(token)
    return out


def build_parser() -> argparse.ArgumentParser:
    """The ``zener-sym`` parser with every subcommand of :data:`COMMANDS`."""
    from .. import __version__

    p = Parser(
        prog="zener-sym",
        description="Zener's sphere-plate impact: exact solution, homotopy-analysis models, "
        "derivation, generated kernels and paper audit.",
    )
    p.add_argument("--version", action="version", version=f"zener-sym {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")
    for module in COMMANDS:
        module.add_parser(sub)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``zener-sym`` with ``argv`` (default ``sys.argv[1:]``); returns the exit code."""
    parser = build_parser()
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        args = parser.parse_args(_join_negative_values(argv))
    except SystemExit as exc:  # --help, --version, or a usage error already printed
        return int(exc.code or 0)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    return int(args.func(args) or 0)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
