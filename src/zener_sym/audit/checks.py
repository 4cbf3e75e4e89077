"""One check per printed equation or definition: which derived form it is compared with, and how.

Each check returns ``(verdict, derived_text, evidence, note)``. The printed side always comes from
:mod:`.printed` (``printed.parse``), so a changed transcription changes the verdict; the derived
side comes from :mod:`.derived` (registry first) or from a few SymPy lines here that start from an
earlier equation of the paper (named in the evidence).
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from . import derived as D
from . import printed as P
from .verdicts import _L, _M, _Ts, compare, dimension, equal_up_to_factor, rounds_to

S = P.SYM
lam, tau, k, beta, omega0, p, x, y = (S[n] for n in "lam tau k beta omega0 p x y".split())
t, V0, ms, m1, Es, R = (S[n] for n in "t V0 ms m1 Es R".split())
CHECKS: dict = {}


def check(*ids):
    def deco(fn):
        for i in ids:
            CHECKS[i] = fn
        return fn
    return deco


def _p(item_id):
    return P.parse(P.by_id(item_id))


def _cmp(item_id, derived, source, what="", transform=None, note_ok="", note_bad=""):
    pr = _p(item_id)
    ok, ev = compare(pr if transform is None else transform(pr), derived)
    verdict = "consistent" if ok else "typo"
    note = note_ok if ok else note_bad
    return verdict, str(derived), f"{what + '; ' if what else ''}{ev}; derived form: {source}", note


def _named(item_id, name, *, what="", sub=None, note_ok="", note_bad=""):
    expr, src = D.get(name)
    if sub:
        expr = sub(expr)
    return _cmp(item_id, expr, src, what=what, note_ok=note_ok, note_bad=note_bad)


# ---- the dimensionless core -------------------------------------------------------------------
@check("1")
def _eq1():
    d = P.d
    derived = d(t).diff(t, 2) + S["kc"] * d(t) ** sp.Rational(3, 2)
    pr = _p("1")
    ok, ev = equal_up_to_factor(pr.lhs - pr.rhs, derived)
    return ("consistent" if ok else "typo", "Derivative(d(t), t, 2) + kc*d(t)**(3/2)",
            f"Eq. (7) with alpha = 0 and Hertz's law (8) gives delta^(3/2) (kc = 4 E* R^(1/2)/(3 m)); "
            f"{ev}", "" if ok else "the Hertz force is delta^(3/2), not delta^3")


@check("10")
def _eq10():
    # Substitute delta = T V0 dbar(tau), t = T tau into (7) with F of (8), divide by V0/T.
    d, db = P.d, sp.Function("db")
    T = D.get("T")[0]
    alpha = S["alpha"]
    F = sp.Rational(4, 3) * Es * sp.sqrt(R) * (T * V0 * db(tau)) ** sp.Rational(3, 2)
    eq7 = (V0 / T) * db(tau).diff(tau, 2) + F / ms + alpha / T * sp.diff(F, tau)
    red = sp.expand(sp.powsimp(sp.expand_power_base(eq7 * T / V0, force=True), force=True))
    lam_phys = D.get("lam_phys_alpha")[0]
    red = red.subs(alpha, lam * alpha / lam_phys)  # name the coefficient of the d/dtau term lambda
    red = sp.simplify(red).subs(db, d)
    pr = _p("10")
    ok, ev = equal_up_to_factor(pr.lhs - pr.rhs, red)
    return ("consistent" if ok else "typo", f"{red} = 0",
            f"Eq. (7)+(8) in the scales (9) with T = {D.get('T')[0]}; {ev}", "")


@check("12")
def _eq12():
    return ("not-checkable", "", "definition of the auxiliary linear operator (a choice of the "
            "method); its use is checked through (15) and (28)", "a choice, nothing to derive")


@check("13")
def _eq13():
    pr = _p("13")
    e10 = _p("10")
    ok, ev = compare(pr, e10.lhs - e10.rhs)
    return ("consistent" if ok else "typo", str(e10.lhs), f"N must be the operator of Eq. (10); {ev}", "")


@check("14", "16", "37")
def _definitions():
    return ("not-checkable", "", "a definition (homotopy, series ansatz, variation-of-constants "
            "ansatz): nothing to derive", "definition")


def _Lop(f):
    return f.diff(tau, 2) + (f + lam * f.diff(tau)) * k


def _N(f):
    return f.diff(tau, 2) + f ** sp.Rational(3, 2) + lam * sp.diff(f ** sp.Rational(3, 2), tau)


@check("15")
def _eq15():
    d = P.d
    derived = sp.expand((1 - p) * _Lop(d(tau)) + p * _N(d(tau)))
    return _cmp("15", derived, "(1 - p) L + p N with L, N of (12), (13), expanded here")


@check("17")
def _eq17():
    # delta'' = y dy/ddelta with y = delta'; d/dtau delta^(3/2) = (3/2) sqrt(delta) y
    yf = P.yf
    derived = yf(x) * yf(x).diff(x) + sp.Rational(3, 2) * lam * sp.sqrt(x) * yf(x) + x ** sp.Rational(3, 2)
    return _cmp("17", derived, "Eq. (10) with y = d delta/d tau as a function of delta (derived here)")


@check("18")
def _eq18():
    yf = P.yf
    derived = sp.expand((yf(x) * yf(x).diff(x) + sp.Rational(3, 2) * lam * sp.sqrt(x) * yf(x)) / yf(x))
    return _cmp("18", derived, "(17)/y without the delta^(3/2)/y term (dominant for large lambda)")


@check("19")
def _eq19():
    yy = sp.Function("yy")
    sol = sp.dsolve(yy(x).diff(x) + sp.Rational(3, 2) * lam * sp.sqrt(x), yy(x), ics={yy(0): 1}).rhs
    return _cmp("19", sol, "dsolve of (18) with y(0) = 1 (derived here)")


@check("20")
def _eq20():
    return _named("20", "dm_mthreehalves_inf", what="root of y = 0 in (19)")


@check("21")
def _eq21():
    yf = P.yf
    return _cmp("21", yf(x) * yf(x).diff(x) + x ** sp.Rational(3, 2), "(17) at lambda = 0")


@check("22")
def _eq22():
    yy = sp.Function("yy")
    sols = sp.dsolve(yy(x) * yy(x).diff(x) + x ** sp.Rational(3, 2), yy(x))
    sols = sols if isinstance(sols, list) else [sols]
    C1 = sp.Symbol("C1")
    for s_ in sols:
        c = sp.solve(s_.rhs.subs(x, 0) - 1, C1)
        if c:
            cand = s_.rhs.subs(C1, c[0])
            if sp.N(cand.subs(x, sp.Rational(1, 10))) > 0:
                return _cmp("22", cand, "dsolve of (21) with y(0) = 1, positive branch (derived here)")
    return ("not-checkable", "", "dsolve gave no branch with y(0) = 1", "")


@check("23")
def _eq23():
    return _named("23", "dm_lam0", what="root of y = 0 in (22)")


@check("24")
def _eq24():
    return _named("24", "dm_interp_m32", what="(20) + value of (23)^(-3/2): lambda + (5/4)^(-3/5)",
                  note_bad="the constant is (5/4)^(-3/5) = dm(0)^(-3/2), not (5/4)^(-3/2)")


@check("25")
def _eq25():
    return _named("25", "k_of_lam", note_bad="inner constant (5/4)^(-3/5), not (5/4)^(-3/2)")


def _series_check(item_id, func):
    d0, d1 = P.d0, P.d1
    a, b = sp.symbols("a b", positive=True)
    ser = sp.series(func(a + p * b), p, 0, 3).removeO()
    derived = ser.subs({a: d0(tau), b: d1(tau)})
    return _cmp(item_id, derived, "SymPy series in p to O(p^3) (derived here)")


@check("26")
def _eq26():
    r = _series_check("26", sp.sqrt)
    return r


@check("27")
def _eq27():
    v, dv, ev, note = _series_check("27", lambda z: z ** sp.Rational(3, 2))
    return v, dv, ev, "" if v == "consistent" else "the p term is (3/2) sqrt(d0) d1 p: d1 is missing"


def _orders():
    d0, d1 = P.d0, P.d1
    f = d0(tau) + p * d1(tau)
    hom = (1 - p) * _Lop(f) + p * _N(f)
    ser = sp.expand(sp.series(hom, p, 0, 2).removeO())
    return ser.coeff(p, 0), ser.coeff(p, 1)


@check("28")
def _eq28():
    o0, _ = _orders()
    return _cmp("28", o0, "order p^0 of (14) with the series (16), by SymPy series (derived here)")


@check("30")
def _eq30():
    o0, o1 = _orders()
    derived = o1 + o0  # o1 = L(d1) + N(d0) - L(d0), o0 = L(d0) = 0 by (28)
    pr = _p("30")
    ok, ev = equal_up_to_factor(pr.lhs - pr.rhs, derived)
    return ("consistent" if ok else "typo", f"{derived} = 0",
            f"order p^1 of (14), using (28) L(d0) = 0; {ev}", "")


def _ics(item_id):
    # delta(0) = d0(0) + p d1(0) = 0 and delta'(0) = d0'(0) + p d1'(0) = 1 for every p.
    a0, a1, b0, b1 = sp.symbols("a0 a1 b0 b1")
    eqs = sp.Poly(a0 + p * a1, p).all_coeffs()[::-1] + sp.Poly(b0 + p * b1 - 1, p).all_coeffs()[::-1]
    sol = sp.solve(eqs, [a0, a1, b0, b1], dict=True)[0]
    derived = (sol[a0], sol[b0]) if item_id == "29" else (sol[a1], sol[b1])
    pr = tuple(_p(item_id))
    ok = pr == tuple(derived)
    return ("consistent" if ok else "typo", str(derived),
            f"the initial conditions of (10) do not depend on p: the orders p^0, p^1 of "
            f"delta(0) = 0, delta'(0) = 1 with the series (16) give (d0(0), d0'(0)) = "
            f"({sol[a0]}, {sol[b0]}), (d1(0), d1'(0)) = ({sol[a1]}, {sol[b1]})", "")


CHECKS["29"] = lambda: _ics("29")
CHECKS["31"] = lambda: _ics("31")


@check("32")
def _eq32():
    return _named("32", "beta_of_lam", note_bad="should be lam/2 (lam + (5/4)^(-3/5))^(-1/3)")


@check("33")
def _eq33():
    return _named("33", "omega0_of_lam",
                  note_bad="exponents -1/3 and -2/3 and constant (5/4)^(-3/5)")


@check("34")
def _eq34():
    pr = _p("34")
    res = sp.simplify(_Lop(pr).subs({k: beta**2 + omega0**2, lam: 2 * beta / (beta**2 + omega0**2)}))
    ok = res == 0
    return ("consistent" if ok else "typo", "exp(-beta tau)(c1 sin + c2 cos) solves (28)",
            f"substituted into (28) with k = beta^2 + omega0^2, k lam = 2 beta: residual {res}", "")


@check("35")
def _eq35():
    return _named("35", "delta0", what="dsolve of (28)-(29)")


def _forcing_local():
    return D.get("forcing")


@check("36")
def _eq36():
    f, src = D.get("forcing")
    f = f.subs(lam, 2 * beta / (beta**2 + omega0**2))
    pr = _p("36").subs(lam, 2 * beta / (beta**2 + omega0**2))
    ok, ev = compare(pr, f)
    return ("consistent" if ok else "typo", str(f),
            f"f = -(d0'' + 3/2 lam sqrt(d0) d0' + d0^(3/2)) with d0 of (35), lam = 2 beta/k; {ev}; "
            f"derived form: {src}", "")


@check("38")
def _eq38():
    # Variation of constants: with d1 = e^(-beta tau)(A s + B c) and A' s + B' c = 0,
    # L(d1) = e^(-beta tau) omega0 (A' c - B' s) + (terms in the constraint and its derivative).
    A, B, g = sp.Function("A"), sp.Function("B"), sp.Function("g")
    s_, c_ = sp.sin(omega0 * tau), sp.cos(omega0 * tau)
    d1 = sp.exp(-beta * tau) * (A(tau) * s_ + B(tau) * c_)
    Lsub = {k: beta**2 + omega0**2, lam: 2 * beta / (beta**2 + omega0**2)}
    Ld1 = _Lop(d1).subs(Lsub)
    cons = A(tau).diff(tau) * s_ + B(tau).diff(tau) * c_
    rest = Ld1 - sp.exp(-beta * tau) * omega0 * (A(tau).diff(tau) * c_ - B(tau).diff(tau) * s_)
    resid = sp.simplify(rest - sp.diff(sp.exp(-beta * tau) * cons, tau) - 2 * beta * sp.exp(-beta * tau)
                        * cons + beta * sp.exp(-beta * tau) * cons)
    resid = sp.simplify(sp.expand(resid))
    ok_vc = resid == 0
    pr = _p("38")
    Fs = S["F"]
    derived = sp.Eq(A(tau).diff(tau) * c_ - B(tau).diff(tau) * s_, sp.exp(beta * tau) * Fs / omega0)
    prr = (pr.lhs - pr.rhs).subs({P.C11: A, P.C12: B})
    same = sp.simplify(prr - (derived.lhs - derived.rhs)) == 0
    ok = ok_vc and same
    return ("consistent" if ok else "typo", str(derived),
            f"L(d1) - e^(-beta tau) omega0 (C11' c - C12' s) reduces to the constraint and its "
            f"derivative (residual {resid}); printed second line {'matches' if same else 'differs'}", "")


@check("39")
def _eq39():
    expr, src = D.get("C11_prime")
    f, _ = D.get("forcing")
    return _cmp("39", expr, src, what="solving (38) for C11' (C12' likewise)",
                transform=lambda e: e.subs(S["F"], f))


def _elem(expr):
    """The elementary part of an expression in sqrt(sin): drop the terms with fractional powers."""
    s_ = sp.sin(omega0 * tau)
    terms = sp.Add.make_args(sp.expand(expr))
    return sp.Add(*[tt for tt in terms if not any(
        b == s_ and not e.is_integer for b, e in (a.as_base_exp() for a in sp.Mul.make_args(tt)))])


def _check_C(item_id):
    which = "C11" if item_id == "40" else "C12"
    prime, src = D.get(f"{which}_prime")
    prime = sp.expand(prime.subs(lam, 2 * beta / (beta**2 + omega0**2)))
    sub_lam = {lam: 2 * beta / (beta**2 + omega0**2)}
    elem_d = _elem(prime)
    pr = _p(item_id).subs(sub_lam)
    names = ("C111", "C112") if which == "C11" else ("C121", "C122")
    pieces = {x: sp.diff(_p(names[0]), tau), y: sp.diff(_p(names[1]), tau)}
    elem_p = sp.expand(pr.subs({P.C11(tau): 0, P.C12(tau): 0}).subs(pieces))
    ok_e, ev_e = compare(elem_p, elem_d)
    s_, c_ = sp.sin(omega0 * tau), sp.cos(omega0 * tau)
    # The sqrt part: C123 = C114 is printed, and (41)'s C123 coefficient fixes
    # C123' = e^(-beta tau/2) s^(3/2) c; with that normalisation check the C114 term of (40) and
    # the C124 term of (41) (C124' = e^(-beta tau/2) s^(5/2)).
    g = sp.exp(-beta * tau / 2)
    sqrt_d = sp.expand(prime - elem_d)
    if which == "C11":
        coef_p = pr.coeff(P.C12(tau))
        integrand = g * s_ ** sp.Rational(3, 2) * c_
        label = "C114"
    else:
        coef_p = pr.coeff(P.C12(tau))
        integrand = g * s_ ** sp.Rational(5, 2)
        label = "C124"
    coef_d = sp.simplify(sp.expand(sqrt_d).coeff(s_ ** sp.Rational(3 if which == "C11" else 5, 2)) / (g * (c_ if which == "C11" else 1)))
    ok_s, ev_s = compare(coef_p, coef_d)
    ok = ok_e and ok_s
    return ("consistent" if ok else "typo", f"d/dtau {which} = {prime}",
            f"elementary part ({names[0]}, {names[1]} terms) vs {which}' of (39): {ev_e}; "
            f"{label} term, normalised ({'by the printed C123 = C114 and the C123 term of (41)' if label == 'C114' else 'by the check of the printed C124'}) as the integral of "
            f"{integrand}: coefficient printed {coef_p}, derived {coef_d}: {ev_s}; derived form: {src}",
            "" if ok else ("elementary part disagrees" if not ok_e else
                           f"the {label} coefficient needs omega0^(5/2), not omega0^(3/2)"
                           + (" (or C123 = C114 is the slip)" if label == "C114" else
                              " (C124's normalisation is confirmed by its own check)")))


CHECKS["40"] = lambda: _check_C("40")
CHECKS["41"] = lambda: _check_C("41")


@check("42")
def _eq42():
    # delta1 = e^(-beta tau)((C11 - C11(0)) s + (C12 - C12(0)) c) with the constraint: ICs (31)?
    A, B = sp.Function("A"), sp.Function("B")
    s_, c_ = sp.sin(omega0 * tau), sp.cos(omega0 * tau)
    d1 = sp.exp(-beta * tau) * ((A(tau) - A(0)) * s_ + (B(tau) - B(0)) * c_)
    v0 = sp.simplify(d1.subs(tau, 0))
    dd = sp.diff(d1, tau)
    # use the constraint A' s + B' c = 0 of (38)
    dd = dd.subs(B(tau).diff(tau), -A(tau).diff(tau) * s_ / c_)
    v1 = sp.simplify(dd.subs(tau, 0).doit())
    ok = v0 == 0 and v1 == 0
    pr = _p("42")
    derived = P.d0(tau) + d1.subs({A: P.C11, B: P.C12})
    same = sp.simplify(pr - derived) == 0
    return ("consistent" if ok and same else "typo", str(derived),
            f"delta1 = e^(-beta tau)((C11(tau)-C11(0)) sin + (C12(tau)-C12(0)) cos) meets (31): "
            f"delta1(0) = {v0}, delta1'(0) = {v1} (with the constraint of (38)); printed "
            f"{'matches' if same else 'differs'}", "")


@check("45")
def _eq45():
    # F / F_scale = (4/3) Es sqrt(R) (T V0 dbar)^(3/2) / (ms V0 / T)
    T = D.get("T")[0]
    Fs, src = D.get("F_scale")
    db = P.d(tau)
    derived = sp.simplify(sp.Rational(4, 3) * Es * sp.sqrt(R) * (T * V0 * db) ** sp.Rational(3, 2) / Fs)
    return _cmp("45", derived, src, what="F of (8) over the force scale")


@check("49")
def _eq49():
    # delta1 must vanish at tau = 0 (31). Printed (49): delta1 = sin/(2 omega0) + C11^d sin + C12^d cos,
    # so delta1(0+) = C12^d(0+); evaluate it, with the printed C12^d and with its power 7/5 -> 7/2.
    C111_0 = _p("C111").subs(tau, 0)
    ok_term, _ = compare(_p("49"), -C111_0 * sp.sin(omega0 * tau))
    d1 = _p("49") + _p("C11^d") * sp.sin(omega0 * tau) + _p("C12^d") * sp.cos(omega0 * tau)
    fixed = d1.subs(sp.Rational(7, 5), sp.Rational(7, 2))
    a1, a2 = _limit0(d1)
    b1, b2 = _limit0(fixed)
    ok = abs(a2) < 1e-6 and abs(b2) < 1e-6
    return ("consistent" if ok else "typo", "delta1 = (C11(tau) - C11(0)) sin + (C12(tau) - C12(0)) cos "
            "at lambda = 0; delta1(0) = 0",
            f"explicit term sin/(2 omega0) = -C11(0) sin: {ok_term}; printed delta1 at tau = 1e-7, "
            f"1e-9 (omega0 = 1): {complex(a1):.4g}, {complex(a2):.4g}; with C12^d's power 7/2: "
            f"{complex(b1):.6g}, {complex(b2):.6g}; (31) needs 0",
            "" if ok else "a '- C12^d(0) cos(omega0 tau)' term is missing (C12^d(0+) != 0)")


def _check_Cd(item_id):
    which = "C11" if item_id == "C11^d" else "C12"
    prime, src = D.get(f"{which}_prime")
    prime0 = sp.simplify(prime.subs({lam: 0, beta: 0}))
    pr = _p(item_id)
    pr_n = pr.replace(P.G, lambda a, b, c, z: sp.hyper([a, b], [c], z))
    dpr = sp.diff(pr_n, tau)
    ok, ev = _hyper_compare(dpr, prime0)
    return ("consistent" if ok else "typo", f"d/dtau {item_id} = {prime0}",
            f"d/dtau of the printed form vs {which}' of (39) at lambda = 0 (mpmath 30 digits, "
            f"2F1 by mpmath.hyp2f1); {ev}; derived form: {src}",
            "" if ok else ("the power is (sin/omega0)^(5/2)" if which == "C11" else
                           "should be +(4/5) e^(i omega0 tau) G (sin/omega0)^(7/2)"))


CHECKS["C11^d"] = lambda: _check_Cd("C11^d")
CHECKS["C12^d"] = lambda: _check_Cd("C12^d")


def _hyper_compare(a, b, n=5):
    """Compare two expressions of tau, omega0 (possibly with 2F1) with mpmath at 30 digits."""
    fa = sp.lambdify((tau, omega0), a, modules="mpmath")
    fb = sp.lambdify((tau, omega0), b, modules="mpmath")
    worst, at = 0.0, None
    with mp.workdps(30):
        for i in range(n):
            w0 = mp.mpf("0.7") + mp.mpf(i) / 10
            tt = (mp.mpf(i) + mp.mpf("0.5")) / (n + 1) * mp.pi / w0
            va, vb = mp.mpc(fa(tt, w0)), mp.mpc(fb(tt, w0))
            err = abs(va - vb) / max(abs(vb), mp.mpf(10) ** -30)
            if err > worst:
                worst, at = err, (float(tt), float(w0), complex(va), complex(vb))
    if worst < mp.mpf(10) ** -20:
        return True, f"agree at {n} points in (0, pi/omega0) (max rel. diff {float(worst):.1e})"
    return False, (f"at tau={at[0]:.4g}, omega0={at[1]:.4g}: printed {at[2]:.8g}, "
                   f"derived {at[3]:.8g} (rel. diff {float(worst):.3g})")


@check("C124")
def _C124():
    # Is d/dtau of the printed C124 a constant multiple of e^(-beta tau/2) sin^(5/2)?
    pr = _p("C124").replace(P.G, lambda a, b, c, z: sp.hyper([a, b], [c], z))
    dpr = sp.diff(pr, tau)
    target = sp.exp(-beta * tau / 2) * sp.sin(omega0 * tau) ** sp.Rational(5, 2)
    f = sp.lambdify((tau, beta, omega0), dpr / target, modules="mpmath")
    vals = []
    with mp.workdps(30):
        for (tt, b, w0) in ((0.4, 0.3, 0.9), (1.1, 0.3, 0.9), (2.0, 0.3, 0.9), (0.7, 0.6, 0.5)):
            try:
                vals.append(mp.mpc(f(mp.mpf(tt), mp.mpf(b), mp.mpf(w0))))
            except Exception as exc:
                return ("not-checkable", "", f"mpmath could not evaluate: {exc}", "")
    same_beta = vals[:3]
    spread = max(abs(v - same_beta[0]) for v in same_beta) / abs(same_beta[0])
    ok = spread < 1e-20 and abs(vals[0] - 1) < 1e-20 and abs(vals[3] - 1) < 1e-20
    return ("consistent" if ok else "typo", "C124 = integral of e^(-beta tau/2) sin^(5/2)(omega0 tau)",
            f"d/dtau printed / (e^(-beta tau/2) sin^(5/2)) at 4 points (mpmath 30 digits): "
            f"{', '.join(f'{complex(v):.6g}' for v in vals)}",
            "" if ok else "the derivative of the printed form is not the integrand (up to 1)")


@check("C113", "C114", "C123")
def _garbled_C():
    return ("garbled", "", "G(...) printed with 3 arguments run together and misplaced fractions "
            "(e.g. G(1, i beta/2, 1/(4 omega0) - 1/4 i beta/(4 omega0) + 3/4 e^(2 i omega0 tau))); no "
            "2F1(a, b; c; z) can be read off", "derived form: registry C113/C114/C123 (issue 3)")


def _hyp(expr):
    return expr.replace(P.G, lambda a, b, c, z: sp.hyper([a, b], [c], z))


def _limit0(expr, w0=1, b=0, lam_v=0):
    """tau -> 0+ limit of a printed expression of tau (mpmath, 30 digits, two small tau)."""
    f = sp.lambdify(tau, _hyp(expr).subs({omega0: w0, beta: b, lam: lam_v}), modules="mpmath")
    with mp.workdps(30):
        v1, v2 = mp.mpc(f(mp.mpf("1e-7"))), mp.mpc(f(mp.mpf("1e-9")))
    return v1, v2


def _check_C12_0():
    # (42) subtracts C12(0), the value at tau = 0+ of the paper's own C12(tau) of (41). At
    # lambda = 0 every term of (41) is readable: C12 = -C121 + omega0^(-3/2) C124 (C123 has a
    # factor lambda). Compare that limit with the printed C12(0) at lambda = 0.
    pr = _p("C12(0)").subs({beta: 0, lam: 0, omega0: 1})
    c41 = _p("41").subs({P.C11(tau): _p("C123") if _p("C123") is not None else 0,
                         P.C12(tau): _p("C124"), x: _p("C121"), y: _p("C122")})
    c41 = c41.subs({lam: 0, beta: 0})
    v1, v2 = _limit0(c41)
    settled = abs(v1 - v2) < 1e-6 * max(1, abs(v2))
    ok = settled and abs(v2 - complex(pr)) < 1e-6
    return ("consistent" if ok else "typo", f"lim tau->0+ of (41) at lambda = 0, omega0 = 1: "
            f"{complex(v2):.8g}",
            f"at lambda = 0 (omega0 = 1) the printed C12(0) is {pr}; the printed (41) with the printed "
            f"C121 and C124 (whose derivative is checked exactly) tends to {complex(v1):.8g} at "
            f"tau = 1e-7 and {complex(v2):.8g} at 1e-9", "" if ok else
            "C12(0) omits the value of C124 at 0 (a complex constant of its 2F1 form), so "
            "delta1(0) != 0 with the printed constants")


def _check_C11_0():
    # At lambda = 0 the printed C11(0) must be C11^d(0+) of Sec. 3.2; for lambda > 0 it depends on
    # the garbled C113, C114, so only the lambda = 0 value can be compared.
    pr = _p("C11(0)").subs({beta: 0, lam: 0})
    lim = sp.limit(_p("C11^d"), tau, 0, "+")  # elementary: SymPy's limit is exact
    ok0 = sp.simplify(pr - lim) == 0
    return ("not-checkable", f"C11^d(0+) = {lim}",
            f"at lambda = 0: printed C11(0) = {pr} {'equals' if ok0 else 'differs from'} the limit "
            f"of the printed C11^d; for lambda > 0 it depends on the paper's normalisation of the "
            f"garbled C113, C114 (only C(tau) - C(0) is invariant)",
            "needs readable C113/C114")


CHECKS["C11(0)"] = _check_C11_0
CHECKS["C12(0)"] = _check_C12_0


def _check_elem_C(item_id):
    s_, c_ = sp.sin(omega0 * tau), sp.cos(omega0 * tau)
    integrand = {"C111": s_ * c_, "C112": c_**2, "C121": s_**2, "C122": s_ * c_}[item_id]
    d = sp.simplify(sp.diff(_p(item_id), tau) - integrand)
    ok = d == 0
    return ("consistent" if ok else "typo", f"an antiderivative of {integrand}",
            f"d/dtau printed - {integrand} simplifies to {d} (the integrand is fixed by the split of "
            f"(39) in (40)-(41))", "")


for _i in ("C111", "C112", "C121", "C122"):
    CHECKS[_i] = (lambda i: (lambda: _check_elem_C(i)))(_i)


@check("54")
def _eq54():
    return _named("54", "tau_d0_of_lam", note_bad="exponents are -1/3 and -2/3 (k = (lam+c)^(-1/3))")


@check("56")
def _eq56():
    return _named("56", "delta0_dot")


@check("57")
def _eq57():
    return _named("57", "delta0_dot", what="(57) is delta0'(tau_dc) = 0")


@check("58")
def _eq58():
    expr, src = D.get("tau_dc0")
    pr = _p("58")
    ok_root = sp.simplify(D.get("delta0_dot")[0].subs(tau, pr)) == 0
    ok, ev = compare(pr, expr)
    return ("consistent" if ok and ok_root else "typo", str(expr),
            f"printed tau_dc is a root of (57): {ok_root}; {ev}; derived form: {src}", "")


@check("59")
def _eq59():
    return _named("59", "tau_dc0_of_lam", note_bad="constant (5/4)^(-3/5) and exponents -1/3, -2/3")


@check("60")
def _eq60():
    return _named("60", "tau_dr0_of_lam", note_bad="exponents -1/3 and -2/3 in the denominator")


@check("61")
def _eq61():
    return _named("61", "eta0_of_lam")


@check("78")
def _eq78():
    expr, src = D.get("e0")
    pr = _p("78").subs({tau: sp.pi / omega0, k: (beta**2 + omega0**2), lam: 2 * beta / (beta**2 + omega0**2)})
    ok, ev = compare(pr, expr)
    return ("consistent" if ok else "typo", f"|delta0'(tau_d)| = {expr}",
            f"printed evaluated at tau = tau_d = pi/omega0 (sign: delta0'(tau_d) < 0); {ev}; "
            f"derived form: {src}", "reads as the magnitude at tau_d, not a function of tau")


@check("79")
def _eq79():
    expr, src = D.get("e0")
    pr = _p("79").subs({k: beta**2 + omega0**2, lam: 2 * beta / (beta**2 + omega0**2)})
    ok, ev = compare(pr, expr)
    return ("consistent" if ok else "typo", str(expr), f"with k = beta^2 + omega0^2, lam = 2 beta/k; "
            f"{ev}; derived form: {src}", "")


@check("80")
def _eq80():
    return _named("80", "e0_of_lam", note_bad="constant (5/4)^(-3/5), not (5/4)^(-1/3)")


@check("81")
def _eq81():
    kl, src = D.get("k_of_lam")
    derived = 4 / kl - lam**2  # lam <= 2/sqrt(k)  <=>  4/k - lam^2 >= 0
    return _cmp("81", derived, src, what="lam < 2/sqrt(k) as 4/k - lam^2 > 0",
                note_bad="constant (5/4)^(-3/5), not (5/4)^(-1/3)")


# ---- the lambda = 0 numbers ------------------------------------------------------------------
def _w00():
    return D.get("omega0_lam0")


@check("50")
def _eq50():
    w, src = _w00()
    derived = (sp.sin(w * tau) / w) ** sp.Rational(3, 2)
    r = _cmp("50", derived, src, what="delta0^(3/2) at lambda = 0, omega0 = (5/4)^(1/10)")
    pr_const = "0.966"
    ok_c, ev_c = rounds_to(sp.N(w ** sp.Rational(-3, 2)), pr_const)
    return (r[0], f"{derived} = {sp.N(w ** sp.Rational(-3, 2), 6)} sin^(3/2)({sp.N(w, 6)} tau)",
            r[2] + f"; constant: {ev_c}", "the power is 3/2, not 3/5" if r[0] == "typo" else "")


@check("51")
def _eq51():
    w, src = _w00()
    pr = _p("51")
    ok_c, ev_c = rounds_to(sp.N(sp.Rational(3, 2) / w), "1.467")
    expo = pr.as_base_exp()[1]
    ok = ok_c and expo == sp.Rational(3, 2)
    return ("consistent" if ok else "typo",
            f"(3/(2 omega0) sin + C11^d sin + C12^d cos)^(3/2), 3/(2 omega0) = {sp.N(1.5 / w, 6)}",
            f"exponent printed {expo}, derived 3/2 (F = delta^(3/2), Eq. 45); 1/omega0 + 1/(2 omega0): "
            f"{ev_c}; derived form: {src}", "" if ok else "the power is 3/2, not 3/5")


def _hertz_pulse(which):
    """F_hunter / F_reed in the scales (9), (44): from (3)-(6) with dm/(T V0) = (5/4)^(2/5)."""
    dmb, _ = D.get("dm_lam0")
    om = sp.Float(1.068, 30) / dmb  # frequency in tau: 1.068 V0 T/dm
    if which == "hunter":
        amp = dmb * om**2  # m1 dm (1.068 V0/dm)^2 / (m V0 / T)
        return amp * sp.sin(om * tau), om, amp, sp.Integer(1)
    amp = dmb ** sp.Rational(3, 2)  # (4/3) sqrt(R) E* dm^(3/2) / F_scale = dmbar^(3/2)
    return amp * sp.sin(om * tau) ** sp.Rational(3, 2), om, amp, sp.Rational(3, 2)


def _check_pulse(item_id):
    which = "hunter" if item_id == "52" else "reed"
    name = "F_hunter" if which == "hunter" else "F_reed"
    derived, om, amp, expo = _hertz_pulse(which)
    pr = _p(item_id)
    pa = pr.as_coeff_Mul()[0]
    arg = list(pr.atoms(sp.sin))[0].args[0]
    pom = arg.as_coeff_Mul()[0]
    pe = pr.as_coeff_Mul()[1].as_base_exp()[1]
    ok_a, ev_a = rounds_to(amp, f"{float(pa):g}")
    ok_o, ev_o = rounds_to(om, f"{float(pom):g}")
    ok_e = pe == expo
    ok = ok_a and ok_o and ok_e
    src = "derived in the audit from (4)-(6) and the scales (9), (44)"
    try:
        D.get(name)
        src += f"; registry {name} exists"
    except D.NotAvailable:
        pass
    return ("consistent" if ok else "typo", f"{sp.N(amp, 6)} sin^{expo}({sp.N(om, 6)} tau)",
            f"amplitude {ev_a}; frequency {ev_o}; power printed {pe}, derived {expo}; {src}",
            "" if ok else "Reed's pulse has sin^(3/2), not sin^3" if ok_a and ok_o else "")


CHECKS["52"] = lambda: _check_pulse("52")
CHECKS["53"] = lambda: _check_pulse("53")


@check("71")
def _eq71():
    ser = sp.series(_p("70"), lam, 0, 5).removeO()
    pr = _p("71")
    bad = []
    for n in range(1, 5):
        ok, ev = rounds_to(abs(ser.coeff(lam, n)), f"{float(abs(pr.coeff(lam, n))):.3f}")
        if not ok or sp.sign(ser.coeff(lam, n)) != sp.sign(pr.coeff(lam, n)):
            bad.append(f"lam^{n}: {ev}")
    return ("consistent" if not bad else "typo", str(sp.N(ser, 6)),
            "Taylor series of the printed (70) to lam^4, coefficients compared at the printed "
            f"3 decimals{': ' + '; '.join(bad) if bad else ': all agree'}", "")


@check("69")
def _eq69():
    return _cmp("69", 1 - (1 - x) ** 2, "(67)-(68) with V-bar = 1 - I-bar of (64)")


@check("64")
def _eq64():
    return _cmp("64", sp.Integer(1) - x, "(63) divided by m1 V0 with m* ~ m1")


# ---- physical-unit equations: dimensional analysis, then the derived scale --------------------
_TIME, _LEN, _FORCE = _Ts, _L, _M * _L / _Ts**2


def _dims_then(item_id, want, what, derived=None, src="", transform=None, extra=None):
    pr = _p(item_id)
    expr = pr if transform is None else transform(pr)
    dim = dimension(expr, extra)
    ok_dim = dim is not None and sp.simplify(dim / want) == 1
    ev = f"dimensions of printed {what}: {dim}, required {want}"
    if not ok_dim:
        return "typo", str(derived) if derived is not None else "", ev + (
            f"; derived form: {src}" if src else ""), "dimensionally wrong"
    if derived is None:
        return "consistent", "", ev + " (dimensional analysis only)", ""
    ok, ev2 = compare(expr, derived)
    return ("consistent" if ok else "typo", str(derived), f"{ev}; {ev2}; derived form: {src}", "")


@check("2")
def _eq2():
    T, src = D.get("T")
    tH = sp.Float("2.94") * (sp.Rational(5, 4)) ** sp.Rational(2, 5) * T  # 2.94 dm(0) T
    mh = S["mh"]
    derived = tH.subs(ms, m1 * mh / (m1 + mh))
    return _dims_then("2", _TIME, "T_Hertz", derived, src + "; T_Hertz = 2.94 delta_m/V0 with (3)")


@check("3")
def _eq3():
    sc, src = D.get("delta_scale")
    dm0, _ = D.get("dm_lam0")
    mh = S["mh"]
    return _dims_then("3", _LEN, "delta_m", (sc * dm0).subs(ms, m1 * mh / (m1 + mh)),
                      src + "; delta_m = T V0 dm(0)")


@check("4")
def _eq4():
    r = _dims_then("4", _LEN, "delta(t)", None)
    ok, ev = rounds_to(sp.pi / sp.Float("2.94", 30), "1.068")
    return ("consistent" if r[0] == "consistent" and ok else "typo", "dm sin(pi/2.94 V0 t/dm)",
            r[2] + f"; half period = T_Hertz = 2.94 dm/V0 gives pi/2.94: {ev}", "")


@check("5")
def _eq5():
    derived = m1 * sp.diff(_p("4"), t, 2)
    return _dims_then("5", _FORCE, "F", derived, "m1 d^2/dt^2 of (4)")


@check("6")
def _eq6():
    derived = -sp.Rational(4, 3) * Es * sp.sqrt(R) * _p("4") ** sp.Rational(3, 2)
    return _dims_then("6", _FORCE, "F", derived, "Hertz's law (8) applied to (4), sign as in (5)")


@check("7")
def _eq7():
    pr = _p("7")
    dims = [dimension(tt) for tt in sp.Add.make_args(pr.lhs - pr.rhs)]
    ok = all(dd is not None and sp.simplify(dd / dims[0]) == 1 for dd in dims)
    return ("consistent" if ok else "typo", "", f"dimensions of the three terms: {dims} "
            "(dimensional analysis only; the equation is Zener's model)", "")


@check("8")
def _eq8():
    return _dims_then("8", _FORCE, "F", None)


@check("9")
def _eq9():
    T, src = D.get("T")
    dT = dimension(T)
    ok = dT is not None and sp.simplify(dT / _TIME) == 1
    return ("consistent" if ok else "typo", "delta-bar = delta/(T V0), tau = t/T",
            f"with the derived T ({dT}) both ratios are dimensionless; derived form: {src}", "")


@check("11")
def _eq11():
    lp, src = D.get("lam_phys_Es")
    return ("garbled", str(lp), "the printed (11) has an XML cross-reference "
            "(<ce:texref>... Lalanne ...) in place of a factor; derived form: " + src,
            "reading the junk as (R/H)^2, the exponents pi^(3/2), (V0/VW)^(1/2), (rho1/rho2)^(3/2), "
            "(...)^(2/3) would all be typos of 3/5, 1/5, 3/5, 2/5")


@check("T")
def _T():
    T, src = D.get("T")
    return _dims_then("T", _TIME, "T", T, src)


@check("alpha")
def _alpha():
    a, src = D.get("alpha")
    return _dims_then("alpha", _Ts / _M, "alpha", a, "Zener's coefficient, checked by units: alpha "
                      "dF/dt must be an acceleration")


@check("V_W")
def _VW():
    v, src = D.get("V_W")
    return _dims_then("V_W", _L / _Ts, "V_W", v, "quasi-longitudinal plate wave speed (Landau et al.)")


@check("chi")
def _chi():
    c, src = D.get("chi")
    return _dims_then("chi", (_L / _Ts) ** sp.Rational(-1, 5), "chi", c,
                      src + "; chi = 2 lambda / ((R/H)^2 V0^(1/5)), m* = (4/3) pi R^3 rho1")


def _check_Fscale(item_id):
    Fs, src = D.get("F_scale")
    return _dims_then(item_id, _FORCE, "force scale", Fs, src + "; F scale = m* V0 / T")


CHECKS["43"] = lambda: _check_Fscale("43")
CHECKS["44"] = lambda: _check_Fscale("44")


@check("47")
def _eq47():
    Fs, _ = D.get("F_scale")
    T, _ = D.get("T")
    Is, src = D.get("I_scale")
    ok = sp.simplify(Fs * T - Is) == 0
    return ("consistent" if ok else "typo", "I-bar = integral of F-bar dtau with I = F_scale T I-bar",
            f"F scale x T = {sp.simplify(Fs * T)} = I scale: {ok}; derived form: {src}", "")


@check("48")
def _eq48():
    Is, src = D.get("I_scale")
    return _dims_then("48", _M * _L / _Ts, "impulse scale", Is, src)


CHECKS["46"] = lambda: _dims_then("46", _M * _L / _Ts, "I (definition)", None)
CHECKS["73"] = lambda: _dims_then("73", _M * _L**2 / _Ts**2, "W (definition)", None)


@check("62")
def _eq62():
    return _dims_then("62", _M * _L / _Ts, "m1 V", None)


@check("63")
def _eq63():
    Is, src = D.get("I_scale")
    return _dims_then("63", _M * _L / _Ts, "m1 V", m1 * V0 - Is * x, src + "; (62) with I = I-scale I-bar")


@check("65")
def _eq65():
    a, _ = D.get("alpha")
    return _dims_then("65", _L, "w", a * S["I"], "w = alpha I (Zener's plate deflection)")


@check("66")
def _eq66():
    ws, src = D.get("w_scale")
    a, _ = D.get("alpha")
    return _dims_then("66", _L, "deflection scale", ws.subs(S["alpha"], a), src)


@check("67")
def _eq67():
    return _dims_then("67", _M * _L**2 / _Ts**2, "W", None)


@check("68")
def _eq68():
    return _dims_then("68", sp.Integer(1), "xi", None)


@check("72")
def _eq72():
    lp, src = D.get("lam_phys")
    ex_V = sp.simplify(V0 * sp.diff(lp, V0) / lp)
    ex_H = sp.simplify(S["H"] * sp.diff(lp, S["H"]) / lp)
    ok = ex_V == sp.Rational(1, 5) and ex_H == -2
    return ("consistent" if ok else "typo", f"xi ~ 2 lambda int F^2 ~ lambda, lambda ~ (R/H)^2 V0^{ex_V}",
            f"log-derivatives of the derived lambda: V0 -> {ex_V}, H -> {ex_H}; derived form: {src}", "")


@check("74")
def _eq74():
    a, _ = D.get("alpha")
    return _dims_then("74", _M * _L**2 / _Ts**2, "W", a * x, "W = int F dw = alpha int F^2 dt",
                      extra={x: (_M * _L / _Ts**2) ** 2 * _Ts})


@check("75")
def _eq75():
    Ws, src = D.get("W_scale")
    lp, _ = D.get("lam_phys_Es")
    chi, _ = D.get("chi")
    derived = sp.Rational(1, 2) * chi * ms * V0 ** sp.Rational(11, 5) * (R / S["H"]) ** 2 * x
    return _dims_then("75", _M * _L**2 / _Ts**2, "W", derived,
                      src + "; W = alpha F_scale^2 T int = lambda m* V0^2 int, lambda = chi/2 (R/H)^2 V0^(1/5)",
                      extra={S["chi"]: (_L / _Ts) ** sp.Rational(-1, 5)})


def _check_xi(item_id):
    chi, src = D.get("chi")
    base = S["chi"] * V0 ** sp.Rational(1, 5) * (R / S["H"]) ** 2
    derived = base * x if item_id == "76" else base * sp.Float("1.78")
    r = _dims_then(item_id, sp.Integer(1), "xi", derived,
                   "xi = 2 lambda int F-bar^2 with lambda = chi/2 (R/H)^2 V0^(1/5)",
                   extra={S["chi"]: (_L / _Ts) ** sp.Rational(-1, 5)})
    note = "V0^(1/5), not V0^(1/2)" if r[0] == "typo" else ""
    return r[0], r[1], r[2], note


CHECKS["76"] = lambda: _check_xi("76")
CHECKS["77"] = lambda: _check_xi("77")


@check("omega0(0)")
def _w0():
    w, src = _w00()
    return _cmp("omega0(0)", w, src, what="omega0 of (33) at lambda = 0 = sqrt(k(0))")
