"""Lookup tables of the dimensionless summary over a lambda grid, for DEM codes.

A discrete-element code that integrates viscoelastic grains needs e and the contact time for
each collision; with lambda = A (rho/m_eff)^{2/5} v0^{1/5} (``zener_sym.viscoelastic_lambda``)
it can interpolate them in a table of e(lambda) and tau_d(lambda) (contact time t_c = T tau_d,
T = (m_eff/rho)^{2/5} v0^{-1/5}). :func:`lookup_table` computes the table, :func:`lookup_csv`
writes it; ``zener-sym table`` is the command line.
"""
from __future__ import annotations

import io
import math

import numpy as np

from ..api import summary
from ..exact.force_end import check_contact_end
from ..models import get_model

__all__ = ["parse_lam_grid", "lookup_table", "lookup_csv"]


def parse_lam_grid(spec) -> np.ndarray:
    """``"start:stop:n"`` (n equally spaced values, ends included), ``"x"``, or an array.

    Raises
    ------
    ValueError
        For a malformed spec, n < 1, stop < start or a non-finite or negative value.
    """
    if isinstance(spec, str):
        parts = spec.split(":")
        try:
            if len(parts) == 1:
                grid = np.array([float(parts[0])])
            elif len(parts) == 3:
                a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
                if n < 1:
                    raise ValueError
                if not (math.isfinite(a) and math.isfinite(b)) or b < a:
                    raise ValueError
                grid = np.linspace(a, b, n)
            else:
                raise ValueError
        except ValueError:
            raise ValueError(f"lambda grid {spec!r} is not understood; allowed: 'start:stop:n' "
                             f"(n >= 1 values from start to stop >= start, ends included) or a "
                             f"single number") from None
    else:
        grid = np.asarray(spec, dtype=float).ravel()
    if grid.size == 0 or not np.all(np.isfinite(grid)) or np.any(grid < 0):
        raise ValueError(f"lambda grid must be finite and >= 0, got {spec!r}")
    return grid


def lookup_table(quantities=("e", "tau_d"), lam="0:5:1001", *, contact_end="delta",
                 model="exact", **options) -> dict:
    """The summary quantities of ``model`` on a lambda grid.

    Parameters
    ----------
    quantities : sequence of str or str
        Summary fields (e.g. ``"e,tau_d"`` or ``("e", "tau_d", "F_m")``).
    lam : str or array_like
        The grid: ``"start:stop:n"`` or values (see :func:`parse_lam_grid`).
    contact_end : {"delta", "force"}
        End of contact: the plate's delta = 0, or the grains' force-free end.
    model : str
        A registered model taking ``contact_end`` (``"exact"`` default, ``"series"``).
    **options
        Other model options.

    Returns
    -------
    dict
        ``lam`` and each quantity as float arrays, in the order asked.

    Raises
    ------
    ValueError
        For an unknown quantity (the allowed ones are listed), a bad grid or criterion, or a
        lambda the model does not accept (its range is stated).
    """
    contact_end = check_contact_end(contact_end)
    if isinstance(quantities, str):
        quantities = [q.strip() for q in quantities.split(",") if q.strip()]
    quantities = [q for q in quantities if q != "lam"]
    m = get_model(model)
    unknown = [q for q in quantities if q not in m.summary_fields]
    if unknown or not quantities:
        raise ValueError(f"unknown quantity {unknown[0] if unknown else ''!r} for model {model!r}; "
                         f"allowed: {', '.join(f for f in m.summary_fields if f != 'lam')}")
    grid = parse_lam_grid(lam)
    if contact_end != "delta" or "contact_end" in m.options:
        options["contact_end"] = contact_end
    s = summary(grid, model=model, **options)
    out = {"lam": grid}
    for q in quantities:
        out[q] = np.atleast_1d(np.asarray(getattr(s, q), dtype=float))
    return out


def lookup_csv(table: dict) -> str:
    """CSV text of a :func:`lookup_table` result: a header of names, then one row per lambda with
    17 significant digits (round-trips a float64)."""
    buf = io.StringIO()
    names = list(table)
    buf.write(",".join(names) + "\n")
    for row in zip(*(table[n] for n in names)):
        buf.write(",".join(f"{x:.17g}" for x in row) + "\n")
    return buf.getvalue()
