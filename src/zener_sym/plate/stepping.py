"""One contact, stepped on a uniform grid with the force solved implicitly at each node.

From the contact's start t_s (delta = 0, F = 0) the force is piecewise linear on the nodes
t_k = t_s + k h. The approach at node k is then

    delta_k = d_k - sum_{j<k} L_{k-j} F_j - (L_0 + C_res) F_k,

with d_k the free motion of ball and modes from the start state (exact) and L the hat responses
of :mod:`.kernels`, so each step costs one dot product and a scalar Newton solve of
F_k = max(delta_k, 0)^{3/2}. When delta_k <= 0 the contact has ended inside the last step: its end
t_e is where the force, linear from F_{k-1} to 0 over [t_{k-1}, t_e], brings delta back to 0
(a scalar root in the partial step's width, which exists because delta_{k-1} > 0 >= delta_k).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..typing import FloatArray
from .kernels import ComplexArray, Kernel, Rates, psi2

__all__ = ["ContactRun", "step_contact", "end_of_contact"]


@dataclass
class ContactRun:
    """One contact on its grid: start, step, node forces, the partial last step and the end state."""

    t_s: float
    h: float
    F: FloatArray            # F[0] = 0 at t_s, ..., F[k-1] > 0; the end t_e = t_s + (k-1) h + a
    a: float
    x_e: float
    v_e: float
    B_e: ComplexArray        # modal amplitudes at t_e

    @property
    def t_e(self) -> float:
        return self.t_s + (len(self.F) - 1) * self.h + self.a

    @property
    def impulse(self) -> float:
        """The integral of the piecewise-linear force."""
        F, h = self.F, self.h
        if len(F) < 2:
            return 0.0
        # hats: a whole step at nodes 1 .. k-2, half a step plus half the partial step at k-1
        return float(h * np.sum(F[1:-1]) + F[-1] * (h + self.a) / 2.0)

    @property
    def peak(self) -> tuple[float, float]:
        """(time, force) of the maximum: the parabola through the largest node and its neighbours."""
        F, h = self.F, self.h
        i = int(np.argmax(F))
        if 0 < i < len(F) - 1:
            f0, f1, f2 = F[i - 1], F[i], F[i + 1]
            den = f0 - 2.0 * f1 + f2
            if den < 0.0:
                u = 0.5 * (f0 - f2) / den
                return self.t_s + (i + u) * h, float(f1 - 0.25 * (f0 - f2) * u)
        return self.t_s + i * h, float(F[i])


def step_contact(kernel: Kernel, c_res: float, x_s: float, v_s: float, B_s: ComplexArray,
                 max_steps: int) -> tuple[FloatArray, int]:
    """Node forces F[0..k] of a contact starting at (x_s, v_s, B_s): F[k] is the first zero.

    Returns the forces and k. Raises RuntimeError past ``max_steps``.
    """
    h = kernel.h
    n = max(kernel.E.shape[1] - 1, 64)
    F = np.zeros(1)
    k0 = 1
    while True:
        kernel.grow(n)
        m = np.arange(k0, n + 1)
        d_free = x_s + v_s * h * m - _combine(B_s, kernel.E[:, k0:n + 1]).real
        F = np.concatenate([F, np.zeros(n + 1 - len(F))])
        k = _march(F, d_free, kernel.Lrev, kernel.L[0] + c_res, k0, n)
        if k is not None:
            return F[:k + 1], k
        if n >= max_steps:
            raise RuntimeError(f"a contact lasted more than max_steps = {max_steps} steps of "
                               f"h = {h:.3g}; raise max_steps or loosen rtol")
        k0, n = n + 1, min(2 * n, max_steps)


def _combine(B: ComplexArray, E: ComplexArray) -> ComplexArray:
    """B @ E without BLAS (a threaded complex BLAS costs more than it saves at these sizes)."""
    return np.einsum("n,nm->m", B, E)


def _march(F: FloatArray, d_free: FloatArray, Lrev: FloatArray, a: float, k0: int,
           n: int) -> int | None:
    """Fill F[k0..n] until the force vanishes; that node's index, or None if it did not.

    ``d_free[k - k0]`` is the free approach at node k; F_k solves F = (d - a F)^{3/2} by Newton
    on u = F^{1/3} (u^2 + a u^3 = d, convex: from above, Newton decreases monotonically).
    """
    top = len(Lrev)          # Lrev[top - 1 - m] = L[m]
    dot, sqrt = np.dot, math.sqrt
    for k in range(k0, n + 1):
        d = float(d_free[k - k0])
        if k > 1:
            d -= float(dot(Lrev[top - k:top - 1], F[1:k]))
        if d <= 0.0:
            return k
        u = sqrt(d)
        if k > 2:            # linear extrapolation, kept only if above the root
            g = 2.0 * F[k - 1] - F[k - 2]
            if g > 0.0:
                ug = g ** (1.0 / 3.0) * (1.0 + 1e-9)
                if ug < u and ug * ug * (1.0 + a * ug) >= d:
                    u = ug
        for _ in range(60):
            du = (u * u * (1.0 + a * u) - d) / (u * (2.0 + 3.0 * a * u))
            u -= du
            if du <= 4e-16 * u:
                break
        F[k] = u * u * u
    return None


def end_of_contact(kernel: Kernel, c_res: float, t_s: float, x_s: float, v_s: float,
                   B_s: ComplexArray, F: FloatArray) -> ContactRun:
    """The contact's end inside the last step and the state there (``F[-1]`` is the zero node)."""
    r, h = kernel.rates, kernel.h
    k = len(F) - 1                    # F[k] = 0: the end lies in (t_{k-1}, t_k]
    Fk = F[:k]                        # nodes 0 .. k-1
    f1 = float(Fk[-1])
    km = k - 1
    # ball and modes at node k-1
    j = np.arange(1, km + 1)
    mb = (km - j).astype(float)
    wb = np.where(mb == 0, h * h / 6.0, mb * h * h)
    x1 = x_s + v_s * km * h - float(wb @ Fk[1:])
    v1 = v_s - h * float(np.sum(Fk[1:km])) - 0.5 * h * f1
    P = kernel.forced(Fk)
    E1 = kernel.E[:, km]
    cw = r.c / r.wd
    y1 = (B_s * E1).real + cw * P.imag
    u1 = (r.s * B_s * E1).real + cw * (r.s * P).imag
    B1 = r.amplitude(y1, u1)

    def delta(w: float) -> float:
        return x1 + v1 * w - f1 * w * w / 3.0 - float(np.sum(_modes_after(r, B1, f1, w)[0]))

    w_end = h if delta(h) >= 0.0 else brentq(delta, 0.0, h, xtol=1e-15 * max(h, 1e-300),
                                             rtol=8.9e-16)
    y_e, u_e = _modes_after(r, B1, f1, w_end)
    return ContactRun(t_s=t_s, h=h, F=np.array(Fk), a=w_end,
                      x_e=x1 + v1 * w_end - f1 * w_end**2 / 3.0, v_e=v1 - 0.5 * f1 * w_end,
                      B_e=r.amplitude(y_e, u_e))


def _modes_after(r: Rates, B1: ComplexArray, f1: float,
                 w: float) -> tuple[FloatArray, FloatArray]:
    """Modal displacements and velocities a time w after node k-1, the force falling linearly
    from f1 to 0 over w."""
    e = np.exp(r.s * w)
    load = f1 * w * psi2(r.s * w) * (r.c / r.wd)
    return (B1 * e).real + load.imag, (r.s * B1 * e).real + (r.s * load).imag

