"""Integrals of a function of (tau, lambda) over a contact piece [A, B], through the smoothstep map.

* ``contact_integral``: (the per-point rule; the kernels use ``cumulative_integral``, and the
  tests use this one as its second route) tau = A + (B - A) v^2 (3 - 2 v) and Gauss-Legendre
  in v. The map's derivative vanishes at both ends, which turns the endpoint behaviours of the
  force, (tau - A)^{3/2} at the start and the end of contact and (pi/omega0 - tau)^{3/2} where
  the zeroth-order sqrt terms switch off, into analytic integrands in v, so Gauss-Legendre
  converges geometrically.
* ``cumulative_integral``: the same integrand in v, interpolated at N_CHEB Chebyshev points once
  per lambda and integrated as a Chebyshev series, then evaluated at every requested upper limit.
  A history of P times costs N_CHEB integrand evaluations per lambda instead of N_GL per time.
  ``cumulative_rows`` is the same with rows given by index (``zener_sym.ham.spectral`` uses it).
* ``smoothstep_rule``: that Chebyshev rule in v as matrices, for n points (cached): the one
  definition these functions and ``zener_sym.ham.higher`` (on theta pieces) share.
"""
from __future__ import annotations

import functools
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray, RealArrayLike
from .chebyshev import cheb_nodes, chebint_matrix, clenshaw_take
from .maps import smoothstep, smoothstep_inverse, smoothstep_slope

__all__ = ["N_GL", "N_CHEB", "SmoothstepRule", "smoothstep_rule", "contact_integral",
           "cumulative_integral", "cumulative_rows"]

N_GL = 48
_gx, _gw = np.polynomial.legendre.leggauss(N_GL)
_V = (1.0 + _gx) / 2.0
_WV = _gw / 2.0
_MAP = smoothstep(_V)
_DMAP = smoothstep_slope(_V)


def contact_integral(fun: Callable[[FloatArray, FloatArray], FloatArray], A: RealArrayLike,
                     B: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """integral_A^B fun(tau, lam) dtau per point, smoothstep map and Gauss-Legendre (N_GL nodes).

    Parameters
    ----------
    fun : callable
        fun(tau, lam) on arrays, the nodes on a trailing axis.
    A, B, lam : array_like
        The limits (A <= B; B < A gives 0) and lambda, broadcast together.

    Returns
    -------
    ndarray
        The integrals, the broadcast shape.
    """
    A_, B_, lam_ = np.broadcast_arrays(np.asarray(A, float), np.asarray(B, float),
                                       np.asarray(lam, float))
    L = np.maximum(B_ - A_, 0.0)
    t = A_[..., None] + L[..., None] * _MAP
    vals = fun(t, lam_[..., None])
    out: FloatArray = L * np.sum(vals * (_DMAP * _WV), axis=-1)
    return out


class SmoothstepRule(NamedTuple):
    """The Chebyshev rule in the smoothstep variable v of a piece (``smoothstep_rule``).

    On a piece [A, B] the points are tau_j = A + (B - A) ``map[j]``; for g_j = f(tau_j) (B - A)
    ``slope[j]``, ``fit @ g`` are the Chebyshev coefficients in x = 2 v - 1 of the integrand in
    v, ``cumulative @ g`` the integrals from A to each point and ``end @ g`` the one to B.
    """

    #: the Chebyshev points of the first kind, descending (``cheb_nodes``)
    x: FloatArray
    #: smoothstep(v) and its slope at v = (1 + x) / 2
    map: FloatArray
    slope: FloatArray
    #: values -> Chebyshev coefficients, [degree, point]
    fit: FloatArray
    #: values -> integral from the piece's start to each point, [point, point]
    cumulative: FloatArray
    #: values -> integral over the whole piece, [point]
    end: FloatArray


@functools.lru_cache(maxsize=None)
def smoothstep_rule(n: int) -> SmoothstepRule:
    """The smoothstep-mapped Chebyshev rule of n points (cached per n).

    Parameters
    ----------
    n : int
        Number of Chebyshev points, >= 1.

    Returns
    -------
    SmoothstepRule
        Its points and matrices (einsum products: no BLAS, whose blocking and threads would
        make the digits depend on the machine's load).
    """
    x = cheb_nodes(n)
    v = (1.0 + x) / 2.0
    vander = np.polynomial.chebyshev.chebvander
    fit = np.asarray(np.linalg.inv(vander(x, n - 1)), dtype=np.float64)
    intc = np.einsum("ij,jk->ik", chebint_matrix(n), fit)  # values -> antiderivative in x
    # dv = dx / 2: the halves turn integrals in x into integrals in v
    cumulative = np.einsum("ij,jk->ik", vander(x, n), intc) * 0.5
    end = np.einsum("ij,jk->ik", vander(np.array([1.0]), n), intc)[0] * 0.5
    return SmoothstepRule(x, smoothstep(v), smoothstep_slope(v), fit, cumulative, end)


N_CHEB = 64
_RULE = smoothstep_rule(N_CHEB)
_CMAP, _CDMAP, _CFIT = _RULE.map, _RULE.slope, _RULE.fit


def cumulative_integral(fun: Callable[[FloatArray, FloatArray], FloatArray], A: RealArrayLike,
                        B: RealArrayLike, lam: RealArrayLike, X: RealArrayLike) -> FloatArray:
    """integral_A^X fun(tau, lam) dtau for A <= X <= B, where A and B depend on lam only.

    The integrand in the smoothstep variable v (see ``contact_integral``) is interpolated at
    N_CHEB Chebyshev points for each distinct lam and integrated as a Chebyshev series, which is
    then evaluated at every X of that lam: no Python loop over points or over lam.

    Parameters
    ----------
    fun : callable
        fun(tau, lam) on arrays: tau of shape (R, N_CHEB), lam of shape (R, 1).
    A, B, lam, X : array_like
        The piece's ends, lambda and the upper limits, broadcast together.

    Returns
    -------
    ndarray
        The integrals, the broadcast shape.
    """
    A_, B_, lam_, X_ = np.broadcast_arrays(*(np.asarray(a, float) for a in (A, B, lam, X)))
    lam_u, first, inv = np.unique(lam_.ravel(), return_index=True, return_inverse=True)
    return cumulative_rows(lambda t, r: fun(t, lam_u[r]), A_.ravel()[first], B_.ravel()[first],
                           inv.reshape(X_.shape), X_)


def cumulative_rows(fun: Callable[[FloatArray, npt.NDArray[np.intp]], FloatArray],
                    A: RealArrayLike, B: RealArrayLike, rows: npt.ArrayLike,
                    X: RealArrayLike) -> FloatArray:
    """integral_{A[r]}^X fun(tau, r) dtau at each X, with r = ``rows`` there (A[r] <= X <= B[r]).

    One Chebyshev antiderivative per row, as in ``cumulative_integral``.

    Parameters
    ----------
    fun : callable
        fun(t, r) gets t of shape (R, N_CHEB) and r of shape (R, 1) (row indices into A and B).
    A, B : array_like
        1-D: each row's piece.
    rows : array_like of int
        Each point's row.
    X : array_like
        The upper limits, rows' shape.

    Returns
    -------
    ndarray
        The integrals, rows' shape.
    """
    A_, B_ = np.asarray(A, float), np.asarray(B, float)
    rows_ = np.asarray(rows, dtype=np.intp)
    X_ = np.asarray(X, float)
    R = np.arange(A_.size)
    L_u = np.maximum(B_ - A_, 0.0)
    t = A_[:, None] + L_u[:, None] * _CMAP
    g = fun(t, R[:, None]) * (L_u[:, None] * _CDMAP)
    # Chebyshev coefficients in x = 2 v - 1, one row per lambda; einsum rather than a BLAS matmul,
    # whose blocking would make a lambda's digits depend on which other lambdas share the call
    coef = np.einsum("uj,kj->uk", g, _CFIT)
    icoef = np.polynomial.chebyshev.chebint(coef, lbnd=-1.0, scl=0.5, axis=1)
    L = L_u.take(rows_)
    with np.errstate(invalid="ignore", divide="ignore"):
        frac = np.where(L > 0.0, (X_ - A_.take(rows_)) / L, 0.0)
    x = 2.0 * smoothstep_inverse(frac) - 1.0
    icT = np.ascontiguousarray(icoef.T)
    at_a = clenshaw_take(icT, R, np.full(R.size, -1.0))  # same arithmetic: exactly 0 at X = A
    out = clenshaw_take(icT, rows_, x) - at_a.take(rows_)
    res: FloatArray = np.where(L > 0.0, out, 0.0)
    return res
