"""Error map: each method's force error over lambda in [0, 10] and tau across the contact.

Each cell (lambda, s = tau / tau_d) holds the force error |F − F_ref| / F_m,ref against the exact
model (scipy, rtol 1e-12, itself checked against the mpmath path in the tests), drawn on a
continuous log colour scale, and a class: ``refused`` (a ValueError from the API: a clear error,
the intended behaviour outside a model's validity), ``exception`` (any other exception: a bug),
``nan`` (a non-finite value), ``>10%``, ``>1%`` or ``ok``. Cells where the exact force is below
``SMALL_FORCE`` of F_m (the contact's start and end) are marked: there every model is close to 0
and a small error says little. A method whose error is below ``QUIET`` everywhere is listed in one
line under the chart instead of drawn.
"""
from __future__ import annotations

import csv
import pathlib
from collections.abc import Mapping, Sequence
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from ..exact import solver as exact
from ..typing import FloatArray
from .methods import Method

#: A method's cells on the grid: one of ``CLASSES`` each (an object array of str).
Cells = npt.NDArray[np.object_]

CLASSES = ("ok", ">1%", ">10%", "nan", "exception", "refused")
#: Cells where the exact force is below this fraction of F_m are marked (not judged).
SMALL_FORCE = 0.01
#: Methods whose force error stays below this everywhere are summarised, not drawn.
QUIET = 1e-6
#: Range of the log colour scale of the force error.
ERR_RANGE = (1e-8, 1.0)


def grid(quick: bool = False) -> tuple[FloatArray, FloatArray]:
    """The lambdas and the fractions s = tau / tau_d of the map (coarser with ``quick``)."""
    lams = np.linspace(0.0, 10.0, 21 if quick else 41)
    s = np.linspace(0.0, 1.0, 11 if quick else 21)
    return lams, s


def classify(err: FloatArray) -> Cells:
    """The class of each error: "ok", ">1%", ">10%" or "nan" (non-finite)."""
    out = np.full(err.shape, "ok", dtype=object)
    out[err > 0.01] = ">1%"
    out[err > 0.10] = ">10%"
    out[~np.isfinite(err)] = "nan"
    return out


class ErrorMap(NamedTuple):
    """What :func:`run` measures (a tuple: ``result, lams, s, errors, small = run(...)``)."""

    #: method name -> array of classes, shape (len(lams), len(s))
    result: dict[str, Cells]
    #: the grid's lambdas
    lams: FloatArray
    #: the grid's tau / tau_d
    s: FloatArray
    #: method name -> force error |F - F_ref| / F_m,ref (NaN where refused or failed)
    errors: dict[str, FloatArray]
    #: cells where the exact force is below ``SMALL_FORCE`` F_m
    small: npt.NDArray[np.bool_]


def run(methods: Sequence[Method], quick: bool = False) -> ErrorMap:
    """Classes and errors of each method on the grid.

    Returns
    -------
    ErrorMap
        result, lams, s, errors, small (see :class:`ErrorMap`).
    """
    lams, s = grid(quick)
    refs = [exact.solve(x) for x in lams]
    taus = [r.tau_d * s for r in refs]
    fref = [r.history(t)["force"] for r, t in zip(refs, taus)]
    small = np.array([f < SMALL_FORCE * r.F_m for f, r in zip(fref, refs)])
    result: dict[str, Cells] = {}
    errors: dict[str, FloatArray] = {}
    for m in methods:
        force = m.force
        if force is None:
            continue
        cells = np.empty((len(lams), len(s)), dtype=object)
        errs = np.full((len(lams), len(s)), np.nan)
        for i, lam in enumerate(lams):
            try:
                with np.errstate(all="ignore"):
                    f = np.asarray(force(np.array([lam]), [taus[i]])[0], dtype=float)
                errs[i] = np.abs(f - fref[i]) / refs[i].F_m
                cells[i] = classify(errs[i])
            except ValueError:
                cells[i] = "refused"
            except Exception:
                cells[i] = "exception"
        result[m.name] = cells
        errors[m.name] = errs
    return ErrorMap(result, lams, s, errors, small)


def quiet_methods(result: Mapping[str, Cells], errors: Mapping[str, FloatArray]) -> list[str]:
    """Methods with nothing to show: every cell answered and its error below ``QUIET``."""
    return [n for n in result
            if np.all(result[n] == "ok") and np.nanmax(errors[n]) < QUIET]


def summary_rows(result: Mapping[str, Cells], lams: FloatArray) -> list[dict[str, str]]:
    """Per method: the smallest lambda at which each failure class first appears."""
    rows = []
    for name, cells in result.items():
        row = {"method": name}
        for c in CLASSES[1:]:
            hit = [lams[i] for i in range(len(lams)) if (cells[i] == c).any()]
            row[c] = f"{min(hit):.3g}" if hit else "-"
        rows.append(row)
    return rows


def write_csv(result: Mapping[str, Cells], lams: FloatArray, s: FloatArray, path: pathlib.Path,
              errors: Mapping[str, FloatArray] | None = None,
              small: npt.NDArray[np.bool_] | None = None) -> None:
    """The map as CSV: one row per method and cell (class, error, small-force mark)."""
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["method", "lambda", "tau_over_tau_d", "class", "force_error",
                    "exact_force_small"])
        for name, cells in result.items():
            for i, lam in enumerate(lams):
                for j, sj in enumerate(s):
                    err = "" if errors is None or not np.isfinite(errors[name][i, j]) \
                        else f"{errors[name][i, j]:.3g}"
                    sm = "" if small is None else int(small[i, j])
                    w.writerow([name, f"{lam:.4g}", f"{sj:.4g}", cells[i, j], err, sm])


def chart(result: Mapping[str, Cells], lams: FloatArray, s: FloatArray, path: pathlib.Path,
          errors: Mapping[str, FloatArray] | None = None,
          small: npt.NDArray[np.bool_] | None = None) -> None:
    """The error map: one panel per method that has something to show (package style)."""
    from ..plot import style as st

    plt = st.pyplot(headless=True)
    from matplotlib.colors import ListedColormap, LogNorm
    from matplotlib.patches import Patch

    if errors is None:  # classes only: errors unknown, draw every method
        errors = {n: np.full(c.shape, np.nan) for n, c in result.items()}
    quiet = quiet_methods(result, errors)
    names = [n for n in result if n not in quiet]
    ncol = 4
    nrow = max(1, -(-len(names) // ncol))
    with plt.rc_context(st.RC):
        fig, axes = plt.subplots(nrow, ncol, figsize=(st.PAGE_WIDTH, 1.75 * nrow + 0.9),
                                 squeeze=False, sharex=True, sharey=True, layout="constrained")
        ext = (lams[0], lams[-1], s[0], s[-1])
        norm = LogNorm(*ERR_RANGE, clip=True)
        fail_cmap = ListedColormap(["#bbbbbb", "#d62728", "#9467bd"])  # refused, exception, nan
        im = None
        for ax, name in zip(axes.flat, names):
            e = np.where(errors[name] > 0, errors[name], ERR_RANGE[0])
            im = ax.imshow(np.ma.masked_invalid(e).T, origin="lower", aspect="auto",
                           cmap="viridis", norm=norm, extent=ext, interpolation="nearest")
            code = np.full(result[name].shape, np.nan)
            code[result[name] == "refused"] = 0
            code[result[name] == "exception"] = 1
            code[result[name] == "nan"] = 2
            ax.imshow(np.ma.masked_invalid(code).T, origin="lower", aspect="auto", cmap=fail_cmap,
                      vmin=-0.5, vmax=2.5, extent=ext, interpolation="nearest")
            if small is not None:
                ax.contourf(lams, s, small.T.astype(float), levels=[0.5, 1.5], colors="none",
                            hatches=["////"])
            ax.set_title(st.style_for(name)["label"] if name in st.MODEL_STYLES else name,
                         fontsize=7)
            ax.grid(False)
        for ax in axes[-1]:
            ax.set_xlabel(st.label("lam"))
        for ax in axes[:, 0]:
            ax.set_ylabel(r"$\tau/\tau_d$")
        for ax in list(axes.flat)[len(names):]:
            ax.axis("off")
        if im is not None:
            fig.colorbar(im, ax=axes, shrink=0.6, label=r"$|\bar F-\bar F_{\rm exact}|/\bar F_m$")
        handles = [Patch(facecolor="#bbbbbb", label="refused (ValueError)"),
                   Patch(facecolor="#d62728", label="exception"),
                   Patch(facecolor="#9467bd", label="non-finite"),
                   Patch(facecolor="white", edgecolor="black", hatch="////",
                         label=f"exact force < {SMALL_FORCE:g} $\\bar F_m$")]
        fig.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=4,
                   frameon=False)
        if quiet:
            fig.text(0.5, -0.07, f"Not drawn (force error below {QUIET:g} everywhere): "
                     + ", ".join(quiet), ha="center", va="top", fontsize=6, wrap=True)
        fig.suptitle(r"Error map: force error over the contact, $\lambda \in [0, 10]$")
        st.save(fig, path.with_suffix(""), (path.suffix.lstrip(".") or "png",))
        plt.close(fig)
