r"""Physical scaling of Zener's equation: from SI inputs to lambda and back (Eqs. 7-11, 65-76).

Derivation (by hand; the derivation package re-does it with SymPy offline). Eq. (7),

    d^2 delta/dt^2 + F/m* + alpha dF/dt = 0,   F = K delta^{3/2},   K = (4/3) E* sqrt(R)  (Eq. 8),

with delta = T V0 delta_bar and t = T tau (Eq. 9), multiplied by T / V0, reads

    delta_bar'' + (K T^{5/2} V0^{1/2} / m*) delta_bar^{3/2}
                + (alpha K T^{3/2} V0^{1/2}) d/dtau delta_bar^{3/2} = 0.

The first coefficient is 1 for

    T = (m* / (K sqrt(V0)))^{2/5} = (m* / ((4/3) E* sqrt(R V0)))^{2/5}

(the paper prints the exponent 2/3; 2/5 is what makes Eq. 10 dimensionless), and then the
second coefficient is Zener's inelasticity parameter

    lambda = alpha K T^{3/2} V0^{1/2} = alpha m* / T.

alpha = (1 / (4 rho2 H^2)) sqrt(3 rho2 (1 - nu2^2) / E2) = 1 / (8 sqrt(D rho2 H)), with
D = E2 H^3 / (12 (1 - nu2^2)), is the point-load admittance of an infinite thin plate (centre
velocity per unit force, units s/kg). With m* = m1 = (4/3) pi R^3 rho1 this gives the derived
Eq. (11):

    lambda = (pi^{3/5} / sqrt 3) (R/H)^2 (V0/V_W)^{1/5} (rho1/rho2)^{3/5}
             (E1' / (E1' + E2'))^{2/5},     E_i' = E_i / (1 - nu_i^2),  V_W = sqrt(E2' / rho2)

(the paper prints pi^{3/2} and the exponents 1/2, 3/2, 2/3). Forces scale as F = (m* V0 / T) F_bar,
the impulse as I = m* V0 I_bar, the plate deflection as w = alpha I = lambda T V0 I_bar (Eq. 65-66)
and the energy loss ratio xi = 2 lambda (m*/m1) int F_bar^2 dtau = chi V0^{1/5} (R/H)^2 int F_bar^2
dtau (Eqs. 74-76) with

    chi = (2 pi^{3/5} / sqrt 3) sqrt(rho2 (1 - nu2^2) / E2) (E*/rho2)^{2/5} (rho1/rho2)^{3/5}

(printed with pi^{3/2} and exponents 2/3, 2/3, and V0^{1/2} in Eq. 76; chi has units (s/m)^{1/5}).

Reduced mass: Zener's plate is infinite; its inertia is entirely in the admittance alpha (the plate
answers a force with a velocity alpha F, not with a rigid-body acceleration), so the reduced mass
of Eq. (7) is m* = m1 (the paper's m*^{-1} = m1^{-1} + m2^{-1} with m2 -> infinity). Every function
takes ``m_star`` explicitly so that this choice is visible at the call site.
"""
from __future__ import annotations

import math

__all__ = ["effective_modulus", "sphere_mass", "plate_admittance", "plate_wave_speed",
           "flexural_rigidity", "characteristic_time", "inelasticity", "inelasticity_eq11", "chi",
           "force_scale", "length_scale"]


def effective_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """E* [Pa] with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (below Eq. 8)."""
    return 1.0 / ((1.0 - nu1**2) / E1 + (1.0 - nu2**2) / E2)


def sphere_mass(R: float, rho1: float) -> float:
    """m1 = (4/3) pi R^3 rho1 [kg]."""
    return 4.0 / 3.0 * math.pi * R**3 * rho1


def plate_admittance(E2: float, nu2: float, rho2: float, H: float) -> float:
    """Zener's alpha = (1/(4 rho2 H^2)) sqrt(3 rho2 (1 - nu2^2)/E2) [s/kg] (below Eq. 7).

    Equal to 1/(8 sqrt(D rho2 H)): the centre velocity of an infinite thin plate per unit point
    force.
    """
    return math.sqrt(3.0 * rho2 * (1.0 - nu2**2) / E2) / (4.0 * rho2 * H**2)


def plate_wave_speed(E2: float, nu2: float, rho2: float) -> float:
    """V_W = sqrt(E2 / (rho2 (1 - nu2^2))) [m/s], quasi-longitudinal plate waves (below Eq. 11)."""
    return math.sqrt(E2 / (rho2 * (1.0 - nu2**2)))


def flexural_rigidity(E2: float, nu2: float, H: float) -> float:
    """D = E2 H^3 / (12 (1 - nu2^2)) [N m]."""
    return E2 * H**3 / (12.0 * (1.0 - nu2**2))


def characteristic_time(m_star: float, E_star: float, R: float, V0: float) -> float:
    """T = (m* / ((4/3) E* sqrt(R V0)))^{2/5} [s] (Eq. 9, exponent derived: 2/5)."""
    return float((m_star / (4.0 / 3.0 * E_star * math.sqrt(R * V0))) ** 0.4)


def inelasticity(alpha: float, m_star: float, T: float) -> float:
    """lambda = alpha m* / T (from nondimensionalising Eq. 7; see the module docstring)."""
    return alpha * m_star / T


def inelasticity_eq11(R: float, H: float, V0: float, rho1: float, E1: float, nu1: float, rho2: float, E2: float, nu2: float) -> float:
    """lambda in the closed form of the derived Eq. (11) (m* = m1); equals ``inelasticity``."""
    E1p, E2p = E1 / (1.0 - nu1**2), E2 / (1.0 - nu2**2)
    VW = math.sqrt(E2p / rho2)
    return float(math.pi**0.6 / math.sqrt(3.0) * (R / H) ** 2 * (V0 / VW) ** 0.2
                 * (rho1 / rho2) ** 0.6 * (E1p / (E1p + E2p)) ** 0.4)


def chi(rho1: float, E_star: float, rho2: float, E2: float, nu2: float) -> float:
    """chi [(s/m)^{1/5}] of Eq. (76), derived: xi = chi V0^{1/5} (R/H)^2 int F_bar^2 dtau."""
    return float(2.0 * math.pi**0.6 / math.sqrt(3.0) * math.sqrt(rho2 * (1.0 - nu2**2) / E2)
                 * (E_star / rho2) ** 0.4 * (rho1 / rho2) ** 0.6)


def force_scale(m_star: float, V0: float, T: float) -> float:
    """F / F_bar = m* V0 / T [N] (= K (T V0)^{3/2} by the choice of T)."""
    return m_star * V0 / T


def length_scale(T: float, V0: float) -> float:
    """delta / delta_bar = T V0 [m] (Eq. 9)."""
    return T * V0
