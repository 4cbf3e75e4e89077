r"""The plate under the sphere, from Kirchhoff's plate theory: the infinite plate (Zener's alpha,
Eq. 7), the bounded plate's modes, its static compliance, and the dimensionless modal problem.

Kirchhoff's plate, D nabla^4 w + mu w_tt = F(t) delta(x) (mu = rho h, D = E h^3/(12(1 - nu^2))):

* **Infinite plate.** The Hankel transform (w = int_0^inf w^(xi, t) J0(xi r) xi dxi, the point
  load's transform 1/(2 pi)) turns the equation into mu w^_tt + D xi^4 w^ = F/(2 pi); an impulse
  I gives w^ = I sin(omega t)/(2 pi mu omega), omega = xi^2 sqrt(D/mu), and at the load point
  w(0, t) = I/(2 pi mu c) int_0^inf sin(c t xi^2)/xi dxi = I/(8 sqrt(D mu)) for every t > 0: a
  step. By superposition the load point moves with velocity alpha F, alpha = 1/(8 sqrt(D mu)):
  Zener's alpha of Eq. (7), and with t_0 = T of Eq. (9), lambda = alpha m / t_0 (Eq. 11).
* **Circle** (radius b, struck at its centre): the axisymmetric modes W = J0(kr)/J0(kb) -
  I0(kr)/I0(kb) solve nabla^4 W = k^4 W and W(b) = 0; clamped (W'(b) = 0) gives
  J0 I1 + J1 I0 = 0, simply supported (W'' + nu W'/r = 0 at b) gives
  (1 - nu)(J1 I0 + J0 I1) - 2 x J0 I0 = 0 (x = kb). Lommel's integrals give the modal mass in
  closed form, M = pi mu b^2 (2 + t_J^2 - t_I^2 - 2 (t_J + t_I)/x), t_J = J1/J0, t_I = I1/I0, so
  psi = W(0)^2 mu b^2 / M = (1/J0 - 1/I0)^2 / (pi (2 + t_J^2 - t_I^2 - 2 (t_J + t_I)/x)).
* **Rectangle** (a x b, simply supported, struck at (x, y) = (xi a, eta b)): Navier's modes
  sin(m pi x/a) sin(n pi y/b), Omega = pi^2 (m^2 b/a + n^2 a/b), psi = 4 sin^2(m pi xi)
  sin^2(n pi eta).
* **Static compliance** at the impact point, S = C_s D / L^2: 1/(16 pi) (clamped circle),
  (3 + nu)/(16 pi (1 + nu)) (simply supported circle), and for the rectangle a single series
  (the sum over n in closed form), whose algebraic part is s (zeta(3) - Cl_3(2 pi xi))/(4 pi^3)
  and whose rest falls exponentially. Each equals sum_n psi_n / Omega_n^2.
* **Dimensionless problem** (Zener's scales, t_0 = T): omega_n t_0 = beta Omega_n,
  c_n = m phi_n^2 / M_n = 8 lambda beta psi_n, C_s m / t_0^2 = 8 lambda S / beta, with
  beta = t_0 sqrt(D/mu)/L^2. Every shape has the same density of participation,
  psi dN/dOmega -> 1/(4 pi), so as beta -> 0 the admittance sum_n c_n p/(p^2 + omega_n^2) of the
  modal kernel sum_n c_n cos(omega_n tau) tends to lambda: Zener's dashpot w' = lambda F, Eq. (10).

Standalone (not a part of the paper's registry): ``python -m zener_sym.derivation.plate`` runs
it; ``zener_sym.codegen.plate`` prints :func:`expressions` into ``generated/plate.py``.
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import sympy as sp

from . import scaling
from .steps import Context, run_script, symbolic_zero

__all__ = ["derive", "expressions", "SYMBOLS", "I0E", "I1E"]

_pos = dict(positive=True)
#: The plate's symbols: the root x = k b, the wavenumber, radius, Poisson's ratio, the rectangle's
#: aspect s = a/b, mode numbers, impact fractions, the inner sum's c = m/s and Cl_3 (the
#: Clausen-type sum of cos(2 pi m xi)/m^3), and the physical D, mu = rho h, m, t_0, L.
SYMBOLS = {
    "x": sp.Symbol("x", **_pos), "k": sp.Symbol("k", **_pos), "r": sp.Symbol("r", **_pos),
    "b": sp.Symbol("b", **_pos), "nu": sp.Symbol("nu", real=True), "s": sp.Symbol("s", **_pos),
    "m": sp.Symbol("m", **_pos), "n": sp.Symbol("n", **_pos), "u": sp.Symbol("u", real=True),
    "v": sp.Symbol("v", real=True), "xi": sp.Symbol("xi", **_pos), "eta": sp.Symbol("eta", **_pos),
    "c": sp.Symbol("c", **_pos), "cl3": sp.Symbol("cl3", real=True),
    "D": sp.Symbol("D", **_pos), "mu": sp.Symbol("mu", **_pos), "msph": sp.Symbol("m_s", **_pos),
    "t0": sp.Symbol("t_0", **_pos), "L": sp.Symbol("L", **_pos), "t": sp.Symbol("t", **_pos),
    "lam": sp.Symbol("lambda", **_pos), "beta": sp.Symbol("beta", **_pos),
}
#: The exponentially scaled modified Bessel functions e^{-x} I0(x), e^{-x} I1(x): the printed
#: formulas use them so that nothing overflows for x in the thousands.
I0E, I1E = sp.Function("i0e"), sp.Function("i1e")

_Y = SYMBOLS


def _scaled(expr, x):
    """``expr`` with I0(x) = e^x i0e(x), I1(x) = e^x i1e(x), exponentials merged."""
    e = expr.subs({sp.besseli(0, x): sp.exp(x) * I0E(x), sp.besseli(1, x): sp.exp(x) * I1E(x)})
    return sp.powsimp(sp.expand(e))


def _unscaled(expr, x):
    return expr.subs({I0E(x): sp.exp(-x) * sp.besseli(0, x), I1E(x): sp.exp(-x) * sp.besseli(1, x)})


# ------------------------------------------------------------------------ the infinite plate
def _infinite_plate(ctx: Context) -> None:
    D, mu, t, m, t0, L = (_Y[n] for n in ("D", "mu", "t", "msph", "t0", "L"))
    xi_w, r, eps, Imp = sp.symbols("xi_w r epsilon I", positive=True)
    c = sp.sqrt(D / mu)
    omega = c * xi_w**2
    # the point load delta(x) = delta(r - eps)/(2 pi r), eps -> 0, in Hankel space
    load = sp.integrate(sp.DiracDelta(r - eps) / (2 * sp.pi * r) * sp.besselj(0, xi_w * r) * r,
                        (r, 0, sp.oo))
    ctx.check("7", "the point load's Hankel transform is 1/(2 pi)", "SymPy integrate, eps -> 0",
              lambda: (sp.simplify(sp.limit(load, eps, 0) - 1 / (2 * sp.pi)) == 0, f"{load}"))
    w_hat = Imp * sp.sin(omega * t) / (2 * sp.pi * mu * omega)
    ode = mu * w_hat.diff(t, 2) + D * xi_w**4 * w_hat
    ctx.check("7", "an impulse I: w^ = I sin(omega t)/(2 pi mu omega) solves mu w^_tt + D xi^4 w^ "
              "= 0 for t > 0 with w^(0) = 0, mu w^_t(0+) = I/(2 pi)", "SymPy substitution",
              lambda: (sp.simplify(ode) == 0 and w_hat.subs(t, 0) == 0
                       and sp.simplify(mu * w_hat.diff(t).subs(t, 0) - Imp / (2 * sp.pi)) == 0,
                       "residual 0, initial values hold"))
    w0 = sp.integrate(w_hat * xi_w, (xi_w, 0, sp.oo))  # J0(0) = 1 at the load point
    alpha = 1 / (8 * sp.sqrt(D * mu))
    ctx.check("7", "the load point's deflection after an impulse I is the step I/(8 sqrt(D mu)) "
              "for every t > 0, so it moves with velocity alpha F, alpha = 1/(8 sqrt(D mu))",
              "SymPy integrate (inverse Hankel transform at r = 0)",
              lambda: (sp.simplify(w0 - alpha * Imp) == 0, f"w(0, t) = {sp.simplify(w0)}"))
    # the paper's alpha (as derivation.scaling transcribes it) and the chain to lambda (11)
    sc = Context(checks=False)
    scaling.derive(sc)
    P = sc.symbols
    E2, nu2, rho2, H = P["E2"], P["nu2"], P["rho2"], P["H"]
    sub = {D: E2 * H**3 / (12 * (1 - nu2**2)), mu: rho2 * H}
    g = sp.Symbol("g", positive=True)  # g = 1 - nu2^2 > 0
    ratio = (alpha.subs(sub) / sc.expr["alpha"]).subs(nu2, sp.sqrt(1 - g))
    ctx.check("7", "alpha = 1/(8 sqrt(D rho h)) with D = E h^3/(12 (1 - nu^2)) is the paper's "
              "alpha = sqrt(3 rho (1 - nu^2)/E)/(4 rho H^2)", "SymPy simplify",
              lambda: (sp.simplify(ratio) == 1, f"ratio {sp.simplify(ratio)}"))
    T = sc.expr["T"]
    lam_plate = m / (8 * t0 * sp.sqrt(D * mu))

    def chain():
        # lambda = alpha m / T (Eq. 9's T) with our alpha and m = m1: Zener's Eq. (11)
        lam = (lam_plate.subs({t0: T, m: sc.expr["m1"]}).subs(sub)
               .subs({P["m"]: sc.expr["m1"], P["Estar"]: sc.expr["Estar_phys"]}))
        table1 = {P["E1"]: sp.Rational("12.23e9"), P["nu1"]: sp.Rational("0.21"),
                  P["rho1"]: sp.Integer(879), P["E2"]: sp.Rational("73e9"),
                  P["nu2"]: sp.Rational("0.21"), P["rho2"]: sp.Integer(2500),
                  P["R"]: sp.Rational("0.9e-3"), P["H"]: sp.Rational("0.4e-3"),
                  P["V0"]: sp.Integer(3)}
        num = abs(sp.N((lam / sc.expr["lam_phys"]).subs(table1), 30) - 1)
        return num < 1e-25, f"|lambda / lambda_11 - 1| = {sp.N(num, 3)} (Table 1 values)"

    ctx.check("11", "lambda = m/(8 t0 sqrt(D rho h)) with t0 = T (Eq. 9), m = m1 is Zener's "
              "Eq. (11)", "SymPy at 30 digits", chain)
    ctx.expr.update(alpha_plate=alpha, lam_plate=lam_plate,
                    beta_plate=t0 * sp.sqrt(D / mu) / L**2)


# ------------------------------------------------------------------------------ the circle
def _lap(f, r):
    return f.diff(r, 2) + f.diff(r) / r


def _circle(ctx: Context) -> None:
    k, r, b, nu, x = _Y["k"], _Y["r"], _Y["b"], _Y["nu"], _Y["x"]
    X = k * b
    J0, J1, I0, I1 = (sp.besselj(0, X), sp.besselj(1, X), sp.besseli(0, X), sp.besseli(1, X))
    W = sp.besselj(0, k * r) / J0 - sp.besseli(0, k * r) / I0
    ctx.check("plate", "circle: W = J0(kr)/J0(kb) - I0(kr)/I0(kb) solves nabla^4 W = k^4 W "
              "(the free plate's modes, omega^2 = D k^4 / (rho h)) and W(b) = 0",
              "SymPy simplify", lambda: (symbolic_zero(_lap(_lap(W, r), r) - k**4 * W)[0]
                                         and W.subs(r, b) == 0, "residual 0"))
    G_cl = J0 * I1 + J1 * I0
    G_ss = (1 - nu) * (J1 * I0 + J0 * I1) - 2 * X * J0 * I0
    slope = W.diff(r).subs(r, b)
    moment = (W.diff(r, 2) + nu * W.diff(r) / r).subs(r, b)
    ctx.check("plate", "clamped circle: W'(b) = 0 iff J0 I1 + J1 I0 = 0 (x = kb)",
              "SymPy simplify", lambda: symbolic_zero(slope * J0 * I0 / (-k) - G_cl))
    ctx.check("plate", "simply supported circle: the radial moment W'' + nu W'/r = 0 at b iff "
              "(1 - nu)(J1 I0 + J0 I1) - 2 x J0 I0 = 0", "SymPy simplify",
              lambda: symbolic_zero(moment * X * J0 * I0 / k**2 - G_ss))
    # Lommel: an antiderivative of r W^2
    Jr0, Jr1, Ir0, Ir1 = (sp.besselj(0, k * r), sp.besselj(1, k * r), sp.besseli(0, k * r),
                          sp.besseli(1, k * r))
    prim = (r**2 / 2 * (Jr0**2 + Jr1**2) / J0**2 + r**2 / 2 * (Ir0**2 - Ir1**2) / I0**2
            - r / k * (Jr1 * Ir0 + Jr0 * Ir1) / (J0 * I0))
    ctx.check("plate", "Lommel: d/dr [r^2 (J0^2 + J1^2)/(2 J0(x)^2) + r^2 (I0^2 - I1^2)/(2 "
              "I0(x)^2) - r (J1 I0 + J0 I1)/(k J0(x) I0(x))] = r W^2", "SymPy simplify",
              lambda: symbolic_zero(prim.diff(r) - r * W**2))
    tJ, tI = J1 / J0, I1 / I0
    mass = sp.pi * b**2 * (2 + tJ**2 - tI**2 - 2 * (tJ + tI) / X)  # M / (rho h)
    ctx.check("plate", "modal mass M = 2 pi rho h int_0^b r W^2 dr = pi rho h b^2 (2 + t_J^2 - "
              "t_I^2 - 2 (t_J + t_I)/x)", "SymPy simplify (the antiderivative at b and 0)",
              lambda: symbolic_zero(2 * sp.pi * (prim.subs(r, b) - sp.limit(prim, r, 0)) - mass))
    psi = sp.simplify(W.subs(r, 0) ** 2 * b**2 / mass)
    ctx.check("plate", "clamped: the modal mass is 2 pi rho h b^2 (t_J = -t_I at the roots)",
              "SymPy substitution of the frequency equation",
              lambda: symbolic_zero((mass - 2 * sp.pi * b**2).subs(J1, -J0 * I1 / I0)))
    # the printed forms, in x = kb, scaled by e^{-x} (i0e = e^{-x} I0, i1e = e^{-x} I1)
    j0, j1, i0e, i1e = sp.besselj(0, x), sp.besselj(1, x), I0E(x), I1E(x)
    tJx, tIx = j1 / j0, i1e / i0e
    out = {}
    for name, G in (("freq_clamped", G_cl), ("freq_ss", G_ss)):
        Gx = G.subs(k, x / b)
        dG = Gx.diff(x).subs({sp.besselj(2, x): 2 * sp.besselj(1, x) / x - sp.besselj(0, x),
                              sp.besseli(2, x): sp.besseli(0, x) - 2 * sp.besseli(1, x) / x})
        g = sp.collect(sp.expand(_scaled(sp.expand(Gx * sp.exp(-x)), x)), [nu, x])
        out[name] = g
        out[name + "_dx"] = sp.collect(sp.expand(_scaled(sp.expand(dG * sp.exp(-x)), x) - g),
                                       [nu, x])
    out["psi_circle"] = ((1 / j0 - sp.exp(-x) / i0e) ** 2
                         / (sp.pi * (2 + tJx**2 - tIx**2 - 2 * (tJx + tIx) / x)))
    ctx.check("plate", "psi = W(0)^2 rho h b^2 / M = (1/J0 - 1/I0)^2 / (pi (2 + t_J^2 - t_I^2 - "
              "2 (t_J + t_I)/x)), printed with e^{-x}/i0e for 1/I0", "SymPy simplify",
              lambda: symbolic_zero(_unscaled(out["psi_circle"], x) - psi.subs(k, x / b)))
    for name, e in out.items():
        if b in e.free_symbols or e.has(sp.besseli):
            raise ValueError(f"{name} is not in x alone or not scaled: {e}")
    ctx.check("plate", "the scaled forms g = e^{-x} G (i0e = e^{-x} I0, i1e = e^{-x} I1: no "
              "overflow) and their x-derivatives g' = e^{-x} G' - g", "mpmath against the "
              "unscaled G and a central difference, at 30 digits",
              lambda: _check_scaled(out, x, nu))
    ctx.expr.update(out, Omega_circle=x**2, mode_circle=W, mass_circle=mass)
    _orthogonality(ctx, W, k, r, b)
    _circle_static(ctx)


def _mp(expr, x, nu):
    """An mpmath function of (x, nu) from a scaled expression."""
    f = sp.lambdify((x, _Y["nu"]), _unscaled(expr, x), "mpmath")
    return lambda xv, nv=mpmath.mpf("0.3"): f(mpmath.mpf(xv), mpmath.mpf(nv))


def _check_scaled(out, x, nu):
    worst = mpmath.mpf(0)
    with mpmath.workdps(30):
        for xv in ("0.7", "3.3", "21.9", "140.2"):
            X, nv = mpmath.mpf(xv), mpmath.mpf("0.3")
            J0, J1 = mpmath.besselj(0, X), mpmath.besselj(1, X)
            I0, I1 = mpmath.besseli(0, X), mpmath.besseli(1, X)
            G = {"freq_clamped": J0 * I1 + J1 * I0,
                 "freq_ss": (1 - nv) * (J1 * I0 + J0 * I1) - 2 * X * J0 * I0}
            for name, ref in G.items():
                f = _mp(out[name], x, nu)
                worst = max(worst, abs(f(X, nv) - ref * mpmath.exp(-X)) / abs(ref * mpmath.exp(-X)))
                d = _mp(out[name + "_dx"], x, nu)
                num = mpmath.diff(lambda z: f(z, nv), X)
                worst = max(worst, abs(d(X, nv) - num) / abs(num))
    return worst < mpmath.mpf(10) ** -20, f"max rel error {mpmath.nstr(worst, 3)}"


def _mp_roots(support: str, count: int, nu="0.3"):
    """The first roots x_n at 30 digits, by mpmath's findroot in the scaled form."""
    with mpmath.workdps(30):
        nv = mpmath.mpf(nu)
        if support == "clamped":
            f = lambda z: (mpmath.besselj(0, z) * mpmath.besseli(1, z)  # noqa: E731
                           + mpmath.besselj(1, z) * mpmath.besseli(0, z)) * mpmath.exp(-z)
            guesses = [mpmath.pi * (j + 1) for j in range(count)]
        else:
            f = lambda z: ((1 - nv) * (mpmath.besselj(1, z) * mpmath.besseli(0, z)  # noqa: E731
                                       + mpmath.besselj(0, z) * mpmath.besseli(1, z))
                           - 2 * z * mpmath.besselj(0, z) * mpmath.besseli(0, z)) * mpmath.exp(-z)
            guesses = [mpmath.besseljzero(0, j + 1) - (1 - nv) / (2 * mpmath.besseljzero(0, j + 1))
                       for j in range(count)]
        return [mpmath.findroot(f, g) for g in guesses]


def _orthogonality(ctx: Context, W, k, r, b) -> None:
    def run():
        worst = mpmath.mpf(0)
        with mpmath.workdps(30):
            for support in ("clamped", "simply-supported"):
                roots = _mp_roots(support, 4)
                modes = [sp.lambdify(r, W.subs({k: xv, b: 1}), "mpmath") for xv in roots]
                for i in range(4):
                    for j in range(i + 1, 4):
                        ip = mpmath.quad(lambda z: z * modes[i](z) * modes[j](z), [0, 0.5, 1])
                        nn = mpmath.sqrt(mpmath.quad(lambda z: z * modes[i](z) ** 2, [0, 1])
                                         * mpmath.quad(lambda z: z * modes[j](z) ** 2, [0, 1]))
                        worst = max(worst, abs(ip) / nn)
        return worst < 1e-20, f"max |<W_i, W_j>| / (|W_i| |W_j|) = {mpmath.nstr(worst, 3)}"

    ctx.check("plate", "the circle's modes (first 4 roots, both supports) are orthogonal: "
              "int_0^b r W_i W_j dr = 0", "mpmath quad at 30 digits", run)


def _circle_static(ctx: Context) -> None:
    """Timoshenko's central point load: w = A + B r^2 + C r^2 ln(r/b) (regular at 0), the load
    P carried by the shear, 2 pi r D d/dr(nabla^2 w) = P."""
    r, b, nu = _Y["r"], _Y["b"], _Y["nu"]
    A, B, C, P, Dp = sp.symbols("A B C P D", real=True)
    w = A + B * r**2 + C * r**2 * sp.log(r / b)
    shear = sp.solve(sp.Eq(2 * sp.pi * r * Dp * _lap(w, r).diff(r), P), C)[0]
    w = w.subs(C, shear)
    wc = sp.solve([w.subs(r, b), w.diff(r).subs(r, b)], [A, B])
    ws = sp.solve([w.subs(r, b), (w.diff(r, 2) + nu * w.diff(r) / r).subs(r, b)], [A, B])
    S_cl = sp.simplify(wc[A] * Dp / (P * b**2))
    S_ss = sp.simplify(ws[A] * Dp / (P * b**2))
    ctx.check("plate", "static compliance at the centre, S = C_s D / b^2: clamped 1/(16 pi), "
              "simply supported (3 + nu)/(16 pi (1 + nu))", "SymPy solve of the biharmonic "
              "equation with the point load in the shear",
              lambda: (sp.simplify(S_cl - 1 / (16 * sp.pi)) == 0
                       and sp.simplify(S_ss - (3 + nu) / (16 * sp.pi * (1 + nu))) == 0,
                       f"S = {S_cl}, {S_ss}"))
    psi = ctx.expr["psi_circle"]
    x = _Y["x"]

    def modal_sum():
        # sum psi/Omega^2 over the first 40 modes (mpmath roots) plus the asymptotic tail
        # int (x/2) x^-4 dx/pi from the midpoint past the last root: psi ~ x/2, spacing pi
        worst = mpmath.mpf(0)
        with mpmath.workdps(30):
            for support, exact in (("clamped", S_cl), ("simply-supported", S_ss)):
                roots = _mp_roots(support, 40)
                f = _mp(psi, x, _Y["nu"])
                total = mpmath.fsum(f(z) / z**4 for z in roots)
                total += 1 / (4 * mpmath.pi * (roots[-1] + mpmath.pi / 2) ** 2)
                ref = sp.N(exact.subs(nu, sp.Rational(3, 10)), 30)
                worst = max(worst, abs(total / mpmath.mpf(str(ref)) - 1))
        return worst < 1e-6, f"max rel difference {mpmath.nstr(worst, 3)} (40 modes + tail)"

    ctx.check("plate", "the modal sum of psi_n / Omega_n^2 reproduces S (nu = 0.3)",
              "mpmath roots at 30 digits, tail from the asymptotics", modal_sum)
    ctx.expr.update(S_circle_clamped=S_cl, S_circle_ss=S_ss)


# --------------------------------------------------------------------------- the rectangle
def _rectangle(ctx: Context) -> None:
    X, Yc, a, bb, nu = sp.symbols("x_p y_p a b_r", positive=True) + (_Y["nu"],)
    mm, nn = sp.symbols("m_i n_i", integer=True, positive=True)
    s, xi, eta, u, v = _Y["s"], _Y["xi"], _Y["eta"], _Y["u"], _Y["v"]
    phi = sp.sin(mm * sp.pi * X / a) * sp.sin(nn * sp.pi * Yc / bb)
    k2 = sp.pi**2 * (mm**2 / a**2 + nn**2 / bb**2)
    lap = lambda f: f.diff(X, 2) + f.diff(Yc, 2)  # noqa: E731
    bc = [phi.subs(X, 0), phi.subs(X, a), phi.subs(Yc, 0), phi.subs(Yc, bb),
          (phi.diff(X, 2) + nu * phi.diff(Yc, 2)).subs(X, a),
          (phi.diff(Yc, 2) + nu * phi.diff(X, 2)).subs(Yc, bb)]
    ctx.check("plate", "rectangle: Navier's sin(m pi x/a) sin(n pi y/b) solves nabla^4 phi = "
              "k^4 phi, k^2 = pi^2 (m^2/a^2 + n^2/b^2), with w = 0 and zero bending moment on "
              "every edge", "SymPy simplify",
              lambda: (symbolic_zero(lap(lap(phi)) - k2**2 * phi)[0]
                       and all(sp.simplify(e) == 0 for e in bc), "residual 0, edges hold"))
    M = sp.integrate(phi**2, (X, 0, a), (Yc, 0, bb))
    p, q = sp.symbols("p_i q_i", integer=True, positive=True)
    ortho = sp.integrate(sp.sin(mm * sp.pi * X / a) * sp.sin(p * sp.pi * X / a), (X, 0, a))
    ctx.check("plate", "Navier modes: int phi^2 = a b / 4 (M = rho h a b/4), and sin(m pi x/a) "
              "is orthogonal to sin(p pi x/a) for integers m != p", "SymPy integrate",
              lambda: (sp.simplify(M - a * bb / 4) == 0
                       and sp.simplify(ortho.subs({mm: 2, p: 5})) == 0
                       and sp.simplify(ortho.subs({mm: 3, p: 3}) - a / 2) == 0, f"{M}, {ortho}"))
    L2 = a * bb
    Omega = sp.simplify(k2 * L2)  # omega L^2 sqrt(mu/D) = k^2 L^2
    Omega_s = sp.pi**2 * (_Y["m"] ** 2 / s + _Y["n"] ** 2 * s)
    ctx.check("plate", "Omega = omega a b sqrt(rho h/D) = pi^2 (m^2 b/a + n^2 a/b) = "
              "pi^2 (m^2/s + n^2 s), s = a/b; psi = phi^2 rho h a b / M = 4 sin^2 sin^2",
              "SymPy substitution",
              lambda: (sp.simplify(Omega.subs({a: s * bb}) - Omega_s.subs({_Y["m"]: mm, _Y["n"]: nn})) == 0
                       and sp.simplify(phi**2 * L2 / M - 4 * phi**2) == 0, f"Omega = {Omega}"))
    psi_rect = 4 * sp.sin(sp.pi * u) ** 2 * sp.sin(sp.pi * v) ** 2
    ctx.expr.update(Omega_rect=Omega_s.subs({_Y["n"]: _Y["k"]}), psi_rect=psi_rect)
    _rect_static(ctx)


def _rect_static(ctx: Context) -> None:
    r"""S = sum_{m,n} psi/Omega^2; the inner sum over n in closed form from
    sum_n cos(n t)/(n^2 + c^2) = pi cosh(c (pi - t))/(2 c sinh(pi c)) - 1/(2 c^2) (0 <= t <= 2pi),
    differentiated in c."""
    s, xi, eta, c, cl3, mv = (_Y[n] for n in ("s", "xi", "eta", "c", "cl3", "m"))
    t, nn = sp.symbols("t n_i", positive=True)
    A = sp.pi * sp.cosh(c * (sp.pi - t)) / (2 * c * sp.sinh(sp.pi * c)) - 1 / (2 * c**2)

    def fourier():
        # A'' - c^2 A = 1/2 on (0, 2 pi), A'(0+) = -pi/2, A'(2 pi-) = pi/2, A even about pi: the
        # periodic A'' = c^2 A + 1/2 - pi delta, delta = (1 + 2 sum cos(n t))/(2 pi), whose
        # cosine coefficients are a_n = 1/(n^2 + c^2), a_0 = 0
        ode = sp.simplify(A.diff(t, 2) - c**2 * A - sp.Rational(1, 2))
        d0 = sp.simplify(A.diff(t).subs(t, 0) + sp.pi / 2)
        d2 = sp.simplify(A.diff(t).subs(t, 2 * sp.pi) - sp.pi / 2)
        even = sp.simplify(A.subs(t, 2 * sp.pi - t) - A)
        return ode == 0 and d0 == 0 and d2 == 0 and even == 0, f"residuals {ode}, {d0}, {d2}, {even}"

    ctx.check("plate", "sum_n cos(n t)/(n^2 + c^2) = pi cosh(c (pi - t))/(2 c sinh(pi c)) - "
              "1/(2 c^2) on [0, 2 pi]", "SymPy: the periodic ODE it solves", fourier)
    # inner sum: sum_n sin^2(n pi eta)/(n^2 + c^2)^2 = (1/(4c)) d/dc [A(2 pi eta) - A(0)]
    f = sp.simplify(A.subs(t, 2 * sp.pi * eta) - A.subs(t, 0))
    E = lambda z: sp.exp(-2 * sp.pi * c * z)  # noqa: E731
    g = sp.pi / (2 * c) * (E(eta) + E(1 - eta) - 2 * E(1)) / (1 - E(1))
    ctx.check("plate", "A(2 pi eta) - A(0) = -pi/(2c) + g(c), g = pi/(2c) (E_eta + E_{1-eta} - "
              "2 E_1)/(1 - E_1), E_z = exp(-2 pi c z): exponentially small", "SymPy (exp form)",
              lambda: symbolic_zero(sp.simplify((f + sp.pi / (2 * c) - g).rewrite(sp.exp))))
    inner = (sp.pi / (2 * c**2) + g.diff(c)) / (4 * c)
    # psi/Omega^2 = 4 sin^2 sin^2 / (pi^4 s^2 (n^2 + c^2)^2), c = m/s: the n-sum is `inner`
    term = sp.sin(sp.pi * mv * xi) ** 2 / (sp.pi**4 * s**2 * c) * g.diff(c)
    term = term.subs(c, mv / s)
    alg = s * (sp.zeta(3) - cl3) / (4 * sp.pi**3)

    def series():
        worst = mpmath.mpf(0)
        with mpmath.workdps(20):
            for sv, xv, ev in (("1", "0.5", "0.5"), ("2", "0.3", "0.6"), ("0.7", "0.21", "0.4")):
                sv, xv, ev = mpmath.mpf(sv), mpmath.mpf(xv), mpmath.mpf(ev)
                fin = sp.lambdify((c, eta), inner, "mpmath")
                nv = np.arange(1, 200_001, dtype=float)
                for m in (1, 2, 5):  # the closed inner sum against the sum over n (numpy)
                    cc = float(m / sv)
                    ref = math.fsum(np.sin(nv * np.pi * float(ev)) ** 2 / (nv**2 + cc**2) ** 2)
                    worst = max(worst, abs(fin(cc, ev) / ref - 1))
                ft = sp.lambdify((mv, s, xi, eta), term, "mpmath")
                fa = sp.lambdify((s, cl3), alg, "mpmath")
                cl = mpmath.re(mpmath.polylog(3, mpmath.expjpi(2 * xv)))
                S = fa(sv, cl) + mpmath.nsum(lambda m: ft(m, sv, xv, ev), [1, mpmath.inf])
                # the double sum by brute force: psi/Omega^2 over m, n < 400 plus tail, 1e-5
                tot = mpmath.fsum(4 * mpmath.sin(m * mpmath.pi * xv) ** 2
                                  * mpmath.sin(n * mpmath.pi * ev) ** 2
                                  / (mpmath.pi**2 * (m**2 / sv + n**2 * sv)) ** 2
                                  for m in range(1, 200) for n in range(1, 200))
                worst2 = abs(tot / S - 1)
                if worst2 > 2e-3:
                    return False, f"S = {S} vs double sum {tot} at s = {sv}"
            S_sq = fa(1, mpmath.re(mpmath.polylog(3, -1))) + mpmath.nsum(
                lambda m: ft(m, 1, mpmath.mpf("0.5"), mpmath.mpf("0.5")), [1, mpmath.inf])
        ok = worst < 1e-12 and abs(S_sq - mpmath.mpf("0.01160")) < 5e-6
        return ok, (f"inner sum max rel error {mpmath.nstr(worst, 3)}; square, centre: S = "
                    f"{mpmath.nstr(S_sq, 6)} (Timoshenko: 0.01160)")

    ctx.check("plate", "rectangle: S = s (zeta(3) - Cl_3(2 pi xi))/(4 pi^3) + sum_m sin^2(m pi "
              "xi) g'(m/s)/(pi^4 s^2 (m/s)) (the algebraic 1/m^3 part summed in closed form)",
              "the inner sum term by term, the double sum, Timoshenko's 0.01160", series)
    ctx.expr.update(S_rect_algebraic=alg, S_rect_term=term)


# --------------------------------------------------------------- the dimensionless problem
def _dimensionless(ctx: Context) -> None:
    D, mu, m, t0, L, lam, beta = (_Y[n] for n in ("D", "mu", "msph", "t0", "L", "lam", "beta"))
    Om, psi, Sx, phi2, M = sp.symbols("Omega psi S phi2 M", positive=True)
    omega_SI = Om * sp.sqrt(D / mu) / L**2
    c_n = m * phi2 / M
    lam_d = ctx.expr["lam_plate"]
    beta_d = ctx.expr["beta_plate"]
    Cs = Sx * L**2 / D
    ctx.check("plate", "Zener's scales: omega_n t0 = beta Omega_n, c_n = m phi_n^2/M_n = 8 lambda "
              "beta psi_n (psi = phi^2 rho h L^2/M), C_s m/t0^2 = 8 lambda S/beta (S = C_s D/L^2)",
              "SymPy simplify",
              lambda: (sp.simplify(omega_SI * t0 - beta_d * Om) == 0
                       and sp.simplify(c_n.subs(phi2, psi * M / (mu * L**2))
                                       - 8 * lam_d * beta_d * psi) == 0
                       and sp.simplify(m * Cs / t0**2 - 8 * lam_d * Sx / beta_d) == 0, "equal"))
    x, n = _Y["x"], _Y["n"]
    # large-x Bessel forms: J0 ~ sqrt(2/(pi x)) cos(x - pi/4), J1 ~ sqrt(2/(pi x)) sin(x - pi/4),
    # I1/I0 -> 1, e^{-x}/I0 -> 0: psi at the asymptotic roots
    amp = sp.sqrt(2 / (sp.pi * x))

    def density():
        ni = sp.Symbol("n_i", integer=True, positive=True)
        tJ = sp.tan(x - sp.pi / 4)
        psi_asym = (1 / (amp * sp.cos(x - sp.pi / 4))) ** 2 / (sp.pi * (1 + tJ**2 - 2 * (tJ + 1) / x))
        # clamped: t_J = -t_I -> -1 at x_n ~ n pi; simply supported: t_J -> oo at J0's zeros
        clamped = sp.simplify(sp.limit(psi_asym.subs(x, ni * sp.pi) / (ni * sp.pi), ni, sp.oo))
        ss = sp.limit(psi_asym / x, x, sp.Rational(3, 4) * sp.pi + 2 * sp.pi * ni)
        ss = sp.simplify(sp.limit(ss, ni, sp.oo))
        rect_mean = sp.integrate(4 * sp.sin(sp.pi * _Y["u"]) ** 2 * sp.sin(sp.pi * _Y["v"]) ** 2,
                                 (_Y["u"], 0, 1), (_Y["v"], 0, 1))
        Xs = sp.Symbol("X", positive=True)  # quarter ellipse m^2/s + n^2 s <= X/pi^2
        count = sp.pi / 4 * (sp.sqrt(Xs * _Y["s"]) / sp.pi) * (sp.sqrt(Xs / _Y["s"]) / sp.pi)
        ok = (clamped == sp.Rational(1, 2) and ss == sp.Rational(1, 2) and rect_mean == 1
              and sp.simplify(count.diff(Xs) - 1 / (4 * sp.pi)) == 0)
        return ok, (f"circle psi_n/x_n -> {clamped} (clamped), {ss} (simply supported), roots "
                    f"pi apart: psi dN/dOmega = (x/2)/(2 pi x) = 1/(4 pi); rectangle: mean "
                    f"psi = {rect_mean}, dN/dOmega = {sp.simplify(count.diff(Xs))}")

    ctx.check("10", "every plate has the participation density psi dN/dOmega -> 1/(4 pi) at "
              "high Omega (circle: psi_n ~ x_n/2, x_{n+1} - x_n -> pi; rectangle: mean psi 1, "
              "N(Omega) ~ Omega/(4 pi))", "SymPy with the Bessel asymptotics", density)
    p, Om_v = sp.symbols("p Omega_v", positive=True)
    Y = sp.integrate(8 * lam * beta / (4 * sp.pi) * p / (p**2 + beta**2 * Om_v**2), (Om_v, 0, sp.oo))
    ctx.check("10", "as beta -> 0 the admittance sum_n c_n p/(p^2 + omega_n^2) (the Laplace "
              "transform of the kernel sum c_n cos(omega_n tau)) becomes 8 lambda beta int "
              "p/(p^2 + beta^2 Omega^2) dOmega/(4 pi) = lambda for every p: the kernel is "
              "lambda delta(tau), Zener's dashpot w' = lambda F", "SymPy integrate",
              lambda: (sp.simplify(Y - lam) == 0, f"Y = {sp.simplify(Y)}"))
    tau = sp.Symbol("tau", positive=True)
    xs, F = sp.Function("x"), sp.Function("F")
    w = sp.Function("w")
    delta = xs(tau) - w(tau)
    eq = delta.diff(tau, 2).subs({xs(tau).diff(tau, 2): -F(tau), w(tau).diff(tau, 2):
                                  lam * F(tau).diff(tau)})
    ctx.check("10", "with x'' = -F and w' = lambda F, delta = x - w obeys delta'' + F + lambda "
              "F' = 0 (F = delta^{3/2}): Zener's Eq. (10)", "SymPy substitution",
              lambda: (sp.simplify(eq + F(tau) + lam * F(tau).diff(tau)) == 0, f"{eq}"))

    def numeric():
        # the rectangle's exact modes at beta = 1e-3 (no root finding): Y(1) -> lambda
        bv, lv = 1e-3, 1.3
        mi, ni = np.meshgrid(np.arange(1, 3001.0), np.arange(1, 3001.0), indexing="ij")
        Omv = np.pi**2 * (mi**2 + ni**2)
        ps = 4 * np.sin(mi * np.pi * 0.31) ** 2 * np.sin(ni * np.pi * 0.42) ** 2
        inside = Omv < np.pi**2 * 3000**2
        tot = math.fsum((8 * lv * bv * ps / (1 + (bv * Omv) ** 2))[inside])
        rel = abs(tot / lv - 1)
        return rel < 0.01, f"Y(1)/lambda - 1 = {rel:.2g} (square, beta = 1e-3)"

    ctx.check("10", "numerically: Y(1) of a square struck at (0.31, 0.42) at beta = 1e-3 is "
              "lambda within 1 %", "numpy sum over the Navier modes", numeric)


def derive(ctx: Context | None = None) -> Context:
    """Run the plate derivation (checked unless ``ctx.checks`` is False).

    Adds to ``ctx.expr``: ``alpha_plate``, ``lam_plate``, ``beta_plate`` (the physical
    definitions), the circle's ``freq_clamped``, ``freq_clamped_dx``, ``freq_ss``,
    ``freq_ss_dx``, ``Omega_circle``, ``psi_circle``, ``mode_circle``, ``mass_circle``,
    ``S_circle_clamped``, ``S_circle_ss``, and the rectangle's ``Omega_rect``, ``psi_rect``,
    ``S_rect_algebraic``, ``S_rect_term``.
    """
    ctx = Context() if ctx is None else ctx
    ctx.symbols.update(SYMBOLS)
    _infinite_plate(ctx)
    _circle(ctx)
    _rectangle(ctx)
    _dimensionless(ctx)
    return ctx


@functools.cache
def expressions() -> dict:
    """The printed formulas (unchecked run, cached): name -> SymPy expression."""
    return dict(derive(Context(checks=False)).expr)


if __name__ == "__main__":  # pragma: no cover
    import sys

    sys.exit(run_script(derive))
