"""The one Chebyshev-table engine offline: sampling, fitting, trimming, the text of a generated
table and the comparison of a rebuild with it.

A table is a :class:`~.cheb_table.TableSpec` (its pieces, fields, points per piece, trimming
level, ``--check`` tolerance) and a sample function: ``sample(piece index, lambdas)`` gives
each lambda's data, the stored summary values by field name and, for a table with a history, per
``(time piece, field)`` the samples [sub-piece, point] (with ``(time piece, "delta")`` the
weights, see :func:`history_coefficients`). :func:`build_tables` samples it at
the Chebyshev points of every piece and fits the series. The plate's end of contact
(``exact.table_build``), the force-free end (``exact.force_table_build``) and the ham1 summary
(``ham.table_build``) are configurations of it; tests/test_cheb_table.py builds a new one.

The text helpers write what :mod:`.cheb_table` reads back; :func:`render_history` writes a
coefficient matrix given as a string verbatim, so a table can be re-rendered from its committed
numbers (:func:`stored_tables`) when only its text changes.
"""
from __future__ import annotations

import dataclasses
import textwrap
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any, TypedDict

import numpy as np

from ..typing import FloatArray
from .cheb_table import Pieces, TableSpec, spec_assignments, spec_of
from .cheb_table_history import history_assignments, parse_array
from .chebyshev import cheb_coefficients, cheb_nodes, coefficient_difference, trim_trailing

__all__ = ["NodeData", "Tables", "TableFile", "HistorySettings", "TableBuilder", "piece_nodes",
           "sub_nodes", "fit", "build_tables", "history_coefficients", "format_quantised",
           "render_summary", "render_history", "table_lines", "table_module", "stored_tables",
           "compare"]

#: One lambda node's data: summary values by name, and per (time piece, field) the history
#: samples [sub-piece, point] (with (time piece, "delta") the sub-pieces' weights).
NodeData = dict[str | tuple[str, str], Any]
#: ``sample(piece index, lambda nodes)``: each node's data.
SampleFunction = Callable[[int, FloatArray], Sequence[NodeData]]


class Tables(TypedDict, total=False):
    """A built (or stored) table: what :func:`build_tables` returns and the renderers write."""

    #: field -> per lambda piece one 1-D Chebyshev series
    summary: dict[str, list[FloatArray]]
    #: (time piece, field) -> per lambda piece one [time degree, lambda degree] matrix per
    #: sub-piece (an array, or its "rows cols v..." string as stored; an empty tuple where the
    #: piece has no such time piece)
    history: dict[tuple[str, str], list[tuple[Any, ...]]]
    #: the same keys: per lambda piece the sub-pieces' weights
    weights: dict[tuple[str, str], list[tuple[float, ...]]]
    #: the description the table was built from
    spec: TableSpec


def piece_nodes(kind: str, a: float, b: float, n: int) -> FloatArray:
    """The lambda nodes of a piece: Chebyshev points of the first kind in its variable.

    Parameters
    ----------
    kind : str
        The piece's variable (``cheb_table.PIECE_KINDS``).
    a, b : float
        The piece's ends in lambda.
    n : int
        Number of points.

    Returns
    -------
    ndarray
        The n lambda values, inside (a, b), in the order of the points (descending x).

    Examples
    --------
    >>> from zener_sym.numerics.cheb_table_build import piece_nodes
    >>> [round(float(x), 6) for x in piece_nodes("log", 1.0, 100.0, 2)]  # ln-lambda midpoints
    [50.945612, 1.962878]
    """
    x = cheb_nodes(n)
    if kind == "lam":
        nodes: FloatArray = a + (b - a) * (x + 1.0) / 2.0
        return nodes
    p = Pieces([(kind, a, b)])
    ga, gb = float(p.ga[0]), float(p.gb[0])
    g = ga + (gb - ga) * (x + 1.0) / 2.0
    if kind == "log":
        nodes = np.exp(g)
    elif kind == "sqrt_lam":
        nodes = g * g
    else:
        nodes = a + g * g
    return nodes


def sub_nodes(n_sub: int, n_time: int) -> FloatArray:
    """Reduced times y in [0, 1] of the Chebyshev points of every sub-piece of a time piece cut
    into ``n_sub`` equal parts (y in [j/K, (j+1)/K] maps to x in [-1, 1]).

    Parameters
    ----------
    n_sub : int
        Sub-pieces K.
    n_time : int
        Points per sub-piece.

    Returns
    -------
    ndarray
        [sub-piece, point].
    """
    x = cheb_nodes(n_time)
    return (np.arange(n_sub)[:, None] + (x[None, :] + 1.0) / 2.0) / n_sub


def fit(values: Sequence[float] | FloatArray, trim: float) -> FloatArray:
    """The Chebyshev coefficients through values at Chebyshev points, trimmed where the trailing
    ones fall below ``trim`` of the largest.

    Parameters
    ----------
    values : array_like
        Values at ``cheb_nodes(n)``.
    trim : float
        Relative trimming level.

    Returns
    -------
    ndarray
        The kept coefficients.
    """
    c = cheb_coefficients(np.asarray(values, dtype=float))
    return trim_trailing(c, np.abs(c) > trim * np.abs(c).max())


def history_coefficients(data: Sequence[NodeData], key: tuple[str, str], trim: float,
                         weight: Callable[[Sequence[NodeData], tuple[str, str]], FloatArray],
                         ) -> tuple[tuple[FloatArray, ...], tuple[float, ...]]:
    """One lambda piece's history series of ``key`` = (time piece, field) from its node data.

    Parameters
    ----------
    data : sequence of dict
        The piece's node data, one per lambda node.
    key : tuple of str
        (time piece, field).
    trim : float
        A trailing row or column is dropped when each of its coefficients, times the
        sub-piece's weight, is below this.
    weight : callable(data, key) -> ndarray
        Per sub-piece the scale a coefficient moves the field by.

    Returns
    -------
    tuple
        Per sub-piece one [time degree, lambda degree] Chebyshev matrix, and the weights.
    """
    vals = np.array([d[key] for d in data])  # [lambda node, sub, time node]
    c = cheb_coefficients(cheb_coefficients(vals, axis=2), axis=0)
    wt = np.asarray(weight(data, key), dtype=float)
    mats = tuple(trim_trailing(c[:, j, :].T, np.abs(c[:, j, :].T) * wt[j] > trim)
                 for j in range(c.shape[1]))
    return mats, tuple(float(x) for x in wt)


def build_tables(spec: TableSpec, sample: SampleFunction,
                 history: "HistorySettings | None" = None) -> Tables:
    """Sample at the Chebyshev points of every piece of ``spec`` and fit the series.

    Parameters
    ----------
    spec : TableSpec
        The description.
    sample : callable(piece index, lambdas) -> sequence of dict
        Each node's data (``NodeData``), in the order of the lambdas.
    history : HistorySettings, optional
        The history's series, trimming and weights (none: a summary-only table). A piece
        whose nodes give no such key gets an empty entry.

    Returns
    -------
    Tables
        summary, history, weights and the spec.

    Raises
    ------
    RuntimeError
        A node gave a non-finite summary value.
    """
    keys = history.keys if history is not None else ()
    summary: dict[str, list[FloatArray]] = {k: [] for k in spec.fields}
    mats: dict[tuple[str, str], list[tuple[Any, ...]]] = {k: [] for k in keys}
    weights: dict[tuple[str, str], list[tuple[float, ...]]] = {k: [] for k in keys}
    for p, ((kind, a, b), n) in enumerate(zip(spec.pieces, spec.nodes)):
        data = list(sample(p, piece_nodes(kind, a, b, n)))
        for k in spec.fields:
            v = np.array([d[k] for d in data], dtype=float)
            if not np.all(np.isfinite(v)):
                raise RuntimeError(f"table build: a non-finite {k} on the piece [{a}, {b}]")
            summary[k].append(fit(v, spec.trim))
        for key in keys:
            if key not in data[0]:
                mats[key].append(())
                weights[key].append(())
                continue
            assert history is not None
            m, wts = history_coefficients(data, key, history.trim, history.weight)
            mats[key].append(m)
            weights[key].append(wts)
    out: Tables = {"summary": summary, "spec": spec}
    if history is not None:
        out["history"], out["weights"] = mats, weights
    return out


def _floats(values: Iterable[float], digits: int) -> str:
    return "(" + ", ".join(f"{float(v):.{digits}g}" for v in values) + ",)"


def format_quantised(a: FloatArray, quantum: float) -> str:
    """A 2-D array as the string "rows cols v v ...", each number with the digits that resolve
    ``quantum`` (at most 16). A string rather than a tuple literal: Python compiles a module of
    80 000 float literals in about a second (every process, where bytecode is not cached),
    numpy parses the strings in milliseconds (``cheb_table.parse_array``).

    Parameters
    ----------
    a : ndarray
        [rows, cols].
    quantum : float
        Numbers below it are written as 0.

    Returns
    -------
    str
    """
    def one(value: float) -> str:
        v = float(value)
        if abs(v) < quantum:
            return "0"
        n = int(np.clip(np.floor(np.log10(abs(v))) - np.floor(np.log10(quantum)) + 1, 1, 16))
        return f"{v:.{n}g}"

    return f"{a.shape[0]} {a.shape[1]} " + " ".join(one(v) for v in a.ravel())


def render_summary(name: str, summary: Mapping[str, Sequence[Any]], fields: Sequence[str],
                   digits: int) -> list[str]:
    """``NAME = {field: (one coefficient tuple per piece, ...), ...}`` lines.

    Parameters
    ----------
    name : str
        The assigned name (``SUMMARY`` in every generated table).
    summary : mapping
        field -> per piece a 1-D series.
    fields : sequence of str
        The order written.
    digits : int
        Significant digits per coefficient.

    Returns
    -------
    list of str
    """
    lines = [f"{name} = {{"]
    for k in fields:
        lines.append(f"    {k!r}: (")
        lines += ["        " + _floats(c, digits) + "," for c in summary[k]]
        lines.append("    ),")
    return lines + ["}"]


def render_history(history: Mapping[tuple[str, str], Sequence[Sequence[Any]]],
                   weights: Mapping[tuple[str, str], Sequence[Sequence[float]]],
                   quantum: float) -> list[str]:
    """``HISTORY = {(time piece, field): per piece (per sub-piece one string, ...), ...}`` lines;
    each matrix quantised to ``quantum`` divided by its weight (a string is written verbatim).

    Parameters
    ----------
    history, weights : mapping
        As in ``Tables`` (weights may lack a key whose matrices are all strings).
    quantum : float
        The rounding level on the field's scale.

    Returns
    -------
    list of str
    """
    lines = ["HISTORY = {"]
    for key in sorted(history):
        lines.append(f"    {key!r}: (")
        for p, subs in enumerate(history[key]):
            wts = weights[key][p] if key in weights else (1.0,) * len(subs)
            lines.append("        (")
            lines += [f"            "
                      f"{(c if isinstance(c, str) else format_quantised(c, quantum / wt))!r},"
                      for c, wt in zip(subs, wts)]
            lines.append("        ),")
        lines.append("    ),")
    return lines + ["}"]


def table_lines(t: Tables, spec: TableSpec, head: Sequence[str], summary_note: str,
                history: "HistorySettings | None" = None) -> list[str]:
    """The body of a generated table module: ``head`` (a layout of its own), the description
    (``TABLE_*``), for a table with a history its description (``history_assignments``), the
    summary series (``SUMMARY``) and the history (``HISTORY``).

    Parameters
    ----------
    t : Tables
        The built or stored table.
    spec : TableSpec
        Its description.
    head : sequence of str
        Lines written first.
    summary_note : str
        The comment above the summary.
    history : HistorySettings, optional
        The history's description, rounding and comment.

    Returns
    -------
    list of str
    """
    lines = [*head, *spec_assignments(spec)]
    if history is not None:
        lines += [*history_assignments(history.time_pieces, history.fields, history.n_sub,
                                       history.hi)]
    lines += ["", f"#: {summary_note}",
              *render_summary("SUMMARY", t["summary"], spec.fields, spec.digits)]
    if "history" in t and history is not None:
        lines += ["", *history.note,
                  *render_history(t["history"], t.get("weights", {}), history.quantum)]
    return lines


@dataclasses.dataclass(frozen=True)
class TableFile:
    """A generated table module's own words: where it lives, the command that rebuilds it, what
    its docstring says and the comment above its summary (a :class:`TableBuilder` holds one).

    Attributes
    ----------
    filename : str
        The file under generated/.
    artefact : str
        Its name for ``zener-sym regen``.
    title : str
        The first line of its docstring.
    provenance : str
        How its numbers were obtained; ``{scipy}`` stands for scipy's version.
    summary_note : str
        The comment above the summary (:func:`table_lines`).
    """

    filename: str
    artefact: str
    title: str
    provenance: str
    summary_note: str = "field -> one tuple of Chebyshev coefficients per lambda piece"

    @property
    def command(self) -> str:
        """The ``zener-sym`` sub-command that rebuilds the file."""
        return f"regen {self.artefact}"

    def words(self, scipy_version: str = "") -> tuple[str, str, str]:
        """(title, command, provenance) of the module's docstring."""
        return self.title, self.command, self.provenance.format(scipy=scipy_version)


#: ``weight(a lambda piece's node data, (time piece, field))``: per sub-piece the scale a
#: history coefficient moves its field by (``history_coefficients``).
WeightFunction = Callable[[Sequence[NodeData], tuple[str, str]], FloatArray]


@dataclasses.dataclass(frozen=True)
class HistorySettings:
    """A table's history in one place: its description (written into the file and read back
    by the runtime's :class:`~.cheb_table_history.History`), how its series are trimmed,
    weighed, rounded and compared, and the comment above them in the file.

    Attributes
    ----------
    time_pieces : tuple of str
        The time pieces, in the order of time.
    fields : tuple of str
        The two stored fields of every time piece (the pair the runtime evaluates together).
    n_sub : dict
        Sub-pieces (equal parts of the reduced time) per time piece.
    hi : float
        The history covers the lambda pieces that end by this.
    trim : float
        ``history_coefficients``' trimming level; a rebuilt coefficient that moves its field by
        less than this also passes ``compare`` (its floor).
    quantum : float
        The written coefficients' rounding level on the field's scale (``render_history``).
    weight : callable
        Per sub-piece the scale a coefficient moves its field by (:data:`WeightFunction`).
    note : tuple of str
        The comment lines above the history.
    """

    time_pieces: tuple[str, ...]
    fields: tuple[str, str]
    n_sub: dict[str, int]
    hi: float
    trim: float
    quantum: float
    weight: WeightFunction
    note: tuple[str, ...] = ()

    @property
    def keys(self) -> tuple[tuple[str, str], ...]:
        """The (time piece, field) series, in the order they are built."""
        return tuple((p, k) for p in self.time_pieces for k in self.fields)


def _no_lines(spec: TableSpec) -> list[str]:
    return []


@dataclasses.dataclass(frozen=True)
class TableBuilder:
    """One generated table, offline: its description, its file's words, its node function, its
    history and its inputs' hash; it builds, renders, reads back and compares the table (each table
    of the package is one: ``exact.table_build.BUILDER``, ``exact.force_table_build.BUILDER``,
    ``ham.table_build.BUILDER``; ``artefacts`` and the table commands use only these methods).

    Attributes
    ----------
    spec : TableSpec or callable
        The description, or a function that finds it at build time (ham1's last piece starts at
        a root found then).
    file : TableFile
        The file's words.
    sample : callable(piece index, lambdas) -> sequence of dict
        Each node's data (:data:`SampleFunction`).
    digest : callable() -> str
        The inputs hash of the sources the table is built from (``codegen.inputs_hash`` of the
        builder's input files; the engine, a leaf helper, does not import codegen).
    history : HistorySettings, optional
        The history (none: a summary-only table).
    head : callable(spec) -> list of str
        Lines written before the description (a table's own layout).
    tail : tuple of str
        Lines written last.
    """

    spec: TableSpec | Callable[[], TableSpec]
    file: TableFile
    sample: SampleFunction
    digest: Callable[[], str]
    history: HistorySettings | None = None
    head: Callable[[TableSpec], list[str]] = _no_lines
    tail: tuple[str, ...] = ()

    def description(self) -> TableSpec:
        """The table's :class:`~.cheb_table.TableSpec` (found now when ``spec`` is a function)."""
        return self.spec if isinstance(self.spec, TableSpec) else self.spec()

    def build(self) -> Tables:
        """Sample every piece and fit the series (:func:`build_tables`).

        Returns
        -------
        Tables
            summary, spec and, with a history, history and weights.
        """
        return build_tables(self.description(), self.sample, self.history)

    def render(self, tables: Mapping[str, Any] | None = None) -> str:
        """The generated module's text.

        Parameters
        ----------
        tables : mapping, optional
            Built tables, or the committed ones in any form ``as_tables`` reads (re-rendered
            with their own numbers); default: :meth:`build` now.

        Returns
        -------
        str
        """
        import scipy

        t = self.build() if tables is None else self.as_tables(tables)
        spec = t["spec"]
        body = [*table_lines(t, spec, self.head(spec), self.file.summary_note, self.history),
                *self.tail]
        return table_module(*self.file.words(scipy.__version__), self.digest(), body)

    def as_tables(self, t: Mapping[str, Any]) -> Tables:
        """A table in any of its forms as ``Tables``: already one (it has ``spec``), the
        generated module's names (with its ``TABLE_*`` description), or ``{"summary": ...,
        "history": ...}`` (strings or bare arrays, weights optional) with this builder's
        description.

        Parameters
        ----------
        t : mapping
            The table.

        Returns
        -------
        Tables
        """
        if "spec" in t:
            return dict(t)  # type: ignore[return-value]
        if "TABLE_PIECES" in t:
            return stored_tables(t)
        out: Tables = {"spec": self.description(), "summary": dict(t["summary"])}
        for key in ("history", "weights"):
            if key in t:
                out[key] = dict(t[key])
        return out

    def compare(self, stored: Mapping[str, Any], fresh: Mapping[str, Any]) -> list[str]:
        """Differences beyond the description's ``check_rtol`` between two tables (any form
        ``as_tables`` reads): :func:`compare` with the history's settings.

        Returns
        -------
        list of str
            Readable lines, one per difference (empty: they agree).
        """
        return compare(self.as_tables(stored), self.as_tables(fresh), self.history)


def table_module(title: str, command: str, provenance: str, digest: str,
                 body: Iterable[str]) -> str:
    """A generated table module: a docstring (``title``, the do-not-edit line naming
    ``zener-sym <command>`` with ``provenance`` wrapped after it, the inputs hash), then
    ``INPUTS_HASH`` and the ``body`` lines.

    Parameters
    ----------
    title : str
        First line of the module docstring.
    command : str
        The ``zener-sym`` sub-command that rebuilds the table.
    provenance : str
        How the data were obtained (wrapped at 100 columns).
    digest : str
        The builder's inputs hash (:func:`zener_sym.codegen.inputs_hash`).
    body : iterable of str
        The module's lines after ``INPUTS_HASH``.

    Returns
    -------
    str
        The module text, ending with a newline.
    """
    note = textwrap.fill(f"GENERATED by `zener-sym {command}`: DO NOT EDIT. {provenance}", 100)
    lines = [f'"""{title}', "", note, "", f"Inputs hash: {digest}", '"""',
             f"INPUTS_HASH = {digest!r}", *body]
    return "\n".join(lines) + "\n"


def stored_tables(ns: Mapping[str, Any]) -> Tables:
    """A committed table module's numbers as ``Tables`` (history matrices as their strings), for
    :func:`compare` and for re-rendering with the committed numbers.

    Parameters
    ----------
    ns : mapping
        The module's globals.

    Returns
    -------
    Tables
    """
    spec = spec_of(ns)
    out: Tables = {"spec": spec, "summary": {k: [np.asarray(c, dtype=float) for c in v]
                                             for k, v in ns["SUMMARY"].items()}}
    if "HISTORY" in ns:
        out["history"] = {k: [tuple(subs) for subs in v] for k, v in ns["HISTORY"].items()}
    return out


def _matrices(entries: Sequence[Any]) -> list[FloatArray]:
    """Per (piece, sub-piece) one array, flattened (strings parsed; empty pieces skipped)."""
    out: list[FloatArray] = []
    for subs in entries:
        out.extend(parse_array(c) if isinstance(c, str) else np.asarray(c, dtype=float)
                   for c in subs)
    return out


def compare(stored: Tables, fresh: Tables, history: "HistorySettings | None" = None) -> list[str]:
    """Differences beyond the fresh spec's ``check_rtol`` between a stored and a rebuilt table.

    Parameters
    ----------
    stored, fresh : Tables
        The committed table (``stored_tables``) and the rebuilt one (``build_tables``).
    history : HistorySettings, optional
        The history's settings: a history coefficient change that moves its field by less
        than its ``trim`` (on the field's scale: divided by the sub-piece's weight) passes too.
        Without them every change counts.

    Notes
    -----
    A summary series that is identically zero in both tables agrees by rule: a relative
    difference would be 0/0 there. Such a series is one a table stores as 0 where it does not
    use it (the force-free end's ``log_tau_p`` on its ln-lambda pieces); a zero series against
    a nonzero one is still a difference.

    Returns
    -------
    list of str
        Readable lines, one per difference (empty: they agree).
    """
    spec, old_spec = fresh["spec"], stored["spec"]
    rtol = spec.check_rtol
    bad: list[str] = []
    kinds = [k for k, _, _ in spec.pieces]
    if [k for k, _, _ in old_spec.pieces] != kinds or any(
            abs(a - b) > rtol * max(abs(b), 1.0) for a, b in zip(old_spec.edges, spec.edges)):
        return [f"pieces {old_spec.pieces!r} != rebuilt {spec.pieces!r}"]
    for k in spec.fields:
        if k not in stored["summary"]:
            bad.append(f"summary {k}: missing from the stored table")
            continue
        for p, (c_new, c_old) in enumerate(zip(fresh["summary"][k], stored["summary"][k])):
            if not np.any(c_new) and not np.any(c_old):
                continue  # both identically zero: no relative difference to take
            with np.errstate(divide="ignore"):  # a zero series against a nonzero one: inf
                err = coefficient_difference(c_new, c_old)
            if not err <= rtol:
                bad.append(f"summary {k} lambda piece {p}: relative difference {err:.2e} > "
                           f"{rtol:g}")
    for key, entries in fresh.get("history", {}).items():
        new, old = _matrices(entries), _matrices(stored.get("history", {}).get(key, []))
        if len(new) != len(old):
            bad.append(f"history {key}: {len(new)} arrays, the stored table has {len(old)}")
            continue
        # without weights (a table given as bare arrays) every change counts
        wts = [w for subs in fresh.get("weights", {}).get(key, []) for w in subs]
        floor = history.trim if history is not None else 0.0
        floors = [floor / w / rtol for w in wts] or [0.0] * len(new)
        for i, (c_new, c_old, floor) in enumerate(zip(new, old, floors)):
            err = coefficient_difference(c_new, c_old, floor)
            if not err <= rtol:
                bad.append(f"history {key} array {i}: relative difference {err:.2e} > {rtol:g}")
    return bad
