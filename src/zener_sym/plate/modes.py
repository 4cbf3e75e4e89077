"""The bounded plate's modes seen from the impact point: :func:`modal_plate` builds a ModalPlate.

The mode formulas (derived in ``zener_sym.derivation.plate``, printed into
``zener_sym.generated.plate``) give, for a plate of size L (the circle's radius b, or sqrt(a b)
for an a x b rectangle), the dimensionless frequencies Omega_n = omega_n L^2 sqrt(rho h / D) and
participations psi_n = phi_n(impact)^2 rho h L^2 / M_n, and the static compliance at the impact
point S = C_s D / L^2 = sum_n psi_n / Omega_n^2. In Zener's scales (see :mod:`.modal`)

    omega_n = beta Omega_n,   c_n = 8 lambda beta psi_n,   C_s = (8 lambda / beta) S,

with Zener's lambda = m / (8 t_0 sqrt(D rho h)) (Eq. 11) and beta = t_0 sqrt(D / (rho h)) / L^2.

Here the roots of the circle's frequency equation are found for n up to :data:`MAX_MODES`: the
n-th root lies in a bracket of width pi fixed by the zeros of J0 and J1 (the derivation shows
why), and a safeguarded Newton iteration, vectorised over all roots, polishes them. The
rectangle's modes are the Navier modes sin(m pi x/a) sin(n pi y/b); those with a nodal line
through the impact point (m x/a or n y/b an integer) do not participate and are left out.
"""
from __future__ import annotations

import math
import numbers
from typing import NamedTuple

import numpy as np

from ..typing import FloatArray
from . import formulas as F
from .modal import ModalPlate

__all__ = ["modal_plate", "plate_constants", "dimensionless_modes", "PlateConstants",
           "SHAPES", "SUPPORTS", "MAX_MODES", "ASPECT_RANGE", "EDGE_GAP"]

#: The plate shapes: a circle struck at its centre, a rectangle struck anywhere inside.
SHAPES = ("circle", "rectangle")
#: The edge supports; the rectangle is simply supported only (its modes are then Navier's).
SUPPORTS = ("clamped", "simply-supported")
#: The rectangle's aspect a/b allowed (beyond it, a strip is a beam).
ASPECT_RANGE = (1e-3, 1e3)
#: The closest an impact point may come to a rectangle's edge, as a fraction of the side: within
#: a plate's thickness of its support Kirchhoff's plate does not hold.
EDGE_GAP = 1e-4
#: The largest mode count: a million modes take 16 MB and about a second to find; more would
#: only feed rounding (the static correction covers the modes left out).
MAX_MODES = 1_000_000


class PlateConstants(NamedTuple):
    """The numbers that judge a plate against Zener's infinite one (dimensionless, of shape and
    support alone): the first participating mode's frequency Omega_1 = omega_1 L^2 sqrt(rho h/D)
    and the static compliance S = C_s D / L^2 at the impact point. In Zener's scales the first
    mode rings at omega_1 t_0 = beta Omega_1 (quasi-static when it is >> 1, the contact lasting
    about 3 t_0) and the static compliance is C_s m / t_0^2 = 8 lambda S / beta."""

    Omega1: float
    S: float


def _check_choice(name: str, value: object, allowed: tuple[str, ...]) -> str:
    if not isinstance(value, str) or value not in allowed:
        raise ValueError(f"unknown {name} {value!r}; allowed: {', '.join(map(repr, allowed))}")
    return value


def _check_real(name: str, value: object, *, lo: float | None = None, hi: float | None = None,
                lo_open: bool = True, hi_open: bool = True, allowed: str = "") -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a real number ({allowed}), got {value!r}")
    x = float(value)
    bad = not math.isfinite(x)
    if lo is not None:
        bad = bad or (x <= lo if lo_open else x < lo)
    if hi is not None:
        bad = bad or (x >= hi if hi_open else x > hi)
    if bad:
        raise ValueError(f"{name} = {value!r} is outside the allowed range: {allowed}")
    return x


def _check_n_modes(n_modes: object) -> int:
    if isinstance(n_modes, bool) or not isinstance(n_modes, numbers.Integral):
        raise ValueError(f"n_modes must be an integer, 1 <= n_modes <= {MAX_MODES}, "
                         f"got {n_modes!r}")
    n = int(n_modes)
    if not 1 <= n <= MAX_MODES:
        raise ValueError(f"n_modes = {n} is not allowed: 1 <= n_modes <= {MAX_MODES} (more modes "
                         "than that this machine would hold only as rounding; the static "
                         "correction covers the modes left out)")
    return n


def _check_geometry(shape: str, aspect: object, impact: object) -> tuple[float, float, float]:
    """(aspect, xi, eta), checked: the impact point inside the plate, the circle at its centre."""
    if not (isinstance(impact, (tuple, list)) and len(impact) == 2):
        raise ValueError(f"impact must be a pair (x/a, y/b) of fractions, got {impact!r}")
    xi, eta = (_check_real(f"impact[{i}]", v, allowed="a fraction of the plate's side")
               for i, v in enumerate(impact))
    if shape == "circle":
        if aspect != 1.0:
            raise ValueError(f"aspect = {aspect!r} is the rectangle's a/b; a circle has none "
                             "(leave it at 1.0)")
        if (xi - 0.5) ** 2 + (eta - 0.5) ** 2 >= 0.25:
            raise ValueError(f"impact = {tuple(impact)!r} is outside the circle (fractions of "
                             "its diameter; the centre is (0.5, 0.5))")
        if (xi, eta) != (0.5, 0.5):
            raise ValueError(f"impact = {tuple(impact)!r}: a circle is struck at its centre "
                             "(0.5, 0.5) only (its modes here are the axisymmetric ones)")
        return 1.0, xi, eta
    s = _check_real("aspect", aspect, lo=ASPECT_RANGE[0], hi=ASPECT_RANGE[1], lo_open=False,
                    hi_open=False, allowed=f"{ASPECT_RANGE[0]:g} <= a/b <= {ASPECT_RANGE[1]:g} "
                    "(a longer plate is a beam)")
    if not (0.0 < xi < 1.0 and 0.0 < eta < 1.0):
        raise ValueError(f"impact = {tuple(impact)!r} is outside the plate: each fraction "
                         "(x/a, y/b) must lie strictly between 0 and 1 (on the supported edge "
                         "no mode moves)")
    if min(xi, eta, 1.0 - xi, 1.0 - eta) < EDGE_GAP * (1.0 - 1e-9):  # 1 - 0.9999 rounds below
        raise ValueError(f"impact = {tuple(impact)!r} is closer to the supported edge than "
                         f"{EDGE_GAP:g} of the side: allowed {EDGE_GAP:g} <= x/a, y/b <= "
                         f"{1 - EDGE_GAP:g} (nearer, Kirchhoff's thin plate does not hold)")
    return s, xi, eta


def _check_plate(shape: object, support: object, aspect: object, impact: object,
                 nu: object) -> tuple[str, str, float, float, float, float]:
    shape = _check_choice("shape", shape, SHAPES)
    support = _check_choice("support", support, SUPPORTS)
    if shape == "rectangle" and support != "simply-supported":
        raise ValueError(f"support {support!r} for a rectangle: only 'simply-supported' is "
                         "allowed (the Navier modes; a clamped rectangle has no closed-form modes)")
    s, xi, eta = _check_geometry(shape, aspect, impact)
    nu = _check_real("nu", nu, lo=-1.0, hi=0.5, allowed="Poisson's ratio, -1 < nu < 0.5")
    return shape, support, s, xi, eta, nu


# ------------------------------------------------------------------------------ the circle
def _circle_brackets(n: int, support: str, nu: float) -> tuple[FloatArray, FloatArray]:
    """Brackets [lo, hi] holding exactly the n-th axisymmetric root x_n = k_n b, n = 1..N.

    Clamped: J1/J0 = -I1/I0 lies in (-1, 0), which happens only between a zero of J0 and the
    next zero of J1: x_n in (j_{0,n}, j_{1,n}) within ((n - 1/2) pi, (n + 1/2) pi).
    Simply supported: J1/J0 = 2x/(1 - nu) - I1/I0 > 0, only between j_{1,n-1} and j_{0,n}:
    x_n in ((n - 1) pi, n pi) (the trivial root x = 0 excluded for n = 1).
    """
    k = np.arange(1, n + 1, dtype=float)
    if support == "clamped":
        return (k - 0.5) * np.pi, (k + 0.5) * np.pi
    lo = (k - 1.0) * np.pi
    # near 0, G = -(1 + nu) x + (5 + nu) x^5/96 + O(x^7) < 0 below x_1^4 ~ 96 (1 + nu)/(5 + nu)
    lo[0] = min(0.25, 0.5 * (1.0 + nu) ** 0.25)
    return lo, k * np.pi


def _circle_roots(n: int, support: str, nu: float) -> FloatArray:
    """The first n positive roots of the circle's frequency equation (scaled: no overflow)."""
    def g(x: FloatArray) -> tuple[FloatArray, FloatArray]:
        if support == "clamped":
            return F.NUMPY.freq_clamped(x), F.NUMPY.freq_clamped_dx(x)
        return F.NUMPY.freq_ss(x, nu), F.NUMPY.freq_ss_dx(x, nu)

    lo, hi = _circle_brackets(n, support, nu)
    g_lo, g_hi = g(lo)[0], g(hi)[0]
    if np.any(np.sign(g_lo) == np.sign(g_hi)):  # the derivation's bracket claim, kept honest
        bad = int(np.argmax(np.sign(g_lo) == np.sign(g_hi))) + 1
        raise RuntimeError(f"frequency equation: no sign change in the bracket of root {bad}")
    x = np.clip(_circle_guess(n, support, nu), lo, hi)
    s_lo = np.sign(g_lo)
    active = np.arange(n)
    for it in range(200):  # Newton converges in a few steps from the guess; bisection backs it
        xa = x[active]
        gx, dg = g(xa)
        left = np.sign(gx) == s_lo[active]
        lo[active] = np.where(left, xa, lo[active])
        hi[active] = np.where(left, hi[active], xa)
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = xa - gx / dg
        # every 4th step after the 8th bisects: where the equation is flat to rounding (nu near
        # -1), Newton could wander inside the bracket for ever
        inside = np.isfinite(newton) & (newton >= lo[active]) & (newton <= hi[active])
        inside &= it < 8 or it % 4 != 3
        x_new = np.where(inside, newton, 0.5 * (lo[active] + hi[active]))
        x_new = np.where(gx == 0.0, xa, x_new)  # an exact root stays
        x[active] = x_new
        # done when the step or the bracket is within rounding of the equation (a few ulp)
        tol = 16 * np.finfo(float).eps * x_new
        moving = (np.abs(x_new - xa) > tol) & (hi[active] - lo[active] > tol)
        active = active[moving & (gx != 0.0)]
        if active.size == 0:
            return x
    raise RuntimeError("frequency equation: root polishing did not converge")  # pragma: no cover


def _circle_guess(n: int, support: str, nu: float) -> FloatArray:
    """Asymptotic roots: J0's zeros (McMahon) j_{0,n} ~ (n - 1/4) pi + 1/(8 (n - 1/4) pi);
    clamped J1/J0 = -I1/I0 ~ -1 gives x_n ~ n pi; simply supported J1/J0 ~ 2x/(1 - nu) puts
    x_n just below j_{0,n}, by (1 - nu)/(2 x)."""
    k = np.arange(1, n + 1, dtype=float)
    if support == "clamped":
        return k * np.pi
    j0 = (k - 0.25) * np.pi + 1.0 / (8.0 * (k - 0.25) * np.pi)
    return j0 - (1.0 - nu) / (2.0 * j0)


def _circle(n: int, support: str, nu: float) -> tuple[FloatArray, FloatArray]:
    x = _circle_roots(n, support, nu)
    return F.NUMPY.Omega_circle(x), F.NUMPY.psi_circle(x)


# ------------------------------------------------------------------------------ the rectangle
def _node_free(k: FloatArray, frac: float) -> FloatArray:
    """sin(k pi frac) reduced to (-1/2, 1/2] turns (exact at the nodes), 0 where k frac is an
    integer to rounding: those modes have a nodal line through the impact point."""
    t = k * frac
    u = t - np.round(t)
    return np.where(np.abs(u) <= 8 * np.finfo(float).eps * np.maximum(t, 1.0), 0.0, u)


def _rectangle(n: int, s: float, xi: float, eta: float) -> tuple[FloatArray, FloatArray]:
    """The n lowest Navier modes with psi > 0: Omega = pi^2 (m^2/s + k^2 s), s = a/b."""
    bound = 4.0 * np.pi * n * 4.0 + F.NUMPY.Omega_rect(1.0, 1.0, s)  # count ~ Omega/(4 pi)
    while True:
        m_max = int(math.sqrt(bound * s) / np.pi) + 1
        m = np.arange(1, m_max + 1, dtype=float)
        k_max = np.floor(np.sqrt(np.maximum(bound / np.pi**2 - m**2 / s, 0.0) / s)).astype(int)
        mm = np.repeat(m, k_max)
        kk = np.concatenate([np.arange(1, j + 1, dtype=float) for j in k_max]) if k_max.sum() \
            else np.zeros(0)
        u, v = _node_free(mm, xi), _node_free(kk, eta)
        keep = (u != 0.0) & (v != 0.0)
        if keep.sum() >= n or bound > 1e15:
            break
        bound *= 2.0
    mm, kk, u, v = mm[keep], kk[keep], u[keep], v[keep]
    Omega = F.NUMPY.Omega_rect(mm, kk, s)
    order = np.lexsort((kk, mm, Omega))[:n]  # ties (a square's m <-> k) in a fixed order
    if order.size < n:  # pragma: no cover - the bound doubles until enough modes are inside
        raise RuntimeError("too few participating modes of the rectangle found")
    return Omega[order], F.NUMPY.psi_rect(u[order], v[order])


def dimensionless_modes(n_modes: int, *, shape: str = "circle", support: str,
                        aspect: float = 1.0, impact: tuple[float, float] = (0.5, 0.5),
                        nu: float = 0.3) -> tuple[FloatArray, FloatArray]:
    """The n_modes lowest participating modes as numbers of the plate's shape and support alone.

    Parameters
    ----------
    n_modes : int
        1 <= n_modes <= :data:`MAX_MODES`.
    shape, support, aspect, impact, nu
        As for :func:`modal_plate`.

    Returns
    -------
    Omega : ndarray
        Omega_n = omega_n L^2 sqrt(rho h / D), ascending (a circle: (k_n b)^2).
    psi : ndarray
        psi_n = phi_n(impact)^2 rho h L^2 / M_n > 0.

    Raises
    ------
    ValueError
        An unknown shape or support, an impact point outside the plate, nu outside (-1, 0.5),
        n_modes outside [1, MAX_MODES].

    Examples
    --------
    >>> from zener_sym.plate.modes import dimensionless_modes
    >>> Omega, psi = dimensionless_modes(3, support="clamped")
    >>> [round(float(o), 3) for o in Omega]
    [10.216, 39.771, 89.104]
    """
    n = _check_n_modes(n_modes)
    shape, support, s, xi, eta, nu = _check_plate(shape, support, aspect, impact, nu)
    if shape == "circle":
        return _circle(n, support, nu)
    return _rectangle(n, s, xi, eta)


def _static(shape: str, support: str, s: float, xi: float, eta: float, nu: float) -> float:
    if shape == "circle":
        return float(F.NUMPY.S_circle_clamped() if support == "clamped"
                     else F.NUMPY.S_circle_ss(nu))
    return F.S_rectangle(s, xi, eta)


def plate_constants(*, shape: str = "circle", support: str, aspect: float = 1.0,
                    impact: tuple[float, float] = (0.5, 0.5), nu: float = 0.3) -> PlateConstants:
    """Omega_1 and S of a plate: what judges it against Zener's infinite plate.

    Parameters
    ----------
    shape, support, aspect, impact, nu
        As for :func:`modal_plate`.

    Returns
    -------
    PlateConstants
        ``(Omega1, S)``: see :class:`PlateConstants`.

    Examples
    --------
    >>> from zener_sym.plate.modes import plate_constants
    >>> c = plate_constants(support="clamped")
    >>> round(c.Omega1, 4), round(c.S * 16 * 3.141592653589793, 12)
    (10.2158, 1.0)
    """
    shape, support, s, xi, eta, nu = _check_plate(shape, support, aspect, impact, nu)
    Omega, _ = dimensionless_modes(1, shape=shape, support=support, aspect=aspect,
                                   impact=impact, nu=nu)
    return PlateConstants(float(Omega[0]), _static(shape, support, s, xi, eta, nu))


def modal_plate(lam: float, beta: float, *, shape: str = "circle", support: str, n_modes: int,
                aspect: float = 1.0, impact: tuple[float, float] = (0.5, 0.5),
                nu: float = 0.3) -> ModalPlate:
    """The n_modes lowest participating modes of a bounded Kirchhoff plate, in Zener's scales.

    Parameters
    ----------
    lam : float
        Zener's lambda = m / (8 t_0 sqrt(D rho h)) (Eq. 11), >= 0.
    beta : float
        The plate-size parameter beta = t_0 sqrt(D / (rho h)) / L^2 > 0 (L: the circle's radius
        b, or sqrt(a b) for an a x b rectangle); beta -> 0 is Zener's infinite plate.
    shape : {"circle", "rectangle"}
        A circle struck at its centre, or a rectangle struck at ``impact``.
    support : {"clamped", "simply-supported"}
        The edge support (no default: the answer depends on it); a rectangle is simply
        supported.
    n_modes : int
        How many modes, 1 <= n_modes <= :data:`MAX_MODES`; those with a node at the impact point
        are not counted.
    aspect : float
        The rectangle's a/b, within :data:`ASPECT_RANGE` (a circle: leave 1.0).
    impact : (float, float)
        The impact point as fractions (x/a, y/b) of the rectangle's sides, each at least
        :data:`EDGE_GAP` from 0 and 1; a circle only at its centre (0.5, 0.5).
    nu : float
        Poisson's ratio of the plate, -1 < nu < 0.5; only the simply supported circle depends
        on it.

    Returns
    -------
    ModalPlate
        omega = beta Omega_n (ascending), c = 8 lambda beta psi_n, static = 8 lambda S / beta.

    Raises
    ------
    ValueError
        An unknown shape or support (or a clamped rectangle), an impact point outside the plate
        (or off a circle's centre, or within EDGE_GAP of a rectangle's edge), an aspect outside
        ASPECT_RANGE, nu outside (-1, 0.5), lambda < 0 or beta <= 0 or either not finite,
        n_modes not an integer in [1, MAX_MODES].

    Examples
    --------
    >>> from zener_sym.plate.modes import modal_plate
    >>> p = modal_plate(1.0, 0.01, support="clamped", n_modes=200)
    >>> p.omega.shape, 0.0 < p.residual < 0.01 * p.static
    ((200,), True)
    """
    lam = _check_real("lam", lam, lo=0.0, lo_open=False, allowed="Zener's lambda >= 0, finite")
    beta = _check_real("beta", beta, lo=0.0, allowed="beta > 0, finite")
    Omega, psi = dimensionless_modes(n_modes, shape=shape, support=support, aspect=aspect,
                                     impact=impact, nu=nu)
    shape, support, s, xi, eta, nu = _check_plate(shape, support, aspect, impact, nu)
    S = _static(shape, support, s, xi, eta, nu)
    return ModalPlate(omega=beta * Omega, c=8.0 * lam * beta * psi, static=8.0 * lam * S / beta,
                      support=support, shape=shape)
