"""Exact responses of the modes (and the ball) to a piecewise-linear contact force.

Each mode obeys y'' + 2 zeta omega y' + omega^2 y = c F with zeta = eta / 2 (eta the modal loss
factor, 0 for the undamped plate). Its free motion is y = Re(B e^{s t}) with
s = -zeta omega + i omega_d, omega_d = omega sqrt(1 - zeta^2), and its impulse response is
g(u) = Im(e^{s u}) / omega_d. With F piecewise linear on a grid of step h (hat functions), the
response at a node to one hat is a closed-form integral of g, so the modes are propagated exactly
whatever omega h is: stiff high modes never limit the step. The ball (x'' = -F) is the limit
omega -> 0 of the same integrals.

The integrals use
    phi2(x) = (e^x - 1 - x) / x^2     (a half hat rising to the node),
    psi2(x) = (1 + (x - 1) e^x) / x^2 (a half hat falling from the node, seen a width later),
summed as series for small |x|, where the closed forms cancel (:mod:`.loops`, which computes
them with the rest of each step).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from types import ModuleType

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray

__all__ = ["Rates", "Kernel", "compiled"]

ComplexArray = npt.NDArray[np.complex128]

@dataclass(frozen=True)
class Rates:
    """The modes' complex rates s_n and damped frequencies omega_d for a loss factor eta."""

    omega: FloatArray
    c: FloatArray
    loss: float
    s: ComplexArray = field(init=False)
    wd: FloatArray = field(init=False)
    #: C_N = sum c_n / omega_n^2, the modes' own static compliance
    compliance: float = field(init=False)

    def __post_init__(self) -> None:
        zeta = 0.5 * self.loss
        wd = self.omega * np.sqrt(1.0 - zeta * zeta)
        object.__setattr__(self, "wd", wd)
        object.__setattr__(self, "s", -zeta * self.omega + 1j * wd)
        object.__setattr__(self, "compliance", float(np.sum(self.c / self.omega**2)))

    def amplitude(self, y: FloatArray, v: FloatArray) -> ComplexArray:
        """B with y = Re(B), y' = Re(s B): the free motion from displacement y and velocity v."""
        return y - 1j * (v - self.s.real * y) / self.wd

    def energy(self, B: ComplexArray) -> float:
        """E_p = sum (y'^2 + omega^2 y^2) / (2 c_n) of the modes in state B (at its time)."""
        return float(compiled().energy(self.s, self.omega, self.c, B))


_LOOPS: list[ModuleType] = []


def compiled() -> ModuleType:
    """The compiled loops (:mod:`.loops`), imported on first use: importing numba costs some
    0.3 s that a command not solving a plate should not pay."""
    if not _LOOPS:
        from . import loops
        _LOOPS.append(loops)
    return _LOOPS[0]


class Kernel:
    """One step h: every mode's exact step under a force linear between two nodes.

    With y = Re B and y' = Re(s B) (:meth:`Rates.amplitude`), a mode's amplitude over one step
    from node k to k + 1 is B_{k+1} = E B_k + P F_k + Q F_{k+1}: E = e^{s h} is its free motion,
    and P = -i (c / omega_d) h psi2(s h), Q = -i (c / omega_d) h phi2(s h) are its responses to
    the half hats falling from node k and rising to node k + 1 (the closed-form integrals of its
    impulse response). The stiffest mode is stepped as exactly as the softest, whatever
    omega h is.
    """

    def __init__(self, rates: Rates, h: float) -> None:
        self.rates, self.h = rates, h
        self.E, self.P, self.Q = compiled().coefficients(rates.s, rates.c / rates.wd, h)

    def state(self, B: ComplexArray, F: FloatArray) -> ComplexArray:
        """The modes' amplitudes at the last node of F, from B at its first node."""
        out: ComplexArray = compiled().replay(self.E, self.P, self.Q, np.array(B, dtype=complex),
                                              np.ascontiguousarray(F, dtype=float))
        return out
