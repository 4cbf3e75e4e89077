"""Text of the audit for a reader: expressions as LaTeX in the paper's notation, numbers, units.

Every formula the audit shows (printed form, derived form, the expressions quoted in evidence)
goes through :func:`tex` (SymPy's LaTeX printer with the paper's notation and ordering rules of
:mod:`zener_sym.derivation.printing`), so AUDIT.md carries no SymPy or Python syntax.
The code names of the transcriptions (``x``, ``y`` as placeholders, ``C11(tau)`` standing for
C113 in (40), ...) are given their meaning per item in :data:`PLACEHOLDERS`.
"""
from __future__ import annotations

from typing import SupportsComplex, SupportsFloat

import sympy as sp

from zener_sym.derivation.printing import mathtext_safe, paper_latex

from .printed import Expr

__all__ = ["tex", "dim_tex", "PLACEHOLDERS", "num"]

_DB = r"\bar\delta"
_I_BAR = r"\bar I"
_INT_F2 = r"\left(\int \bar F^2\, d\tau\right)"  # bracketed: a factor among others

#: Per item: (symbol names, function names) of the placeholders the transcription uses.
PLACEHOLDERS: dict[str, tuple[dict[str, str], dict[str, tuple[str, bool]]]] = {
    **{n: ({"x": _DB}, {}) for n in ("17", "18", "19", "21", "22")},
    "34": ({"x": "c_2", "y": "c_1"}, {}),
    "38": ({"F": r"f(\tau)"}, {}),
    "39": ({"F": r"f(\tau)"}, {}),
    "40": ({"x": "C_{111}", "y": "C_{112}"}, {"C11": ("C_{113}", False), "C12": ("C_{114}", False)}),
    "41": ({"x": "C_{121}", "y": "C_{122}"}, {"C11": ("C_{123}", False), "C12": ("C_{124}", False)}),
    "51": ({}, {"C11": (r"C_{11}^d", False), "C12": (r"C_{12}^d", False)}),
    "63": ({"x": _I_BAR}, {}), "64": ({"x": _I_BAR}, {}), "69": ({"x": _I_BAR}, {}),
    "74": ({"x": r"\left(\int F^2\, dt\right)"}, {}),
    "75": ({"x": _INT_F2}, {}), "76": ({"x": _INT_F2}, {}),
    "4": ({"dm": r"\delta_m"}, {}),
}
# the physical equations: d(t) is the compression delta(t), not the dimensionless one
_PHYSICAL_D = {"d": (r"\delta", False)}
for _n in ("1", "7", "8"):
    PLACEHOLDERS[_n] = ({}, dict(_PHYSICAL_D))


def tex(expr: Expr, item_id: str | None = None, literal: bool = False) -> str:
    """LaTeX (without $) of a SymPy expression (or tuple, or relation) in the paper's notation;
    ``literal`` for a transcription (kept in its printed order and grouping)."""
    names, functions = PLACEHOLDERS.get(item_id, ({}, {})) if item_id is not None else ({}, {})
    if isinstance(expr, (tuple, list)):
        return r"\left(" + ", ".join(tex(e, item_id, literal) for e in expr) + r"\right)"
    if isinstance(expr, sp.Equality):
        return f"{tex(expr.lhs, item_id, literal)} = {tex(expr.rhs, item_id, literal)}"
    try:
        out: str = paper_latex(sp.sympify(expr), names=names, functions=functions, literal=literal)
    except Exception:  # an odd (mutated) transcription must never cost a verdict
        out = mathtext_safe(sp.latex(expr))
    return out


_DIM_NAMES = {"M": r"\mathrm{M}", "L": r"\mathrm{L}", "Ts": r"\mathrm{T}"}


def dim_tex(mono: Expr | None) -> str:
    """A dimension monomial in M, L, Ts as LaTeX (``M L T^{-2}``); ``1`` for dimensionless."""
    if mono is None:
        return r"\text{none (terms of different dimensions)}"
    mono = sp.sympify(mono)
    if mono == 1:
        return "1"
    powers = mono.as_powers_dict()
    parts = []
    for name in ("M", "L", "Ts"):
        e = next((v for k, v in powers.items() if getattr(k, "name", "") == name), 0)
        if e == 0:
            continue
        base = _DIM_NAMES[name]
        parts.append(base if e == 1 else "%s^{%s}" % (base, sp.latex(sp.Rational(e))))
    return r"\,".join(parts)


def _real(v: float, digits: int) -> str:
    s = f"{v:.{digits}g}"
    if "e" not in s:
        return s
    mant, ex = s.split("e")
    return f"${mant} \\times 10^{{{int(ex)}}}$"


def num(x: complex | SupportsComplex | SupportsFloat, digits: int = 4) -> str:
    """A real number with ``digits`` significant digits (a complex one as a + bi); powers of ten
    as inline math, never Python's e-notation."""
    z = complex(x)
    if abs(z.imag) <= 1e-12 * max(1.0, abs(z.real)):
        return _real(z.real, digits)
    sign = "+" if z.imag >= 0 else "-"
    return f"{_real(z.real, digits)} {sign} {_real(abs(z.imag), digits)}i"
