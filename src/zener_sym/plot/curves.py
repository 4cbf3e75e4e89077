"""Public plotting functions: the force history and the restitution curve, in the package style.

Each function draws on a given matplotlib Axes (or a new one) and returns it; matplotlib is
imported only when one is called (the optional ``[plot]`` extra).
"""
from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from ..api import history, summary
from ..models import get_model
from ..typing import FloatArray, RealArrayLike, RealLike
from . import style as _st

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from ..scene.scene import Scene

__all__ = ["force_history", "restitution", "valid_lams", "DEFAULT_RESTITUTION_MODELS"]

#: Models drawn by :func:`restitution` by default: every system the paper's Fig. 15 compares.
DEFAULT_RESTITUTION_MODELS: tuple[str, ...] = ("exact", "ham0", "ham1", "linear", "raman")


def valid_lams(model: str, lams: RealArrayLike) -> FloatArray:
    """The part of ``lams`` inside ``model``'s validity (below its exclusive ``lam_bound``).

    Parameters
    ----------
    model : str
        A model name of ``zener_sym.MODELS``.
    lams : array_like
        Values of Zener's lambda (Eq. 11).

    Returns
    -------
    numpy.ndarray
        The float values of ``lams`` below the model's bound, in their order (all of them for
        a model valid at every lambda).

    Raises
    ------
    ValueError
        ``model`` is not a registered model.

    Examples
    --------
    >>> from zener_sym.plot.curves import valid_lams
    >>> valid_lams("exact", [0.5, 1.0, 3.0])
    array([0.5, 1. , 3. ])
    >>> valid_lams("raman", [0.25, 0.5, 1.0])   # e = 1 - c1 lambda reaches 0 near 0.58
    array([0.25, 0.5 ])
    """
    lams = np.asarray(lams, dtype=np.float64)
    bound: float | None = get_model(model).lam_bound
    return lams if bound is None else lams[lams < bound]


def _names(model: str | Iterable[str]) -> tuple[str, ...]:
    if isinstance(model, str):
        return (model,)
    names = tuple(model)
    if not names or not all(isinstance(m, str) for m in names):
        raise ValueError(f"model must be a model name or a sequence of them, got {model!r}")
    return names


def _axes(ax: Axes | None, width: float = _st.COLUMN_WIDTH, height: float = 2.4) -> Axes:
    if ax is not None:
        return ax
    plt = _st.pyplot()
    with plt.rc_context(_st.RC):
        # constrained layout keeps the labels and the legend below the axes inside the figure
        # when the caller saves it without bbox_inches="tight"
        new: Axes = plt.subplots(figsize=(width, height), layout="constrained")[1]
    return new


def force_history(lam_or_scene: RealLike | Scene, model: str | Iterable[str] = "exact",
                  ax: Axes | None = None, reference: bool = True, n: int = 400,
                  legend: bool = True) -> Axes:
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
        ``ax`` (or the new axes) with one line per model, labelled by
        :func:`~zener_sym.plot.style.style_for`.

    Raises
    ------
    ValueError
        ``lam_or_scene`` is neither a scalar nor a Scene, ``model`` is not a name or a
        sequence of names of ``zener_sym.MODELS``, a model does not give a force history or
        refuses the lambda, or ``n`` is not an integer >= 2.

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

    A scene in SI units gives the time in µs and the force in N:

    >>> ax = force_history(zs.Scene("steel", "glass", radius=1e-3, thickness=2e-3, v0=1.0),
    ...                    model="ham1", n=50)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('$t$ (µs)', '$F$ (N)')
    """
    names = _names(model)
    if reference and "exact" not in names:
        names = ("exact",) + names
    if isinstance(n, bool) or not isinstance(n, int) or n < 2:
        raise ValueError(f"n must be an integer >= 2, got {n!r}")
    ax = _axes(ax)
    plt = _st.pyplot()
    with plt.rc_context(_st.RC):
        if not hasattr(lam_or_scene, "result"):  # a number: dimensionless axes
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
            scene = cast("Scene", lam_or_scene)  # a Scene, or anything answering like one
            exact = scene.result(model="exact", warn=False)
            t_d = exact.contact_duration_s
            if t_d is None:  # the exact model gives every field; a stand-in might not
                raise ValueError("force_history: the scene's exact result has no contact "
                                 "duration")
            t = np.linspace(0.0, 1.1 * t_d, n)
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


def _line(name: str, n: int) -> dict[str, Any]:
    """Style keywords for a dense curve: markers thinned to about a dozen along it."""
    kw = _st.style_for(name)
    if kw.get("marker"):
        kw["markevery"] = max(n // 12, 1)
    return kw


def restitution(lams: RealArrayLike | None = None,
                models: str | Iterable[str] = DEFAULT_RESTITUTION_MODELS, ax: Axes | None = None,
                legend: bool = True) -> Axes:
    """Draw the coefficient of restitution e(lambda) of several models (cf. the paper's Fig. 15).

    Each model is drawn only where it is valid (below its ``lam_bound``).

    Parameters
    ----------
    lams : array_like, optional
        Lambda values (default 241 points on [0, 2.4]).
    models : str or sequence of str
        Model name(s) giving ``e`` (default :data:`DEFAULT_RESTITUTION_MODELS`).
    ax : matplotlib.axes.Axes, optional
        Where to draw; a new column-width figure if omitted.
    legend : bool
        Put a legend below the axes.

    Returns
    -------
    matplotlib.axes.Axes
        ``ax`` (or the new axes) with one line per model that is valid somewhere on ``lams``.

    Raises
    ------
    ValueError
        ``models`` is not a name or a sequence of names of ``zener_sym.MODELS``, or a model
        refuses a lambda of ``lams`` (a negative one, say).

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
