"""Charts of the LAMMPS studies (:mod:`zener_sym.bench.lammps.studies`), in the package style."""
from __future__ import annotations

import math
import os
from collections.abc import Sequence
from typing import Any

import numpy as np

from ...api import summary

__all__ = ["convergence_chart", "stability_chart", "mpi_chart"]

_END_TITLE = {"force": r"force-free end (limit_damping)", "delta": r"end at $\delta = 0$"}


def _lam_color(lam: float, lams: Sequence[float]) -> Any:
    from ...plot.style import pyplot

    cmap = pyplot().get_cmap("viridis")
    i = sorted(lams).index(lam)
    return cmap(i / max(len(lams) - 1, 1))


def convergence_chart(rows: Sequence[dict[str, Any]], path: str | os.PathLike[str],
                      geometry: str = "wall") -> None:
    """|e_LAMMPS - e| against steps per contact, one line per lambda, both ends of contact,
    with a slope -1 guide (first order)."""
    from ...plot.style import PAGE_WIDTH, legend_outside, rc

    lams = sorted({r["lambda"] for r in rows})
    with rc() as plt:
        fig, axes = plt.subplots(1, 2, figsize=(PAGE_WIDTH, 3.0), sharey=True)
        for ax, end in zip(axes, ("force", "delta")):
            for lam in lams:
                sel = [r for r in rows if r["geometry"] == geometry and r["contact_end"] == end
                       and r["lambda"] == lam and r["status"] == "ok"]
                if not sel:
                    continue
                n = np.array([r["steps"] for r in sel], dtype=float)
                err = np.abs([r["e_err"] for r in sel])
                ax.loglog(n, np.maximum(err, 1e-17), marker="o", ms=3,
                          color=_lam_color(lam, lams), label=rf"$\lambda = {lam:g}$")
            n = np.array([20.0, 5120.0])
            ax.loglog(n, 3e-3 * 20 / n, color="#7F7F7F", ls=":", label="slope $-1$")
            ax.set_title(_END_TITLE[end])
            ax.set_xlabel(r"steps per contact $\tau_d/\Delta\tau$")
        axes[0].set_ylabel(r"$|e_{\rm LAMMPS} - e_{\rm exact}|$")
        legend_outside(fig, ncol=5)
        fig.suptitle(f"LAMMPS (hertz/material, viscoelastic) against the exact e: {geometry}")
        fig.tight_layout()
        fig.savefig(path, dpi=150, metadata={"Software": None}, bbox_inches="tight")
        plt.close(fig)


_FAIL_MARKERS = {"e off >10%": "v", "energy gain": "^", "missed contact": "x", "blow-up": "*",
                 "none on the ladder": "o"}


def stability_chart(rows: Sequence[dict[str, Any]], path: str | os.PathLike[str]) -> None:
    """Left: the steps per contact LAMMPS needs to keep the collision (the stability limit) over
    lambda, marked by how it fails one rung coarser; right: LAMMPS's e at the limit (hollow)
    and one rung beyond it (filled) beside the exact e (black)."""
    from ...plot.style import PAGE_WIDTH, legend_outside, rc, style_for

    lc = style_for("lammps")["color"]
    colors = {"force": lc, "delta": lc}  # LAMMPS's colour; the ends by line style and fill
    dashes = {"force": "-", "delta": "--"}
    top = max(lv_top(rows), 1.0)
    with rc() as plt:
        fig, (a, b) = plt.subplots(1, 2, figsize=(PAGE_WIDTH, 3.2))
        for end in ("force", "delta"):
            sel = [r for r in rows if r["contact_end"] == end]
            lam = np.array([r["lambda"] for r in sel])
            lim = np.array([r["steps_at_limit"] for r in sel], dtype=float)
            a.loglog(lam, lim, color=colors[end], lw=1.0, ls=dashes[end], label=_END_TITLE[end])
            for r in sel:
                if math.isfinite(r["steps_at_limit"]):
                    a.loglog(r["lambda"], r["steps_at_limit"], ls="none", color=colors[end],
                             marker=_FAIL_MARKERS.get(r["failure_beyond"], "o"), ms=5,
                             markerfacecolor=colors[end] if end == "force" else "none")
                else:  # unstable on the whole ladder: the limit lies above its finest rung
                    a.annotate("", xy=(r["lambda"], 3 * top), xytext=(r["lambda"], top),
                               arrowprops=dict(arrowstyle="->", color=colors[end]))
            b.loglog(lam, [r["e_at_limit"] for r in sel], ls="none", marker="o", ms=4,
                     color=colors[end], markerfacecolor="none")
            beyond = [(r["lambda"], r["e_beyond"]) for r in sel
                      if math.isfinite(r["e_beyond"]) and r["e_beyond"] > 0]
            if beyond:
                b.loglog(*zip(*beyond), ls="none", marker="x", ms=4, color=colors[end])
            lam_fine = np.geomspace(min(lam), max(lam), 200)
            b.loglog(lam_fine, summary(lam_fine, model="exact", contact_end=end).e,
                     color="#000000", ls=dashes[end], lw=1.0, label=f"exact, {end} end")
        for name, mk in _FAIL_MARKERS.items():
            if any(r["failure_beyond"] == name for r in rows):
                a.plot([], [], ls="none", marker=mk, color="#7F7F7F", label=f"beyond: {name}")
        a.plot([], [], ls="none", marker=r"$\uparrow$", color="#7F7F7F",
               label="limit above the ladder")
        b.plot([], [], ls="none", marker="o", markerfacecolor="none", color=lc,
               label="LAMMPS at the limit")
        b.plot([], [], ls="none", marker="x", color=lc, label="LAMMPS one rung coarser")
        a.set_xlabel(r"$\lambda$")
        a.set_ylim(top=5 * top)
        a.set_ylabel("steps per contact at the limit")
        a.set_title("coarsest timestep that keeps the collision")
        b.set_xlabel(r"$\lambda$")
        b.set_ylabel(r"$e$")
        b.set_title(r"$e$ there, and the exact $e$")
        legend_outside(a, ncol=1)
        legend_outside(b, ncol=1)
        fig.tight_layout()
        fig.savefig(path, dpi=150, metadata={"Software": None}, bbox_inches="tight")
        plt.close(fig)


def lv_top(rows: Sequence[dict[str, Any]]) -> float:
    """The finest finite stability limit of ``rows`` (where the chart's arrows start)."""
    lims = [r["steps_at_limit"] for r in rows if math.isfinite(r["steps_at_limit"])]
    return float(max(lims)) if lims else 1.0


def mpi_chart(v: np.ndarray, e_lammps: np.ndarray, e_exact: np.ndarray,
              path: str | os.PathLike[str]) -> None:
    """LAMMPS's e(v) of every grain on the exact curve, and the error distribution."""
    from ...plot.style import PAGE_WIDTH, legend_outside, rc, style_for

    order = np.argsort(v)
    v, e_l, e_x = v[order], e_lammps[order], e_exact[order]
    with rc() as plt:
        fig, (a, b) = plt.subplots(1, 2, figsize=(PAGE_WIDTH, 3.0))
        kw = style_for("exact")
        kw.update(lw=0.8, zorder=4)  # the exact curve drawn over the grains, visible on them
        a.semilogx(v, e_x, **kw)
        a.semilogx(v, e_l, ls="none", marker=".", ms=2.0, color=style_for("lammps")["color"],
                   zorder=3, label=f"LAMMPS, {len(v)} grains (2 MPI ranks)")
        a.set_title(r"$e(v_0)$ of every grain, force-free end")
        a.set_xlabel(r"$v_0$ (m/s)")
        a.set_ylabel(r"$e$")
        err = e_l - e_x
        b.hist(err * 1e3, bins=60, color=style_for("lammps")["color"])
        b.axvline(-1.0, color="#7F7F7F", ls=":", lw=0.8)
        b.axvline(1.0, color="#7F7F7F", ls=":", lw=0.8,
                  label=r"$\pm 10^{-3}$ (the table's promise)")
        b.set_xlabel(r"$(e_{\rm LAMMPS} - e_{\rm exact}) \times 10^3$")
        b.set_ylabel("grains")
        b.set_title("error distribution")
        legend_outside(fig, ncol=3)
        fig.tight_layout()
        fig.savefig(path, dpi=150, metadata={"Software": None}, bbox_inches="tight")
        plt.close(fig)
