"""Hand-written C around the printed formulas and the table data, kept as plain C text beside
this module (``zener_sym.h.in``: the header's API; ``types.c.in``: the one table type
``zs__table``; ``runtime.c.in``: the one summary evaluator ``zs__eval`` and the one history
engine ``zs__history_run`` (blocks, sub-piece lookup, contraction in lambda, Horner), the kinds
that supply each end of contact's derived summary, reduced time and back-transform, as
``zener_sym.exact.table`` and ``zener_sym.exact.force_table`` do, the ham1 summary of
``zener_sym.ham.table``, the square-root integrals of ``zener_sym.numerics.sqrt_integrals``, and
the inverse e -> lambda). The emitter (``codegen.c``) fills in the ``@NAME@`` slots."""
from __future__ import annotations

import pathlib

_HERE = pathlib.Path(__file__).resolve().parent

#: The C template files, in the order the emitter reads them.
TEMPLATES = ("zener_sym.h.in", "types.c.in", "runtime.c.in")


def _read(name: str) -> str:
    return (_HERE / name).read_text(encoding="utf-8")


HEADER = _read("zener_sym.h.in")
TYPES = _read("types.c.in")
RUNTIME = _read("runtime.c.in")
