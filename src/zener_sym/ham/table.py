"""Fast ham1 summary: Chebyshev tables in lambda of the first-order HAM summary (Eq. 42).

The tables (``generated/ham1_table.py``, built offline by :mod:`zener_sym.ham.table_build` from
the float64 reference :func:`zener_sym.ham.spectral.summary_numpy`) cover ``0 <= lambda <
lam_crit``: two pieces in lambda and, from lam_cont = 2.03045... (where the first-order tau_d
meets pi/omega0), one piece in sqrt(lambda - lam_cont). They are never extrapolated:
:func:`in_range` tells the caller which lambda to compute another way.

Documented error bound: ``SUMMARY_RTOL`` relative on every summary field, against the mpmath
closed forms (``backend="mpmath"``) at lambda between the nodes; tests/test_ham_table.py checks
it on every piece, next to lam_cont and near lam_crit, and docs/ham.md lists the measured error.

Cost: one table row gather and one small matrix product per call; T_k(x) = cos(k arccos x) in
one vectorised step (no recurrence loop in Python), so a scalar costs a few numpy calls.
"""
from __future__ import annotations

import functools
import importlib
from typing import TypedDict

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray, RealArrayLike

__all__ = ["SUMMARY_RTOL", "in_range", "summary", "lam_max", "variable_ends"]

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
    return (a, b) if kind == "lam" else (0.0, float(np.sqrt(b - a)))


class _Tables(TypedDict):
    """The generated table as arrays (see :func:`_tables`)."""

    keys: tuple[str, ...]  # the tabulated fields, in COEF's order
    inner: FloatArray  # starts of the pieces after the first
    start: FloatArray  # start of every piece in lambda
    top: float  # lam_crit, the table's (excluded) upper end
    sqrt: npt.NDArray[np.bool_]  # piece in the variable sqrt(lambda - start)
    ga: FloatArray  # the Chebyshev variable's ends per piece
    gb: FloatArray
    k: FloatArray  # 0, 1, ..., degree - 1
    coef: FloatArray  # [piece, degree, field]


@functools.cache
def _tables() -> _Tables:
    """The generated table (the one source of its pieces and fields), loaded on first use, as
    arrays."""
    t = importlib.import_module("zener_sym.generated.ham1_table")
    keys = tuple(t.COEF)
    kinds = [p[0] for p in t.PIECES]
    starts = np.array([float(p[1]) for p in t.PIECES])
    ends = np.array([float(p[2]) for p in t.PIECES])
    ga, gb = np.array([variable_ends(k, a, b) for k, a, b in t.PIECES]).T
    deg = max(len(c) for v in t.COEF.values() for c in v)
    coef = np.zeros((len(t.PIECES), deg, len(keys)))  # [piece, degree, field]
    for j, key in enumerate(keys):
        for i, c in enumerate(t.COEF[key]):
            coef[i, : len(c), j] = c
    return {"keys": keys, "inner": starts[1:], "start": starts, "top": float(ends[-1]),
            "sqrt": np.array([k == "sqrt" for k in kinds]), "ga": ga, "gb": gb,
            "k": np.arange(deg, dtype=float), "coef": coef}


def lam_max() -> float:
    """Upper end of the table (lam_crit; lambda itself must stay below it).

    Returns
    -------
    float
        lam_crit (Eq. 81), 2.4424389...
    """
    return _tables()["top"]


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
    lam = np.asarray(lam, dtype=float)
    return (lam >= 0.0) & (lam < _tables()["top"])


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
    t = _tables()
    lam = np.asarray(lam, dtype=float)
    flat = lam.reshape(-1)
    if not np.all(in_range(flat)):
        bad = float(flat[~in_range(flat)][0])
        raise ValueError(f"lambda = {bad!r} is outside the ham1 table's range "
                         f"[0, {t['top']!r})")
    i = np.searchsorted(t["inner"], flat, side="right")  # piece index
    g = np.where(t["sqrt"][i], np.sqrt(np.maximum(flat - t["start"][i], 0.0)), flat)
    a, b = t["ga"][i], t["gb"][i]
    x = np.clip((2.0 * g - a - b) / (b - a), -1.0, 1.0)
    # T_k(x) = cos(k arccos x): accurate to a few ulp of k arccos(x), and one numpy call
    T = np.cos(np.arccos(x)[:, None] * t["k"])  # [lambda, degree]
    v = np.matmul(T[:, None, :], t["coef"][i])[:, 0, :]  # [lambda, field], row by row
    d = {key: v[:, j].reshape(lam.shape) for j, key in enumerate(t["keys"])}
    return {"delta_m": d["delta_m"], "tau_dc": d["tau_dc"], "tau_d": np.exp(d["log_tau_d"]),
            "e": np.exp(d["log_e"]), "F_m": d["delta_m"] ** 1.5, "impulse": d["impulse"],
            "int_F2": d["int_F2"]}
