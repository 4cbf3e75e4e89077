"""Hunter's (1957) and Reed's (1985) stress-wave loss of a sphere on an elastic half-space, derived.

Not part of the paper's derivation chain (``registry.PARTS``): the paper quotes, for Fig. 14,
xi = k V0^{3/5} with k_Hunter ~ 0.0013 and k_Reed ~ 0.0058 (V0 in m/s, Table 1 materials) without
a derivation. Run ``python -m zener_sym.derivation.stress_waves``.

1. The half-space (Lamb 1904; Miller & Pursey 1954). A normal point force F e^{-i omega t} on the
   surface of a half-space (density rho, shear speed c2, Poisson ratio nu) moves the loaded point
   by u = G(omega) F with the Hankel-transform compliance

       G(omega) = k_T / (2 pi mu) int_0^inf K(s) ds,  K(s) = s sqrt(s^2 - kappa^2) / D(s),
       D(s) = 4 s^2 sqrt(s^2 - kappa^2) sqrt(s^2 - 1) - (2 s^2 - 1)^2,

   s = k / k_T the horizontal wavenumber over the shear one (k_T = omega / c2), mu = rho c2^2,
   kappa^2 = c2^2 / c1^2 = (1 - 2 nu) / (2 (1 - nu)). K(inf) = 1 - nu gives Boussinesq's static
   u = F (1 - nu) / (2 pi mu r) (checked). The real part of G diverges at r = 0 (the static
   singularity, which stores energy and gives it back); the imaginary part, with the outgoing
   branches sqrt(s^2 - a^2) = -i sqrt(a^2 - s^2) for s < a and the Rayleigh pole s_R = c2 / c_R
   passed below, is finite:

       Im G = k_T h(nu) / (2 pi mu),   h = I_1 + I_2 + I_R,
       I_1 = int_0^kappa s a / ((2s^2 - 1)^2 + 4 s^2 a b) ds               (a = sqrt(kappa^2 - s^2),
       I_2 = int_kappa^1 4 s^3 a'^2 b / ((2s^2 - 1)^4 + 16 s^4 a'^2 b^2) ds   a' = sqrt(s^2 - kappa^2),
       I_R = pi s_R sqrt(s_R^2 - kappa^2) / D'(s_R)                          b = sqrt(1 - s^2)),

   I_R being the Rayleigh wave, I_1 + I_2 the body waves. At nu = 1/4 this reproduces Miller &
   Pursey's (1955) partition (67.4% Rayleigh; 25.8% shear + 6.9% compression = the other 32.6%),
   and a contour route (the path pushed below the real axis, principal square roots, no splitting)
   gives the same h (both checked).

2. The radiated energy. The work of F(t) on the surface, W = int F u' dt, in Fourier form:

       W = 1/pi int_0^inf omega Im G |F^(omega)|^2 d omega
         = h(nu) / (2 pi^2 rho c2^3) int_0^inf omega^2 |F^(omega)|^2 d omega
         = h(nu) / (2 pi rho c2^3) int F'(t)^2 dt                 (Parseval),

   which for F = F0 cos(omega t) is the Miller-Pursey power omega^2 F0^2 h / (4 pi rho c2^3)
   (checked). Only the half-space enters: its rho2, c2 (from E2, nu2) and, through h, c1 and c_R.

3. The pulses, in the paper's scaling (Eq. 9 with m* = m1: F = m1 V0 / T F-bar, t = T tau,
   T^{5/2} = m1 / ((4/3) E* sqrt(R V0)); the paper prints the exponent 2/3, the scaling of
   Eq. (10) needs 2/5), with delta-bar_m = (5/4)^{2/5} (Eq. 3) and Hunter's Omega = 1.068 /
   delta-bar_m (Eq. 4; pi / 1.068 = 2.94 is Hertz's duration factor of Eq. 2):

       Hunter (Eq. 5 -> 52): F-bar = A_H sin(Omega tau), A_H = delta-bar_m Omega^2,
                             J = int F-bar'^2 dtau = (pi / 2) A_H^2 Omega,
       Reed (Eq. 6 -> 53):   F-bar = A_R sin^{3/2}(Omega tau), A_R = delta-bar_m^{3/2},
                             J = (3/2) A_R^2 Omega   (the paper's (53) prints sin^3; its (6) and the
                             Hertz law it comes from give 3/2),
       Hertz (exact, lambda = 0): F-bar = delta^{3/2}, delta'^2 = 1 - (4/5) delta^{5/2},
                             J = (9/5) (5/4)^{4/5} B(4/5, 3/2).

   Reed's pulse is the one read here because it is what the paper writes (Eq. 6): Reed's own
   paper is not available. The Hunter frequency integral is checked in closed form against a
   numerical quadrature of omega^2 |F^|^2.

4. The loss. xi = W / (m1 V0^2 / 2) = k V0^{3/5} with, for m1 = (4/3) pi R^3 rho1,

       k = h(nu2) J / (pi rho2 c2^3) (4 E* / 3)^{6/5} (4 pi rho1 / 3)^{-1/5},

   independent of R; E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) carries both materials, rho1 the
   sphere's mass. For two equal materials (E, nu, rho) k c0^{3/5} is a number C(nu) (c0 = sqrt(E/rho)):
   Hunter's xi = C (V0/c0)^{3/5}.
"""
from __future__ import annotations

import sys

import mpmath
import sympy as sp

from .steps import MP_DPS, Context, mp_max_rel_residual, symbolic_zero

__all__ = ["derive", "main", "radiation_h", "partition", "rayleigh_root", "k_coefficient",
           "equal_material_constant", "PULSE_J", "TABLE1", "HUNTER_OMEGA_FACTOR"]

_R = sp.Rational
#: Hunter's frequency factor 1.068 of Eq. (4) (pi / 1.068 = 2.94, Hertz's duration factor of
#: Eq. 2): an input of his model, kept as he gives it.
HUNTER_OMEGA_FACTOR = _R(1068, 1000)
_DM = _R(5, 4) ** _R(2, 5)                  # Hertz's delta-bar_m, Eq. (3)/(23)
_OMEGA = HUNTER_OMEGA_FACTOR / _DM          # Eq. (52)'s 0.977
_A_H = _DM * _OMEGA**2                      # Eq. (52)'s 1.043
_A_R = _DM ** _R(3, 2)                      # Eq. (53)'s 1.143
#: J = int (dF-bar/dtau)^2 dtau of each pulse, exact (see the module docstring, item 3).
PULSE_J = {
    "hunter": sp.pi / 2 * _A_H**2 * _OMEGA,
    "reed": _R(3, 2) * _A_R**2 * _OMEGA,
    "hertz": _R(9, 5) * _R(5, 4) ** _R(4, 5) * sp.gamma(_R(4, 5)) * sp.gamma(_R(3, 2)) / sp.gamma(_R(23, 10)),
}
#: The paper's Table 1 (sphere gamma-Al2O3, plate glass) and R = 0.9 mm, SI units.
TABLE1 = {"E1": 12.23e9, "nu1": 0.21, "rho1": 879.0, "E2": 73e9, "nu2": 0.21, "rho2": 2500.0,
          "R": 0.9e-3}


def _kappa2(nu):
    nu = mpmath.mpf(nu)
    return (1 - 2 * nu) / (2 * (1 - nu))


def _D(s, k2):
    return 4 * s**2 * mpmath.sqrt(s**2 - k2) * mpmath.sqrt(s**2 - 1) - (2 * s**2 - 1) ** 2


def rayleigh_root(nu):
    """s_R = c2 / c_R > 1, the real root of D(s) = 0 (mpmath, working precision)."""
    k2 = _kappa2(nu)
    # D(1) = -1 < 0 and D(s) -> 2 s^2 (1 - kappa^2) > 0: one sign change on (1, 2); a bracketing
    # solver keeps s > 1, where D is real
    return mpmath.findroot(lambda s: _D(s, k2), (mpmath.mpf(1), mpmath.mpf(2)), solver="illinois")


def _dD(s, k2):
    """dD/ds (alpha' = s / alpha, beta' = s / beta)."""
    al, be = mpmath.sqrt(s**2 - k2), mpmath.sqrt(s**2 - 1)
    return 8 * s * al * be + 4 * s**3 * (be / al + al / be) - 8 * s * (2 * s**2 - 1)


def partition(nu):
    """(I_1, I_2, I_R) of the module docstring: the imaginary part of int K ds by regions."""
    k2 = _kappa2(nu)
    ka = mpmath.sqrt(k2)

    def rs(x):  # nodes next to an end point may round k2 - s^2 to a tiny negative number
        return mpmath.sqrt(max(x, 0))

    def f1(s):
        a, b = rs(k2 - s**2), rs(1 - s**2)
        return s * a / ((2 * s**2 - 1) ** 2 + 4 * s**2 * a * b)

    def f2(s):
        a2, b = max(s**2 - k2, 0), rs(1 - s**2)
        return 4 * s**3 * a2 * b / ((2 * s**2 - 1) ** 4 + 16 * s**4 * a2 * b**2)

    i1 = mpmath.quad(f1, [0, ka])
    i2 = mpmath.quad(f2, [ka, 1])
    sr = rayleigh_root(nu)
    ir = mpmath.pi * sr * mpmath.sqrt(sr**2 - k2) / _dD(sr, k2)
    return i1, i2, ir


def radiation_h(nu):
    """h(nu) = I_1 + I_2 + I_R: Im G(omega) = omega h / (2 pi mu c2) at the loaded point."""
    return sum(partition(nu))


def _h_contour(nu, depth=mpmath.mpf("0.25"), top=4):
    """h by a second route: Im of int K(s) ds on s = x - i depth sin(pi x / top), 0 <= x <= top,
    with principal square roots (below the real axis they are the outgoing branches, and the path
    passes below the Rayleigh pole); beyond x = top, K is real."""
    k2 = _kappa2(nu)

    def K(s):
        a = mpmath.sqrt(s**2 - k2)
        return s * a / (4 * s**2 * a * mpmath.sqrt(s**2 - 1) - (2 * s**2 - 1) ** 2)

    w = mpmath.pi / top

    def f(x):
        s = x - 1j * depth * mpmath.sin(w * x)
        return K(s) * (1 - 1j * depth * w * mpmath.cos(w * x))

    return mpmath.im(mpmath.quad(f, mpmath.linspace(0, top, 9)))


def k_coefficient(pulse, E1, nu1, rho1, E2, nu2, rho2):
    """k of xi = k V0^{3/5} (V0 in m/s) for a sphere (1) on a half-space (2), mpmath."""
    E1, nu1, rho1, E2, nu2, rho2 = (mpmath.mpf(x) for x in (E1, nu1, rho1, E2, nu2, rho2))
    es = 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)
    c2 = mpmath.sqrt(E2 / (2 * (1 + nu2) * rho2))
    J = mpmath.mpf(str(sp.N(PULSE_J[pulse], MP_DPS)))
    return (radiation_h(nu2) * J / (mpmath.pi * rho2 * c2**3) * (4 * es / 3) ** (mpmath.mpf(6) / 5)
            * (4 * mpmath.pi * rho1 / 3) ** (mpmath.mpf(-1) / 5))


def equal_material_constant(pulse, nu):
    """C(nu) = k c0^{3/5} for a sphere and a half-space of one material (E and rho drop out)."""
    return k_coefficient(pulse, 1, nu, 1, 1, nu, 1)


def derive(ctx: Context | None = None) -> Context:
    """Derive and check the radiated energy, the pulses' J and the loss coefficient k; adds
    ``K_lamb``, ``W_transient``, ``J_hunter``, ``J_reed``, ``J_hertz``, ``k_halfspace`` to
    ``ctx.expr`` and returns the context."""
    ctx = ctx or Context()
    E = ctx.expr
    s, nu, a, b = sp.symbols("s nu a b", positive=True)
    k2 = (1 - 2 * nu) / (2 * (1 - nu))
    al, be = sp.sqrt(s**2 - k2), sp.sqrt(s**2 - 1)
    D = 4 * s**2 * al * be - (2 * s**2 - 1) ** 2
    K = s * al / D
    E["K_lamb"] = K

    def static_limit():
        # large s: D ~ 2 s^2 (1 - kappa^2); K -> 1/(2 (1 - kappa^2)) = 1 - nu (Boussinesq)
        x = sp.Symbol("x", positive=True)  # x = 1/s
        lim = sp.limit(K.subs(s, 1 / x), x, 0)
        return symbolic_zero(lim - (1 - nu))
    ctx.check("Lamb", "K(s) -> 1 - nu as s -> inf: the static limit is Boussinesq's "
              "u = F (1 - nu) / (2 pi mu r)", "SymPy limit", static_limit)

    def branches():
        # s < kappa: alpha = -i a, beta = -i b; kappa < s < 1: alpha real (a), beta = -i b
        K1 = (s * (-sp.I * a) / (4 * s**2 * (-sp.I * a) * (-sp.I * b) - (2 * s**2 - 1) ** 2))
        f1 = s * a / ((2 * s**2 - 1) ** 2 + 4 * s**2 * a * b)
        K2 = s * a / (4 * s**2 * a * (-sp.I * b) - (2 * s**2 - 1) ** 2)
        f2 = 4 * s**3 * a**2 * b / ((2 * s**2 - 1) ** 4 + 16 * s**4 * a**2 * b**2)
        ok1, d1 = symbolic_zero(K1 - sp.I * f1)
        ok2, d2 = symbolic_zero(sp.im(sp.expand_complex(K2)) - f2)
        return ok1 and ok2, f"region 1: {d1}; region 2: {d2}"
    ctx.check("Lamb", "with the outgoing branches Im K = I_1's and I_2's integrands (both >= 0: the "
              "half-space only takes energy)", "SymPy simplification", branches)

    def rayleigh_quarter():
        # nu = 1/4: (c_R / c2)^2 = 2 - 2/sqrt(3), the classical closed form
        with mpmath.workdps(MP_DPS):
            sr = rayleigh_root(mpmath.mpf(1) / 4)
            ref = 1 / mpmath.sqrt(2 - 2 / mpmath.sqrt(3))
            return mp_max_rel_residual(lambda _: sr, lambda _: ref, [0], 1e-30)
    ctx.check("Lamb", "Rayleigh root at nu = 1/4: c_R / c2 = sqrt(2 - 2/sqrt(3))", "mpmath findroot "
              f"at {MP_DPS} digits", rayleigh_quarter)

    def miller_pursey():
        with mpmath.workdps(30):
            i1, i2, ir = partition(mpmath.mpf(1) / 4)
            h = i1 + i2 + ir
            fr, fb = ir / h, (i1 + i2) / h
        # Miller & Pursey (1955): Rayleigh 67.4%, shear 25.8%, compression 6.9% at nu = 1/4
        ok = round(float(100 * fr), 1) == 67.4 and abs(float(100 * fb) - (25.8 + 6.9)) < 0.15
        return ok, (f"Rayleigh {mpmath.nstr(100 * fr, 6)}% (67.4%), body waves "
                    f"{mpmath.nstr(100 * fb, 6)}% (25.8% + 6.9%), h(1/4) = {mpmath.nstr(h, 15)}")
    ctx.check("Lamb", "energy partition at nu = 1/4 is Miller & Pursey's (1955)", "mpmath quadrature "
              "and residue", miller_pursey)

    def contour():
        with mpmath.workdps(25):
            pts = [mpmath.mpf(1) / 4, mpmath.mpf("0.21"), mpmath.mpf("0.3"), mpmath.mpf("0.45")]
            return mp_max_rel_residual(_h_contour, radiation_h, pts, 1e-15)
    ctx.check("Lamb", "h(nu) by regions + residue equals Im int K ds on a contour below the real "
              "axis (no branch splitting, no residue)", "mpmath, nu = 1/4, 0.21, 0.3, 0.45", contour)

    # --- the radiated energy: harmonic power and transient work agree
    rho, c2, om, F0, t, h = sp.symbols("rho c_2 omega F_0 t h", positive=True)
    W_rate = h / (2 * sp.pi * rho * c2**3)  # W = W_rate * int F'^2 dt
    E["W_transient"] = W_rate

    def harmonic():
        # F = F0 cos(omega t): <P> = (1/2) omega F0^2 Im G, Im G = omega h / (2 pi rho c2^3)
        P = sp.Rational(1, 2) * om * F0**2 * (om * h / (2 * sp.pi * rho * c2**3))
        per = 2 * sp.pi / om
        Wp = W_rate * sp.integrate(sp.diff(F0 * sp.cos(om * t), t) ** 2, (t, 0, per)) / per
        return symbolic_zero(P - Wp)
    ctx.check("W", "W = h/(2 pi rho c2^3) int F'^2 dt gives the Miller-Pursey mean power "
              "omega^2 F0^2 h / (4 pi rho c2^3) for F0 cos(omega t)", "SymPy integration", harmonic)

    # --- Hunter's half-sine: frequency integral in closed form and by quadrature
    T, Fm, x = sp.symbols("T F_m x", positive=True)
    Fh = Fm * sp.sin(sp.pi * t / T)
    time_form = sp.pi * sp.integrate(sp.diff(Fh, t) ** 2, (t, 0, T))  # int_0^inf w^2 |F^|^2 dw

    def hunter_frequency():
        ok, det = symbolic_zero(time_form - sp.pi**3 * Fm**2 / (2 * T))
        # F^(omega) = int_0^T F e^{i omega t} dt from the antiderivative
        # P(t) = e^{i w t} (-a cos(a t) + i w sin(a t)) / (a^2 - w^2), a = pi / T
        a_ = sp.pi / T
        P = sp.exp(sp.I * om * t) * (-a_ * sp.cos(a_ * t) + sp.I * om * sp.sin(a_ * t)) / (a_**2 - om**2)
        ok1, det1 = symbolic_zero(sp.diff(P, t) - sp.sin(a_ * t) * sp.exp(sp.I * om * t))
        Fhat = sp.simplify(Fm * (P.subs(t, T) - P.subs(t, 0)))
        # = pi T F_m (1 + e^{i x}) / (pi^2 - x^2), x = omega T: |F^|^2 = (2 pi T F_m)^2 cos^2(x/2)
        # / (pi^2 - x^2)^2, so int_0^inf omega^2 |F^|^2 d omega = 4 pi^2 F_m^2 / T * j
        ok2, det2 = symbolic_zero(Fhat.subs(om, x / T) - sp.pi * T * Fm * (1 + sp.exp(sp.I * x))
                                  / (sp.pi**2 - x**2))
        with mpmath.workdps(25):
            # x^2 cos^2(x/2) / (pi^2 - x^2)^2 without the cancellation at x = pi
            f = lambda y: (y / (mpmath.pi + y)) ** 2 * (mpmath.sinc((mpmath.pi - y) / 2) / 2) ** 2  # noqa
            j = mpmath.nsum(lambda n: mpmath.quad(f, [2 * mpmath.pi * n, 2 * mpmath.pi * (n + 1)]),
                            [0, mpmath.inf])
            ok3, det3 = mp_max_rel_residual(lambda _: 4 * mpmath.pi**2 * j,
                                            lambda _: mpmath.pi**3 / 2, [0], 1e-18)
        return ok and ok1 and ok2 and ok3, (f"Parseval: {det}; antiderivative: {det1}; F^: {det2}; "
                                            f"quadrature over periods: {det3}")
    ctx.check("52", "Hunter's pulse: int_0^inf omega^2 |F^|^2 d omega = pi^3 F_m^2 / (2 T), "
              "closed form vs quadrature of the transform", "SymPy + mpmath quadosc", hunter_frequency)

    # --- J of each pulse in the paper's scaling
    Om, A, tau = sp.symbols("Omega A tau", positive=True)
    j_sine = sp.integrate(sp.diff(A * sp.sin(Om * tau), tau) ** 2, (tau, 0, sp.pi / Om))
    ph = sp.Symbol("phi", positive=True)
    # sin^{3/2}: (dF/dtau)^2 = (9/4) A^2 Omega^2 sin(phi) cos(phi)^2, dtau = dphi / Omega
    j_32 = sp.integrate(_R(9, 4) * A**2 * Om * sp.sin(ph) * sp.cos(ph) ** 2, (ph, 0, sp.pi))
    E["J_hunter"], E["J_reed"], E["J_hertz"] = PULSE_J["hunter"], PULSE_J["reed"], PULSE_J["hertz"]
    ctx.check("52-53", "J = int F-bar'^2 dtau: (pi/2) A^2 Omega (sine), (3/2) A^2 Omega (sin^{3/2})",
              "SymPy integration", lambda: (
                  symbolic_zero(j_sine - sp.pi / 2 * A**2 * Om)[0]
                  and symbolic_zero(j_32 - _R(3, 2) * A**2 * Om)[0], "both simplify to 0"))

    def hertz_j():
        # F = delta^{3/2}: F'^2 = (9/4) delta delta'^2, delta'^2 = 1 - (4/5) delta^{5/2}; over the
        # contact (compression and recovery) J = 2 int_0^dm (9/4) delta sqrt(1 - (4/5) delta^{5/2}).
        # Quadrature in delta = dm (1 - t^2)^{2/5}... simpler: v = sqrt(1 - u), u = (4/5) delta^{5/2}
        with mpmath.workdps(MP_DPS):
            dm = mpmath.power(mpmath.mpf(5) / 4, mpmath.mpf(2) / 5)
            f = lambda d: mpmath.mpf(9) / 2 * d * mpmath.sqrt(1 - mpmath.mpf(4) / 5 * d ** 2.5)  # noqa
            ref = mpmath.quad(f, [0, dm / 2, dm])
            val = mpmath.mpf(str(sp.N(PULSE_J["hertz"], MP_DPS)))
            return mp_max_rel_residual(lambda _: val, lambda _: ref, [0], 1e-25)
    ctx.check("10", "exact Hertz pulse (lambda = 0): J = (9/5)(5/4)^{4/5} B(4/5, 3/2)",
              f"mpmath quadrature at {MP_DPS} digits", hertz_j)

    # --- the loss coefficient: xi = W / (m1 V0^2 / 2) = k V0^{3/5}, k free of V0 and R
    E1s, R, V0, r1, r2, Es, Jp = sp.symbols("m_1 R V_0 rho_1 rho_2 E^* J", positive=True)
    m1 = _R(4, 3) * sp.pi * R**3 * r1
    Tch = (m1 / (_R(4, 3) * Es * sp.sqrt(R * V0))) ** _R(2, 5)
    # int F'^2 dt with F = m1 V0/T F-bar(t/T): (m1 V0 / T)^2 / T * J
    W = h / (2 * sp.pi * r2 * c2**3) * (m1 * V0 / Tch) ** 2 / Tch * Jp
    xi = sp.powsimp(sp.powdenest(W / (m1 * V0**2 / 2), force=True), force=True)
    k_closed = h * Jp / (sp.pi * r2 * c2**3) * (4 * Es / 3) ** _R(6, 5) * (4 * sp.pi * r1 / 3) ** _R(-1, 5)
    E["k_halfspace"] = k_closed

    def scaling():
        ratio = sp.simplify(sp.powsimp(sp.powdenest(xi / (k_closed * V0 ** _R(3, 5)), force=True),
                                       force=True))
        # and numerically at two speeds and two radii
        vals = {h: 0.9, Jp: 1.7, r1: 879, r2: 2500, c2: 3473, Es: 1.1e10}
        x1 = xi.subs(vals).subs({V0: 1, R: 1e-3})
        x2 = xi.subs(vals).subs({V0: 7, R: 3e-3})
        slope = sp.log(x2 / x1) / sp.log(7)
        return (ratio == 1 and abs(float(slope) - 0.6) < 1e-12,
                f"xi / (k V0^(3/5)) = {ratio}; d ln xi / d ln V0 between V0 = 1 and 7 m/s "
                f"(R changed too) = {float(slope):.15f}")
    ctx.check("3-6", "xi = W / (m1 V0^2 / 2) = k V0^{3/5}, k = h J (4E*/3)^{6/5} "
              "(4 pi rho1/3)^{-1/5} / (pi rho2 c2^3), independent of R", "SymPy simplification "
              "and two substituted speeds", scaling)

    def dimensional():
        # the same xi straight from Eqs. (3)-(5) in SI, without the paper's scaling
        with mpmath.workdps(30):
            p = {n: mpmath.mpf(v) for n, v in TABLE1.items()}
            es = 1 / ((1 - p["nu1"] ** 2) / p["E1"] + (1 - p["nu2"] ** 2) / p["E2"])
            m = 4 * mpmath.pi * p["R"] ** 3 * p["rho1"] / 3
            c = mpmath.sqrt(p["E2"] / (2 * (1 + p["nu2"]) * p["rho2"]))
            hh = radiation_h(p["nu2"])
            om_f = mpmath.mpf(1068) / 1000
            out = []
            for v in (mpmath.mpf(1), mpmath.mpf(13)):
                dm = (15 * m * v**2 / (16 * es * mpmath.sqrt(p["R"]))) ** (mpmath.mpf(2) / 5)  # Eq. (3)
                Tc = mpmath.pi * dm / (om_f * v)                     # sine period, Eq. (4)
                fm = m * dm * (om_f * v / dm) ** 2                   # Eq. (5) amplitude
                w = hh / (2 * mpmath.pi * p["rho2"] * c**3) * fm**2 * (mpmath.pi / Tc) ** 2 * Tc / 2
                out.append(w / (m * v**2 / 2) / v ** (mpmath.mpf(3) / 5))
            k = k_coefficient("hunter", *(TABLE1[n] for n in ("E1", "nu1", "rho1", "E2", "nu2", "rho2")))
            return mp_max_rel_residual(lambda i: out[i], lambda i: k, [0, 1], 1e-20)
    ctx.check("3-5", "Hunter's k from Eqs. (3)-(5) in SI units (no scaling) at V0 = 1 and 13 m/s",
              "mpmath at 30 digits", dimensional)

    def hunter_published():
        with mpmath.workdps(20):
            c = equal_material_constant("hunter", mpmath.mpf("0.3"))
        rel = float(c / mpmath.mpf("1.04") - 1)
        return abs(rel) < 0.05, (f"C(0.3) = {mpmath.nstr(c, 6)} against Hunter's 1.04 "
                                 f"({100 * rel:+.2f}%)")
    ctx.check("Hunter", "equal materials, nu = 0.3 (steel on steel): xi = C (V0/c0)^{3/5} with C near "
              "Hunter's published 1.04", "mpmath; tolerance 5%", hunter_published)
    return ctx


def main() -> int:
    from .steps import format_step

    ctx = derive()
    for st in ctx.log.steps:
        print(format_step(st))
    with mpmath.workdps(30):
        nu2 = TABLE1["nu2"]
        i1, i2, ir = partition(nu2)
        print(f"h({nu2}) = {mpmath.nstr(i1 + i2 + ir, 20)}  (Rayleigh {mpmath.nstr(ir / (i1 + i2 + ir), 6)})")
        for p in PULSE_J:
            k = k_coefficient(p, *(TABLE1[n] for n in ("E1", "nu1", "rho1", "E2", "nu2", "rho2")))
            print(f"J_{p} = {sp.N(PULSE_J[p], 20)}   k_{p} (Table 1) = {mpmath.nstr(k, 15)}"
                  f"   C_{p}(0.3) = {mpmath.nstr(equal_material_constant(p, '0.3'), 10)}")
    print("OK" if ctx.log.ok else "FAILED")
    return 0 if ctx.log.ok else 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
