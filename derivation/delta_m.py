"""Maximum compression delta_m and the coefficient k of L, Eqs. (17)-(25).

(17) is Eq. (10) with y = delta' as a function of delta. Its two asymptotes are solved with
``dsolve``: lambda -> infinity (18)-(20) gives delta_m^{-3/2} = lambda, lambda -> 0 (21)-(23)
gives delta_m = (5/4)^{2/5}. The interpolation (24) adds them in the variable delta_m^{-3/2}:

    delta_m^{-3/2} = lambda + (5/4)^{-3/5}          (the printed -3/2 exponent is wrong)

and k = sqrt(delta_m) = (lambda + (5/4)^{-3/5})^{-1/3} (25). How far (24) is from the exact
delta_m is a numeric claim of the paper: the audit measures it against the exact solution (the
derivation imports nothing of the runtime package).
"""
from __future__ import annotations

import sympy as sp

from .steps import Context, symbolic_zero

__all__ = ["derive"]

def derive(ctx: Context) -> dict:
    """Derive (17)-(25); adds ``dm_of_lam`` and ``k_of_lam`` to ``ctx.expr``. The accuracy of
    the interpolation (24) is a claim of the paper, measured by the audit (claim eq24_5pct)."""
    lam = ctx.symbols["lam"]
    d = sp.Symbol("delta", positive=True)
    y = sp.Function("y")
    yd = y(d)

    # (17): with y(delta) = delta', delta'' = y dy/ddelta and (delta^{3/2})' = (3/2) sqrt(delta) y.
    tau = ctx.symbols["tau"]
    D = sp.Function("delta")(tau)
    Y = sp.Symbol("Y")
    zener = D.diff(tau, 2) + D ** sp.Rational(3, 2) + lam * (D ** sp.Rational(3, 2)).diff(tau)
    eq17 = yd * yd.diff(d) + sp.Rational(3, 2) * lam * sp.sqrt(d) * yd + d ** sp.Rational(3, 2)
    zener_y = zener.subs(D.diff(tau, 2), Y * sp.Symbol("Yp")).subs(D.diff(tau), Y).subs(D, d)
    ctx.check("17", "Eq. (10) with delta' = y(delta) is y y' + (3/2) lambda sqrt(delta) y + delta^(3/2) = 0",
              "chain rule substitution, SymPy",
              lambda: symbolic_zero(zener_y - eq17.subs(yd.diff(d), sp.Symbol("Yp")).subs(yd, Y)))

    # (18)-(20): lambda -> oo, divide (17) by y and keep the lambda term.
    sol19 = sp.dsolve(sp.Eq(yd.diff(d) + sp.Rational(3, 2) * lam * sp.sqrt(d), 0), yd, ics={y(0): 1}).rhs
    ctx.check("19", "y = 1 - lambda delta^(3/2) solves (18) with y(0) = 1", "SymPy dsolve",
              lambda: symbolic_zero(sol19 - (1 - lam * d ** sp.Rational(3, 2))))
    lam_pos = sp.Symbol("lambda_p", positive=True)
    dm_inf = sp.solve(sol19.subs(lam, lam_pos), d)
    ctx.check("20", "root of (19): delta_m^(-3/2) = lambda", "SymPy solve",
              lambda: (len(dm_inf) == 1 and sp.simplify(dm_inf[0] ** sp.Rational(-3, 2) - lam_pos) == 0,
                       f"roots {dm_inf}"))

    # (21)-(23): lambda -> 0; solve for y^2 to stay on the branch y(0) = +1.
    w = sp.Function("w")  # w = y^2, so y y' = w'/2
    sol22 = sp.dsolve(sp.Eq(w(d).diff(d) / 2 + d ** sp.Rational(3, 2), 0), w(d), ics={w(0): 1}).rhs
    ctx.check("22", "y = sqrt(1 - (4/5) delta^(5/2)) solves (21) with y(0) = 1", "SymPy dsolve for y^2",
              lambda: symbolic_zero(sol22 - (1 - sp.Rational(4, 5) * d ** sp.Rational(5, 2))))
    dm0 = [r for r in sp.solve(sol22, d) if r.is_positive]  # delta is positive during contact
    ctx.check("23", "root of (22): delta_m = (5/4)^(2/5)", "SymPy solve",
              lambda: (len(dm0) == 1 and sp.nsimplify(dm0[0] - sp.Rational(5, 4) ** sp.Rational(2, 5)) == 0,
                       f"roots {dm0}"))

    # (24)-(25): sum of the asymptotes in the variable delta_m^{-3/2}.
    c = (sp.Rational(5, 4) ** sp.Rational(2, 5)) ** sp.Rational(-3, 2)
    dm_of_lam = (lam + c) ** sp.Rational(-2, 3)
    k_of_lam = sp.sqrt(dm_of_lam)
    ctx.check("24", "interpolation reproduces both asymptotes: exact at lambda = 0, "
              "delta_m^(-3/2)/lambda -> 1 as lambda -> oo", "SymPy limit",
              lambda: (sp.simplify(dm_of_lam.subs(lam, 0) - dm0[0]) == 0
                       and sp.limit(dm_of_lam ** sp.Rational(-3, 2) / lam, lam, sp.oo) == 1,
                       f"(5/4)^(-3/5) = {sp.N(c, 12)}"))
    ctx.check("25", "k = sqrt(delta_m) = (lambda + (5/4)^(-3/5))^(-1/3)", "SymPy powsimp",
              lambda: symbolic_zero(k_of_lam - (lam + sp.Rational(5, 4) ** sp.Rational(-3, 5)) ** sp.Rational(-1, 3)))

    ctx.expr.update(dm_of_lam=dm_of_lam, k_of_lam=k_of_lam)
    dm = sp.Symbol(r"\bar\delta_m")
    ctx.eq("17", sp.Symbol(r"y\,\frac{dy}{d\bar\delta}"),
           sp.Symbol(r"-\tfrac{3}{2}\lambda\sqrt{\bar\delta}\,y - \bar\delta^{3/2}"), "Eq. (10) with y = delta'")
    ctx.eq("18", sp.Symbol(r"\frac{dy}{d\bar\delta} + \tfrac{3}{2}\lambda\sqrt{\bar\delta}"), 0,
           "(17) divided by y, lambda -> oo")
    ctx.eq("19", sp.Symbol("y"), sol19, "asymptote lambda -> oo")
    ctx.eq("21", sp.Symbol(r"y\,\frac{dy}{d\bar\delta} + \bar\delta^{3/2}"), 0, "(17) with lambda -> 0")
    ctx.eq("20", dm ** sp.Rational(-3, 2), lam, "lambda -> oo")
    ctx.eq("22", sp.Symbol("y"), sp.sqrt(sol22), "asymptote lambda -> 0")
    ctx.eq("23", dm, dm0[0], "lambda -> 0")
    ctx.eq("24", dm ** sp.Rational(-3, 2), lam + c, "interpolation of the asymptotes")
    ctx.eq("25", ctx.symbols["k"], k_of_lam, "coefficient of L")
    return {"dm_of_lam", "k_of_lam"}

