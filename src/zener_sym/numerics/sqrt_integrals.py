"""Real-valued float64 evaluation of the first-order "square-root" integrals, vectorised in numpy.

The first-order HAM correction (Eqs. 36-42) needs, with t = omega0 * s the phase,

    K_g(a, theta) = integral_0^theta exp(-a t) g(t) sqrt(sin t) dt,    0 <= theta <= pi,

for a few trigonometric monomials g (cos^2 t, sin t cos t, sin^2 t, and sin t for the zeroth-order
impulse), with a = beta / (2 omega0) >= 0 (or 3 beta / (2 omega0)). Their closed forms are Gauss
hypergeometric functions 2F1(-1/2, s; s + 1; exp(2 i theta)) with complex s = (m - 1/2)/2 + i a/2,
which ``scipy.special.hyp2f1`` cannot take (complex parameters), and whose series converge slowly on
the unit circle near z = 1 (theta -> 0 and theta -> pi). So numpy evaluates the integrals instead:

* Choice: Gauss-Jacobi quadrature with the square-root singularity in the weight, which is exact to
  rounding because what is left of the integrand is analytic. On [0, T] (T <= pi/2) substitute
  t = T u: sqrt(sin t) = sqrt(T u) sqrt(sinc), so the integral is
  T^{3/2} * integral_0^1 u^{1/2} [exp(-a T u) g(T u) sqrt(sin(T u)/(T u))] du, a Gauss-Jacobi rule
  with weight u^{1/2}. The bracket is analytic on a Bernstein ellipse reaching u = pi/T >= 2.
* Past pi/2 the integral is K(pi) - integral_theta^pi, and the piece near pi uses the same rule
  with the weight at the pi end (sin(pi - x) = sin x; sin and cos of pi - x are formed from x, so
  nothing is lost to rounding of pi - x).
* exp(-a t) is entire, but a large a (near the critical lambda, omega0 -> 0) makes it steep: the
  left piece is cut at t = CUT / a, past which the integrand is below exp(-CUT) = 1e-26 of its
  scale, so the quadrature never sees more than exp(-CUT) of decay. With N_NODES = 64 nodes the
  rule integrates exp(-x u) for x <= CUT to rounding (checked against the 2F1 closed form at 30
  digits in tests/test_ham_quadrature.py).
* Past theta = pi (end of zeroth-order contact) the integrals are frozen at their values at pi:
  delta0 < 0 there, so delta0's contact force and sqrt(delta0) are zero (the physical
  continuation; the mpmath kernels do the same).

Nodes and weights are module-level constants computed once at import; the points go on a
trailing axis, so there is no Python loop over evaluation points.
"""
from __future__ import annotations

import functools
from collections.abc import Callable, Sequence

import numpy as np
import numpy.typing as npt
from scipy.special import roots_jacobi

from ..typing import FloatArray, RealArrayLike
from .blocks import BLOCK
from .chebyshev import cheb_fit_matrix, cheb_nodes, cheb_to_monomial, horner_take

__all__ = ["K_FUNCS", "sqrt_integrals", "N_NODES", "CUT"]

#: Number of Gauss-Jacobi nodes per piece.
N_NODES = 64
#: Largest exponent a * t the left piece integrates; beyond it the integrand is < exp(-CUT).
CUT = 60.0

_x, _w = roots_jacobi(N_NODES, 0.0, 0.5)  # weight (1 + x)^{1/2} on [-1, 1]
#: nodes u in (0, 1) and weights for integral_0^1 u^{1/2} h(u) du
_U = (1.0 + _x) / 2.0
_W = _w / 2.0**1.5

#: name -> g(sin t, cos t)
K_FUNCS: dict[str, Callable[[FloatArray, FloatArray], FloatArray]] = {
    "cc": lambda s, c: c * c,
    "sc": lambda s, c: s * c,
    "ss": lambda s, c: s * s,
    "s": lambda s, c: s,
    "one": lambda s, c: np.ones_like(s),
}


def _sin_over(s: FloatArray, x: FloatArray) -> FloatArray:
    """sin(x)/x from sin(x), with the limit 1 at x = 0 (T = 0 puts every node at 0)."""
    return np.divide(s, x, out=np.ones_like(x), where=x > 0)


def _left(a: FloatArray, T: FloatArray, names: Sequence[str]) -> dict[str, FloatArray]:
    """integral_0^T exp(-a t) g(t) sqrt(sin t) dt for 0 <= T <= pi/2 (arrays broadcast)."""
    x = T[..., None] * _U  # trailing axis: nodes
    s, c = np.sin(x), np.cos(x)
    base = np.exp(-a[..., None] * x) * np.sqrt(_sin_over(s, x)) * _W
    scale = T * np.sqrt(T)
    return {n: scale * np.sum(base * K_FUNCS[n](s, c), axis=-1) for n in names}


def _right(a: FloatArray, r: FloatArray, names: Sequence[str]) -> dict[str, FloatArray]:
    """integral_{pi - r}^{pi} exp(-a t) g(t) sqrt(sin t) dt for 0 <= r <= pi/2."""
    x = r[..., None] * _U  # distance from pi
    s, c = np.sin(x), -np.cos(x)  # sin and cos of t = pi - x
    # exp(-a t) with t = pi - x >= pi/2: never overflows
    base = np.exp(-a[..., None] * (np.pi - x)) * np.sqrt(_sin_over(s, x)) * _W
    scale = r * np.sqrt(r)
    return {n: scale * np.sum(base * K_FUNCS[n](s, c), axis=-1) for n in names}


def sqrt_integrals(a: RealArrayLike, theta: RealArrayLike,
                   names: Sequence[str] = ("cc", "sc", "ss")) -> dict[str, FloatArray]:
    """K_g(a, theta) = integral_0^min(theta, pi) exp(-a t) g(t) sqrt(sin t) dt, for g in ``names``.

    The square-root integrals of the first-order HAM correction (Eqs. 36-42).

    Parameters
    ----------
    a : array_like
        Decay rate, finite and >= 0.
    theta : array_like
        Phase(s), finite and >= 0; values beyond pi give the frozen value at pi.
    names : sequence of str
        Keys of ``K_FUNCS``.

    Returns
    -------
    dict
        name -> float64 array of the broadcast shape of ``a`` and ``theta``.

    Raises
    ------
    ValueError
        If an ``a`` or a ``theta`` is negative or not finite.
    """
    a_b, theta_b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(theta, dtype=float))
    if not (np.all(np.isfinite(a_b)) and np.all(a_b >= 0)):
        raise ValueError("sqrt_integrals: the decay rate a must be finite and >= 0")
    if not (np.all(np.isfinite(theta_b)) and np.all(theta_b >= 0)):
        raise ValueError("sqrt_integrals: theta must be finite and >= 0")
    shape = a_b.shape
    a1 = a_b.reshape(-1)
    th = np.minimum(theta_b, np.pi).reshape(-1)
    if a1.size > _CHUNK:
        # blocks of points keep the (points x nodes) temporaries in cache-sized memory
        parts = [_flat(a1[i:i + _CHUNK], th[i:i + _CHUNK], names)
                 for i in range(0, a1.size, _CHUNK)]
        return {n: np.concatenate([p[n] for p in parts]).reshape(shape) for n in names}
    return {n: v.reshape(shape) for n, v in _flat(a1, th, names).items()}


_CHUNK = 2048


def _flat(a: FloatArray, th: FloatArray, names: Sequence[str]) -> dict[str, FloatArray]:
    """sqrt_integrals on validated 1-D arrays, th already clipped to [0, pi]."""
    half = np.pi / 2.0
    with np.errstate(divide="ignore", over="ignore"):  # subnormal a: CUT / a = inf, no cap
        cap = np.where(a > 0, CUT / np.where(a > 0, a, 1.0), np.inf)
    T = np.minimum(np.minimum(th, half), cap)
    out = _left(a, T, names)
    past = th > half
    if np.any(past):
        # K(theta) = K(pi/2) + [integral_{pi/2}^{pi} - integral_{theta}^{pi}]
        ap = a[past]
        # the piece over [pi/2, pi] depends on a only: once per distinct a
        ua, inv = np.unique(ap, return_inverse=True)
        full = {n: v[inv] for n, v in _right(ua, np.full(ua.shape, half), names).items()}
        tail = _right(ap, np.pi - th[past], names)
        for n in names:
            out[n][past] += full[n] - tail[n]
    return out


# ----------------------------------------------------------------------------------------------
# Many phases per decay rate: K_s(a, theta) = int_0^theta exp(-a t) sin^{3/2} t dt as series.
#
# A history asks for K_s at hundreds of phases theta for each of a few decay rates a (one per
# lambda). We store, once per process, Chebyshev series in (theta, a), piecewise in theta, of
#   K_s(a, theta)              = theta^{5/2} G(a, theta)               on [0, pi/2],
#   K_s(a, pi) - K_s(a, theta) = r^{5/2} H(a, r),  r = pi - theta,      on [0, pi/2],
# from the quadrature above at Chebyshev points. G and H are analytic (sin^{3/2} t =
# t^{3/2} (sin t / t)^{3/2}, exp entire), so both series converge geometrically. Per distinct a
# the a-direction is contracted once and each piece's theta series is turned into monomials;
# each phase then costs one short polynomial by Horner's rule (numerics.chebyshev.horner_take).
# exp(-a t) makes G steep for large a: the series serve a <= A_SERIES, the rule the rest.

#: Pieces per half of [0, pi] (in theta on the left, in r on the right), Chebyshev points in
#: theta (or r) per piece, and in a on [0, A_SERIES]. Short pieces keep the theta degree low
#: (about 12 instead of 36 with one piece): each degree costs every point a gather and a
#: multiply-add, which is most of a history's time.
N_PIECES = 8
N_SERIES = 14
N_RATE = 36
#: Largest decay rate the series serve (ham0's a = 3 beta / (2 omega0) is 8.5 at lambda = 2.4).
A_SERIES = 10.0
_WIDTH = np.pi / 2.0 / N_PIECES
#: Points per block in the series evaluation.
_BLOCK = BLOCK


@functools.cache
def _ks_table() -> tuple[FloatArray, FloatArray]:
    """Coefficients [piece, theta degree, a degree] of G and H (computed on first use, about
    4000 quadrature points; read-only, as every caller shares them)."""
    a = A_SERIES / 2.0 * (cheb_nodes(N_RATE) + 1.0)
    dt, da = cheb_fit_matrix(N_SERIES), cheb_fit_matrix(N_RATE)
    cG: list[FloatArray] = []
    cH: list[FloatArray] = []
    for p in range(N_PIECES):
        y = _WIDTH * (p + 0.5 * (cheb_nodes(N_SERIES) + 1.0))  # theta or r in the piece
        A, Y = np.meshgrid(a, y)  # [theta node, a node]
        G = _left(A, Y, ("s",))["s"] / Y**2.5
        H = _right(A, Y, ("s",))["s"] / Y**2.5  # integral over [pi - r, pi], no cancellation
        cG.append(dt @ G @ da.T)
        cH.append(dt @ H @ da.T)
    out = (np.array(cG), np.array(cH))
    for arr in out:
        arr.flags.writeable = False
    return out


def impulse_s(a: RealArrayLike, theta: RealArrayLike) -> FloatArray:
    """K_s(a, theta) = int_0^min(theta, pi) exp(-a t) sin^{3/2} t dt, fast for many theta per a.

    Same value as ``sqrt_integrals(a, theta, ("s",))["s"]`` to about 1e-14 (tests), from the
    Chebyshev series for a <= A_SERIES and the quadrature for larger a.

    Parameters
    ----------
    a : array_like
        Decay rates, finite and >= 0 (a broadcast column, one rate per line, is fastest).
    theta : array_like
        Phases, finite and >= 0; past pi the value at pi.

    Returns
    -------
    ndarray
        K_s, the broadcast shape of ``a`` and ``theta``.

    Raises
    ------
    ValueError
        If an ``a`` or a ``theta`` is negative or not finite.
    """
    a_b, th_b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(theta, dtype=float))
    # a broadcast column (one rate per line of theta, stride 0 along it): its lines are checked
    # and sorted, not every point
    column = a_b.ndim >= 1 and a_b.shape[-1] > 1 and a_b.strides[-1] == 0
    rates = a_b[..., :1] if column else a_b
    if not (np.all(np.isfinite(rates)) and np.all(rates >= 0)):
        raise ValueError("impulse_s: the decay rate a must be finite and >= 0")
    lo, hi = (th_b.min(), th_b.max()) if th_b.size else (0.0, 0.0)
    if not (lo >= 0 and hi < np.inf):  # a NaN fails both
        raise ValueError("impulse_s: theta must be finite and >= 0")
    if column and np.all(rates <= A_SERIES):
        u, line = np.unique(rates[..., 0], return_inverse=True)
        return _series_eval(u, th_b.reshape(-1), line=line.ravel(),
                            n_col=a_b.shape[-1]).reshape(a_b.shape)
    out = np.empty(a_b.shape)
    fast = a_b <= A_SERIES
    if (~fast).any():
        out[~fast] = sqrt_integrals(a_b[~fast], th_b[~fast], ("s",))["s"]
    if fast.any():
        u, inv = np.unique(a_b[fast], return_inverse=True)
        out[fast] = _series_eval(u, th_b[fast], inv=inv)
    return out


@functools.cache
def _ks_pieces() -> FloatArray:
    """[theta degree, q, a degree]: K_s's Chebyshev series in each theta piece's local variable
    x = 2 (theta - q w) / w - 1 (w = _WIDTH, q = 0 ... 2 N_PIECES - 1 along [0, pi]). Pieces
    q < N_PIECES hold G (K_s = theta^{5/2} G); the right half's H, a series in r = pi - theta
    whose local variable is -x there, is stored with the odd degrees negated (T_j(-x) =
    (-1)^j T_j(x)) and the whole sign flipped, so that K_s = K_s(a, pi) + r^{5/2} P(x) with P
    the stored series: one row per (piece, rate) serves both halves."""
    cG, cH = _ks_table()
    flip = -((-1.0) ** np.arange(cG.shape[1]))[:, None, None]
    pieces: FloatArray = np.concatenate([cG.transpose(1, 0, 2), flip * cH[::-1].transpose(1, 0, 2)], axis=1)
    return pieces


#: Rates per matrix product in ``KsSeries``: a product of a piece's [theta degree, N_RATE]
#: coefficients with this many rates stays under 2^18 multiply-adds, below which OpenBLAS runs
#: it on one thread. One product for all pieces and rates ran on two threads: on a busy
#: two-core machine the wait for the second thread took 5-30 ms, against 0.06 ms on one
#: (issue 36; the ham0 history is 3 ms).
_RATES_PER_PRODUCT = 512


class KsSeries:
    """K_s(u[i], theta) from the series for a fixed set of rates u (all in [0, A_SERIES]).

    The a direction is contracted once here, so callers that evaluate a history block by block
    (a model keeping its temporaries cache-sized) pay it once. ``at`` evaluates one block.

    Parameters
    ----------
    u : array_like
        The decay rates, finite and in [0, A_SERIES].

    Raises
    ------
    ValueError
        If a rate is outside [0, A_SERIES] or not finite.
    """

    n: int
    rows: FloatArray
    base: FloatArray

    def __init__(self, u: RealArrayLike) -> None:
        u = np.asarray(u, dtype=float).ravel()
        if not (np.all(np.isfinite(u)) and np.all(u >= 0) and np.all(u <= A_SERIES)):
            raise ValueError(f"KsSeries: the decay rates must be finite and in [0, {A_SERIES:g}]")
        n = self.n = u.size
        Ta = np.polynomial.chebyshev.chebvander(2.0 * u / A_SERIES - 1.0, N_RATE - 1)
        pieces = _ks_pieces()
        # [theta degree, piece, rate]: one small matrix product per piece and block of rates
        c = np.empty((*pieces.shape[:2], n))
        step = _RATES_PER_PRODUCT
        for q in range(pieces.shape[1]):
            for a in range(0, n, step):
                np.matmul(pieces[:, q], Ta[a:a + step].T, out=c[:, q, a:a + step])
        # K_s(a, pi) = (pi/2)^{5/2} (G + H) at theta = r = pi/2: G's last piece at x = 1, H's
        # (stored as piece N_PIECES, in -x and with the sign flipped) at x = -1
        alt = (-1.0) ** np.arange(c.shape[0])[:, None]
        k_pi = (np.pi / 2) ** 2.5 * (c[:, N_PIECES - 1].sum(axis=0)
                                     - (alt * c[:, N_PIECES]).sum(axis=0))
        # the trailing theta degrees at the noise level of the 2-D fit for every rate at hand
        # are dropped (each costs every point a Horner step), then the rest turned into
        # monomials in x (well conditioned on a short piece: they fall off like a Taylor series)
        mag = np.abs(c).max(axis=2)
        deg = int(np.flatnonzero(np.any(mag > 1e-14 * mag.max(axis=0), axis=1)).max()) + 1
        self.rows = cheb_to_monomial(deg) @ c[:deg].reshape(deg, -1)  # [power, piece * rate]
        self.base = np.concatenate([np.zeros(N_PIECES * n), np.tile(k_pi, N_PIECES)])  # per row

    def at(self, th: FloatArray, iv: npt.NDArray[np.intp]) -> FloatArray:
        """K_s at the phases th for the rates u[iv].

        Parameters
        ----------
        th : ndarray
            1-D phases, >= 0; past pi the value at pi.
        iv : ndarray of intp
            Each phase's rate, an index into u; it must be in range (it indexes without a
            bounds check).

        Returns
        -------
        ndarray
            K_s at the phases, th's shape.
        """
        t = np.minimum(th, np.pi)
        u_ = t * (1.0 / _WIDTH)
        row = u_.astype(np.intp)
        np.minimum(row, 2 * N_PIECES - 1, out=row)
        x = u_ - row
        x *= 2.0
        x -= 1.0
        row *= self.n
        row += iv
        y = np.pi - t
        np.minimum(y, t, out=y)  # theta on the left half, r = pi - theta on the right
        val: FloatArray = np.sqrt(y)
        val *= y
        val *= y
        val *= horner_take(self.rows, row, x)
        val += self.base.take(row, mode="clip")
        return val


#: Most rates contracted at once (their rows take 16 pieces x 13 degrees x 8 bytes each): points
#: with more distinct rates (one lambda per point) are taken in groups of rates.
_MAX_RATES = 2048


def _series_eval(u: FloatArray, th: FloatArray, inv: npt.NDArray[np.intp] | None = None,
                 line: npt.NDArray[np.intp] | None = None,
                 n_col: int | None = None) -> FloatArray:
    """K_s at phases th for the rates u (all <= A_SERIES), from the series: point i has the rate
    u[inv[i]], or, with ``line``, u[line[i // n_col]] (a rate per line of n_col points, so no
    per-point index array is built). th >= 0; phases past pi give K_s(a, pi)."""
    out = np.empty(th.shape)
    if u.size > _MAX_RATES:
        # points sorted by rate; each group of rates contracted alone (bounded memory)
        if inv is None:
            assert line is not None and n_col is not None  # the callers give one or the other
            inv = np.repeat(line, n_col)
        order = np.argsort(inv, kind="stable")
        bounds = np.searchsorted(inv[order], np.arange(0, u.size + _MAX_RATES, _MAX_RATES))
        for g, (a, b) in enumerate(zip(bounds[:-1], bounds[1:])):
            at = order[a:b]
            out[at] = _series_eval(u[g * _MAX_RATES:(g + 1) * _MAX_RATES], th[at],
                                   inv=inv[at] - g * _MAX_RATES)
        return out
    series = KsSeries(u)
    # blocks of points small enough that the dozen temporaries stay in cache (and below the
    # allocator's mmap threshold): whole-array temporaries cost more than their arithmetic
    for s in range(0, th.size, _BLOCK):
        e = min(s + _BLOCK, th.size)
        if line is None:
            assert inv is not None
            iv = inv[s:e]
        else:
            assert n_col is not None
            iv = line.take(np.arange(s, e) // n_col, mode="clip")
        out[s:e] = series.at(th[s:e], iv)
    return out
