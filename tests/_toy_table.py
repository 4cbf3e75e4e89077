"""A table the package does not ship, as a configuration alone: a summary (fields ``one`` and
``g`` = ln(1 + lambda)) on a lambda piece and a sqrt(lambda) piece, and a two-field history on
sub-pieces of a reduced time y in [0, 1] (f = exp(-lambda y), I = sin(lambda y)), given to the
engine's ``TableBuilder`` with no module of its own. tests/test_cheb_table.py evaluates it in
Python, tests/test_c_new_table.py in C (the closed forms are the independent route)."""
from __future__ import annotations

import numpy as np

from zener_sym.numerics import cheb_table_build as engine
from zener_sym.numerics.cheb_table import TableSpec

#: Sub-pieces of the time piece, Chebyshev points per sub-piece.
N_SUB, N_TIME = 4, 12
#: The history's series: (time piece, field).
KEYS = (("T", "f"), ("T", "I"))


def g(lam):
    """The summary's field g: ln(1 + lambda)."""
    return np.log1p(np.asarray(lam, dtype=float))


def builder():
    """The toy table's ``TableBuilder``: its description, its file's words, its sample function
    and its history settings."""
    y = engine.sub_nodes(N_SUB, N_TIME)

    def sample(p, lams):
        return [{"one": 1.0, "g": float(g(lam)), ("T", "f"): np.exp(-lam * y),
                 ("T", "I"): np.sin(lam * y)} for lam in lams]

    return engine.TableBuilder(
        spec=TableSpec(pieces=(("lam", 0.0, 1.0), ("sqrt_lam", 1.0, 3.0)), fields=("one", "g"),
                       nodes=(16, 16), trim=1e-15, check_rtol=1e-12),
        file=engine.TableFile("toy_table.py", "toy-table", title="A toy table.",
                              provenance="Built by the test."),
        sample=sample, digest=lambda: "0" * 16,
        history=engine.HistorySettings(keys=KEYS, trim=1e-15, quantum=1e-17,
                                       weight=lambda data, key: np.ones(N_SUB),
                                       note=("#: the toy history",)))
