"""Lookup tables of the dimensionless summary over a lambda grid, for DEM codes.

A discrete-element code that integrates viscoelastic grains needs e and the contact time for
each collision; with lambda = A (rho/m_eff)^{2/5} v0^{1/5} (``zener_sym.lam_from_dissipation``)
it can interpolate them in a table of e(lambda) and tau_d(lambda) (contact time t_c = T tau_d,
T = (m_eff/rho)^{2/5} v0^{-1/5}). :func:`lookup_table` computes the table, :func:`lookup_csv`
writes it; ``zener-sym table`` is the command line.
"""
from __future__ import annotations

import io
import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ..api import summary
from ..exact.force_end import check_contact_end
from ..models import get_model
from ..typing import FloatArray, RealArrayLike

__all__ = ["parse_lam_grid", "lookup_table", "lookup_csv"]


def parse_lam_grid(spec: str | RealArrayLike) -> FloatArray:
    """A grid of Zener's lambda from ``"start:stop:n"``, ``"x"`` or values.

    Parameters
    ----------
    spec : str or float or array_like
        ``"start:stop:n"`` (n equally spaced values, ends included), one number as a string
        (``"0.5"``), or the values themselves.

    Returns
    -------
    numpy.ndarray
        The grid, 1-d, float.

    Raises
    ------
    ValueError
        For a malformed spec, n < 1, stop < start or a non-finite or negative value.

    Examples
    --------
    >>> from zener_sym.scene.lookup import parse_lam_grid
    >>> parse_lam_grid("0:1:5")
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    >>> parse_lam_grid(0.5)
    array([0.5])
    >>> parse_lam_grid("0:1")
    Traceback (most recent call last):
    ...
    ValueError: lambda grid '0:1' is not understood; allowed: 'start:stop:n' (n >= 1 values from start to stop >= start, ends included) or a single number
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


def lookup_table(quantities: str | Sequence[str] = ("e", "tau_d"),
                 lam: str | RealArrayLike = "0:5:1001", *, contact_end: str = "delta",
                 model: str = "exact", **options: Any) -> dict[str, FloatArray]:
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

    Examples
    --------
    >>> from zener_sym.scene.lookup import lookup_table
    >>> t = lookup_table("e,tau_d", "0:2:3")
    >>> list(t), t["e"].round(4), t["tau_d"].round(4)
    (['lam', 'e', 'tau_d'], array([1.    , 0.1841, 0.0207]), array([3.2181, 4.3876, 8.4832]))
    >>> t = lookup_table("e", [0.5], contact_end="force")    # the grains' end of contact
    >>> round(float(t["e"][0]), 4)
    0.4788
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
    out: dict[str, FloatArray] = {"lam": grid}
    for q in quantities:
        out[q] = np.atleast_1d(np.asarray(getattr(s, q), dtype=float))
    return out


def lookup_csv(table: Mapping[str, RealArrayLike]) -> str:
    """CSV text of a :func:`lookup_table` result: a header of names, then one row per lambda with
    17 significant digits (round-trips a float64).

    Parameters
    ----------
    table : mapping of str to array_like
        Column name -> values, all of one length (a :func:`lookup_table` result).

    Returns
    -------
    str
        The CSV text, one line per row, ending in a newline.

    Examples
    --------
    >>> from zener_sym.scene.lookup import lookup_csv, lookup_table
    >>> print(lookup_csv(lookup_table("e", "0:1:2")), end="")
    lam,e
    0,1
    1,0.18412287416504775
    """
    buf = io.StringIO()
    names = list(table)
    buf.write(",".join(names) + "\n")
    for row in zip(*(np.asarray(table[n], dtype=float) for n in names)):
        buf.write(",".join(f"{x:.17g}" for x in row) + "\n")
    return buf.getvalue()
