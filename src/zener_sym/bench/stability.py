"""Stability map: where each method fails over lambda in [0, 10] and tau across the contact.

Each cell (lambda, s = tau / tau_d) is classed as ``refused`` (a ValueError from the API: a clear
error, the intended behaviour outside a model's validity), ``exception`` (any other exception: a
bug), ``nan`` (a non-finite value), ``>10%``, ``>1%`` or ``ok``, by the force error
|F − F_ref| / F_m,ref against the exact model (scipy, rtol 1e-12, itself checked against the
mpmath path in the tests).
"""
from __future__ import annotations

import csv
import pathlib

import numpy as np

from ..exact import solver as exact

CLASSES = ("ok", ">1%", ">10%", "nan", "exception", "refused")
COLORS = ("#2ca02c", "#ffdd57", "#ff7f0e", "#9467bd", "#d62728", "#bbbbbb")


def grid(quick: bool = False):
    lams = np.linspace(0.0, 10.0, 21 if quick else 41)
    s = np.linspace(0.0, 1.0, 11 if quick else 21)
    return lams, s


def classify(err: np.ndarray) -> np.ndarray:
    out = np.full(err.shape, "ok", dtype=object)
    out[err > 0.01] = ">1%"
    out[err > 0.10] = ">10%"
    out[~np.isfinite(err)] = "nan"
    return out


def run(methods, quick: bool = False):
    """Dict method name -> array of classes, shape (len(lams), len(s)); and the grid."""
    lams, s = grid(quick)
    refs = [exact.solve(x) for x in lams]
    taus = [r.tau_d * s for r in refs]
    fref = [r.history(t)["force"] for r, t in zip(refs, taus)]
    result = {}
    for m in methods:
        if m.force is None:
            continue
        cells = np.empty((len(lams), len(s)), dtype=object)
        for i, lam in enumerate(lams):
            try:
                with np.errstate(all="ignore"):
                    f = np.asarray(m.force(np.array([lam]), [taus[i]])[0], dtype=float)
                cells[i] = classify(np.abs(f - fref[i]) / refs[i].F_m)
            except ValueError:
                cells[i] = "refused"
            except Exception:
                cells[i] = "exception"
        result[m.name] = cells
    return result, lams, s


def summary_rows(result, lams):
    """Per method: the smallest lambda at which each failure class first appears."""
    rows = []
    for name, cells in result.items():
        row = {"method": name}
        for c in CLASSES[1:]:
            hit = [lams[i] for i in range(len(lams)) if (cells[i] == c).any()]
            row[c] = f"{min(hit):.3g}" if hit else "-"
        rows.append(row)
    return rows


def write_csv(result, lams, s, path: pathlib.Path) -> None:
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["method", "lambda", "tau_over_tau_d", "class"])
        for name, cells in result.items():
            for i, lam in enumerate(lams):
                for j, sj in enumerate(s):
                    w.writerow([name, f"{lam:.4g}", f"{sj:.4g}", cells[i, j]])


def chart(result, lams, s, path: pathlib.Path) -> None:
    from ._plot import pyplot

    plt = pyplot()
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    names = list(result)
    ncol = 4
    nrow = max(1, -(-len(names) // ncol))
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.2 * ncol, 2.6 * nrow + 0.8), squeeze=False)
    cmap = ListedColormap(COLORS)
    for ax, name in zip(axes.flat, names):
        idx = np.vectorize(CLASSES.index)(result[name]).astype(float)
        ax.imshow(idx.T, origin="lower", aspect="auto", cmap=cmap, vmin=-0.5, vmax=len(CLASSES) - 0.5,
                  extent=(lams[0], lams[-1], s[0], s[-1]))
        ax.set_title(name, fontsize=7)
        ax.set_xlabel("lambda", fontsize=7)
        ax.set_ylabel("tau / tau_d", fontsize=7)
        ax.tick_params(labelsize=6)
    for ax in list(axes.flat)[len(names):]:
        ax.axis("off")
    fig.legend(handles=[Patch(color=c, label=k) for k, c in zip(CLASSES, COLORS)], loc="lower center",
               ncol=len(CLASSES), fontsize=8)
    fig.suptitle("Stability map: force error |F - F_exact| / F_m over the contact", fontsize=10)
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    fig.savefig(path, dpi=100)
    plt.close(fig)
