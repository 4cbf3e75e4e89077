"""Zeroth-order solution, Eqs. (32)-(35) and (54)-(61), (78)-(81).

The characteristic equation of (28), x^2 + k lambda x + k = 0, has the roots -beta +- i omega0
with beta = k lambda / 2 (32) and omega0 = sqrt(4k - k^2 lambda^2)/2 (33); delta0 (35) comes from
``dsolve`` with (29). Contact ends at tau_d0 = pi/omega0 (54); compression ends where delta0' = 0,
tau_dc0 = (pi/2 - atan(beta/omega0))/omega0 (58; equal to atan(omega0/beta)/omega0 for beta > 0
and also right at beta = 0); eta0 = tau_dr0/tau_dc0 (61); e0 = -delta0'(tau_d0) =
exp(-pi beta/omega0) (79). The validity bound (81), omega0 real, is lambda < lam_crit where
lambda^6 = 64 (lambda + (5/4)^{-3/5}), solved numerically at 50 digits.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from .steps import Context, symbolic_zero

__all__ = ["derive"]


def derive(ctx: Context) -> dict:
    """Derive (32)-(35), (54)-(61), (78)-(81); see the module docstring for the names added."""
    S = ctx.symbols
    lam, tau, k, beta, w = S["lam"], S["tau"], S["k"], S["beta"], S["omega0"]
    k_of_lam = ctx.expr["k_of_lam"]

    x = sp.Symbol("x")
    char = x**2 + k * lam * x + k
    roots = sp.solve(char, x)
    beta_k = k * lam / 2
    omega_k = sp.sqrt(4 * k - k**2 * lam**2) / 2
    ctx.check("32-33", "roots of x^2 + k lambda x + k are -beta +- i omega0, beta = k lambda/2, "
              "omega0 = sqrt(4k - k^2 lambda^2)/2", "SymPy solve",
              lambda: (len(roots) == 2 and all(
                  sp.expand(char.subs(x, -beta_k + sg * sp.I * omega_k)) == 0 for sg in (1, -1)),
                  "both -beta +- i omega0 are roots of the quadratic"))
    beta_of_lam = beta_k.subs(k, k_of_lam)
    omega0_of_lam = omega_k.subs(k, k_of_lam)

    # lam_crit: omega0 = 0  <=>  lambda^2 = 4/k  <=>  lambda^6 = 64 (lambda + (5/4)^{-3/5}).
    c = sp.Rational(5, 4) ** sp.Rational(-3, 5)
    lam_crit_eq = sp.Eq(lam**6, 64 * (lam + c))
    with mpmath.workdps(60):
        root = sp.nsolve(lam_crit_eq.lhs - lam_crit_eq.rhs, lam, 2.4, prec=50)
    lam_crit = sp.Float(root, 50)
    def crit_check():
        same = sp.simplify((4 * k - k**2 * lam**2).subs(k, k_of_lam) * (lam + c) ** sp.Rational(2, 3)
                           - (4 * (lam + c) ** sp.Rational(1, 3) - lam**2)) == 0
        zero = abs(sp.N(omega0_of_lam.subs(lam, lam_crit), 40)) < 1e-20
        poly = sp.Poly(lam_crit_eq.lhs - lam_crit_eq.rhs, lam)
        pos = [r for r in poly.nroots(n=30) if r.is_real and r > 0]
        return same and zero and len(pos) == 1, (f"lam_crit = {sp.N(lam_crit, 20)} (paper: 2.442); "
                                                 f"positive real roots: {len(pos)}")

    ctx.check("81", "omega0(lambda) = 0 exactly where lambda^6 = 64 (lambda + (5/4)^(-3/5)); "
              "one positive root", "SymPy simplify of 4k - k^2 lambda^2, nroots at 30 digits",
              crit_check)

    # (34)-(35) by dsolve with the initial conditions (29).
    f = sp.Function("f")
    ode = f(tau).diff(tau, 2) + 2 * beta * f(tau).diff(tau) + (beta**2 + w**2) * f(tau)
    delta0 = sp.dsolve(ode, f(tau), ics={f(0): 0, f(tau).diff(tau).subs(tau, 0): 1}).rhs
    delta0 = sp.simplify(delta0)
    want35 = sp.exp(-beta * tau) * sp.sin(w * tau) / w
    ctx.check("35", "delta0 = exp(-beta tau) sin(omega0 tau)/omega0", "SymPy dsolve with (29) "
              "(k = beta^2 + omega0^2, k lambda = 2 beta)",
              lambda: symbolic_zero(delta0 - want35, rewrite_trig=True))
    ctx.check("28", "delta0 solves (28) with k, lambda from beta, omega0", "SymPy substitution",
              lambda: symbolic_zero((want35.diff(tau, 2) + k * lam * want35.diff(tau) + k * want35)
                                    .subs(lam, 2 * beta / k).subs(k, beta**2 + w**2)))
    delta0 = want35
    delta0_dot = delta0.diff(tau)
    ctx.check("56", "delta0' = exp(-beta tau)(cos(omega0 tau) - beta/omega0 sin(omega0 tau))",
              "SymPy diff", lambda: symbolic_zero(
                  delta0_dot - sp.exp(-beta * tau) * (sp.cos(w * tau) - beta / w * sp.sin(w * tau))))

    tau_d0 = sp.pi / w
    tau_dc0 = (sp.pi / 2 - sp.atan(beta / w)) / w
    tau_dr0 = tau_d0 - tau_dc0
    eta0 = sp.simplify(tau_dr0 / tau_dc0)
    e0 = sp.simplify(-delta0_dot.subs(tau, tau_d0))
    ctx.check("54", "delta0(pi/omega0) = 0 (first zero after 0: exp > 0, sin > 0 on (0, pi))", "SymPy substitution", lambda: (delta0.subs(tau, tau_d0) == 0, "delta0(tau_d0) = 0"))
    ctx.check("57-58", "delta0'(tau_dc0) = 0 with tau_dc0 in (0, pi/(2 omega0)]", "SymPy substitution",
              lambda: symbolic_zero(sp.expand_trig(delta0_dot.subs(tau, tau_dc0))))
    ctx.check("79", "e0 = -delta0'(tau_d0) = exp(-pi beta/omega0)", "SymPy substitution",
              lambda: symbolic_zero(e0 - sp.exp(-sp.pi * beta / w)))
    ctx.check("61", "eta0 = pi/(pi/2 - atan(beta/omega0)) - 1 = pi/atan(omega0/beta) - 1", "SymPy",
              lambda: symbolic_zero(eta0 - (sp.pi / (sp.pi / 2 - sp.atan(beta / w)) - 1)))

    sub = {beta: beta_of_lam, w: omega0_of_lam}
    of_lam = {n: sp.simplify(e.subs(sub)) for n, e in
              (("tau_d0", tau_d0), ("tau_dc0", tau_dc0), ("tau_dr0", tau_dr0), ("eta0", eta0), ("e0", e0))}
    # (80): beta/omega0 = lambda/sqrt(4/k - lambda^2) and 1/k = (lambda + c)^{1/3}.
    e80 = sp.exp(-sp.pi * lam / sp.sqrt(4 * (lam + c) ** sp.Rational(1, 3) - lam**2))
    ctx.check("80", "e0(lambda) = exp(-pi lambda / sqrt(4 (lambda + (5/4)^(-3/5))^(1/3) - lambda^2))",
              "mpmath at 40 digits, 7 lambdas in [0, lam_crit)", lambda: _num_equal(
                  of_lam["e0"], e80, lam, [0, 0.11, 0.5, 1.01, 1.51, 1.99, 2.43]))
    ctx.check("60", "at lambda = 0: tau_dc0 = tau_dr0 = tau_d0/2 and tau_d0 = pi (5/4)^(-1/10) = 3.072",
              "SymPy", lambda: (sp.simplify(of_lam["tau_dc0"].subs(lam, 0) - of_lam["tau_dr0"].subs(lam, 0)) == 0,
                                f"tau_d0(0) = {sp.N(of_lam['tau_d0'].subs(lam, 0), 10)}"))

    # FORMULAS.md shows the same expressions before SymPy's simplify (as the paper writes them)
    shown = {n: e.subs(sub) for n, e in (("tau_d0", tau_d0), ("tau_dc0", tau_dc0), ("tau_dr0", tau_dr0))}
    ctx.expr.update(beta_of_lam=beta_of_lam, omega0_of_lam=omega0_of_lam, lam_crit=lam_crit,
                    lam_crit_eq=lam_crit_eq, delta0=delta0, delta0_dot=delta0_dot, tau_d0=tau_d0,
                    tau_dc0=tau_dc0, tau_dr0=tau_dr0, eta0=eta0, e0=e0,
                    **{f"{n}_of_lam": v for n, v in of_lam.items()})
    d0 = sp.Symbol(r"\bar\delta_0")
    ctx.eq("32", beta, beta_of_lam, r"damping rate, $\beta = k\lambda/2$")
    ctx.eq("33", w, omega0_of_lam, r"frequency, $\omega_0 = \sqrt{4k - k^2\lambda^2}/2$")
    ctx.eq("34", d0, sp.exp(-beta * tau) * (sp.Symbol("c_1") * sp.sin(w * tau) + sp.Symbol("c_2") * sp.cos(w * tau)),
           "general solution of (28); (29) gives c_1 = 1/omega0, c_2 = 0")
    ctx.eq("35", d0, delta0, "zeroth-order solution")
    ctx.eq("54", sp.Symbol(r"\tau_{d}"), tau_d0, "zeroth-order contact duration")
    ctx.eq("54a", sp.Symbol(r"\tau_{d}"), shown["tau_d0"], "zeroth-order contact duration in lambda")
    ctx.eq("56", sp.Symbol(r"\dot{\bar\delta}_0"), delta0_dot, "zeroth-order velocity")
    ctx.eq("57", delta0_dot.subs(tau, sp.Symbol(r"\tau_{dc}")), 0, "end of compression")
    ctx.eq("78", sp.Symbol(r"\dot{\bar\delta}_0(\tau_d)"), -e0, "terminal relative velocity")
    ctx.eq("58", sp.Symbol(r"\tau_{dc}"), tau_dc0, "compression duration")
    ctx.eq("59", sp.Symbol(r"\tau_{dc}"), shown["tau_dc0"], "compression duration in lambda")
    ctx.eq("60", sp.Symbol(r"\tau_{dr}"), shown["tau_dr0"], "recovery duration in lambda")
    ctx.eq("61", sp.Symbol(r"\eta"), eta0, "asymmetry index")
    ctx.eq("79", sp.Symbol("e"), e0, "zeroth-order restitution")
    ctx.eq("80", sp.Symbol("e"), e80, "zeroth-order restitution in lambda")
    ctx.eq("81", sp.Symbol(r"\lambda_{crit}"), sp.Float(lam_crit, 20),
           r"validity bound: $4(\lambda + (5/4)^{-3/5})^{1/3} > \lambda^2$, i.e. "
           r"$\lambda^6 < 64(\lambda + (5/4)^{-3/5})$")
    return set(ctx.expr)


def _num_equal(a, b, lam, lams, dps=40, tol=1e-30):
    fa, fb = sp.lambdify(lam, a, "mpmath"), sp.lambdify(lam, b, "mpmath")
    with mpmath.workdps(dps):
        worst = max(abs(fa(mpmath.mpf(x)) / fb(mpmath.mpf(x)) - 1) for x in lams)
    return worst < tol, f"max rel difference {mpmath.nstr(worst, 3)}"

