"""Both ends of lambda: the small-lambda series and the large-lambda regime of Eq. (10), for the
plate's end of contact (delta = 0) and the grains' force-free end (delta + (3/2) lambda delta' = 0).

Small lambda
------------
In u = sqrt(delta) the loading and unloading branches of Eq. (10) are analytic in (u, lambda)
(the start u = 0 is regular, see ``zener_sym.exact``), and the middle, in tau, is analytic while
delta > 0. With phase boundaries that do not depend on lambda (u = U1 on loading, a fixed span S
in tau, then u down to 0) every quantity at the plate's end u = 0 is an analytic function of
lambda near 0: the perturbation hierarchy delta = delta_0 + lambda delta_1 + ... has integer
powers only, and

    e = 1 - c1 lambda + c2 lambda^2 - ...,   c1 = int_0^tau_H delta_0^3 dtau = (4/5) (5/4)^(8/5) B(8/5, 1/2)

(Raman's coefficient; the closed form follows from the energy balance xi = 2 lambda int F^2 at
first order and the Hertz quadrature tau(delta) along delta_0' = sqrt(1 - (4/5) delta_0^(5/2))).
The force-free end lies at u = mu sqrt(-(3/2) delta'(u)) with mu = sqrt(lambda): it is analytic in
mu, not lambda, so the grains' series runs in powers of lambda^(1/2) (the v^(1/10) of the granular
literature). The two ends differ first at order lambda^(5/2): between them the attractive force is
O(lambda^(3/2)) for a time O(lambda), and its impulse gives e_force - e_delta = (4/15) (3 lambda/2)^(5/2)
+ ..., i.e. a5 = (3/5) sqrt(3/2).

The coefficients of the hierarchy are computed numerically, to 50 digits, as the Taylor
coefficients of these analytic functions, by two routes that share only the Taylor integrator of
this module (jets in the style of ``zener_sym.exact.mp``, which this module must not import):

1. Cauchy's integral on a circle |lambda| = r1 (|mu| = r1 for the grains), M1 points, in complex
   arithmetic (the integrator runs on complex lambda along the same fixed phases);
2. interpolation at M2 Chebyshev points of the real interval [-r2, r2] (negative lambda is the
   anti-damped equation, still analytic), converted to monomial coefficients.

A coefficient is reported as derived when the two routes agree to at least 20 significant digits
(the independent check of the package's own mpmath solver is in tests/test_lambda_series.py).

Large lambda
------------
The scaling delta = lambda^-4 P, 1 - I = lambda^-5 W, tau = lambda s maps Eq. (10) onto the same
equation with lambda = 1 and the initial velocity W(0) = lambda^5 (it is the v0^(1/5) scaling of
the grain mapping read backwards). As lambda grows the solution leaves P = 0 in a layer of
duration O(lambda^(-5/3)) in s, then follows the slow manifold P^(3/2) = W q(W^(-1/3)),

    q(z) = 1 + (2/3) z + ...   (exact rational coefficients from (2/3) z q^(2/3) (q - z q'/3) = q - 1),

which in this 2-D autonomous system is one trajectory, attracting at a rate ~ W^(1/3). So

    e lambda^5 -> K_delta,   tau_d = lambda (5 ln lambda + C_delta) + 3 lambda^(-2/3) + O(lambda^(-7/3))

with exponentially small corrections to e lambda^5 (K_delta is the end velocity of the manifold
trajectory; K_delta and C_delta come from integrating it from W_s, started on the truncated
manifold series, at two W_s and two truncations; the 3 is 2 from the manifold's time correction
and 1 from the initial layer, where W lags the manifold by W0^(2/3) int p' dsigma = W0^(2/3)). delta_m lambda^(2/3) -> 1 and F_m lambda -> 1
on the plate (F = delta^(3/2)): the compression ends in the initial layer delta = lambda^(-2/3) D,
D' = 1 - D^(3/2).

The grains separate soon after the end of compression: on the slow manifold the viscoelastic
force is already attractive, delta + (3/2) lambda delta' = W^(2/3) (-(4/9) W^(-1/3) + ...) < 0. At
the force-free end e = delta/((3/2) lambda) exactly and delta -> delta_m -> lambda^(-2/3), so

    e lambda^(5/3) -> 2/3,   F_m lambda^(-2/3) -> (9/8) 4^(-1/3)   (grains' end; the peak of the
    viscoelastic force sits in the initial layer at D^(3/2) = 1/4),

and tau_d lambda^(2/3) grows like (20/9) ln lambda (the transient must fall to the second order of
lambda^(-5/3) before the force vanishes; measured, not derived to a constant).
"""
from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import sympy as sp

from .steps import Context

__all__ = ["derive", "raman_c1", "grain_a5", "small_lambda_coefficients", "large_lambda_constants",
           "manifold_series", "solve_point", "main"]

DPS = 50  # working digits of the coefficient routes
_U1 = mpmath.mpf("0.8")  # loading phase ends at u = U1 (delta = 0.64)
_S = mpmath.mpf("1.8")  # the tau phase lasts S (ends near delta = 0.66 at lambda = 0)
_FIELDS_LAM = ("e_delta", "tau_d_delta", "delta_m", "tau_dc", "F_m_plate", "F_m_grain")
_FIELDS_MU = ("e_force", "tau_d_force")


# --- Taylor jets (plain numbers: mpf or mpc) ------------------------------------------------

def _jets_u(u0, tau0, v0, lam, N):
    """Coefficients in s = u - u0 of (tau, v) of the u-form: dtau/du = 2u/v, dv/du = -2u^4/v - 3 lam u^2."""
    tau, v, q = [tau0], [v0], []
    P1 = [2 * u0, 2]
    P2 = [3 * lam * u0**2, 6 * lam * u0, 3 * lam]
    P4 = [2 * mpmath.binomial(4, k) * u0 ** (4 - k) for k in range(5)]
    inv = 1 / v0
    for k in range(N):
        q.append(inv if k == 0 else -mpmath.fdot(v[1:k + 1], q[k - 1::-1]) * inv)
        a = mpmath.fdot(P1[:k + 1], q[k::-1][:2])
        b = mpmath.fdot(P4[:k + 1], q[k::-1][:5])
        tau.append(a / (k + 1))
        v.append((-b - (P2[k] if k < 3 else 0)) / (k + 1))
    return [tau, v]


def _jets_t(d0, v0, lam, N):
    """Coefficients in s = tau - tau0 of (delta, v): delta' = v, v' = -delta^(3/2) - (3/2) lam sqrt(delta) v."""
    d, v, sq = [d0], [v0], [mpmath.sqrt(d0)]
    c = mpmath.mpf(3) / 2 * lam
    for k in range(N):
        if k > 0:
            sq.append((d[k] - mpmath.fdot(sq[1:k], sq[k - 1:0:-1])) / (2 * sq[0]))
        F = mpmath.fdot(d[:k + 1], sq[k::-1])
        G = mpmath.fdot(sq[:k + 1], v[k::-1])
        d.append(v[k] / (k + 1))
        v.append((-F - c * G) / (k + 1))
    return [d, v]


# Horner's rule and the Taylor derivative again (zener_sym.numerics.taylor has them): the
# derivation is the lowest layer and imports nothing of the package, so that its results stand
# apart from the code they check.
def _horner(c, s):
    acc = c[-1]
    for ck in reversed(c[:-1]):
        acc = acc * s + ck
    return acc


def _dpoly(c):
    return [k * c[k] for k in range(1, len(c))]


def _hmax(c, N):
    """Step bound rho e^-2 from the last six coefficients (as in zener_sym.exact.mp)."""
    rho = None
    for ci in c:
        for j in range(N - 5, N + 1):
            a = abs(ci[j])
            if a:
                r = a ** (-mpmath.mpf(1) / j)
                rho = r if rho is None or r < rho else rho
    return mpmath.mpf(1) if rho is None else rho * mpmath.exp(-2)


def _newton(f, df, x, what):
    for _ in range(100):
        dx = f(x) / df(x)
        x -= dx
        if abs(dx) <= abs(x) * mpmath.mpf(10) ** (-mpmath.mp.dps + 3) + mpmath.mpf(10) ** (-mpmath.mp.dps - 3):
            return x
    raise RuntimeError(f"lambda_series: Newton's method did not converge ({what})")


def _order():
    return int(math.ceil((mpmath.mp.dps + 5) * math.log(10) / 2)) + 1


def solve_point(x, crit="delta"):
    """The fields at one (complex) parameter along the fixed phases (small lambda only).

    ``crit="delta"``: x is lambda; returns e, tau_d at delta = 0 and delta_m, tau_dc, the plate's
    F_m = delta_m^(3/2) and the grains' F_m = max(delta^(3/2) + lambda (delta^(3/2))').
    ``crit="force"``: x is mu = sqrt(lambda); returns e and tau_d at the force-free end.
    """
    lam = x if crit == "delta" else x * x
    N = _order()
    key = (mpmath.mp.dps, repr(lam))
    if crit == "force":
        # mu and -mu share lambda, and conj(mu)^2 = conj(lambda) has the conjugate flow: reuse
        # the flow to u = 0 (the end itself depends on the sign of mu).
        if key in _AT_ZERO:
            tau, v = _AT_ZERO[key]
            return _force_end(x, lam, tau, v, N)
        ckey = (mpmath.mp.dps, repr(mpmath.conj(lam)))
        if ckey in _AT_ZERO:
            tau, v = (mpmath.conj(y) for y in _AT_ZERO[ckey])
            return _force_end(x, lam, tau, v, N)
    zero = mpmath.mpf(0)
    # Phase 1: u from 0 to U1.
    u, tau, v = zero, zero, mpmath.mpf(1)
    while u < _U1:
        c = _jets_u(u, tau, v, lam, N)
        h = min(_hmax(c, N), _U1 - u)
        tau, v = _horner(c[0], h), _horner(c[1], h)
        u = _U1 if h == _U1 - u else u + h
    # Phase 2: tau over the fixed span S.
    d, s_done, out = u * u, zero, {}
    while s_done < _S:
        c = _jets_t(d, v, lam, N)
        h = min(_hmax(c, N), _S - s_done)
        d1, v1 = _horner(c[0], h), _horner(c[1], h)
        if crit == "delta" and "tau_dc" not in out and mpmath.re(v1) <= 0:
            cv, dcv = c[1], _dpoly(c[1])
            s = _newton(lambda s: _horner(cv, s), lambda s: _horner(dcv, s), h / 2, "v = 0")
            out["tau_dc"], out["delta_m"] = tau + s, _horner(c[0], s)
            out["F_m_plate"] = out["delta_m"] * mpmath.sqrt(out["delta_m"])
            # grains: F_c = sqrt(delta) (delta + 1.5 lam v) peaks where its derivative vanishes;
            # F_c' = -v'' in terms of the polynomials of delta and v.
            cd, cd1 = c[0], _dpoly(c[0])
            cw, cw1, cw2 = c[1], _dpoly(c[1]), _dpoly(_dpoly(c[1]))
            s = _newton(lambda s: _horner(cw2, s), lambda s: _horner(_dpoly(cw2), s), s, "max F_c")
            out["F_m_grain"] = -_horner(cw1, s)  # F_c = -delta'' = -v'
        tau, d, v = tau + h, d1, v1
        s_done = _S if h == _S - s_done else s_done + h
    # Phase 3: u from sqrt(delta) to 0 along the straight line (complex for complex lambda).
    u = mpmath.sqrt(d)
    while u != 0:
        c = _jets_u(u, tau, v, lam, N)
        hm = _hmax(c, N)
        h = -u if abs(u) <= hm else -u * hm / abs(u)
        tau, v = _horner(c[0], h), _horner(c[1], h)
        u = zero if h == -u else u + h
    if crit == "delta":
        out["e_delta"], out["tau_d_delta"] = -v, tau
        return out
    if len(_AT_ZERO) > 1000:
        _AT_ZERO.clear()
    _AT_ZERO[key] = (tau, v)
    return _force_end(x, lam, tau, v, N)


_AT_ZERO = {}


def _force_end(x, lam, tau, v, N):
    zero = mpmath.mpf(0)
    # Force-free end: u = mu sqrt(-(3/2) v(u)) (the branch with the sign of mu). Integrate on from
    # u = 0 along the straight line to the first-order guess mu sqrt(-(3/2) v(0)), with the same
    # step control, then Newton on the local polynomial there (the root is O(lambda^(3/2)) away).
    k = mpmath.mpf(3) / 2
    target = x * mpmath.sqrt(-k * v)
    u = zero
    while True:
        c = _jets_u(u, tau, v, lam, N)
        gap = target - u
        if gap == 0:
            break
        hm = _hmax(c, N)
        h = gap if abs(gap) <= hm else gap * hm / abs(gap)
        tau, v = _horner(c[0], h), _horner(c[1], h)
        u = target if h == gap else u + h
    cv, dcv = c[1], _dpoly(c[1])

    def f(s):
        return u + s - x * mpmath.sqrt(-k * _horner(cv, s))

    def df(s):
        return 1 + x * k * _horner(dcv, s) / (2 * mpmath.sqrt(-k * _horner(cv, s)))

    s = _newton(f, df, zero, "force-free end")
    return {"e_force": -_horner(cv, s), "tau_d_force": _horner(c[0], s)}


def _cauchy(fn, r, M, K):
    """Taylor coefficients 0..K of a real-on-the-real-axis analytic fn, by the trapezoidal rule on
    |x| = r with M points (conjugate symmetry: only the upper half is evaluated)."""
    vals = {}
    for j in range(M // 2 + 1):
        x = r * mpmath.expjpi(mpmath.mpf(2 * j) / M)
        vals[j] = fn(x if j not in (0, M // 2) else mpmath.re(x))
    names = vals[0].keys()
    out = {}
    for n in names:
        f = [vals[j][n] if j in vals else mpmath.conj(vals[M - j][n]) for j in range(M)]
        out[n] = [mpmath.re(mpmath.fsum(f[j] * mpmath.expjpi(-mpmath.mpf(2 * j * k) / M) for j in range(M)))
                  / M / r**k for k in range(K + 1)]
    return out


def _chebyshev(fn, r, M, K):
    """Taylor coefficients 0..K from interpolation at M Chebyshev points of [-r, r]."""
    xs = [r * mpmath.cos(mpmath.pi * (j + mpmath.mpf(1) / 2) / M) for j in range(M)]
    vals = [fn(x) for x in xs]
    out = {}
    for n in vals[0]:
        f = [v[n] for v in vals]
        a = [2 * mpmath.fsum(f[j] * mpmath.cos(mpmath.pi * k * (j + mpmath.mpf(1) / 2) / M) for j in range(M)) / M
             for k in range(M)]
        a[0] /= 2
        # sum_k a_k T_k(x/r) -> monomials in x, by the three-term recurrence of T_k.
        mono = [mpmath.mpf(0)] * M
        Tm, T = [mpmath.mpf(1)], [mpmath.mpf(0), 1 / r]
        for k in range(M):
            Tk = Tm if k == 0 else T
            for i, t in enumerate(Tk):
                mono[i] += a[k] * t
            if k >= 1:
                Tm, T = T, [(2 / r) * (T[i - 1] if i >= 1 else 0) - (Tm[i] if i < len(Tm) else 0)
                            for i in range(len(T) + 1)]
        out[n] = mono[:K + 1]
    return out


def _agree(a, b):
    """Significant digits to which a and b agree (60 when both are below 1e-30: a vanishing coefficient)."""
    scale = max(abs(a), abs(b))
    if scale < mpmath.mpf(10) ** -30:  # a coefficient that vanishes (both routes below 1e-30)
        return 60
    d = abs(a - b) / scale
    return 60 if d == 0 else float(-mpmath.log10(d))


def small_lambda_coefficients(K=16, *, routes=((mpmath.mpf("0.15"), 48), (mpmath.mpf("0.1"), 40)),
                              mu_routes=((mpmath.mpf("0.25"), 96), (mpmath.mpf("0.2"), 64)), dps=DPS):
    """Taylor coefficients of every small-lambda field by both routes, and their agreement.

    Returns
    -------
    dict
        ``coef[name]`` (route 1, list of mpf, index k is the coefficient of lambda^k, or of
        mu^k = lambda^(k/2) for ``e_force`` and ``tau_d_force``), ``other[name]`` (route 2) and
        ``digits[name]`` (list of agreement digits per coefficient).
    """
    with mpmath.workdps(dps):
        (r1, M1), (r2, M2) = routes
        (s1, N1), (s2, N2) = mu_routes
        c1 = _cauchy(lambda x: solve_point(x, "delta"), r1, M1, K)
        c1.update(_cauchy(lambda x: solve_point(x, "force"), s1, N1, 2 * K))
        c2 = _chebyshev(lambda x: solve_point(x, "delta"), r2, M2, K)
        c2.update(_chebyshev(lambda x: solve_point(x, "force"), s2, N2, 2 * K))
        digits = {n: [_agree(a, b) for a, b in zip(c1[n], c2[n])] for n in c1}
    return {"coef": c1, "other": c2, "digits": digits}


def raman_c1():
    """Raman's coefficient c1 = -de/dlambda at 0 = (4/5) (5/4)^(8/5) B(8/5, 1/2), a SymPy number."""
    return sp.Rational(4, 5) * sp.Rational(5, 4) ** sp.Rational(8, 5) * sp.gamma(sp.Rational(8, 5)) * sp.sqrt(sp.pi) / sp.gamma(sp.Rational(21, 10))


def grain_a5():
    """The first coefficient where the grains' end differs from the plate's: e_force - e_delta =
    a5 lambda^(5/2) + ..., a5 = (4/15) (3/2)^(5/2) = (3/5) sqrt(3/2), a SymPy number."""
    return sp.Rational(3, 5) * sp.sqrt(sp.Rational(3, 2))


# --- large lambda ------------------------------------------------------------------------

def _fr_mul(a, b, K):
    return [sum(a[i] * b[k - i] for i in range(k + 1)) for k in range(K + 1)]


def _fr_pow(a, alpha, K):
    """(a)^alpha for a series with a[0] = 1 (J.C.P. Miller's recurrence), exact in Fractions."""
    g = [Fraction(1)] + [Fraction(0)] * K
    for k in range(1, K + 1):
        g[k] = sum((alpha * j - (k - j)) * a[j] * g[k - j] for j in range(1, k + 1)) / k
    return g


def manifold_series(K=40):
    """Exact coefficients b_k of q(z) = 1 + sum b_k z^k, z = W^(-1/3), on the slow manifold
    P^(3/2) = W q of P' = W - P^(3/2), W' = -P^(3/2) (Eq. 10 at lambda = 1): the fixed point of
    q = 1 + (2/3) z q^(2/3) (q - z q'/3), one order per sweep."""
    q = [Fraction(1)] + [Fraction(0)] * K
    for _ in range(K + 1):
        dq = [k * q[k] for k in range(K + 1)]  # z q'
        inner = [q[k] - dq[k] / 3 for k in range(K + 1)]
        rhs = _fr_mul(_fr_pow(q, Fraction(2, 3), K), inner, K)
        q = [Fraction(1)] + [Fraction(2, 3) * rhs[k - 1] for k in range(1, K + 1)]
    return q


def _trajectory(lam, tau0, d0, v0, force=True):
    """Real trajectory of Eq. (10) from a tau-form state (delta0 > 0): tau-form until v < 0 and
    v^2 >= 2 delta^(5/2), then u-form down to u = 0. Returns the plate's end (``e_delta``,
    ``tau_d_delta``) and, with ``force``, stops at the grains' force-free end (the first point after
    the end of compression with delta + (3/2) lam v = 0; ``e_force``, ``tau_d_force``, ``delta_m``,
    ``tau_dc``)."""
    N = _order()
    k = mpmath.mpf(3) / 2 * lam
    tau, d, v = tau0, d0, v0
    out = {}
    while True:
        c = _jets_t(d, v, lam, N)
        h = _hmax(c, N)
        d1, v1 = _horner(c[0], h), _horner(c[1], h)
        if not d1 > 0:
            h /= 4
            continue
        if "tau_dc" not in out and v > 0 and v1 <= 0:
            cv, dcv = c[1], _dpoly(c[1])
            s = _newton(lambda s: _horner(cv, s), lambda s: _horner(dcv, s), h / 2, "v = 0")
            out["tau_dc"], out["delta_m"] = tau + s, _horner(c[0], s)
        if force and "tau_dc" in out and d1 + k * v1 < 0:
            g = [c[0][i] + k * c[1][i] for i in range(len(c[1]))]
            s = _newton(lambda s: _horner(g, s), lambda s: _horner(_dpoly(g), s), h / 2, "force-free end")
            out["e_force"], out["tau_d_force"] = -_horner(c[1], s), tau + s
            return out
        tau, d, v = tau + h, d1, v1
        if v < 0 and v * v >= 2 * d * d * mpmath.sqrt(d):
            break
    u = mpmath.sqrt(d)
    while u > 0:
        c = _jets_u(u, tau, v, lam, N)
        h = -min(_hmax(c, N), u)
        u1 = u + h if h != -u else mpmath.mpf(0)
        v1 = _horner(c[1], h)
        if force and u1 * u1 + k * v1 <= 0:
            g = [(u * u if i == 0 else 2 * u if i == 1 else 1 if i == 2 else 0) + k * c[1][i]
                 for i in range(len(c[1]))]
            s = _newton(lambda s: _horner(g, s), lambda s: _horner(_dpoly(g), s), h / 2, "force-free end")
            out["e_force"], out["tau_d_force"] = -_horner(c[1], s), _horner(c[0], s)
            return out
        tau, v, u = _horner(c[0], h), v1, u1
    out["e_delta"], out["tau_d_delta"] = -v, tau
    return out


def physical_point(lam, force=True, dps=30):
    """Eq. (10) from its start (u-form to v = 1/2, then :func:`_trajectory`), real lambda: the plate's
    or the grains' end. A second integrator for the large-lambda checks."""
    with mpmath.workdps(dps):
        lam = mpmath.mpf(lam)
        N = _order()
        u, tau, v = mpmath.mpf(0), mpmath.mpf(0), mpmath.mpf(1)
        half = mpmath.mpf(1) / 2
        while True:
            c = _jets_u(u, tau, v, lam, N)
            h = _hmax(c, N)
            if _horner(c[1], h) <= half:
                cv, dcv = [c[1][0] - half] + c[1][1:], _dpoly(c[1])
                h = _newton(lambda s: _horner(cv, s), lambda s: _horner(dcv, s), h / 2, "v = 1/2")
                tau, v, u = _horner(c[0], h), half, u + h
                break
            tau, v, u = _horner(c[0], h), _horner(c[1], h), u + h
        return _trajectory(lam, tau, u * u, v, force=force)


def large_lambda_constants(W_s=mpmath.mpf(10) ** 6, K=24, dps=40):
    """K_delta = lim e lambda^5 and C_delta = lim (tau_d/lambda - 5 ln lambda) at the plate's end,
    from the manifold trajectory started at W = W_s on the series truncated after z^K."""
    q = manifold_series(K)
    with mpmath.workdps(dps):
        W = mpmath.mpf(W_s)
        z = W ** (-mpmath.mpf(1) / 3)
        Q = W * mpmath.fsum(mpmath.mpf(b.numerator) / b.denominator * z**i for i, b in enumerate(q))
        P = Q ** (mpmath.mpf(2) / 3)
        end = _trajectory(mpmath.mpf(1), mpmath.mpf(0), P, W - Q, force=False)
        # time from W_s back to W -> infinity: s(W) = ln W + C + sum (3 g_k / k) z^k with 1/q - 1 = sum g_k z^k
        inv = _fr_pow(q, Fraction(-1), K)
        tail = mpmath.fsum(3 * (mpmath.mpf(g.numerator) / g.denominator) / i * z**i for i, g in enumerate(inv) if i)
        return {"K_delta": end["e_delta"], "C_delta": end["tau_d_delta"] - mpmath.log(W) + tail}


def derive(ctx: Context | None = None, *, K=16, large=True) -> Context:
    """Run the derivation and its checks; puts ``small`` (see :func:`small_lambda_coefficients`),
    ``raman_c1`` and ``large`` (constants) in ``ctx.expr``."""
    ctx = ctx if ctx is not None else Context()
    with mpmath.workdps(DPS):  # mpf arithmetic in the checks rounds to the working precision
        return _derive(ctx, K, large)


def _derive(ctx, K, large):
    c1 = raman_c1()

    def c1_closed():
        # Energy balance at first order: 2 c1 lambda = 2 lambda int delta0^3 dtau; along the Hertz
        # solution dtau = d delta / sqrt(1 - (4/5) delta^(5/2)), twice (loading and unloading);
        # x = (4/5) delta^(5/2) turns it into const x^(3/5) (1 - x)^(-1/2) dx, a Beta integral.
        # (SymPy 1.x integrates that Beta integral to a wrong, negative, hypergeometric value, so
        # the Beta function is applied by hand and checked by quadrature in delta.)
        x = sp.symbols("x", positive=True)
        dl_x = (sp.Rational(5, 4) * x) ** sp.Rational(2, 5)
        integrand = 2 * dl_x**3 * dl_x.diff(x) / sp.sqrt(1 - x)
        const = sp.Rational(4, 5) * sp.Rational(5, 4) ** sp.Rational(8, 5)
        subst_ok = sp.simplify(integrand - const * x ** sp.Rational(3, 5) / sp.sqrt(1 - x)) == 0
        with mpmath.workdps(40):
            dm = (mpmath.mpf(5) / 4) ** (mpmath.mpf(2) / 5)
            direct = 2 * mpmath.quad(lambda d: d**3 / mpmath.sqrt(1 - mpmath.mpf(4) / 5 * d ** mpmath.mpf(2.5)), [0, dm])
        direct = mpmath.re(direct)  # rounding at the upper end leaves an imaginary part ~1e-21
        ok = subst_ok and abs(mpmath.mpf(sp.N(c1, 45)) - direct) < 1e-20
        return ok, f"substitution {'exact' if subst_ok else 'WRONG'}; c1 = {sp.N(c1, 25)} (quadrature in delta {mpmath.nstr(direct, 25)})"

    ctx.check("R", "Raman's c1 = int delta_0^3 dtau over the Hertz contact = (4/5)(5/4)^(8/5) B(8/5,1/2)",
              "SymPy substitution, Beta function; mpmath quad in delta at 40 digits", c1_closed)

    small = small_lambda_coefficients(K)
    co, dg = small["coef"], small["digits"]

    def good_orders(name, step=1):
        n = 0
        for k in range(0, len(dg[name]), step):
            if dg[name][k] < 20:
                break
            n = k
        return n

    ctx.check("R", "e(lambda) at delta = 0: c1 of the hierarchy equals the closed form",
              "route 1 vs SymPy at 40 digits",
              lambda: (abs(-co["e_delta"][1] - mpmath.mpf(sp.N(c1, 60))) < 1e-35, f"-de/dlambda = {mpmath.nstr(-co['e_delta'][1], 25)}"))
    for name in _FIELDS_LAM:
        n = good_orders(name)
        ctx.check("S", f"{name}: Taylor coefficients in lambda agree by both routes to >= 20 digits through order {n}",
                  "Cauchy (r = 0.15, 48 points) vs Chebyshev (r = 0.1, 40 points) at 50 digits",
                  lambda n=n, name=name: (n >= 10, f"orders 0..{n}; digits {[round(x) for x in dg[name][:n + 1]]}"))
    for name in _FIELDS_MU:
        n = good_orders(name)
        ctx.check("S", f"{name}: Taylor coefficients in lambda^(1/2) agree by both routes to >= 20 digits through order {n}",
                  "Cauchy (|mu| = 0.25, 96 points) vs Chebyshev (mu in [-0.2, 0.2], 64 points) at 50 digits",
                  lambda n=n, name=name: (n >= 16, f"orders 0..{n}"))
    ctx.check("S", "force-free end: no lambda^(1/2), lambda^(3/2) terms; equal to the plate's e through lambda^2, "
              "differs at lambda^(5/2)", "coefficients of route 1",
              lambda: (all(abs(co["e_force"][j]) < 1e-40 for j in (1, 3))
                       and all(abs(co["e_force"][2 * j] - co["e_delta"][j]) < 1e-35 for j in (0, 1, 2))
                       and abs(co["e_force"][5]) > 1e-3,
                       f"lambda^(5/2) coefficient {mpmath.nstr(co['e_force'][5], 20)}"))

    def a5_closed():
        # Between the force-free point (delta = (3/2) lambda |v|) and delta = 0 the plate's contact
        # still acts with F_c = sqrt(delta) (delta - (3/2) lambda) (v = -1, dtau = d delta at
        # leading order); the grains skip that impulse, so e_force - e_delta = its integral.
        d, lam = sp.symbols("delta lambda", positive=True)
        k = sp.Rational(3, 2) * lam
        dv = sp.integrate(sp.sqrt(d) * (k - d), (d, 0, k))
        closed = sp.Rational(4, 15) * k ** sp.Rational(5, 2)
        ok_sym = sp.simplify(dv - closed) == 0
        a5 = mpmath.mpf(str(sp.N(grain_a5(), 60)))
        return ok_sym and abs(co["e_force"][5] - a5) < 1e-35, (
            f"integral = {dv}; a5 = (3/5) sqrt(3/2) = {mpmath.nstr(a5, 20)}, hierarchy {mpmath.nstr(co['e_force'][5], 20)}")

    ctx.check("S", "force-free end: e_force - e_delta = (4/15) (3 lambda/2)^(5/2) + ..., the impulse of the "
              "attractive tail the grains skip", "SymPy integrate; route 1 at 50 digits", a5_closed)
    ctx.expr["small"] = small
    ctx.expr["raman_c1"] = c1
    ctx.expr["grain_a5"] = grain_a5()

    if large:
        a = large_lambda_constants(mpmath.mpf(10) ** 6, 24)
        b = large_lambda_constants(mpmath.mpf(10) ** 9, 16)
        agree = {n: _agree(a[n], b[n]) for n in a}
        ctx.check("L", "plate: e lambda^5 -> K_delta and tau_d/lambda - 5 ln lambda -> C_delta from the manifold trajectory",
                  "W_s = 1e6 with 24 terms vs W_s = 1e9 with 16 terms, 40 digits",
                  lambda: (min(agree.values()) >= 15,
                           "; ".join(f"{n} = {mpmath.nstr(a[n], 20)} ({agree[n]:.0f} digits)" for n in a)))
        pts = {lam: physical_point(lam) for lam in (100, 1000)}

        def grains_large():
            # At the force-free end e = delta/(3/2 lambda) exactly, and delta -> delta_m -> lambda^(-2/3).
            rows = []
            ok = True
            for lam, r in pts.items():
                L = mpmath.mpf(lam)
                ef, dm = r["e_force"] * L ** (mpmath.mpf(5) / 3), r["delta_m"] * L ** (mpmath.mpf(2) / 3)
                ok &= abs(ef - mpmath.mpf(2) / 3) < 3 / L and abs(dm - 1) < 2 / L
                rows.append(f"lambda = {lam}: e lambda^(5/3) = {mpmath.nstr(ef, 8)}, delta_m lambda^(2/3) = {mpmath.nstr(dm, 8)}")
            return ok, "; ".join(rows)

        ctx.check("L", "grains: e lambda^(5/3) -> 2/3 (e = delta/(3/2 lambda) at the force-free end, which follows "
                  "the end of compression, delta_m lambda^(2/3) -> 1)", "this module's integrator from the start, "
                  "lambda = 100, 1000", grains_large)
        def plate_from_start():
            # e lambda^5 = K_delta up to exponentially small terms, and
            # tau_d = lambda (5 ln lambda + C_delta) + 3 lambda^(-2/3) + O(lambda^(-7/3)): the 3 is
            # 2 from the manifold's own time, -3 g_1 z with 1/q = 1 - (2/3) z + ..., plus 1 from the
            # initial layer, where W lags the manifold by W0^(2/3) int (1 - p^(3/2)) dsigma =
            # W0^(2/3) int p' dsigma = W0^(2/3) (p(inf) - p(0)) = W0^(2/3).
            rows, ok, prev = [], True, None
            with mpmath.workdps(25):
                for lam in (10, 30):
                    r = physical_point(lam, force=False, dps=20)
                    L = mpmath.mpf(lam)
                    ek = r["e_delta"] * L**5 / a["K_delta"] - 1
                    corr = (r["tau_d_delta"] - L * (5 * mpmath.log(L) + a["C_delta"])) * L ** (mpmath.mpf(2) / 3)
                    nxt = (corr - 3) * L ** (mpmath.mpf(5) / 3)  # the next term's coefficient
                    ok &= abs(ek) < 1e-15 and abs(corr - 3) < 2 * L ** (-mpmath.mpf(5) / 3)
                    if prev is not None:
                        ok &= abs(nxt / prev - 1) < 0.05  # the remainder scales as lambda^(-7/3)
                    prev = nxt
                    rows.append(f"lambda = {lam}: e lambda^5/K - 1 = {mpmath.nstr(ek, 3)}, "
                                f"(tau_d - lambda (5 ln lambda + C)) lambda^(2/3) = {mpmath.nstr(corr, 10)}")
            return ok, "; ".join(rows)

        ctx.check("L", "plate from the start: e lambda^5 = K_delta (exponentially small remainder), "
                  "tau_d = lambda (5 ln lambda + C_delta) + 3 lambda^(-2/3) + O(lambda^(-7/3))",
                  "this module's integrator from the start at lambda = 10, 30 (20 digits)", plate_from_start)
        ctx.expr["large"] = dict(a, tau_d_corr=sp.Integer(3), e_force_lim=sp.Rational(2, 3), delta_m_lim=sp.Integer(1))
    Dd = sp.Symbol("D", positive=True)
    fpk = sp.Rational(3, 2) * sp.sqrt(Dd) * (1 - Dd ** sp.Rational(3, 2))
    crit = [r for r in sp.solve(sp.diff(fpk, Dd), Dd) if r.is_positive]
    peak = sp.simplify(fpk.subs(Dd, crit[0])) if len(crit) == 1 else None
    ctx.check("L", "grains at large lambda: F_c lambda^(-2/3) -> max_D (3/2) sqrt(D) (1 - D^(3/2)) = (9/8) 4^(-1/3) "
              "in the initial layer delta = lambda^(-2/3) D, D' = 1 - D^(3/2)", "SymPy solve",
              lambda: (peak is not None and sp.simplify(peak - sp.Rational(9, 8) * 4 ** sp.Rational(-1, 3)) == 0,
                       f"peak at D = {crit}, value {peak}"))
    ctx.expr["grain_peak_large"] = peak
    return ctx


def coefficients_json(ctx: Context) -> str:
    """The verified coefficients and constants as deterministic JSON text (25 significant digits;
    only the coefficients both routes agree on to >= 20 digits), for the ``series`` model."""
    import json

    small = ctx.expr["small"]
    out = {"source": "python -m zener_sym.derivation.lambda_series --write <path> (derivation/lambda_series.py)",
           "note": "c[k]: coefficient of lambda^k (plate fields, F_m_grain) or of lambda^(k/2) (e_force, "
                   "tau_d_force); digits: agreement of the two routes; large: limits at large lambda",
           "small": {}, "large": {}}
    for name in sorted(small["coef"]):
        dg = small["digits"][name]
        n = 0
        while n < len(dg) and dg[n] >= 20:
            n += 1
        out["small"][name] = {"c": [mpmath.nstr(c, 25, min_fixed=1, max_fixed=0) if abs(c) > mpmath.mpf(10) ** -30
                                    else "0" for c in small["coef"][name][:n]],
                              "digits": [int(d) for d in dg[:n]]}
    with mpmath.workdps(30):
        for name, v in sorted(ctx.expr.get("large", {}).items()):
            out["large"][name] = mpmath.nstr(mpmath.mpf(str(sp.N(v, 30))) if isinstance(v, sp.Basic) else v, 25)
    return json.dumps(out, indent=1, sort_keys=True) + "\n"


def main(argv=None) -> int:  # pragma: no cover - command line
    import sys

    argv = sys.argv[1:] if argv is None else argv
    ctx = Context()
    ctx.log.echo = print
    derive(ctx)
    print(f"{'OK' if ctx.log.ok else 'FAILED'}: {len(ctx.log.steps)} steps")
    if argv[:1] == ["--write"] and ctx.log.ok:
        with open(argv[1], "w", encoding="utf-8") as fh:
            fh.write(coefficients_json(ctx))
        print(f"wrote {argv[1]}")
    return 0 if ctx.log.ok else 1


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
