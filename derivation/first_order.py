r"""First-order correction, Eqs. (36)-(42).

Forcing (36). f = -N(delta0) is obtained by substituting delta0 (35) into the right-hand side of
(30). It splits into ``forcing_elem = -delta0''`` (no fractional powers) and ``forcing_sqrt`` =
-(3/2) lambda sqrt(delta0) delta0' - delta0^{3/2}, which carries sqrt(sin(omega0 tau)) and is
real only on 0 < omega0 tau < pi (the whole derivation of delta1 lives on that interval).

Variation of constants (37)-(39). delta1 = exp(-beta tau)(C11 sin + C12 cos) with
C11' sin + C12' cos = 0 gives the linear system (38), solved by SymPy:
C11' = cos(omega0 tau) exp(beta tau) f / omega0, C12' = -sin(omega0 tau) exp(beta tau) f / omega0.

Elementary parts (C111, C112, C121, C122) are integrated by SymPy.

Sqrt parts. With s = sin(omega0 tau), c = cos(omega0 tau),

    C11'_sqrt = -3 lambda/(2 omega0^{3/2}) e^{-beta tau/2} s^{1/2} c^2
                + (3 lambda beta - 2)/(2 omega0^{5/2}) e^{-beta tau/2} s^{3/2} c,
    C12'_sqrt = +3 lambda/(2 omega0^{3/2}) e^{-beta tau/2} s^{3/2} c
                - (3 lambda beta - 2)/(2 omega0^{5/2}) e^{-beta tau/2} s^{5/2}.

Our pieces are the plain integrals (no coefficients)

    C113 = int e^{-beta tau/2} s^{1/2} c^2,   C114 = C123 = int e^{-beta tau/2} s^{3/2} c,
    C124 = int e^{-beta tau/2} s^{5/2},

so C11_hyp = -3 lambda/(2 omega0^{3/2}) C113 + (3 lambda beta - 2)/(2 omega0^{5/2}) C114 and
C12_hyp = 3 lambda/(2 omega0^{3/2}) C123 - (3 lambda beta - 2)/(2 omega0^{5/2}) C124. The paper's
(40)-(41) print the coefficient (3 lambda beta - 2)/(2 omega0^{3/2}) in front of C114 and C124, so
the paper's C114, C124 correspond to ours divided by omega0 (and any constant is immaterial: only
C(tau) - C(0) enters (42)).

All three reduce, by parts and by the reduction formula of int e^{a tau} s^n, to one integral

    K(tau) = int e^{-beta tau/2} s^{1/2} dtau.

With theta = omega0 tau and z = exp(2 i theta): 1 - z = 2 s exp(i(theta - pi/2)), whose argument
lies in (-pi/2, pi/2) for theta in (0, pi), so with the principal square root
s^{1/2} = exp(i pi/4) exp(-i theta/2) (1 - z)^{1/2} / sqrt(2). Then with
a = (i beta/omega0 - 1)/4 and z^a := exp(2 i a theta) = exp(-beta tau/2 - i omega0 tau/2)
(written through theta, never through the principal log of z, which jumps at theta = pi/2),

    K_c(tau) = exp(i pi/4) / (2 i sqrt(2) omega0 a) z^a 2F1(-1/2, a; a + 1; z),

because d/dz [z^a 2F1(-1/2, a; a+1; z) / a] = z^{a-1} (1 - z)^{1/2} (proved termwise, symbolically)
and the 2F1 is the principal branch (|z| = 1, the cut [1, oo) touched only at theta = 0, pi; the
series converges on |z| = 1 since Re(c - a - b) = 3/2 > 0). K_c is complex; its derivative is the
real integrand, so K = re(K_c) is a real antiderivative (a constant apart). C11_0, C12_0 are the
values at tau -> 0+, with 2F1(-1/2, a; a+1; 1) = Gamma(a+1) Gamma(3/2) / Gamma(a + 3/2) (Gauss).
At lambda = 0 (beta = 0) a = -1/4: nothing degenerates.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from .steps import MP_DPS, Context, max_rel_residual, symbolic_zero

__all__ = ["derive", "check_antiderivative", "CHECK_LAMBDAS", "check_thetas"]

#: Lambda values of the differentiation proofs (lam_crit * 0.995 is appended at run time).
CHECK_LAMBDAS = ("0", "0.5", "1.01", "1.99")


def check_thetas(n: int = 20):
    """n midpoints of (0, pi) plus two points 1e-3 from each end (where z -> 1)."""
    pts = [mpmath.pi * (j + mpmath.mpf(1) / 2) / n for j in range(n)]
    return pts + [mpmath.pi * mpmath.mpf("1e-3"), mpmath.pi * (1 - mpmath.mpf("1e-3"))]


def _is_fractional_sin_power(term) -> bool:
    return any(isinstance(pw, sp.Pow) and isinstance(pw.base, sp.sin) and not pw.exp.is_integer
               for pw in term.atoms(sp.Pow))


def split_sqrt(expr):
    """(terms without, terms with) a fractional power of sin in the expanded ``expr``."""
    terms = sp.Add.make_args(sp.expand(expr))
    elem = sp.Add(*[t for t in terms if not _is_fractional_sin_power(t)])
    frac = sp.Add(*[t for t in terms if _is_fractional_sin_power(t)])
    return elem, frac


def check_antiderivative(F, integrand, symbols, lam_beta_omega, dps=MP_DPS, tol=1e-25, n=20):
    """Prove F' = integrand by differentiation at ``dps`` digits.

    Parameters
    ----------
    F, integrand : sympy expressions in ``symbols = (lam, beta, omega0, tau)``
    lam_beta_omega : list of (lam, beta, omega0) mpmath triples
    n : int
        Number of interior points of (0, pi/omega0) (two near-end points are added).

    Returns
    -------
    (passed, detail)
    """
    lam, beta, w, tau = symbols
    dF = sp.lambdify((lam, beta, w, tau), sp.diff(F, tau), "mpmath", cse=True)
    g = sp.lambdify((lam, beta, w, tau), integrand, "mpmath", cse=True)
    worst, nchk = mpmath.mpf(0), 0
    with mpmath.workdps(dps):
        for lv, bv, wv in lam_beta_omega:
            r = max_rel_residual(lambda t: mpmath.re(dF(lv, bv, wv, t)), lambda t: g(lv, bv, wv, t),
                                 [th / wv for th in check_thetas(n)])
            # the imaginary part of F' must vanish too (F is real on the interval)
            for th in check_thetas(n)[::5]:
                im = abs(mpmath.im(dF(lv, bv, wv, th / wv))) / abs(g(lv, bv, wv, th / wv))
                r = max(r, im)
            worst = max(worst, r)
            nchk += n + 2
    return worst <= tol, (f"max rel residual {mpmath.nstr(worst, 3)} at {dps} digits, {nchk} points, "
                          f"{len(lam_beta_omega)} lambdas (tol {tol:g})")


def derive(ctx: Context) -> dict:
    """Derive (36)-(42); see the module docstring for the names added to ``ctx.expr``."""
    S = ctx.symbols
    lam, tau, k, beta, w = S["lam"], S["tau"], S["k"], S["beta"], S["omega0"]
    delta0 = ctx.expr["delta0"]
    half = sp.Rational(1, 2)
    s, c = sp.sin(w * tau), sp.cos(w * tau)
    bw = {k: beta**2 + w**2}  # k = beta^2 + omega0^2 and k lambda = 2 beta tie (28) to (35)

    # (36) by substitution into the right-hand side of (30).
    forcing = sp.expand(-(delta0.diff(tau, 2) + sp.Rational(3, 2) * lam * sp.sqrt(delta0) * delta0.diff(tau)
                          + delta0 ** sp.Rational(3, 2)))
    forcing = sp.expand(sp.powsimp(sp.expand_power_base(forcing, force=True), force=True))
    f_elem, f_sqrt = split_sqrt(forcing)
    ctx.check("36", "f = -N(delta0) splits into forcing_elem = -delta0'' (integer powers only) and "
              "forcing_sqrt = -(3/2) lambda sqrt(delta0) delta0' - delta0^(3/2)",
              "SymPy substitution; numeric equality of the split at 40 digits",
              lambda: _split_ok(f_elem, f_sqrt, delta0, lam, beta, w, tau))

    # (37)-(39): variation of constants.
    A, B = sp.Function("C11")(tau), sp.Function("C12")(tau)
    Ap, Bp = sp.symbols("C11p C12p")
    d1 = sp.exp(-beta * tau) * (A * s + B * c)
    constraint = sp.Eq(Ap * s + Bp * c, 0)
    fsym = sp.Symbol("f")
    # with the constraint, delta1' = A (e^{-bt} s)' + B (e^{-bt} c)'; then L(delta1) = f is linear in A', B'.
    d1p = A * (sp.exp(-beta * tau) * s).diff(tau) + B * (sp.exp(-beta * tau) * c).diff(tau)
    d1pp = d1p.diff(tau).subs({A.diff(tau): Ap, B.diff(tau): Bp})
    L_d1 = sp.expand(sp.expand(d1pp + k * lam * d1p + k * d1).subs(lam, 2 * beta / k).subs(bw))
    sol = sp.solve([constraint, sp.Eq(L_d1, fsym)], [Ap, Bp], dict=True)[0]
    c11p_gen = sp.simplify(sol[Ap])
    c12p_gen = sp.simplify(sol[Bp])
    ctx.check("38-39", "C11' = cos(omega0 tau) e^(beta tau) f/omega0, C12' = -sin(omega0 tau) e^(beta tau) f/omega0",
              "SymPy solve of the variation-of-constants system (A, B terms cancel)",
              lambda: (symbolic_zero(c11p_gen - c * sp.exp(beta * tau) * fsym / w)[0]
                       and symbolic_zero(c12p_gen + s * sp.exp(beta * tau) * fsym / w)[0]
                       and not L_d1.has(A) and not L_d1.has(B), "solved and matched"))

    def vary(fpart):
        return (sp.expand(sp.powsimp(c11p_gen.subs(fsym, fpart), force=True)),
                sp.expand(sp.powsimp(c12p_gen.subs(fsym, fpart), force=True)))

    C11p_elem, C12p_elem = vary(f_elem)
    C11p_sqrt, C12p_sqrt = vary(f_sqrt)
    C11p, C12p = C11p_elem + C11p_sqrt, C12p_elem + C12p_sqrt

    # Elementary parts by SymPy.
    C111 = sp.integrate(s * c, tau)
    C112 = sp.integrate(c**2, tau)
    C121 = sp.integrate(s**2, tau)
    C122 = C111
    C11_elem = (w**2 - beta**2) / w**2 * C111 + 2 * beta / w * C112
    C12_elem = -(w**2 - beta**2) / w**2 * C121 - 2 * beta / w * C122
    ctx.check("40-41", "C111..C122 by SymPy; C11_elem' = C11'_elem, C12_elem' = C12'_elem",
              "SymPy integrate, then differentiation",
              lambda: (symbolic_zero(C11_elem.diff(tau) - C11p_elem, rewrite_trig=True)[0]
                       and symbolic_zero(C12_elem.diff(tau) - C12p_elem, rewrite_trig=True)[0],
                       f"C111 = {C111}, C112 = {C112}, C121 = {C121}"))

    # The sqrt parts: coefficients of the three basic integrands.
    E = sp.exp(-beta * tau / 2)
    g_a, g_b, g_c = E * sp.sqrt(s) * c**2, E * s ** sp.Rational(3, 2) * c, E * s ** sp.Rational(5, 2)
    q1, q2 = -3 * lam / (2 * w ** sp.Rational(3, 2)), (3 * lam * beta - 2) / (2 * w ** sp.Rational(5, 2))
    ctx.check("39", "C11'_sqrt = q1 e^(-bt/2) s^(1/2) c^2 + q2 e^(-bt/2) s^(3/2) c and "
              "C12'_sqrt = -q1 e^(-bt/2) s^(3/2) c - q2 e^(-bt/2) s^(5/2), "
              "q1 = -3 lambda/(2 omega0^(3/2)), q2 = (3 lambda beta - 2)/(2 omega0^(5/2))",
              "SymPy expand", lambda: (symbolic_zero(C11p_sqrt - (q1 * g_a + q2 * g_b))[0]
                                       and symbolic_zero(C12p_sqrt - (-q1 * g_b - q2 * g_c))[0], "matched"))

    # Symbolic reduction of the three integrals to K (K' = e^{-bt/2} s^{1/2}).
    Kf = sp.Function("K")(tau)
    Kp = E * sp.sqrt(s)
    J_c = (-2 * E * s ** sp.Rational(3, 2) * (beta * s + 5 * w * c) / (beta**2 + 25 * w**2)
           + 15 * w**2 / (beta**2 + 25 * w**2) * Kf)
    J_a = Kf - J_c
    J_b = 2 / (5 * w) * E * s ** sp.Rational(5, 2) + beta / (5 * w) * J_c

    def reduce_ok():
        worst = []
        for J, g in ((J_a, g_a), (J_b, g_b), (J_c, g_c)):
            r = sp.expand(J.diff(tau).subs(Kf.diff(tau), Kp) - g)
            r = sp.simplify(sp.expand(sp.powsimp(sp.expand_power_base(r, force=True), force=True)
                                      .subs(c**2, 1 - s**2)))
            worst.append(r)
        return all(r == 0 for r in worst), f"residuals {worst}"

    ctx.check("40-41", "reduction: C124 = -2e^(-bt/2)s^(3/2)(b s + 5w c)/(b^2+25w^2) + 15w^2/(b^2+25w^2) K, "
              "C113 = K - C124, C114 = C123 = 2/(5w) e^(-bt/2)s^(5/2) + b/(5w) C124, with K' = e^(-bt/2) s^(1/2)",
              "SymPy differentiation with K' substituted (symbolic proof)", reduce_ok)

    # K in closed form through 2F1.
    a = (sp.I * beta / w - 1) / 4
    z = sp.exp(2 * sp.I * w * tau)
    za = sp.exp(-beta * tau / 2 - sp.I * w * tau / 2)
    pref = sp.exp(sp.I * sp.pi / 4) / (2 * sp.I * sp.sqrt(2) * w * a)
    Kc = pref * za * sp.hyper([-half, a], [a + 1], z)
    K = sp.re(Kc, evaluate=False)
    Kc0 = sp.exp(sp.I * sp.pi / 4) * sp.sqrt(sp.pi) * sp.gamma(a) / (4 * sp.I * sp.sqrt(2) * w * sp.gamma(a + sp.Rational(3, 2)))
    K0 = sp.re(Kc0, evaluate=False)

    def lemma():
        aa, zz, n = sp.Symbol("a"), sp.Symbol("z"), sp.Symbol("n", integer=True, nonnegative=True)
        # coefficient of z^(a-1+n) in d/dz[z^a 2F1(-1/2, a; a+1; z)/a] vs in z^(a-1)(1-z)^(1/2)
        # coefficient of z^(a-1+n) of the left side: (-1/2)_n (a)_n/((a+1)_n n!) (a+n)/a, which is
        # (-1/2)_n/n! iff (a)_n/(a+1)_n = a/(a+n); and (-1/2)_n/n! = (-1)^n binomial(1/2, n).
        r1 = sp.simplify(sp.gammasimp(sp.rf(aa, n) / sp.rf(aa + 1, n)) - aa / (aa + n))
        r2 = sp.simplify(sp.gammasimp(sp.expand_func(sp.binomial(half, n) * (-1) ** n
                                                     - sp.rf(-half, n) / sp.factorial(n))))
        # branch: 1 - exp(2 i th) = 2 sin(th) exp(i (th - pi/2))
        th = sp.Symbol("theta", real=True)
        r3 = sp.simplify(sp.expand((1 - sp.exp(2 * sp.I * th)) - 2 * sp.sin(th) * sp.exp(sp.I * (th - sp.pi / 2)))
                         .rewrite(sp.exp))
        return (r1 == 0 and r2 == 0 and r3 == 0,
                f"termwise coefficient difference {r1}, binomial {r2}, branch identity {r3}")

    ctx.check("40-41", "lemma: d/dz[z^a 2F1(-1/2, a; a+1; z)/a] = z^(a-1) (1-z)^(1/2), and "
              "1 - e^(2i theta) = 2 sin(theta) e^(i(theta - pi/2)) (principal sqrt on 0 < theta < pi)",
              "SymPy termwise series identity (rising factorials), exp rewrite", lemma)

    # The checking lambdas: 0, ..., and one within 1% of lam_crit.
    lam_crit = ctx.expr["lam_crit"]
    lams = [sp.Float(x, 50) for x in CHECK_LAMBDAS] + [sp.Float(lam_crit * sp.Rational(995, 1000), 50)]
    with mpmath.workdps(MP_DPS + 10):
        fb = sp.lambdify(lam, ctx.expr["beta_of_lam"], "mpmath")
        fw = sp.lambdify(lam, ctx.expr["omega0_of_lam"], "mpmath")
        lbw = [(mpmath.mpf(str(x)), fb(mpmath.mpf(str(x))), fw(mpmath.mpf(str(x)))) for x in lams]
    syms = (lam, beta, w, tau)
    ctx.check("40-41", "K = re(K_c): d/dtau K_c = e^(-beta tau/2) sin^(1/2)(omega0 tau) on (0, pi/omega0)",
              f"analytic derivative of hyper, mpmath at {MP_DPS} digits, 22 points per lambda, "
              f"lambda in {{{', '.join(CHECK_LAMBDAS)}, 0.995 lam_crit}}",
              lambda: check_antiderivative(K, Kp, syms, lbw))

    sub_K = {Kf: K}
    C113, C114, C124 = J_a.subs(sub_K), J_b.subs(sub_K), J_c.subs(sub_K)
    C123 = C114
    C11_hyp = q1 * C113 + q2 * C114
    C12_hyp = -q1 * C123 - q2 * C124
    for name, F, g in (("C113", C113, g_a), ("C114 = C123", C114, g_b), ("C124", C124, g_c),
                       ("C11_hyp", C11_hyp, C11p_sqrt), ("C12_hyp", C12_hyp, C12p_sqrt)):
        ctx.check("40-41", f"{name}' = its integrand on (0, pi/omega0)",
                  f"analytic derivative of hyper, mpmath at {MP_DPS} digits",
                  lambda F=F, g=g: check_antiderivative(F, g, syms, lbw))

    # Constants at tau -> 0+: the elementary parts by substitution, K by Gauss's sum.
    sub0_elem = lambda e: sp.simplify(e.subs(tau, 0))  # noqa: E731
    C124_0 = 15 * w**2 / (beta**2 + 25 * w**2) * K0
    C113_0 = K0 - C124_0
    C114_0 = beta / (5 * w) * C124_0
    C11_0 = sub0_elem(C11_elem) + q1 * C113_0 + q2 * C114_0
    C12_0 = sub0_elem(C12_elem) - q1 * C114_0 - q2 * C124_0

    def const_ok():
        f = sp.lambdify(syms, sp.Matrix([C11_elem + C11_hyp - C11_0, C12_elem + C12_hyp - C12_0]), "mpmath")
        g1 = sp.lambdify(syms, C11p, "mpmath")
        g2 = sp.lambdify(syms, C12p, "mpmath")
        worst = mpmath.mpf(0)
        with mpmath.workdps(MP_DPS):
            for lv, bv, wv in lbw:
                # limit at 0+: C(tau) - C(0) = O(tau^(3/2))
                with mpmath.workdps(2 * MP_DPS):
                    # C(t) - C(0) = O(t) (the elementary parts start linearly): 1e-30 at t = 1e-30
                    t0 = mpmath.mpf("1e-30")
                    worst = max(worst, max(abs(x) for x in f(lv, bv, wv, t0)) / 1e5)
                # and an independent route: the integral from 0 by tanh-sinh quadrature
                for th in (mpmath.mpf(1), mpmath.mpf(3)):
                    t = th / wv
                    got = f(lv, bv, wv, t)
                    q1_ = mpmath.quad(lambda x: g1(lv, bv, wv, x), [0, t])
                    q2_ = mpmath.quad(lambda x: g2(lv, bv, wv, x), [0, t])
                    worst = max(worst, abs(mpmath.re(got[0]) - q1_) / max(abs(q1_), 1),
                                abs(mpmath.re(got[1]) - q2_) / max(abs(q2_), 1))
        return worst < 1e-25, f"max {mpmath.nstr(worst, 3)} (|C(t) - C(0)| at t = 1e-30 times 1e5, and quad at omega0 tau = 1, 3)"

    ctx.check("42", "C11_0, C12_0 (Gamma functions) are the limits at tau -> 0+ and C(tau) - C(0) = "
              "integral of C' from 0", f"mpmath at {MP_DPS} digits (80 for the limit): tau = 1e-30 and tanh-sinh quadrature",
              const_ok)

    C11 = C11_elem + C11_hyp
    C12 = C12_elem + C12_hyp
    delta1 = sp.exp(-beta * tau) * ((C11 - C11_0) * s + (C12 - C12_0) * c)
    delta_ham1 = delta0 + delta1

    def ode_ok():
        L1 = delta1.diff(tau, 2) + 2 * beta * delta1.diff(tau) + (beta**2 + w**2) * delta1
        res = sp.lambdify(syms, L1, "mpmath", cse=True)
        ff = sp.lambdify(syms, forcing, "mpmath")
        d1f = sp.lambdify(syms, sp.Matrix([delta1, delta1.diff(tau)]), "mpmath", cse=True)
        worst, ic = mpmath.mpf(0), mpmath.mpf(0)
        with mpmath.workdps(MP_DPS):
            for lv, bv, wv in lbw:
                for th in check_thetas(8):
                    t = th / wv
                    worst = max(worst, abs(res(lv, bv, wv, t) - ff(lv, bv, wv, t)) / abs(ff(lv, bv, wv, t)))
                with mpmath.workdps(2 * MP_DPS):
                    # delta1 = O(t^2), delta1' = O(t): a wrong constant would leave O(1) here
                    t0 = mpmath.mpf("1e-20")
                    v = d1f(lv, bv, wv, t0)
                    ic = max(ic, abs(v[0]) / t0 ** 2, abs(v[1]) / t0)
        return worst < 1e-25 and ic < 10, (f"ODE max rel residual {mpmath.nstr(worst, 3)}; "
                                           f"max(|delta1(t)|/t^2, |delta1'(t)|/t) at t = 1e-20, 80 digits: "
                                           f"{mpmath.nstr(ic, 3)}")

    ctx.check("30-31, 42", "delta1 = e^(-bt)((C11 - C11_0) sin + (C12 - C12_0) cos) satisfies (30) and (31)",
              f"SymPy derivatives, mpmath at {MP_DPS} digits, 10 points x {len(lbw)} lambdas", ode_ok)

    ctx.expr.update(
        forcing=f_elem + f_sqrt, forcing_elem=f_elem, forcing_sqrt=f_sqrt,
        C11_prime=C11p, C12_prime=C12p, C11_prime_elem=C11p_elem, C11_prime_sqrt=C11p_sqrt,
        C12_prime_elem=C12p_elem, C12_prime_sqrt=C12p_sqrt, C11_elem=C11_elem, C12_elem=C12_elem,
        C111=C111, C112=C112, C121=C121, C122=C122, K_hyp=K, K_hyp_0=K0,
        C113=C113, C114=C114, C123=C123, C124=C124, C11_hyp=C11_hyp, C12_hyp=C12_hyp,
        C11_0=C11_0, C12_0=C12_0, delta1=delta1, delta_ham1=delta_ham1,
    )
    ctx.eq("36", sp.Symbol("f(\\tau)"), f_elem + f_sqrt, "forcing of (30), valid for 0 < omega0 tau < pi")
    ctx.eq("37", sp.Symbol(r"\bar\delta_1"), sp.exp(-beta * tau) * (sp.Symbol("C_{11}(\\tau)") * s + sp.Symbol("C_{12}(\\tau)") * c),
           "variation of constants")
    ctx.eq("38", sp.Symbol(r"C'_{11}\sin(\omega_0\tau) + C'_{12}\cos(\omega_0\tau) = 0,\quad "
                            r"C'_{11}\cos(\omega_0\tau) - C'_{12}\sin(\omega_0\tau)"),
           sp.exp(beta * tau) * sp.Symbol(r"f(\tau)") / w, "variation-of-constants system")
    ctx.eq("39a", sp.Symbol("C'_{11}"), C11p, "solved from (38)")
    ctx.eq("39b", sp.Symbol("C'_{12}"), C12p, "solved from (38)")
    ctx.eq("40", sp.Symbol("C_{11}"), sp.Symbol("C_{11,elem}") + q1 * sp.Symbol("C_{113}") + q2 * sp.Symbol("C_{114}"),
           "antiderivative of C'_11 (paper's C114 = ours / omega0)")
    ctx.eq("40a", sp.Symbol("C_{11,elem}"), C11_elem, "elementary part of C11")
    ctx.eq("40b", sp.Symbol("K"), K,
           r"$K' = e^{-\beta\tau/2}\sin^{1/2}(\omega_0\tau)$, principal 2F1 on $|z| = 1$")
    ctx.eq("40c", sp.Symbol("C_{124}"), J_c.subs(Kf, sp.Symbol("K")), "reduction to K")
    ctx.eq("40d", sp.Symbol("C_{113}"), sp.Symbol("K") - sp.Symbol("C_{124}"), "reduction to K")
    ctx.eq("40e", sp.Symbol("C_{114}"), 2 / (5 * w) * E * s ** sp.Rational(5, 2) + beta / (5 * w) * sp.Symbol("C_{124}"),
           "by parts; C123 = C114")
    ctx.eq("41", sp.Symbol("C_{12}"), sp.Symbol("C_{12,elem}") - q1 * sp.Symbol("C_{123}") - q2 * sp.Symbol("C_{124}"),
           "antiderivative of C'_12 (paper's C124 = ours / omega0)")
    ctx.eq("41a", sp.Symbol("C_{12,elem}"), C12_elem, "elementary part of C12")
    ctx.eq("42a", sp.Symbol("K_0"), K0, "K at tau -> 0+, by Gauss's sum")
    ctx.eq("42b", sp.Symbol("C_{11}(0)"), sp.factor(C11_0.subs(K0, sp.Symbol("K_0"))), "value at tau -> 0+")
    ctx.eq("42c", sp.Symbol("C_{12}(0)"), sp.factor(C12_0.subs(K0, sp.Symbol("K_0"))), "value at tau -> 0+")
    ctx.eq("42", sp.Symbol(r"\bar\delta"), delta0 + sp.exp(-beta * tau) * ((sp.Symbol("C_{11}(\\tau)") - sp.Symbol("C_{11}(0)")) * s
                                                                         + (sp.Symbol("C_{12}(\\tau)") - sp.Symbol("C_{12}(0)")) * c),
           "first-order HAM solution")
    return set(ctx.expr)


def _split_ok(f_elem, f_sqrt, delta0, lam, beta, w, tau):
    want_elem = -delta0.diff(tau, 2)
    want_sqrt = -(sp.Rational(3, 2) * lam * sp.sqrt(delta0) * delta0.diff(tau) + delta0 ** sp.Rational(3, 2))
    ok_elem = symbolic_zero(f_elem - want_elem)[0]
    no_frac = not any(_is_fractional_sin_power(t) for t in sp.Add.make_args(f_elem))
    fa = sp.lambdify((lam, beta, w, tau), f_sqrt, "mpmath")
    fb = sp.lambdify((lam, beta, w, tau), want_sqrt, "mpmath")
    with mpmath.workdps(40):
        pts = [(mpmath.mpf(l), mpmath.mpf(b), mpmath.mpf(x), mpmath.mpf(t))
               for l, b, x, t in ((0, 0, 1, 1), (1, "0.3", "0.8", 2), ("2", "0.7", "0.2", 10))]
        worst = max(abs(fa(*p) / fb(*p) - 1) for p in pts)
    return ok_elem and no_frac and worst < 1e-35, f"elem part exact; sqrt part rel diff {mpmath.nstr(worst, 3)}"

