"""The package's one chart style: a fixed look per model and method, math labels, units, fonts.

Every chart of zener-sym (the paper's figures, the benchmark charts, scene plots) draws with
:func:`style_for` and :func:`rc`, so a model has the same colour, marker and line in every chart
and every run, labels are math text in the paper's notation, times are in "µs", legends sit
outside the data and fonts stay readable at a journal's column width (3.5 in).

The colours are the Okabe-Ito palette (distinguishable with the common colour-vision
deficiencies), assigned by name, never by drawing order.
"""
from __future__ import annotations

import os
import zlib
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # matplotlib is the optional [plot] extra: imported when drawing, not here
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure, SubFigure
    from matplotlib.legend import Legend

__all__ = ["pyplot", "rc", "style_for", "label", "LABELS", "MODEL_STYLES", "METHOD_STYLES",
           "LAMBDA_COLORS",
           "COLUMN_WIDTH", "PAGE_WIDTH", "legend_outside", "save", "ERROR_LABEL", "error_label"]

#: Figure width of one journal column, in inches (the default width of the charts).
COLUMN_WIDTH: float = 3.5
#: Figure width of a full page, in inches.
PAGE_WIDTH: float = 7.2

_OI = {"black": "#000000", "orange": "#E69F00", "sky": "#56B4E9", "green": "#009E73",
       "yellow": "#F0E442", "blue": "#0072B2", "vermillion": "#D55E00", "purple": "#CC79A7",
       "grey": "#7F7F7F", "olive": "#999933", "wine": "#882255", "teal": "#44AA99"}

#: Model name -> (colour, marker, line style, legend label). The exact solution is the black
#: reference line; approximations are coloured and dashed/dotted so they stay apart in grey print.
MODEL_STYLES: dict[str, tuple[str, str, str | tuple[int, tuple[float, ...]], str]] = {
    "exact": (_OI["black"], "", "-", "exact (Eq. 10)"),
    "ham0": (_OI["blue"], "o", "--", "HAM 0th order"),
    "ham1": (_OI["vermillion"], "s", "-.", "HAM 1st order"),
    "hertz": (_OI["grey"], "h", ":", r"Hertz ($\lambda=0$)"),
    "hunter": (_OI["green"], "^", (0, (5, 1.5)), "Hunter (Eq. 52)"),
    "reed": (_OI["purple"], "v", (0, (3, 1, 1, 1, 1, 1)), "Reed (Eq. 53)"),
    "oneway": (_OI["sky"], "D", (0, (1, 1)), "one-way coupling"),
    "linear": (_OI["orange"], "P", (0, (6, 2)), "Mueller et al. (linear)"),
    "raman": (_OI["olive"], "X", (0, (2, 2)), "Raman (small $\\lambda$)"),
    "fits": (_OI["wine"], "*", (0, (4, 1, 1, 1)), "paper's fit (Eqs. 24, 55, 70, 80)"),
    "ham": ("#332288", "p", (0, (3, 1)), "HAM series, order $M$"),
    "series": ("#DDCC77", "H", (0, (3, 1, 1, 1)), r"$\lambda$-series / asymptotics"),
    # the sphere on a bounded plate, every contact (docs/finite_plates.md)
    "finite-plate": ("#117733", "o", "-", "finite plate (modes, every contact)"),
    # not a model: LAMMPS's hertz/material + viscoelastic contact, integrated (docs/lammps.md)
    "lammps": ("#CC6677", "8", (0, (5, 1, 1, 1)), "LAMMPS (hertz/material, viscoelastic)"),
    # not a model: the small-lambda form of the loss, Eq. (77), drawn in Fig. 14
    "fit77": (_OI["teal"], "d", (0, (1, 2)), "Eq. (77), small $\\lambda$"),
}

#: The lambda values of the paper's Figs. 5, 10, 11 -> colour, for charts whose curves are
#: lambda values rather than models (the convergence study).
LAMBDA_COLORS: dict[float, str] = {0.11: _OI["sky"], 1.01: _OI["orange"], 1.51: _OI["green"],
                 1.99: _OI["vermillion"]}

#: Integrator (solve_ivp method) -> (colour, marker) for the benchmark's solver families.
METHOD_STYLES: dict[str, tuple[str, str]] = {
    "DOP853": (_OI["teal"], "o"), "RK45": (_OI["sky"], "s"), "LSODA": ("#117733", "^"),
    "Radau": ("#332288", "D"), "BDF": ("#661100", "v"), "RK23": ("#AA4499", "<"),
}

_FALLBACK = ("#332288", "#117733", "#DDCC77", "#AA4499", "#88CCEE", "#661100", "#6699CC")
_FALLBACK_MARKERS = ("o", "s", "^", "v", "D", "P", "X")

#: Quantity -> math-text axis label (paper notation; dimensionless unless a unit is given).
LABELS: dict[str, str] = {
    "lam": r"$\lambda$", "tau": r"$\tau$", "t_us": r"$t$ (µs)", "delta": r"$\bar\delta$",
    "delta_m": r"$\bar\delta_m$", "delta_m_m32": r"$\bar\delta_m^{-3/2}$",
    "tau_d": r"$\tau_d$", "tau_dc": r"$\tau_{dc}$", "tau_dr": r"$\tau_{dr}$", "eta": r"$\eta$",
    "e": r"$e$", "F_m": r"$\bar F_m$", "force": r"$\bar F$", "force_N": r"$F$ (N)",
    "impulse": r"$\bar I(\tau_d)$", "impulse_history": r"$\bar I$",
    "velocity": r"$\bar V$", "deflection": r"$\bar w$", "int_F2": r"$\int_0^{\tau_d}\bar F^2\,d\tau$",
    "xi": r"$\xi$", "V0": r"$V_0$ (m/s)",
}

#: Lower-panel label of the comparison figures.
ERROR_LABEL: str = "rel. error"


def error_label(what: str = "") -> str:
    r"""The error axis label of the comparison figures, ``|q - q_exact| / q_exact`` by default.

    Parameters
    ----------
    what : str, optional
        A label of the caller's own; returned as given when not empty.

    Returns
    -------
    str
        Math text of the relative error (``what`` when given).

    Examples
    --------
    >>> from zener_sym.plot.style import error_label
    >>> print(error_label())
    $|q - q_{\rm exact}|\,/\,q_{\rm exact}$
    >>> error_label("rel. error of e")
    'rel. error of e'
    """
    return what or r"$|q - q_{\rm exact}|\,/\,q_{\rm exact}$"


def label(quantity: str) -> str:
    r"""Math-text axis label of a quantity, in the paper's notation (:data:`LABELS`).

    Parameters
    ----------
    quantity : str
        A field name such as ``"tau_d"``, ``"e"``, ``"lam"`` or ``"force_N"``.

    Returns
    -------
    str
        Its math-text label with the unit when it has one; ``quantity`` itself when unknown.

    Examples
    --------
    >>> from zener_sym.plot.style import label
    >>> print(label("tau_d"), label("t_us"))
    $\tau_d$ $t$ (µs)
    >>> label("my quantity")
    'my quantity'
    """
    return LABELS.get(quantity, quantity)


def _fallback(name: str) -> tuple[str, str]:
    i = zlib.crc32(name.encode())  # stable across runs and machines, unlike hash()
    return _FALLBACK[i % len(_FALLBACK)], _FALLBACK_MARKERS[(i // 7) % len(_FALLBACK_MARKERS)]


def style_for(name: str) -> dict[str, Any]:
    """Matplotlib keyword arguments (color, marker, linestyle, label) for a model or method.

    Parameters
    ----------
    name : str
        A model name (``"ham1"``), a model with options (``"exact backend=mpmath"``: the
        model's colour, hollow markers, dotted), or a benchmark family such as
        ``"exact, solve_ivp DOP853"`` (the integrator's colour) and ``"naive solve_ivp RK45"``
        (the integrator's colour, dashed, hollow). Unknown names get a colour fixed by the
        name (the same in every run and on every machine).

    Returns
    -------
    dict
        A new dict of ``color``, ``marker``, ``linestyle``, ``label`` (and ``markerfacecolor``
        for hollow markers), ready for ``ax.plot(x, y, **style_for(name))``; the caller may
        change it.

    Examples
    --------
    >>> from zener_sym.plot.style import style_for
    >>> style_for("exact")["color"]
    '#000000'
    >>> style_for("ham1")
    {'color': '#D55E00', 'marker': 's', 'linestyle': '-.', 'label': 'HAM 1st order'}
    >>> style_for("ham1")["color"] == style_for("ham1 backend=mpmath")["color"]
    True
    >>> style_for("naive solve_ivp RK45")["label"]
    'naive RK45'
    """
    base, _, opts = name.partition(" ")
    if base in MODEL_STYLES:
        color, marker, ls, lab = MODEL_STYLES[base]
        kw: dict[str, Any] = dict(color=color, marker=marker or None, linestyle=ls, label=lab)
        if opts:
            kw.update(linestyle=":", markerfacecolor="none", label=f"{lab}, {opts}")
        return kw
    for method, (color, marker) in METHOD_STYLES.items():
        if name.endswith("solve_ivp " + method):
            naive = name.startswith("naive")
            return dict(color=color, marker=marker, linestyle="--" if naive else "-",
                        markerfacecolor="none" if naive else color,
                        label=("naive " if naive else "") + method)
    color, marker = _fallback(name)
    return dict(color=color, marker=marker, linestyle="-", label=name)


def pyplot(headless: bool = False) -> ModuleType:
    """``matplotlib.pyplot``, imported lazily (it is the optional ``plot`` extra).

    Parameters
    ----------
    headless : bool, optional
        Select the Agg backend first (files only, no window), as the command line needs.

    Returns
    -------
    module
        ``matplotlib.pyplot``.

    Raises
    ------
    ImportError
        matplotlib is not installed; the message says which extra to install.

    Examples
    --------
    >>> from zener_sym.plot.style import pyplot
    >>> plt = pyplot(headless=True)
    >>> plt.__name__
    'matplotlib.pyplot'
    >>> plt.get_backend().lower()
    'agg'
    """
    try:
        import matplotlib
    except ImportError:
        raise ImportError("zener_sym.plot needs matplotlib, the optional [plot] extra: "
                          "pip install 'zener-sym[plot]'") from None
    if headless:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    module: ModuleType = plt  # a module to mypy also where matplotlib ships no type hints
    return module


#: rcParams of the style: 8 pt text at 3.5 in width, thin grids, no top/right spines.
RC: dict[str, Any] = {
    "font.size": 8, "axes.titlesize": 8, "axes.labelsize": 8, "xtick.labelsize": 7,
    "ytick.labelsize": 7, "legend.fontsize": 7, "legend.frameon": False,
    "axes.spines.top": False, "axes.spines.right": False, "axes.grid": True,
    "grid.alpha": 0.25, "grid.linewidth": 0.5, "lines.linewidth": 1.3, "lines.markersize": 4,
    "mathtext.fontset": "dejavusans", "figure.dpi": 100, "savefig.dpi": 200,
    "savefig.bbox": "tight", "savefig.pad_inches": 0.03, "axes.titleweight": "normal",
    "svg.hashsalt": "zener-sym", "pdf.compression": 6,
}


@contextmanager
def rc() -> Iterator[ModuleType]:
    """Context manager applying the package style (the rcParams :data:`RC`) while it is open.

    Returns
    -------
    contextlib.AbstractContextManager
        Entering it gives ``matplotlib.pyplot``; leaving it restores the caller's rcParams.

    Raises
    ------
    ImportError
        matplotlib is not installed.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from zener_sym.plot.style import rc
    >>> with rc() as plt:
    ...     fig, ax = plt.subplots()
    ...     size = plt.rcParams["font.size"]
    >>> size
    8.0
    >>> plt.close(fig)
    """
    plt = pyplot()
    with plt.rc_context(RC):
        yield plt


def legend_outside(fig_or_ax: Figure | SubFigure | Axes, handles: Sequence[Artist] | None = None,
                   labels: Sequence[str] | None = None, where: str = "bottom",
                   ncol: int | None = None) -> Legend:
    """A legend outside the data: below the figure, or below or right of an axes.

    Parameters
    ----------
    fig_or_ax : matplotlib.figure.Figure or matplotlib.axes.Axes
        A figure: the legend goes below it and collects the unique labels of all its axes
        (first occurrence; labels starting with ``_`` are skipped). An axes: the legend goes
        below it (``where="bottom"``) or right of it (any other ``where``).
    handles : sequence of matplotlib.artist.Artist, optional
        The artists to list (default: those with labels).
    labels : sequence of str, optional
        Their labels (with ``handles``).
    where : str, optional
        ``"bottom"`` (default) or e.g. ``"right"``, for an axes.
    ncol : int, optional
        Number of legend columns (default: up to 4 below a figure, 2 below an axes).

    Returns
    -------
    matplotlib.legend.Legend

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from zener_sym.plot.style import legend_outside, pyplot, style_for
    >>> plt = pyplot()
    >>> fig, (a, b) = plt.subplots(1, 2)
    >>> _ = a.plot([0, 1], [0, 1], **style_for("exact"))
    >>> _ = b.plot([0, 1], [1, 0], **style_for("exact"))
    >>> _ = b.plot([0, 1], [1, 1], **style_for("ham0"))
    >>> [t.get_text() for t in legend_outside(fig).get_texts()]
    ['exact (Eq. 10)', 'HAM 0th order']
    >>> bool(legend_outside(a, where="right").get_bbox_to_anchor().x0 > a.bbox.x1)  # right of a
    True
    >>> plt.close(fig)
    """
    from matplotlib.figure import FigureBase  # a Figure or a SubFigure: every axes' legend

    if isinstance(fig_or_ax, FigureBase):
        fig = fig_or_ax
        if handles is None:
            seen: dict[str, Artist] = {}
            for ax in fig.axes:
                for h, lab in zip(*ax.get_legend_handles_labels()):
                    if not lab.startswith("_") and lab not in seen:
                        seen[lab] = h
            labels, handles = list(seen), list(seen.values())
        elif labels is None:  # handles alone: their own labels, as an axes' legend takes them
            labels = [str(h.get_label()) for h in handles]
        n = ncol or min(len(labels), 4)
        return fig.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                          ncol=max(n, 1), frameon=False)
    ax = fig_or_ax
    if where == "bottom":
        return ax.legend(handles=handles, labels=labels, loc="upper center",
                         bbox_to_anchor=(0.5, -0.22), ncol=ncol or 2, frameon=False) \
            if handles is not None else ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.22),
                                                  ncol=ncol or 2, frameon=False)
    return ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False)


_METADATA: dict[str, dict[str, None]] = {
    "png": {"Software": None},
    "pdf": {"CreationDate": None, "ModDate": None, "Producer": None, "Creator": None},
    "svg": {"Date": None, "Creator": None}}


def save(fig: Figure, path: str | os.PathLike[str],
         formats: Sequence[str] = ("png",)) -> list[Path]:
    """Save ``fig`` once per format, without time stamps or version strings in the metadata.

    The files of a chart are then byte-identical from run to run (the committed charts are
    checked for freshness).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str or os.PathLike
        The file name; its suffix is replaced by each format's.
    formats : sequence of str, optional
        Formats matplotlib writes, e.g. ``("png", "pdf", "svg")`` (default png only).

    Returns
    -------
    list of pathlib.Path
        The written files, in the order of ``formats``.

    Raises
    ------
    ValueError
        A format matplotlib does not write (its message lists those it does).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import tempfile
    >>> from pathlib import Path
    >>> from zener_sym.plot.style import pyplot, save
    >>> plt = pyplot()
    >>> fig, ax = plt.subplots()
    >>> _ = ax.plot([0, 1], [0, 1])
    >>> folder = Path(tempfile.mkdtemp())
    >>> [p.name for p in save(fig, folder / "chart", ("png", "svg"))]
    ['chart.png', 'chart.svg']
    >>> b"<dc:date>" in (folder / "chart.svg").read_bytes()
    False
    >>> plt.close(fig)
    """
    path = Path(path)
    out = []
    for fmt in formats:
        p = path.with_suffix("." + fmt)
        fig.savefig(p, format=fmt, metadata=_METADATA.get(fmt))
        out.append(p)
    return out
