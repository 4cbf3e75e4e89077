"""Type aliases shared by the package's signatures (a leaf: imports nothing of the package).

What an array argument accepts is said once here, so that every signature reads the same way:

``RealLike``
    A real number: a Python ``int`` or ``float``, or a numpy real scalar.
``RealArrayLike``
    A real number, a sequence of real numbers, or a real numpy array (what ``np.asarray`` turns
    into a float array). Strings, complex values and ragged lists are refused at run time with a
    ``ValueError`` by :mod:`zener_sym.params`.
``FloatArray``
    A numpy array of float64, what the package returns.
"""
from __future__ import annotations

from collections.abc import Sequence
from typing import Union

import numpy as np
import numpy.typing as npt

__all__ = ["RealLike", "RealArrayLike", "FloatArray"]

RealLike = Union[int, float, np.integer, np.floating]
# Python numbers and numpy scalars in separate Sequence members: a Sequence of their union is
# not an ``npt.ArrayLike`` for numpy's stubs (np.ndim, np.asarray would refuse it).
RealArrayLike = Union[RealLike, Sequence[float], Sequence[Sequence[float]],
                      Sequence[Union[np.integer, np.floating]],
                      npt.NDArray[np.integer], npt.NDArray[np.floating]]
FloatArray = npt.NDArray[np.float64]
