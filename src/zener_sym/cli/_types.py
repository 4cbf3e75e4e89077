"""Types shared by the subcommand modules (annotations only)."""
from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import TypeAlias

__all__ = ["Subparsers", "Out"]

#: What ``ArgumentParser.add_subparsers`` returns; each subcommand module's ``add_parser``
#: registers its parser there.
Subparsers: TypeAlias = "argparse._SubParsersAction[argparse.ArgumentParser]"

#: Where a command writes its lines: ``print``, or a list's ``append`` in tests.
Out: TypeAlias = Callable[[str], object]
