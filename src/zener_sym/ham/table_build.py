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

The table is a configuration of the package's one Chebyshev-table engine
(:mod:`zener_sym.numerics.cheb_table_build`): :func:`spec` describes it (its last piece starts at
lam_cont, found at build time), the node function samples :func:`reference`.

The node values come from floating-point root finding and quadrature, so the text is not meant
to be bit-reproducible across machines: the table is NOT in ``codegen.BUILDERS``;
``zener-sym regen --check ham1-table`` rebuilds it and compares numerically (``CHECK_RTOL``).
"""
from __future__ import annotations

import pathlib

import numpy as np

from ..numerics import cheb_table_build as engine
from ..numerics.cheb_table import TableSpec
from ..numerics.cheb_table_build import NodeData
from ..typing import FloatArray, RealArrayLike

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


def spec(lam_cont: float) -> TableSpec:
    """The table's description for the engine: :func:`pieces`, ``KEYS``, ``N_NODES``, ``TRIM``,
    ``CHECK_RTOL`` and 17 digits.

    Parameters
    ----------
    lam_cont : float
        As for :func:`pieces`.

    Returns
    -------
    TableSpec
        The description, written into the table by :func:`render`.
    """
    return TableSpec(pieces=tuple(pieces(lam_cont)), fields=KEYS, nodes=N_NODES, trim=TRIM,
                     check_rtol=CHECK_RTOL, digits=17)


def piece_nodes(kind: str, a: float, b: float, n: int) -> FloatArray:
    """The lambda nodes of a piece: Chebyshev points in its variable
    (``numerics.cheb_table_build.piece_nodes``).

    Parameters
    ----------
    kind : {'lam', 'sqrt'}
        The piece's variable (``numerics.cheb_table.PIECE_KINDS``).
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
    return engine.piece_nodes(kind, a, b, n)


def description() -> TableSpec:
    """The table's description, its last piece starting at lam_cont found now
    (:func:`continuation_lambda`).

    Returns
    -------
    TableSpec
    """
    return spec(continuation_lambda())


def sample(p: int, lams: FloatArray) -> list[NodeData]:
    """The nodes' data of a lambda piece: the reference, one vectorised call per piece.

    Parameters
    ----------
    p : int
        The lambda piece (unused: the reference holds on every piece).
    lams : ndarray
        Its nodes.

    Returns
    -------
    list of dict
        ``KEYS`` -> value, one per node.
    """
    v = reference(lams)
    return [{k: float(v[k][j]) for k in KEYS} for j in range(len(lams))]


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


def digest() -> str:
    """The table's inputs hash (``codegen.inputs_hash`` of :func:`input_files`)."""
    from ..codegen import inputs_hash

    return inputs_hash(input_files())


def _lam_cont_lines(sp: TableSpec) -> list[str]:
    """The file's lines before its description: lam_cont, the last piece's start."""
    return ["#: lambda where the first-order tau_d equals pi/omega0 (the variable changes there)",
            f"LAM_CONT = {float(sp.pieces[-1][1]):.17g}"]


#: The table: ``BUILDER.build()``, ``.render()``, ``.compare()`` (the engine's methods).
BUILDER = engine.TableBuilder(
    spec=description,
    file=engine.TableFile(
        "ham1_table.py", "ham1-table",
        title=("Chebyshev tables of the first-order HAM summary (Eq. 42) for 0 <= lambda < "
               "lam_crit."),
        provenance=("Built by zener_sym.ham.table_build from the float64 ham1 summary "
                    "(zener_sym.ham.spectral.summary_numpy); `zener-sym regen --check ham1-table` "
                    "rebuilds and compares numerically (the node values come from floating-point "
                    "root finding and quadrature).")),
    sample=sample, digest=digest, head=_lam_cont_lines)

# the builder's methods under the names the table commands and tests call
build_tables, render, compare = BUILDER.build, BUILDER.render, BUILDER.compare
as_tables = BUILDER.as_tables
