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

import textwrap
from collections.abc import Sequence
from typing import Any, NamedTuple

import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from . import header
from .ham_exprs import REGISTRY_SOURCES
from .ham_exprs import SYMBOLS as Y
from .ham_exprs import ham_expressions

__all__ = ["build_ham0", "build_ham1"]

_SOURCES = ("zener_sym.codegen.ham", "zener_sym.codegen.ham_exprs") + REGISTRY_SOURCES

#: (name, SymPy expression) of one printed output
Output = tuple[str, Any]


class _NeutralPrinter(NumPyPrinter):  # type: ignore[misc]  # sympy is untyped: its classes are Any
    """Prints for any math namespace ``xp`` given as the first argument of each function.

    numpy's printing (so the numpy results keep their bits: ``x**(-1.0)``, float exponents),
    every module name read as ``xp``, and each rational p/q as ``xp.rational(p, q)``: the numpy
    namespace divides two ints (the same double as the literal p/q), the mpmath namespace gives
    ``mpf(p)/q``, exact at the working precision."""

    def _module_format(self, fqn: str, register: bool = True) -> str:
        return "xp." + fqn.split(".", 1)[1] if fqn.startswith("numpy.") else fqn

    def _print_Rational(self, e: Any) -> str:
        return f"xp.rational({e.p}, {e.q})"

    def _print_Half(self, e: Any) -> str:
        return self._print_Rational(e)

    def _print_P3(self, e: Any) -> str:
        return f"xp.p3({self._print(e.args[0])})"

    def _print_Atan2(self, e: Any) -> str:
        return f"xp.atan2({self._print(e.args[0])}, {self._print(e.args[1])})"

    def _print_re(self, e: Any) -> str:
        return f"xp.re({self._print(e.args[0])})"

    def _print_im(self, e: Any) -> str:
        return f"xp.im({self._print(e.args[0])})"

    def _print_gamma(self, e: Any) -> str:
        return f"xp.gamma({self._print(e.args[0])})"

    def _print_hyper(self, e: Any) -> str:
        ap, bq = (self._print_seq(seq) for seq in (e.ap, e.bq))  # tuples, as mpmath.hyper takes
        return f"xp.hyper({ap}, {bq}, {self._print(e.argument)})"


class _HalfWavePrinter(_NeutralPrinter):
    """For delta0 on its contact only: its one sine, of the phase omega0 tau, is printed as the
    first half wave (``xp.half_wave_sin``: sin on [0, pi], 0 beyond)."""

    def _print_sin(self, e: Any) -> str:
        return f"xp.half_wave_sin({self._print(e.args[0])})"


def _block(printer: Any, outputs: Sequence[Output], indent: str = "    ",
           prefix: str = "_x") -> str:
    """Assignments computing ``outputs`` [(name, expr)] with shared subexpressions."""
    exprs = [ex for _, ex in outputs]
    reps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix), order="canonical")
    lines = [f"{indent}{printer.doprint(s)} = {printer.doprint(v)}" for s, v in reps]
    lines += [f"{indent}{name} = {printer.doprint(r)}" for (name, _), r in zip(outputs, reduced)]
    return "\n".join(lines)


# ------------------------------------------------------------------------------ docstrings
# The generated functions' docstrings are numpydoc (the API reference renders them) and their
# Examples run as doctests (tests/test_codegen_ham.py). The code outside the docstrings names no
# backend: the namespaces are zener_sym.ham.xp's NUMPY and MPMATH.

_FLOATS = "float or ndarray"  # what the NUMPY namespace broadcasts (MPMATH: one mpf)

#: argument name -> (type, description), shared by every generated function
_ARG_DOCS: dict[str, tuple[str, str]] = {
    "xp": ("types.SimpleNamespace", "The math namespace: ``zener_sym.ham.xp.NUMPY`` (float64, "
           "arrays broadcast) or ``zener_sym.ham.xp.MPMATH`` (at the working precision)."),
    "lam": (_FLOATS, "The damping parameter lambda of Eq. (10), 0 <= lambda < ``LAM_CRIT`` "
            "(Eq. 81)."),
    "tau": (_FLOATS, "Dimensionless time tau of Eq. (10), >= 0."),
    "beta": (_FLOATS, "The decay rate beta = k lambda / 2 (32), from ``params`` of "
             "``zener_sym.generated.ham0``."),
    "omega0": (_FLOATS, "The frequency omega0 = sqrt(k - beta^2) > 0 (33), from ``params`` "
               "of ``zener_sym.generated.ham0``."),
    "Kcc": (_FLOATS, "K_cc(a, theta) = int_0^theta exp(-a t) cos^2 t sqrt(sin t) dt (36), at "
            "a = ``a_first(xp, beta, omega0)`` and theta = min(omega0 tau, pi)."),
    "Ksc": (_FLOATS, "K_sc, as ``Kcc`` with sin t cos t for cos^2 t."),
    "Kss": (_FLOATS, "K_ss, as ``Kcc`` with sin^2 t for cos^2 t."),
    "Ks": (_FLOATS, "K_s(a, theta) = int_0^theta exp(-a t) sin(t)^(3/2) dt at "
           "a = ``a_impulse(xp, beta, omega0)``, theta = min(omega0 tau, pi)."),
    "m": ("int", "The harmonic m of J_m (0, 1 or 2 in the K integrals)."),
    "a": ("float", "Decay rate a >= 0."),
    "theta": ("float", "Upper end of the integral, 0 < theta < pi."),
}


class _Doc(NamedTuple):
    """A generated function's docstring: summary line, paragraph, Returns entries
    (name, type, description) and the Examples' doctest lines."""

    summary: str
    extended: str
    returns: Sequence[tuple[str, str, str]]
    examples: Sequence[str]


def _fill(text: str, indent: str) -> list[str]:
    """``text`` wrapped at 96 columns (``indent`` included), every line indented."""
    return textwrap.wrap(text, 96, initial_indent=indent, subsequent_indent=indent,
                         break_on_hyphens=False)


def _docstring(args: Sequence[str], doc: _Doc) -> str:
    """The numpydoc docstring (indented for a function body) of ``name(xp, *args)``."""
    i, j = "    ", "        "
    lines = _fill(doc.summary, i)  # the first line follows the opening quotes
    lines = [lines[0].lstrip()] + lines[1:]
    if doc.extended:
        lines += [""] + _fill(doc.extended, i)
    lines += ["", i + "Parameters", i + "----------"]
    for a in ("xp", *args):
        kind, text = _ARG_DOCS[a]
        lines += [f"{i}{a} : {kind}"] + _fill(text, j)
    lines += ["", i + "Returns", i + "-------"]
    for out, kind, text in doc.returns:
        lines += [f"{i}{out} : {kind}"] + _fill(text, j)
    lines += ["", i + "Examples", i + "--------"] + [i + x if x else "" for x in doc.examples]
    return '"""' + "\n".join(lines) + "\n" + i + '"""'


def _function(printer: Any, name: str, args: Sequence[str], doc: _Doc,
              outputs: Sequence[Output], returns: str | None = None, prefix: str = "_x") -> str:
    """One printed formula function: ``def name(args)``, the docstring, the cse block of
    ``outputs`` [(name, expr)], and ``return returns`` (default: the outputs, a tuple when
    several). Every free symbol of an output must be an argument or an earlier output."""
    missing = [a for a in args if a not in _ARG_DOCS]
    if missing:
        raise ValueError(f"{name}: no parameter description for {missing} in _ARG_DOCS")
    have = {str(a) for a in args}
    for out, ex in outputs:  # an output may use the arguments and the outputs before it
        extra = sorted(str(s) for s in ex.free_symbols if str(s) not in have)
        if extra:
            raise ValueError(f"{name}: output {out} needs {extra} beyond the arguments {args}")
        have.add(out)
    ret = returns or ", ".join(n for n, _ in outputs)
    return (f"\n\ndef {name}({', '.join(('xp',) + tuple(map(str, args)))}):\n"
            f"    {_docstring(args, doc)}\n"
            f"{_block(printer, outputs, prefix=prefix)}\n    return {ret}\n")


def _common() -> tuple[dict[str, Any], Any]:
    e = ham_expressions()
    lam_crit = sp.Float(e["lam_crit"], 40)
    return e, lam_crit


def _params_outputs(e: dict[str, Any]) -> list[Output]:
    return [("k", e["k_of_lam"]), ("beta", e["beta_of_lam"]), ("omega0", e["omega0_of_lam"])]


def _scaled(expr: Any) -> Any:
    """exp(beta tau) * expr, with the exponentials merged (avoids underflow in root finding)."""
    return sp.expand(sp.powsimp(sp.expand(expr * sp.exp(Y["beta"] * Y["tau"]))))


def _summary0_outputs(e: dict[str, Any]) -> list[Output]:
    return [("tau_d", e["tau_d0"]), ("tau_dc", e["tau_dc0"]), ("tau_dr", e["tau_dr0"]),
            ("eta", e["eta0"]), ("e", e["e0"]), ("delta_m", e["delta_m0"]),
            ("int_F2", e["int_F2_0"]), ("a_imp", e["a_impulse0"])]


_CONTACT = ("tau", "lam", "beta", "omega0")  # arguments of a formula on the contact
_WITH_K = _CONTACT + ("Kcc", "Ksc", "Kss")  # ... and of one with the square-root integrals
_SUMMARY0_RETURN = ("dict(tau_d=tau_d, tau_dc=tau_dc, tau_dr=tau_dr, eta=eta, e=e, delta_m=delta_m,"
                    "\n                int_F2=int_F2, a_imp=a_imp)")


def _lam_crit_data(e: dict[str, Any], lam_crit: Any, with_float: bool) -> str:
    eq = str(e["lam_crit_eq"])
    lines = []
    if with_float:
        lines += ["#: Critical lambda: omega0 = 0 there (Eq. 81); the HAM solution needs "
                  "0 <= lambda < LAM_CRIT.", f"LAM_CRIT = {float(lam_crit)!r}"]
    lines += [f"#: LAM_CRIT to 40 significant digits (root of {eq} = 0)",
              f'LAM_CRIT_DIGITS = "{lam_crit}"']
    return "\n".join(lines) + "\n"


# doctest lines shared by the examples
_NP = ">>> from zener_sym.ham.xp import NUMPY"
_MP = ">>> from zener_sym.ham.xp import MPMATH"
_H0 = ">>> from zener_sym.generated.ham0 import delta0, params"
_K_OF = (">>> from zener_sym.numerics.sqrt_integrals import sqrt_integrals",
         ">>> lam, tau = 0.5, 1.0",
         ">>> k, beta, omega0 = params(NUMPY, lam)",
         ">>> K = sqrt_integrals(a_first(NUMPY, beta, omega0), omega0 * tau, (\"cc\", \"sc\", \"ss\"))",
         ">>> Kcc, Ksc, Kss = K[\"cc\"], K[\"sc\"], K[\"ss\"]")
_K0 = "0.0, 0.0, 0.0"  # the K integrals at tau = 0


def _zeroth_docs() -> dict[str, _Doc]:
    """Docstrings of generated/ham0.py's functions."""
    f = _FLOATS
    return {
        "params": _Doc(
            "The coefficients k (25), beta (32) and omega0 (33) of the zeroth-order operator.",
            "The auxiliary linear operator (12) is delta'' + k lambda delta' + k delta, with roots "
            "-beta +- i omega0; k = (lambda + delta_m(0)^(-3/2))^(-1/3) with delta_m(0) = "
            "(5/4)^(2/5), the elastic maximum compression (23).",
            [("k", f, "The coefficient k (25) of the auxiliary operator, > 0."),
             ("beta", f, "The decay rate beta = k lambda / 2 (32)."),
             ("omega0", f, "The frequency omega0 = sqrt(4 k - k^2 lambda^2) / 2 (33), real "
              "below LAM_CRIT.")],
            [_NP, ">>> k, beta, omega0 = params(NUMPY, 0.0)",
             ">>> bool(abs(k - 1.25 ** 0.2) < 1e-15), float(beta)  # elastic: k = delta_m(0)^(1/2)",
             "(True, 0.0)", ">>> k, beta, omega0 = params(NUMPY, 1.0)",
             ">>> bool(abs(beta ** 2 + omega0 ** 2 - k) < 1e-15)  # |root|^2 = k",
             "True"]),
        "delta0": _Doc(
            "Zeroth-order compression delta0 (35), continued analytically (no clipping).",
            "delta0 = exp(-beta tau) sin(omega0 tau) / omega0 solves the auxiliary linear "
            "equation (28) with delta0(0) = 0, delta0'(0) = 1 (29); it is negative past "
            "tau = pi / omega0, the end of the zeroth-order contact (54).",
            [("delta0", f, "The compression delta0 at ``tau``.")],
            [_NP, ">>> k, beta, omega0 = params(NUMPY, 0.0)",
             ">>> tau = NUMPY.pi / (2 * omega0)  # the maximum when lambda = 0",
             ">>> bool(abs(delta0(NUMPY, tau, 0.0, beta, omega0) - 1 / omega0) < 1e-15)",
             "True"]),
        "delta0_dot": _Doc(
            "Zeroth-order relative velocity delta0' (56).",
            "d/dtau of delta0 (35), continued analytically like it.",
            [("delta0_dot", f, "The velocity delta0' at ``tau``.")],
            [_NP, ">>> k, beta, omega0 = params(NUMPY, 1.0)",
             ">>> round(float(delta0_dot(NUMPY, 0.0, 1.0, beta, omega0)), 15)  # (29): delta0'(0) = 1",
             "1.0"]),
        "delta_contact": _Doc(
            "The compression delta0 (35) on the zeroth-order contact, 0 after it (54).",
            "Its sine is printed as the first half wave ``xp.half_wave_sin`` (sin on [0, pi], 0 "
            "beyond), so the compression is 0 from omega0 tau = pi on; the NUMPY namespace only.",
            [("delta", f, "The compression delta0 at ``tau`` on the contact, 0 after it.")],
            [">>> import numpy as np", _NP, ">>> k, beta, omega0 = params(NUMPY, 1.0)",
             ">>> tau = np.array([0.3, 1.5]) * np.pi / omega0  # on the contact, after it",
             ">>> d = delta_contact(NUMPY, tau, 1.0, beta, omega0)",
             ">>> bool(abs(d[0] - delta0(NUMPY, tau[0], 1.0, beta, omega0)) < 1e-15), float(d[1])",
             "(True, 0.0)"]),
        "a_impulse": _Doc(
            "Decay rate a = 3 beta / (2 omega0) of K_s in the impulse (47).",
            "delta0^(3/2) = omega0^(-3/2) exp(-a omega0 tau) sin(omega0 tau)^(3/2).",
            [("a_imp", f, "The rate a of ``Ks`` in :func:`impulse`.")],
            [_NP, ">>> float(a_impulse(NUMPY, 1.0, 2.0))", "0.75"]),
        "impulse": _Doc(
            "Zeroth-order impulse (47), omega0^(-5/2) K_s.",
            "The integral of the contact force delta0^(3/2) from 0 to tau, with K_s at "
            "a = a_impulse(beta, omega0) and theta = min(omega0 tau, pi).",
            [("impulse", f, "The impulse up to ``tau``.")],
            [_NP, ">>> from math import gamma, pi, sqrt",
             ">>> Ks = sqrt(pi) * gamma(1.25) / gamma(1.75)  # int_0^pi sin^(3/2) t dt (a = 0)",
             ">>> k, beta, omega0 = params(NUMPY, 0.0)",
             ">>> round(float(impulse(NUMPY, omega0, Ks)), 12)  # lambda = 0: the whole contact",
             "1.653192620197"]),
        "summary": _Doc(
            "Zeroth-order closed forms of one impact.",
            "tau_d (54), tau_dc (58), tau_dr (60), eta (61), e (79), delta_m = delta0(tau_dc), "
            "the integral of F^2 = delta0^3 over the contact, and the rate a_imp of the "
            "impulse (47).",
            [("summary", "dict", "Keys ``tau_d``, ``tau_dc``, ``tau_dr``, ``eta``, ``e``, "
              "``delta_m``, ``int_F2``, ``a_imp``; values of the shape of ``beta``.")],
            [_NP, ">>> k, beta, omega0 = params(NUMPY, 0.0)",
             ">>> s = summary(NUMPY, beta, omega0)",
             ">>> float(s[\"e\"]), float(s[\"eta\"])  # elastic: e = 1, symmetric contact",
             "(1.0, 1.0)",
             ">>> bool(abs(s[\"tau_d\"] - NUMPY.pi / omega0) < 1e-15)", "True"]),
        "J_pi": _Doc(
            "J_m(a, pi) by Gauss's theorem (Gamma functions).",
            "J_m(a, theta) = int_0^theta exp((-a + i m) t) sqrt(sin t) dt at theta = pi, the "
            "value the K integrals (36) freeze at; needs ``xp.gamma`` (the MPMATH namespace).",
            [("J", "complex", "J_m(a, pi) (an mpc).")],
            [_MP, ">>> from math import gamma, pi, sqrt",
             ">>> J = complex(J_pi(MPMATH, 0, 0))",
             ">>> bool(abs(J - sqrt(pi) * gamma(0.75) / gamma(1.25)) < 1e-13)  # Beta(3/4, 1/2)",
             "True"]),
        "J_theta": _Doc(
            "J_m(a, theta) by its 2F1 closed form, 0 < theta < pi.",
            "J_m(a, theta) = int_0^theta exp((-a + i m) t) sqrt(sin t) dt, from which the "
            "square-root integrals K (36) are formed; needs ``xp.hyper`` and ``xp.gamma`` (the "
            "MPMATH namespace).",
            [("J", "complex", "J_m(a, theta) (an mpc).")],
            [_MP, ">>> J = complex(J_theta(MPMATH, 0, 0, MPMATH.pi / 2))",
             ">>> half = complex(J_pi(MPMATH, 0, 0)) / 2  # sqrt(sin t) is symmetric about pi/2",
             ">>> bool(abs(J - half) < 1e-13)", "True"]),
    }


def _first_docs() -> dict[str, _Doc]:
    """Docstrings of generated/ham1.py's functions."""
    f = _FLOATS
    return {
        "a_first": _Doc(
            "Decay rate a = beta / (2 omega0) of the square-root integrals K (36).",
            "sqrt(delta0) = omega0^(-1/2) exp(-a omega0 tau) sqrt(sin(omega0 tau)).",
            [("a", f, "The rate a of ``Kcc``, ``Ksc``, ``Kss``.")],
            [_NP, ">>> float(a_first(NUMPY, 1.0, 2.0))", "0.25"]),
        "delta1": _Doc(
            "First-order correction delta1 (37)-(42).",
            "The variation-of-constants solution of the first-order deformation equation (30) "
            "with zero initial data (31): an elementary part and the square-root part through "
            "K_cc, K_sc, K_ss (36).",
            [("delta1", f, "The correction delta1 at ``tau``.")],
            [_NP, _H0, ">>> k, beta, omega0 = params(NUMPY, 0.5)",
             f">>> float(delta1(NUMPY, 0.0, 0.5, beta, omega0, {_K0}))  # (31): delta1(0) = 0",
             "0.0"]),
        "delta": _Doc(
            "First-order HAM compression delta0 + delta1 (42).",
            "Printed whole, not as the sum of two calls, so that it keeps its bits; on the "
            "zeroth-order contact (K frozen at theta = pi beyond it: the continuation).",
            [("delta", f, "The compression delta0 + delta1 at ``tau``.")],
            [_NP, _H0, *_K_OF,
             ">>> d = delta(NUMPY, tau, lam, beta, omega0, Kcc, Ksc, Kss)",
             ">>> d1 = delta1(NUMPY, tau, lam, beta, omega0, Kcc, Ksc, Kss)",
             ">>> bool(abs(d - delta0(NUMPY, tau, lam, beta, omega0) - d1) < 1e-15)", "True"]),
        "delta_dot": _Doc(
            "Relative velocity d/dtau (delta0 + delta1) of the first-order solution (42).",
            "The C' terms of (37) cancel by Eq. (38), so it has the form of delta with "
            "differentiated trigonometric factors.",
            [("delta_dot", f, "The velocity at ``tau``.")],
            [_NP, _H0, ">>> k, beta, omega0 = params(NUMPY, 0.5)",
             f">>> v = delta_dot(NUMPY, 0.0, 0.5, beta, omega0, {_K0})",
             ">>> bool(abs(v - 1.0) < 1e-15)  # (29), (31): delta'(0) = 1 + 0", "True"]),
        "delta_scaled": _Doc(
            "The product exp(beta tau) (delta0 + delta1): the sign of delta (42) without underflow.",
            "The exponentials merged into the terms: root finding on the end of contact uses it.",
            [("delta_scaled", f, "The product exp(beta tau) delta at ``tau``.")],
            [_NP, ">>> from math import exp", _H0, *_K_OF,
             ">>> d = delta(NUMPY, tau, lam, beta, omega0, Kcc, Ksc, Kss)",
             ">>> ds = delta_scaled(NUMPY, tau, lam, beta, omega0, Kcc, Ksc, Kss)",
             ">>> bool(abs(ds - exp(beta * tau) * d) < 1e-15)", "True"]),
        "delta_dot_scaled": _Doc(
            "The product exp(beta tau) d/dtau (delta0 + delta1): the sign of delta' (42) without "
            "underflow.",
            "The exponentials merged into the terms: root finding on the end of compression uses "
            "it.",
            [("delta_dot_scaled", f, "The product exp(beta tau) delta' at ``tau``.")],
            [_NP, ">>> from math import exp", _H0, *_K_OF,
             ">>> v = delta_dot(NUMPY, tau, lam, beta, omega0, Kcc, Ksc, Kss)",
             ">>> vs = delta_dot_scaled(NUMPY, tau, lam, beta, omega0, Kcc, Ksc, Kss)",
             ">>> bool(abs(vs - exp(beta * tau) * v) < 1e-15)", "True"]),
    }


def _zeroth(p: Any, e: dict[str, Any]) -> str:
    """The formulas both orders share: k, beta, omega0 (25, 32, 33), delta0 (35), delta0' (56),
    delta0 on its contact (with ``xp.half_wave_sin``), the zeroth-order closed forms (47, 54-61,
    79), and the 2F1 closed forms J of the square-root integrals (with ``xp.gamma``,
    ``xp.hyper``: the mpmath namespace)."""
    sines = e["delta0"].atoms(sp.sin)
    if len(sines) != 1 or next(iter(sines)).args[0] != Y["omega0"] * Y["tau"]:
        raise ValueError(f"delta_contact expects one sine of omega0*tau in delta0, got {sines}")
    d = _zeroth_docs()
    text = _function(p, "params", ("lam",), d["params"], _params_outputs(e))
    text += _function(p, "delta0", _CONTACT, d["delta0"], [("out", e["delta0"])], "out")
    text += _function(p, "delta0_dot", _CONTACT, d["delta0_dot"], [("out", e["delta0_dot"])],
                      "out")
    text += _function(_HalfWavePrinter(), "delta_contact", _CONTACT, d["delta_contact"],
                      [("out", e["delta0"])], "out")
    text += _function(p, "a_impulse", ("beta", "omega0"), d["a_impulse"],
                      [("a_imp", e["a_impulse0"])])
    text += _function(p, "impulse", ("omega0", "Ks"), d["impulse"], [("out", e["impulse0"])],
                      "out")
    text += _function(p, "summary", ("beta", "omega0"), d["summary"], _summary0_outputs(e),
                      _SUMMARY0_RETURN)
    text += _function(p, "J_pi", ("m", "a"), d["J_pi"], [("out", e["J_pi"])], "out")
    text += _function(p, "J_theta", ("m", "a", "theta"), d["J_theta"], [("out", e["J_theta"])],
                      "out")
    return text


def _first(p: Any, e: dict[str, Any]) -> str:
    """The first-order formulas: delta1 (37-42), delta0 + delta1 and
    its derivative, with the square-root integrals K_cc, K_sc, K_ss (36) as arguments, and the
    scaled forms the numpy root finding uses."""
    dd0 = e["delta0"] + e["delta1"]
    ddd = e["delta0_dot"] + e["delta1_dot"]
    d = _first_docs()
    text = _function(p, "a_first", ("beta", "omega0"), d["a_first"], [("a", e["a_first"])])
    text += _function(p, "delta1", _WITH_K, d["delta1"], [("out", e["delta1"])], "out")
    # printed whole, not as delta0() + delta1(): that sum rounds differently (up to 4e-16 in
    # delta, 5 ulp in F_m), and every number must keep its bits
    text += _function(p, "delta", _WITH_K, d["delta"], [("out", dd0)], "out")
    text += _function(p, "delta_dot", _WITH_K, d["delta_dot"], [("out", ddd)], "out")
    text += _function(p, "delta_scaled", _WITH_K, d["delta_scaled"], [("out", _scaled(dd0))],
                      "out")
    text += _function(p, "delta_dot_scaled", _WITH_K, d["delta_dot_scaled"],
                      [("out", _scaled(ddd))], "out")
    return text


def build_ham0() -> str:
    """generated/ham0.py: the zeroth-order formulas and the 2F1 closed forms J, for any math
    namespace ``xp``.

    Returns
    -------
    str
        The module text: the header, ``LAM_CRIT`` and ``LAM_CRIT_DIGITS``, and one documented
        function per formula.
    """
    e, lam_crit = _common()
    return (header(_SOURCES, "Zeroth-order HAM formulas of Zener's equation (10), printed once "
                   "for every backend: each function takes the math namespace xp first (the "
                   "runtimes: zener_sym.ham.runtime_numpy, runtime_mpmath; the namespaces: "
                   "zener_sym.ham.xp).")
            + "\n" + _lam_crit_data(e, lam_crit, True) + _zeroth(_NeutralPrinter(), e))


def build_ham1() -> str:
    """generated/ham1.py: the first-order formulas, for any math namespace ``xp``.

    Returns
    -------
    str
        The module text: the header and one documented function per formula.
    """
    e, _ = _common()
    return (header(_SOURCES, "First-order HAM formulas of Zener's equation (10), printed once "
                   "for every backend: each function takes the math namespace xp first (the "
                   "runtimes: zener_sym.ham.runtime_numpy, runtime_mpmath; the namespaces: "
                   "zener_sym.ham.xp).")
            + _first(_NeutralPrinter(), e))
