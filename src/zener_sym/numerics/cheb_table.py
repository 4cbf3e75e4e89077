"""The one Chebyshev-table engine at run time: a table's description as data, and the evaluator
every table of the package is an instance of.

A table is piecewise in lambda. Its description (:class:`TableSpec`) is data written into the
generated table module: the pieces ``(kind, start, end)``, the stored fields, the degrees (points
per piece), the trimming level and the ``--check`` tolerance. The kind of a piece names its
Chebyshev variable g (:data:`PIECE_KINDS`): lambda, ln lambda, sqrt(lambda) or
sqrt(lambda - start). The plate's end of contact (``exact.table``), the force-free end
(``exact.force_table``) and the ham1 summary (``ham.table``) are instances: each loads its
generated module into a :class:`SummaryTable` (and, for the exact tables, a
:class:`~.cheb_table_history.History`, the engine's history part) and keeps only what is its own
(the derived fields, the time maps of its history). The offline side is :mod:`.cheb_table_build`.

Arithmetic is in a fixed order (the series summed term by term, the lambda contraction one
matrix product per piece), so each lambda's value does not depend on how many others are
evaluated with it.
"""
from __future__ import annotations

import dataclasses
from collections.abc import Mapping, Sequence
from typing import Any, TypeVar

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray, RealArrayLike
# the history's part of the engine, named here too (their public import path)
from .cheb_table_history import (HistoryPiece, Index, history_rows, history_tables,
                                 line_coefficients, parse_array)

__all__ = ["PIECE_KINDS", "TableSpec", "Pieces", "SummaryTable", "parse_array", "history_rows",
           "history_tables", "line_coefficients", "HistoryPiece", "spec_assignments", "spec_of",
           "WrittenConstants", "derivative_input"]

#: The Chebyshev variable g of a lambda piece [start, end], by kind.
PIECE_KINDS = {"lam": "lambda", "log": "ln lambda", "sqrt_lam": "sqrt(lambda)",
               "sqrt": "sqrt(lambda - start)"}

_W = TypeVar("_W", bound="WrittenConstants")


class WrittenConstants:
    """A frozen dataclass of constants written into a generated module as ``NAME = value``
    lines (field names are the module's names) and read back from it: a table's own layout
    beside its :class:`TableSpec` (the exact tables' time pieces and maps)."""

    @classmethod
    def of(cls: type[_W], module: Any) -> _W:
        """The constants written into a generated module (its upper-case names).

        Parameters
        ----------
        module : module
            The generated table module.

        Returns
        -------
        WrittenConstants
            An instance of the dataclass ``of`` is called on.
        """
        fields = dataclasses.fields(cls)  # type: ignore[arg-type]
        return cls(**{f.name: getattr(module, f.name) for f in fields})

    def assignments(self) -> list[str]:
        """``NAME = value`` lines of a generated module, in field order (read back by ``of``).

        Returns
        -------
        list of str
            One line per field.
        """
        return [f"{f.name} = {getattr(self, f.name)!r}"
                for f in dataclasses.fields(self)]  # type: ignore[arg-type]


@dataclasses.dataclass(frozen=True)
class TableSpec:
    """The description of a piecewise Chebyshev table in lambda (data, written into the
    generated module by :func:`spec_assignments`).

    Attributes
    ----------
    pieces : tuple of (str, float, float)
        ``(kind, start, end)`` per lambda piece, contiguous, kinds from :data:`PIECE_KINDS`.
    fields : tuple of str
        The stored series, in order.
    nodes : tuple of int
        Chebyshev points of the first kind per piece (the series' degree + 1 before trimming).
    trim : float
        Trailing coefficients below this fraction of a series' largest are dropped.
    check_rtol : float
        ``--check`` tolerance: a rebuilt coefficient may differ by this relative to its
        series' largest.
    digits : int
        Significant digits of each stored summary coefficient.
    """

    pieces: tuple[tuple[str, float, float], ...]
    fields: tuple[str, ...]
    nodes: tuple[int, ...]
    trim: float
    check_rtol: float
    digits: int = 15

    def __post_init__(self) -> None:
        if not self.pieces:
            raise ValueError("a table needs at least one lambda piece")
        for kind, a, b in self.pieces:
            if kind not in PIECE_KINDS:
                raise ValueError(f"unknown piece kind {kind!r}; allowed: {', '.join(PIECE_KINDS)}")
            if not float(a) < float(b):
                raise ValueError(f"piece ({kind!r}, {a!r}, {b!r}): its start must lie below its "
                                 "end")
        for (_, _, b), (_, a, _) in zip(self.pieces[:-1], self.pieces[1:]):
            if float(a) != float(b):
                raise ValueError(f"pieces must be contiguous: one ends at {b!r}, the next starts "
                                 f"at {a!r}")
        if len(self.nodes) != len(self.pieces):
            raise ValueError(f"{len(self.nodes)} node counts for {len(self.pieces)} pieces")

    @classmethod
    def on_edges(cls, edges: Sequence[float], below: str, log_from: float, fields: Sequence[str],
                 nodes: int, **kw: Any) -> "TableSpec":
        """A table on the pieces between consecutive ``edges``: in ln lambda from ``log_from`` up,
        of kind ``below`` under it, each with ``nodes`` points.

        Parameters
        ----------
        edges : sequence of float
            The breakpoints, increasing.
        below : str
            The kind of the pieces that start under ``log_from``.
        log_from : float
            Pieces that start here or above are ln-lambda pieces.
        fields : sequence of str
            The stored series.
        nodes : int
            Points per piece.
        **kw
            The other attributes (``trim``, ``check_rtol``, ``digits``).

        Returns
        -------
        TableSpec
        """
        pieces = tuple(("log" if a >= log_from else below, a, b)
                       for a, b in zip(edges[:-1], edges[1:]))
        return cls(pieces=pieces, fields=tuple(fields), nodes=(nodes,) * len(pieces), **kw)

    @property
    def edges(self) -> tuple[float, ...]:
        """The breakpoints: every piece's start and the last piece's end."""
        return (*(float(a) for _, a, _ in self.pieces), float(self.pieces[-1][2]))

    @property
    def log_from(self) -> float:
        """Where the ln-lambda pieces start (infinite without one): the exact tables' switch
        to their large-lambda form."""
        return min((float(a) for k, a, _ in self.pieces if k == "log"), default=float("inf"))

    def kind_of(self, start: float) -> str:
        """The kind of Chebyshev variable of the piece that starts at ``start``.

        Parameters
        ----------
        start : float
            A piece's lower end (one of :attr:`edges` but the last).

        Returns
        -------
        str
            One of :data:`PIECE_KINDS`.

        Raises
        ------
        ValueError
            When no piece starts there.
        """
        for kind, a, _ in self.pieces:
            if float(a) == float(start):
                return kind
        raise ValueError(f"no piece starts at {start!r}; the pieces start at "
                         f"{', '.join(repr(float(a)) for _, a, _ in self.pieces)}")


def spec_assignments(spec: TableSpec) -> list[str]:
    """The ``TABLE_*`` lines of a generated module that hold ``spec`` (read back by
    :meth:`SummaryTable.of`'s caller through ``TableSpec(**...)``).

    Parameters
    ----------
    spec : TableSpec
        The description.

    Returns
    -------
    list of str
        Comment and assignment lines.
    """
    pieces = [f"    ({k!r}, {float(a)!r}, {float(b)!r})," for k, a, b in spec.pieces]
    return ["#: the table's description (zener_sym.numerics.cheb_table.TableSpec): per lambda",
            "#: piece (kind of Chebyshev variable, start, end), the stored fields, points per",
            "#: piece, trimming level, --check tolerance, digits",
            "TABLE_PIECES = (", *pieces, ")", f"TABLE_FIELDS = {tuple(spec.fields)!r}",
            f"TABLE_NODES = {tuple(spec.nodes)!r}", f"TABLE_TRIM = {spec.trim!r}",
            f"TABLE_CHECK_RTOL = {spec.check_rtol!r}", f"TABLE_DIGITS = {spec.digits!r}"]


def spec_of(module: Any) -> TableSpec:
    """The :class:`TableSpec` a generated module holds (its ``TABLE_*`` names).

    Parameters
    ----------
    module : module or mapping
        A generated table module, or its globals.

    Returns
    -------
    TableSpec
    """
    ns = module if isinstance(module, Mapping) else vars(module)
    return TableSpec(pieces=tuple((str(k), float(a), float(b)) for k, a, b in ns["TABLE_PIECES"]),
                     fields=tuple(ns["TABLE_FIELDS"]), nodes=tuple(ns["TABLE_NODES"]),
                     trim=float(ns["TABLE_TRIM"]), check_rtol=float(ns["TABLE_CHECK_RTOL"]),
                     digits=int(ns["TABLE_DIGITS"]))


class Pieces:
    """The lambda pieces of a table: lookup, the Chebyshev variable and its slope.

    Parameters
    ----------
    pieces : sequence of (str, float, float)
        ``TableSpec.pieces``.
    """

    def __init__(self, pieces: Sequence[tuple[str, float, float]]) -> None:
        kinds = [k for k, _, _ in pieces]
        self.edges = np.array([float(a) for _, a, _ in pieces] + [float(pieces[-1][2])])
        self.start = self.edges[:-1]
        self.kind = {k: np.array([x == k for x in kinds]) for k in PIECE_KINDS if k in kinds}
        every = np.arange(len(kinds))
        self.ga = self.variable(self.edges[:-1], every)
        self.gb = self.variable(self.edges[1:], every)

    def variable(self, lam: FloatArray, i: Index) -> FloatArray:
        """The Chebyshev variable g of piece ``i`` at each lambda (elementwise)."""
        g = lam
        with np.errstate(divide="ignore", invalid="ignore"):
            if "log" in self.kind:
                m = self.kind["log"][i]
                g = np.where(m, np.log(np.where(m, lam, 1.0)), g)
            if "sqrt_lam" in self.kind:
                g = np.where(self.kind["sqrt_lam"][i], np.sqrt(lam), g)
            if "sqrt" in self.kind:
                g = np.where(self.kind["sqrt"][i], np.sqrt(np.maximum(lam - self.start[i], 0.0)),
                             g)
        return np.asarray(g, dtype=float)

    def locate(self, lam: FloatArray, last: int | None = None) -> tuple[Index, FloatArray]:
        """Piece index (at most ``last``, default the last piece) and the local x in [-1, 1]."""
        top = len(self.start) - 1 if last is None else last
        i = np.clip(np.searchsorted(self.edges, lam, side="right") - 1, 0, top)
        g = self.variable(lam, i)
        a, b = self.ga[i], self.gb[i]
        return i, np.clip((2.0 * g - a - b) / (b - a), -1.0, 1.0)

    def dx_dlam(self, lam: FloatArray, i: Index) -> FloatArray:
        """dx/dlambda of each lambda's piece variable (infinite where g has a square-root
        branch point: sqrt pieces at their origin)."""
        width = self.gb[i] - self.ga[i]
        scale = 2.0 / width
        with np.errstate(divide="ignore", invalid="ignore"):
            if "log" in self.kind:
                scale = np.where(self.kind["log"][i],
                                 2.0 / (width * np.where(lam > 0, lam, 1.0)), scale)
            if "sqrt_lam" in self.kind:
                scale = np.where(self.kind["sqrt_lam"][i], 1.0 / (width * np.sqrt(lam)), scale)
            if "sqrt" in self.kind:
                scale = np.where(self.kind["sqrt"][i],
                                 1.0 / (width * np.sqrt(lam - self.start[i])), scale)
        return np.asarray(scale, dtype=float)


#: Lambdas per block of ``_series_sum``: its two [lambda, field] buffers (a degree's gathered
#: coefficients and the running sums, 64 kB each for 8 fields) stay in cache, whatever the number
#: of lambdas.
_SUM_BLOCK = 1024
#: Up to this many lambdas, ``_series_sum`` gathers every degree's coefficients in one call (at
#: most [degree, 256, field]): for few lambdas the per-degree calls cost more than the sums.
_GATHER_ALL = 256


def _series_sum(tl: FloatArray, coef: FloatArray, i: Index) -> FloatArray:
    """sum_k tl[:, k] coef[k, i, :], the series summed term after term, in place.

    The one ordered sum of every table (values, derivatives, one series): the products
    T_k(x) c_k added left to right from degree 0, the order of the C kernels' ``zs__eval``, so
    a lambda's value does not depend on the others evaluated with it, and C and Python give the
    same doubles.

    Parameters
    ----------
    tl : ndarray
        T_k(x) per lambda, [lambda, degree].
    coef : ndarray
        The coefficients, degree-major [degree, piece, field]: a degree's gather is one
        contiguous [piece, field] row, so a block of lambdas needs no copy of every degree.
    i : ndarray of int
        Each lambda's piece.

    Returns
    -------
    ndarray
        [lambda, field].
    """
    n = min(tl.shape[1], coef.shape[0])
    out = np.empty((len(i), coef.shape[2]))
    buf = np.empty((min(len(i), _SUM_BLOCK), coef.shape[2]))
    for s in range(0, len(i), _SUM_BLOCK):
        ib, tb, ob = i[s:s + _SUM_BLOCK], tl[s:s + _SUM_BLOCK], out[s:s + _SUM_BLOCK]
        bb = buf[:len(ib)]
        rows = coef[:n].take(ib, axis=1) if len(ib) <= _GATHER_ALL else None
        for k in range(n):
            ck = rows[k] if rows is not None else coef[k].take(ib, axis=0, out=bb)
            if k == 0:
                np.multiply(tb[:, :1], ck, out=ob)
            else:
                np.multiply(tb[:, k:k + 1], ck, out=bb)
                ob += bb
    return out


def _one_series_sum(tl: FloatArray, coef: FloatArray, i: Index) -> FloatArray:
    """``_series_sum`` of one series: the same products added in the same order (degree 0 first,
    then left to right, so the same bits), but gathered for every degree at once, [degree,
    lambda], and added by ``np.add.accumulate`` along the degrees (strictly in order): one
    field's per-degree gathers cost more than its sums (``lam_from_summary`` calls this in its
    root finding).

    Parameters
    ----------
    tl : ndarray
        T_k(x) per lambda, [lambda, degree].
    coef : ndarray
        The series' coefficients, [degree, piece].
    i : ndarray of int
        Each lambda's piece.

    Returns
    -------
    ndarray
        [lambda].
    """
    n = min(tl.shape[1], coef.shape[0])
    prods = coef[:n].take(i, axis=1)
    prods *= tl[:, :n].T
    out: FloatArray = np.add.accumulate(prods, axis=0, out=prods)[-1].copy()
    return out


def _basis(x: FloatArray, n: int) -> FloatArray:
    """T_0..T_{n-1} at x, [point, degree], by the three-term recurrence T_k = 2 x T_{k-1} -
    T_{k-2} (numpy's ``chebvander``; for a few points the same operations on Python floats,
    which cost less than numpy's per-degree calls)."""
    if len(x) > 4 or n < 2:
        return np.asarray(np.polynomial.chebyshev.chebvander(x, max(n - 1, 0)), dtype=float)
    out = np.empty((len(x), n))
    for j, xj in enumerate(x.tolist()):
        x2, t0, t1 = 2.0 * xj, 1.0, xj
        row = [t0, t1]
        for _ in range(2, n):
            t0, t1 = t1, t1 * x2 - t0
            row.append(t1)
        out[j] = row
    return out


class SummaryTable:
    """The summary series of a table: per lambda piece one Chebyshev series per field.

    Parameters
    ----------
    pieces : sequence of (str, float, float)
        The lambda pieces (``TableSpec.pieces``).
    fields : sequence of str
        The stored series' names.
    series : mapping
        field -> one sequence of Chebyshev coefficients per piece (lengths may differ).
    what : str
        The table's name in messages ("exact table", ...).
    hint : str
        Appended to the out-of-range message (what to do instead).
    top_open : bool
        The range excludes its upper end (the ham1 table ends at a singularity).
    """

    def __init__(self, pieces: Sequence[tuple[str, float, float]], fields: Sequence[str],
                 series: Mapping[str, Sequence[Sequence[float]]], what: str, hint: str = "",
                 top_open: bool = False) -> None:
        self.pieces = Pieces(pieces)
        self.fields = tuple(fields)
        n = len(pieces)
        deg = max(len(series[k][p]) for k in self.fields for p in range(n))
        c = np.zeros((deg, n, len(self.fields)))  # [degree, piece, field], zero-padded
        for f, k in enumerate(self.fields):
            for p in range(n):
                c[: len(series[k][p]), p, f] = series[k][p]
        self.coef = c
        # d/dx term by term (chebder: exact on the stored coefficients but for its recurrence)
        self.dcoef = (np.zeros_like(c) if deg <= 1 else
                      np.ascontiguousarray(np.polynomial.chebyshev.chebder(c, axis=0),
                                           dtype=float))
        self.what, self.hint, self.top_open = what, hint, top_open
        self.lo, self.hi = float(self.pieces.edges[0]), float(self.pieces.edges[-1])

    @classmethod
    def of(cls, module: Any, what: str, hint: str = "", top_open: bool = False) -> "SummaryTable":
        """The summary of a generated table module, with the description written into it.

        Parameters
        ----------
        module : module or mapping
            The generated table module (``TABLE_*`` and the series, ``SUMMARY``), or its
            globals.
        what, hint, top_open
            As for the constructor.

        Returns
        -------
        SummaryTable
        """
        spec = spec_of(module)
        ns = module if isinstance(module, Mapping) else vars(module)
        return cls(spec.pieces, spec.fields, ns["SUMMARY"], what, hint, top_open)

    def in_range(self, lam: RealArrayLike, hi: float | None = None) -> npt.NDArray[np.bool_]:
        """Boolean mask: lambda inside the range [lo, hi] ([lo, hi) for an open top).

        Parameters
        ----------
        lam : array_like
            lambda.
        hi : float, optional
            Another upper end (the history's), default the table's.

        Returns
        -------
        ndarray of bool
            lam's shape.
        """
        lam_a = np.asarray(lam, dtype=float)
        top = self.hi if hi is None else hi
        upper = lam_a < top if self.top_open else lam_a <= top
        inside: npt.NDArray[np.bool_] = (lam_a >= self.lo) & upper
        return inside

    def check(self, lam: FloatArray, hi: float | None = None, what: str | None = None) -> None:
        """ValueError naming the first lambda outside the range (``in_range``).

        Parameters
        ----------
        lam : ndarray
            lambda.
        hi : float, optional
            Another upper end (the history's).
        what : str, optional
            Another name for the table in the message.
        """
        inside = self.in_range(lam, hi)
        if not np.all(inside):
            bad = float(np.asarray(lam)[~inside].ravel()[0])
            top = self.hi if hi is None else hi
            rng = (f"[{self.lo:g}, {top!r})" if self.top_open else f"[{self.lo:g}, {top:g}]")
            raise ValueError(f"lambda = {bad!r} is outside the {what or self.what}'s range "
                             f"{rng}{self.hint}")

    def locate(self, lam: FloatArray, hi: float | None = None) -> tuple[Index, FloatArray]:
        """Checked piece index and local x (``hi``: among the pieces that end by ``hi``, so
        lambda = hi is the end of the last of them)."""
        self.check(lam)
        last = None if hi is None else int(np.count_nonzero(self.pieces.edges[1:] <= hi)) - 1
        return self.pieces.locate(lam, last)

    def values(self, lam: FloatArray,
               hi: float | None = None) -> tuple[dict[str, FloatArray], Index, FloatArray,
                                                  FloatArray]:
        """Every stored series at lam (1-D): the values by field, piece index, x and the
        Chebyshev basis T_k(x) [lambda, degree]."""
        i, x = self.locate(lam, hi)
        tl = _basis(x, self.coef.shape[0])
        return dict(zip(self.fields, _series_sum(tl, self.coef, i).T)), i, x, tl

    def derivatives(self, lam: FloatArray, i: Index, x: FloatArray) -> dict[str, FloatArray]:
        """d(stored series)/dlambda at lam (1-D) on pieces i at x (from ``values``)."""
        tl = _basis(x, self.dcoef.shape[0])
        scale = self.pieces.dx_dlam(lam, i)
        return {k: c * scale for k, c in zip(self.fields, _series_sum(tl, self.dcoef, i).T)}

    def one(self, lam: FloatArray, field: str) -> tuple[FloatArray, FloatArray]:
        """One stored series and its d/dlambda at lam (1-D): only that series is summed, by the
        same ordered sum as ``values`` and ``derivatives`` (the same bits as theirs)."""
        k = self.fields.index(field)
        i, x = self.locate(lam)
        tl = _basis(x, self.coef.shape[0])
        val = _one_series_sum(tl, self.coef[:, :, k], i)
        der = _one_series_sum(tl, self.dcoef[:, :, k], i)
        return val, der * self.pieces.dx_dlam(lam, i)


def derivative_input(lam: RealArrayLike, field: object,
                     allowed: Sequence[str]) -> tuple[FloatArray, FloatArray]:
    """A summary derivative's checked input: lambda as given and flattened.

    Parameters
    ----------
    lam : array_like
        lambda.
    field : object
        The field asked for.
    allowed : sequence of str
        The fields that have a derivative.

    Returns
    -------
    tuple of ndarray
        lambda in its shape, and flattened.

    Raises
    ------
    ValueError
        For a field not in ``allowed`` or a lambda that is not finite.
    """
    if not isinstance(field, str) or field not in allowed:
        raise ValueError(f"unknown summary field {field!r} to differentiate; allowed: "
                         f"{', '.join(allowed)}")
    lam_in = np.asarray(lam, dtype=float)
    lam1 = lam_in.reshape(-1)
    if not np.all(np.isfinite(lam1)):
        raise ValueError("lambda must be finite")
    return lam_in, lam1
