"""Chebyshev series: points, coefficients, trimming, and pointwise evaluation.

* ``cheb_nodes``, ``cheb_fit_matrix``, ``cheb_coefficients``: points of the first kind and the
  interpolant's coefficients through values there (DCT-II), the one definition the table
  builders, the K_s series and the integrators share. ``trim_trailing`` drops the trailing
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

__all__ = ["cheb_nodes", "cheb_fit_matrix", "cheb_coefficients", "trim_trailing",
           "cheb_to_monomial", "coefficient_difference", "clenshaw_take", "horner_take",
           "horner_take_pair"]


def cheb_nodes(n: int) -> np.ndarray:
    """Chebyshev points of the first kind, x_k = cos(pi (k + 1/2) / n), k = 0..n-1 (descending)."""
    return np.cos(np.pi * (np.arange(n) + 0.5) / n)


def cheb_fit_matrix(n: int) -> np.ndarray:
    """[degree, point]: the DCT-II matrix taking values at ``cheb_nodes(n)`` to the coefficients
    of their interpolant."""
    k = np.arange(n)
    m = np.cos(np.pi * np.outer(k, k + 0.5) / n) * (2.0 / n)
    m[0] *= 0.5
    return m


def cheb_coefficients(values, axis: int = 0) -> np.ndarray:
    """Coefficients of the interpolant through values at ``cheb_nodes(n)`` along ``axis``."""
    values = np.moveaxis(np.asarray(values, dtype=float), axis, 0)
    m = cheb_fit_matrix(values.shape[0])
    return np.moveaxis(np.tensordot(m, values, axes=1), 0, axis)


def trim_trailing(c: np.ndarray, keep) -> np.ndarray:
    """c without its trailing rows (and, for a 2-D array, columns) in which no entry is marked
    by the boolean array ``keep`` (of c's shape); at least one row and column stay."""
    keep = np.asarray(keep, dtype=bool)
    if c.ndim == 1:
        nz = np.flatnonzero(keep)
        return c[: (nz.max() + 1 if nz.size else 1)]
    rows, cols = np.flatnonzero(keep.any(axis=1)), np.flatnonzero(keep.any(axis=0))
    return c[: (rows.max() + 1 if rows.size else 1), : (cols.max() + 1 if cols.size else 1)]


@functools.lru_cache(maxsize=None)
def cheb_to_monomial(n: int) -> np.ndarray:
    """[power, Chebyshev degree]: the monomial coefficients of T_0 ... T_{n-1} on [-1, 1]."""
    m = np.zeros((n, n))
    for j in range(n):
        m[: j + 1, j] = np.polynomial.chebyshev.cheb2poly(np.eye(n)[j])[: j + 1]
    return m


def clenshaw_take(cT, idx, x):
    """sum_j cT[j, idx] T_j(x) pointwise: each point takes its coefficient row by index (no
    copy of a row per point)."""
    n = cT.shape[0]
    idx = np.asarray(idx)
    if idx.ndim >= 1 and idx.shape[-1] > 1 and idx.strides[-1] == 0:
        idx = idx[..., :1]  # a broadcast column: take once per line, broadcast in the arithmetic
    x2 = 2.0 * x
    b1 = cT[n - 1].take(idx)
    b2 = np.zeros_like(x2)
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


def horner_take(rows, idx, x):
    """sum_j rows[j, idx] x^j pointwise by Horner's rule, each step gathering the points'
    coefficients into one buffer and adding it in place (contiguous passes; gathering each
    point's whole row once and reading it by columns was slower). idx must be in range (the
    callers build it so): the gathers skip numpy's bounds check (mode="clip", about 25% faster)."""
    f = rows[-1].take(idx, mode="clip")
    tmp = np.empty_like(f)
    for j in range(rows.shape[0] - 2, -1, -1):
        f *= x
        f += rows[j].take(idx, out=tmp, mode="clip")
    return f


def horner_take_pair(rows, idx, x):
    """Two polynomials sharing their points, p = sum_j Re(rows[j, idx]) x^j and q with Im, by
    Horner's rule on the complex128 rows: each step gathers both coefficients of a point in one
    16-byte take (a quarter faster than two ``horner_take``; the multiply-adds run on the real
    view, against x repeated once per part, so no complex arithmetic is done). Returns (p, q),
    strided views of one buffer. idx must be in range, as for ``horner_take``."""
    f = rows[-1].take(idx, mode="clip")
    tmp = np.empty_like(f)
    fv, tv = f.view(np.float64), tmp.view(np.float64)
    x2 = np.repeat(x, 2)
    for j in range(rows.shape[0] - 2, -1, -1):
        fv *= x2
        rows[j].take(idx, out=tmp, mode="clip")
        fv += tv
    return fv[0::2], fv[1::2]


def coefficient_difference(new, old, floor: float = 0.0) -> float:
    """max |new - old| / max(max |new|, floor), both zero-padded to a common shape: how far a
    rebuilt coefficient array is from a stored one (trimming may differ)."""
    new, old = np.asarray(new, dtype=float), np.asarray(old, dtype=float)
    shape = tuple(max(p, q) for p, q in zip(new.shape, old.shape))
    a, b = np.zeros(shape), np.zeros(shape)
    a[tuple(slice(0, n) for n in new.shape)] = new
    b[tuple(slice(0, n) for n in old.shape)] = old
    return float(np.abs(a - b).max() / max(np.abs(a).max(), floor))
