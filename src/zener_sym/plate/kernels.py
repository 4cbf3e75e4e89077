"""Exact responses of the modes (and the ball) to a piecewise-linear contact force.

Each mode obeys y'' + 2 zeta omega y' + omega^2 y = c F with zeta = eta / 2 (eta the modal loss
factor, 0 for the undamped plate). Its free motion is y = Re(B e^{s t}) with
s = -zeta omega + i omega_d, omega_d = omega sqrt(1 - zeta^2), and its impulse response is
g(u) = Im(e^{s u}) / omega_d. With F piecewise linear on a grid of step h (hat functions), the
response at a node to one hat is a closed-form integral of g, so the modes are propagated exactly
whatever omega h is: stiff high modes never limit the step. The ball (x'' = -F) is the limit
omega -> 0 of the same integrals.

The integrals use
    phi2(x) = (e^x - 1 - x) / x^2     (a half hat ending at the node),
    psi2(x) = (1 + (x - 1) e^x) / x^2 (a half hat starting at the node, seen a width later),
    (e^x - 1)^2 / x^2                 (a whole hat, one step and more earlier),
written without cancellation for small |x| and without overflow for damped stiff modes.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from ..numerics.taylor import horner
from ..typing import FloatArray

__all__ = ["Rates", "phi2", "psi2", "Kernel", "powers", "re_dot"]

ComplexArray = npt.NDArray[np.complex128]

#: Largest kernel table (modes x steps complex numbers) built, in GiB.
MAX_GIB = 2.0
#: Below this |x| the series are used (12 terms: the next one is below 1e-17 there).
_SERIES = 0.25
_TERMS = 12
_PHI2 = [1.0 / math.factorial(n) for n in range(2, 2 + _TERMS)]
_PSI2 = [(n - 1) / math.factorial(n) for n in range(2, 2 + _TERMS)]


def _series_where_small(x: ComplexArray, out: ComplexArray, coef: list[float]) -> ComplexArray:
    """out with the entries where |x| < _SERIES replaced by the series sum coef_k x^k."""
    small = np.abs(x) < _SERIES
    if small.any():
        out[small] = horner(coef, x[small])
    return out


def phi2(x: ComplexArray) -> ComplexArray:
    """(e^x - 1 - x) / x^2, accurate for every complex x with Re x <= 0 (and small |x|)."""
    x = np.asarray(x, dtype=complex)
    xs = np.where(x == 0.0, 1.0, x)
    return _series_where_small(x, (np.expm1(xs) - xs) / xs**2, _PHI2)


def psi2(x: ComplexArray) -> ComplexArray:
    """(1 + (x - 1) e^x) / x^2 = e^x phi2(-x), accurate for Re x <= 0."""
    x = np.asarray(x, dtype=complex)
    xs = np.where(x == 0.0, 1.0, x)
    return _series_where_small(x, (1.0 + (xs - 1.0) * np.exp(xs)) / xs**2, _PSI2)


def powers(z: ComplexArray, n: int, out: ComplexArray | None = None) -> ComplexArray:
    """The matrix z_i^j, j = 0 .. n-1, by doubling products (a complex exp costs some 20 times a
    product). The rounding of z^j grows as j ulp, as that of e^{s j h} from its rounded argument
    does."""
    if out is None:
        out = np.empty((len(z), n), dtype=complex)
    out[:, 0] = 1.0
    m, zm = 1, z
    while m < n:
        k = min(m, n - m)
        np.multiply(out[:, :k], zm[:, None], out=out[:, m:m + k])
        m += k
        zm = zm * zm
    return out


def re_dot(a: ComplexArray, Er: FloatArray, Ei: FloatArray) -> FloatArray:
    """Re(a @ (Er + i Ei)) by two real products: numpy's complex products either skip BLAS
    (einsum, slow) or take a threaded zgemm/zgemv that, on a loaded machine, can cost a hundred
    times more than the real dgemm/dgemv pair (measured)."""
    out: FloatArray = a.real @ Er - a.imag @ Ei
    return out


@dataclass(frozen=True)
class Rates:
    """The modes' complex rates s_n and damped frequencies omega_d for a loss factor eta."""

    omega: FloatArray
    c: FloatArray
    loss: float
    s: ComplexArray = field(init=False)
    wd: FloatArray = field(init=False)

    def __post_init__(self) -> None:
        zeta = 0.5 * self.loss
        wd = self.omega * np.sqrt(1.0 - zeta * zeta)
        object.__setattr__(self, "wd", wd)
        object.__setattr__(self, "s", -zeta * self.omega + 1j * wd)

    def amplitude(self, y: FloatArray, v: FloatArray) -> ComplexArray:
        """B with y = Re(B), y' = Re(s B): the free motion from displacement y and velocity v."""
        return y - 1j * (v - self.s.real * y) / self.wd

    def energy(self, B: ComplexArray) -> float:
        """E_p = sum (y'^2 + omega^2 y^2) / (2 c_n) of the modes in state B (at its time)."""
        y, v = B.real, (self.s * B).real
        return float(np.sum((v * v + self.omega**2 * y * y) / (2.0 * self.c)))


class Kernel:
    """The hat responses on a uniform grid of step h, grown on demand.

    ``L[m]`` is the approach delta lost at node k to a unit hat at node k - m (ball and modes
    together, static correction excluded). The powers e^{s j h} are never tabulated whole (a
    modes x steps table costs more to fill and copy than to use): j = b M + i with
    ``W[:, i] = e^{s i h}`` (i < M) and ``Q[:, b] = e^{s b M h}``, so a sum over the modes of
    every power is a few real matrix products (:meth:`series`, :meth:`poly`).
    """

    #: M, the powers in one block
    M = 32

    def __init__(self, rates: Rates, h: float, n_steps: int) -> None:
        self.rates, self.h = rates, h
        sh = rates.s * h
        self.step = np.exp(sh)
        self.whole = np.expm1(sh) ** 2 / (rates.s**2 * h)   # hat one step and more earlier
        self.half = h * phi2(sh)                             # half hat ending at the node
        W = powers(self.step, self.M + 1)
        self._zm = W[:, self.M].copy()                       # e^{s M h}
        self.Wr, self.Wi = np.ascontiguousarray(W[:, :self.M].real), \
            np.ascontiguousarray(W[:, :self.M].imag)
        self.Q = np.empty((len(rates.s), 0), dtype=complex)
        self.L = np.empty(0)
        self.grow(n_steps)

    def grow(self, n_steps: int) -> None:
        """Make L cover nodes 0 .. n_steps (at least doubling, so growth is amortised)."""
        have = len(self.L)
        if have > n_steps:
            return
        n_new = max(n_steps + 1, 2 * have)
        nb = -(-n_new // self.M)
        r, h = self.rates, self.h
        gib = 16.0 * 4 * len(r.s) * (nb + self.M) / 2**30
        if gib > MAX_GIB:
            raise RuntimeError(f"{len(r.s)} modes over {n_new} steps need {gib:.1f} GiB for the "
                               f"kernel (limit {MAX_GIB:g} GiB): use fewer modes or a looser rtol")
        self.Q = powers(self._zm, nb)
        n = nb * self.M
        cw = r.c / r.wd
        L = np.empty(n)
        L[0] = h * h / 6.0 + float(np.sum(cw * self.half.imag))
        L[1:] = np.arange(1, n) * h * h + self.series(cw * self.whole, n - 1).imag
        self.L = L

    def series(self, a: ComplexArray, n: int) -> ComplexArray:
        """sum_n a_n e^{s_n j h} for j = 0 .. n-1 (n <= len(L))."""
        nb = -(-n // self.M)
        A = a[:, None] * self.Q[:, :nb]
        Ar, Ai = np.ascontiguousarray(A.real.T), np.ascontiguousarray(A.imag.T)
        re = Ar @ self.Wr - Ai @ self.Wi
        im = Ar @ self.Wi + Ai @ self.Wr
        out: ComplexArray = (re + 1j * im).ravel()[:n]
        return out

    def poly(self, c: FloatArray) -> ComplexArray:
        """sum_i c_i e^{s i h} over i < len(c) (len(c) <= len(L)), for each mode."""
        nb = -(-len(c) // self.M)
        C = np.zeros(nb * self.M)
        C[:len(c)] = c
        C = C.reshape(nb, self.M).T
        Vr, Vi = self.Wr @ C, self.Wi @ C
        Q = self.Q[:, :nb]
        out: ComplexArray = (Q.real * Vr - Q.imag * Vi).sum(axis=1) \
            + 1j * (Q.real * Vi + Q.imag * Vr).sum(axis=1)
        return out

    def column(self, j: int) -> ComplexArray:
        """e^{s j h} for every mode."""
        b, i = divmod(j, self.M)
        out: ComplexArray = self.Q[:, b] * (self.Wr[:, i] + 1j * self.Wi[:, i])
        return out

    def forced(self, F: FloatArray) -> ComplexArray:
        """P_n = sum_j F_j G_n(k - j) for nodes j = 1 .. k of F (F[0] at the contact's start is 0),
        the complex response at node k = len(F) - 1; y = Im(c P) / omega_d, y' = Im(c s P) /
        omega_d."""
        k = len(F) - 1
        P: ComplexArray = self.half * F[k]
        if k >= 2:
            # sum_{j=1}^{k-1} F_j e^{s (k-1-j) h}
            P = P + self.whole * self.poly(F[k - 1:0:-1])
        return P
