"""The chart of a fitted dissipative constant (:func:`zener_sym.fit_dissipation`): measured e
against v0 with the fitted curve and the band of A's confidence interval, and the residuals
below. Drawn in the package style; matplotlib is imported only when drawing."""
from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

import numpy as np

from ..typing import FloatArray
from . import style as _st

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["fit_chart"]


class FittedDissipation(Protocol):
    """What :func:`fit_chart` reads of a fit: a :class:`~zener_sym.scene.calibrate.DissipationFit`
    has it all. (A protocol rather than that class: the scene layer draws its fits with this
    module, so naming the class here would close an import cycle.)"""

    @property
    def A(self) -> float: ...  # the fitted dissipative constant [s]

    @property
    def v0(self) -> FloatArray: ...  # measured impact speeds [m/s]

    @property
    def e(self) -> FloatArray: ...  # measured coefficients of restitution

    @property
    def sigma(self) -> FloatArray | None: ...  # their standard errors, if given

    @property
    def residuals(self) -> FloatArray: ...  # e - e_fit at each point

    @property
    def confidence(self) -> float: ...  # level of A's interval, e.g. 0.95

    def predict(self, v0: FloatArray) -> Mapping[str, float | FloatArray]:
        """Fitted ``"e"`` and its interval ``"e_low"``, ``"e_high"`` at the speeds ``v0``
        (arrays here; a fit gives floats for one speed)."""
        ...


def _speed_grid(v0: FloatArray, n: int = 200) -> FloatArray:
    lo, hi = float(v0.min()), float(v0.max())
    if hi == lo:
        lo, hi = lo / 2.0, hi * 2.0
    return np.geomspace(lo / 1.15, hi * 1.15, n)


def _sci(x: float) -> str:
    """Math text of x to 3 digits: 1.26e-04 -> 1.26 x 10^-4."""
    mant, _, exp = f"{x:.2e}".partition("e")
    return rf"${mant}\times10^{{{int(exp)}}}$"


def fit_chart(fit: FittedDissipation, path: str | os.PathLike[str] | None = None,
              title: str | None = None, data_label: str = "measured") -> Figure:
    r"""Draw a fitted dissipative constant: e(v0) above, the residuals e - e_fit below.

    The upper panel has the measured points (with error bars when sigma was given), the fitted
    curve and the band of A's confidence interval; the legend sits below the figure.

    Parameters
    ----------
    fit : DissipationFit
        A fit of :func:`zener_sym.fit_dissipation` (its ``plot`` method calls this), or any
        object with the attributes of :class:`FittedDissipation`.
    path : str or os.PathLike, optional
        Where to save the chart (its suffix picks the format: png, pdf, svg); not saved when
        omitted. Saving selects matplotlib's file-only Agg backend.
    title : str, optional
        Title of the upper panel.
    data_label : str, optional
        Legend entry of the points (default ``"measured"``).

    Returns
    -------
    matplotlib.figure.Figure
        The figure, two axes: e(v0) and the residuals.

    Raises
    ------
    ImportError
        matplotlib (the ``plot`` extra) is not installed.
    ValueError
        The suffix of ``path`` is a format matplotlib does not write.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import zener_sym as zs
    >>> from zener_sym.plot.calibration import fit_chart
    >>> fit = zs.fit_dissipation("glass", "1 mm", 1e-5, v0=[0.5, 1.0, 2.0], e=[0.82, 0.80, 0.77],
    ...                          wall="steel")
    >>> fig = fit_chart(fit, title="glass on steel")
    >>> [ax.get_ylabel() for ax in fig.axes]
    ['$e$', '$e - e_{\\rm fit}$']
    >>> [t.get_text() for t in fig.legends[0].get_texts()]
    ['95% interval of $A$', 'fit, $A$ = $2.40\\times10^{-7}$ s', 'measured']
    """
    plt = _st.pyplot(headless=path is not None)
    grid = _speed_grid(fit.v0)
    pred = fit.predict(grid)
    log_x = fit.v0.max() / fit.v0.min() > 10.0
    exact = _st.style_for("exact")
    data_color = _st.style_for("linear")["color"]
    with plt.rc_context(_st.RC):
        fig: Figure
        fig, (ax, axr) = plt.subplots(2, 1, figsize=(_st.COLUMN_WIDTH, 3.6), sharex=True,
                                      height_ratios=(2.2, 1.0), layout="constrained")
        ax.fill_between(grid, pred["e_low"], pred["e_high"], color=exact["color"], alpha=0.15,
                        linewidth=0, label=f"{fit.confidence:.0%} interval of $A$")
        ax.plot(grid, pred["e"], color=exact["color"], linestyle="-",
                label=f"fit, $A$ = {_sci(fit.A)} s")
        err = fit.sigma
        ax.errorbar(fit.v0, fit.e, yerr=err, fmt="o", color=data_color, markersize=3.5,
                    elinewidth=0.8, capsize=1.5, label=data_label)
        ax.set_ylabel(_st.label("e"))
        _st.legend_outside(fig)  # below the residuals, off the data
        axr.axhline(0.0, color=exact["color"], linewidth=0.8)
        axr.errorbar(fit.v0, fit.residuals, yerr=err, fmt="o", color=data_color, markersize=3.5,
                     elinewidth=0.8, capsize=1.5)
        axr.set_ylabel(r"$e - e_{\rm fit}$")
        axr.set_xlabel(_st.label("V0"))
        if log_x:
            axr.set_xscale("log")
        if title:
            ax.set_title(title)
        if path is not None:
            p = Path(path)
            _st.save(fig, p.with_suffix(""), (p.suffix.lstrip(".") or "png",))
    return fig
