"""Taylor polynomials sum_k c_k s^k held as coefficient lists: value, derivative, product, integral
and root.

The exact solvers step along Taylor series (``zener_sym.exact.mp``, ``zener_sym.exact.force_end``)
and read everything they report off one step's polynomial. Plain arithmetic, so the same functions
serve mpmath numbers, floats and numpy arrays (a sequence of coefficient arrays: one polynomial
per element). ``horner_take`` in :mod:`.chebyshev` is Horner's rule again, gathering each
coefficient in place by index: the tables' hot path, where a list of gathered rows would cost a
copy per coefficient.
"""
from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Union

import mpmath
import numpy.typing as npt

__all__ = ["Coefficients", "horner", "derivative", "product", "integral", "root"]

#: Coefficients c_0 ... c_n: a sequence, or an array whose first axis runs over the powers.
Coefficients = Union[Sequence[Any], npt.NDArray[Any]]


def horner(c: Coefficients, s: Any) -> Any:
    """sum_k c_k s^k by Horner's rule.

    Parameters
    ----------
    c : sequence or ndarray
        Coefficients c_0 ... c_n, n >= 0 (mpmath numbers, floats, or arrays of one shape; an
        array's first axis runs over the powers).
    s : mpmath.mpf, float or ndarray
        The argument.

    Returns
    -------
    mpmath.mpf, float or ndarray
        The polynomial at s.

    Examples
    --------
    >>> horner([1.0, 2.0, 3.0], 2.0)  # 1 + 2 s + 3 s^2
    17.0
    """
    acc = c[-1]
    for ck in reversed(c[:-1]):
        acc = acc * s + ck
    return acc


def derivative(c: Sequence[Any]) -> list[Any]:
    """The coefficients of d/ds sum_k c_k s^k.

    Parameters
    ----------
    c : sequence
        Coefficients c_0 ... c_n.

    Returns
    -------
    list
        k c_k for k = 1 ... n (empty for a constant).
    """
    return [k * c[k] for k in range(1, len(c))]


def product(a: Sequence[Any], b: Sequence[Any]) -> list[Any]:
    """The coefficients of the product of two polynomials (mpmath).

    Parameters
    ----------
    a, b : sequence
        Coefficients, each at least one.

    Returns
    -------
    list of mpmath.mpf
        len(a) + len(b) - 1 coefficients.
    """
    out = [mpmath.mpf(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                out[i + j] += x * y
    return out


def integral(c: Sequence[Any], s: Any) -> Any:
    """int_0^s sum_k c_k x^k dx (mpmath).

    Parameters
    ----------
    c : sequence
        Coefficients c_0 ... c_n.
    s : mpmath.mpf
        The upper limit.

    Returns
    -------
    mpmath.mpf
        The integral, summed by ``mpmath.fsum``.
    """
    return mpmath.fsum(ck * s ** (k + 1) / (k + 1) for k, ck in enumerate(c))


def root(c: Sequence[Any], target: Any, h: Any) -> Any:
    """s between 0 and h with sum_k c_k s^k = target, at the current mpmath precision.

    Newton's method from the secant guess, kept inside the bracket by bisection (the polynomial
    minus ``target`` must change sign between 0 and h).

    Parameters
    ----------
    c : sequence of mpmath.mpf
        Coefficients c_0 ... c_n.
    target : mpmath.mpf
        The value sought.
    h : mpmath.mpf
        The other end of the bracket (either sign).

    Returns
    -------
    mpmath.mpf
        The root, to about 6 bits short of the working precision in units of h.

    Raises
    ------
    RuntimeError
        If the iteration does not converge in 200 steps.

    Examples
    --------
    >>> import mpmath
    >>> bool(abs(root([mpmath.mpf(-2), 0, 1], 0, mpmath.mpf(2)) - mpmath.sqrt(2)) < 1e-14)
    True
    """
    dc = derivative(c)
    a, fa = 0 * h, c[0] - target
    b = h
    fb = horner(c, h) - target
    s = h * (-fa) / (fb - fa)
    tol = abs(h) * mpmath.mpf(2) ** (-mpmath.mp.prec + 6)
    for _ in range(200):
        f = horner(c, s) - target
        if (f > 0) == (fa > 0):
            a, fa = s, f
        else:
            b = s
        d = horner(dc, s) if dc else 0
        nxt = s - f / d if d else (a + b) / 2
        if not (min(a, b) <= nxt <= max(a, b)):
            nxt = (a + b) / 2
        if abs(nxt - s) <= tol:
            return nxt
        s = nxt
    raise RuntimeError("numerics.taylor.root: Newton's method on the Taylor polynomial did not "
                       "converge")
