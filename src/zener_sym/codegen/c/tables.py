"""C data for the Chebyshev tables: the exact model's (``generated/exact_table.py`` layout) and
the ham1 summary's (``generated/ham1_table.py``).

The table modules are read as data (``runpy`` on the file in generated/, not imported: codegen
sits below generated/ and must run when those files are stale). Every coefficient is written
with the digits the Python file holds (the history's strings verbatim, the summary's floats by
``repr``), so C and numpy evaluate the same numbers.

``exact_table_c(name, ns)`` is generic over a table module with the exact table's layout
(``TABLE_PIECES``, whose ln-lambda pieces start at LOG_FROM, ``HISTORY_TO``, ``C_STRETCH``,
``C_END``, ``S_ORBIT``, ``S_TRANSIENT``, ``N_SUB``, ``SUMMARY``, ``HISTORY``): another end of contact with its own table
is one more entry in ``zener_sym.codegen.c.EXACT_TABLES``.
"""
from __future__ import annotations

import math
import os
import runpy
from collections.abc import Sequence
from fractions import Fraction
from typing import Any, SupportsFloat

import mpmath

#: Summary fields of an exact table, in the order the C code reads them (zs__S_* indices).
EXACT_SUMMARY_KEYS = ("delta_m", "tau_dc", "log_tau_d", "log_e", "int_F2", "rest_over_lam")
#: Time pieces of the history, in the C code's order.
TIME_PIECES = ("C", "A", "M", "B")
#: ham1 table fields, in the C code's order.
HAM1_KEYS = ("delta_m", "tau_dc", "log_tau_d", "log_e", "impulse", "int_F2")
#: Fields a summary table may have in C (ZS__MAX_NF of types.c.in).
MAX_FIELDS = 16


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


def log_start(pieces: Sequence[Sequence[Any]]) -> float:
    """Where a table's ln-lambda pieces start (its TABLE_PIECES; ``TableSpec.log_from``)."""
    return min((float(a) for k, a, _ in pieces if k == "log"), default=math.inf)


def _pieces_init(p: str, n: int) -> str:
    return f"{{{n}, {p}_edges, {p}_ga, {p}_gb, {p}_kind}}"


def exact_table_c(name: str, ns: dict[str, Any]) -> tuple[str, dict[str, int]]:
    """C text defining ``static const zs__exact_table zs__tab_<name>``, and its sizes."""
    pieces = tuple(ns.get("TIME_PIECES", TIME_PIECES))
    if pieces != TIME_PIECES or tuple(ns.get("HISTORY_KEYS", ("f", "I"))) != ("f", "I"):
        raise ValueError(f"table {name}: time pieces {pieces}; the C runtime evaluates "
                         f"{TIME_PIECES} with fields ('f', 'I') (add the new maps to "
                         "codegen/c/runtime.c.in first)")
    pieces = ns["TABLE_PIECES"]
    edges = [float(a) for _, a, _ in pieces] + [float(pieces[-1][2])]
    n_lam = len(pieces)
    log_from = log_start(ns["TABLE_PIECES"])
    hist_to = float(ns["HISTORY_TO"])
    p = f"zs__{name}"
    out = [f"/* ---- exact table '{name}': {n_lam} lambda pieces ---- */\n"]
    sizes = {"max_lamdeg": 0, "max_rows": 0, "max_sub": 0, "max_sum": 0}
    # x = g k - o, a summary's piece variable without a division (IEEE operations on the
    # written doubles: the same on every machine)
    summary, init, sizes["max_sum"] = summary_c(p, ns, EXACT_SUMMARY_KEYS, fold_x=True)
    out.append(summary)
    # history: per time piece and field, per lambda piece and sub-piece, a [rows][cols] matrix
    n_hist = sum(1 for b in edges[1:] if b <= hist_to)
    tpieces = _history_c(name, p, ns, TIME_PIECES, ("f", "I"), n_lam, out, sizes)
    for key in ("max_lamdeg", "max_sum"):
        sizes[key] = max(sizes[key], 2)
    out.append(
        f"static const zs__exact_table zs__tab_{name} = {{\n"
        f"    {init},\n    {n_hist}, {num(hist_to)},\n"
        f"    {num(log_from)}, {num(ns['C_STRETCH'])}, {num(ns['C_END'])}, "
        f"{num(ns['S_ORBIT'])}, {num(ns['S_TRANSIENT'])},\n"
        f"    {{{', '.join(tpieces)}}}\n}};\n\n")
    return "".join(out), sizes


def summary_c(p: str, ns: dict[str, Any], keys: Sequence[str], fold_x: bool = False,
              summary_name: str = "SUMMARY") -> tuple[str, str, int]:
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
    summary_name : str
        The name the module assigns its series to.

    Returns
    -------
    tuple
        The C text of the arrays, the initialiser and the largest degree.
    """
    if not 0 < len(keys) <= MAX_FIELDS:
        raise ValueError(f"table {p}: {len(keys)} fields; the C runtime sums 1 to {MAX_FIELDS}")
    pieces = ns["TABLE_PIECES"]
    n_lam = len(pieces)
    text, ga, gb = pieces_c(p, pieces)
    out = [text]
    ptrs, lens, top = [], [], 0
    for ip in range(n_lam):
        cs = [list(ns[summary_name][key][ip]) for key in keys]
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


def field_enum(tag: str, keys: Sequence[str]) -> str:
    """``enum { ZS__<tag>_<FIELD>, ..., ZS__N<tag> }``: the positions of a table's fields in its
    summary blocks (``summary_c``'s ``keys``), by which the runtime reads them."""
    names = [f"ZS__{tag}_{k.upper()}" for k in keys] + [f"ZS__N{tag}"]
    return "enum {\n    " + ",\n    ".join(names) + "\n};\n"


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


def _history_c(name: str, p: str, ns: dict[str, Any], pieces: Sequence[str], keys: Sequence[str],
               n_lam: int, out: list[str], sizes: dict[str, int]) -> list[str]:
    """Append to ``out`` the history of every time piece and return the ``zs__tpiece``
    initialisers, in ``pieces`` order. Per lambda piece and sub-piece one matrix
    [lambda degree k][time power j][field] (``keys``' two fields interleaved, zero-padded to the
    larger degrees): the time direction converted from Chebyshev to monomials in the
    sub-piece's x here, once, so the C code only contracts in lambda (per call, contiguous rows
    of field pairs) and evaluates Horner's rule per point. A lambda piece without history gets
    empty entries. ``sizes`` is updated."""
    pieces_c = []
    convs = {}
    for tp in pieces:
        n_sub = int(ns["N_SUB"][tp])
        sizes["max_sub"] = max(sizes["max_sub"], n_sub)
        per = [ns["HISTORY"][(tp, fld)] for fld in keys]
        entries = []
        for ip in range(n_lam):
            subs = [f[ip] if ip < len(f) else () for f in per]
            if not len(subs[0]) and not len(subs[1]):
                entries.extend(["{0, 0, 0, NULL, {0}}"] * n_sub)
                continue
            for fld, sb in zip(keys, subs):
                if len(sb) != n_sub:
                    raise ValueError(f"table {name}: piece {tp}/{fld} has {len(sb)} sub-pieces, "
                                     f"N_SUB says {n_sub}")
            for s in range(n_sub):
                mats = []
                for fld, sb in zip(keys, subs):
                    parts = sb[s].split()
                    rows, cols = int(parts[0]), int(parts[1])
                    if len(parts) - 2 != rows * cols:
                        raise ValueError(f"table {name}: malformed array {tp}/{fld}/{ip}/{s}")
                    if rows not in convs:
                        convs[rows] = _cheb_to_monomial_exact(rows)
                    mats.append(_to_monomial(parts[2:], rows, cols, convs[rows]))
                R = max(len(m) for m in mats)
                K = max(len(m[0]) for m in mats)
                # rows zero-padded to a multiple of ROW_BLOCK: the C contraction then runs in
                # whole blocks of registers (Horner still starts at row R - 1)
                rp = -(-R // ROW_BLOCK) * ROW_BLOCK
                vals = [m[j][k] if j < len(m) and k < len(m[j]) else 0.0
                        for k in range(K) for j in range(rp) for m in mats]
                # per block of ROW_BLOCK rows, the lambda degrees up to its last nonzero (at
                # least 1): beyond them the contraction would add exact zeros
                bcols = []
                for b0 in range(0, rp, ROW_BLOCK):
                    nz = [k for k in range(K) for j in range(b0, b0 + ROW_BLOCK) for m in mats
                          if j < len(m) and k < len(m[j]) and m[j][k] != 0.0]
                    bcols.append(str(max(nz, default=0) + 1))
                if K > 255:
                    raise ValueError(f"table {name}: {K} lambda degrees in {tp}/{ip}/{s}; the C "
                                     "layout counts them in an unsigned char (at most 255)")
                arr = f"{p}_{tp}_{ip}_{s}"
                out.append(_array(arr, vals, per_line=6))
                entries.append(f"{{{rp}, {K}, {R}, {arr}, {{{', '.join(bcols)}}}}}")
                sizes["max_rows"] = max(sizes["max_rows"], rp)
                sizes["max_lamdeg"] = max(sizes["max_lamdeg"], K)
        out.append(f"static const zs__mat {p}_{tp}[{len(entries)}] = {{\n    "
                   + ",\n    ".join(entries) + "\n};\n")
        pieces_c.append(f"{{{n_sub}, {p}_{tp}}}")
    return pieces_c

def ham1_table_c(ns: dict[str, Any]) -> tuple[str, int]:
    """C text of the ham1 summary table (``static const zs__sumtab zs__h1``), and its largest
    degree."""
    text, init, deg = summary_c("zs__h1", ns, HAM1_KEYS)
    return ("/* ---- ham1 summary table ---- */\n" + text
            + f"static const zs__sumtab zs__h1 = {init};\n\n"), deg


#: Summary fields of a force-free-end table the C code reads (zs__F_* order).
FORCE_SUMMARY_KEYS = ("delta_m", "tau_dc", "log_tau_d", "log_e", "xi_over_lam", "log_F_m",
                      "log_int_F2", "log_tau_p")
#: Time pieces and fields of a force-free-end history, in the C code's order.
FORCE_TIME_PIECES = ("C", "R")
FORCE_HISTORY_KEYS = ("f", "v")


def force_table_c(name: str, ns: dict[str, Any]) -> tuple[str, dict[str, int]]:
    """C text defining ``static const zs__force_table zs__ftab_<name>`` (a force-free-end table,
    ``generated/exact_force_table.py`` layout: summary in sqrt(lambda) below LOG_FROM, ln lambda
    above; history in time pieces C and R, fields f and v), and its sizes."""
    if (tuple(ns.get("TIME_PIECES", ())) != FORCE_TIME_PIECES
            or tuple(ns.get("HISTORY_KEYS", ())) != FORCE_HISTORY_KEYS):
        raise ValueError(f"force table {name}: time pieces {ns.get('TIME_PIECES')}, fields "
                         f"{ns.get('HISTORY_KEYS')}; the C runtime evaluates "
                         f"{FORCE_TIME_PIECES} with {FORCE_HISTORY_KEYS}")
    keys = tuple(ns.get("TABLE_FIELDS", ()))
    missing = [k for k in FORCE_SUMMARY_KEYS if k not in keys]
    if missing:
        raise ValueError(f"force table {name}: summary keys {missing} missing")
    n_lam = len(ns["TABLE_PIECES"])
    p = f"zs__f{name}"
    summary, init, deg = summary_c(p, ns, FORCE_SUMMARY_KEYS)
    out = [f"/* ---- force-free-end summary table '{name}' ---- */\n", summary]
    sizes = {"max_lamdeg": 2, "max_rows": 1, "max_sub": 1, "max_sum": max(2, deg)}
    tpieces = _history_c(name, p, ns, FORCE_TIME_PIECES, FORCE_HISTORY_KEYS, n_lam, out, sizes)
    out.append(f"static const zs__force_table zs__ftab_{name} = {{\n"
               f"    {init},\n    {{{', '.join(tpieces)}}}\n}};\n\n")
    return "".join(out), sizes
