"""Numbers as text for generated modules.

A generated table module's text (its do-not-edit header, inputs hash and data) is the table
engine's (``numerics.cheb_table_build.table_module`` and ``TableBuilder.render``).
"""
from __future__ import annotations

from collections.abc import Iterable

__all__ = ["float_tuple"]


def float_tuple(values: Iterable[float], digits: int) -> str:
    """A 1-D sequence as a tuple literal, each number printed with ``digits`` significant digits.

    Parameters
    ----------
    values : iterable of float
        The numbers.
    digits : int
        Significant digits of each (``17`` keeps every double).

    Returns
    -------
    str
        ``"(v0, v1, ...,)"``.

    Examples
    --------
    >>> from zener_sym.codegen.tables import float_tuple
    >>> float_tuple([1 / 3, 2.0], 5)
    '(0.33333, 2,)'
    """
    return "(" + ", ".join(f"{float(v):.{digits}g}" for v in values) + ",)"
