"""C data of the Chebyshev tables, every table by one emitter (:func:`table_c`) from the
description its generated module holds.

The table modules are read as data (``runpy`` on the file in generated/, not imported: codegen
sits below generated/ and must run when those files are stale). What the C code needs of a table
comes from the module itself (:func:`describe`): its lambda pieces and fields (``TABLE_PIECES``,
``TABLE_FIELDS``, the ``TABLE_*`` lines of ``numerics.cheb_table.TableSpec``), its summary series
(``SUMMARY``), its history
(``HISTORY``: the time pieces, the two fields and the sub-pieces are read from its keys and
entries; ``TIME_PIECES``, ``HISTORY_KEYS`` and ``N_SUB`` where written only order and check them)
and its own scalar constants (the layout of its time maps). No field list is written here: the
C enums that name the fields' positions (:func:`enums_c`) are generated from the same
description, so a table with other fields is read by other names, never misread.

Every coefficient is written with the digits the Python file holds (the history's strings
verbatim, the summary's floats by ``repr``), so C and numpy evaluate the same numbers.
"""
from __future__ import annotations

import dataclasses
import math
import os
import re
import runpy
from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import Any, SupportsFloat

import mpmath

#: Fields a summary table may have in C (ZS__MAX_NF of types.c.in).
MAX_FIELDS = 16
#: Fields of a history: two, side by side in each coefficient matrix (``zs__mat``).
HISTORY_FIELDS = 2


def load(path: str | os.PathLike[str]) -> dict[str, Any]:
    """A table module's globals, read from its file (not imported)."""
    return runpy.run_path(str(path))


def num(v: SupportsFloat | str) -> str:
    """A float as a C literal that reads back to the same double."""
    v = float(v)
    if not math.isfinite(v):
        raise ValueError(f"table value {v!r} is not finite")
    s = repr(v)
    return s if ("e" in s or "." in s) else s + ".0"


def _array(name: str, values: Sequence[SupportsFloat | str], per_line: int = 6) -> str:
    vals = [v if isinstance(v, str) else num(v) for v in values]
    if not vals:
        vals = ["0.0"]
    lines = [", ".join(vals[i:i + per_line]) for i in range(0, len(vals), per_line)]
    return f"static const double {name}[{len(vals)}] = {{\n    " + ",\n    ".join(lines) + "\n};\n"


def _log_rounded(x: float) -> float:
    """ln x correctly rounded (mpmath), so the file does not depend on the machine's libm."""
    with mpmath.workdps(40):
        return float(mpmath.log(mpmath.mpf(x)))


#: C codes of the lambda pieces' kinds of Chebyshev variable (``numerics.cheb_table.PIECE_KINDS``;
#: ZS__LAM .. ZS__SQRT in types.c.in).
PIECE_CODES = {"lam": 0, "log": 1, "sqrt_lam": 2, "sqrt": 3}


def _variable_ends(kind: str, a: float, b: float) -> tuple[float, float]:
    """The Chebyshev variable's ends on the piece [a, b] (``numerics.cheb_table.Pieces``),
    correctly rounded (mpmath's log, IEEE sqrt), so the file does not depend on the machine."""
    if kind == "log":
        return _log_rounded(a), _log_rounded(b)
    if kind == "sqrt_lam":
        return math.sqrt(a), math.sqrt(b)
    if kind == "sqrt":
        return 0.0, math.sqrt(b - a)
    return a, b


def pieces_c(p: str, pieces: Sequence[Sequence[Any]]) -> tuple[str, list[float], list[float]]:
    """C text of a table's lambda pieces (from its description, the generated module's
    TABLE_PIECES): the arrays ``<p>_edges``, ``_ga``, ``_gb``, ``_kind`` that a ``zs__pieces``
    points to, and the variable's ends ga, gb."""
    kinds = [str(k) for k, _, _ in pieces]
    unknown = sorted(set(kinds) - set(PIECE_CODES))
    if unknown:
        raise ValueError(f"table {p}: piece kinds {unknown}; the C runtime knows "
                         f"{', '.join(PIECE_CODES)}")
    edges = [float(a) for _, a, _ in pieces] + [float(pieces[-1][2])]
    ends = [_variable_ends(k, float(a), float(b)) for k, a, b in pieces]
    ga, gb = [e[0] for e in ends], [e[1] for e in ends]
    codes = ", ".join(str(PIECE_CODES[k]) for k in kinds)
    text = (_array(f"{p}_edges", edges) + _array(f"{p}_ga", ga) + _array(f"{p}_gb", gb)
            + f"static const int {p}_kind[{len(pieces)}] = {{{codes}}};\n")
    return text, ga, gb


def _pieces_init(p: str, n: int) -> str:
    return f"{{{n}, {p}_edges, {p}_ga, {p}_gb, {p}_kind}}"


def summary_c(p: str, ns: Mapping[str, Any], keys: Sequence[str],
              fold_x: bool = False) -> tuple[str, str, int]:
    """C text of a table's summary series as the one ``zs__sumtab`` shape every table has
    (evaluated by the runtime's ``zs__eval``): its arrays, the ``zs__sumtab`` initialiser that
    points to them, and its largest degree.

    Per lambda piece one block [degree][field] of the series ``keys`` (interleaved, each
    zero-padded to the piece's longest: a padded term adds an exact 0, so each field's sum in
    order of degree is unchanged), then the arrays ``<p>_sum`` (their pointers) and
    ``<p>_sum_len`` (their degrees). The C loop over degrees then carries every field's sum at
    once (independent additions the processor overlaps).

    Parameters
    ----------
    p : str
        The C name of the table (a prefix of its arrays).
    ns : dict
        The generated table module's names: ``TABLE_PIECES`` and the series.
    keys : sequence of str
        The fields, in the order the C code reads them (``field_enum``).
    fold_x : bool
        Also write x = g xk - xo per piece (a summary's variable without a division).

    Returns
    -------
    tuple
        The C text of the arrays, the initialiser and the largest degree.
    """
    if not 0 < len(keys) <= MAX_FIELDS:
        raise ValueError(f"table {p}: {len(keys)} fields; the C runtime sums 1 to {MAX_FIELDS}")
    series = summary_of(ns)
    pieces = ns["TABLE_PIECES"]
    n_lam = len(pieces)
    text, ga, gb = pieces_c(p, pieces)
    out = [text]
    ptrs, lens, top = [], [], 0
    for ip in range(n_lam):
        cs = [list(series[key][ip]) for key in keys]
        deg = max(len(c) for c in cs)
        vals = [c[j] if j < len(c) else 0.0 for j in range(deg) for c in cs]
        out.append(_array(f"{p}_s{ip}", vals, per_line=len(keys)))
        ptrs.append(f"{p}_s{ip}")
        lens.append(str(deg))
        top = max(top, deg)
    fold = "NULL, NULL"
    if fold_x:
        out += [_array(f"{p}_xk", [2.0 / (b - a) for a, b in zip(ga, gb)]),
                _array(f"{p}_xo", [(a + b) / (b - a) for a, b in zip(ga, gb)])]
        fold = f"{p}_xk, {p}_xo"
    out.append(f"static const double *const {p}_sum[{n_lam}] = {{{', '.join(ptrs)}}};\n"
               f"static const int {p}_sum_len[{n_lam}] = {{{', '.join(lens)}}};\n")
    init = f"{{{_pieces_init(p, n_lam)}, {len(keys)}, {fold}, {p}_sum, {p}_sum_len}}"
    return "".join(out), init, top


def summary_of(ns: Mapping[str, Any]) -> Any:
    """A table module's summary series (``SUMMARY``, every generated table's name for them); a
    ValueError for a module without them."""
    if "SUMMARY" not in ns:
        raise ValueError("table module without summary series: it assigns no SUMMARY")
    return ns["SUMMARY"]


#: A name the C code spells from a table's own (a field, a time piece, a constant).
_C_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


@dataclasses.dataclass(frozen=True)
class Description:
    """What the C code needs of a table, read from its generated module (:func:`describe`).

    Attributes
    ----------
    pieces : tuple of (str, float, float)
        The lambda pieces (``TABLE_PIECES``).
    fields : tuple of str
        The summary's fields, in the order of its blocks (``TABLE_FIELDS``).
    summary : mapping
        field -> per lambda piece one Chebyshev series.
    time_pieces : tuple of str
        The history's time pieces (empty: a summary alone).
    history_fields : tuple of str
        The history's two fields, in the order of each matrix's pair.
    n_sub : tuple of int
        Sub-pieces per time piece.
    n_hist : int
        The history covers the first ``n_hist`` lambda pieces.
    history : mapping
        (time piece, field) -> per lambda piece per sub-piece a "rows cols v..." string.
    constants : tuple of (str, float)
        The module's own scalar constants (its time maps' layout), in the module's order.
    """

    pieces: tuple[tuple[str, float, float], ...]
    fields: tuple[str, ...]
    summary: Mapping[str, Sequence[Sequence[float]]]
    time_pieces: tuple[str, ...] = ()
    history_fields: tuple[str, ...] = ()
    n_sub: tuple[int, ...] = ()
    n_hist: int = 0
    history: Mapping[tuple[str, str], Sequence[Sequence[str]]] = dataclasses.field(
        default_factory=dict)
    constants: tuple[tuple[str, float], ...] = ()

    @property
    def edges(self) -> list[float]:
        """Every lambda piece's start and the last one's end."""
        return [float(a) for _, a, _ in self.pieces] + [float(self.pieces[-1][2])]


def _in_order(found: Sequence[str], written: Any, what: str) -> tuple[str, ...]:
    """``found`` (in order of first appearance) in the order a module writes it, if it does."""
    if written is None:
        return tuple(found)
    if sorted(written) != sorted(found):
        raise ValueError(f"table module: {what} {tuple(written)} written, the history has "
                         f"{tuple(found)}")
    return tuple(written)


def _history_of(ns: Mapping[str, Any], n_lam: int) -> dict[str, Any]:
    """The history part of :class:`Description` from a module's ``HISTORY``."""
    hist = ns["HISTORY"]
    tps = _in_order(list(dict.fromkeys(tp for tp, _ in hist)), ns.get("TIME_PIECES"),
                    "time pieces")
    flds = _in_order(list(dict.fromkeys(f for _, f in hist)), ns.get("HISTORY_KEYS"),
                     "history fields")
    if len(flds) != HISTORY_FIELDS or any((tp, f) not in hist for tp in tps for f in flds):
        raise ValueError(f"table module: history fields {flds} over time pieces {tps}; the C "
                         f"runtime evaluates {HISTORY_FIELDS} fields in every time piece")
    n_sub, n_hist = [], 0
    for tp in tps:
        counts = {len(subs) for f in flds for subs in hist[(tp, f)] if len(subs)}
        if len(counts) != 1:
            raise ValueError(f"table module: time piece {tp} has {sorted(counts)} sub-pieces; one "
                             "count per time piece")
        n_sub.append(counts.pop())
        written = ns.get("N_SUB", {}).get(tp, n_sub[-1])
        if written != n_sub[-1]:
            raise ValueError(f"table module: time piece {tp} has {n_sub[-1]} sub-pieces, N_SUB "
                             f"says {written}")
        n_hist = max([n_hist] + [ip + 1 for f in flds
                                 for ip, subs in enumerate(hist[(tp, f)]) if len(subs)])
    if n_hist > n_lam:
        raise ValueError(f"table module: a history on {n_hist} lambda pieces of {n_lam}")
    return {"time_pieces": tps, "history_fields": flds, "n_sub": tuple(n_sub),
            "n_hist": n_hist, "history": hist}


def describe(ns: Mapping[str, Any]) -> Description:
    """A table module's :class:`Description` (its ``TABLE_*`` lines, series, history and
    constants).

    Parameters
    ----------
    ns : mapping
        The module's globals (``load``).

    Returns
    -------
    Description

    Raises
    ------
    ValueError
        For a history the C runtime cannot evaluate, or a name C cannot spell.
    """
    pieces = tuple((str(k), float(a), float(b)) for k, a, b in ns["TABLE_PIECES"])
    fields = tuple(str(f) for f in ns["TABLE_FIELDS"])
    skip = {"INPUTS_HASH"}
    consts = tuple((k, float(v)) for k, v in ns.items()
                   if k.isupper() and not k.startswith(("TABLE_", "_")) and k not in skip
                   and isinstance(v, (int, float)) and not isinstance(v, bool))
    hist = _history_of(ns, len(pieces)) if "HISTORY" in ns else {}
    d = Description(pieces=pieces, fields=fields, summary=summary_of(ns),
                    constants=consts, **hist)
    for name in (*d.fields, *d.time_pieces, *d.history_fields, *(k for k, _ in consts)):
        if not _C_NAME.match(name):
            raise ValueError(f"table module: the name {name!r} is no C identifier")
    if "HISTORY_TO" in ns and d.n_hist and d.edges[d.n_hist] != float(ns["HISTORY_TO"]):
        raise ValueError(f"table module: HISTORY_TO = {ns['HISTORY_TO']!r}, the history ends at "
                         f"{d.edges[d.n_hist]!r}")
    return d


def field_enum(tag: str, keys: Sequence[str]) -> str:
    """``enum { ZS__<tag>_<KEY>, ..., ZS__N<tag> }``: positions by name (``keys``' order)."""
    names = [f"ZS__{tag}_{k.upper()}" for k in keys] + [f"ZS__N{tag}"]
    if len({n.upper() for n in names}) != len(names):
        raise ValueError(f"C names {names}: two differ only in case")
    return "enum {\n    " + ",\n    ".join(names) + "\n};\n"


def enums_c(tag: str, d: Description) -> str:
    """The C enums of a table, generated from its description: its summary fields' positions
    in its blocks (``ZS__<tag>_<FIELD>``, ``ZS__N<tag>``), its time pieces
    (``ZS__<tag>P_<PIECE>``), its history fields (``ZS__<tag>H_<FIELD>``) and its constants
    (``ZS__<tag>K_<NAME>``), by which the runtime's code for the table reads them."""
    out = field_enum(tag, d.fields)
    for sfx, keys in (("P", d.time_pieces), ("H", d.history_fields),
                      ("K", [k for k, _ in d.constants])):
        if keys:
            out += field_enum(tag + sfx, keys)
    return out


def _cheb_to_monomial_exact(n: int) -> list[list[Fraction]]:
    """[power i][Chebyshev degree j]: the (integer) monomial coefficients of T_j on [-1, 1]."""
    rows = [[Fraction(0)] * n for _ in range(n)]
    prev, cur = [1], [0, 1]  # T_0, T_1 as monomial coefficient lists
    polys = [prev, cur]
    for _ in range(2, n):
        nxt = [0] + [2 * c for c in cur]
        for i, c in enumerate(prev):
            nxt[i] -= c
        prev, cur = cur, nxt
        polys.append(cur)
    for j in range(n):
        for i, c in enumerate(polys[j]):
            rows[i][j] = Fraction(c)
    return rows


def _to_monomial(vals: list[str], rows: int, cols: int,
                 conv: list[list[Fraction]]) -> list[list[float]]:
    """A [rows: Chebyshev degree in time][cols: lambda degree] matrix (the file's digits) as
    [time power][lambda degree]: each coefficient the exact sum, rounded once (machine
    independent; ``numerics.cheb_table.history_rows`` does the same conversion in float64)."""
    c = [[Fraction(float(vals[j * cols + k])) for k in range(cols)] for j in range(rows)]
    return [[float(sum(conv[i][j] * c[j][k] for j in range(i, rows))) for k in range(cols)]
            for i in range(rows)]


#: rows of a history matrix are padded to a multiple of this (zs__contract's register blocks)
ROW_BLOCK = 4


def _history_c(p: str, d: Description, out: list[str], sizes: dict[str, int]) -> list[str]:
    """Append to ``out`` the history of every time piece and return the ``zs__tpiece``
    initialisers, in the description's order. Per lambda piece and sub-piece one matrix
    [lambda degree k][time power j][field] (the two fields interleaved, zero-padded to the
    larger degrees): the time direction converted from Chebyshev to monomials in the
    sub-piece's x here, once, so the C code only contracts in lambda (per call, contiguous rows
    of field pairs) and evaluates Horner's rule per point. A lambda piece without history gets
    empty entries. ``sizes`` is updated."""
    pieces_c = []
    convs: dict[int, list[list[Fraction]]] = {}
    for tp, n_sub in zip(d.time_pieces, d.n_sub):
        sizes["max_sub"] = max(sizes["max_sub"], n_sub)
        per = [d.history[(tp, fld)] for fld in d.history_fields]
        entries = []
        for ip in range(len(d.pieces)):
            subs = [f[ip] if ip < len(f) else () for f in per]
            if not any(len(sb) for sb in subs):
                entries.extend(["{0, 0, 0, NULL, {0}}"] * n_sub)
                continue
            for s in range(n_sub):
                mats = []
                for fld, sb in zip(d.history_fields, subs):
                    parts = sb[s].split()
                    rows, cols = int(parts[0]), int(parts[1])
                    if len(parts) - 2 != rows * cols:
                        raise ValueError(f"table {p}: malformed array {tp}/{fld}/{ip}/{s}")
                    if rows not in convs:
                        convs[rows] = _cheb_to_monomial_exact(rows)
                    mats.append(_to_monomial(parts[2:], rows, cols, convs[rows]))
                entries.append(_matrix_c(f"{p}_{tp}_{ip}_{s}", mats, out, sizes))
        out.append(f"static const zs__mat {p}_{tp}[{len(entries)}] = {{\n    "
                   + ",\n    ".join(entries) + "\n};\n")
        pieces_c.append(f"{{{n_sub}, {p}_{tp}}}")
    return pieces_c


def _matrix_c(arr: str, mats: list[list[list[float]]], out: list[str],
              sizes: dict[str, int]) -> str:
    """One sub-piece's matrices as the array ``arr`` (appended to ``out``) and its ``zs__mat``
    initialiser."""
    R = max(len(m) for m in mats)
    K = max(len(m[0]) for m in mats)
    # rows zero-padded to a multiple of ROW_BLOCK: the C contraction then runs in whole blocks
    # of registers (Horner still starts at row R - 1)
    rp = -(-R // ROW_BLOCK) * ROW_BLOCK
    vals = [m[j][k] if j < len(m) and k < len(m[j]) else 0.0
            for k in range(K) for j in range(rp) for m in mats]
    # per block of ROW_BLOCK rows, the lambda degrees up to its last nonzero (at least 1):
    # beyond them the contraction would add exact zeros
    bcols = []
    for b0 in range(0, rp, ROW_BLOCK):
        nz = [k for k in range(K) for j in range(b0, b0 + ROW_BLOCK) for m in mats
              if j < len(m) and k < len(m[j]) and m[j][k] != 0.0]
        bcols.append(str(max(nz, default=0) + 1))
    if K > 255:
        raise ValueError(f"{arr}: {K} lambda degrees; the C layout counts them in an unsigned "
                         "char (at most 255)")
    out.append(_array(arr, vals, per_line=6))
    sizes["max_rows"] = max(sizes["max_rows"], rp)
    sizes["max_lamdeg"] = max(sizes["max_lamdeg"], K)
    return f"{{{rp}, {K}, {R}, {arr}, {{{', '.join(bcols)}}}}}"


#: The sizes the runtime's buffers need (``ZS__MAX_*`` of types.c.in), raised to each table's.
SIZES = ("max_lamdeg", "max_rows", "max_sub", "max_sum", "max_tp")


def table_c(name: str, d: Description, fold_x: bool = False) -> tuple[str, dict[str, int]]:
    """THE table emitter: C text defining ``static const zs__table zs__tab_<name>`` (its summary
    as a ``zs__sumtab``, its history's time pieces, its constants) from its description, and
    the sizes it needs.

    Parameters
    ----------
    name : str
        The table's C name.
    d : Description
        The table (``describe``).
    fold_x : bool
        ``summary_c``'s: also write the summary's variable without a division.

    Returns
    -------
    tuple
        The C text and its sizes (keys ``SIZES``).
    """
    p = f"zs__{name}"
    hist = f", history on {d.n_hist}, time pieces {', '.join(d.time_pieces)}" if d.n_hist else ""
    out = [f"/* ---- table '{name}': {len(d.pieces)} lambda pieces{hist} ---- */\n"]
    sizes = dict.fromkeys(SIZES, 0)
    summary, init, sizes["max_sum"] = summary_c(
        p, {"TABLE_PIECES": d.pieces, "SUMMARY": d.summary}, d.fields, fold_x=fold_x)
    out.append(summary)
    tpieces = _history_c(p, d, out, sizes)
    sizes["max_tp"] = len(tpieces)
    tp_ptr = consts = "NULL"
    if tpieces:
        out.append(f"static const zs__tpiece {p}_tp[{len(tpieces)}] = "
                   f"{{{', '.join(tpieces)}}};\n")
        tp_ptr = f"{p}_tp"
    if d.constants:
        out.append(_array(f"{p}_k", [v for _, v in d.constants]))
        consts = f"{p}_k"
    out.append(f"static const zs__table zs__tab_{name} = {{\n    {init},\n"
               f"    {d.n_hist}, {num(d.edges[d.n_hist])}, {len(tpieces)}, {tp_ptr}, {consts}\n"
               "};\n\n")
    return "".join(out), sizes
