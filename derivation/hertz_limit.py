"""The lambda = 0 (Hertz) specialisation (49)-(51) and the Hunter and Reed pulses (52)-(53).

At lambda = 0: k = (5/4)^{1/5}, beta = 0, omega0 = sqrt(k) = (5/4)^{1/10} (about 1.0226), and
delta1 of (42) reduces to elementary terms plus one 2F1(-1/2, -1/4; 3/4; exp(2 i omega0 tau)).

Hunter's displacement (4), delta = delta_m sin(1.068 V0 t / delta_m), and Reed's force (6) are
made dimensionless with the scales of :mod:`.scaling` (delta = T V0 delta-bar, t = T tau,
F = (m V0 / T) F-bar) and Hertz's delta_m = T V0 (5/4)^{2/5} (3):

    F_hunter = (1.068^2 / dm) sin(1.068 tau / dm),   F_reed = dm^{3/2} sin^{3/2}(1.068 tau / dm),

dm = (5/4)^{2/5}: 1.0432 sin(0.97680 tau) and 1.1433 sin^{3/2}(0.97680 tau) (the printed (53)
has sin^3). The force is taken positive in compression, as F-bar = delta-bar^{3/2} (45).
"""
from __future__ import annotations

import mpmath
import sympy as sp

from .steps import MP_DPS, Context, symbolic_zero

__all__ = ["derive", "HUNTER_CONSTANT"]

#: Hunter's constant of (4), an input of his sine fit (not derived here).
HUNTER_CONSTANT = sp.Rational(1068, 1000)


def derive(ctx: Context) -> dict:
    """Derive (49)-(53); adds ``omega0_lam0``, ``delta0_lam0``, ``delta1_lam0``, ``F_hunter``,
    ``F_reed`` (and ``F0_lam0``) to ``ctx.expr``."""
    S, P = ctx.symbols, ctx.symbols
    lam, tau, beta, w = S["lam"], S["tau"], S["beta"], S["omega0"]
    E = ctx.expr

    omega0_lam0 = sp.simplify(E["omega0_of_lam"].subs(lam, 0))
    ctx.check("49", "at lambda = 0: beta = 0, omega0 = (5/4)^(1/10) = 1.0226", "SymPy substitution",
              lambda: (E["beta_of_lam"].subs(lam, 0) == 0
                       and sp.simplify(omega0_lam0 - sp.Rational(5, 4) ** sp.Rational(1, 10)) == 0,
                       f"omega0 = {omega0_lam0} = {sp.N(omega0_lam0, 8)}"))
    sub0 = {lam: 0, beta: 0}
    delta0_lam0 = E["delta0"].subs(sub0)
    # collect to the paper's shape sin/(2 omega0) + (...) sin + (...) cos, using cos^2 = 1 - sin^2
    s, c = sp.sin(w * tau), sp.cos(w * tau)
    d1 = sp.expand(sp.expand(sp.expand_trig(sp.simplify(E["delta1"].subs(sub0)))).subs(c**2, 1 - s**2))
    delta1_lam0 = sp.collect(sp.powsimp(d1), c)

    def same_as_general():
        f = sp.lambdify((w, tau), delta1_lam0, "mpmath")
        g = sp.lambdify((lam, beta, w, tau), E["delta1"], "mpmath")
        ff = sp.lambdify((w, tau), E["forcing"].subs(sub0), "mpmath")
        L1 = sp.lambdify((w, tau), delta1_lam0.diff(tau, 2) + w**2 * delta1_lam0, "mpmath")
        worst, res = mpmath.mpf(0), mpmath.mpf(0)
        with mpmath.workdps(MP_DPS):
            wv = mpmath.power(mpmath.mpf(5) / 4, mpmath.mpf(1) / 10)
            for j in range(10):
                t = mpmath.pi * (j + mpmath.mpf(1) / 2) / 10 / wv
                worst = max(worst, abs(f(wv, t) - g(0, 0, wv, t)))
                res = max(res, abs(L1(wv, t) - ff(wv, t)) / abs(ff(wv, t)))
        return worst < 1e-30 and res < 1e-25, (f"|delta1_lam0 - delta1(lambda=0)| <= {mpmath.nstr(worst, 3)}, "
                                               f"ODE rel residual {mpmath.nstr(res, 3)}")

    ctx.check("49", "delta1 at lambda = 0 (simplified) equals the general delta1 there and solves "
              "delta1'' + omega0^2 delta1 = omega0 sin - omega0^(-3/2) sin^(3/2)",
              f"mpmath at {MP_DPS} digits, 10 points", same_as_general)
    d0 = delta0_lam0.subs(w, omega0_lam0)
    F0 = d0 ** sp.Rational(3, 2)
    ctx.check("50", "zeroth-order force at lambda = 0: (sin(omega0 tau)/omega0)^(3/2) = 0.96708 sin^(3/2)(1.0226 tau) "
              "(the printed exponent 3/5 is wrong)", "SymPy",
              lambda: (sp.simplify(F0 - omega0_lam0 ** sp.Rational(-3, 2) * sp.sin(omega0_lam0 * tau) ** sp.Rational(3, 2)) == 0,
                       f"omega0^(-3/2) = {sp.N(omega0_lam0 ** sp.Rational(-3, 2), 6)}"))

    # (52)-(53) from (3)-(6).
    T, V0, m, Es, R, t = (ctx.expr["T"], P["V0"], P["m"], P["Estar"], P["R"], P["t"])
    dm_phys = ctx.expr["dm_hertz_phys"]
    F_scale = ctx.expr["F_scale"]
    c = HUNTER_CONSTANT
    delta_hunter = dm_phys * sp.sin(c * V0 / dm_phys * t)
    F_h_phys = -m * delta_hunter.diff(t, 2)  # Newton (5); compressive force counted positive
    F_hunter = sp.simplify(sp.powsimp((F_h_phys / F_scale).subs(t, T * tau), force=True))
    F_r_phys = sp.Rational(4, 3) * sp.sqrt(R) * Es * dm_phys ** sp.Rational(3, 2) * sp.sin(c * V0 / dm_phys * t) ** sp.Rational(3, 2)
    F_reed = sp.simplify(sp.powsimp((F_r_phys / F_scale).subs(t, T * tau), force=True))
    dm = sp.Rational(5, 4) ** sp.Rational(2, 5)
    want_h = c**2 / dm * sp.sin(c / dm * tau)
    want_r = dm ** sp.Rational(3, 2) * sp.sin(c / dm * tau) ** sp.Rational(3, 2)
    ctx.check("52", "F_hunter = (1.068^2/dm) sin(1.068 tau/dm), dm = (5/4)^(2/5): 1.0432 sin(0.97680 tau)",
              "SymPy from (3)-(5) and the scales", lambda: (
                  not F_hunter.free_symbols - {tau} and symbolic_zero(F_hunter - want_h)[0],
                  f"{sp.N(c**2 / dm, 6)} sin({sp.N(c / dm, 6)} tau)"))
    ctx.check("53", "F_reed = dm^(3/2) sin^(3/2)(1.068 tau/dm): 1.1433 sin^(3/2)(0.97680 tau) "
              "(the printed sin^3 is wrong)", "SymPy from (3), (6) and the scales", lambda: (
                  not F_reed.free_symbols - {tau} and symbolic_zero(F_reed - want_r)[0],
                  f"{sp.N(dm ** sp.Rational(3, 2), 6)} sin^(3/2)({sp.N(c / dm, 6)} tau)"))

    ctx.expr.update(omega0_lam0=omega0_lam0, delta0_lam0=delta0_lam0, delta1_lam0=delta1_lam0,
                    F0_lam0=F0, F_hunter=want_h, F_reed=want_r)
    ctx.eq("49a", w, omega0_lam0, "omega0 at lambda = 0")
    ctx.eq("49b", sp.Symbol(r"\bar\delta_0"), delta0_lam0, "zeroth order at lambda = 0")
    ctx.eq("49c", sp.Symbol(r"\bar\delta_1"), delta1_lam0, "first-order correction at lambda = 0")
    ctx.eq("50", sp.Symbol(r"\bar F"), F0, "zeroth-order force at lambda = 0")
    ctx.eq("51", sp.Symbol(r"\bar F"), (delta0_lam0 + sp.Symbol(r"\bar\delta_1")) ** sp.Rational(3, 2),
           "first-order force at lambda = 0, with delta1 of (49c)")
    ctx.eq("52", sp.Symbol(r"\bar F_{Hunter}"), want_h, "Hunter's pulse (4)-(5) made dimensionless")
    ctx.eq("53", sp.Symbol(r"\bar F_{Reed}"), want_r, "Reed's pulse (6) made dimensionless")
    return set(ctx.expr)

