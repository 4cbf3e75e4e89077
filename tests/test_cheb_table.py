"""The one Chebyshev-table engine (``numerics.cheb_table``, ``numerics.cheb_table_history`` and
``numerics.cheb_table_build``): a new table is a configuration. Small tables are built here from configurations the package
does not ship (a closed-form function on pieces of every kind, an ODE solved by scipy at each
node, a two-field history on sub-pieces) and evaluated by the same evaluator the plate's, the
force-free end's and the ham1 tables use, against independent routes (the closed forms)."""
from __future__ import annotations

import numpy as np
import pytest

from zener_sym.numerics import cheb_table_build as engine
from zener_sym.numerics.cheb_table import (PIECE_KINDS, SummaryTable, TableSpec, spec_assignments,
                                           spec_of)
from zener_sym.numerics.cheb_table_history import (History, Lines, history_rows,
                                                   sub_piece_values)

import _toy_table as toy_table

#: One piece of every kind: lambda, sqrt(lambda - start) (a (lambda - 2)^{3/2} term at its
#: start), sqrt(lambda), ln lambda.
PIECES = (("lam", 0.0, 2.0), ("sqrt", 2.0, 3.0), ("sqrt_lam", 3.0, 5.0), ("log", 5.0, 400.0))


def _f(lam):
    """A function with a branch point at lambda = 2: analytic in sqrt(lambda - 2) above it."""
    lam = np.asarray(lam, dtype=float)
    s = np.sqrt(np.maximum(lam - 2.0, 0.0))
    return np.where(lam < 2.0, np.exp(-lam / 3.0) * np.cos(lam), np.exp(-2.0 / 3.0) * np.cos(2.0)
                    + s**3 / (1.0 + lam / 50.0))


def _g(lam):
    return np.log1p(np.asarray(lam, dtype=float))


def _dg(lam):
    return 1.0 / (1.0 + np.asarray(lam, dtype=float))


def _spec(**kw):
    args = {"pieces": PIECES, "fields": ("f", "g"), "nodes": (30, 30, 30, 40), "trim": 1e-15,
            "check_rtol": 1e-12}
    args.update(kw)
    return TableSpec(**args)


def _summary_table(spec):
    t = engine.build_tables(spec, lambda p, lam: [{"f": float(_f(x)), "g": float(_g(x))}
                                                  for x in lam])
    return t, SummaryTable(spec.pieces, spec.fields, t["summary"], "test table",
                           "; use the closed form")


def test_kinds_are_the_documented_ones():
    assert set(PIECE_KINDS) == {"lam", "log", "sqrt", "sqrt_lam"}
    assert {k for k, _, _ in PIECES} == set(PIECE_KINDS)


def test_a_new_table_is_a_configuration():
    """Pieces of every kind, built by the engine and evaluated by the engine, against the closed
    form between the nodes and at the pieces' ends (the values, d/dlambda, one series)."""
    _, tab = _summary_table(_spec())
    lam = np.concatenate([np.linspace(0.0, 400.0, 2001), [2.0, 2.0 + 1e-12, 3.0, 5.0],
                          np.random.default_rng(5).uniform(0, 6, 300)])
    v, i, x, _ = tab.values(lam)
    np.testing.assert_allclose(v["f"], _f(lam), rtol=0, atol=1e-13 * np.abs(_f(lam)).max())
    np.testing.assert_allclose(v["g"], _g(lam), rtol=1e-13, atol=1e-14)
    # d/dlambda through each piece's variable (the sqrt pieces' slope included; infinite at the
    # branch point lambda = 2, the sqrt piece's start)
    assert np.isinf(tab.derivatives(np.array([2.0]), *tab.values(np.array([2.0]))[1:3])["g"][0])
    inner = (lam > 0.01) & (np.abs(lam - 2.0) > 1e-6)
    d = tab.derivatives(lam[inner], i[inner], x[inner])
    np.testing.assert_allclose(d["g"], _dg(lam[inner]), rtol=1e-10)
    val, der = tab.one(lam[inner], "g")
    np.testing.assert_array_equal(val, v["g"][inner])
    np.testing.assert_allclose(der, _dg(lam[inner]), rtol=1e-10)


def test_range_and_description_are_checked():
    _, tab = _summary_table(_spec())
    assert tab.in_range([0.0, 400.0]).all() and not tab.in_range([-1e-9, 400.1]).any()
    with pytest.raises(ValueError, match=r"outside the test table's range \[0, 400\]; use"):
        tab.values(np.array([401.0]))
    with pytest.raises(ValueError, match="unknown piece kind 'cube'"):
        _spec(pieces=(("cube", 0.0, 1.0),), nodes=(3,))
    with pytest.raises(ValueError, match="contiguous"):
        _spec(pieces=(("lam", 0.0, 1.0), ("lam", 1.5, 2.0)), nodes=(3, 3))
    with pytest.raises(ValueError, match="2 node counts for 4 pieces"):
        _spec(nodes=(3, 3))


def test_scipy_node_function():
    """Nodes from scipy's integrator (y' = -lambda y^{3/2}, y(0) = 1, read at t = 1), the table
    against the closed form y(1) = (1 + lambda / 2)^-2."""
    from scipy.integrate import solve_ivp

    def sample(p, lams):
        out = []
        for lam in lams:
            r = solve_ivp(lambda t, y: -lam * y**1.5, (0.0, 1.0), [1.0], rtol=1e-12, atol=1e-14)
            out.append({"y": float(r.y[0, -1])})
        return out

    spec = TableSpec(pieces=(("lam", 0.0, 4.0), ("log", 4.0, 100.0)), fields=("y",),
                     nodes=(30, 30), trim=1e-13, check_rtol=1e-9)
    t = engine.build_tables(spec, sample)
    tab = SummaryTable(spec.pieces, spec.fields, t["summary"], "ode table")
    lam = np.linspace(0.0, 100.0, 777)
    v, _, _, _ = tab.values(lam)
    np.testing.assert_allclose(v["y"], (1.0 + lam / 2.0) ** -2, rtol=1e-9)


def test_rendered_table_reads_back_and_compares():
    """The text the engine writes (description, summary, history) reads back to the same
    numbers; ``compare`` passes it and catches a moved coefficient."""
    spec = _spec()
    t, _ = _summary_table(spec)
    mat = np.array([[1.0, 2.5e-3], [-3.0e-7, 0.0]])
    t["history"] = {("T", "f"): [(mat,)] * 4}
    t["weights"] = {("T", "f"): [(1.0,)] * 4}
    lines = [*spec_assignments(spec), *engine.render_summary("SUMMARY", t["summary"], spec.fields,
                                                              spec.digits),
             *engine.render_history(t["history"], t["weights"], 1e-15)]
    ns: dict = {}
    exec("\n".join(lines), ns)  # noqa: S102 - the engine's own output
    assert spec_of(ns) == spec
    stored = engine.stored_tables(ns)
    assert engine.compare(stored, t) == []
    # the rendered history string is written verbatim when re-rendered
    again = engine.render_history(stored["history"], {}, 1e-15)
    assert again == engine.render_history(t["history"], t["weights"], 1e-15)
    moved = {**t, "summary": {**t["summary"], "g": [c.copy() for c in t["summary"]["g"]]}}
    moved["summary"]["g"][3][2] *= 1 + 1e-9
    assert engine.compare(stored, moved) == [
        "summary g lambda piece 3: relative difference " + engine.compare(stored, moved)[0]
        .split("difference ")[1]]
    assert len(engine.compare(stored, moved)) == 1


def _check_history(history, tab, atol):
    """The engine's history with the toy maps on a grid of lambdas (a column per line, and
    scattered points) against the closed forms f = exp(-lambda y), I = sin(lambda y)."""
    lam = np.array([0.0, 0.3, 1.0, 2.2, 3.0, 0.3])  # a repeated lambda: one line
    tau = np.linspace(0.0, 1.2, 121)
    for lam_g, tau_g in ((lam[:, None] * np.ones(tau.size), tau[None, :]),
                         (np.repeat(lam, 20), np.resize(tau, lam.size * 20))):
        lines = Lines.of(lam_g, tau_g)
        tab.check(lines.lam, history.hi)
        _, ip, xl, _ = tab.values(lines.lam)
        out = history.evaluate(lines, ip, history.basis(xl), toy_table.ToyMaps(lines.lam))
        lam_y = (np.broadcast_to(lam_g, lines.shape) * np.minimum(np.broadcast_to(
            tau_g, lines.shape), 1.0)).ravel()
        np.testing.assert_allclose(out["f"], np.exp(-lam_y), rtol=0, atol=atol)
        np.testing.assert_allclose(out["I"], np.sin(lam_y), rtol=0, atol=atol)


def _toy_history(n_sub, n_time, hi):
    """The toy history's settings: (T, f) = exp(-lambda y), (T, I) = sin(lambda y)."""
    return engine.HistorySettings(time_pieces=("T",), fields=("f", "I"), n_sub={"T": n_sub},
                                  hi=hi, trim=1e-15, quantum=1e-17,
                                  weight=lambda data, key: np.ones(n_sub),
                                  note=("#: the toy history",))


def _toy_samples(lam, y):
    return {("T", "f"): np.exp(-lam * y), ("T", "I"): np.sin(lam * y)}


def test_history_on_sub_pieces():
    """A two-field history on sub-pieces of a reduced time y in [0, 1] (the exact tables'
    layout): built by the engine and evaluated by its ``History`` with a toy instance's time
    maps, against the closed forms f = exp(-lambda y) and I = sin(lambda y)."""
    n_sub, n_time = 4, 12
    y = engine.sub_nodes(n_sub, n_time)
    spec = TableSpec(pieces=(("lam", 0.0, 1.0), ("lam", 1.0, 3.0)), fields=("one",),
                     nodes=(14, 14), trim=1e-15, check_rtol=1e-12)

    def sample(p, lams):
        return [{"one": 1.0, **_toy_samples(lam, y)} for lam in lams]

    t = engine.build_tables(spec, sample, _toy_history(n_sub, n_time, 3.0))
    piece = history_rows([t["history"][("T", "f")], t["history"][("T", "I")]])
    assert piece.n_sub == n_sub and len(piece.rows) == 2
    tab = SummaryTable(spec.pieces, spec.fields, t["summary"], "history test")
    _check_history(History({"T": piece}, 3.0, "history test"), tab, 1e-13)


def test_one_guard_on_the_sub_piece():
    """The engine's one guard: rounding past a piece's ends is clamped (z a hair below 0 is
    sub-piece 0, z at or past K the last), a reduced time that would index another line's row
    raises: ValueError for a negative or NaN time, RuntimeError (a bug) otherwise."""
    k = 2
    # one line, two sub-pieces: field 0 = 10 s + x (monomial in the sub-piece's x), field 1 = 0
    rows = np.array([[10.0 * s + 0j for s in range(k)], [1.0 + 0j] * k])
    f, _ = sub_piece_values(rows, k, np.array([-1e-17, 0.5, 1.5, k + 1e-12]), np.zeros(4, np.intp),
                            np.ones(4), "toy")
    np.testing.assert_allclose(f, [-1.0, 0.0, 10.0, 11.0], atol=1e-10)
    for z, t, err in ((-1.0, 0.5, RuntimeError), (-3.0, -1.0, ValueError),
                      (np.nan, np.nan, ValueError), (np.nan, 0.5, RuntimeError)):
        with pytest.raises(err, match="toy"):
            sub_piece_values(rows, k, np.array([0.5, z]), np.zeros(2, np.intp),
                             np.array([0.5, t]), "toy")


@pytest.mark.parametrize("builder, module", [
    ("zener_sym.exact.table_build", "zener_sym.generated.exact_table"),
    ("zener_sym.exact.force_table_build", "zener_sym.generated.exact_force_table"),
    ("zener_sym.ham.table_build", "zener_sym.generated.ham1_table")])
def test_committed_tables_rerender_byte_for_byte(builder, module):
    """Each committed table, read back (``as_tables``) and rendered by its builder, is its own
    file byte for byte from INPUTS_HASH on (the docstring above names the scipy installed):
    what ``zener-sym regen`` writes when a rebuild agrees with it."""
    import importlib
    import pathlib

    b, m = importlib.import_module(builder), importlib.import_module(module)
    committed = pathlib.Path(m.__file__).read_text(encoding="utf-8")
    text = b.render(b.as_tables(vars(m)))
    start = committed.index("INPUTS_HASH = ")
    assert text[text.index("INPUTS_HASH = "):] == committed[start:]


def test_a_new_table_with_a_history_is_a_builder_configuration():
    """A table with a summary and a history, from a ``TableBuilder`` configuration alone (no
    module of its own): built, rendered to a module's text, read back by the runtime's
    ``SummaryTable.of`` and ``History.of``, evaluated (the ordered sum; the engine's history
    with a toy instance's time maps: its reduced time and back-transform only) against the
    closed forms f = exp(-lambda y), I = sin(lambda y), and compared with its rebuild (and with
    a moved coefficient). The configuration is tests/_toy_table.py, which
    tests/test_c_new_table.py evaluates in C."""
    builder = toy_table.builder()
    built = builder.build()
    text = builder.render(built)
    assert text.startswith('"""A toy table.') and "GENERATED by `zener-sym regen toy-table`" in text
    ns: dict = {}
    exec(text, ns)  # noqa: S102 - the engine's own output
    assert builder.render(ns) == text and builder.compare(ns, built) == []
    g = ns["SUMMARY"]["g"]
    moved = {**ns, "SUMMARY": {**ns["SUMMARY"], "g": (g[0], tuple(1.001 * c for c in g[1]))}}
    problems = builder.compare(moved, built)
    assert len(problems) == 1 and problems[0].startswith("summary g lambda piece 1:"), problems

    tab = SummaryTable.of(ns, "toy table")
    lu = np.array([0.0, 0.4, 1.0, 1.7, 3.0])
    v, _, _, _ = tab.values(lu)
    np.testing.assert_allclose(v["g"], toy_table.g(lu), rtol=0, atol=1e-12)
    _check_history(History.of(ns, "toy history"), tab, 1e-12)


def test_a_series_zero_in_both_tables_agrees():
    """``compare``'s rule for a series stored as 0 where it is unused (the force-free end's
    log_tau_p on its ln-lambda pieces): zero against zero agrees, zero against nonzero is a
    difference."""
    spec = TableSpec(pieces=(("lam", 0.0, 1.0), ("log", 1.0, 10.0)), fields=("a",), nodes=(4, 4),
                     trim=1e-15, check_rtol=1e-12)
    zero = {"spec": spec, "summary": {"a": [np.array([1.0, 0.5]), np.zeros(1)]}}
    assert engine.compare(zero, zero) == []
    moved = {"spec": spec, "summary": {"a": [np.array([1.0, 0.5]), np.array([1e-30])]}}
    assert len(engine.compare(zero, moved)) == 1 and len(engine.compare(moved, zero)) == 1
