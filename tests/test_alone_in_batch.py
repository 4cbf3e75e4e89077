"""A lambda gets the same bits alone as in a batch, through every public function a table backs.

The tables sum each series in one fixed order (``numerics.cheb_table._series_sum``: degree after
degree, left to right), so no value may depend on how many lambdas are evaluated with it, nor on
their order: ``zs.summary`` for each model a table backs (the exact plate end, the force-free end,
ham1), ``zs.lam_from_summary`` and ``exact.table.summary_derivative``. The batches are longer than
the sum's blocks (``_SUM_BLOCK``) and than the length up to which it gathers every degree at once
(``_GATHER_ALL``), so both of its paths meet the lambda alone.
"""
from __future__ import annotations

import numpy as np
import pytest

import zener_sym as zs
from zener_sym.exact import force_table, inverse, table
from zener_sym.numerics import cheb_table

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")
#: (model, options, lambda range) of each table behind ``zs.summary``.
TABLES = [("exact", {}, 1000.0), ("exact", {"contact_end": "force"}, 1000.0),
          ("ham1", {}, 2.44)]


def _lams(top: float, n: int, seed: int) -> np.ndarray:
    """n lambdas on [0, top], unsorted, with the range's ends and (for the exact tables) the
    pieces' edges and their neighbours among them."""
    rng = np.random.default_rng(seed)
    edges = [e for e in table._tables().summary.pieces.edges if e <= top] if top > 3 else []
    special = [0.0, top, *edges, *(np.nextafter(e, 0.0) for e in edges if e > 0)]
    lam = np.concatenate([special, rng.uniform(0.0, top, n - len(special))])
    return rng.permutation(lam)


def test_the_batches_cover_both_paths_of_the_sum():
    assert 1 <= cheb_table._GATHER_ALL < 1500 and cheb_table._SUM_BLOCK < 1500


@pytest.mark.parametrize("model, options, top", TABLES)
def test_summary_alone_is_the_batch(model, options, top):
    lam = _lams(top, 1500, 1)
    batch = zs.summary(lam, model=model, **options)
    backwards = zs.summary(lam[::-1], model=model, **options)
    for j in range(0, 1500, 9):  # 167 lambdas alone
        one = zs.summary(float(lam[j]), model=model, **options)
        for f in FIELDS:
            assert float(getattr(one, f)) == getattr(batch, f)[j], (model, options, lam[j], f)
    for f in FIELDS:
        np.testing.assert_array_equal(getattr(backwards, f)[::-1], getattr(batch, f), err_msg=f)


@pytest.mark.parametrize("contact_end", ["delta", "force"])
@pytest.mark.parametrize("quantity", ["e", "xi", "tau_d"])
def test_lam_from_summary_alone_is_the_batch(quantity, contact_end):
    """Targets from the forward map on lambda in (0.01, 100) (xi where it is below 1 - 1e-9:
    above, it rounds to 1 or past it, outside the inverse's domain): 600 in a batch (the Newton
    iteration's every step sums the series for all of them), 100 of them alone."""
    lam = np.random.default_rng(2).uniform(0.01, 100.0, 600)
    if quantity == "tau_d":  # tau_d(lambda) has a minimum: targets on its rising branch
        lam_lo, _, _ = inverse.tau_d_branch(contact_end)
        lam = lam[lam > 1.01 * lam_lo]
    s = zs.summary(lam, contact_end=contact_end)
    target = np.asarray(getattr(s, quantity), dtype=float)
    if quantity == "xi":
        target = target[target < 1.0 - 1e-9]
    batch = zs.lam_from_summary(**{quantity: target}, contact_end=contact_end)
    assert np.all(np.isfinite(batch))
    for j in range(0, len(target), 6):
        one = zs.lam_from_summary(**{quantity: float(target[j])}, contact_end=contact_end)
        assert float(one) == batch[j], (quantity, contact_end, target[j])


@pytest.mark.parametrize("contact_end", ["delta", "force"])
def test_summary_derivative_alone_is_the_batch(contact_end):
    lam = _lams(1000.0, 1500, 3)
    lam = lam[lam > 0.0]  # the force-free end has no derivative at lambda = 0
    for field in table.DERIVATIVE_FIELDS:
        batch = table.summary_derivative(lam, field, contact_end=contact_end)
        for j in range(0, len(lam), 50):
            one = table.summary_derivative(float(lam[j]), field, contact_end=contact_end)
            assert float(one) == batch[j], (contact_end, field, lam[j])


@pytest.mark.parametrize("module", [table, force_table])
def test_one_series_is_the_series_of_every_field(module):
    """``SummaryTable.one`` (the inverses' route) sums the same way as ``values`` and
    ``derivatives`` (the summary's and the derivative's route): the same bits."""
    tab = module._tables().summary
    lam = _lams(1000.0, 1500, 4)
    lam = lam[lam > 0.0]
    v, i, x, _ = tab.values(lam)
    d = tab.derivatives(lam, i, x)
    for field in tab.fields:
        val, der = tab.one(lam, field)
        np.testing.assert_array_equal(val, v[field], err_msg=field)
        np.testing.assert_array_equal(der, d[field], err_msg=field)
