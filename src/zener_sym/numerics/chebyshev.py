"""Chebyshev series: points, coefficients, trimming, and pointwise evaluation.

* ``cheb_nodes``, ``cheb_fit_matrix``, ``cheb_coefficients``: points of the first kind and the
  interpolant's coefficients through values there (DCT-II), the one definition the table
  builders, the K_s series and the integrators share. ``first_kind``: the same points ascending,
  with the inverse Vandermonde matrix the HAM solvers fit with; ``chebint_matrix``: coefficients
  to the coefficients of the antiderivative from -1. ``trim_trailing`` drops the trailing
  coefficients below a fraction of the largest; ``cheb_to_monomial`` converts to monomials.
* ``clenshaw_take``: Chebyshev series evaluated pointwise, each point picking its coefficient row
  by index from a transposed table (no per-point copy of a row).
* ``horner_take``: the same for monomial coefficients (Horner's rule), for short pieces where
  monomials are well conditioned; about half the passes of Clenshaw. ``horner_take_pair``: two
  such polynomials on the same points, their coefficients gathered together.
"""
from __future__ import annotations

import functools

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray, RealArrayLike

__all__ = ["cheb_nodes", "cheb_fit_matrix", "cheb_coefficients", "first_kind", "chebint_matrix",
           "trim_trailing",
           "cheb_to_monomial", "coefficient_difference", "clenshaw_take", "horner_take",
           "horner_take_pair"]


def cheb_nodes(n: int) -> FloatArray:
    """Chebyshev points of the first kind, x_k = cos(pi (k + 1/2) / n), k = 0..n-1 (descending).

    Parameters
    ----------
    n : int
        Number of points, >= 1.

    Returns
    -------
    ndarray
        The n points in (-1, 1), descending.
    """
    x: FloatArray = np.cos(np.pi * (np.arange(n) + 0.5) / n)
    return x


def cheb_fit_matrix(n: int) -> FloatArray:
    """The DCT-II matrix taking values at ``cheb_nodes(n)`` to their interpolant's coefficients.

    Parameters
    ----------
    n : int
        Number of points (and of coefficients), >= 1.

    Returns
    -------
    ndarray
        [degree, point], n x n.
    """
    k = np.arange(n)
    m: FloatArray = np.cos(np.pi * np.outer(k, k + 0.5) / n) * (2.0 / n)
    m[0] *= 0.5
    return m


def first_kind(n: int) -> tuple[FloatArray, FloatArray]:
    """Chebyshev points of the first kind, ascending, and the values -> coefficients matrix.

    The matrix is the inverse of the Vandermonde matrix at the points (not the DCT-II of
    ``cheb_fit_matrix``: the same interpolant, other rounding, which the HAM solvers' digits keep).

    Parameters
    ----------
    n : int
        Number of points (and of coefficients), >= 1.

    Returns
    -------
    x : ndarray
        The n points in (-1, 1), ascending.
    fit : ndarray
        [degree, point], n x n.
    """
    x = cheb_nodes(n)[::-1].copy()
    fit = np.asarray(np.linalg.inv(np.polynomial.chebyshev.chebvander(x, n - 1)), dtype=np.float64)
    return x, fit


def chebint_matrix(n: int) -> FloatArray:
    """The matrix taking n Chebyshev coefficients to those of the antiderivative that is 0 at -1.

    Parameters
    ----------
    n : int
        Number of coefficients, >= 1.

    Returns
    -------
    ndarray
        [degree, degree], (n + 1) x n.
    """
    m = np.asarray(np.polynomial.chebyshev.chebint(np.eye(n), lbnd=-1.0, axis=0), dtype=np.float64)
    return m


def cheb_coefficients(values: RealArrayLike, axis: int = 0) -> FloatArray:
    """Coefficients of the interpolant through values at ``cheb_nodes(n)`` along ``axis``.

    Parameters
    ----------
    values : array_like
        Values at the n Chebyshev points along ``axis``.
    axis : int
        The axis of the points.

    Returns
    -------
    ndarray
        Chebyshev coefficients (degree 0 ... n-1) along ``axis``, the other axes unchanged.
    """
    vals = np.moveaxis(np.asarray(values, dtype=float), axis, 0)
    m = cheb_fit_matrix(vals.shape[0])
    c: FloatArray = np.moveaxis(np.tensordot(m, vals, axes=1), 0, axis)
    return c


def trim_trailing(c: FloatArray, keep: npt.ArrayLike) -> FloatArray:
    """c without its trailing rows (and, for a 2-D array, columns) in which no entry is marked.

    Parameters
    ----------
    c : ndarray
        1-D or 2-D coefficients.
    keep : array_like of bool
        c's shape: the entries that matter.

    Returns
    -------
    ndarray
        A leading slice of c; at least one row and column stay.
    """
    mark = np.asarray(keep, dtype=bool)
    if c.ndim == 1:
        nz = np.flatnonzero(mark)
        return c[: (nz.max() + 1 if nz.size else 1)]
    rows, cols = np.flatnonzero(mark.any(axis=1)), np.flatnonzero(mark.any(axis=0))
    return c[: (rows.max() + 1 if rows.size else 1), : (cols.max() + 1 if cols.size else 1)]


@functools.lru_cache(maxsize=None)
def cheb_to_monomial(n: int) -> FloatArray:
    """The monomial coefficients of T_0 ... T_{n-1} on [-1, 1] (cached per n).

    Parameters
    ----------
    n : int
        Number of Chebyshev polynomials, >= 1.

    Returns
    -------
    ndarray
        [power, Chebyshev degree], n x n, upper triangular.
    """
    m = np.zeros((n, n))
    for j in range(n):
        m[: j + 1, j] = np.polynomial.chebyshev.cheb2poly(np.eye(n)[j])[: j + 1]
    return m


def clenshaw_take(cT: FloatArray, idx: npt.ArrayLike, x: FloatArray) -> FloatArray:
    """sum_j cT[j, idx] T_j(x) pointwise by Clenshaw's recurrence.

    Each point takes its coefficient row by index (no copy of a row per point).

    Parameters
    ----------
    cT : ndarray
        [degree, row]: the transposed coefficient table, at least 2 degrees.
    idx : array_like of int
        Each point's row (broadcast against x; a broadcast column is taken once per line).
    x : ndarray
        The points, in [-1, 1].

    Returns
    -------
    ndarray
        The series at the points, x's (broadcast) shape.
    """
    n = cT.shape[0]
    idx = np.asarray(idx)
    if idx.ndim >= 1 and idx.shape[-1] > 1 and idx.strides[-1] == 0:
        idx = idx[..., :1]  # a broadcast column: take once per line, broadcast in the arithmetic
    x2 = 2.0 * x
    b1: FloatArray = cT[n - 1].take(idx)
    b2: FloatArray = np.zeros_like(x2)
    b1 = b1 + b2  # to the points' shape
    for j in range(n - 2, 0, -1):
        b = x2 * b1
        b -= b2
        b += cT[j].take(idx)
        b1, b2 = b, b1
    out = x * b1
    out -= b2
    out += cT[0].take(idx)
    return out


def horner_take(rows: FloatArray, idx: npt.NDArray[np.intp], x: FloatArray) -> FloatArray:
    """sum_j rows[j, idx] x^j pointwise by Horner's rule.

    Each step gathers the points' coefficients into one buffer and adds it in place
    (contiguous passes; gathering each point's whole row once and reading it by columns was
    slower). idx must be in range (the callers build it so): the gathers skip numpy's bounds
    check (mode="clip", about 25% faster).

    Parameters
    ----------
    rows : ndarray
        [power, row]: monomial coefficients.
    idx : ndarray of intp
        Each point's row, in range.
    x : ndarray
        The points (idx's shape).

    Returns
    -------
    ndarray
        The polynomials at the points.
    """
    f: FloatArray = rows[-1].take(idx, mode="clip")
    tmp = np.empty_like(f)
    for j in range(rows.shape[0] - 2, -1, -1):
        f *= x
        f += rows[j].take(idx, out=tmp, mode="clip")
    return f


def horner_take_pair(rows: npt.NDArray[np.complex128], idx: npt.NDArray[np.intp],
                     x: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Two polynomials sharing their points, p = sum_j Re(rows[j, idx]) x^j and q with Im.

    Horner's rule on the complex128 rows: each step gathers both coefficients of a point in one
    16-byte take (a quarter faster than two ``horner_take``; the multiply-adds run on the real
    view, against x repeated once per part, so no complex arithmetic is done). idx must be in
    range, as for ``horner_take``.

    Parameters
    ----------
    rows : ndarray of complex128
        [power, row]: p's coefficients in the real parts, q's in the imaginary parts.
    idx : ndarray of intp
        Each point's row, in range (1-D).
    x : ndarray
        The points (1-D, idx's shape).

    Returns
    -------
    p, q : ndarray
        The two polynomials at the points: strided views of one buffer.
    """
    f = rows[-1].take(idx, mode="clip")
    tmp = np.empty_like(f)
    fv: FloatArray = f.view(np.float64)
    tv: FloatArray = tmp.view(np.float64)
    x2 = np.repeat(x, 2)
    for j in range(rows.shape[0] - 2, -1, -1):
        fv *= x2
        rows[j].take(idx, out=tmp, mode="clip")
        fv += tv
    return fv[0::2], fv[1::2]


def coefficient_difference(new: RealArrayLike, old: RealArrayLike, floor: float = 0.0) -> float:
    """max |new - old| / max(max |new|, floor), both zero-padded to a common shape.

    How far a rebuilt coefficient array is from a stored one (trimming may differ).

    Parameters
    ----------
    new, old : array_like
        Coefficient arrays of the same number of dimensions.
    floor : float
        Smallest denominator (so that a zero ``new`` does not divide by zero).

    Returns
    -------
    float
        The relative difference.
    """
    a_new, a_old = np.asarray(new, dtype=float), np.asarray(old, dtype=float)
    shape = tuple(max(p, q) for p, q in zip(a_new.shape, a_old.shape))
    a, b = np.zeros(shape), np.zeros(shape)
    a[tuple(slice(0, n) for n in a_new.shape)] = a_new
    b[tuple(slice(0, n) for n in a_old.shape)] = a_old
    return float(np.abs(a - b).max() / max(np.abs(a).max(), floor))
