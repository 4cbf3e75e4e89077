"""The ham1 summary tables (zener_sym.ham.table): error bound against the mpmath closed forms
between the nodes, the piece boundary lam_cont, range checks, and freshness of the committed
generated/ham1_table.py."""
from __future__ import annotations

import mpmath
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.codegen import inputs_hash
from zener_sym.ham.runtime_mpmath import ham1 as m1
from zener_sym.ham.runtime_numpy import ham1 as h1
from zener_sym.generated import ham1_table
from zener_sym.ham import table, table_build

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")
LAM_CONT = ham1_table.LAM_CONT
# between the nodes: on every piece, on both sides of lam_cont, and up to 3e-5 below lam_crit
# (2.4424 is above the last node, 2.44205)
OFF_NODES = (0.137, 1.46, LAM_CONT - 3e-4, LAM_CONT + 2e-5, 2.27, 2.4405, 2.4424)


def _distance_to_nodes(lam: float) -> float:
    """Smallest distance from lam to a node of the table, in lambda."""
    lam_cont = ham1_table.LAM_CONT
    nodes = np.concatenate([table_build.piece_nodes(k, a, b, n) for (k, a, b), n in zip(
        table_build.pieces(lam_cont), table_build.N_NODES)])
    return float(np.min(np.abs(nodes - lam)))


@pytest.mark.parametrize("lam", OFF_NODES)
def test_summary_within_the_documented_bound_of_mpmath(lam):
    """Every field within SUMMARY_RTOL (relative) of the mpmath closed forms at dps 30."""
    assert _distance_to_nodes(lam) > 1e-6, "the point must lie between the nodes"
    got = zs.summary(lam, model="ham1")
    ref = zs.summary(lam, model="ham1", backend="mpmath", dps=30)
    for f in FIELDS:
        a, b = float(getattr(got, f)), float(getattr(ref, f))
        assert abs(a - b) <= table.SUMMARY_RTOL * abs(b), (lam, f, a, b)


def test_lam_cont_is_where_tau_d_meets_pi_over_omega0():
    """The stored piece boundary, checked with the mpmath closed forms (an independent route
    from the float64 root finding of the builder): the first-order contact end equals
    pi/omega0 there, and lies beyond it just below, before it just above."""
    with mpmath.workdps(30):
        for dl, sign in ((0.0, 0), (-1e-4, 1), (1e-4, -1)):
            x = LAM_CONT + dl
            tpi = mpmath.pi / m1.params(x)[2]
            diff = float(m1.contact_end(x) - tpi)
            if sign == 0:
                assert abs(diff) < 1e-11 * float(tpi)
            else:
                assert np.sign(diff) == sign and abs(diff) > 1e-6


def test_continuous_across_the_piece_boundaries():
    for edge in (table_build.LAM_SPLIT, LAM_CONT):
        lo, hi = np.nextafter(edge, 0.0), np.nextafter(edge, 3.0)
        v = table.summary(np.array([lo, edge, hi]))
        for f, x in v.items():
            np.testing.assert_allclose(x, x[1], rtol=1e-13, err_msg=f"{f} at {edge}")


def test_batch_and_scalar_agree_bit_for_bit():
    lam = np.array([0.0, 0.3, 1.0, 1.9, LAM_CONT, 2.2, 2.42, 2.4424])
    batch = zs.summary(lam, model="ham1")
    for i, x in enumerate(lam):
        one = zs.summary(float(x), model="ham1")
        for f in FIELDS:
            assert float(getattr(one, f)) == getattr(batch, f)[i], (x, f)
    assert zs.summary(lam.reshape(2, 4), model="ham1").tau_d.shape == (2, 4)


def test_range_is_zero_to_lam_crit():
    assert table.LAM_MAX == h1.LAM_CRIT and table.LAM_MIN == 0.0
    with pytest.warns(DeprecationWarning, match="LAM_MAX"):
        assert table.lam_max() == table.LAM_MAX
    assert list(table.in_range([-1e-300, 0.0, 2.44, h1.LAM_CRIT])) == [False, True, True, False]
    for bad in (-0.1, h1.LAM_CRIT, 3.0):
        with pytest.raises(ValueError, match="outside the ham1 table's range"):
            table.summary(np.array([bad]))


def test_committed_table_is_fresh():
    """generated/ham1_table.py matches a rebuild (inputs hash and coefficients)."""
    assert ham1_table.INPUTS_HASH == inputs_hash(table_build.input_files()), (
        "generated/ham1_table.py is stale: run `zener-sym ham1-table` and commit it")
    problems = table_build.compare(vars(ham1_table), table_build.build_tables())
    assert not problems, "\n".join(problems)


def test_check_command_passes_and_detects_a_change(capsys):
    """`zener-sym regen --check ham1-table` passes on the committed table; the comparison it
    makes fails on a perturbed one."""
    from zener_sym.cli import regen

    assert regen.run(["ham1-table"], check=True) == 0
    assert "ham1-table: up to date" in capsys.readouterr().out
    coef = dict(ham1_table.SUMMARY)
    coef["tau_dc"] = tuple(tuple(c) for c in coef["tau_dc"][:1]) + tuple(
        (c[0] * (1 + 1e-9),) + tuple(c[1:]) for c in coef["tau_dc"][1:])
    stored = {**vars(ham1_table), "SUMMARY": coef}
    problems = table_build.compare(stored, table_build.build_tables())
    assert any("tau_dc lambda piece 1" in p for p in problems), problems


@pytest.mark.parametrize("lam", (0.5, 2.2, 2.42))
def test_history_ends_at_the_summary_tau_d(lam):
    """The history's contact ends at the tabulated tau_d (series rows and, at 2.42, kernel rows):
    delta is 0 from there on and positive just before; the impulse there is the summary's."""
    s = zs.summary(lam, model="ham1")
    h = zs.history(lam, s.tau_d * np.array([1 - 1e-9, 1.0, 1.0 + 1e-12]), model="ham1")
    assert h.delta[0] > 0 and h.delta[1] == 0 and h.delta[2] == 0
    np.testing.assert_allclose(h.impulse[1:], s.impulse, rtol=1e-12)
