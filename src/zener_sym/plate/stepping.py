"""One contact, stepped on a uniform grid with the force solved implicitly at each node.

From the contact's start t_s (delta = 0, F = 0) the force is piecewise linear on the nodes
t_k = t_s + k h. Each mode then steps exactly from node to node (:class:`.kernels.Kernel`:
B_{k+1} = E B_k + P F_k + Q F_{k+1}), and the ball as x'' = -F, so the approach at node k + 1 is

    delta_{k+1} = D_{k+1} - (h^2/6 + sum Re Q + C_res) F_{k+1},

with D_{k+1} known from the state at node k; each node costs one pass over the modes and a scalar
Newton solve of F = max(delta, 0)^{3/2} (:func:`.loops.march`). When D_{k+1} <= 0 the contact has
ended inside that step: its end t_e is where the force, linear from F_k to 0 over [t_k, t_e],
brings delta back to 0 (a scalar root in the partial step's width, which exists because
delta_k > 0 >= D_{k+1}; found by Newton kept inside that bracket, :func:`.loops.contact_end`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..typing import FloatArray
from .kernels import ComplexArray, Kernel, Rates, compiled

__all__ = ["ContactRun", "Nodes", "step_contact", "end_of_contact", "start_kick", "end_defect",
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


#: The most mode-steps one contact may take (each a complex product and sum: some seconds).
MAX_WORK = 2e9


@dataclass
class Nodes:
    """A contact's node forces F[0..k] (F[k] = 0, the first node past its end), the ball's
    position and velocity and the modes' amplitudes at node k - 1, and D <= 0 the approach at
    node k with F_k = 0."""

    F: FloatArray
    x: float
    v: float
    B: ComplexArray
    D: float


def step_contact(kernel: Kernel, c_res: float, x_s: float, v_s: float, B_s: ComplexArray,
                 max_steps: int) -> Nodes:
    """The nodes of a contact starting at (x_s, v_s, B_s), up to the first with no force.

    Raises RuntimeError past ``max_steps`` nodes, or past MAX_WORK mode-steps.
    """
    h, n = kernel.h, len(kernel.E)
    limit = int(min(max_steps, max(MAX_WORK // n, 1)))
    k, F, x, v, B, D = compiled().march(kernel.E, kernel.P, kernel.Q,
                                        np.asarray(B_s, dtype=complex), float(x_s), float(v_s), h,
                                        float(c_res), int(4.0 / h) + 16, limit)
    if k < 0:
        if limit < max_steps:
            raise RuntimeError(f"a contact with {n} modes needs more than {limit} steps of "
                               f"h = {h:.3g}, over {MAX_WORK:.0e} mode-steps (some seconds): use "
                               "fewer modes or a looser rtol")
        raise RuntimeError(f"a contact lasted more than max_steps = {max_steps} steps of "
                           f"h = {h:.3g}; raise max_steps or loosen rtol")
    return Nodes(F=F, x=float(x), v=float(v), B=B, D=float(D))


def end_of_contact(kernel: Kernel, t_s: float, nodes: Nodes) -> ContactRun:
    """The contact's end inside the last step (after node k - 1, where the force is still
    positive) and the state there."""
    r, h = kernel.rates, kernel.h
    F, x1, v1, B1 = nodes.F, nodes.x, nodes.v, nodes.B
    Fk = F[:-1]                       # nodes 0 .. k-1
    f1 = float(Fk[-1])
    # the approach at node k (the force falling to 0 over the whole step) is the march's D
    w_end, y_e, u_e = compiled().contact_end(r.s, B1, r.c / r.wd, x1, v1, f1, h, nodes.D)
    v_e = v1 - 0.5 * f1 * w_end
    # the force's (t_e - t)^{3/2} end, which the linear pieces miss: F ~ (-delta'_e u)^{3/2}
    rate = max(float(np.sum(u_e)) - v_e, 0.0)
    dI = rate**1.5 * h**2.5 * end_defect(w_end / h)
    return ContactRun(t_s=t_s, h=h, F=np.array(Fk), a=w_end,
                      x_e=x1 + v1 * w_end - f1 * w_end**2 / 3.0, v_e=v_e - dI,
                      B_e=r.amplitude(y_e, u_e + r.c * dI), defect=dI)


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
