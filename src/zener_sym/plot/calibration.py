"""The chart of a fitted dissipative constant (:func:`zener_sym.fit_dissipation`): measured e
against v0 with the fitted curve and the band of A's confidence interval, and the residuals
below. Drawn in the package style; matplotlib is imported only when drawing."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from . import style as _st

__all__ = ["fit_chart"]


def _speed_grid(v0: np.ndarray, n: int = 200) -> np.ndarray:
    lo, hi = float(v0.min()), float(v0.max())
    if hi == lo:
        lo, hi = lo / 2.0, hi * 2.0
    return np.geomspace(lo / 1.15, hi * 1.15, n)


def _sci(x: float) -> str:
    """Math text of x to 3 digits: 1.26e-04 -> 1.26 x 10^-4."""
    mant, _, exp = f"{x:.2e}".partition("e")
    return rf"${mant}\times10^{{{int(exp)}}}$"


def fit_chart(fit, path=None, title=None, data_label="measured"):
    """Draw ``fit`` (a :class:`~zener_sym.scene.calibrate.DissipationFit`): e(v0) above, the
    residuals e - e_fit below; save to ``path`` if given (its suffix picks the format).
    ``data_label`` names the points in the legend.

    Returns
    -------
    matplotlib.figure.Figure
    """
    plt = _st.pyplot(headless=path is not None)
    grid = _speed_grid(fit.v0)
    pred = fit.predict(grid)
    log_x = fit.v0.max() / fit.v0.min() > 10.0
    exact = _st.style_for("exact")
    data_color = _st.style_for("linear")["color"]
    with plt.rc_context(_st.RC):
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
