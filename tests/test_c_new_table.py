"""A new table in C is a configuration (issue 36, section 2): the toy table of
``_toy_table`` (a summary and a two-field history, built by the engine's ``TableBuilder`` from
its configuration alone) is rendered to its module's text, read back, emitted by the C emitter
that writes the shipped tables (``codegen.c.build_source(extra=...)``: one ``zs__table``, its
enums generated from the module's description) and evaluated by the C runtime's one summary
evaluator (``zs__eval``) and one history engine (``zs__history_run``). The table's own C is only
its reduced time and back-transform (the ``zs__kind`` written below): no struct, emitter, enum
or dispatch of its own.

References: the Python engine on the same module (``SummaryTable.values``: the same doubles in
order of degree, as tests/test_c_kernels.py demands of the shipped tables; the history by
``History`` with the toy's time maps, ``_toy_table.python_values``: within 1e-14 of the value with a
floor of 1e-14 of the field's scale, the shipped histories' bound), and the closed forms the
table was built from (f = exp(-lambda y), I = sin(lambda y), g = ln(1 + lambda)).

The system C compiler builds it (gcc, cc or clang; CI installs them); a missing compiler skips
with that reason.
"""
from __future__ import annotations

import pathlib
import re
import shutil
import subprocess

import numpy as np
import pytest

import _toy_table as toy_table

C_DIR = pathlib.Path(__file__).resolve().parents[1] / "generated" / "c"
CC = shutil.which("gcc") or shutil.which("cc") or shutil.which("clang")
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]

pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler (gcc, cc or clang) on PATH: "
                                                   "the C kernels cannot be built here")

#: The toy table's own C: its kind (time piece T on the reduced time y in [0, 1], z = k y;
#: past y = 1 no history; the two fields as they are), and a driver. stdin: the lambdas, then
#: the times; stdout per lambda: the summary's fields in order (a history's mode) and in a
#: summary's mode, then per time the two fields (hexadecimal doubles).
KIND_AND_DRIVER = r"""
static void zs__toy_setup(zs__hist_t *H)
{
    (void)H;
}

static void zs__toy_reduce(const zs__hist_t *H, const double *tau, size_t nb, zs__blk_t *B)
{
    const double k = H->t->piece[ZS__TP_T].n_sub;
    size_t b;
    for (b = 0; b < nb; b++) {
        B->pc[b] = tau[b] <= 1.0 ? ZS__TP_T : ZS__NTP;
        B->z[b] = tau[b] * k;
    }
}

static void zs__toy_back(const zs__hist_t *H, size_t nb, zs__blk_t *B, double *const *o)
{
    size_t b;
    (void)H;
    for (b = 0; b < nb; b++) {
        o[0][b] = B->h[ZS__TH_F][b];
        o[1][b] = B->h[ZS__TH_I][b];
    }
}

static const zs__kind zs__kind_toy = {NULL, NULL, zs__toy_setup, zs__toy_reduce, zs__toy_back};

#include <stdio.h>
#include <stdlib.h>
int main(void)
{
    size_t n_lam, n, i, j;
    double *lam, *tau, *o[ZS__NOUT], v[ZS__NT], x;
    int order;
    if (scanf("%zu", &n_lam) != 1)
        return 2;
    lam = (double *)malloc(n_lam * sizeof *lam);
    for (i = 0; i < n_lam; i++)
        if (scanf("%lf", &lam[i]) != 1)
            return 2;
    if (scanf("%zu", &n) != 1)
        return 2;
    tau = (double *)malloc(n * sizeof *tau);
    for (i = 0; i < n; i++)
        if (scanf("%lf", &tau[i]) != 1)
            return 2;
    for (j = 0; j < ZS__NOUT; j++)
        o[j] = (double *)malloc(n * sizeof *o[j]);
    for (i = 0; i < n_lam; i++) {
        for (order = 1; order >= 0; order--) {
            zs__eval(&zs__tab_toy.s, lam[i], zs__tab_toy.s.pieces.n - 1, order, v, &x);
            printf("%a %a\n", v[ZS__T_ONE], v[ZS__T_G]);
        }
        if (zs__history_run(&zs__tab_toy, &zs__kind_toy, lam[i], n, tau, o) != ZS_OK)
            return 3;
        for (j = 0; j < n; j++)
            printf("%a %a\n", o[0][j], o[1][j]);
    }
    return 0;
}
"""


@pytest.fixture(scope="module")
def toy():
    """The toy table: built, rendered, read back from its text (the generated module's names)."""
    builder = toy_table.builder()
    ns: dict = {}
    exec(builder.render(builder.build()), ns)  # noqa: S102 - the engine's own output
    return ns


def _times():
    """Reduced times in [0, 1]: every sub-piece's ends and their neighbouring doubles, a grid,
    and unsorted random times (more than a block of the C engine, ZS__BLOCK = 256)."""
    ends = np.arange(toy_table.N_SUB + 1) / toy_table.N_SUB
    near = np.concatenate([ends, np.nextafter(ends[1:], 0), np.nextafter(ends[:-1], 1)])
    return np.concatenate([near, np.linspace(0.0, 1.0, 101),
                           np.random.default_rng(11).uniform(0.0, 1.0, 600)])


def test_a_new_table_with_a_history_in_c(tmp_path, toy):
    from zener_sym.codegen.c import CTable, build_source

    source = build_source(extra=[CTable("toy", "T", ns=toy)])
    # the toy's C data and enums come from its module: the struct every table has, its field
    # and time-piece names generated from TABLE_FIELDS and HISTORY
    assert "static const zs__table zs__tab_toy = {" in source
    for name in ("ZS__T_ONE", "ZS__T_G", "ZS__TP_T", "ZS__TH_F", "ZS__TH_I"):
        assert re.search(rf"^    {name},$", source, re.M), name
    src = tmp_path / "toy.c"
    src.write_text(source + KIND_AND_DRIVER, encoding="utf-8")
    r = subprocess.run([CC, *STRICT, "-Wno-unused-function", "-O2", f"-I{C_DIR}", str(src), "-o",
                        str(tmp_path / "toy"), "-lm"],
                       capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    lams = np.concatenate([[0.0, 0.4, 1.0, 1.7, 3.0, np.nextafter(1.0, 0)],
                           np.random.default_rng(5).uniform(0.0, 3.0, 6)])
    y = _times()
    stdin = " ".join([str(lams.size), *map(repr, lams.tolist()), str(y.size),
                      *map(repr, y.tolist())])
    run = subprocess.run([str(tmp_path / "toy")], input=stdin, capture_output=True, text=True,
                         check=True)
    rows = [[float.fromhex(w) for w in line.split()] for line in run.stdout.splitlines()]
    per = 2 + y.size
    assert len(rows) == lams.size * per
    for n, lam in enumerate(lams):
        block = np.array(rows[n * per:(n + 1) * per])
        s_order, s_summary, hist = block[0], block[1], block[2:]
        v, f, i = toy_table.python_values(toy, lam, y)
        # the summary: in order of degree Python's doubles, bit for bit; in a summary's mode
        # (other dependency chains) within a few ulps of each series' scale
        np.testing.assert_array_equal(s_order, v, err_msg=f"lambda {lam!r}")
        assert np.all(np.abs(s_summary - v) <= 4e-15 * np.maximum(np.abs(v), 1.0)), lam
        # the history: the shipped histories' bound against Python (tests/test_c_kernels.py)
        for got, want, name in ((hist[:, 0], f, "f"), (hist[:, 1], i, "I")):
            bad = ~(np.abs(got - want) <= 1e-14 * np.maximum(np.abs(want), 1.0))
            assert not bad.any(), (lam, name, y[bad][:3], got[bad][:3], want[bad][:3])
        # and the closed forms the table was built from (the fit's accuracy)
        np.testing.assert_allclose(s_order[1], toy_table.g(lam), rtol=0, atol=1e-12)
        np.testing.assert_allclose(hist[:, 0], np.exp(-lam * y), rtol=0, atol=1e-12)
        np.testing.assert_allclose(hist[:, 1], np.sin(lam * y), rtol=0, atol=1e-12)


#: Names of the shipped table modules that repeat their description (``TABLE_*``) or only order
#: and check what HISTORY holds; the emitter must not need them (issue 36: "each generated file
#: is described twice"; the engine has dropped the first three).
LAYOUT_ONLY = ("LAM_PIECES", "LOG_FROM", "SUMMARY_KEYS", "TIME_PIECES", "HISTORY_KEYS", "N_SUB",
               "HISTORY_TO")


def _stripped(ns):
    return {k: v for k, v in ns.items() if k not in LAYOUT_ONLY}


def _outputs(exe, lams, tau):
    stdin = " ".join(map(repr, [*lams.tolist(), *tau.tolist()]))
    r = subprocess.run([str(exe), str(lams.size), str(tau.size)], input=stdin,
                       capture_output=True, text=True, check=True)
    return r.stdout


SHIPPED_DRIVER = r"""
#include <stdio.h>
#include <stdlib.h>
#include "zener_sym.h"
/* argv: lambdas, times; stdin: their values; stdout: every output of both ends and ham1 */
int main(int argc, char **argv)
{
    size_t m = (size_t)atol(argv[1]), n = (size_t)atol(argv[2]), i, j;
    double *lam = malloc(m * sizeof *lam), *tau = malloc(n * sizeof *tau), *o[4];
    zs_summary_t s;
    int end, k;
    (void)argc;
    for (i = 0; i < m; i++)
        if (scanf("%lf", &lam[i]) != 1)
            return 2;
    for (i = 0; i < n; i++)
        if (scanf("%lf", &tau[i]) != 1)
            return 2;
    for (k = 0; k < 4; k++)
        o[k] = malloc(n * sizeof *o[k]);
    for (i = 0; i < m; i++) {
        for (end = ZS_DELTA; end <= ZS_FORCE; end++) {
            int rc = zs_summary(lam[i], end, &s);
            printf("%d %a %a %a %a %a %a\n", rc, s.delta_m, s.tau_d, s.e, s.F_m, s.int_F2, s.xi);
            printf("%a\n", zs_lam_for_e(s.e, end));
            rc = zs_history(lam[i], end, n, tau, o[0], o[1], o[2], o[3]);
            for (j = 0; j < n; j++)
                printf("%d %a %a %a %a\n", rc, o[0][j], o[1][j], o[2][j], o[3][j]);
        }
        k = zs_ham1_summary(lam[i] / 500.0, &s);
        printf("%d %a %a\n", k, s.delta_m, s.e);
    }
    return 0;
}
"""


def test_the_emitter_reads_the_description_not_the_layout_names(tmp_path):
    """The shipped tables' modules without the names that repeat their description (Layout's
    LAM_PIECES, LOG_FROM, SUMMARY_KEYS; TIME_PIECES, HISTORY_KEYS, N_SUB, HISTORY_TO) and with
    ham1's series under SUMMARY: the emitted library gives every output of the shipped one, bit
    for bit (the time pieces and fields then come in HISTORY's order, read by their generated
    names)."""
    from zener_sym.codegen.c import TABLES, CTable, build_source

    stripped = [CTable(t.name, t.tag, kind=t.kind, contact_end=t.contact_end, fold_x=t.fold_x,
                       ns=_stripped(t.module())) for t in TABLES]
    assert [k for t in stripped for k in LAYOUT_ONLY + ("COEF",) if k in t.module()] == []
    exes = {}
    for name, text in (("shipped", (C_DIR / "zener_sym.c").read_text(encoding="utf-8")),
                       ("stripped", build_source(tables=stripped))):
        (tmp_path / f"{name}.c").write_text(text, encoding="utf-8")
        (tmp_path / f"main_{name}.c").write_text(SHIPPED_DRIVER, encoding="utf-8")
        exes[name] = tmp_path / name
        r = subprocess.run([CC, "-O2", f"-I{C_DIR}", str(tmp_path / f"{name}.c"),
                            str(tmp_path / f"main_{name}.c"), "-o", str(exes[name]), "-lm"],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
    lams = np.concatenate([[0.0, 1e-9, 0.25, 1.0, 4.999, 5.0, 7.5, 999.0, 1000.0, 1001.0],
                           np.random.default_rng(3).uniform(0.0, 1000.0, 8)])
    tau = np.linspace(0.0, 4.0, 700)
    shipped, again = (_outputs(exes[k], lams, tau) for k in ("shipped", "stripped"))
    assert shipped.count("\n") == lams.size * (2 * (2 + tau.size) + 1)
    assert again == shipped
