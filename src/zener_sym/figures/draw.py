"""Draw one of the paper's figures from its data rows, in the package style.

Layout: one column of panels per ``FigureSpec.panels`` entry (four panels: two by two); each
comparison panel has a lower axis with the error of every curve against the exact solution
(log scale). The legend sits below the figure, outside the data.
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from types import ModuleType
from typing import TYPE_CHECKING, Any

import numpy as np

from ..plot import style as st
from ..typing import FloatArray
from .data import FigureSpec, Row

if TYPE_CHECKING:  # matplotlib is the optional [plot] extra, imported only by pyplot()
    from matplotlib.figure import Figure

__all__ = ["draw"]

_ERR_FLOOR = 1e-12  # errors below it (round-off, or both curves 0 after contact) are not drawn
_ERR_LABEL = {"rel": r"$|q-q_{\rm exact}|/q_{\rm exact}$",
              "max": r"$|q-q_{\rm exact}|/\max|q_{\rm exact}|$"}


def _series(rows: Iterable[Row],
            panel: str) -> dict[str, tuple[FloatArray, FloatArray, FloatArray]]:
    """The curves of one panel: series -> (x, y, error), a missing error as NaN."""
    out: dict[str, tuple[list[float], list[float], list[float]]] = {}
    for p, s, x, y, e in rows:
        if p == panel:
            out.setdefault(s, ([], [], []))
            out[s][0].append(x)
            out[s][1].append(y)
            out[s][2].append(np.nan if e is None else e)
    return {s: (np.array(xs[0]), np.array(xs[1]), np.array(xs[2])) for s, xs in out.items()}


def _style(name: str, n: int, labels: Mapping[str, str] | None = None) -> dict[str, Any]:
    """Line keywords of series ``name`` (package style), with this figure's legend label."""
    kw = st.style_for(name)
    if labels and name in labels:
        kw["label"] = labels[name]
    if kw.get("marker"):
        kw["markevery"] = 0.1  # evenly spaced along the drawn curve, whatever the grid
    return kw


def draw(spec: FigureSpec, rows: Sequence[Row], plt: ModuleType) -> Figure:
    """A matplotlib Figure of ``spec`` from ``rows`` (``plt`` is pyplot under the style's rc)."""
    panels = spec.panels
    n = len(panels)
    ncol = 2 if n == 4 else n
    nrow = 2 if n == 4 else 1
    has_err = bool(spec.error_def)
    width = st.COLUMN_WIDTH if n == 1 else st.PAGE_WIDTH
    main_h = 2.0 if n == 1 else 1.9
    ratios = ([3, 1.3] if has_err else [1]) * nrow
    height = sum(ratios) / (4.3 if has_err else 1) * main_h + 0.2 * nrow
    fig: Figure = plt.figure(figsize=(width, height), layout="constrained")
    gs = fig.add_gridspec(len(ratios), ncol, height_ratios=ratios)
    per = 2 if has_err else 1
    for i, panel in enumerate(panels):
        r, c = divmod(i, ncol)
        ax = fig.add_subplot(gs[per * r, c])
        axe = fig.add_subplot(gs[per * r + 1, c], sharex=ax) if has_err else None
        data = _series(rows, panel)
        emin, emax = np.inf, 0.0
        for name, (x, y, e) in data.items():
            ax.plot(x, y, **_style(name, x.size, spec.labels))
            e = np.where(e > _ERR_FLOOR, e, np.nan)
            if axe is not None and name != "exact" and np.isfinite(e).any():
                kw = _style(name, x.size, spec.labels)
                kw["label"] = "_" + kw["label"]
                axe.plot(x, e, **kw)
                emin, emax = min(emin, np.nanmin(e)), max(emax, np.nanmax(e))
        title = spec.panel_titles.get(panel, panel)
        if n > 1:
            ax.set_title(f"{'ABCD'[i]})  {title}", loc="left")
        if spec.xlog:
            from matplotlib.ticker import FormatStrFormatter

            ax.set_xscale("log")
            ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
        if spec.ylog:
            from matplotlib.ticker import FormatStrFormatter

            from matplotlib.ticker import NullFormatter

            ax.set_yscale("log")
            ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
            lo, hi = ax.get_ylim()
            # label the minor ticks only when the axis has too few decades to show a major one
            # (over several decades they would overprint each other)
            ax.yaxis.set_minor_formatter(FormatStrFormatter("%g") if hi / lo < 20 else NullFormatter())
        ylab = st.label(spec.y)
        if spec.number == 8:
            ylab = st.label("tau_dc" if panel == "compression" else "tau_dr")
        if c == 0 or spec.number == 8:
            ax.set_ylabel(ylab)
        if axe is not None:
            axe.set_yscale("log")
            if emax > 0:
                # whole decades around the data, at least two, so small errors stay visible
                # at most five decades below the largest error: the dips to 0 at tau = 0 or
                # at crossings would otherwise squeeze the curves into the top of the panel
                hi = 10.0 ** np.ceil(np.log10(emax * 1.01))
                lo = 10.0 ** np.floor(np.log10(max(emin, 1e-10)))
                axe.set_ylim(min(max(lo, hi * 1e-5), hi / 100.0), hi)
            if c == 0:
                axe.set_ylabel(_ERR_LABEL[spec.error_def], fontsize=6)
            plt.setp(ax.get_xticklabels(), visible=False)
            axe.set_xlabel(st.label(spec.x))
        else:
            ax.set_xlabel(st.label(spec.x))
    st.legend_outside(fig)
    return fig
