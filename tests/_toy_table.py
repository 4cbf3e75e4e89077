"""A table the package does not ship, as a configuration alone: a summary (fields ``one`` and
``g`` = ln(1 + lambda)) on a lambda piece and a sqrt(lambda) piece, and a two-field history on
sub-pieces of a reduced time y in [0, 1] (f = exp(-lambda y), I = sin(lambda y)), given to the
engine's ``TableBuilder`` with no module of its own. tests/test_cheb_table.py evaluates it in
Python, tests/test_c_new_table.py in C (the closed forms are the independent route)."""
from __future__ import annotations

import numpy as np

from zener_sym.numerics import cheb_table_build as engine
from zener_sym.numerics.cheb_table import SummaryTable, TableSpec, spec_of
from zener_sym.numerics.cheb_table_history import History, Lines, TimeMaps

#: Sub-pieces of the time piece, Chebyshev points per sub-piece.
N_SUB, N_TIME = 4, 12


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
        history=history())


def history():
    """The toy history's settings: (T, f) = exp(-lambda y), (T, I) = sin(lambda y) on N_SUB
    sub-pieces, up to lambda = 3."""
    return engine.HistorySettings(time_pieces=("T",), fields=("f", "I"), n_sub={"T": N_SUB},
                                  hi=3.0, trim=1e-15, quantum=1e-17,
                                  weight=lambda data, key: np.ones(N_SUB),
                                  note=("#: the toy history",))


class ToyMaps(TimeMaps):
    """A toy instance's time maps: one time piece "T" over 0 <= tau <= 1 with reduced time
    y = tau, the stored fields as they are, and past tau = 1 their values at y = 1."""

    fields = ("f", "I")

    def __init__(self, lam):
        self.lam = lam

    def piece_of(self, lines):
        return (lines.tau > 1.0).astype(np.int8)

    def constants(self, name, k):
        return k

    def reduced_time(self, name, m, t, li):
        return t * m, None

    def store(self, name, f, g, t, li, aux, out, at):
        out["f"][at], out["I"][at] = f, g

    def after(self, out, at, li):
        out["f"][at], out["I"][at] = np.exp(-self.lam[li]), np.sin(self.lam[li])


def python_values(ns, lam, y):
    """The Python engine on the toy module: the summary at lambda (in the fields' order) and
    the history (f, I) at the reduced times y (``History`` with :class:`ToyMaps`)."""
    spec = spec_of(ns)
    tab = SummaryTable(spec.pieces, spec.fields, ns["SUMMARY"], "toy")
    lines = Lines.of(np.full((1, y.size), float(lam)), np.asarray(y, dtype=float)[None, :])
    history = History.of(ns, "toy history")
    tab.check(lines.lam, history.hi)
    v, ip, xl, _ = tab.values(lines.lam)
    out = history.evaluate(lines, ip, history.basis(xl), ToyMaps(lines.lam))
    return np.array([v[f][0] for f in spec.fields]), out["f"], out["I"]
