"""Offline builder of the Chebyshev tables behind the ham1 summary (``generated/ham1_table.py``).

The first-order HAM summary (Eq. 42: delta_m, tau_dc, tau_d, e, impulse, int_F2; the other
fields follow from these) is sampled from its float64 reference, :func:`zener_sym.ham.spectral.
summary_numpy` (the per-lambda series, and the quadrature kernels from lambda = 2.414 on; both
agree with the mpmath closed forms to ~1e-13), at Chebyshev points of the first kind on each
lambda piece, and stored as Chebyshev coefficients (17 significant digits), trimmed where the
trailing ones fall below ``TRIM`` of the largest. :mod:`zener_sym.ham.table` evaluates them.

The pieces follow the singularities of the summary in lambda:

``[0, 1]``, ``[1, lam_cont]`` in lambda
    On both the first-order contact ends past pi/omega0, on the continuation of Eq. (42) with
    K frozen at pi (see :mod:`zener_sym.models.ham`), where delta is analytic in tau: every field
    is analytic in lambda.
``[lam_cont, lam_crit]`` in the variable s = sqrt(lambda - lam_cont)
    At lam_cont = 2.0304532806... the end of contact tau_d meets pi/omega0. Just above it,
    tau_d < pi/omega0, where delta has a (pi/omega0 - tau)^{3/2} term (the square-root
    integrals K of Eq. 36 end there), so tau_d and e carry a (lambda - lam_cont)^{3/2} term:
    Chebyshev series in lambda converge only algebraically, in s they converge geometrically.
    lam_cont is found at build time by root finding on tau_d - pi/omega0 and stored in the
    table. Up to lam_crit = 2.44243892998... (omega0 -> 0, Eq. 81) nothing else is singular:
    tau_d stays near 11 there (the first-order contact ends well before pi/omega0), so the
    piece reaches lam_crit itself (its nodes never touch it).

tau_d and e are tabulated as their logarithms (relative accuracy: e falls to 1.4e-3).

The node values come from floating-point root finding and quadrature, so the text is not meant
to be bit-reproducible across machines: the table is NOT in ``codegen.BUILDERS``;
``zener-sym ham1-table --check`` rebuilds it and compares numerically (``CHECK_RTOL``).
"""
from __future__ import annotations

import pathlib
from collections.abc import Mapping
from typing import Any, TypedDict

import numpy as np

from ..codegen import inputs_hash
from ..codegen.tables import float_tuple, table_module
from ..numerics.chebyshev import (cheb_coefficients, cheb_nodes, coefficient_difference,
                                  trim_trailing)
from ..typing import FloatArray, RealArrayLike
from .table import variable_ends

#: Chebyshev points per lambda piece (first the two pieces in lambda, then the one in s).
N_NODES = (28, 28, 36)
#: The two pieces in lambda end here, the piece in s = sqrt(lambda - lam_cont) starts at lam_cont.
LAM_SPLIT = 1.0
#: Bracket of lam_cont, where the first-order tau_d equals pi/omega0.
CONT_BRACKET = (2.0, 2.1)
#: Trailing coefficients below this fraction of an array's largest are dropped (noise level).
TRIM = 1e-15
#: ``--check`` passes when every rebuilt coefficient is within this of the stored one (relative
#: to the largest coefficient of its array), and lam_cont within this relative.
CHECK_RTOL = 1e-12

#: The tabulated functions of lambda; tau_d = exp(log_tau_d), e = exp(log_e).
KEYS = ("delta_m", "tau_dc", "log_tau_d", "log_e", "impulse", "int_F2")
#: Kinds of Chebyshev variable: lambda itself, or sqrt(lambda - start of the piece).
KINDS = ("lam", "sqrt")


class Tables(TypedDict):
    """A built table, as :func:`build_tables` gives it and :func:`render` prints it."""

    lam_cont: float
    pieces: list[tuple[str, float, float]]
    coef: dict[str, list[FloatArray]]


def lam_crit() -> float:
    """lam_crit (Eq. 81), the top of the last piece.

    Returns
    -------
    float
        ``LAM_CRIT`` of the generated HAM formulas.
    """
    from .runtime_numpy import ham1 as ham1_numpy

    return float(ham1_numpy.LAM_CRIT)


def reference(lam: RealArrayLike) -> dict[str, FloatArray]:
    """The float64 reference the table samples: the six tabulated functions at ``lam``.

    Parameters
    ----------
    lam : float or array_like
        lambda values, 0 <= lambda < lam_crit.

    Returns
    -------
    dict of str to ndarray
        ``KEYS`` -> 1-D arrays (``lam`` flattened, at least one element).
    """
    from .spectral import summary_numpy

    v = summary_numpy(np.atleast_1d(np.asarray(lam, dtype=float)))
    return {"delta_m": v["delta_m"], "tau_dc": v["tau_dc"], "log_tau_d": np.log(v["tau_d"]),
            "log_e": np.log(v["e"]), "impulse": v["impulse"], "int_F2": v["int_F2"]}


def continuation_lambda() -> float:
    """lam_cont: the lambda where the first-order end of contact tau_d equals pi/omega0
    (below it tau_d > pi/omega0). Brent's method on the reference, to full precision.

    Returns
    -------
    float
        lam_cont, 2.0304532806...
    """
    from scipy.optimize import brentq

    from .runtime_numpy import ham1 as ham1_numpy

    def g(x: float) -> float:
        return float(np.exp(reference(x)["log_tau_d"][0])) - float(np.pi / ham1_numpy.params(x)[2])

    return float(brentq(g, *CONT_BRACKET, xtol=1e-16, rtol=8.9e-16, maxiter=200))


def pieces(lam_cont: float) -> list[tuple[str, float, float]]:
    """(kind, start, end) of every lambda piece.

    Parameters
    ----------
    lam_cont : float
        Start of the piece in sqrt(lambda - lam_cont) (:func:`continuation_lambda`).

    Returns
    -------
    list of (str, float, float)
        ('lam', 0, LAM_SPLIT), ('lam', LAM_SPLIT, lam_cont), ('sqrt', lam_cont, lam_crit).
    """
    return [("lam", 0.0, LAM_SPLIT), ("lam", LAM_SPLIT, lam_cont), ("sqrt", lam_cont, lam_crit())]


def piece_nodes(kind: str, a: float, b: float, n: int) -> FloatArray:
    """The lambda nodes of a piece: Chebyshev points in its variable.

    Parameters
    ----------
    kind : {'lam', 'sqrt'}
        The piece's variable (:func:`zener_sym.ham.table.variable_ends`).
    a, b : float
        The piece's ends in lambda.
    n : int
        Number of Chebyshev points of the first kind.

    Returns
    -------
    ndarray
        The n lambda values, inside (a, b).

    Examples
    --------
    >>> import numpy as np
    >>> from zener_sym.ham.table_build import piece_nodes
    >>> lam = piece_nodes("sqrt", 2.0, 2.25, 5)  # Chebyshev points in s = sqrt(lambda - 2)
    >>> s = np.sqrt(lam - 2.0)
    >>> bool(np.allclose(np.sort(s), 0.25 + 0.25 * np.cos((2 * np.arange(5)[::-1] + 1) * np.pi / 10)))
    True
    """
    ga, gb = variable_ends(kind, a, b)
    g = ga + (gb - ga) * (cheb_nodes(n) + 1.0) / 2.0
    return g if kind == "lam" else a + g * g


def build_tables() -> Tables:
    """Sample the reference on every piece and fit its Chebyshev coefficients (slow: minutes).

    Returns
    -------
    Tables
        {"lam_cont": float, "pieces": [(kind, a, b)], "coef": {key: [1-D per piece]}}.

    Raises
    ------
    RuntimeError
        The reference gave a non-finite value at a node.
    """
    lam_cont = continuation_lambda()
    ps = pieces(lam_cont)
    coef: dict[str, list[FloatArray]] = {k: [] for k in KEYS}
    for (kind, a, b), n in zip(ps, N_NODES):
        v = reference(piece_nodes(kind, a, b, n))
        for k in KEYS:
            if not np.all(np.isfinite(v[k])):
                raise RuntimeError(f"ham1 reference gave a non-finite {k} on the piece [{a}, {b}]")
            c = cheb_coefficients(v[k])
            coef[k].append(trim_trailing(c, np.abs(c) > TRIM * np.abs(c).max()))
    return {"lam_cont": lam_cont, "pieces": ps, "coef": coef}


def input_files() -> list[pathlib.Path]:
    """The sources the table is built from (its inputs hash): this builder, the reference it
    samples (``spectral``, the numpy kernels' runtime, the numerical primitives of
    ``zener_sym.numerics``) and the generated HAM formulas it calls.

    Returns
    -------
    list of pathlib.Path
        In the order they are hashed.
    """
    from ..codegen import generated_dir

    here = pathlib.Path(__file__).resolve().parent
    files = [here / n for n in ("table_build.py", "spectral.py", "runtime_numpy.py")]
    files += sorted((here.parent / "numerics").glob("*.py"))
    files += [generated_dir() / n for n in ("ham0.py", "ham1.py")]
    return files


def render(tables: Tables | None = None) -> str:
    """Text of ``generated/ham1_table.py``.

    Parameters
    ----------
    tables : Tables, optional
        A built table; default: :func:`build_tables` now.

    Returns
    -------
    str
        The module text, with its do-not-edit header and inputs hash.
    """
    t = build_tables() if tables is None else tables
    lines = [
        "#: lambda where the first-order tau_d equals pi/omega0 (the variable changes there)",
        f"LAM_CONT = {float(t['lam_cont']):.17g}",
        "#: (kind, start, end) per lambda piece; kind 'lam': Chebyshev variable lambda,",
        "#: 'sqrt': sqrt(lambda - start)",
        "PIECES = (",
    ]
    for kind, a, b in t["pieces"]:
        lines.append(f"    ({kind!r}, {float(a):.17g}, {float(b):.17g}),")
    lines += [")", "", "#: field -> one tuple of Chebyshev coefficients per lambda piece", "COEF = {"]
    for k in KEYS:
        lines.append(f"    {k!r}: (")
        for c in t["coef"][k]:
            lines.append("        " + float_tuple(c, 17) + ",")
        lines.append("    ),")
    lines += ["}"]
    title = "Chebyshev tables of the first-order HAM summary (Eq. 42) for 0 <= lambda < lam_crit."
    provenance = ("Built by zener_sym.ham.table_build from the float64 ham1 summary "
                  "(zener_sym.ham.spectral.summary_numpy); `zener-sym ham1-table --check` "
                  "rebuilds and compares numerically (the node values come from floating-point "
                  "root finding and quadrature).")
    return table_module(title, "ham1-table", provenance, inputs_hash(input_files()), lines)


def table_path() -> pathlib.Path:
    """Where the table module lives: ``generated/ham1_table.py``.

    Returns
    -------
    pathlib.Path
        The file in :func:`zener_sym.codegen.generated_dir`.
    """
    from ..codegen import generated_dir

    return generated_dir() / "ham1_table.py"


def compare(stored: Mapping[str, Any], fresh: Tables) -> list[str]:
    """Differences beyond CHECK_RTOL between two tables, as readable lines (empty: they agree).

    Parameters
    ----------
    stored : mapping
        The generated module's names: LAM_CONT, PIECES, COEF.
    fresh : Tables
        A table just built (:func:`build_tables`).

    Returns
    -------
    list of str
        One line per difference; empty when they agree.
    """
    bad = []
    if abs(stored["LAM_CONT"] - fresh["lam_cont"]) > CHECK_RTOL * fresh["lam_cont"]:
        bad.append(f"lam_cont {stored['LAM_CONT']!r} != rebuilt {fresh['lam_cont']!r}")
    if [p[0] for p in stored["PIECES"]] != [p[0] for p in fresh["pieces"]] or len(
            stored["PIECES"]) != len(fresh["pieces"]):
        bad.append(f"pieces {stored['PIECES']!r} != rebuilt {fresh['pieces']!r}")
        return bad
    for key in fresh["coef"]:
        if key not in stored["COEF"]:
            bad.append(f"field {key} missing from the stored table")
            continue
        for i, (c_new, c_old) in enumerate(zip(fresh["coef"][key], stored["COEF"][key])):
            err = coefficient_difference(c_new, c_old)
            if not err <= CHECK_RTOL:
                bad.append(f"{key} lambda piece {i}: relative difference {err:.2e} > {CHECK_RTOL:g}")
    return bad
