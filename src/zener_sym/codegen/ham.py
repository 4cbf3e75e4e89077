"""Builders of the HAM formula files in generated/: orders 0 and 1, printed once for every backend.

A generated file holds printed formulas and data only: each function is one list of named
outputs, printed by SymPy's numpy printer from the expressions of ``ham_exprs.ham_expressions()``
(common subexpressions shared through ``sympy.cse``), with the arguments the expressions need and
no check, loop or branch. Every function takes the math namespace ``xp`` first
(``zener_sym.ham.xp``: numpy or mpmath), so a formula is printed once, not once per backend;
rationals are printed as ``xp.rational(p, q)`` (the literal's double for numpy, exact at the
working precision for mpmath). One small template per file kind: the header, the data, the
functions; the files import nothing. The zeroth-order file holds what both orders share (k,
beta, omega0, delta0, the 2F1 closed forms J), so no formula is printed twice.

The hand-written runtime that wraps the formulas (input checks, broadcasting, the square-root
integrals, root finding, contact integrals, mpmath precision and guard digits) is plain code in
``zener_sym.ham.runtime_numpy`` and ``zener_sym.ham.runtime_mpmath``: a change there needs no
regeneration. Output is deterministic: cse uses numbered symbols and its canonical order, and
nothing is printed from an unordered container.
"""
from __future__ import annotations

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from . import header
from .ham_exprs import REGISTRY_SOURCES
from .ham_exprs import SYMBOLS as Y
from .ham_exprs import ham_expressions

__all__ = ["build_ham0", "build_ham1"]

_SOURCES = ("zener_sym.codegen.ham", "zener_sym.codegen.ham_exprs") + REGISTRY_SOURCES


class _NeutralPrinter(NumPyPrinter):
    """Prints for any math namespace ``xp`` given as the first argument of each function.

    numpy's printing (so the numpy results keep their bits: ``x**(-1.0)``, float exponents),
    every module name read as ``xp``, and each rational p/q as ``xp.rational(p, q)``: the numpy
    namespace divides two ints (the same double as the literal p/q), the mpmath namespace gives
    ``mpf(p)/q``, exact at the working precision."""

    def _module_format(self, fqn, register=True):
        return "xp." + fqn.split(".", 1)[1] if fqn.startswith("numpy.") else fqn

    def _print_Rational(self, e):
        return f"xp.rational({e.p}, {e.q})"

    def _print_Half(self, e):
        return self._print_Rational(e)

    def _print_P3(self, e):
        return f"xp.p3({self._print(e.args[0])})"

    def _print_Atan2(self, e):
        return f"xp.atan2({self._print(e.args[0])}, {self._print(e.args[1])})"

    def _print_re(self, e):
        return f"xp.re({self._print(e.args[0])})"

    def _print_im(self, e):
        return f"xp.im({self._print(e.args[0])})"

    def _print_gamma(self, e):
        return f"xp.gamma({self._print(e.args[0])})"

    def _print_hyper(self, e):
        ap, bq = (self._print_seq(seq) for seq in (e.ap, e.bq))  # tuples, as mpmath.hyper takes
        return f"xp.hyper({ap}, {bq}, {self._print(e.argument)})"


class _HalfWavePrinter(_NeutralPrinter):
    """For delta0 on its contact only: its one sine, of the phase omega0 tau, is printed as the
    first half wave (``xp.half_wave_sin``: sin on [0, pi], 0 beyond)."""

    def _print_sin(self, e):
        return f"xp.half_wave_sin({self._print(e.args[0])})"


def _block(printer, outputs, indent="    ", prefix="_x"):
    """Assignments computing ``outputs`` [(name, expr)] with shared subexpressions."""
    exprs = [ex for _, ex in outputs]
    reps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix), order="canonical")
    lines = [f"{indent}{printer.doprint(s)} = {printer.doprint(v)}" for s, v in reps]
    lines += [f"{indent}{name} = {printer.doprint(r)}" for (name, _), r in zip(outputs, reduced)]
    return "\n".join(lines)


def _function(printer, name, args, doc, outputs, returns=None, prefix="_x"):
    """One printed formula function: ``def name(args)``, the docstring, the cse block of
    ``outputs`` [(name, expr)], and ``return returns`` (default: the outputs, a tuple when
    several). Every free symbol of an output must be an argument or an earlier output."""
    have = {str(a) for a in args}
    for out, ex in outputs:  # an output may use the arguments and the outputs before it
        extra = sorted(str(s) for s in ex.free_symbols if str(s) not in have)
        if extra:
            raise ValueError(f"{name}: output {out} needs {extra} beyond the arguments {args}")
        have.add(out)
    ret = returns or ", ".join(n for n, _ in outputs)
    return (f"\n\ndef {name}({', '.join(('xp',) + tuple(map(str, args)))}):\n    \"\"\"{doc}\"\"\"\n"
            f"{_block(printer, outputs, prefix=prefix)}\n    return {ret}\n")


def _common():
    e = ham_expressions()
    lam_crit = sp.Float(e["lam_crit"], 40)
    return e, lam_crit


def _params_outputs(e):
    return [("k", e["k_of_lam"]), ("beta", e["beta_of_lam"]), ("omega0", e["omega0_of_lam"])]


def _scaled(expr):
    """exp(beta tau) * expr, with the exponentials merged (avoids underflow in root finding)."""
    return sp.expand(sp.powsimp(sp.expand(expr * sp.exp(Y["beta"] * Y["tau"]))))


def _summary0_outputs(e):
    return [("tau_d", e["tau_d0"]), ("tau_dc", e["tau_dc0"]), ("tau_dr", e["tau_dr0"]),
            ("eta", e["eta0"]), ("e", e["e0"]), ("delta_m", e["delta_m0"]),
            ("int_F2", e["int_F2_0"]), ("a_imp", e["a_impulse0"])]


_CONTACT = ("tau", "lam", "beta", "omega0")  # arguments of a formula on the contact
_WITH_K = _CONTACT + ("Kcc", "Ksc", "Kss")  # ... and of one with the square-root integrals
_SUMMARY0_RETURN = ("dict(tau_d=tau_d, tau_dc=tau_dc, tau_dr=tau_dr, eta=eta, e=e, delta_m=delta_m,"
                    "\n                int_F2=int_F2, a_imp=a_imp)")


def _lam_crit_data(e, lam_crit, with_float):
    eq = str(e["lam_crit_eq"])
    lines = []
    if with_float:
        lines += ["#: Critical lambda: omega0 = 0 there (Eq. 81); the HAM solution needs "
                  "0 <= lambda < LAM_CRIT.", f"LAM_CRIT = {float(lam_crit)!r}"]
    lines += [f"#: LAM_CRIT to 40 significant digits (root of {eq} = 0)",
              f'LAM_CRIT_DIGITS = "{lam_crit}"']
    return "\n".join(lines) + "\n"


def _zeroth(p, e):
    """The formulas both orders share: k, beta, omega0 (25, 32, 33), delta0 (35), delta0' (56),
    delta0 on its contact (with ``xp.half_wave_sin``), the zeroth-order closed forms (47, 54-61,
    79), and the 2F1 closed forms J of the square-root integrals (with ``xp.gamma``,
    ``xp.hyper``: the mpmath namespace)."""
    sines = e["delta0"].atoms(sp.sin)
    if len(sines) != 1 or next(iter(sines)).args[0] != Y["omega0"] * Y["tau"]:
        raise ValueError(f"delta_contact expects one sine of omega0*tau in delta0, got {sines}")
    text = _function(p, "params", ("lam",), "k (25), beta (32) and omega0 (33) of the "
                     "zeroth-order operator.", _params_outputs(e))
    text += _function(p, "delta0", _CONTACT, "Zeroth-order compression delta0 (35), continued "
                      "analytically (no clipping).", [("out", e["delta0"])], "out")
    text += _function(p, "delta0_dot", _CONTACT, "Zeroth-order relative velocity delta0' (56).",
                      [("out", e["delta0_dot"])], "out")
    text += _function(_HalfWavePrinter(), "delta_contact", _CONTACT, "delta0 (35) on the "
                      "zeroth-order contact, its sine printed as the first half wave (0 after "
                      "omega0 tau = pi, Eq. 54).", [("out", e["delta0"])], "out")
    text += _function(p, "a_impulse", ("beta", "omega0"), "Decay rate a = 3 beta / (2 omega0) "
                      "of K_s in the impulse (47).", [("a_imp", e["a_impulse0"])])
    text += _function(p, "impulse", ("omega0", "Ks"), "Impulse (47) omega0^(-5/2) K_s from "
                      "K_s(a_impulse, omega0 tau).", [("out", e["impulse0"])], "out")
    text += _function(p, "summary", ("beta", "omega0"), "Zeroth-order closed forms: tau_d (54), "
                      "tau_dc (58), tau_dr (60), eta (61), e (79), delta_m = delta0(tau_dc), "
                      "int_F2, and the impulse's rate a_imp.", _summary0_outputs(e),
                      _SUMMARY0_RETURN)
    text += _function(p, "J_pi", ("m", "a"), "J_m(a, pi) by Gauss's theorem (Gamma functions).",
                      [("out", e["J_pi"])], "out")
    text += _function(p, "J_theta", ("m", "a", "theta"), "J_m(a, theta) = int_0^theta "
                      "exp((-a + i m) t) sqrt(sin t) dt by its 2F1 closed form, 0 < theta < pi.",
                      [("out", e["J_theta"])], "out")
    return text


def _first(p, e):
    """The first-order formulas: delta1 (37-42), delta0 + delta1 and
    its derivative, with the square-root integrals K_cc, K_sc, K_ss (36) as arguments, and the
    scaled forms the numpy root finding uses."""
    d = e["delta0"] + e["delta1"]
    dd = e["delta0_dot"] + e["delta1_dot"]
    text = _function(p, "a_first", ("beta", "omega0"), "Decay rate a = beta / (2 omega0) of the "
                     "square-root integrals K (36).", [("a", e["a_first"])])
    text += _function(p, "delta1", _WITH_K, "First-order correction delta1 (37)-(42).",
                      [("out", e["delta1"])], "out")
    # printed whole, not as delta0() + delta1(): that sum rounds differently (up to 4e-16 in
    # delta, 5 ulp in F_m), and every number must keep its bits
    text += _function(p, "delta", _WITH_K, "First-order HAM compression delta0 + delta1 (42).",
                      [("out", d)], "out")
    text += _function(p, "delta_dot", _WITH_K, "d/dtau of delta0 + delta1 (the C' terms cancel "
                      "by Eq. 38).", [("out", dd)], "out")
    text += _function(p, "delta_scaled", _WITH_K, "exp(beta tau) * (delta0 + delta1): same "
                      "sign, no underflow.", [("out", _scaled(d))], "out")
    text += _function(p, "delta_dot_scaled", _WITH_K, "exp(beta tau) * d/dtau (delta0 + "
                      "delta1): same sign, no underflow.", [("out", _scaled(dd))], "out")
    return text


def build_ham0() -> str:
    """generated/ham0.py: the zeroth-order formulas and the 2F1 closed forms J, for any math
    namespace ``xp``."""
    e, lam_crit = _common()
    return (header(_SOURCES, "Zeroth-order HAM formulas of Zener's equation (10), printed once "
                   "for every backend: each function takes the math namespace xp first (the "
                   "runtimes: zener_sym.ham.runtime_numpy, runtime_mpmath; the namespaces: "
                   "zener_sym.ham.xp).")
            + "\n" + _lam_crit_data(e, lam_crit, True) + _zeroth(_NeutralPrinter(), e))


def build_ham1() -> str:
    """generated/ham1.py: the first-order formulas, for any math namespace ``xp``."""
    e, _ = _common()
    return (header(_SOURCES, "First-order HAM formulas of Zener's equation (10), printed once "
                   "for every backend: each function takes the math namespace xp first (the "
                   "runtimes: zener_sym.ham.runtime_numpy, runtime_mpmath; the namespaces: "
                   "zener_sym.ham.xp).")
            + _first(_NeutralPrinter(), e))
