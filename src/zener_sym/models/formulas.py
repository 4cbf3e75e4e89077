"""Hand-written explicit formulas of the paper, corrected, as a second route to the generated kernels.

Written by hand from the derivation's results (not from the printed paper, whose transcription has
wrong exponents), in plain numpy; tests compare them with the generated kernels and the exact model.

Zeroth order (Eqs. 23-25, 32-35, 54, 58, 60, 61, 79):

    delta_m(0) = (5/4)^{2/5},   k = (lambda + (5/4)^{-3/5})^{-1/3},   beta = k lambda / 2,
    omega0 = sqrt(k - beta^2),   delta0 = exp(-beta tau) sin(omega0 tau) / omega0,
    tau_d = pi / omega0,   tau_dc = atan2(omega0, beta) / omega0,   tau_dr = tau_d - tau_dc,
    eta = (pi - phi) / phi with phi = atan2(omega0, beta),   e = exp(-pi beta / omega0),
    delta_m0 = delta0(tau_dc) = exp(-beta tau_dc) / sqrt(k).

The printed (59)-(61), (80) and (81) carry (5/4)^{3/5} or (5/4)^{-1/3} where (5/4)^{-3/5} belongs.

Hunter (52) and Reed (53), from Eqs. (3)-(6) and the scaling delta-bar = delta / (T V0),
tau = t / T, F-bar = F T / (m* V0): Hunter's sine delta = delta_m sin(1.068 V0 t / delta_m) with
the Hertz maximum delta_m (3), i.e. delta-bar_m = (5/4)^{2/5} = 1.09336, has the dimensionless
frequency Omega = 1.068 / delta-bar_m = 0.97681 (printed 0.977). Newton's law (5) gives
F-bar = delta-bar_m Omega^2 sin(Omega tau) (amplitude 1.04322, printed 1.043); Reed's Hertz law (6)
gives F-bar = delta-bar_m^{3/2} sin^{3/2}(Omega tau) (amplitude 1.14328, printed "1.143 sin^3": the
exponent is 3/2). The number 1.068 is Hunter's (pi / 1.068 = 2.94 is Hertz's duration factor in
Eq. 2), kept as his model's input.

Fits: (24) delta_m^{-3/2} = lambda + (5/4)^{-3/5}; (55) tau_d = tau_Hertz exp(0.23 lambda^1.80)
with the paper's tau_Hertz = 3.214; (70) xi = 1 - exp(-2.755 lambda).
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from ..typing import FloatArray, RealArrayLike

__all__ = ["DELTA_M_HERTZ", "LAM_CRIT", "k", "beta", "omega0", "delta0", "delta0_dot", "tau_d0",
           "tau_dc0", "tau_dr0", "eta0", "e0", "e0_paper_form", "delta_m0", "F_m0",
           "OMEGA_HUNTER", "A_HUNTER", "A_REED", "F_hunter", "F_reed", "delta_m_fit_24",
           "tau_d_fit_55", "xi_fit_70", "TAU_HERTZ_PAPER", "int_sin32"]

# Every function takes a float or an array and returns float64 of the (broadcast) shape of its
# arguments: an array, or a numpy float64 for scalars (numpy's arithmetic on 0-d arrays); the
# annotations say FloatArray for both, as numpy's own stubs do. Arguments are not checked: these
# are the formulas, the models check lambda.

#: Hertz's maximum compression at lambda = 0, Eq. (23): 1 - (4/5) delta^{5/2} = 0
DELTA_M_HERTZ: float = 1.25 ** 0.4
_C: float = 1.25 ** -0.6  # delta_m(0)^{-3/2}


def k(lam: RealArrayLike) -> FloatArray:
    """Eq. (25): k = sqrt(delta_m) with delta_m from the interpolation (24).

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), >= 0.

    Returns
    -------
    numpy.ndarray
        k, of the shape of ``lam``.
    """
    return (np.asarray(lam, dtype=float) + _C) ** (-1.0 / 3.0)


def beta(lam: RealArrayLike) -> FloatArray:
    """Eq. (32): beta = k lambda / 2.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), >= 0.

    Returns
    -------
    numpy.ndarray
        The decay rate beta, of the shape of ``lam``.
    """
    lam = np.asarray(lam, dtype=float)
    return k(lam) * lam / 2.0


def omega0(lam: RealArrayLike) -> FloatArray:
    """Eq. (33): omega0 = sqrt(4k - k^2 lambda^2) / 2, written k (4 - k lambda^2) / 4 inside.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), 0 <= lambda < ``LAM_CRIT`` (NaN beyond).

    Returns
    -------
    numpy.ndarray
        The frequency omega0, of the shape of ``lam``.
    """
    lam = np.asarray(lam, dtype=float)
    kk = k(lam)
    return np.sqrt(kk * (4.0 - kk * lam * lam)) / 2.0


#: Critical lambda of Eq. (81): k lambda^2 = 4, i.e. lambda^6 = 64 (lambda + (5/4)^{-3/5})
LAM_CRIT: float = brentq(lambda x: x**6 - 64.0 * (x + _C), 2.0, 3.0, xtol=1e-16, rtol=8.9e-16)


def delta0(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """Eq. (35): the zeroth-order compression exp(-beta tau) sin(omega0 tau) / omega0.

    Parameters
    ----------
    tau : float or array_like
        Dimensionless time (Eq. 9).
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``; broadcast against ``tau``.

    Returns
    -------
    numpy.ndarray
        delta0 (not cut at the end of contact).
    """
    tau = np.asarray(tau, dtype=float)
    w, b = omega0(lam), beta(lam)
    out: FloatArray = np.exp(-b * tau) * np.sin(w * tau) / w
    return out


def delta0_dot(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """Eq. (56): the zeroth-order velocity of compression d delta0 / d tau.

    Parameters
    ----------
    tau : float or array_like
        Dimensionless time (Eq. 9).
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``; broadcast against ``tau``.

    Returns
    -------
    numpy.ndarray
        delta0'.
    """
    tau = np.asarray(tau, dtype=float)
    w, b = omega0(lam), beta(lam)
    out: FloatArray = np.exp(-b * tau) * (np.cos(w * tau) - b / w * np.sin(w * tau))
    return out


def tau_d0(lam: RealArrayLike) -> FloatArray:
    """Eq. (54): the zeroth-order contact duration pi / omega0.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        tau_d, of the shape of ``lam``.
    """
    return np.pi / omega0(lam)


def tau_dc0(lam: RealArrayLike) -> FloatArray:
    """Eq. (58) as atan2 (regular at beta = 0): the zeroth-order compression duration.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        tau_dc, of the shape of ``lam``.
    """
    out: FloatArray = np.arctan2(omega0(lam), beta(lam)) / omega0(lam)
    return out


def tau_dr0(lam: RealArrayLike) -> FloatArray:
    """Eq. (60): the zeroth-order restitution duration tau_d - tau_dc.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        tau_dr, of the shape of ``lam``.
    """
    return tau_d0(lam) - tau_dc0(lam)


def eta0(lam: RealArrayLike) -> FloatArray:
    """Eq. (61): the zeroth-order duration ratio tau_dr / tau_dc = pi / phi - 1.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        eta, of the shape of ``lam``.
    """
    phi = np.arctan2(omega0(lam), beta(lam))
    out: FloatArray = np.pi / phi - 1.0
    return out


def e0(lam: RealArrayLike) -> FloatArray:
    """Eq. (79): e = -delta0'(pi/omega0) = exp(-pi beta / omega0).

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        The zeroth-order coefficient of restitution, of the shape of ``lam``.
    """
    out: FloatArray = np.exp(-np.pi * beta(lam) / omega0(lam))
    return out


def e0_paper_form(lam: RealArrayLike) -> FloatArray:
    """Eq. (79) as printed: exp(-pi lambda / sqrt(4/k - lambda^2)) (same value as :func:`e0`).

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        e, of the shape of ``lam``.
    """
    lam = np.asarray(lam, dtype=float)
    out: FloatArray = np.exp(-np.pi * lam / np.sqrt(4.0 / k(lam) - lam * lam))
    return out


def delta_m0(lam: RealArrayLike) -> FloatArray:
    """delta0 at tau_dc: sin(omega0 tau_dc) = omega0 / sqrt(k).

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        The zeroth-order maximum compression, of the shape of ``lam``.
    """
    out: FloatArray = np.exp(-beta(lam) * tau_dc0(lam)) / np.sqrt(k(lam))
    return out


def F_m0(lam: RealArrayLike) -> FloatArray:
    """Zeroth-order maximum force delta_m0^{3/2}.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda, 0 <= lambda < ``LAM_CRIT``.

    Returns
    -------
    numpy.ndarray
        F_m, of the shape of ``lam``.
    """
    return delta_m0(lam) ** 1.5


OMEGA_HUNTER: float = 1.068 / DELTA_M_HERTZ
A_HUNTER: float = DELTA_M_HERTZ * OMEGA_HUNTER**2
A_REED: float = DELTA_M_HERTZ**1.5


def F_hunter(tau: RealArrayLike) -> FloatArray:
    """Eq. (52): A_HUNTER sin(OMEGA_HUNTER tau) for 0 <= tau <= pi/OMEGA_HUNTER, else 0.

    Parameters
    ----------
    tau : float or array_like
        Dimensionless time (Eq. 9), >= 0.

    Returns
    -------
    numpy.ndarray
        Hunter's force, of the shape of ``tau``.
    """
    tau = np.asarray(tau, dtype=float)
    x = OMEGA_HUNTER * tau
    return np.where(x <= np.pi, A_HUNTER * np.sin(np.clip(x, 0.0, np.pi)), 0.0)


def F_reed(tau: RealArrayLike) -> FloatArray:
    """Eq. (53): A_REED sin^{3/2}(OMEGA_HUNTER tau) on the contact, else 0.

    Parameters
    ----------
    tau : float or array_like
        Dimensionless time (Eq. 9), >= 0.

    Returns
    -------
    numpy.ndarray
        Reed's force, of the shape of ``tau``.
    """
    tau = np.asarray(tau, dtype=float)
    x = OMEGA_HUNTER * tau
    return np.where(x <= np.pi, A_REED * np.sin(np.clip(x, 0.0, np.pi)) ** 1.5, 0.0)


def delta_m_fit_24(lam: RealArrayLike) -> FloatArray:
    """Eq. (24): delta_m = (lambda + (5/4)^{-3/5})^{-2/3}.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), >= 0.

    Returns
    -------
    numpy.ndarray
        The fitted maximum compression, of the shape of ``lam``.
    """
    return (np.asarray(lam, dtype=float) + _C) ** (-2.0 / 3.0)


TAU_HERTZ_PAPER: float = 3.214


def tau_d_fit_55(lam: RealArrayLike) -> FloatArray:
    """Eq. (55): tau_Hertz exp(0.23 lambda^1.80) with the paper's tau_Hertz = 3.214.

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), >= 0.

    Returns
    -------
    numpy.ndarray
        The fitted contact duration, of the shape of ``lam``.
    """
    out: FloatArray = TAU_HERTZ_PAPER * np.exp(0.23 * np.asarray(lam, dtype=float) ** 1.80)
    return out


def xi_fit_70(lam: RealArrayLike) -> FloatArray:
    """Eq. (70): xi = 1 - exp(-2.755 lambda).

    Parameters
    ----------
    lam : float or array_like
        Zener's lambda (Eq. 11), >= 0.

    Returns
    -------
    numpy.ndarray
        The fitted energy-loss ratio, of the shape of ``lam``.
    """
    out: FloatArray = 1.0 - np.exp(-2.755 * np.asarray(lam, dtype=float))
    return out


# integrals of the sinusoidal pulses over their contact, used by the pulse models
_INT_SIN32: float = math.sqrt(math.pi) * math.gamma(1.25) / math.gamma(1.75)  # int_0^pi sin^{3/2}


def int_sin32(x: RealArrayLike) -> FloatArray:
    """int_0^x sin^{3/2} t dt for 0 <= x <= pi, in closed form (Reed's impulse, Eq. 53).

    With s = sin^2 t, sin^{3/2} t dt = (1/2) s^{1/4} (1 - s)^{-1/2} ds on [0, pi/2], so the
    integral is (1/2) B(5/4, 1/2) I_{sin^2 x}(5/4, 1/2) there (I the regularised incomplete
    beta function), and by symmetry B(5/4, 1/2) minus that beyond pi/2.

    Parameters
    ----------
    x : float or array_like
        Upper limit, 0 <= x <= pi (not checked).

    Returns
    -------
    numpy.ndarray
        The integral, of the shape of ``x``.
    """
    from scipy.special import betainc

    x = np.asarray(x, dtype=float)
    s2, c2 = np.sin(x) ** 2, np.cos(x) ** 2
    # near pi/2 take the complement I_s(5/4, 1/2) = 1 - I_{1-s}(1/2, 5/4) with 1 - s = cos^2 x
    # formed directly (1 - sin^2 x would lose digits there)
    near_top = s2 > 0.5
    with np.errstate(all="ignore"):
        low = np.where(near_top, 1.0 - betainc(0.5, 1.25, c2), betainc(1.25, 0.5, s2))
        high = np.where(near_top, 1.0 + betainc(0.5, 1.25, c2), 2.0 - betainc(1.25, 0.5, s2))
    out: FloatArray = 0.5 * _INT_SIN32 * np.where(x <= np.pi / 2, low, high)
    return out
