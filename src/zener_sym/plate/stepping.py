"""One contact, stepped on a uniform grid with the force solved implicitly at each node.

From the contact's start t_s (delta = 0, F = 0) the force is piecewise linear on the nodes
t_k = t_s + k h. The approach at node k is then

    delta_k = d_k - sum_{j<k} L_{k-j} F_j - (L_0 + C_res) F_k,

with d_k the free motion of ball and modes from the start state (exact) and L the hat responses
of :mod:`.kernels`, so each step costs its share of a block's history product and a scalar
Newton solve of F_k = max(delta_k, 0)^{3/2}. When delta_k <= 0 the contact has ended inside the
last step: its end t_e is where the force, linear from F_{k-1} to 0 over [t_{k-1}, t_e], brings
delta back to 0 (a scalar root in the partial step's width, which exists because
delta_{k-1} > 0 >= delta_k; found by Newton kept inside that bracket).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..typing import FloatArray
from .kernels import ComplexArray, Kernel, Rates, psi2

__all__ = ["ContactRun", "step_contact", "end_of_contact", "start_kick", "end_defect",
           "START_DEFECT", "zeta_m32"]


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
    defect: float = 0.0      # impulse the linear pieces miss at the start and the end

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
        return float(h * np.sum(F[1:-1]) + F[-1] * (h + self.a) / 2.0 + self.defect)

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
                return float(self.t_s + (i + u) * h), float(f1 - 0.25 * (f0 - f2) * u)
        return float(self.t_s + i * h), float(F[i])


def step_contact(kernel: Kernel, c_res: float, x_s: float, v_s: float, B_s: ComplexArray,
                 max_steps: int) -> tuple[FloatArray, int]:
    """Node forces F[0..k] of a contact starting at (x_s, v_s, B_s): F[k] is the first zero.

    Returns the forces and k. Raises RuntimeError past ``max_steps``.
    """
    h = kernel.h
    n = max(len(kernel.L) - 1, 64)
    F = np.zeros(1)
    k0 = 1
    while True:
        kernel.grow(n)
        m = np.arange(k0, n + 1)
        d_free: FloatArray = x_s + v_s * h * m.astype(float)
        if np.any(B_s):          # the plate at rest (the first contact) adds nothing
            d_free = d_free - kernel.series(B_s, n + 1)[k0:].real
        F = np.concatenate([F, np.zeros(n + 1 - len(F))])
        k = _march(F, d_free, kernel.L, kernel.L[0] + c_res, k0, n)
        if k is not None:
            return F[:k + 1], k
        if n >= max_steps:
            raise RuntimeError(f"a contact lasted more than max_steps = {max_steps} steps of "
                               f"h = {h:.3g}; raise max_steps or loosen rtol")
        k0, n = n + 1, min(2 * n, max_steps)


#: Nodes marched per block: the history of the nodes before a block enters it by one
#: matrix-vector product, only the block's own nodes are added one by one.
_BLOCK = 16


def _march(F: FloatArray, d_free: FloatArray, L: FloatArray, a: float, k0: int,
           n: int) -> int | None:
    """Fill F[k0..n] until the force vanishes; that node's index, or None if it did not.

    ``d_free[k - k0]`` is the free approach at node k; F_k solves F = (d - a F)^{3/2} by Newton
    on u = F^{1/3} (u^2 + a u^3 = d, convex: from above, Newton decreases monotonically; from
    below, its first step lands above), started from the forces' quadratic extrapolation.
    The nodes go by blocks of _BLOCK: sum_{j < k} L[kk - j] F_j for the block's nodes kk at once
    (a Hankel view of L against the reversed forces), then the block's own terms in Python.
    """
    sqrt = math.sqrt
    dl = d_free.tolist()
    Lb = L[:_BLOCK + 1].tolist()
    # the last three forces, as Python floats
    f1, f2, f3 = (float(F[k0 - i]) if k0 >= i else 0.0 for i in (1, 2, 3))
    k = k0
    while k <= n:
        b = min(_BLOCK, n + 1 - k)
        if k > 1:
            # H[i, q - 1] = L[i + q], q = k - j: the weight of node j = k - q at node k + i
            H = np.ndarray((b, k - 1), dtype=float, buffer=L, offset=L.itemsize,
                           strides=(L.itemsize, L.itemsize))
            hist = (H @ F[k - 1:0:-1]).tolist()
        else:
            hist = [0.0] * b
        fb: list[float] = []
        for i in range(b):
            kk = k + i
            d = dl[kk - k0] - hist[i]
            for j in range(i):
                d -= Lb[i - j] * fb[j]
            if d <= 0.0:
                F[k:kk] = fb
                return kk
            u = sqrt(d)                  # above the root: Newton from there is monotone
            g = 3.0 * (f1 - f2) + f3     # the quadratic extrapolation of the forces
            if kk > 3 and g > 0.0 and g ** (1.0 / 3.0) < u:
                u = g ** (1.0 / 3.0)     # if below the root, one step brings it above
            for _ in range(60):
                du = (u * u * (1.0 + a * u) - d) / (u * (2.0 + 3.0 * a * u))
                u -= du
                # Newton's next correction is about du^2 / (2 u): below 1e-16 u from here
                if abs(du) <= 1e-8 * u:
                    break
            f3, f2, f1 = f2, f1, u * u * u
            fb.append(f1)
        F[k:k + b] = fb
        k += b
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
    E1 = kernel.column(km)
    cw = r.c / r.wd
    y1 = (B_s * E1).real + cw * P.imag
    u1 = (r.s * B_s * E1).real + cw * (r.s * P).imag
    B1 = r.amplitude(y1, u1)

    d_h = _delta_end(r, B1, x1, v1, f1 * cw, f1, h)[0]
    if d_h >= 0.0:
        w_end = h
    else:
        d_0 = x1 - float(B1.real.sum())
        w_end = _end_root(lambda w: _delta_end(r, B1, x1, v1, f1 * cw, f1, w), h,
                          h * d_0 / (d_0 - d_h))
    y_e, u_e = _modes_after(r, B1, f1, w_end)
    v_e = v1 - 0.5 * f1 * w_end
    # the force's (t_e - t)^{3/2} end, which the linear pieces miss: F ~ (-delta'_e u)^{3/2}
    rate = max(float(np.sum(u_e)) - v_e, 0.0)
    dI = rate**1.5 * h**2.5 * end_defect(w_end / h)
    return ContactRun(t_s=t_s, h=h, F=np.array(Fk), a=w_end,
                      x_e=x1 + v1 * w_end - f1 * w_end**2 / 3.0, v_e=v_e - dI,
                      B_e=r.amplitude(y_e, u_e + r.c * dI), defect=dI)


def _delta_end(r: Rates, B1: ComplexArray, x1: float, v1: float, cw1: FloatArray, f1: float,
               w: float) -> tuple[float, float]:
    """The approach delta and d(delta)/dw a time w after node k-1, the force falling linearly
    from f1 to 0 over that same w (so the derivative is not the approach's rate: with
    q(w) = w psi2(s w), q'(w) = e^{s w} - psi2(s w))."""
    x = r.s * w
    e = np.exp(x)
    p = psi2(x)
    d = x1 + v1 * w - f1 * w * w / 3.0 - float((B1 * e).real.sum() + w * (cw1 * p).imag.sum())
    dd = v1 - 2.0 * f1 * w / 3.0 - float((r.s * B1 * e).real.sum() + (cw1 * (e - p)).imag.sum())
    return d, dd


def _end_root(f: Callable[[float], tuple[float, float]], h: float, w: float) -> float:
    """The root of f in (0, h) given f(0) > 0 > f(h): Newton from w (the secant's point), kept
    inside the bracket (bisection when a step would leave it)."""
    lo, hi = 0.0, h
    if not lo < w < hi:
        w = 0.5 * h
    for _ in range(100):
        d, dd = f(w)
        if d == 0.0:
            return w
        if d > 0.0:
            lo = w
        else:
            hi = w
        step = d / dd if dd != 0.0 else math.inf
        w_new = w - step
        if lo < w_new < hi:
            # quadratic convergence: the next step would be about step^2 / h, below rounding
            if abs(step) <= 1e-9 * h:
                return w_new
        else:
            w_new = 0.5 * (lo + hi)
        if hi - lo <= 1e-15 * h:
            return w_new
        w = w_new
    return w


def zeta_m32(q: float) -> float:
    """Hurwitz zeta(-3/2, q) for q > 0: sum_{j<10} (q + j)^{3/2} + zeta(-3/2, q + 10), the tail by
    its Euler-Maclaurin expansion (Bernoulli terms through B_10: below 1e-15 at q >= 10)."""
    tail = q + 10.0
    head = sum((q + j) ** 1.5 for j in range(10))
    # q^{5/2}/(s-1) + q^{3/2}/2 + sum_k B_2k/(2k)! (s)_{2k-1} q^{-s-2k+1}, s = -3/2
    out = -tail**2.5 / 2.5 + 0.5 * tail**1.5
    coef = _EM_COEF
    p = tail**0.5
    for c in coef:
        out += c * p
        p /= tail * tail
    return float(head + out)


def _em_coefficients() -> list[float]:
    bern = [1.0 / 6.0, -1.0 / 30.0, 1.0 / 42.0, -1.0 / 30.0, 5.0 / 66.0]
    s, out = -1.5, []
    for k, b in enumerate(bern, start=1):
        poch = 1.0
        for i in range(2 * k - 1):
            poch *= s + i
        out.append(b / math.factorial(2 * k) * poch)
    return out


_EM_COEF = _em_coefficients()

#: -zeta(-3/2): the impulse that linear pieces miss at a (tau - tau_s)^{3/2} start on the grid,
#: in units of (delta'_s)^{3/2} h^{5/2} (Navot's extension of Euler-Maclaurin)
START_DEFECT = -zeta_m32(1.0)


def end_defect(theta: float) -> float:
    """The impulse linear pieces miss at a (tau_e - tau)^{3/2} end a fraction theta of a step
    after the last node, in units of (-delta'_e)^{3/2} h^{5/2}:
    theta^{3/2}/2 - theta^{5/2}/2 - zeta(-3/2, theta) (Hurwitz zeta)."""
    return float(theta**1.5 / 2.0 - theta**2.5 / 2.0 - zeta_m32(theta))


def start_kick(r: Rates, h: float, v_s: float, B_s: ComplexArray) -> tuple[float, ComplexArray,
                                                                              float]:
    """(v_s, B_s, dI) with the start's missed impulse dI applied at t_s: ball slowed, modes
    pushed."""
    rate = max(v_s - float(np.sum((r.s * B_s).real)), 0.0)
    dI = rate**1.5 * h**2.5 * START_DEFECT
    y, u = B_s.real, (r.s * B_s).real
    return v_s - dI, r.amplitude(y, u + r.c * dI), dI


def _modes_after(r: Rates, B1: ComplexArray, f1: float,
                 w: float) -> tuple[FloatArray, FloatArray]:
    """Modal displacements and velocities a time w after node k-1, the force falling linearly
    from f1 to 0 over w."""
    e = np.exp(r.s * w)
    load = f1 * w * psi2(r.s * w) * (r.c / r.wd)
    return (B1 * e).real + load.imag, (r.s * B1 * e).real + (r.s * load).imag

