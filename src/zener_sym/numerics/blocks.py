"""How a history is laid out in memory: blocks of points and one allocation for its fields.

On the machine these were measured on a fresh page costs about 1.5 us, and a whole-grid float64
temporary of a 200 x 500 history is 200 of them, so a history's time depended more on fresh
memory than on its arithmetic (docs/benchmarks.md). The exact tables (``exact.table``) and the
models (``models.ham0_ham1``) evaluate their points in blocks and put their fields in one allocation.
Imports nothing of the package.
"""
from __future__ import annotations

from collections.abc import Iterator, Sequence

import numpy as np

from ..typing import FloatArray

__all__ = ["BLOCK", "line_blocks", "field_buffers"]

#: Points per block when a model evaluates a history block by block.
BLOCK = 8192


def line_blocks(n_lines: int, n_col: int,
                size: int = BLOCK) -> Iterator[tuple[int, int, int, int]]:
    """Blocks of about ``size`` points covering an n_lines x n_col grid.

    Whole lines while a line is shorter than ``size``, column chunks of one line otherwise.
    A history evaluated block by block keeps its temporaries cache-sized and below the
    allocator's mmap threshold: temporaries as large as the grid cost more in fresh memory
    (page faults) than in arithmetic, and their cost depends on how the allocator was last used.

    Parameters
    ----------
    n_lines, n_col : int
        The grid's lines (e.g. lambda values) and columns (times), both >= 1.
    size : int
        Points per block (``BLOCK`` by default).

    Yields
    ------
    tuple of int
        ``(r0, r1, c0, c1)``: the block is lines r0:r1, columns c0:c1.
    """
    if n_col <= size:
        step = size // n_col
        for r0 in range(0, n_lines, step):
            yield r0, min(r0 + step, n_lines), 0, n_col
    else:
        for r in range(n_lines):
            for c0 in range(0, n_col, size):
                yield r, r + 1, c0, min(c0 + size, n_col)


def field_buffers(names: Sequence[str], shape: Sequence[int]) -> dict[str, FloatArray]:
    """Uninitialized float arrays of ``shape``, one per name, as views of one allocation.

    One block instead of one per field: once freed it raises glibc's (dynamic) mmap threshold
    above its own size, so the next history of that size reuses the memory rather than faulting
    in fresh pages (about 1.5 us a page here, 200 pages per field on a 200 x 500 grid); separate
    arrays below that size kept being returned to the system and faulted in again.

    Parameters
    ----------
    names : sequence of str
        The fields' names.
    shape : sequence of int
        Each field's shape.

    Returns
    -------
    dict of str to ndarray
        name -> uninitialized float64 array of ``shape`` (a view of the shared buffer).
    """
    buf: FloatArray = np.empty((len(names),) + tuple(shape))
    return dict(zip(names, buf))
