"""Fast ham1 summary: Chebyshev tables in lambda of the first-order HAM summary (Eq. 42).

The tables (``generated/ham1_table.py``, built offline by :mod:`zener_sym.ham.table_build` from
the float64 reference :func:`zener_sym.ham.spectral.summary_numpy`) cover ``0 <= lambda <
lam_crit``: two pieces in lambda and, from lam_cont = 2.03045... (where the first-order tau_d
meets pi/omega0), one piece in sqrt(lambda - lam_cont). They are never extrapolated:
:func:`in_range` tells the caller which lambda to compute another way.

Documented error bound: ``SUMMARY_RTOL`` relative on every summary field, against the mpmath
closed forms (``backend="mpmath"``) at lambda between the nodes; tests/test_ham_table.py checks
it on every piece, next to lam_cont and near lam_crit, and docs/ham.md lists the measured error.

The table is an instance of the package's one Chebyshev-table engine
(:class:`zener_sym.numerics.cheb_table.SummaryTable`): piece lookup, variable, range check and
the series sum are the exact tables' own.
"""
from __future__ import annotations

import functools
import importlib
import warnings

import numpy as np
import numpy.typing as npt

from ..numerics.cheb_table import Pieces, SummaryTable
from ..typing import FloatArray, RealArrayLike

__all__ = ["LAM_MIN", "LAM_MAX", "SUMMARY_RTOL", "in_range", "summary", "variable_ends"]

#: Documented (and tested) relative error bound of every ham1 summary field.
SUMMARY_RTOL = 1e-11


def variable_ends(kind: str, a: float, b: float) -> tuple[float, float]:
    """The Chebyshev variable's ends on the lambda piece [a, b] of kind ``kind``: 'lam' (the
    variable is lambda) or 'sqrt' (sqrt(lambda - a)).

    Parameters
    ----------
    kind : {'lam', 'sqrt'}
        The piece's variable.
    a, b : float
        The piece's ends in lambda, a < b.

    Returns
    -------
    tuple of float
        The variable at lambda = a and at lambda = b.

    Examples
    --------
    >>> from zener_sym.ham.table import variable_ends
    >>> variable_ends("sqrt", 2.0, 2.25)
    (0.0, 0.5)
    """
    p = Pieces([(kind, a, b)])
    return float(p.ga[0]), float(p.gb[0])


@functools.cache
def _tables() -> SummaryTable:
    """The generated table (the one source of its pieces and fields), loaded on first use."""
    t = importlib.import_module("zener_sym.generated.ham1_table")
    return SummaryTable.of(t, "ham1 table", top_open=True)


def __getattr__(name: str) -> float:
    """LAM_MIN and LAM_MAX, the table's range 0 <= lambda < LAM_MAX = lam_crit (Eq. 81,
    2.4424389...; lambda itself must stay below it), read from the generated table on first
    use, as the exact tables' ranges are."""
    if name == "LAM_MIN":
        return _tables().lo
    if name == "LAM_MAX":
        return _tables().hi
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def lam_max() -> float:
    """Upper end of the table: deprecated, use ``LAM_MAX`` (the exact tables' name).

    Returns
    -------
    float
        lam_crit (Eq. 81), 2.4424389...
    """
    warnings.warn("zener_sym.ham.table.lam_max() is deprecated; use zener_sym.ham.table.LAM_MAX "
                  "(the range's name in every table module)", DeprecationWarning, stacklevel=2)
    return _tables().hi


def in_range(lam: RealArrayLike) -> npt.NDArray[np.bool_]:
    """Boolean mask: lambda inside the table's range 0 <= lambda < lam_crit.

    Parameters
    ----------
    lam : float or array_like
        lambda values (any, NaN included: NaN is out of range).

    Returns
    -------
    ndarray of bool
        Of the shape of ``lam``.

    Examples
    --------
    >>> from zener_sym.ham.table import in_range
    >>> in_range([0.0, 1.0, 2.5, -0.1]).tolist()
    [True, True, False, False]
    """
    return _tables().in_range(lam)


def summary(lam: RealArrayLike) -> dict[str, FloatArray]:
    """The ham1 summary (Eq. 42) at ``lam`` from the Chebyshev tables.

    Parameters
    ----------
    lam : float or array_like
        lambda values, each in the table's range 0 <= lambda < lam_crit (:func:`in_range`).

    Returns
    -------
    dict of str to ndarray
        delta_m, tau_dc, tau_d, e, F_m, impulse, int_F2, arrays of the shape of ``lam`` (the
        model derives tau_dr, eta and xi), within ``SUMMARY_RTOL`` of the closed forms.

    Raises
    ------
    ValueError
        A lambda outside the table's range.

    Examples
    --------
    >>> from zener_sym.ham.spectral import summary_numpy
    >>> from zener_sym.ham.table import SUMMARY_RTOL, summary
    >>> s, ref = summary(1.0), summary_numpy(1.0)  # the table, the series it was built from
    >>> all(abs(s[f] - ref[f]) <= SUMMARY_RTOL * abs(ref[f]) for f in s)
    True
    """
    lam_a: FloatArray = np.asarray(lam, dtype=float)
    v, _, _, _ = _tables().values(lam_a.reshape(-1))
    d = {key: c.reshape(lam_a.shape) for key, c in v.items()}
    return {"delta_m": d["delta_m"], "tau_dc": d["tau_dc"], "tau_d": np.exp(d["log_tau_d"]),
            "e": np.exp(d["log_e"]), "F_m": d["delta_m"] ** 1.5, "impulse": d["impulse"],
            "int_F2": d["int_F2"]}
