"""Numerical glue for the generated HAM kernels: a stable P3, vectorised root finding, contact
integrals. Hand-written (algorithms, not formulas); the generated numpy modules call it (numpy only; the
mpmath counterparts are in ``zener_sym.ham.mp``).

* ``p3(x) = (sin x - x cos x) / x^3``: the elementary part of delta1 is written with it, so that
  tau -> 0 and omega0 -> 0 lose no digits. Series below |x| < 1/2, direct formula above.
* ``first_root``: the first sign change of f on a scan grid, then bisection to a few ulps, all
  lambda values at once (no Python loop over points; the loop is over bisection steps).
* ``contact_integral``: (the per-point rule; the kernels now use ``cumulative_integral``, and the
  tests use this one as its second route) integral of a function of (tau, lam) over [A, B] with the
  smoothstep map
  tau = A + (B - A) v^2 (3 - 2 v) and Gauss-Legendre in v. The map's derivative vanishes at both
  ends, which turns the endpoint behaviours of the force, (tau - A)^{3/2} at the start and the end
  of contact and (pi/omega0 - tau)^{3/2} where the zeroth-order sqrt terms switch off, into
  analytic integrands in v, so Gauss-Legendre converges geometrically.
* ``cumulative_integral``: the same integrand in v, interpolated at N_CHEB Chebyshev points once
  per lambda and integrated as a Chebyshev series, then evaluated at every requested upper limit.
  A history of P times costs N_CHEB integrand evaluations per lambda instead of N_GL per time.
  ``cumulative_rows`` is the same with rows given by index (``zener_sym.ham.spectral`` uses it).
* ``horner_take``: the same for monomial coefficients (Horner's rule), for short pieces where
  monomials are well conditioned; about half the passes of Clenshaw. ``horner_take_pair``: two
  such polynomials on the same points, their coefficients gathered together.
* ``clenshaw_take``: Chebyshev series evaluated pointwise, each point picking its coefficient row
  by index from a transposed table (no per-point copy of a row).
* ``p3`` evaluates its series only at the points that need it (|x| < 1/2).
* ``half_wave_sin``: the sine's first half wave, vectorized (numpy's float64 sine is a scalar
  loop on this build: about 8 ns a point against about 3).
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["p3", "first_root", "contact_integral", "cumulative_integral", "cumulative_rows",
           "clenshaw_take", "horner_take", "horner_take_pair", "half_wave_sin", "N_GL", "N_CHEB"]

# Taylor coefficients of P3: sum_j (-1)^j 2 (j + 1) x^{2j} / (2j + 3)!
_P3_COEF = [(-1) ** j * 2.0 * (j + 1) / math.factorial(2 * j + 3) for j in range(12)]


def p3(x):
    """(sin x - x cos x)/x^3 for a float array, accurate to rounding (P3(0) = 1/3)."""
    x = np.asarray(x, dtype=float)
    shape = x.shape
    x = x.reshape(-1)
    small = np.abs(x) < 0.5
    xs = np.where(small, 1.0, x)
    out = (np.sin(xs) - xs * np.cos(xs)) / (xs * xs * xs)
    if small.any():  # the series only where it is needed: most points of a history are not small
        x2 = x[small] ** 2
        series = np.zeros_like(x2)
        for c in reversed(_P3_COEF):  # Horner in x^2; 12 terms reach 1e-19 at |x| = 1/2
            series = series * x2 + c
        out[small] = series
    return out.reshape(shape)


def first_root(fun, lam, lo, hi, n_scan=64, what="root"):
    """First zero of fun(tau, lam) in (lo, hi], per lambda (1-D arrays), fun(lo) > 0 assumed.

    Scans about 2 n_scan cells (uniform and geometric from lo), then bisects the first cell where fun <= 0. Raises ValueError, naming
    lambda, if there is no sign change.
    """
    lam = np.asarray(lam, dtype=float)
    lo = np.asarray(lo, dtype=float)
    hi = np.asarray(hi, dtype=float)
    # uniform cells plus geometric ones near lo: omega0 -> 0 stretches [lo, hi] to ~1/omega0
    # while the roots stay at tau = O(1)
    v = np.unique(np.concatenate([np.linspace(0.0, 1.0, n_scan + 1), np.geomspace(1e-10, 1.0, n_scan)]))
    grid = lo[:, None] + (hi - lo)[:, None] * v
    vals = fun(grid, lam[:, None])
    neg = vals <= 0.0
    neg[:, 0] = False
    found = neg.any(axis=1)
    if not found.all():
        bad = lam[~found][0]
        raise ValueError(f"no {what} found between tau = {lo[~found][0]:.6g} and "
                         f"{hi[~found][0]:.6g} at lambda = {bad!r}")
    j = np.argmax(neg, axis=1)
    rows = np.arange(lam.size)
    a, b = grid[rows, j - 1], grid[rows, j]
    for _ in range(200):
        mid = 0.5 * (a + b)
        done = (mid <= a) | (mid >= b)
        if done.all():
            break
        fm = fun(mid, lam)
        pos = fm > 0.0
        a = np.where(pos & ~done, mid, a)
        b = np.where(~pos & ~done, mid, b)
    return 0.5 * (a + b)


N_GL = 48
_gx, _gw = np.polynomial.legendre.leggauss(N_GL)
_V = (1.0 + _gx) / 2.0
_WV = _gw / 2.0
_MAP = _V * _V * (3.0 - 2.0 * _V)
_DMAP = 6.0 * _V * (1.0 - _V)


def contact_integral(fun, A, B, lam):
    """integral_A^B fun(tau, lam) dtau for arrays A <= B, lam (same shape), smoothstep + GL."""
    A, B, lam = np.broadcast_arrays(np.asarray(A, float), np.asarray(B, float),
                                    np.asarray(lam, float))
    L = np.maximum(B - A, 0.0)
    t = A[..., None] + L[..., None] * _MAP
    vals = fun(t, lam[..., None])
    return L * np.sum(vals * (_DMAP * _WV), axis=-1)


N_CHEB = 64
_CX = np.cos(np.pi * (np.arange(N_CHEB) + 0.5) / N_CHEB)  # Chebyshev points of the first kind
_CV = (1.0 + _CX) / 2.0
_CMAP = _CV * _CV * (3.0 - 2.0 * _CV)
_CDMAP = 6.0 * _CV * (1.0 - _CV)
_CFIT = np.linalg.inv(np.polynomial.chebyshev.chebvander(_CX, N_CHEB - 1))


def _smoothstep_inverse(x):
    """v in [0, 1] with v^2 (3 - 2 v) = x, for x in [0, 1]."""
    return 0.5 - np.sin(np.arcsin(np.clip(1.0 - 2.0 * x, -1.0, 1.0)) / 3.0)


def cumulative_integral(fun, A, B, lam, X):
    """integral_A^X fun(tau, lam) dtau for A <= X <= B, where A and B depend on lam only.

    The integrand in the smoothstep variable v (see ``contact_integral``) is interpolated at
    N_CHEB Chebyshev points for each distinct lam and integrated as a Chebyshev series, which is
    then evaluated at every X of that lam: no Python loop over points or over lam.
    """
    A, B, lam, X = np.broadcast_arrays(*(np.asarray(a, float) for a in (A, B, lam, X)))
    lam_u, first, inv = np.unique(lam.ravel(), return_index=True, return_inverse=True)
    return cumulative_rows(lambda t, r: fun(t, lam_u[r]), A.ravel()[first], B.ravel()[first],
                           inv.reshape(X.shape), X)


def cumulative_rows(fun, A, B, rows, X):
    """integral_{A[r]}^X fun(tau, r) dtau at each X, with r = ``rows`` there (A[r] <= X <= B[r]).

    ``fun(t, r)`` gets t of shape (R, N_CHEB) and r of shape (R, 1) (row indices into A and B).
    One Chebyshev antiderivative per row, as in ``cumulative_integral``.
    """
    A, B = np.asarray(A, float), np.asarray(B, float)
    rows = np.asarray(rows, dtype=np.intp)
    X = np.asarray(X, float)
    R = np.arange(A.size)
    L_u = np.maximum(B - A, 0.0)
    t = A[:, None] + L_u[:, None] * _CMAP
    g = fun(t, R[:, None]) * (L_u[:, None] * _CDMAP)
    # Chebyshev coefficients in x = 2 v - 1, one row per lambda; einsum rather than a BLAS matmul,
    # whose blocking would make a lambda's digits depend on which other lambdas share the call
    coef = np.einsum("uj,kj->uk", g, _CFIT)
    icoef = np.polynomial.chebyshev.chebint(coef, lbnd=-1.0, scl=0.5, axis=1)
    L = L_u.take(rows)
    with np.errstate(invalid="ignore", divide="ignore"):
        frac = np.where(L > 0.0, (X - A.take(rows)) / L, 0.0)
    x = 2.0 * _smoothstep_inverse(frac) - 1.0
    icT = np.ascontiguousarray(icoef.T)
    at_a = clenshaw_take(icT, R, np.full(R.size, -1.0))  # same arithmetic: exactly 0 at X = A
    out = clenshaw_take(icT, rows, x) - at_a.take(rows)
    return np.where(L > 0.0, out, 0.0)


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


# Taylor coefficients of sin(y) / y in s = y^2, (-1)^k / (2k + 1)!: on |y| <= pi/2 the first one
# dropped (k = 11) weighs (pi/2)^22 / 23! < 1e-18.
_SIN_COEF = [(-1) ** k / math.factorial(2 * k + 1) for k in range(11)]
# pi = _PI_HI + _PI_LO: _PI_HI - theta is exact for theta in [pi/2, pi] (Sterbenz), so
# pi - theta keeps its relative accuracy up to theta = pi
_PI_HI = math.pi
_PI_LO = 1.2246467991473532e-16  # pi - math.pi; tests derive it with mpmath


def half_wave_sin(theta):
    """sin(theta) for 0 <= theta <= pi and 0 beyond: the first half wave, where the zeroth-order
    HAM compression delta0 (35) is positive (its contact ends at omega0 tau = pi, Eq. 54).

    Vectorized: y = min(theta, pi - theta) in [0, pi/2] (pi in two parts), clipped at 0 past pi,
    then y (1 + s P(s)) with s = y^2 by Horner's rule on the Taylor coefficients. Within 3 ulp
    of the correctly rounded sine on [0, pi] (tests/test_ham_chebyshev.py, against mpmath). theta must be >= 0 (a phase
    omega0 tau); negative theta is a ValueError.
    """
    theta = np.asarray(theta, dtype=float)
    if theta.size and not theta.min() >= 0:  # a NaN fails too
        raise ValueError("half_wave_sin: theta must be >= 0 (and not NaN)")
    y = _PI_HI - theta
    y += _PI_LO
    np.minimum(y, theta, out=y)
    np.maximum(y, 0.0, out=y)  # past pi: 0
    s = y * y
    p = np.full_like(s, _SIN_COEF[-1])
    for c in _SIN_COEF[-2::-1]:
        p *= s
        p += c
    p *= y
    return p
