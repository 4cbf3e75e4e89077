r"""Higher orders of the paper's homotopy (14), with Liao's convergence-control parameter c0.

Not part of the paper's chain (``registry.PARTS``): the paper stops at order 1. Run as
``python -m zener_sym.derivation.ham_higher``.

1. Liao's zero-order deformation equation (1 - p) L[phi - delta0] = c0 p N[phi] is the paper's
   (14) at c0 = -1 (because L[delta0] = 0, Eq. 28).
2. The m-th order deformation equation, from the m-th p-derivative at p = 0 of the homotopy:

       L[delta_m - chi_m delta_{m-1}] = c0 R_m,   R_m = [p^{m-1}] N[sum_j delta_j p^j],
       chi_1 = 0, chi_m = 1 (m >= 2),   delta_m(0) = delta_m'(0) = 0 (m >= 1),

   written out for m = 2, 3, 4 (R_m in delta_0..delta_{m-1}), and the coefficients P_n of
   (sum_j delta_j p^j)^{3/2} checked against J. C. P. Miller's recurrence used by the numerics
   (``zener_sym.ham.higher``).
3. The local exponent at the end of the zeroth-order contact tau -> pi/omega0 (s = pi/omega0 -
   tau -> 0+): delta0 = a s + O(s^2) with a = exp(-beta pi/omega0) > 0 while delta1 -> d1 != 0, so

       R_m = -lambda (5/2 - m) binom(3/2, m - 1) d1^{m-1} a^{5/2-m} s^{3/2-m} (1 + o(1)),

   because in P_{m-1} the product delta1^{m-1} carries the most negative power delta0^{5/2-m}
   (a term with l factors delta_j, j >= 1, carries delta0^{3/2-l} and l <= m - 1, with equality
   only for delta1^{m-1}). Checked by series in sqrt(s) for m = 1..4. The exponent 3/2 - m is
   > -1 (integrable) for m <= 2 and <= -3/2 (not integrable) from m = 3 on; at lambda = 0 the
   leading term is binom(3/2, m - 1) d1^{m-1} a^{5/2-m} s^{5/2-m}, not integrable from m = 4 on.
   Consequence (variation of constants, G(t) ~ t): delta_3' ~ s^{-1/2} -> infinity at
   pi/omega0, delta_4 ~ s^{-1/2} itself; the paper's formulation ends at order 2.
"""
from __future__ import annotations

import sympy as sp

from .steps import Context, symbolic_zero

__all__ = ["derive", "MAX_ORDER"]

#: Orders written out.
MAX_ORDER = 4


def _N(f, fp, fpp, lam):
    """N (13) of a function given by its value and tau-derivatives, (delta^{3/2})' written out."""
    return fpp + f ** sp.Rational(3, 2) + lam * sp.Rational(3, 2) * sp.sqrt(f) * fp


def miller(f, alpha, n):
    """[p^0..p^n] of (sum_j f_j p^j)^alpha by Miller's recurrence (as in the numerics)."""
    g = [f[0] ** alpha]
    for m in range(1, n + 1):
        g.append(sum(((alpha + 1) * j - m) * f[j] * g[m - j] for j in range(1, m + 1)) / (m * f[0]))
    return g


def derive(ctx: Context | None = None, echo=None) -> Context:
    """Derive and check items 1-3 of the module docstring; adds ``R_2..R_4`` (forcings),
    ``higher_exponents`` ({m: exponent of s in R_m}, lambda > 0) and ``higher_exponents_lam0``."""
    if ctx is None:
        ctx = Context()
        ctx.log.echo = echo
    S = ctx.symbols
    lam, k, tau, p = S["lam"], S["k"], S["tau"], S["p"]
    c0 = sp.Symbol("c_0", nonzero=True)
    M = MAX_ORDER
    dl = [sp.Function(f"delta_{j}")(tau) for j in range(M + 1)]

    def L(f):
        return f.diff(tau, 2) + k * lam * f.diff(tau) + k * f

    phi = sum(dl[j] * p**j for j in range(M + 1))

    # 1. Liao's form at c0 = -1 is (14): (1-p) L[phi - delta0] + p N[phi] - ((1-p) L[phi] + p N[phi])
    #    = -(1-p) L[delta0], zero by (28).
    phi_f = sp.Function("phi")(tau)
    Nphi = _N(phi_f, phi_f.diff(tau), phi_f.diff(tau, 2), lam)
    liao = (1 - p) * L(phi_f - dl[0]) - c0 * p * Nphi
    paper14 = (1 - p) * L(phi_f) + p * Nphi
    ctx.check("14", "(1-p) L[phi - delta0] = c0 p N[phi] at c0 = -1 is (14), up to (1-p) L[delta0] = 0 (28)",
              "SymPy expand", lambda: symbolic_zero(liao.subs(c0, -1) - paper14 + (1 - p) * L(dl[0])))

    # 2. m-th order equations: d^m/dp^m at p = 0 / m!, derivatives replaced by symbols so that the
    #    p-series is algebraic.
    D = [[sp.Symbol(f"D{j}_{n}", positive=(j == 0 and n == 0)) for n in range(3)] for j in range(M + 1)]
    back = {D[j][n]: dl[j].diff(tau, n) if n else dl[j] for j in range(M + 1) for n in range(3)}
    ph = [sum(D[j][n] * p**j for j in range(M + 1)) for n in range(3)]
    Lph = [ph[2] + k * lam * ph[1] + k * ph[0]]
    N_alg = _N(ph[0], ph[1], ph[2], lam)
    hom = (1 - p) * (Lph[0] - (D[0][2] + k * lam * D[0][1] + k * D[0][0])) - c0 * p * N_alg
    ser = sp.expand(sp.series(hom, p, 0, M + 1).removeO())
    N_ser = sp.expand(sp.series(N_alg, p, 0, M).removeO())
    R = {m: N_ser.coeff(p, m - 1) for m in range(1, M + 1)}
    for m in range(2, M + 1):
        Lm = lambda j: D[j][2] + k * lam * D[j][1] + k * D[j][0]  # noqa: E731
        want = Lm(m) - Lm(m - 1) - c0 * R[m]
        ctx.check(f"m={m}", f"order p^{m} of the homotopy: L[delta_{m} - delta_{m-1}] = c0 R_{m}, "
                  f"R_{m} = [p^{m-1}] N[sum delta_j p^j]", "SymPy series in p",
                  lambda m=m, want=want: symbolic_zero(ser.coeff(p, m) - want))
    Lm1 = D[1][2] + k * lam * D[1][1] + k * D[1][0]
    ctx.check("30", "order p^1: L[delta_1] = c0 R_1 = c0 N[delta0] (the paper's (30) at c0 = -1)",
              "SymPy series in p", lambda: symbolic_zero(ser.coeff(p, 1) - (Lm1 - c0 * R[1])))

    # P_n and Q_n (sqrt) by Miller's recurrence equal the p-series coefficients
    f0 = [D[j][0] for j in range(M + 1)]
    P_ser = sp.expand(sp.series(ph[0] ** sp.Rational(3, 2), p, 0, M).removeO())
    Q = miller(f0, sp.Rational(1, 2), M - 1)
    P_miller = [sp.expand(sum(Q[j] * f0[n - j] for j in range(n + 1))) for n in range(M)]
    ctx.check("26-27", f"P_n = [p^n](sum delta_j p^j)^(3/2) = sum_j Q_j delta_(n-j), Q by Miller's "
              f"recurrence for sqrt, n = 0..{M - 1} (the numerics' route)", "SymPy simplify",
              lambda: (all(symbolic_zero(P_ser.coeff(p, n) - P_miller[n])[0] for n in range(M)),
                       f"equal for n = 0..{M - 1}"))

    # ICs: phi(0; p) = 0 and phi'(0; p) = 1 for all p
    a = sp.symbols(f"a0:{M + 1}")
    bb = sp.symbols(f"b0:{M + 1}")
    eqs = [sp.expand(sum(a[j] * p**j for j in range(M + 1))).coeff(p, j) for j in range(M + 1)]
    eqs += [sp.expand(sum(bb[j] * p**j for j in range(M + 1)) - 1).coeff(p, j) for j in range(M + 1)]
    ic = sp.solve(eqs, list(a) + list(bb), dict=True)[0]
    ctx.check("29,31", f"delta_m(0) = delta_m'(0) = 0 for m = 1..{M} (delta0'(0) = 1)",
              "coefficients of p^j of phi(0;p) = 0, phi'(0;p) = 1 solved by SymPy",
              lambda: (all(ic[a[j]] == 0 for j in range(M + 1)) and ic[bb[0]] == 1
                       and all(ic[bb[j]] == 0 for j in range(1, M + 1)), f"{ic}"))

    # 3. local exponents at s = pi/omega0 - tau -> 0+, in sigma = sqrt(s): d/dtau = -d/ds =
    #    -(1/(2 sigma)) d/dsigma. delta0 = a s + a2 s^2; delta_j = d_j + e_j s + g_j s^(q_j), the
    #    fractional power its own forcing gives it (q_j = 7/2 - j for lambda > 0: R_j ~ s^(3/2-j)
    #    integrated twice; q_j = 9/2 - j at lambda = 0), consistent with the exponents proven here.
    sg = sp.Symbol("sigma", positive=True)
    aa, a2 = sp.Symbol("a", positive=True), sp.Symbol("a_2")
    d_ = sp.symbols(f"d1:{M + 1}", nonzero=True)
    e_ = sp.symbols(f"e1:{M + 1}")
    g_ = sp.symbols(f"g1:{M + 1}")

    def dtau(f):
        return -sp.diff(f, sg) / (2 * sg)

    def local_values(shift):
        loc = [aa * sg**2 + a2 * sg**4]
        for j in range(1, M + 1):
            loc.append(d_[j - 1] + e_[j - 1] * sg**2 + g_[j - 1] * sg ** (7 + shift - 2 * j))
        vals = {}
        for j in range(M + 1):
            vals[D[j][0]] = loc[j]
            vals[D[j][1]] = dtau(loc[j])
            vals[D[j][2]] = dtau(dtau(loc[j]))
        return vals

    exps, exps0 = {}, {}

    def leading(expr, lam_value):
        e = expr.subs(lam, lam_value).subs(local_values(0 if lam_value != 0 else 2))
        e = e.subs(sp.sqrt(aa * sg**2 + a2 * sg**4), sg * sp.sqrt(aa + a2 * sg**2))
        e = sp.powsimp(sp.expand_power_base(e, force=True), force=True)
        lead = sp.expand(sp.series(e, sg, 0, 8).removeO())
        pw = min(t.as_coeff_exponent(sg)[1] for t in sp.Add.make_args(lead))
        return pw, sp.simplify(lead.coeff(sg, pw))

    lam1 = sp.Symbol("Lambda", positive=True)
    for m in range(1, M + 1):
        want = (-lam1 * (sp.Rational(5, 2) - m) * sp.binomial(sp.Rational(3, 2), m - 1)
                * d_[0] ** (m - 1) * aa ** (sp.Rational(5, 2) - m))
        want0 = sp.binomial(sp.Rational(3, 2), m - 1) * d_[0] ** (m - 1) * aa ** (sp.Rational(5, 2) - m)

        def chk(m=m, want=want, want0=want0):
            pw, cf = leading(R[m], lam1)
            pw0, cf0 = leading(R[m], 0)
            exps[m], exps0[m] = pw / 2, pw0 / 2
            if m == 1:  # delta0'' is regular: R_1 is bounded, its fractional part O(s^(1/2))
                return pw >= 0 and pw0 >= 0, f"R_1 ~ s^({sp.Rational(pw, 2)}) (bounded)"
            ok = (pw == 3 - 2 * m and sp.simplify(cf - want) == 0
                  and pw0 == 5 - 2 * m and sp.simplify(cf0 - want0) == 0)
            return ok, (f"lambda > 0: R_{m} ~ s^({sp.Rational(pw, 2)}) x {sp.sstr(cf)}; "
                        f"lambda = 0: s^({sp.Rational(pw0, 2)}) x {sp.sstr(cf0)}")

        ctx.check(f"m={m}", f"local exponent of R_{m} at tau -> pi/omega0: " + (
                  "bounded" if m == 1 else
                  f"s^(3/2-{m}) x (-lambda (5/2-m) binom(3/2,m-1) d1^(m-1) a^(5/2-m)) for "
                  f"lambda > 0, s^(5/2-{m}) x binom(3/2,m-1) d1^(m-1) a^(5/2-m) at lambda = 0"),
                  "SymPy series in sqrt(s)", chk)

    def integrable():
        first = min(m for m in exps if exps[m] <= -1)
        first0 = min(m for m in exps0 if exps0[m] <= -1)
        return (first == 3 and first0 == 4,
                f"first non-integrable forcing: order {first} (lambda > 0), {first0} (lambda = 0); "
                f"exponents {exps}")

    ctx.check("end", "R_m is integrable at pi/omega0 for m <= 2 only (lambda > 0; m <= 3 at lambda = 0)",
              "exponent <= -1 test on the proven exponents", integrable)

    # what the variation of constants makes of s^q: delta ~ int (u - s) u^q du near u = s
    u, s_ = sp.symbols("u s", positive=True)

    def consequence():
        d3 = sp.integrate((u - s_) * u ** sp.Rational(-3, 2), (u, s_, 1))
        d3p = sp.integrate(u ** sp.Rational(-3, 2), (u, s_, 1))
        d4 = sp.integrate((u - s_) * u ** sp.Rational(-5, 2), (u, s_, 1))
        ok = (sp.limit(d3, s_, 0) == 2 and sp.limit(d3p * sp.sqrt(s_), s_, 0) == 2
              and sp.limit(d4 * sp.sqrt(s_), s_, 0) == sp.Rational(4, 3))
        return ok, (f"forcing s^(-3/2): delta ~ {sp.simplify(d3)} (finite), delta' ~ "
                    f"{sp.simplify(d3p)} (~ 2 s^(-1/2)); forcing s^(-5/2): delta ~ "
                    f"{sp.simplify(d4)} (~ (4/3) s^(-1/2))")

    ctx.check("end", "Green's function G(t) ~ t: forcing s^(-3/2) gives a finite delta_3 with "
              "delta_3' ~ 2 s^(-1/2); forcing s^(-5/2) gives delta_4 ~ (4/3) s^(-1/2)",
              "SymPy integrate and limit", consequence)

    Rb = {m: R[m].subs(back) for m in range(1, M + 1)}
    ctx.expr.update({f"R_{m}": Rb[m] for m in range(2, M + 1)})
    ctx.expr.update(higher_exponents=exps, higher_exponents_lam0=exps0)
    for m in range(2, M + 1):
        lhs = sp.Symbol(rf"\mathcal{{L}}[\bar\delta_{m} - \bar\delta_{m - 1}]")
        ctx.eq(f"H{m}", lhs, c0 * Rb[m], f"order-{m} deformation equation, delta_{m}(0) = delta_{m}'(0) = 0")
    return ctx


if __name__ == "__main__":  # pragma: no cover
    c = derive(echo=print)
    print(f"{'OK' if c.log.ok else 'FAILED'}: {len(c.log.steps)} steps")
    for m in range(2, MAX_ORDER + 1):
        print(f"R_{m} =", c.expr[f"R_{m}"])
