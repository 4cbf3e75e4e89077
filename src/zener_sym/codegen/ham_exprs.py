"""SymPy expressions of the zeroth- and first-order HAM solution that the kernel builders print.

This module collects, for the code generators, the expressions of the HAM solution of Eq. (10) in
the form numerics needs (stable rewrites, split into what numpy evaluates by quadrature and what
is elementary). Its inputs, k(lambda), lam_crit, delta0 and the forcing (36), come from the
derivation's registry (``zener_sym.derivation.registry.derive(checks=False)``); each is checked
here against a cheap independent local route before use (the registry's own checks run in
``zener-sym derive`` and its tests). On top of them it builds:

* zeroth order (25), (32)-(35), (54), (58), (60), (61), (79): k, beta, omega0, delta0, tau_d,
  tau_dc, tau_dr, eta, e, delta_m0 = delta0(tau_dc), the integral of F0^2 (closed form), lam_crit;
* first order (36)-(42) as the variation-of-constants convolution

      delta1(tau) = (1/omega0) int_0^tau exp(-beta (tau - s)) sin(omega0 (tau - s)) f(s) ds,

  which equals (37) with C1j(tau) - C1j(0). The forcing is split into f_elem + S f_sqrt with
  S = sqrt(sin(omega0 s)). The elementary part is written with P3(x) = (sin x - x cos x)/x^3,
  which removes the 1/omega0^3 cancellation of C11(tau) - C11(0) near the critical lambda and
  near tau = 0; that form is proposed and verified symbolically (it solves (30) with f_elem and
  the zero initial data (31), hence is the convolution). The square-root part is expressed through the integrals
  K_g(a, theta) = int_0^theta exp(-a t) g(t) sqrt(sin t) dt, g in {cos^2, sin cos, sin^2},
  a = beta/(2 omega0): numpy evaluates them by Gauss-Jacobi quadrature (``zener_sym.numerics.sqrt_integrals``),
  mpmath by the closed form below.
* the closed form of J_m(a, theta) = int_0^theta exp((-a + i m) t) sqrt(sin t) dt: with
  z = exp(2 i t), sqrt(sin t) = exp(i (pi/4 - t/2)) (1 - z)^{1/2} / sqrt(2) (principal branch, arg of
  1 - z is t - pi/2 in (-pi/2, pi/2) for 0 < t < pi), so with c = -a + i (m - 1/2), s = c/(2i),

      J_m = exp(i pi/4) / (2 sqrt(2) i) [ exp(c t) 2F1(-1/2, s; s + 1; z) / s ]_{t=0}^{t=theta},

  where exp(c t) is the continuous branch of z^s, and at t = 0 (z = 1) Gauss's theorem gives
  2F1(-1/2, s; s+1; 1) = Gamma(s + 1) Gamma(3/2) / Gamma(s + 3/2); at theta = pi likewise with
  exp(c pi). Then K_cc = (Re J_0 + Re J_2)/2, K_ss = (Re J_0 - Re J_2)/2, K_sc = Im J_2 / 2,
  K_s = Im J_1. (Checked against quadrature at 30 digits in tests/test_ham_kernels.py.)
"""
from __future__ import annotations

import functools
from typing import Any

import sympy as sp

__all__ = ["ham_expressions", "SYMBOLS", "P3"]

tau = sp.Symbol("tau", nonnegative=True)
lam = sp.Symbol("lam", nonnegative=True)
beta = sp.Symbol("beta", positive=True)
omega0 = sp.Symbol("omega0", positive=True)
k = sp.Symbol("k", positive=True)
S = sp.Symbol("S", positive=True)  # sqrt(sin(omega0 tau)) on 0 < omega0 tau < pi
Kcc, Ksc, Kss, Ks = sp.symbols("Kcc Ksc Kss Ks", real=True)
a_, theta_, m_ = sp.symbols("a theta m", real=True)


class P3(sp.Function):  # type: ignore[misc]  # sympy is untyped: its classes are Any
    """P3(x) = (sin x - x cos x) / x^3, analytic, P3(0) = 1/3 (printed as a stable helper)."""

    nargs = 1


class Atan2(sp.Function):  # type: ignore[misc]  # sympy is untyped: its classes are Any
    """atan2(y, x) kept unevaluated through cse (SymPy turns atan2 of positive symbols into
    atan(y/x), which divides by zero at beta = 0); printed as arctan2 / mpmath.atan2."""

    nargs = 2


SYMBOLS: dict[str, Any] = {"tau": tau, "lam": lam, "beta": beta, "omega0": omega0, "k": k, "S": S, "Kcc": Kcc,
           "Ksc": Ksc, "Kss": Kss, "Ks": Ks, "a": a_, "theta": theta_, "m": m_}


def _zero(expr: Any) -> bool:
    return bool(sp.simplify(expr) == 0)


def _check(name: str, ok: bool) -> None:
    if not ok:
        raise AssertionError(f"codegen derivation check failed: {name}")


def _from_registry() -> dict[str, Any]:
    """The derivation's named results, in this module's symbols (the registry names lambda
    ``lambda``, a Python keyword, and omega0 ``omega_0``)."""
    from zener_sym.derivation.registry import derive

    d = derive(checks=False)
    sym = d.symbols
    rep = {sym["lam"]: lam, sym["tau"]: tau, sym["beta"]: beta, sym["omega0"]: omega0,
           sym["k"]: k}
    names = ("k_of_lam", "lam_crit", "lam_crit_eq", "delta0", "forcing_elem", "forcing_sqrt")
    return {n: sp.sympify(d.expr[n]).xreplace(rep) for n in names}


#: where the inputs come from (named in the generated files' headers)
REGISTRY_SOURCES = ("zener_sym.derivation.registry",)


@functools.lru_cache(maxsize=None)
def ham_expressions() -> dict[str, Any]:
    """Name -> SymPy expression for every quantity the HAM kernels print (see module docstring).

    k(lambda), lam_crit, delta0 and the forcing (36) come from the derivation's registry; each is
    checked here against an independent local route before use.

    Returns
    -------
    dict of str to sympy.Expr
        ``k_of_lam`` (25), ``beta_of_lam``, ``omega0_of_lam`` (32-33), ``lam_crit`` and
        ``lam_crit_eq`` (81), ``delta0``, ``delta0_dot`` (35, 56), the zeroth-order closed forms
        (``tau_d0``, ``tau_dc0``, ``tau_dr0``, ``eta0``, ``e0``, ``delta_m0``, ``int_F2_0``,
        ``impulse0``, ``a_impulse0``), the forcing (36), ``delta1``, ``delta1_dot`` (37-42) and
        the 2F1 closed forms ``J_theta``, ``J_pi``; cached.

    Raises
    ------
    AssertionError
        A registry result disagrees with its local check (a broken derivation).
    """
    reg = _from_registry()
    e: dict[str, Any] = {}
    _k_and_roots(reg, e)
    d0 = _zeroth_order(reg, e)
    f_elem = _forcing(reg, e, d0)
    _first_order(e, f_elem)
    _j_closed_forms(e)
    return e


# The sections of ham_expressions: each adds its names to ``e`` in the order the generated files
# print them, and checks what it takes from the registry.
def _k_and_roots(reg: dict[str, Any], e: dict[str, Any]) -> None:
    # --- (23)-(25): k(lambda); local route: delta_m(0) from the energy integral (22) ----------------
    dm0 = sp.Rational(5, 4) ** sp.Rational(2, 5)
    _check("(23) y(delta_m(0)) = 0", _zero(1 - sp.Rational(4, 5) * dm0 ** sp.Rational(5, 2)))
    _check("(25) registry k(lambda)",
           _zero(reg["k_of_lam"] - (lam + dm0 ** sp.Rational(-3, 2)) ** sp.Rational(-1, 3)))
    e["k_of_lam"] = reg["k_of_lam"]
    # --- (32)-(33): beta and omega0 from the roots -beta +- i omega0 of x^2 + k lam x + k --------------
    e["beta_of_lam"] = k * lam / 2
    e["omega0_of_lam"] = sp.sqrt(4 * k - k**2 * lam**2) / 2
    x = sp.Symbol("x")
    for r in (-e["beta_of_lam"] + sp.I * e["omega0_of_lam"], -e["beta_of_lam"] - sp.I * e["omega0_of_lam"]):
        _check("(32)-(33) root of the characteristic equation", _zero((x**2 + k * lam * x + k).subs(x, r)))
    e["lam_crit_eq"] = reg["lam_crit_eq"]
    e["lam_crit"] = reg["lam_crit"]
    _check("(81) lam_crit solves k lam^2 = 4",
           abs(sp.N(((4 - k * lam**2).subs(k, e["k_of_lam"])).subs(lam, e["lam_crit"]), 45)) < 1e-38)


def _zeroth_order(reg: dict[str, Any], e: dict[str, Any]) -> Any:
    """delta0 and the zeroth-order closed forms; returns delta0."""
    # --- (35): delta0, verified against (28)-(29) ---------------------------------------------------
    kk = beta**2 + omega0**2  # k in terms of beta, omega0
    d0 = reg["delta0"]
    d0d = sp.diff(d0, tau)
    d0dd = sp.diff(d0, tau, 2)
    _check("(28) delta0 solves delta'' + 2 beta delta' + k delta = 0",
           _zero(d0dd + 2 * beta * d0d + kk * d0))
    _check("(29) delta0(0) = 0, delta0'(0) = 1", d0.subs(tau, 0) == 0 and _zero(d0d.subs(tau, 0) - 1))
    e["delta0"], e["delta0_dot"] = d0, sp.simplify(d0d)
    # --- zeroth-order durations, restitution, extremum -----------------------------------------------
    tau_dc = sp.atan2(omega0, beta) / omega0  # (58); atan2 keeps beta = 0 (lambda = 0) regular
    _check("(57) delta0'(tau_dc) = 0", _zero(sp.expand_trig(d0d.subs(tau, tau_dc))))
    e["tau_d0"] = sp.pi / omega0  # (54)
    # printed with atan2 (unevaluated), so that beta = 0 (lambda = 0) needs no division by zero
    phi = Atan2(omega0, beta)
    e["tau_dc0"] = phi / omega0
    e["tau_dr0"] = (sp.pi - phi) / omega0  # (60)
    e["eta0"] = (sp.pi - phi) / phi  # (61)
    e0 = sp.simplify(-d0d.subs(tau, sp.pi / omega0))
    _check("(79) e0 = exp(-pi beta/omega0)", _zero(e0 - sp.exp(-sp.pi * beta / omega0)))
    e["e0"] = sp.exp(-sp.pi * beta / omega0)
    dm = sp.exp(-beta * tau_dc) / sp.sqrt(kk)  # sin(atan2(omega0, beta)) = omega0 / sqrt(k)
    _check("delta_m0 = delta0(tau_dc)", _zero(sp.expand_trig(d0.subs(tau, tau_dc)) - dm))
    _check("delta_m0 with Atan2", _zero(dm - (sp.exp(-beta * phi / omega0) / sp.sqrt(kk)).replace(
        Atan2, sp.atan2)))
    e["delta_m0"] = sp.exp(-beta * phi / omega0) / sp.sqrt(kk)
    # integral of F0^2 = delta0^3 over the zeroth-order contact, closed form
    u = sp.Symbol("u", positive=True)
    intF2 = sp.integrate(sp.expand(sp.exp(-3 * beta * u / omega0) * sp.expand_trig(sp.sin(u) ** 3)),
                         (u, 0, sp.pi)) / omega0**4
    intF2_stable = 2 * (1 + sp.exp(-3 * sp.pi * beta / omega0)) / (
        3 * (9 * beta**4 + 10 * beta**2 * omega0**2 + omega0**4))  # no overflow as omega0 -> 0
    _check("int F0^2 closed form", _zero(intF2 - intF2_stable))
    e["int_F2_0"] = intF2_stable
    # zeroth-order impulse: int_0^tau delta0^{3/2} = omega0^{-5/2} K_s(3 beta/(2 omega0), theta)
    e["impulse0"] = omega0 ** sp.Rational(-5, 2) * Ks
    e["a_impulse0"] = 3 * beta / (2 * omega0)
    return d0


def _forcing(reg: dict[str, Any], e: dict[str, Any], d0: Any) -> Any:
    """The forcing (36) and its sqrt part's coefficients c1, c2; returns the elementary part."""
    th = omega0 * tau
    d0d, d0dd = sp.diff(d0, tau), sp.diff(d0, tau, 2)
    # --- (36): forcing; local route by substitution into N, compared with the registry's ------------
    sqrt_d0 = omega0 ** sp.Rational(-1, 2) * sp.exp(-beta * tau / 2) * S
    f_local = sp.expand(-(d0dd + sp.Rational(3, 2) * lam * sqrt_d0 * d0d + d0 * sqrt_d0))
    f_elem, f_sqrt = reg["forcing_elem"], reg["forcing_sqrt"]
    _check("(36) registry forcing_elem", _zero(f_elem - f_local.coeff(S, 0)))
    # the registry's sqrt part carries sqrt(sin) (and sin^{3/2}); divide it out
    g = sp.expand(sp.powsimp(sp.expand(f_sqrt * sp.exp(sp.Rational(3, 2) * beta * tau)
                                       / sp.sqrt(sp.sin(th)))))
    _check("(36) registry forcing_sqrt",
           _zero(g - sp.expand(f_local.coeff(S, 1) * sp.exp(sp.Rational(3, 2) * beta * tau))))
    e["forcing_elem"], e["forcing_sqrt"] = f_elem, f_sqrt
    # exp(beta tau) f_sqrt = exp(-beta tau/2) (c1 cos + c2 sin) sqrt(sin)
    c1 = g.coeff(sp.cos(th))
    c2 = g.coeff(sp.sin(th))
    _check("(36) sqrt part = exp(-3 beta tau/2) (c1 cos + c2 sin) sqrt(sin)",
           _zero(g - c1 * sp.cos(th) - c2 * sp.sin(th)) and not (c1.has(tau) or c2.has(tau)))
    e["c1"], e["c2"] = c1, c2
    return f_elem


def _first_order(e: dict[str, Any], f_elem: Any) -> None:
    """delta1 and delta1' (37)-(42): the elementary part checked against (30)-(31), the sqrt part
    through the K integrals."""
    th = omega0 * tau
    kk = beta**2 + omega0**2
    c1, c2 = e["c1"], e["c2"]
    # --- (37)-(42): elementary part of delta1, proposed in a stable form and verified ---------------
    # It is the convolution (1/omega0) int_0^tau exp(-beta(tau-s)) sin(omega0(tau-s)) f_elem(s) ds, i.e.
    # the solution of L[delta] = f_elem with zero initial data (30)-(31): check exactly that.
    def p3_def(ex: Any) -> Any:
        return ex.replace(P3, lambda y: (sp.sin(y) - y * sp.cos(y)) / y**3)

    d1e_stable = sp.exp(-beta * tau) * ((omega0**2 - beta**2) / 2 * tau**3 * P3(th)
                                        + beta * tau * sp.sin(th) / omega0)
    d1e = p3_def(d1e_stable)
    _check("delta1 elementary part solves (30) with f_elem",
           _zero(sp.diff(d1e, tau, 2) + 2 * beta * sp.diff(d1e, tau) + kk * d1e - f_elem))
    _check("delta1 elementary part: (31) initial conditions",
           _zero(d1e.subs(tau, 0)) and sp.limit(sp.diff(d1e, tau), tau, 0) == 0)
    d1ed_stable = sp.exp(-beta * tau) * (beta**3 / 2 * tau**3 * P3(th)
                                         + beta * (1 - 3 * beta * tau) * sp.sin(th) / (2 * omega0)
                                         + sp.Rational(3, 2) * beta * tau * sp.cos(th)
                                         + omega0 * tau * sp.sin(th) / 2)
    _check("delta1' elementary part is the derivative", _zero(sp.diff(d1e, tau) - p3_def(d1ed_stable)))
    # --- square-root part through K integrals (a = beta / (2 omega0)) --------------------------------
    A11 = c1 * Kcc + c2 * Ksc  # omega0^2 (C11_sqrt(tau) - C11_sqrt(0))
    A12 = -(c1 * Ksc + c2 * Kss)  # omega0^2 (C12_sqrt(tau) - C12_sqrt(0))
    d1s = sp.exp(-beta * tau) / omega0**2 * (A11 * sp.sin(th) + A12 * sp.cos(th))
    d1sd = -beta * d1s + sp.exp(-beta * tau) / omega0 * (A11 * sp.cos(th) - A12 * sp.sin(th))
    e["a_first"] = beta / (2 * omega0)
    e["delta1"] = d1e_stable + d1s
    e["delta1_dot"] = d1ed_stable + d1sd
    e["delta1_sqrt"], e["delta1_elem"] = d1s, d1e_stable


def _j_closed_forms(e: dict[str, Any]) -> None:
    """The 2F1 closed forms of J_m for the mpmath kernels."""
    # --- closed forms of J_m for the mpmath kernels ---------------------------------------------------
    c = -a_ + sp.I * (m_ - sp.Rational(1, 2))
    sJ = c / (2 * sp.I)
    pref = sp.exp(sp.I * sp.pi / 4) / (2 * sp.sqrt(2) * sp.I)
    gauss1 = sp.gamma(sJ + 1) * sp.gamma(sp.Rational(3, 2)) / sp.gamma(sJ + sp.Rational(3, 2))
    F_theta = sp.exp(c * theta_) / sJ * sp.hyper([-sp.Rational(1, 2), sJ], [sJ + 1],
                                                 sp.exp(2 * sp.I * theta_))
    F_0 = gauss1 / sJ
    F_pi = sp.exp(c * sp.pi) * gauss1 / sJ
    e["J_theta"] = pref * (F_theta - F_0)
    e["J_pi"] = pref * (F_pi - F_0)
