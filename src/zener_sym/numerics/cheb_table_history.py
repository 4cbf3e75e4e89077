"""The history part of the Chebyshev-table engine: a table's history in time and lambda,
evaluated once for every table that has one.

A history is stored per time piece (C, A, M, B for the plate's end of contact; C, R for the
force-free end): per lambda piece and per sub-piece (equal parts of the piece's reduced time
y in [0, 1]) one [time degree, lambda degree] Chebyshev matrix of two fields. The engine does
what every history does the same way (:class:`History`):

- the distinct lambdas of a (lambda, tau) grid (:class:`Lines`: one per line when lambda is
  a broadcast column), checked against the history's range;
- the lambda contraction, once per distinct lambda and time piece (:func:`line_coefficients`);
- the points of each time piece in blocks of ``blocks.BLOCK`` (per-point temporaries as large
  as the grid cost more in fresh memory than in arithmetic);
- the sub-piece lookup and Horner's rule on both fields at once (:func:`sub_piece_values`),
  with one guard (below).

Each instance supplies only its time maps (:class:`TimeMaps`): which time piece a point lies
in, the reduced time z = K y of a piece (K sub-pieces) and the back-transform of the two
fields to its output, and the values past the end of contact.

The guard. Rounding puts z a hair outside [0, K] at a piece's ends: truncation toward zero
already sends z in (-1, 0) to sub-piece 0, and z >= K is clamped to the last sub-piece
(x a hair beyond 1: the polynomial a hair past its end, well inside its accuracy). A negative
sub-piece (z <= -1, or z NaN, whose cast is the most negative integer) would index another
line's row and return a plausible wrong number, so it raises: a ValueError when the time
itself is bad (negative or NaN: the public functions refuse those before), a RuntimeError
otherwise (a map that left its piece is a bug). Clamping it instead, as the force-free end
once did, silently evaluated row 0 at a NaN or far-out x.
"""
from __future__ import annotations

import abc
from collections.abc import Mapping, Sequence
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray, RealArrayLike
from .blocks import BLOCK, field_buffers
from .chebyshev import cheb_to_monomial, horner_take_pair

__all__ = ["Index", "parse_array", "HistoryPiece", "history_rows", "history_tables",
           "line_coefficients", "Lines", "TimeMaps", "History", "sub_piece_values",
           "history_assignments"]

#: Piece, line or row indices.
Index = npt.NDArray[np.intp]


def parse_array(text: str) -> FloatArray:
    """The 2-D array written as the string "rows cols v v ..." (the history coefficients).

    Parameters
    ----------
    text : str
        "rows cols" then rows * cols numbers, separated by spaces.

    Returns
    -------
    ndarray
        [rows, cols].
    """
    v = np.array(text.split(), dtype=float)
    return v[2:].reshape(int(v[0]), int(v[1]))


class HistoryPiece(NamedTuple):
    """One time piece's history arranged for :func:`line_coefficients` (``history_rows``)."""

    #: Per lambda piece [time degree, lambda degree, 2 * sub-piece + field] monomial
    #: coefficients in the sub-piece's x (None where the lambda piece has no such time piece).
    rows: list[FloatArray | None]
    #: Sub-pieces K.
    n_sub: int
    #: Time degree (rows of every array).
    degree: int
    #: Per lambda piece the time degree its own coefficients need (Horner starts there).
    need: npt.NDArray[np.int_]


def history_rows(mats: Sequence[Sequence[Sequence[str | RealArrayLike]]]) -> HistoryPiece:
    """One time piece's history arranged for :func:`line_coefficients`.

    Per lambda piece an array [time degree, lambda degree, 2 * sub-piece + field] (two fields,
    zero-padded to the time piece's largest degree, trimmed in lambda degree to the last
    nonzero), so the lambda contraction gives per line the pairs (field 0, field 1) next to each
    other, read as one complex128 per sub-piece by ``chebyshev.horner_take_pair``. The time
    direction is converted from Chebyshev to monomial coefficients in the sub-piece's x
    (Horner's rule: fewer passes over the points than Clenshaw's; on a sub-piece the
    coefficients fall fast, so the conversion loses no digits that matter).

    Parameters
    ----------
    mats : sequence
        Per field (two), per lambda piece, per sub-piece one [time degree, lambda degree]
        Chebyshev matrix (an array or its "rows cols v..." string); a lambda piece without this
        time piece has no sub-pieces.

    Returns
    -------
    HistoryPiece
    """
    arrs = [[[parse_array(c) if isinstance(c, str) else np.asarray(c, dtype=float) for c in subs]
             for subs in per] for per in mats]
    n_lam = len(arrs[0])
    n_sub = max(len(subs) for per in arrs for subs in per)
    flat = [c for per in arrs for subs in per for c in subs]
    deg, n_k = max(c.shape[0] for c in flat), max(c.shape[1] for c in flat)
    conv = cheb_to_monomial(deg)  # monomial = conv @ Chebyshev
    fields = []
    for per in arrs:
        a = np.zeros((n_lam, n_sub, deg, n_k))  # [lambda piece, sub, j, k]
        for p, subs in enumerate(per):
            for s, c in enumerate(subs):
                a[p, s, : c.shape[0], : c.shape[1]] = c
        fields.append(np.einsum("ij,psjk->psik", conv, a))
    blk = np.stack(fields, axis=2)  # [lambda piece, sub, field, degree, k]
    rows: list[FloatArray | None] = []
    for p in range(n_lam):
        if not len(arrs[0][p]):
            rows.append(None)
            continue
        b = blk[p]
        nz = np.flatnonzero(np.any(b != 0.0, axis=(0, 1, 2)))
        k = int(nz.max()) + 1 if nz.size else 1
        rows.append(np.ascontiguousarray(b[..., :k].transpose(2, 3, 0, 1).reshape(deg, k,
                                                                                   2 * n_sub)))
    need = np.array([max([c.shape[0] for per in arrs for c in per[p]] or [1])
                     for p in range(n_lam)])
    return HistoryPiece(rows, n_sub, deg, need)


def history_tables(history: Mapping[tuple[str, str], Any], time_pieces: Sequence[str],
                   keys: Sequence[str]) -> dict[str, HistoryPiece]:
    """``history_rows`` of every time piece of a generated module's HISTORY.

    Parameters
    ----------
    history : mapping
        (time piece, field) -> per lambda piece, per sub-piece, a matrix string.
    time_pieces : sequence of str
        The time pieces.
    keys : sequence of str
        The two fields, in the order of the pair (real part first).

    Returns
    -------
    dict
        time piece -> its :class:`HistoryPiece`.
    """
    return {piece: history_rows([history[(piece, k)] for k in keys]) for piece in time_pieces}


def line_coefficients(rows: Sequence[FloatArray | None], ip: Index, tl: FloatArray, deg: int,
                      n_sub: int) -> npt.NDArray[np.complex128]:
    """[time degree, line * sub-piece], complex: one time piece's monomial coefficients per
    line (real part field 0's, imaginary part field 1's), sum_k C[j, k, 2 s + field] T_k(x).

    Parameters
    ----------
    rows : sequence
        ``history_rows``' arrays per lambda piece.
    ip : ndarray of int
        Each line's lambda piece, sorted (the lines are distinct sorted lambdas), so each
        piece's lines are one slice: one stacked matrix product per piece present.
    tl : ndarray
        T_k(x_lambda) per line, [line, degree] (at least as many degrees as any piece needs).
    deg, n_sub : int
        The time piece's degree and sub-piece count.

    Returns
    -------
    ndarray of complex128
    """
    out = np.zeros((deg, len(ip), 2 * n_sub))
    for p in np.unique(ip):
        c = rows[int(p)]
        if c is None:
            continue
        a, b = np.searchsorted(ip, p), np.searchsorted(ip, p, side="right")
        # one small matrix product per time degree (a stack of them), written straight into
        # the [degree, line, ...] layout
        np.matmul(tl[a:b, : c.shape[1]], c, out=out[:, a:b])
    return out.reshape(deg, -1).view(np.complex128)


def history_assignments(time_pieces: Sequence[str], keys: Sequence[str],
                        n_sub: Mapping[str, int], hi: float) -> list[str]:
    """The lines of a generated module that describe its history (read back by
    :meth:`History.of`; the C emitter reads the same names).

    Parameters
    ----------
    time_pieces : sequence of str
        The time pieces, in the order of time.
    keys : sequence of str
        The two stored fields.
    n_sub : mapping
        Sub-pieces per time piece.
    hi : float
        The history ends at this lambda.

    Returns
    -------
    list of str
    """
    return ["#: the history's description (zener_sym.numerics.cheb_table_history.History): its",
            "#: upper end in lambda, time pieces in the order of time, the two stored fields",
            "#: and the sub-pieces per time piece",
            f"HISTORY_TO = {float(hi)!r}", f"TIME_PIECES = {tuple(time_pieces)!r}",
            f"HISTORY_KEYS = {tuple(keys)!r}", f"N_SUB = {dict(n_sub)!r}"]


class Lines(NamedTuple):
    """The distinct lambdas of a (lambda, tau) grid and the map from points to them."""

    #: The distinct lambdas, sorted.
    lam: FloatArray
    #: Each grid line's lambda (``n_col`` set: lambda is a column, one per line of tau) or
    #: each point's (an index into ``lam``).
    of_line: Index
    #: Points per line when lambda is a column, else None.
    n_col: int | None
    #: The times, flat.
    tau: FloatArray
    #: The grid's shape.
    shape: tuple[int, ...]

    @classmethod
    def of(cls, lam: RealArrayLike, tau: RealArrayLike) -> "Lines":
        """The grid of ``lam`` and ``tau`` broadcast together.

        When lambda is constant along the last axis (a broadcast column), the lines are
        sorted, not every point, and points find their line by division.
        """
        lam_a, tau_a = np.broadcast_arrays(np.asarray(lam, dtype=float),
                                           np.asarray(tau, dtype=float))
        if lam_a.ndim >= 1 and lam_a.shape[-1] > 1 and np.array_equal(
                lam_a, np.broadcast_to(lam_a[..., :1], lam_a.shape)):
            lu, line = np.unique(lam_a[..., 0].ravel(), return_inverse=True)
            return cls(lu, line.ravel(), lam_a.shape[-1], tau_a.ravel(), tau_a.shape)
        lu, inv = np.unique(lam_a.ravel(), return_inverse=True)
        return cls(lu, inv.ravel(), None, tau_a.ravel(), tau_a.shape)

    def line_of(self, at: Index) -> Index:
        """The line (distinct lambda) of the points at flat positions ``at``."""
        if self.n_col is not None:
            return self.of_line.take(at // self.n_col, mode="clip")
        return self.of_line.take(at, mode="clip")

    def per_point(self, bounds: Sequence[FloatArray]) -> tuple[FloatArray, list[FloatArray]]:
        """The times and per-line quantities ``bounds`` made to broadcast point by point:
        [line, column] and [line, 1] for a column of lambdas (no gather per point), else flat
        and gathered per point."""
        if self.n_col is not None:
            return (self.tau.reshape(len(self.of_line), self.n_col),
                    [q[self.of_line, None] for q in bounds])
        return self.tau, [q.take(self.of_line, mode="clip") for q in bounds]


class TimeMaps(abc.ABC):
    """An instance's time maps for one evaluation (per-line constants from its summary): what
    a history supplies to :meth:`History.evaluate`. Subclasses set ``fields``, the output
    field names."""

    fields: tuple[str, ...] = ()

    @abc.abstractmethod
    def piece_of(self, lines: Lines) -> npt.NDArray[np.int8]:
        """Each point's time piece (flat, int8): its index in the history's time pieces, or
        their count past the end of contact."""

    @abc.abstractmethod
    def constants(self, name: str, k: int) -> Any:
        """Per-line constants of time piece ``name``'s map (K = ``k`` sub-pieces)."""

    @abc.abstractmethod
    def reduced_time(self, name: str, m: Any, t: FloatArray,
                     li: Index) -> tuple[FloatArray, Any]:
        """z = K y in [0, K] at times t on the lines li (``m`` from ``constants``), and
        anything ``store`` needs of the map."""

    @abc.abstractmethod
    def store(self, name: str, f: FloatArray, g: FloatArray, t: FloatArray, li: Index, aux: Any,
              out: dict[str, FloatArray], at: Index) -> None:
        """The back-transform: the output fields at the flat positions ``at`` from the two
        stored fields f, g at times t on the lines li."""

    @abc.abstractmethod
    def after(self, out: dict[str, FloatArray], at: Index, li: Index) -> None:
        """The output fields past the end of contact at ``at`` (lines li)."""


def sub_piece_values(rows: npt.NDArray[np.complex128], k: int, z: FloatArray, li: Index,
                     t: FloatArray, what: str) -> tuple[FloatArray, FloatArray]:
    """Both stored fields at reduced times z = K y on the lines li: the sub-piece, its x and
    Horner's rule on the line's coefficients (``horner_take_pair``), with the engine's one
    guard (the module docstring).

    Parameters
    ----------
    rows : ndarray of complex128
        [time degree, line * sub-piece] (``line_coefficients``).
    k : int
        Sub-pieces K.
    z : ndarray
        Reduced times times K (modified: the caller's temporary).
    li : ndarray of int
        Each point's line.
    t : ndarray
        The points' times (for the message).
    what : str
        The history and time piece, for the message.

    Returns
    -------
    tuple of ndarray
        Field 0 and field 1.

    Raises
    ------
    ValueError
        For a negative or NaN time.
    RuntimeError
        For a reduced time below its piece otherwise (a bug of the map).
    """
    with np.errstate(invalid="ignore"):  # a NaN's cast is checked just below
        sub = z.astype(np.intp)  # z > -1: truncation is floor, or 0
    if sub.size and sub.min() < 0:  # never index another line's row
        bad = ~(t >= 0.0)
        if bad.any():
            raise ValueError(f"{what}: tau must be >= 0 and not NaN, got {t[bad][0]!r}")
        raise RuntimeError(f"{what}: reduced time {z[sub < 0][0]!r} below its piece at tau = "
                           f"{t[sub < 0][0]!r}; this is a bug")
    np.minimum(sub, k - 1, out=sub)
    x = z - sub
    x *= 2.0
    x -= 1.0
    sub += li * k  # the point's row: line, sub-piece
    return horner_take_pair(rows, sub, x)


class History:
    """A table's history: per time piece its :class:`HistoryPiece`, evaluated on a grid with
    an instance's :class:`TimeMaps`.

    Parameters
    ----------
    pieces : mapping
        time piece -> :class:`HistoryPiece`, in the order of time.
    hi : float
        The history ends at this lambda.
    what : str
        The history's name in messages.
    """

    def __init__(self, pieces: Mapping[str, HistoryPiece], hi: float, what: str) -> None:
        self.pieces = dict(pieces)
        self.time_pieces = tuple(self.pieces)
        self.hi, self.what = float(hi), what
        #: lambda degrees the contraction needs (the basis is made once for every piece)
        self.lam_degree = max(c.shape[1] for h in self.pieces.values() for c in h.rows
                              if c is not None)

    @classmethod
    def of(cls, module: Any, what: str) -> "History":
        """The history of a generated table module, or of its globals (``HISTORY`` and the
        names written by :func:`history_assignments`)."""
        ns = module if isinstance(module, Mapping) else vars(module)
        return cls(history_tables(ns["HISTORY"], ns["TIME_PIECES"], ns["HISTORY_KEYS"]),
                   ns["HISTORY_TO"], what)

    def basis(self, xl: FloatArray) -> FloatArray:
        """T_k(x) of the distinct lambdas, [line, degree], for :meth:`evaluate` (numpy's
        ``chebvander``: a view in degree-major memory).

        The basis's memory layout decides how numpy's matrix product (BLAS) rounds the lambda
        contraction: the plate's history has always used this one, the force-free end the
        summary's own basis (``SummaryTable.values``; row-major for up to 4 lambdas), and each
        keeps its own so that its doubles do not change.
        """
        return np.asarray(np.polynomial.chebyshev.chebvander(xl, self.lam_degree - 1),
                          dtype=float)

    def evaluate(self, lines: Lines, ip: Index, tl: FloatArray,
                 maps: TimeMaps) -> dict[str, FloatArray]:
        """The output fields on the grid ``lines`` (lambda pieces ``ip`` and Chebyshev basis
        ``tl`` of its distinct lambdas), flat.

        The lambda direction is contracted once per distinct lambda and time piece; each
        point then costs its piece's map, one polynomial per field (Horner) and the
        back-transform. The points of a time piece are found chunk by chunk of the grid (no
        index array of the grid's size: the call's peak memory decides whether glibc keeps it
        for the next call) and evaluated in blocks of ``BLOCK``.

        Parameters
        ----------
        lines : Lines
            The grid.
        ip : ndarray of int
            The distinct lambdas' pieces (their summary's).
        tl : ndarray
            T_k(x) of the distinct lambdas, [line, degree], at least ``lam_degree`` degrees
            (:meth:`basis`, or the summary's).
        maps : TimeMaps
            The instance's maps for these lines.

        Returns
        -------
        dict of str to ndarray
            ``maps.fields``, flat.
        """
        piece = maps.piece_of(lines)
        out = field_buffers(maps.fields, lines.tau.shape)
        for n, name in enumerate((*self.time_pieces, None)):
            if not np.any(piece == n):
                continue
            rows: npt.NDArray[np.complex128] | None = None
            if name is not None:
                h = self.pieces[name]
                rows = line_coefficients(h.rows, ip, tl, h.degree, h.n_sub)[:int(h.need[ip].max())]
                m = maps.constants(name, h.n_sub)
            for c0 in range(0, piece.size, 4 * BLOCK):
                at_chunk = np.flatnonzero(piece[c0:c0 + 4 * BLOCK] == n)
                at_chunk += c0
                for s in range(0, at_chunk.size, BLOCK):
                    at = at_chunk[s:s + BLOCK]
                    li = lines.line_of(at)
                    if name is None or rows is None:
                        maps.after(out, at, li)
                        continue
                    t = lines.tau.take(at, mode="clip")
                    z, aux = maps.reduced_time(name, m, t, li)
                    f, g = sub_piece_values(rows, self.pieces[name].n_sub, z, li, t,
                                            f"{self.what}, time piece {name}")
                    maps.store(name, f, g, t, li, aux, out, at)
            rows = None  # freed before the next piece's coefficients are made
        return out
