"""Public plotting functions: the force history and the restitution curve, in the package style.

Each function draws on a given matplotlib Axes (or a new one) and returns it; matplotlib is
imported only when one is called (the optional ``[plot]`` extra).
"""
from __future__ import annotations

import numpy as np

from ..api import history, summary
from ..models import get_model
from . import style as _st

__all__ = ["force_history", "restitution", "valid_lams", "DEFAULT_RESTITUTION_MODELS"]

#: Models drawn by :func:`restitution` by default: every system the paper's Fig. 15 compares.
DEFAULT_RESTITUTION_MODELS = ("exact", "ham0", "ham1", "linear", "raman")


def valid_lams(model: str, lams) -> np.ndarray:
    """The part of ``lams`` inside ``model``'s validity (below its ``lam_bound``)."""
    lams = np.asarray(lams, dtype=float)
    bound = get_model(model).lam_bound
    return lams if bound is None else lams[lams < bound]


def _names(model) -> tuple:
    if isinstance(model, str):
        return (model,)
    names = tuple(model)
    if not names or not all(isinstance(m, str) for m in names):
        raise ValueError(f"model must be a model name or a sequence of them, got {model!r}")
    return names


def _axes(ax, width=_st.COLUMN_WIDTH, height=2.4):
    if ax is not None:
        return ax
    plt = _st.pyplot()
    with plt.rc_context(_st.RC):
        # constrained layout keeps the labels and the legend below the axes inside the figure
        # when the caller saves it without bbox_inches="tight"
        _, ax = plt.subplots(figsize=(width, height), layout="constrained")
    return ax


def force_history(lam_or_scene, model="exact", ax=None, reference: bool = True, n: int = 400,
                  legend: bool = True):
    """Draw the contact force over the contact for one lambda or one scene.

    Parameters
    ----------
    lam_or_scene : float or Scene
        Zener's lambda (dimensionless axes: tau and F-bar, Eq. 45) or a ``zener_sym.Scene``
        (time in µs and force in N).
    model : str or sequence of str
        Model name(s) of ``zener_sym.MODELS`` that give a force history.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new column-width figure if omitted.
    reference : bool
        Also draw the exact solution (black) when it is not among ``model``.
    n : int
        Number of time points (over 1.1 times the longest contact).
    legend : bool
        Put a legend below the axes (outside the data).

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import zener_sym as zs
    >>> from zener_sym.plot import force_history
    >>> ax = force_history(1.01, model=("ham0", "ham1", "linear"))
    >>> [line.get_label() for line in ax.get_lines()]
    ['exact (Eq. 10)', 'HAM 0th order', 'HAM 1st order', 'Mueller et al. (linear)']
    >>> ax.get_xlabel()
    '$\\\\tau$'
    """
    names = _names(model)
    if reference and "exact" not in names:
        names = ("exact",) + names
    scene = lam_or_scene if hasattr(lam_or_scene, "result") else None
    if isinstance(n, bool) or not isinstance(n, int) or n < 2:
        raise ValueError(f"n must be an integer >= 2, got {n!r}")
    ax = _axes(ax)
    plt = _st.pyplot()
    with plt.rc_context(_st.RC):
        if scene is None:
            lam = float(lam_or_scene) if np.ndim(lam_or_scene) == 0 else None
            if lam is None:
                raise ValueError("force_history takes one lambda (a scalar) or a Scene")
            tau_end = 1.1 * float(summary(lam).tau_d)
            tau = np.linspace(0.0, tau_end, n)
            for name in names:
                ax.plot(tau, history(lam, tau, model=name, fields="force").force,
                        **_line(name, n))
            ax.set_xlabel(_st.label("tau"))
            ax.set_ylabel(_st.label("force"))
            ax.set_title(rf"$\lambda = {lam:.4g}$")
        else:
            exact = scene.result(model="exact", warn=False)
            t = np.linspace(0.0, 1.1 * exact.contact_duration_s, n)
            for name in names:
                f = exact.history(t, model=name)["force_N"]
                ax.plot(t * 1e6, f, **_line(name, n))
            ax.set_xlabel(_st.label("t_us"))
            ax.set_ylabel(_st.label("force_N"))
            ax.set_title(rf"$\lambda = {scene.lam:.4g}$")
        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=0.0)
        if legend:
            _st.legend_outside(ax)
    return ax


def _line(name, n):
    """Style keywords for a dense curve: markers thinned to about a dozen along it."""
    kw = _st.style_for(name)
    if kw.get("marker"):
        kw["markevery"] = max(n // 12, 1)
    return kw


def restitution(lams=None, models=DEFAULT_RESTITUTION_MODELS, ax=None, legend: bool = True):
    """Draw the coefficient of restitution e(lambda) of several models (cf. the paper's Fig. 15).

    Each model is drawn only where it is valid (below its ``lam_bound``).

    Parameters
    ----------
    lams : array_like, optional
        Lambda values (default 241 points on [0, 2.4]).
    models : sequence of str
        Model names giving ``e``.
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new column-width figure if omitted.
    legend : bool
        Put a legend below the axes.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from zener_sym.plot import restitution
    >>> ax = restitution(models=("exact", "raman"))
    >>> raman = ax.get_lines()[1]
    >>> float(raman.get_xdata().max()) < 0.58   # e = 1 - c1 lambda stops at e = 0
    True
    """
    lams = np.linspace(0.0, 2.4, 241) if lams is None else np.asarray(lams, dtype=float)
    ax = _axes(ax)
    plt = _st.pyplot()
    with plt.rc_context(_st.RC):
        for name in _names(models):
            x = valid_lams(name, lams)
            if x.size == 0:
                continue
            ax.plot(x, summary(x, model=name).e, **_line(name, x.size))
        ax.set_xlabel(_st.label("lam"))
        ax.set_ylabel(_st.label("e"))
        ax.set_ylim(0.0, 1.02)
        if legend:
            _st.legend_outside(ax)
    return ax
