"""The registry of checks, and the small helpers every topic module uses.

A check is registered with ``@check(id, ...)`` and called as ``fn(item_id)``; it returns a
:class:`~.verdicts.Verdict`. One function may serve several items (it reads ``item_id``). The topic
modules (:mod:`.forms_core`, :mod:`.forms_first_order`, :mod:`.constants`, :mod:`.units`,
:mod:`.claims`, :mod:`.claims_literature`) register their checks when imported; :mod:`.checks`
imports them all.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import SupportsFloat

import sympy as sp

from . import derived, printed
from .printed import Expr
from .texts import tex
from .verdicts import Verdict, compare

__all__ = ["CHECKS", "Check", "check", "printed_form", "printed_decimal", "printed_float",
           "hertz_constant", "hunter_factor",
           "sentences", "source", "compare_form", "named_form", "hyper"]

#: A check: called with the item id, returns the item's verdict.
Check = Callable[[str], Verdict]

#: item id -> check function (called with the item id, returns a Verdict).
CHECKS: dict[str, Check] = {}


def check(*ids: str) -> Callable[[Check], Check]:
    """Register the decorated function as the check of each item in ``ids``."""
    def deco(fn: Check) -> Check:
        for i in ids:
            if i in CHECKS:
                raise ValueError(f"item {i!r} has two checks: {CHECKS[i].__name__} and {fn.__name__}")
            CHECKS[i] = fn
        return fn
    return deco


def printed_form(item_id: str) -> Expr:
    """The SymPy form of the printed transcription of ``item_id`` (:func:`.printed.parse`)."""
    return printed.parse(printed.by_id(item_id))


def printed_decimal(value: SupportsFloat) -> str:
    """A printed number of a transcription as the decimal string it was printed as ('0.966').

    The transcription holds plain decimals without trailing zeros, so ``%g`` gives the digits
    back; :func:`.verdicts.rounds_to` reads the number of printed decimals from it.
    """
    return f"{float(value):g}"


def printed_float(item_id: str) -> Expr:
    """The one decimal number printed in ``item_id``, as transcribed (read unevaluated, so that
    SymPy does not fold it into other constants)."""
    form: Expr = printed.parse(printed.by_id(item_id), evaluate=False)
    floats = form.atoms(sp.Float)
    if len(floats) != 1:
        raise ValueError(f"item {item_id!r} prints {len(floats)} decimal numbers, not one")
    return floats.pop()


def hertz_constant() -> Expr:
    """The printed 2.94 of (2): T_Hertz = 2.94 delta_m / V0 (Hertz's duration constant)."""
    return printed_float("2")


def hunter_factor() -> str:
    """The printed 1.068 of (4), delta = delta_m sin(1.068 V0 t / delta_m), as printed."""
    return printed_decimal(printed_float("4"))


def sentences(*parts: str) -> str:
    """Evidence text: the non-empty parts as sentences (first letter up, full stop)."""
    out = []
    for part in parts:
        part = part.strip()
        if not part:
            continue
        part = part[0].upper() + part[1:]
        out.append(part if part.endswith(".") else part + ".")
    return " ".join(out)


def source(src: str) -> str:
    """The provenance of a derived form, as a sentence."""
    return f"derived form: {src}"


def compare_form(item_id: str, derived_expr: Expr, source_: str, what: str = "",
                 transform: Callable[[Expr], Expr] | None = None, note_ok: str = "",
                 note_bad: str = "") -> Verdict:
    """Printed form of ``item_id`` (optionally transformed) against ``derived_expr``."""
    pr = printed_form(item_id)
    ok, ev = compare(pr if transform is None else transform(pr), derived_expr)
    return Verdict.form(ok, tex(derived_expr, item_id), sentences(what, ev, source(source_)),
                        note_bad=note_bad, note_ok=note_ok)


def named_form(item_id: str, name: str, *, what: str = "", note_ok: str = "",
               note_bad: str = "") -> Verdict:
    """Printed form of ``item_id`` against the derived form called ``name`` (:func:`.derived.get`)."""
    expr, src = derived.get(name)
    return compare_form(item_id, expr, src, what=what, note_ok=note_ok, note_bad=note_bad)


def hyper(expr: Expr) -> Expr:
    """The paper's ``G(a, b, c, z)`` as SymPy's hypergeometric 2F1(a, b; c; z)."""
    return expr.replace(printed.G, lambda a, b, c, z: sp.hyper([a, b], [c], z))
