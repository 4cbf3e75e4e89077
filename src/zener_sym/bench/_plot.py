"""matplotlib, imported lazily: it is the optional ``plot`` extra (see zener_sym.plot.style)."""
from __future__ import annotations

from typing import Any


def pyplot() -> Any:
    """``matplotlib.pyplot`` on a headless backend (a module of an untyped library: Any)."""
    from ..plot.style import pyplot as _pyplot

    return _pyplot(headless=True)
