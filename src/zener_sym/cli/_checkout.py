"""The source checkout that some commands check or write (generated/, FORMULAS.md, AUDIT.md).

Those files live in the repository, not in an installed package. The checkout is the one this
package runs from (an editable install, ``pip install -e .``), or the folder named by the
environment variable ``ZENER_SYM_SOURCE`` (a clone whose code is the installed one, as when
tox or a packager installs a wheel built from it and runs the tests in the clone).
"""
from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

__all__ = ["CheckoutError", "source_root", "check_result", "ENV"]

#: Environment variable naming the checkout explicitly.
ENV: str = "ZENER_SYM_SOURCE"


class CheckoutError(ValueError):
    """A command that needs a source checkout was run without one."""


def _is_checkout(root: Path) -> bool:
    return ((root / "pyproject.toml").is_file() and (root / "derivation").is_dir()
            and (root / "generated").is_dir() and (root / "src" / "zener_sym").is_dir())


def source_root(command: str) -> Path:
    """The checkout's root folder; CheckoutError saying why not, before any work is done.

    Parameters
    ----------
    command : str
        The command asking, for the message (e.g. ``"zener-sym audit --check"``).
    """
    named = os.environ.get(ENV)
    if named:
        root = Path(named).resolve()
        if not _is_checkout(root):
            raise CheckoutError(f"{command}: {ENV}={named} is not a zener-sym source checkout "
                                "(no pyproject.toml, derivation/, generated/ and src/zener_sym/ "
                                "there)")
        return root
    here = Path(__file__).resolve().parents[1]  # .../zener_sym
    root = here.parents[1]
    if here.parent.name == "src" and _is_checkout(root):
        return root
    raise CheckoutError(f"{command} needs a source checkout (it checks or writes files of the "
                        f"repository), but zener_sym runs from {here}, an installed copy. Run it "
                        f"in a clone installed with `pip install -e .`, or set {ENV} to a clone "
                        "of the installed version")


def check_result(diffs: Sequence[str], stale: str, fresh: str) -> int:
    """What a ``--check`` prints and returns: the ``stale`` line and each difference, indented
    (exit 1), or the ``fresh`` line (exit 0)."""
    if diffs:
        print(stale)
        for d in diffs:
            print("  " + d)
        return 1
    print(fresh)
    return 0
