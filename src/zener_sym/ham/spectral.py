"""Fast first-order HAM solution: delta0 + delta1 per lambda as piecewise Chebyshev series.

Why: the generated kernel ``ham1_numpy.delta`` costs three 64-node Gauss-Jacobi quadratures per
point (the square-root integrals K_cc, K_sc, K_ss), and its contact end two scans and bisections
on that kernel. A history asks for many times at few lambda values, so this module pays the
quadrature once per lambda and then evaluates polynomials.

How, for each lambda (all lambda values at once, no Python loop over them or over points):

1. Zeroth-order contact, 0 <= tau <= pi/omega0, in the variable t in [0, 1] with
   theta = omega0 tau = pi sin^2(pi t / 2). The map is quadratic at both ends, which turns the
   endpoint behaviours theta^{3/2} and (pi - theta)^{3/2} of the K integrals into analytic
   functions of t. The integrands of K are sampled at N_GLOBAL Chebyshev points in t and
   integrated as one Chebyshev series (a constant N x N matrix), which gives K at any t.
2. delta from the generated formula ``ham1_numpy.delta_from_K`` at the same points, fitted by
   one series, which a constant matrix re-expands as series of degree N_LOCAL - 1 on N_PIECES
   equal pieces of [0, 1] (short pieces, low degree: a point costs N_LOCAL steps of Clenshaw's
   recurrence instead of N_GLOBAL).
3. End of contact tau_d: the first sign change of delta on a grid, then safeguarded Newton on the
   series (when tau_d <= pi/omega0) or on the closed form with K frozen at pi (beyond, Eq. 42's
   continuation, see ``zener_sym.models.ham``).
4. Past pi/omega0 and up to tau_d, one more series in tau itself (the frozen-K formula is
   analytic there).

Each row checks itself: a lambda whose series (the global one and every piece) do not decay to
TAIL_TOL of its largest compression is marked ``ok = False``; callers use the quadrature kernels
for those rows. That happens from lambda = 2.414 on (a = beta/(2 omega0) = 3.6), as omega0 -> 0
near the critical lambda makes exp(-beta tau) too steep for N_GLOBAL points; rows with a above
A_MAX are not tried at all. Agreement with the quadrature kernels and with the mpmath closed forms
is pinned in tests/test_ham_spectral.py; the speed is measured by ``zener-sym bench``.

All linear algebra is done row by row (batched matmuls), so a lambda's digits do not depend on
which other lambda values share the call.
"""
from __future__ import annotations

import types
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt

from ..numerics.chebyshev import chebint_matrix, clenshaw_take, first_kind
from ..numerics.integrate import cumulative_rows
from ..numerics.maps import sine_squared, sine_squared_inverse
from ..typing import FloatArray, RealArrayLike

#: integer row indices into a Ham1Series
IntArray = npt.NDArray[np.intp]

__all__ = ["Ham1Series", "rows_of", "summary_numpy", "N_GLOBAL", "N_PIECES", "N_LOCAL", "A_MAX", "TAIL_TOL",
           "SPAN_PAST"]

_C = np.polynomial.chebyshev

#: Chebyshev points for the K integrals on the whole zeroth-order contact.
N_GLOBAL = 64
#: Pieces of [0, 1] in t, and the number of coefficients of delta's series on each.
N_PIECES = 16
N_LOCAL = 16
#: Largest decay rate a = beta / (2 omega0) tried; the truncation check stops at a = 3.6 anyway.
A_MAX = 20.0
#: A row is used only if the last two coefficients of its series are below this times max|delta|.
TAIL_TOL = 5e-14
#: Past pi/omega0 the series covers (1 + SPAN_PAST) pi/omega0: the first-order contact ends by
#: 1.09 pi/omega0 for 0 <= lambda <= 2.414; a row that needs more goes to the kernels.
SPAN_PAST = 0.25
#: Grid cells per piece (and past pi/omega0) for the first sign change of delta.
_SCAN = 8


# Global series for K: integrand values at the nodes -> K at any t, through a fixed matrix.
_GX, _GFIT = first_kind(N_GLOBAL)
_GT = 0.5 * (1.0 + _GX)
_GTH, _GDTH = sine_squared(_GT)
_GS, _GC = np.sin(_GTH), np.cos(_GTH)
# integrand factor common to the three K (dtheta/dx = dtheta/dt / 2), and g(theta) per K
_GBASE = np.sqrt(_GS) * 0.5 * _GDTH
_GG = np.stack([_GC * _GC, _GS * _GC, _GS * _GS])
_GINT = chebint_matrix(N_GLOBAL)  # coefficients of the antiderivative
_GINTFIT = _GINT @ _GFIT  # integrand values at the nodes -> coefficients of K


def _k_matrix(t: FloatArray) -> FloatArray:
    """Matrix taking integrand values at the N_GLOBAL nodes to K at the points t (in [0, 1])."""
    out: FloatArray = (_C.chebvander(2.0 * np.asarray(t) - 1.0, N_GLOBAL) @ _GINTFIT).T
    return out


_GKP = _k_matrix(np.append(_GT, 1.0))  # (N, N + 1): K at the global nodes, then at pi
# Local pieces: Chebyshev points of each piece, and the global -> piece coefficients matrix
_LX, _LFIT = first_kind(N_LOCAL)
_LT = (np.arange(N_PIECES)[:, None] + 0.5 * (1.0 + _LX)) / N_PIECES  # (P, n) t of the nodes
_REEXPAND = (_C.chebvander(2.0 * _LT.ravel() - 1.0, N_GLOBAL - 1).T
             @ np.kron(np.eye(N_PIECES), _LFIT.T))  # (N, P n)
# scan grid: _SCAN points per piece from its left end, in local x
_SX = -1.0 + 2.0 * np.arange(_SCAN) / _SCAN
_SV = _C.chebvander(_SX, N_LOCAL - 1).T  # (n, _SCAN)
_SV2 = _C.chebvander(-1.0 + 2.0 * np.arange(_SCAN + 1) / _SCAN, N_LOCAL - 1).T  # both ends
_DER = np.vstack([_C.chebder(np.eye(N_LOCAL), axis=0), np.zeros((1, N_LOCAL))])  # d/dx, (n, n)


def _rowmul(A: npt.NDArray[np.floating[Any]], B: npt.NDArray[np.floating[Any]]) -> FloatArray:
    """A @ B over the last axis of A, one row at a time (a batched matmul): a row's digits do
    not depend on which other rows share the call, as they may in one blocked BLAS product."""
    out: FloatArray = np.matmul(A[..., None, :], B)[..., 0, :]
    return out


def _h1() -> types.SimpleNamespace:
    from .runtime_numpy import ham1

    return ham1


class Ham1Series:
    """Piecewise Chebyshev series of the first-order solution for sorted, distinct lambda values.

    Attributes (arrays over the rows): ``lam``, ``k``, ``beta``, ``omega0``, ``tpi`` = pi/omega0,
    ``tau_d`` (end of contact), ``ok`` (the row passed its checks; other rows hold no series and
    NaN in ``tau_d``), ``K_pi`` (3 x rows, K at theta = pi).
    """

    lam: FloatArray
    k: FloatArray
    beta: FloatArray
    omega0: FloatArray
    tpi: FloatArray
    tau_d: FloatArray
    ok: npt.NDArray[np.bool_]
    K_pi: FloatArray

    def __init__(self, lam: RealArrayLike) -> None:
        h1 = _h1()
        la: FloatArray = np.asarray(lam, dtype=float)
        self.lam = la
        self.k, self.beta, self.omega0 = h1.params(la)
        self.tpi = np.pi / self.omega0
        U, P, n = la.size, N_PIECES, N_LOCAL
        a = self.beta / (2.0 * self.omega0)
        tried = a <= A_MAX
        # 1. K at the global nodes and at pi, from the integrand at the global nodes
        f = np.exp(-np.minimum(a, A_MAX)[:, None] * _GTH) * _GBASE  # (U, N)
        fg = f[None, :, :] * _GG[:, None, :]  # (3, U, N)
        self._fg = fg
        K = _rowmul(fg, _GKP)  # (3, U, N + 1)
        K, self.K_pi = K[:, :, :-1], np.ascontiguousarray(K[:, :, -1])
        # 2. delta at the global nodes, its series, re-expanded on the pieces
        tau_g = _GTH[None, :] / self.omega0[:, None]
        d = h1.delta_from_K(tau_g, la[:, None], *K)  # lam as a column: params once per row
        gcoef = _rowmul(d, _GFIT.T)
        coef = _rowmul(gcoef, _REEXPAND).reshape(U, P, n)
        # truncation: the last two coefficients, globally and on every piece, against the largest
        # compression of the row
        scale = np.max(np.abs(d), axis=1)
        tail = np.maximum(np.max(np.abs(gcoef[:, -2:]), axis=1),
                          np.max(np.abs(coef[:, :, -2:]), axis=(1, 2)))
        ok = tried & (tail <= TAIL_TOL * scale) & np.isfinite(scale)
        self._seg1 = coef
        # 3. past pi/omega0 (K frozen at pi): one series in tau on [pi, (1 + SPAN_PAST) pi]/omega0
        self._seg2_den = SPAN_PAST * self.tpi  # length of that interval
        tn = self.tpi[:, None] + self._seg2_den[:, None] * (0.5 * (1.0 + _LX))
        d2 = h1.delta_from_K(tn, la[:, None], *(k[:, None] for k in self.K_pi))
        self._seg2 = _rowmul(d2, _LFIT.T)
        ok &= np.max(np.abs(self._seg2[:, -2:]), axis=1) <= TAIL_TOL * scale
        # 4. end of contact, on the series
        self.tau_d = np.full(U, np.nan)
        self.ok = ok
        self._contact_end()
        self.tau_d[~self.ok] = np.nan
        # coefficient table for evaluation: rows r*P + p (pieces), then U*P + r (past pi/omega0)
        self._cT = np.ascontiguousarray(
            np.concatenate([self._seg1.reshape(U * P, n), self._seg2]).T)

    # ----------------------------------------------------------------------- end of contact
    def _seg1_eval(self, rows: IntArray, t: FloatArray,
                   order: int = 0) -> tuple[FloatArray, FloatArray]:
        """d^order delta / dt^order and the next derivative on the zeroth-order contact, at t in
        [0, 1], one t per row (order 0 with its derivative: Newton on delta; order 1: on delta')."""
        y = t * N_PIECES
        p = np.minimum(y.astype(np.intp), N_PIECES - 1)
        x = 2.0 * (y - p) - 1.0
        c = self._seg1[rows, p]  # (m, n)
        V = _C.chebvander(x, N_LOCAL - 1)
        out: list[FloatArray] = []
        for k in (order, order + 1):
            ck: FloatArray = c
            for _ in range(k):
                ck = _rowmul(ck, _DER.T)
            out.append(np.einsum("mj,mj->m", ck, V) * (2.0 * N_PIECES) ** k)
        return out[0], out[1]

    def _K_at(self, rows: IntArray, t: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """K_cc, K_sc, K_ss at t in [0, 1], one t per row, from the global series."""
        M = _rowmul(_C.chebvander(2.0 * t - 1.0, N_GLOBAL), _GINTFIT)  # (m, N)
        cc, sc, ss = (np.einsum("mn,mn->m", self._fg[g, rows], M) for g in range(3))
        return cc, sc, ss

    def _contact_end(self) -> None:
        """tau_d: the first sign change of delta after 0 on a grid (_SCAN cells per piece, then
        _SCAN cells past pi/omega0), refined by Newton on the series. A row without one before
        (1 + SPAN_PAST) pi/omega0 is left to the kernels (ok = False)."""
        rows = np.flatnonzero(self.ok)
        if rows.size == 0:
            return
        n1 = N_PIECES * _SCAN
        grid = np.concatenate([_rowmul(self._seg1[rows], _SV).reshape(rows.size, n1),
                               _rowmul(self._seg2[rows], _SV2)], axis=1)
        neg = grid <= 0.0
        neg[:, 0] = False  # delta(0) = 0: contact starts there
        found = neg.any(axis=1)
        self.ok[rows[~found]] = False
        rows, grid, neg = rows[found], grid[found], neg[found]
        j = np.argmax(neg, axis=1)
        ii = np.arange(rows.size)
        lo_f, hi_f = grid[ii, j - 1], grid[ii, j]
        # the grid's column n1 is delta at pi/omega0 twice: as t = 1 and as x = -1 past it
        first = j <= n1
        if first.any():
            r, jf = rows[first], j[first]
            tg = np.arange(n1 + 1) / n1
            t = _newton(lambda t: self._seg1_eval(r, t), tg[jf - 1], tg[jf], lo_f[first],
                        hi_f[first])
            self.tau_d[r] = sine_squared(t)[0] / self.omega0[r]
        if (~first).any():
            r, jp = rows[~first], j[~first] - n1
            xg = -1.0 + 2.0 * np.arange(_SCAN + 1) / _SCAN
            c = self._seg2[r]

            def fun(x: FloatArray) -> tuple[FloatArray, FloatArray]:
                V = _C.chebvander(x, N_LOCAL - 1)
                return (np.einsum("mj,mj->m", c, V),
                        np.einsum("mj,mj->m", _rowmul(c, _DER.T), V))

            x = _newton(fun, xg[jp - 1], xg[jp], lo_f[~first], hi_f[~first])
            self.tau_d[r] = self.tpi[r] + self._seg2_den[r] * (0.5 * (1.0 + x))

    # ------------------------------------------------------------------------- evaluation
    def delta(self, rows: npt.ArrayLike, tau: RealArrayLike) -> FloatArray:
        """delta (42) at times ``tau`` (>= 0) for rows ``rows``: 0 from the end of contact on.

        Parameters
        ----------
        rows : array_like of int
            Row (lambda) of each time, same shape as ``tau``; rows with ``ok`` only.
        tau : array_like
            Times, >= 0 (not checked: the callers pass validated arrays).

        Returns
        -------
        ndarray
            delta0 + delta1 from the series, of the shape of ``tau``.

        Examples
        --------
        >>> import numpy as np
        >>> from zener_sym.ham.runtime_numpy import ham1
        >>> from zener_sym.ham.spectral import Ham1Series
        >>> s = Ham1Series([0.5])
        >>> tau = np.array([0.3, 1.0, 2.0])
        >>> d = s.delta(np.zeros(3, dtype=int), tau)
        >>> bool(np.allclose(d, ham1.delta(tau, 0.5), rtol=1e-12))  # the quadrature kernel
        True
        """
        rows = np.asarray(rows, dtype=np.intp)
        tau = np.asarray(tau, dtype=float)
        if rows.ndim >= 1 and rows.shape[-1] > 1 and rows.strides[-1] == 0:
            rows = rows[..., :1]  # one row per line of tau (rows_of's broadcast column)
        w, tpi, td = self.omega0.take(rows), self.tpi.take(rows), self.tau_d.take(rows)
        f = np.minimum(tau * (w * (1.0 / np.pi)), 1.0)
        t = np.arcsin(np.sqrt(f))
        t *= 2.0 * N_PIECES / np.pi
        p = np.minimum(t.astype(np.intp), N_PIECES - 1)
        x1 = 2.0 * (t - p) - 1.0
        on1 = tau < tpi
        x2 = np.minimum((tau - tpi) * (2.0 / self._seg2_den.take(rows)) - 1.0, 1.0)
        x = np.where(on1, x1, x2)
        idx = np.where(on1, rows * N_PIECES + p, self.lam.size * N_PIECES + rows)
        d = clenshaw_take(self._cT, idx, x)
        out: FloatArray = np.where(tau < td, np.maximum(d, 0.0), 0.0)
        return out

    def impulse(self, rows: npt.ArrayLike, tau: RealArrayLike) -> FloatArray:
        """Impulse (47) int_0^min(tau, tau_d) F dtau: a Chebyshev antiderivative per row on
        [0, min(tau_d, pi/omega0)] and on [pi/omega0, max(tau_d, pi/omega0)], as the kernels
        (``chebyshev.cumulative_integral``), with the force from the series.

        Parameters
        ----------
        rows : array_like of int
            Row (lambda) of each time, same shape as ``tau``.
        tau : array_like
            Times, >= 0.

        Returns
        -------
        ndarray
            The impulse up to each time (frozen after the end of contact).
        """
        return self._contact_integral(lambda d: d * np.sqrt(d), rows, tau)

    def summary(self) -> dict[str, FloatArray]:
        """First-order summary per row (NaN where ``ok`` is False): tau_dc, delta_m, tau_d, e,
        F_m, impulse, int_F2, as ``ham1_numpy.summary`` gives them from the quadrature kernels.

        tau_dc is the first zero of delta' on the zeroth-order contact (grid, then Newton on the
        series); e = -delta'(tau_d) from the generated formula with K at tau_d.

        Returns
        -------
        dict of str to ndarray
            Field -> one value per row.
        """
        h1 = _h1()
        U = self.lam.size
        out = {f: np.full(U, np.nan) for f in ("tau_dc", "delta_m", "e", "impulse", "int_F2")}
        ok = self.ok.copy()
        rows = np.flatnonzero(ok)
        if rows.size:
            dcoef = _rowmul(self._seg1[rows], _DER.T)
            grid = _rowmul(dcoef, _SV).reshape(rows.size, -1)  # sign of d delta/dt, t >= 0
            neg = grid <= 0.0
            neg[:, 0] = False  # d delta/dt = 0 at t = 0 (d tau/dt = 0 there)
            found = neg.any(axis=1)
            ok[rows[~found]] = False  # no maximum before pi/omega0: left to the kernels
            rows, grid, neg = rows[found], grid[found], neg[found]
        if rows.size:
            j = np.argmax(neg, axis=1)
            ii = np.arange(rows.size)
            tg = np.arange(grid.shape[1]) / (N_PIECES * _SCAN)
            t = _newton(lambda t: self._seg1_eval(rows, t, order=1), tg[j - 1], tg[j],
                        grid[ii, j - 1], grid[ii, j])
            out["tau_dc"][rows] = sine_squared(t)[0] / self.omega0[rows]
            out["delta_m"][rows] = self._seg1_eval(rows, t)[0]
            td = self.tau_d[rows]
            lam = self.lam[rows]
            past = td >= self.tpi[rows]
            t_d = np.where(past, 1.0, sine_squared_inverse(td * self.omega0[rows]))
            K = self._K_at(rows, t_d)
            Kf = tuple(np.where(past, kp, k) for kp, k in zip(self.K_pi[:, rows], K))
            out["e"][rows] = -h1.delta_dot_from_K(td, lam, *Kf)
            all_rows = np.arange(U)
            tau_end = np.where(ok, self.tau_d, 0.0)
            out["impulse"][rows] = self.impulse(all_rows, tau_end)[rows]
            out["int_F2"][rows] = self._contact_integral(lambda d: d ** 3, all_rows, tau_end)[rows]
        for v in out.values():
            v[~ok] = np.nan
        out["tau_d"] = np.where(ok, self.tau_d, np.nan)
        out["F_m"] = out["delta_m"] ** 1.5
        return out

    def _contact_integral(self, power: Callable[[FloatArray], FloatArray], rows: npt.ArrayLike,
                          tau: RealArrayLike) -> FloatArray:
        rows = np.asarray(rows, dtype=np.intp)
        tau = np.asarray(tau, dtype=float)
        u = np.arange(self.lam.size)
        safe = np.where(self.ok, self.tau_d, self.tpi)
        def fun(tt: FloatArray, r: IntArray) -> FloatArray:
            return power(self.delta(np.broadcast_to(r, tt.shape), tt))

        end = np.minimum(tau, safe.take(rows))
        tpi = self.tpi.take(rows)
        first = cumulative_rows(fun, np.zeros(u.size), np.minimum(safe, self.tpi), rows,
                                   np.minimum(end, tpi))
        second = cumulative_rows(fun, self.tpi, np.maximum(safe, self.tpi), rows,
                                    np.maximum(end, tpi))
        out: FloatArray = first + second
        return out


def _newton(fun: Callable[[FloatArray], tuple[FloatArray, FloatArray]], lo: FloatArray,
            hi: FloatArray, f_lo: FloatArray, f_hi: FloatArray, iters: int = 60) -> FloatArray:
    """Root of f in [lo, hi] with f(lo) > 0 >= f(hi), per element: from the secant point, Newton
    steps kept inside the bracket (bisection otherwise); ``fun(x) -> (f, f')``."""
    lo = np.array(lo, dtype=float)
    hi = np.array(hi, dtype=float)
    x = lo + (hi - lo) * (f_lo / (f_lo - f_hi))
    tiny = np.finfo(float).tiny
    for _ in range(iters):
        f, fp = fun(x)
        pos = f > 0.0
        lo = np.where(pos, x, lo)
        hi = np.where(pos, hi, x)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = x - f / fp
        good = np.isfinite(step) & (step >= lo) & (step <= hi)
        new = np.where(good, step, 0.5 * (lo + hi))
        done = np.abs(new - x) <= 2.0 * np.finfo(float).eps * np.maximum(np.abs(x), tiny)
        x = new
        if done.all():
            break
    return x


def rows_of(lam: RealArrayLike) -> tuple[FloatArray, IntArray]:
    """Distinct lambda values of ``lam`` (sorted) and, per element, its row among them.

    A ``lam`` constant along its last axis (a column broadcast against times) is recognised
    without sorting every element.

    Parameters
    ----------
    lam : float or array_like
        lambda values.

    Returns
    -------
    unique : ndarray
        The distinct values, sorted.
    rows : ndarray of int
        Of the shape of ``lam``: ``unique[rows] == lam``.

    Examples
    --------
    >>> from zener_sym.ham.spectral import rows_of
    >>> u, rows = rows_of([0.5, 0.1, 0.5])
    >>> u.tolist(), rows.tolist()
    ([0.1, 0.5], [1, 0, 1])
    """
    la: FloatArray = np.asarray(lam, dtype=float)
    u: FloatArray
    if la.ndim >= 1 and la.shape[-1] > 1 and np.array_equal(la, np.broadcast_to(
            la[..., :1], la.shape)):
        u, inv = np.unique(la[..., 0], return_inverse=True)
        return u, np.broadcast_to(inv.reshape(la.shape[:-1] + (1,)), la.shape)
    u, inv = np.unique(la, return_inverse=True)
    return u, inv.reshape(la.shape)


def summary_numpy(lam: RealArrayLike) -> dict[str, FloatArray]:
    """ham1 summary in float64 (tau_dc, delta_m, tau_d, e, F_m, impulse, int_F2) from the
    per-lambda series, and from the quadrature kernels (``ham1_numpy.summary``) for the lambda
    values whose series fail their check (from lambda = 2.414 on). Same shape as ``lam``.

    This is the reference the ham1 summary table (:mod:`zener_sym.ham.table_build`) samples.

    Parameters
    ----------
    lam : float or array_like
        lambda values, 0 <= lambda < lam_crit (Eq. 81).

    Returns
    -------
    dict of str to ndarray
        Field -> array of the shape of ``lam``.

    Examples
    --------
    >>> from zener_sym.ham.runtime_numpy import ham1
    >>> from zener_sym.ham.spectral import summary_numpy
    >>> s, k = summary_numpy([1.0]), ham1.summary([1.0])  # series, quadrature kernels
    >>> all(abs(s[f][0] - k[f][0]) <= 1e-11 * abs(k[f][0]) for f in s)
    True
    """
    u, rows = rows_of(lam)
    v = Ham1Series(u).summary()
    slow = np.isnan(v["tau_d"])
    if slow.any():
        k = _h1().summary(u[slow])
        for f in v:
            v[f][slow] = k[f]
    return {f: x[rows] for f, x in v.items()}
