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

__all__ = ["Rates", "phi2", "psi2", "Kernel"]

ComplexArray = npt.NDArray[np.complex128]

#: Largest kernel table (modes x steps complex numbers) built, in GiB.
MAX_GIB = 2.0
#: Below this |x| the series are used (12 terms: the next one is below 1e-17 there).
_SERIES = 0.25
_TERMS = 12
_PHI2 = [1.0 / math.factorial(n) for n in range(2, 2 + _TERMS)]
_PSI2 = [(n - 1) / math.factorial(n) for n in range(2, 2 + _TERMS)]


def phi2(x: ComplexArray) -> ComplexArray:
    """(e^x - 1 - x) / x^2, accurate for every complex x with Re x <= 0 (and small |x|)."""
    x = np.asarray(x, dtype=complex)
    small = np.abs(x) < _SERIES
    xs = np.where(small, 1.0, x)
    out = (np.expm1(xs) - xs) / xs**2
    res: ComplexArray = np.where(small, horner(_PHI2, x), out)
    return res


def psi2(x: ComplexArray) -> ComplexArray:
    """(1 + (x - 1) e^x) / x^2 = e^x phi2(-x), accurate for Re x <= 0."""
    x = np.asarray(x, dtype=complex)
    small = np.abs(x) < _SERIES
    xs = np.where(small, 1.0, x)
    out = (1.0 + (xs - 1.0) * np.exp(xs)) / xs**2
    res: ComplexArray = np.where(small, horner(_PSI2, x), out)
    return res


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
    together, static correction excluded); ``E[:, m] = e^{s m h}``.
    """

    def __init__(self, rates: Rates, h: float, n_steps: int) -> None:
        self.rates, self.h = rates, h
        sh = rates.s * h
        self.whole = np.expm1(sh) ** 2 / (rates.s**2 * h)   # hat one step and more earlier
        self.half = h * phi2(sh)                             # half hat ending at the node
        self.E = np.empty((len(rates.s), 0), dtype=complex)
        self.L = np.empty(0)
        self.grow(n_steps)

    def grow(self, n_steps: int) -> None:
        """Make E and L cover nodes 0 .. n_steps (at least doubling, so growth is amortised)."""
        have = self.E.shape[1]
        if have > n_steps:
            return
        n_new = max(n_steps + 1, 2 * have)
        r, h = self.rates, self.h
        gib = 16.0 * len(r.s) * n_new / 2**30
        if gib > MAX_GIB:
            raise RuntimeError(f"{len(r.s)} modes over {n_new} steps need {gib:.1f} GiB for the "
                               f"kernel (limit {MAX_GIB:g} GiB): use fewer modes or a looser rtol")
        E = np.empty((len(r.s), n_new), dtype=complex)
        # e^{s m h} by blocks: exp on the first block, then products (cheaper than exp)
        blk = min(n_new, 64)
        E[:, :blk] = np.exp(np.outer(r.s, np.arange(blk) * h))
        while blk < n_new:
            nb = min(blk, n_new - blk)
            np.multiply(E[:, :nb], np.exp(r.s * (blk * h))[:, None], out=E[:, blk:blk + nb])
            blk += nb
        self.E = E
        m = np.arange(n_new)
        cw = r.c / r.wd
        L = np.empty(n_new)
        L[0] = h * h / 6.0 + float(np.sum(cw * self.half.imag))
        L[1:] = m[1:] * h * h + np.einsum("n,nm->m", cw * self.whole, E[:, :-1]).imag
        self.L = L
        self.Lrev = np.ascontiguousarray(L[::-1])

    def forced(self, F: FloatArray) -> ComplexArray:
        """P_n = sum_j F_j G_n(k - j) for nodes j = 1 .. k of F (F[0] at the contact's start is 0),
        the complex response at node k = len(F) - 1; y = Im(c P) / omega_d, y' = Im(c s P) /
        omega_d."""
        k = len(F) - 1
        P: ComplexArray = self.half * F[k]
        if k >= 2:
            P = P + self.whole * np.einsum("nm,m->n", self.E[:, :k - 1][:, ::-1], F[1:k])
        return P
