"""Homotopy construction, Eqs. (12)-(16) and (26)-(31).

The operators L (12) and N (13), the zero-order deformation equation (14)/(15), the series (16)
truncated after p^2, the Taylor expansions (26)-(27) of sqrt(delta) and delta^{3/2} about delta0
(derived here, not copied), and the order-p^0 and order-p^1 equations (28)-(31) obtained by
expanding (14) in p.
"""
from __future__ import annotations

import sympy as sp

from .steps import Context, symbolic_zero

__all__ = ["derive"]


def _operators(lam, k):
    """L and N of Eqs. (12)-(13) acting on an expression in tau (derivative written out)."""

    def L(d, tau):
        return sp.diff(d, tau, 2) + k * d + lam * k * sp.diff(d, tau)

    def N(d, tau):
        return sp.diff(d, tau, 2) + d ** sp.Rational(3, 2) + lam * sp.diff(d ** sp.Rational(3, 2), tau)

    return L, N


def derive(ctx: Context) -> dict:
    """Derive and check Eqs. (12)-(16) and (26)-(31); adds ``taylor_sqrt``, ``taylor_32``,
    ``order0_eq``, ``order1_eq`` (left-hand sides equal to 0) to ``ctx.expr``.

    Returns
    -------
    dict
        The names added.
    """
    S = ctx.symbols
    lam, k, tau, p = S["lam"], S["k"], S["tau"], S["p"]
    L, N = _operators(lam, k)
    d = sp.Function("delta")(tau)
    d0, d1, d2 = (sp.Function(f"delta_{i}")(tau) for i in range(3))
    half, three_half = sp.Rational(1, 2), sp.Rational(3, 2)

    # (15) is (14) with the operators written out: delta^{3/2}' = (3/2) sqrt(delta) delta'.
    eq15 = ((1 - p) * (d.diff(tau, 2) + k * lam * d.diff(tau) + k * d)
            + p * (d.diff(tau, 2) + three_half * lam * sp.sqrt(d) * d.diff(tau) + d ** three_half))
    eq14 = (1 - p) * L(d, tau) + p * N(d, tau)
    ctx.check("14-15", "(1-p) L + p N equals the written-out Eq. (15)", "SymPy expand",
              lambda: symbolic_zero(eq14 - eq15))

    # (26)-(27): Taylor expansions in p about delta0 (symbols stand for the values at one tau).
    D0, D1 = sp.symbols("delta0 delta1", positive=True)
    t_sqrt = sp.series(sp.sqrt(D0 + p * D1), p, 0, 3).removeO()
    t_32 = sp.series((D0 + p * D1) ** three_half, p, 0, 3).removeO()
    want_sqrt = sp.sqrt(D0) + D1 / (2 * sp.sqrt(D0)) * p - D1**2 / (8 * D0 ** three_half) * p**2
    want_32 = D0 ** three_half + three_half * sp.sqrt(D0) * D1 * p + sp.Rational(3, 8) * D1**2 / sp.sqrt(D0) * p**2
    ctx.check("26", "sqrt(d0 + p d1) = sqrt(d0) + d1/(2 sqrt(d0)) p - d1^2/(8 d0^(3/2)) p^2 + O(p^3)",
              "SymPy series in p", lambda: symbolic_zero(t_sqrt - want_sqrt))
    ctx.check("27", "(d0 + p d1)^(3/2) = d0^(3/2) + (3/2) sqrt(d0) d1 p + (3/8) d1^2/sqrt(d0) p^2 + O(p^3) "
              "(the printed (27) lacks d1 in the p term)",
              "SymPy series in p", lambda: symbolic_zero(t_32 - want_32))

    # (16) truncated: collect (14) by powers of p. Derivatives become plain symbols so that the
    # series in p is an algebraic one.
    series16 = d0 + p * d1 + p**2 * d2
    expr14 = sp.expand(eq15.subs(d, series16).doit())
    reps, back = {}, {}
    for i, f in enumerate((d0, d1, d2)):
        for n in (2, 1, 0):
            s = sp.Symbol(f"D{i}_{n}", positive=(i == 0 and n == 0))
            term = f.diff(tau, n) if n else f
            reps[term] = s
            back[s] = term
    e_alg = expr14.subs(reps)
    ser = sp.series(e_alg, p, 0, 2).removeO()
    order0 = sp.expand(ser.coeff(p, 0)).subs(back)
    order1 = sp.expand(ser.coeff(p, 1)).subs(back)
    L0, N0, L1 = L(d0, tau), N(d0, tau), L(d1, tau)
    ctx.check("28", "order p^0 of (14): L(delta0) = 0", "series of (15) in p, SymPy",
              lambda: symbolic_zero(order0 - L0))
    ctx.check("30", "order p^1 of (14): L(delta1) = L(delta0) - N(delta0), i.e. -N(delta0) by (28)",
              "series of (15) in p, SymPy", lambda: symbolic_zero(sp.expand(order1 - (L1 - L0 + N0))))

    # (29), (31): delta(0) = 0 and delta'(0) = 1 for every p give the conditions order by order.
    a0, a1, b0, b1 = sp.symbols("a0 a1 b0 b1")
    ic = sp.solve([sp.Poly(a0 + p * a1, p).coeff_monomial(1),
                   sp.Poly(a0 + p * a1, p).coeff_monomial(p),
                   sp.Poly(b0 + p * b1 - 1, p).coeff_monomial(1),
                   sp.Poly(b0 + p * b1 - 1, p).coeff_monomial(p)], [a0, a1, b0, b1], dict=True)[0]
    ctx.check("29,31", "delta0(0)=0, delta0'(0)=1, delta1(0)=delta1'(0)=0 from delta(0)=0, delta'(0)=1 "
              "for all p", "coefficients of p^0, p^1 solved by SymPy",
              lambda: (ic == {a0: 0, a1: 0, b0: 1, b1: 0}, f"solution {ic}"))

    ctx.expr.update(taylor_sqrt=t_sqrt, taylor_32=t_32, order0_eq=order0, order1_eq=order1)
    ctx.symbols.update(delta0_value=D0, delta1_value=D1)
    ctx.eq("12", sp.Symbol(r"\mathcal{L}(\bar\delta)"),
           sp.Symbol(r"\ddot{\bar\delta} + k\lambda\dot{\bar\delta} + k\bar\delta"), "auxiliary linear operator")
    ctx.eq("13", sp.Symbol(r"\mathcal{N}(\bar\delta)"),
           sp.Symbol(r"\ddot{\bar\delta} + \tfrac{3}{2}\lambda\sqrt{\bar\delta}\,\dot{\bar\delta} + \bar\delta^{3/2}"),
           "nonlinear operator (Zener's equation 10)")
    ctx.eq("14", sp.Symbol(r"(1-p)\mathcal{L}(\bar\delta) + p\,\mathcal{N}(\bar\delta)"), 0,
           "zero-order deformation equation")
    ctx.eq("16", sp.Symbol(r"\bar\delta"), sp.Symbol(r"\bar\delta_0 + \sum_{i\ge1}\bar\delta_i p^i"),
           "homotopy series")
    ctx.eq("26", sp.sqrt(D0 + p * D1), want_sqrt + sp.O(p**3), "Taylor expansion in p")
    ctx.eq("27", (D0 + p * D1) ** three_half, want_32 + sp.O(p**3), "Taylor expansion in p")
    ctx.eq("28", sp.Symbol(r"\ddot{\bar\delta}_0 + k\lambda\dot{\bar\delta}_0 + k\bar\delta_0"), 0,
           "order p^0, with (29): delta0(0) = 0, delta0'(0) = 1")
    ctx.eq("29", sp.Symbol(r"\bar\delta_0(0) = 0,\quad \dot{\bar\delta}_0(0)"), 1, "initial conditions at order p^0")
    ctx.eq("31", sp.Symbol(r"\bar\delta_1(0) = 0,\quad \dot{\bar\delta}_1(0)"), 0, "initial conditions at order p^1")
    ctx.eq("30", sp.Symbol(r"\ddot{\bar\delta}_1 + k\lambda\dot{\bar\delta}_1 + k\bar\delta_1"),
           sp.Symbol(r"-\left(\ddot{\bar\delta}_0 + \tfrac{3}{2}\lambda\sqrt{\bar\delta_0}\,"
                     r"\dot{\bar\delta}_0 + \bar\delta_0^{3/2}\right)"),
           "order p^1, with (31): delta1(0) = delta1'(0) = 0")
    return {"taylor_sqrt", "taylor_32", "order0_eq", "order1_eq"}

