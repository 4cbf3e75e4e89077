"""Number and table formatting shared by the report's sections."""
from __future__ import annotations

from collections.abc import Iterable, Sequence

from ..typing import RealLike

#: The lambda values of the paper's figures 5, 10 and 11 (and 0, Hertz's rigid half-space).
PAPER_LAMBDAS: tuple[float, ...] = (0.0, 0.11, 1.01, 1.51, 1.99)


def fmt(x: RealLike, digits: int = 10) -> str:
    """``x`` to ``digits`` significant digits (``g`` format)."""
    return f"{x:.{digits}g}"


def markdown_table(header: Sequence[str], rows: Iterable[Sequence[object]]) -> str:
    """A markdown table: the ``header`` cells, then one line per row (cells shown with str)."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def seconds(dt: float) -> str:
    """A duration for people: two significant digits, and "< 0.01 s" instead of "0.0 s"."""
    return "< 0.01 s" if dt < 0.01 else f"{dt:.2g} s" if dt < 10 else f"{dt:.0f} s"

