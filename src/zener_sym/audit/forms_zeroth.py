"""Checks of the zeroth-order closed forms: Eqs. (24), (25), (32), (33), (35), (54)-(61),
(78)-(81) and omega_0(0), each against its derived form (:mod:`.derived`)."""
from __future__ import annotations

import sympy as sp

from . import derived
from .forms_core import LAM_OF_BETA
from .printed import SYM
from .registry import check, compare_form, named_form, printed_form, sentences, source
from .texts import tex
from .verdicts import Verdict, compare

lam, tau, k, beta, omega0 = (SYM[n] for n in ("lam", "tau", "k", "beta", "omega0"))

_EXPONENTS = r"the exponents are $-1/3$ and $-2/3$"
#: item -> (derived name, how the derived form is obtained, note when the printed form differs)
NAMED = {
    "24": ("dm_interp_m32", r"(20) plus the value of (23) to the power $-3/2$: $\lambda + (5/4)^{-3/5}$",
           r"the constant is $(5/4)^{-3/5} = \bar\delta_m(0)^{-3/2}$, not $(5/4)^{-3/2}$"),
    "25": ("k_of_lam", r"$k = \sqrt{\bar\delta_m}$ with $\bar\delta_m$ of (24)",
           r"the inner constant is $(5/4)^{-3/5}$, not $(5/4)^{-3/2}$"),
    "32": ("beta_of_lam", r"$\beta = k\lambda/2$ with $k$ of (25)",
           r"the outer exponent is $-1/3$ and the constant $(5/4)^{-3/5}$: "
           r"$\beta = \frac{\lambda}{2}(\lambda + (5/4)^{-3/5})^{-1/3}$"),
    "33": ("omega0_of_lam", r"$\omega_0 = \sqrt{4k - k^2\lambda^2}/2$ with $k$ of (25)",
           _EXPONENTS + r" and the constant $(5/4)^{-3/5}$"),
    "35": ("delta0", "SymPy's dsolve of (28) with (29)", ""),
    "54": ("tau_d0_of_lam", r"$\tau_d = \pi/\omega_0$ with $\omega_0$ of (33)",
           _EXPONENTS + r" ($k = (\lambda + (5/4)^{-3/5})^{-1/3}$)"),
    "56": ("delta0_dot", "", ""),
    "57": ("delta0_dot", r"(57) is $\dot{\bar\delta}_0(\tau_{dc}) = 0$", ""),
    "59": ("tau_dc0_of_lam", r"(58) with $\beta$, $\omega_0$ of (32), (33)",
           r"the constant is $(5/4)^{-3/5}$ and the exponents $-1/3$, $-2/3$"),
    "60": ("tau_dr0_of_lam", r"$\tau_d - \tau_{dc}$ with (54) and (59)",
           r"the exponents in the denominator are $-1/3$ and $-2/3$"),
    "61": ("eta0_of_lam", r"$\tau_{dr}/\tau_{dc}$ with (59) and (60)", ""),
    "80": ("e0_of_lam", r"(79) with $\beta$, $\omega_0$ of (32), (33)",
           r"the constant is $(5/4)^{-3/5}$, not $(5/4)^{-1/3}$"),
}


@check(*NAMED)
def _named(item_id: str) -> Verdict:
    name, what, note_bad = NAMED[item_id]
    return named_form(item_id, name, what=what, note_bad=note_bad)


@check("58")
def _eq58(item_id: str) -> Verdict:
    expr, src = derived.get("tau_dc0")
    pr = printed_form(item_id)
    ok_root = sp.simplify(derived.get("delta0_dot")[0].subs(tau, pr)) == 0
    ok, ev = compare(pr, expr)
    return Verdict.form(ok and ok_root, tex(expr), sentences(
        r"the printed $\tau_{dc}$ is a root of (57): " + ("yes" if ok_root else "no"), ev, source(src)))


@check("78")
def _eq78(item_id: str) -> Verdict:
    expr, src = derived.get("e0")
    pr = printed_form(item_id).subs({tau: sp.pi / omega0, k: beta**2 + omega0**2, lam: LAM_OF_BETA})
    ok, ev = compare(pr, expr)
    note = r"reads as the magnitude at $\tau_d$, not as a function of $\tau$"
    return Verdict.form(ok, r"\left|\dot{\bar\delta}_0(\tau_d)\right| = %s" % tex(expr),
                        sentences(r"the printed form evaluated at $\tau = \tau_d = \pi/\omega_0$ (where "
                                  r"$\dot{\bar\delta}_0 < 0$)", ev, source(src)),
                        note_bad=note, note_ok=note)


@check("79")
def _eq79(item_id: str) -> Verdict:
    expr, src = derived.get("e0")
    pr = printed_form(item_id).subs({k: beta**2 + omega0**2, lam: LAM_OF_BETA})
    ok, ev = compare(pr, expr)
    return Verdict.form(ok, tex(expr), sentences(
        r"with $k = \beta^2 + \omega_0^2$ and $\lambda = 2\beta/k$", ev, source(src)))


@check("81")
def _eq81(item_id: str) -> Verdict:
    kl, src = derived.get("k_of_lam")
    der = 4 / kl - lam**2  # lam <= 2/sqrt(k)  <=>  4/k - lam^2 >= 0
    return compare_form(item_id, der, src, what=r"$\lambda < 2/\sqrt{k}$ written as $4/k - \lambda^2 > 0$",
                        note_bad=r"the constant is $(5/4)^{-3/5}$, not $(5/4)^{-1/3}$")


@check("omega0(0)")
def _omega0_lam0(item_id: str) -> Verdict:
    w, src = derived.get("omega0_lam0")
    return compare_form(item_id, w, src, what=r"$\omega_0$ of (33) at $\lambda = 0$, $\sqrt{k(0)}$")
