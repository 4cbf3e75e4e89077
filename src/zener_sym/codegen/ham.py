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

import functools
import json
import textwrap
from collections.abc import Sequence
from importlib import resources
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


def _docstring(args: Sequence[str], doc: _Doc,
               arg_docs: dict[str, tuple[str, str]] = _ARG_DOCS) -> str:
    """The numpydoc docstring (indented for a function body) of ``name(xp, *args)``, each
    argument described by ``arg_docs`` (default: the HAM formulas')."""
    i, j = "    ", "        "
    lines = _fill(doc.summary, i)  # the first line follows the opening quotes
    lines = [lines[0].lstrip()] + lines[1:]
    if doc.extended:
        lines += [""] + _fill(doc.extended, i)
    lines += ["", i + "Parameters", i + "----------"]
    for a in ("xp", *args):
        kind, text = arg_docs[a]
        lines += [f"{i}{a} : {kind}"] + _fill(text, j)
    lines += ["", i + "Returns", i + "-------"]
    for out, kind, text in doc.returns:
        lines += [f"{i}{out} : {kind}"] + _fill(text, j)
    lines += ["", i + "Examples", i + "--------"] + [i + x if x else "" for x in doc.examples]
    return '"""' + "\n".join(lines) + "\n" + i + '"""'


def _function(printer: Any, name: str, args: Sequence[str], doc: _Doc,
              outputs: Sequence[Output], returns: str | None = None, prefix: str = "_x",
              arg_docs: dict[str, tuple[str, str]] = _ARG_DOCS) -> str:
    """One printed formula function: ``def name(args)``, the docstring, the cse block of
    ``outputs`` [(name, expr)], and ``return returns`` (default: the outputs, a tuple when
    several). Every free symbol of an output must be an argument or an earlier output; every
    argument is described in ``arg_docs`` (default: the HAM formulas')."""
    missing = [a for a in args if a not in arg_docs]
    if missing:
        raise ValueError(f"{name}: no parameter description for {missing} in arg_docs")
    have = {str(a) for a in args}
    for out, ex in outputs:  # an output may use the arguments and the outputs before it
        extra = sorted(str(s) for s in ex.free_symbols if str(s) not in have)
        if extra:
            raise ValueError(f"{name}: output {out} needs {extra} beyond the arguments {args}")
        have.add(out)
    ret = returns or ", ".join(n for n, _ in outputs)
    return (f"\n\ndef {name}({', '.join(('xp',) + tuple(map(str, args)))}):\n"
            f"    {_docstring(args, doc, arg_docs)}\n"
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


@functools.cache
def _docs(module: str) -> dict[str, _Doc]:
    """Docstrings of the functions of generated/``module``.py ("ham0" or "ham1").

    Text, so it lives in the package data file ham_docs.json: per function its summary line,
    paragraph, Returns entries and Examples' doctest lines, where a line "@NAME" stands for the
    lines of the file's ``snippets[NAME]`` (shared imports and set-ups).
    """
    raw = json.loads((resources.files(__package__) / "ham_docs.json").read_text("utf-8"))
    snippets: dict[str, list[str]] = raw["snippets"]

    def lines(examples: list[str]) -> list[str]:
        return [ln for x in examples for ln in (snippets[x[1:]] if x.startswith("@") else [x])]

    return {name: _Doc(d["summary"], d["extended"], [tuple(r) for r in d["returns"]],
                       lines(d["examples"]))
            for name, d in raw[module].items()}


def _zeroth(p: Any, e: dict[str, Any]) -> str:
    """The formulas both orders share: k, beta, omega0 (25, 32, 33), delta0 (35), delta0' (56),
    delta0 on its contact (with ``xp.half_wave_sin``), the zeroth-order closed forms (47, 54-61,
    79), and the 2F1 closed forms J of the square-root integrals (with ``xp.gamma``,
    ``xp.hyper``: the mpmath namespace)."""
    sines = e["delta0"].atoms(sp.sin)
    if len(sines) != 1 or next(iter(sines)).args[0] != Y["omega0"] * Y["tau"]:
        raise ValueError(f"delta_contact expects one sine of omega0*tau in delta0, got {sines}")
    d = _docs("ham0")
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
    d = _docs("ham1")
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
