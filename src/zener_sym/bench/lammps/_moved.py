"""The flat modules ``bench/lammps_*.py`` that users imported before this subpackage (issue 36):
each still answers, with a ``DeprecationWarning`` naming the new place, for one release."""
from __future__ import annotations

import importlib
import warnings
from collections.abc import Callable
from typing import Any

__all__ = ["moved"]


def moved(old: str, new: str) -> Callable[[str], Any]:
    """A module ``__getattr__`` for the old module ``old``: every public name of ``new``,
    with a ``DeprecationWarning``."""
    def __getattr__(name: str) -> Any:
        module = importlib.import_module(new)
        if (name.startswith("__") and name != "__all__") or not hasattr(module, name):
            raise AttributeError(f"module {old!r} has no attribute {name!r}")
        warnings.warn(f"{old} is deprecated: use {new} (the same {name}); {old} goes in the next "
                      f"release", DeprecationWarning, stacklevel=2)
        return getattr(module, name)

    return __getattr__
