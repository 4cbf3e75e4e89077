r"""Higher-order HAM solutions of Zener's equation (10), with Liao's convergence-control c0.

Two formulations, both with the paper's auxiliary operator (12) and zeroth-order solution (35),
derived in ``zener_sym.derivation.ham_higher`` and ``zener_sym.derivation.ham_strained``:

``"paper"``: the homotopy (14) written as Liao's (1 - p) L[delta - delta0] = c0 p N[delta]
    (the paper's (14) is c0 = -1). The m-th order deformation equation is

        L[delta_m - chi_m delta_{m-1}] = c0 R_m,   delta_m(0) = delta_m'(0) = 0,
        R_m = delta_{m-1}'' + P_{m-1} + lambda P_{m-1}',   P_n = [p^n] (sum_j delta_j p^j)^{3/2},

    (chi_1 = 0, chi_m = 1 for m >= 2). P_n carries delta0^{3/2 - n}, which vanishes linearly at
    pi/omega0, so R_m ~ (pi/omega0 - tau)^{3/2 - m} there (lambda > 0): integrable for m <= 2,
    not for m >= 3 (delta_3' is infinite at pi/omega0, delta_4 itself). This formulation stops at
    order 2 (:data:`PAPER_MAX_ORDER`); higher orders raise ValueError. Past pi/omega0, delta0 < 0
    and the fractional terms are set to zero (the continuation of ``zener_sym.models.ham0_ham1``'s
    first order: zero force of the zeroth-order compression), which leaves a linear cascade of
    constant-coefficient ODEs, solved by a matrix exponential.

``"strained"``: the same operator in the strained time phi = Omega tau with the unknown
    Omega = sum_m Omega_m p^m (Lindstedt-Poincare inside HAM) and delta = E(phi)/Omega:

        N[E, Omega] = Omega E'' + lambda Omega^{-1/2} (E^{3/2})' + Omega^{-3/2} E^{3/2},
        L = d^2/dphi^2 + 2 b d/dphi + (1 + b^2),   b = beta/omega0,   E0 = exp(-b phi) sin phi,
        L[E_m - chi_m E_{m-1}] = c0 [p^{m-1}] N,   E_m(0) = E_m'(0) = 0,   E_m(pi) = 0,

    the last condition fixing Omega_{m-1} (at m = 1 a quintic in Omega0^{1/2}, after that a
    linear equation). Every E_m vanishes at phi = pi, so E_m/E0 stays bounded at both ends and
    no order meets the singularity: contact ends exactly at tau_d = pi/Omega. Order M uses
    E_0..E_M and Omega_0..Omega_{M-1}.

Numerics (both): the variable t in [0, 1] with theta = pi sin^2(pi t / 2) (theta = omega0 tau,
resp. phi), which turns the half-integer powers of the end behaviours into analytic functions of
t; every order is sampled at N_NODES Chebyshev points, and the variation-of-constants integrals
int exp(b psi) {cos, sin}(psi) R dpsi are Chebyshev antiderivatives (one constant matrix).
A solution whose series of delta do not decay to TAIL_TOL is refused (lambda too close to
lam_crit for the grid), never returned inaccurate.

The convergence-control parameter c0 defaults to the minimiser of Liao's averaged squared
residual. The residual of Eq. (10) itself is not square-integrable at order 2 of the paper's
formulation (delta_2'' ~ (pi/omega0 - tau)^{-1/2}), so the residual used is that of the
once-integrated equation (the momentum balance)

    r(tau) = delta'(tau) - 1 + lambda delta^{3/2}(tau) + I(tau),   I = int_0^tau delta^{3/2},

averaged over the approximation's own contact: E_M(c0) = (1/tau_d) int_0^tau_d r^2 dtau
(:func:`squared_residual`, :func:`optimal_c0`).
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Sequence
from typing import Any, cast

import numpy as np
import numpy.typing as npt
import scipy.optimize

from ..numerics.chebyshev import chebint_matrix, first_kind
from ..numerics.integrate import smoothstep_rule
from ..numerics.maps import sine_squared, sine_squared_inverse, smoothstep_inverse
from ..typing import FloatArray, RealArrayLike, RealLike

__all__ = ["FORMULATIONS", "PAPER_MAX_ORDER", "STRAINED_MAX_ORDER", "N_NODES", "TAIL_TOL",
           "C0_RANGE", "HamSolution", "solve", "optimal_c0", "squared_residual", "check_order",
           "check_c0", "check_formulation"]

_C = np.polynomial.chebyshev

FORMULATIONS = ("paper", "strained")
#: Highest order of the paper's formulation: R_3 ~ (pi/omega0 - tau)^{-3/2} is not integrable.
PAPER_MAX_ORDER = 2
#: Highest order offered in the strained formulation (each one tested).
STRAINED_MAX_ORDER = 8
#: Largest lambda of the strained formulation (exclusive): there the two positive roots of its
#: first-order condition for Omega0 merge, and beyond it there is none (``strained_lam_bound``
#: recomputes it by bisection; a test pins this value).
STRAINED_LAM_BOUND = 2.032131391
#: Chebyshev points in t on the zeroth-order contact.
N_NODES = 96
#: The last two Chebyshev coefficients of delta must be below this times max |delta|.
TAIL_TOL = 1e-11
#: Search interval of the optimal c0 (Liao's c0 is negative for this sign convention).
C0_RANGE = (-2.0, -0.05)


# ------------------------------------------------------------------------- fixed matrices
_X, _FIT = first_kind(N_NODES)
_T = 0.5 * (1.0 + _X)
_TH, _DTH = sine_squared(_T)  # theta and d theta / dt at the nodes


def _mm(A: npt.NDArray[np.floating[Any]], B: npt.NDArray[np.floating[Any]]) -> FloatArray:
    """A @ B without BLAS (thread-count independent digits, see ``_mv``)."""
    out: FloatArray = np.einsum("ij,jk->ik", A, B)
    return out


_INTC = _mm(chebint_matrix(N_NODES), _FIT)  # values -> antiderivative
_CUM = _mm(_C.chebvander(_X, N_NODES), _INTC) * 0.5  # int_0^{t_j} g dt from node values (dt = dx/2)
_CUM_END = _mm(_C.chebvander(np.array([1.0]), N_NODES), _INTC)[0] * 0.5

# quadrature on a piece [A, B] of theta: smoothstep theta = A + (B - A) v^2 (3 - 2 v), Chebyshev
# points in v (the map's derivative vanishes at both ends: endpoint powers s^{1/2} become analytic)
_Q = smoothstep_rule(96)
_QMAP, _QDMAP, _QFIT, _QCUM, _QEND = _Q.map, _Q.slope, _Q.fit, _Q.cumulative, _Q.end


def _mv(A: FloatArray, v: FloatArray) -> FloatArray:
    """A @ v without BLAS: the same digits whatever the thread count (BLAS may split the sum
    across threads), and no thread start-up for these small products."""
    out: FloatArray = np.einsum("...j,j->...", A, v)
    return out


def _expm_stack(A: FloatArray, h: RealArrayLike) -> FloatArray:
    """exp(A h) for each h (a 1-D array), by Taylor series and squaring, all in einsum: scipy's
    expm goes through threaded BLAS, whose spinning threads made the study ten times slower on a
    loaded machine. Scaled so that |A h / 2^s|_1 <= 1/2, where 20 Taylor terms are exact to
    rounding (2^-20 / 20! ~ 4e-25)."""
    ha = np.asarray(h, dtype=float)
    norm = np.abs(A).sum(axis=0).max() * np.abs(ha)
    s = np.maximum(np.ceil(np.log2(np.maximum(norm, 1e-300) / 0.5)), 0).astype(int)
    X = A[None] * (ha / 2.0 ** s)[:, None, None]
    n = A.shape[0]
    E = np.broadcast_to(np.eye(n), X.shape).copy()
    term = E.copy()
    for j in range(1, 21):
        term = np.einsum("nij,njk->nik", term, X) / j
        E += term
    for k in range(int(s.max()) if s.size else 0):
        sq = np.einsum("nij,njk->nik", E, E)
        E = np.where((k < s)[:, None, None], sq, E)
    out: FloatArray = E
    return out


def _theta_to_x(theta: RealArrayLike) -> FloatArray:
    """Chebyshev variable x in [-1, 1] of theta in [0, pi]."""
    out: FloatArray = 2.0 * sine_squared_inverse(theta) - 1.0
    return out


# ---------------------------------------------------------------------------- validation
def check_order(order: object, formulation: object = "paper") -> int:
    """``order`` as an int, or ValueError naming the allowed orders of ``formulation``.

    Parameters
    ----------
    order : int
        The HAM order asked for.
    formulation : {'paper', 'strained'}
        The homotopy (module docstring).

    Returns
    -------
    int
        ``order``, 1 <= order <= PAPER_MAX_ORDER (paper) or STRAINED_MAX_ORDER (strained).

    Raises
    ------
    ValueError
        Not a positive integer (a bool is refused), or beyond the formulation's orders.

    Examples
    --------
    >>> from zener_sym.ham.higher import check_order
    >>> check_order(5, "strained")
    5
    >>> check_order(3, "paper")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: order 3 does not exist in the paper's formulation: ...
    """
    formulation = check_formulation(formulation)
    top = PAPER_MAX_ORDER if formulation == "paper" else STRAINED_MAX_ORDER
    if isinstance(order, bool) or not isinstance(order, numbers.Integral) or int(order) < 1:
        raise ValueError(f"order must be a positive integer, got {order!r}; allowed for the "
                         f"{formulation!r} formulation: 1 to {top}")
    order = int(order)
    if formulation == "paper" and order > PAPER_MAX_ORDER:
        raise ValueError(
            f"order {order} does not exist in the paper's formulation: its order-m forcing holds "
            f"delta1^(m-1) delta0^(5/2-m) and its derivative, ~ (pi/omega0 - tau)^(3/2-m) at the "
            f"end of the zeroth-order contact, which is not integrable from m = 3 on (lambda > 0; "
            f"m = 4 at lambda = 0), and delta0 < 0 past pi/omega0. Allowed orders: 1, 2; use "
            f"formulation='strained' for orders 1 to {STRAINED_MAX_ORDER}")
    if order > top:
        raise ValueError(f"order {order} is not offered; allowed for the {formulation!r} "
                         f"formulation: 1 to {top}")
    return order


def check_c0(c0: object) -> float:
    """``c0`` as a float, or ValueError: c0 must be finite and non-zero.

    Parameters
    ----------
    c0 : float
        Liao's convergence-control parameter (the paper's homotopy (14) is c0 = -1).

    Returns
    -------
    float

    Raises
    ------
    ValueError
        Not a real number (a bool is refused), not finite, or zero.

    Examples
    --------
    >>> from zener_sym.ham.higher import check_c0
    >>> check_c0(-1)
    -1.0
    """
    if (isinstance(c0, bool) or not isinstance(c0, numbers.Real) or not math.isfinite(float(c0))
            or c0 == 0):
        raise ValueError(f"c0 must be a finite, non-zero real number (the paper's homotopy is "
                         f"c0 = -1; None picks the optimum), got {c0!r}")
    return float(c0)


def check_formulation(formulation: object) -> str:
    """``formulation`` if it is one of ``FORMULATIONS``, else ValueError.

    Parameters
    ----------
    formulation : {'paper', 'strained'}
        The homotopy (module docstring).

    Returns
    -------
    str

    Raises
    ------
    ValueError
        Any other value, with the allowed ones.

    Examples
    --------
    >>> from zener_sym.ham.higher import check_formulation
    >>> check_formulation("strained")
    'strained'
    """
    if not isinstance(formulation, str) or formulation not in FORMULATIONS:
        raise ValueError(f"unknown formulation {formulation!r}; allowed: "
                         f"{', '.join(map(repr, FORMULATIONS))}")
    return formulation


# ------------------------------------------------------------------ the linear operator
def _lam_params(lam: RealLike) -> tuple[float, float, float]:
    from .runtime_numpy import ham1 as ham1_numpy

    la = float(lam)
    if not (math.isfinite(la) and 0.0 <= la < ham1_numpy.LAM_CRIT):
        raise ValueError(f"lambda = {la!r} is outside the HAM formulations' range: allowed "
                         f"0 <= lambda < lam_crit = {ham1_numpy.LAM_CRIT_DIGITS} (omega0 of the "
                         f"auxiliary operator (12) is real only below it, Eq. 81)")
    k, beta, omega0 = (float(v) for v in ham1_numpy.params(la))
    return k, beta, omega0


class _Op:
    """Inverse of L = D^2 + 2 b D + (1 + b^2) in theta with zero initial values, at the nodes:
    y = int_0^theta exp(-b (theta - psi)) sin(theta - psi) R(psi) dpsi (variation of constants)."""

    def __init__(self, b: float) -> None:
        self.b = b
        self.e_minus = np.exp(-b * _TH)
        self.s, self.c = np.sin(_TH), np.cos(_TH)
        w = np.exp(b * _TH) * _DTH
        self.wc, self.ws = w * self.c, w * self.s
        self.e_pi = math.exp(-b * math.pi)

    def solve(self, R: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray, float, float]:
        """(y, y', y'') at the nodes and (y, y') at theta = pi, for R at the nodes."""
        b = self.b
        A, B = _mv(_CUM, self.wc * R), _mv(_CUM, self.ws * R)
        y = self.e_minus * (self.s * A - self.c * B)
        y1 = self.e_minus * ((self.c - b * self.s) * A + (self.s + b * self.c) * B)
        y2 = R - 2.0 * b * y1 - (1.0 + b * b) * y
        Ap, Bp = _mv(_CUM_END, self.wc * R), _mv(_CUM_END, self.ws * R)
        return y, y1, y2, float(self.e_pi * Bp), float(self.e_pi * (-Ap - b * Bp))

    def at_pi(self, R: FloatArray) -> float:
        """y(pi) only."""
        return float(self.e_pi * (_mv(_CUM_END, self.ws * R)))


def _omega0_condition(lam: float) -> tuple[float, float, float]:
    """(c1, c2, c3) of the strained first-order condition c1 u^5 + lam c2 u^2 + c3 = 0,
    u^2 = Omega0: y(pi) of L^{-1} applied to E0'', (E0^{3/2})' and E0^{3/2}."""
    k, beta, omega0 = _lam_params(lam)
    b = beta / omega0
    op = _Op(b)
    e = np.exp(-b * _TH)
    s, c = np.sin(_TH), np.cos(_TH)
    E0, E1, E2 = e * s, e * (c - b * s), e * ((b * b - 1.0) * s - 2.0 * b * c)
    c1, c2, c3 = (float(op.at_pi(g)) for g in (E2, 1.5 * np.sqrt(E0) * E1, E0 * np.sqrt(E0)))
    return c1, c2, c3


def _has_omega0(lam: float) -> bool:
    c1, c2, c3 = _omega0_condition(lam)
    r = np.roots([c1, 0.0, 0.0, lam * c2, 0.0, c3])
    return any(abs(x.imag) <= 1e-9 * abs(x) and x.real > 0 for x in r)


def strained_lam_bound(tol: float = 1e-10) -> float:
    """The lambda from which the strained first-order condition has no positive Omega0 (where
    its two positive roots merge), by bisection between 1.9 (roots) and 2.2 (none).

    Parameters
    ----------
    tol : float
        Width of the final bracket.

    Returns
    -------
    float
        The bracket's lower end (``STRAINED_LAM_BOUND`` is this value, pinned by a test).
    """
    lo, hi = 1.9, 2.2
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _has_omega0(mid) else (lo, mid)
    return lo


def _power_coeffs(f: Sequence[Any], alpha: float, n: int) -> list[Any]:
    """[p^0..p^n] of (sum_j f_j p^j)^alpha (rows of f; J. C. P. Miller's recurrence).

    The coefficients are float arrays (node values) or floats (the strained Omega_m)."""
    g = [f[0] ** alpha]
    for m in range(1, n + 1):
        acc = 0.0
        for j in range(1, m + 1):
            if j < len(f):
                acc = acc + ((alpha + 1.0) * j - m) * f[j] * g[m - j]
        g.append(acc / (m * f[0]))
    return g


def _cauchy(a: Sequence[Any], b: Sequence[Any], n: int) -> Any:
    """[p^n] of (sum a_j p^j)(sum b_j p^j), missing terms taken as 0 (arrays or floats)."""
    return sum(a[j] * b[n - j] for j in range(n + 1) if j < len(a) and n - j < len(b))


# ------------------------------------------------------------------------------ solution
class HamSolution:
    """One lambda, order, c0 and formulation: delta and delta' as functions of theta.

    theta = omega_s tau, with omega_s = omega0 (paper) or Omega (strained); the contact is
    0 <= theta <= theta_d. Attributes: ``lam, order, c0, formulation, k, beta, omega0, b,
    omega_s, theta_d, tau_d``, ``Omega`` (the strained frequency coefficients Omega_0..), and the
    node values ``orders`` (list of (delta_m, delta_m', delta_m'') in tau derivatives (paper) or
    of (E_m, E_m', E_m'') in phi (strained)).
    """

    lam: float
    order: int
    c0: float
    formulation: str
    k: float
    beta: float
    omega0: float
    b: float
    omega_s: float
    theta_d: float
    tau_d: float
    Omega: list[float]
    orders: list[tuple[FloatArray, FloatArray, FloatArray]]

    def __init__(self, lam: RealLike, order: int, c0: float, formulation: str) -> None:
        self.formulation = check_formulation(formulation)
        self.order = check_order(order, formulation)
        self.c0 = check_c0(c0)
        self.lam = float(lam)
        self.k, self.beta, self.omega0 = _lam_params(lam)
        if self.formulation == "strained" and not self.lam < STRAINED_LAM_BOUND:
            raise ValueError(
                f"lambda = {lam!r} is beyond the strained formulation's range: its first-order "
                f"condition for Omega0 has no positive root from lambda = {STRAINED_LAM_BOUND!r} "
                f"on; allowed 0 <= lambda < {STRAINED_LAM_BOUND!r}")
        self.b = self.beta / self.omega0
        self._op = _Op(self.b)
        self.Omega = []
        if self.formulation == "paper":
            self._solve_paper()
        else:
            self._solve_strained()
        self._fit()
        self.theta_d = self._contact_end()
        self.tau_d = self.theta_d / self.omega_s

    # ------------------------------------------------------------------- the two cascades
    def _zeroth(self) -> tuple[FloatArray, FloatArray, FloatArray]:
        b, e = self.b, np.exp(-self.b * _TH)
        s, c = np.sin(_TH), np.cos(_TH)
        E0 = e * s
        E1 = e * (c - b * s)
        E2 = e * ((b * b - 1.0) * s - 2.0 * b * c)
        return E0, E1, E2

    def _solve_paper(self) -> None:
        lam, c0, w = self.lam, self.c0, self.omega0
        E0, E1, E2 = self._zeroth()
        # delta0 = E0/omega0; tau derivatives: d/dtau = omega0 d/dtheta
        d, dp, dpp = [E0 / w], [E1], [E2 * w]
        end = [(0.0, -math.exp(-self.b * math.pi))]  # (delta_m, d delta_m/dtheta) at theta = pi
        end[0] = (0.0, end[0][1] / w)
        for m in range(1, self.order + 1):
            Q = _power_coeffs(d, 0.5, m - 1)
            P = _cauchy(Q, d, m - 1)
            D = 1.5 * _cauchy(Q, dp, m - 1)
            R = dpp[m - 1] + P + lam * D
            y, y1, y2, yp, y1p = self._op.solve(R)
            chi = 1.0 if m >= 2 else 0.0
            # L_tau = omega0^2 L_theta: delta_m - chi delta_{m-1} = (c0/omega0^2) y
            d.append(chi * d[m - 1] + c0 / w**2 * y)
            dp.append(chi * dp[m - 1] + c0 / w * y1)
            dpp.append(chi * dpp[m - 1] + c0 * y2)
            end.append((chi * end[m - 1][0] + c0 / w**2 * yp, chi * end[m - 1][1] + c0 / w**2 * y1p))
        self.orders = list(zip(d, dp, dpp))
        self.omega_s = w
        self._delta_nodes = np.sum(d, axis=0)
        self._vel_nodes = np.sum(dp, axis=0)
        self._past_matrix, self._past_state = self._cascade(end)

    def _cascade(self, end: Sequence[tuple[float, float]]) -> tuple[FloatArray, FloatArray]:
        """Past theta = pi: L_theta[delta_m - chi delta_{m-1}] = c0 delta_{m-1}'' (the fractional
        terms switched off), delta0'' = -2 b delta0' - (1 + b^2) delta0: z' = A z for
        z = (delta_0..delta_M, delta_0'..delta_M') in theta."""
        M, b, c0 = self.order, self.b, self.c0
        n = M + 1
        A = np.zeros((2 * n, 2 * n))
        acc: list[FloatArray] = []  # row vectors of delta_m'' over z
        for m in range(n):
            row = np.zeros(2 * n)
            row[n + m] -= 2.0 * b
            row[m] -= 1.0 + b * b
            if m >= 1:
                chi = 1.0 if m >= 2 else 0.0
                row += (chi + c0) * acc[m - 1]
                row[n + m - 1] += 2.0 * b * chi
                row[m - 1] += (1.0 + b * b) * chi
            acc.append(row)
            A[m, n + m] = 1.0
            A[n + m] = row
        z = np.array([e[0] for e in end] + [e[1] for e in end])
        return A, z

    def _solve_strained(self) -> None:
        lam, c0 = self.lam, self.c0
        op = self._op
        E0, E1, E2 = self._zeroth()
        E, Ep, Epp = [E0], [E1], [E2]
        Om: list[float] = []
        for m in range(1, self.order + 1):
            Q = _power_coeffs(E, 0.5, m - 1)
            P = [_cauchy(Q, E, n) for n in range(m)]
            D = [1.5 * _cauchy(Q, Ep, n) for n in range(m)]

            def forcing(om: list[float]) -> FloatArray:
                Oh = _power_coeffs(om, -0.5, m - 1)
                O3 = _power_coeffs(om, -1.5, m - 1)
                out: FloatArray = (_cauchy(om, Epp, m - 1) + lam * _cauchy(Oh, D, m - 1)
                                   + _cauchy(O3, P, m - 1))
                return out

            if m == 1:
                # y(pi) = 0: c1 Om0 + lam c2 Om0^{-1/2} + c3 Om0^{-3/2} = 0, i.e. with u^2 = Om0:
                # c1 u^5 + lam c2 u^2 + c3 = 0
                c1, c2, c3 = (float(op.at_pi(g)) for g in (E2, D[0], P[0]))
                roots = np.roots([c1, 0.0, 0.0, lam * c2, 0.0, c3])
                u = sorted(r.real for r in roots if abs(r.imag) <= 1e-9 * abs(r) and r.real > 0)
                if not u:
                    raise ValueError(
                        f"lambda = {lam!r} is beyond the strained formulation's range: its "
                        f"first-order condition for Omega0 has no positive root from lambda = "
                        f"{STRAINED_LAM_BOUND:.6f} on; allowed 0 <= lambda < {STRAINED_LAM_BOUND:.6f}")
                # the smallest positive root is the branch continuous from lambda = 0 (a second
                # one comes in from infinity when c1 changes sign near lambda = 1.65)
                Om.append(u[0] ** 2)
            else:
                r0 = forcing(Om + [0.0])
                S = forcing(Om + [1.0]) - r0  # the forcing is affine in Omega_{m-1}
                Om.append(-float(op.at_pi(r0)) / float(op.at_pi(S)))
            R = forcing(Om)
            y, y1, y2, _, _ = op.solve(R)
            chi = 1.0 if m >= 2 else 0.0
            E.append(chi * E[m - 1] + c0 * y)
            Ep.append(chi * Ep[m - 1] + c0 * y1)
            Epp.append(chi * Epp[m - 1] + c0 * y2)
        self.Omega = Om
        self.orders = list(zip(E, Ep, Epp))
        Omega = float(sum(Om))
        if not Omega > 0:
            raise ValueError(f"lambda = {lam!r}, order {self.order}, c0 = {c0!r}: the strained "
                             f"frequency Omega = {Omega!r} is not positive")
        self.omega_s = Omega
        self._delta_nodes = np.sum(E, axis=0) / Omega  # delta = E/Omega
        self._vel_nodes = np.sum(Ep, axis=0)  # d delta/dtau = dE/dphi

    # ------------------------------------------------------------------------ evaluation
    def _fit(self) -> None:
        self._cd = _mv(_FIT, self._delta_nodes)
        self._cv = _mv(_FIT, self._vel_nodes)
        scale = np.max(np.abs(self._delta_nodes))
        tail = np.max(np.abs(self._cd[-2:]))
        if not (np.isfinite(scale) and tail <= TAIL_TOL * scale):
            raise ValueError(
                f"lambda = {self.lam!r}: the order-{self.order} series of delta is not resolved "
                f"by {N_NODES} Chebyshev points (tail {tail:.1e} of {scale:.1e}); lambda is too "
                f"close to lam_crit for this grid (beta/omega0 = {self.b:.3g}); use a smaller "
                f"lambda")

    def delta(self, theta: RealArrayLike) -> FloatArray:
        """delta at theta (paper: continued past pi by the cascade; strained: 0 <= theta <= pi).

        Parameters
        ----------
        theta : float or array_like
            theta = omega_s tau, >= 0 (strained: at most pi).

        Returns
        -------
        ndarray
            delta, of the shape of ``theta``.

        Raises
        ------
        ValueError
            theta > pi in the strained formulation.
        """
        return self._eval(theta)[0]

    def velocity(self, theta: RealArrayLike) -> FloatArray:
        """d delta / d tau at theta.

        Parameters
        ----------
        theta : float or array_like
            theta = omega_s tau, as in :meth:`delta`.

        Returns
        -------
        ndarray
            The velocity, of the shape of ``theta``.
        """
        return self._eval(theta)[1]

    def _eval(self, theta: RealArrayLike) -> tuple[FloatArray, FloatArray]:
        th = np.asarray(theta, dtype=float)
        x = _theta_to_x(th)
        # float64 coefficients at float64 points (numpy types chebval's result as floating)
        d = cast(FloatArray, _C.chebval(x, self._cd))
        v = cast(FloatArray, _C.chebval(x, self._cv))
        past = th > np.pi
        if past.any():
            if self.formulation != "paper":
                raise ValueError("the strained solution ends at phi = pi")
            dp, vp = self._past(th[past])
            d, v = np.array(d, dtype=float), np.array(v, dtype=float)
            d[past], v[past] = dp, vp
        return d, v

    def _past(self, theta: FloatArray) -> tuple[FloatArray, FloatArray]:
        n = self.order + 1
        Z = np.einsum("nij,j->ni", _expm_stack(self._past_matrix, theta - np.pi), self._past_state)
        return Z[:, :n].sum(axis=1), self.omega_s * Z[:, n:].sum(axis=1)

    def _first_zero(self, fun: Callable[[FloatArray], FloatArray], lo: float, hi: float,
                    n: int = 400) -> float | None:
        """First theta in (lo, hi] where fun changes sign from positive; None if there is none."""
        th = np.linspace(lo, hi, n + 1)
        f = fun(th)
        neg = np.flatnonzero(f[1:] <= 0.0)
        if neg.size == 0:
            return None
        j = neg[0] + 1
        if f[j] == 0.0:
            return float(th[j])
        root: float = scipy.optimize.brentq(lambda x: float(fun(np.array([x]))[0]), th[j - 1],
                                            th[j], xtol=1e-15, rtol=1e-15, maxiter=200)
        return root

    def _contact_end(self) -> float:
        if self.formulation == "strained":
            return math.pi
        root = self._first_zero(self.delta, 1e-6, math.pi)
        if root is None:
            root = self._first_zero(self.delta, math.pi, 3.0 * math.pi)
        if root is None:
            raise ValueError(f"lambda = {self.lam!r}, order {self.order}, c0 = {self.c0!r}: the "
                             f"approximation does not return to delta = 0 before 3 pi/omega0")
        return root

    # ------------------------------------------------------------------------- quantities
    def _pieces(self) -> list[tuple[float, float]]:
        if self.theta_d <= np.pi:
            return [(0.0, self.theta_d)]
        return [(0.0, np.pi), (np.pi, self.theta_d)]

    def summary(self) -> dict[str, float]:
        """delta_m, tau_dc, tau_d, e, F_m, impulse, int_F2 (as ``zener_sym.models`` use them).

        Returns
        -------
        dict of str to float
            The maximum compression and its time (first zero of the velocity), the contact
            time, e = -delta'(tau_d), F_m = delta_m^(3/2), and the integrals of F and F^2 over
            the contact.

        Raises
        ------
        ValueError
            The velocity has no zero before the contact end.

        Examples
        --------
        >>> from zener_sym.ham.higher import solve
        >>> s = solve(0.5, 2, c0=-1.0).summary()  # the paper's homotopy, order 2
        >>> bool(0 < s["e"] < 1 and s["tau_dc"] < s["tau_d"])
        True
        """
        thc = self._first_zero(self.velocity, 1e-9, self.theta_d)
        if thc is None:
            raise ValueError(f"lambda = {self.lam!r}: no maximum of delta before the contact end")
        dm = float(self.delta(np.array([thc]))[0])
        imp = f2 = 0.0
        for A, B in self._pieces():
            th = A + (B - A) * _QMAP
            d = np.maximum(self.delta(th), 0.0)
            wq = (B - A) * _QDMAP / self.omega_s
            imp += float(_mv(_QEND, d * np.sqrt(d) * wq))
            f2 += float(_mv(_QEND, d**3 * wq))
        e = -float(self.velocity(np.array([self.theta_d]))[0])
        return dict(delta_m=dm, tau_dc=thc / self.omega_s, tau_d=self.tau_d, e=e, F_m=dm**1.5,
                    impulse=float(imp), int_F2=float(f2))

    def squared_residual(self) -> float:
        """Liao's averaged squared residual of the integrated equation over the contact (module
        docstring): (1/tau_d) int_0^tau_d (delta' - 1 + lambda delta^{3/2} + I)^2 dtau.

        Returns
        -------
        float
            E_M(c0) >= 0; 0 only for the exact solution.
        """
        total, I0 = 0.0, 0.0
        for A, B in self._pieces():
            th = A + (B - A) * _QMAP
            d, v = self._eval(th)
            F = np.maximum(d, 0.0) ** 1.5
            wq = (B - A) * _QDMAP / self.omega_s
            I = I0 + _mv(_QCUM, F * wq)
            r = v - 1.0 + self.lam * F + I
            total += float(_mv(_QEND, r * r * wq))
            I0 += float(_mv(_QEND, F * wq))
        return float(total / self.tau_d)

    def history(self, tau: RealArrayLike) -> dict[str, FloatArray]:
        """delta, velocity, force, impulse at times ``tau`` (0 past the contact end; the
        impulse keeps its final value).

        Parameters
        ----------
        tau : float or array_like
            Dimensionless times, >= 0.

        Returns
        -------
        dict of str to ndarray
            ``delta``, ``force`` = delta^(3/2), ``impulse`` (its integral from 0) and
            ``velocity`` = 1 - impulse (the momentum balance), of the shape of ``tau``.
        """
        ta = np.asarray(tau, dtype=float)
        th = np.minimum(ta * self.omega_s, self.theta_d)
        on = ta * self.omega_s < self.theta_d
        d = np.zeros(ta.shape)
        if on.any():
            d[on] = np.maximum(self.delta(th[on]), 0.0)
        imp = np.zeros(ta.shape)
        I0 = 0.0
        for A, B in self._pieces():
            L = B - A
            qth = A + L * _QMAP
            dq = np.maximum(self.delta(qth), 0.0)
            coef = _C.chebint(_mv(_QFIT, dq * np.sqrt(dq) * L * _QDMAP / self.omega_s), lbnd=-1.0,
                              scl=0.5)
            sel = th >= A
            frac = np.clip((th[sel] - A) / L, 0.0, 1.0)
            v = smoothstep_inverse(frac)
            val = I0 + _C.chebval(2.0 * v - 1.0, coef)
            imp[sel] = val
            I0 = I0 + float(_C.chebval(1.0, coef))
        return {"delta": d, "force": d * np.sqrt(d), "impulse": imp, "velocity": 1.0 - imp}


# ------------------------------------------------------------------------- entry points
def solve(lam: RealLike, order: int, c0: float | None = None,
          formulation: str = "paper") -> HamSolution:
    """The order-``order`` HAM solution at one lambda (c0 None: the optimum, :func:`optimal_c0`).

    Parameters
    ----------
    lam : float
        lambda, 0 <= lambda < lam_crit (Eq. 81); the strained formulation stops at
        ``STRAINED_LAM_BOUND``.
    order : int
        1 to ``PAPER_MAX_ORDER`` (paper) or ``STRAINED_MAX_ORDER`` (strained).
    c0 : float, optional
        Liao's convergence-control parameter; None: the minimiser of the squared residual.
    formulation : {'paper', 'strained'}
        The homotopy (module docstring).

    Returns
    -------
    HamSolution

    Raises
    ------
    ValueError
        Bad order (not a positive integer, or beyond the formulation: the paper's stops at 2),
        c0 not finite or zero, lambda outside [0, lam_crit), or a grid that does not resolve the
        solution.

    Examples
    --------
    >>> from zener_sym.ham.higher import solve
    >>> sol = solve(0.0, 4, c0=-1.0, formulation="strained")
    >>> bool(abs(sol.summary()["e"] - 1.0) < 1e-6)  # lambda = 0: elastic, e = 1
    True
    """
    formulation = check_formulation(formulation)
    order = check_order(order, formulation)
    if c0 is None:
        c0 = optimal_c0(lam, order, formulation)
    return HamSolution(lam, order, c0, formulation)


def squared_residual(lam: RealLike, order: int, c0: float, formulation: str = "paper") -> float:
    """Liao's averaged squared residual E_M(c0) (module docstring); inf where the approximation
    has no contact end.

    Parameters
    ----------
    lam : float
        lambda, as in :func:`solve`.
    order : int
        The HAM order, as in :func:`solve`.
    c0 : float
        Liao's convergence-control parameter, finite and non-zero.
    formulation : {'paper', 'strained'}
        The homotopy (module docstring).

    Returns
    -------
    float
        E_M(c0) >= 0, or inf.
    """
    try:
        return HamSolution(lam, order, c0, formulation).squared_residual()
    except ValueError as exc:
        if "does not return" in str(exc) or "not positive" in str(exc):
            return math.inf
        raise


_C0_GRID = np.linspace(C0_RANGE[0], C0_RANGE[1], 40)


def optimal_c0(lam: RealLike, order: int, formulation: str = "paper") -> float:
    """The c0 in C0_RANGE minimising :func:`squared_residual` at this lambda and order: the best
    of a 40-point grid, refined by a bounded Brent search between its neighbours.

    Parameters
    ----------
    lam : float
        lambda, as in :func:`solve`.
    order : int
        The HAM order, as in :func:`solve`.
    formulation : {'paper', 'strained'}
        The homotopy (module docstring).

    Returns
    -------
    float
        The optimal c0, in ``C0_RANGE``.

    Raises
    ------
    ValueError
        Bad arguments, or no c0 of the range gives a contact end.
    """
    formulation = check_formulation(formulation)
    order = check_order(order, formulation)
    _lam_params(lam)
    vals = np.array([squared_residual(lam, order, c, formulation) for c in _C0_GRID])
    if not np.isfinite(vals).any():
        raise ValueError(f"lambda = {lam!r}, order {order}: no c0 in {C0_RANGE} gives a contact end")
    j = int(np.argmin(vals))
    lo, hi = _C0_GRID[max(j - 1, 0)], _C0_GRID[min(j + 1, _C0_GRID.size - 1)]
    res = scipy.optimize.minimize_scalar(lambda c: squared_residual(lam, order, c, formulation),
                                         bounds=(lo, hi), method="bounded",
                                         options={"xatol": 1e-6})
    return float(res.x) if res.fun <= vals[j] else float(_C0_GRID[j])
