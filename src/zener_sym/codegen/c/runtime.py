"""Hand-written C around the printed formulas and the table data, kept as plain C text beside
this module (``zener_sym.h.in``: the header's API; ``types.c.in``: the table types;
``runtime.c.in``: the functions that evaluate the tables the way ``zener_sym.exact.table``,
``zener_sym.exact.force_table`` and ``zener_sym.ham.table`` do (piece lookup, lambda maps, time
maps, Horner per sub-piece), the square-root integrals of ``zener_sym.numerics.sqrt_integrals``,
and the inverse e -> lambda). The emitter (``codegen.c``) fills in the ``@NAME@`` slots."""
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
