"""The older rebuild commands, kept for one release: hidden from ``--help`` and deprecated.

``zener-sym regen`` is the one rebuild command. The commands that rebuilt one artefact each
(``generate``, ``exact-table``, ``ham1-table``, ``envelopes``, ``ham-convergence`` and
``audit --write``) still work, but are no longer listed by ``zener-sym --help`` and print on
stderr which ``regen`` call replaces them.
"""
from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from typing import Any

from ._types import Subparsers

__all__ = ["note", "hidden_parser", "deprecated"]


def note(command: str, replacement: str) -> None:
    """Print on stderr that ``zener-sym command`` is deprecated for ``zener-sym replacement``."""
    print(f"zener-sym {command}: deprecated, use `zener-sym {replacement}` instead (this alias "
          f"will be removed in the next release)", file=sys.stderr)


def hidden_parser(sub: Subparsers, name: str, replacement: str) -> argparse.ArgumentParser:
    """Register the subcommand ``name`` without listing it in ``zener-sym --help`` (argparse
    lists only subcommands registered with a ``help``); its own ``--help`` names the
    replacement."""
    return sub.add_parser(name, description=f"Deprecated: use `zener-sym {replacement}`.")


def deprecated(command: str, replacement: Callable[[argparse.Namespace], str],
               func: Callable[[argparse.Namespace], Any]) -> Callable[[argparse.Namespace], Any]:
    """``func`` with the deprecation note first; ``replacement(args)`` is the ``regen`` call
    that does the same as these arguments."""
    def run(args: argparse.Namespace) -> Any:
        note(command, replacement(args))
        return func(args)
    return run
