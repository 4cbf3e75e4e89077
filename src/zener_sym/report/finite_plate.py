"""Finite plates in charts and in the report: the regime map, a force history with every contact.

``zener-sym regen finite-plate-figures`` writes

- ``docs/data/finite_plate_force.csv`` and ``docs/figures/finite_plate_force.png``: the issue's
  steel ball (radius 2.5 mm, 1 m/s) on a 1 mm glass plate clamped at radius 50 mm and 100 mm,
  the finite plate's force over every contact beside Zener's;
- ``docs/figures/finite_plate_regime.png``: e_plate / e_Zener over (lambda, beta) for each
  support of the circle, from the criterion's table (``data/plate_criterion.json``), with the
  region where Zener holds to 1 % in every quantity and the region of several contacts.

:func:`section` is the report's finite-plate section.
"""
from __future__ import annotations

import io
import time
import warnings
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .format import markdown_table, seconds

if TYPE_CHECKING:
    from ..scene.scene import Scene

__all__ = ["FORCE_CSV", "FORCE_CHART", "REGIME_CHART", "CASES", "case_scene", "force_csv",
           "compare_csv", "write_charts", "section", "COMPARE_RTOL"]

FORCE_CSV = "docs/data/finite_plate_force.csv"
FORCE_CHART = "docs/figures/finite_plate_force.png"
REGIME_CHART = "docs/figures/finite_plate_regime.png"

#: The issue's scenes: (label, sphere, plate, ball radius, thickness, v0, plate keywords).
CASES: tuple[tuple[str, str, str, str, str, str, dict[str, Any]], ...] = (
    ("glass, clamped, b = 50 mm", "steel", "glass", "2.5 mm", "1 mm", "1 m/s",
     {"plate_radius": "50 mm", "support": "clamped"}),
    ("glass, clamped, b = 100 mm", "steel", "glass", "2.5 mm", "1 mm", "1 m/s",
     {"plate_radius": "100 mm", "support": "clamped"}),
    ("steel, simply supported, 50 mm square", "steel", "steel", "5 mm", "2 mm", "1 m/s",
     {"plate_size": ("50 mm", "50 mm"), "support": "simply-supported"}),
)
#: Samples per microsecond of the force chart's data.
_PER_US = 4


def case_scene(i: int) -> Scene:
    """The scene of :data:`CASES` [i]."""
    from ..scene.scene import Scene

    _, sphere, plate, radius, thickness, v0, kw = CASES[i]
    return Scene(sphere, plate, radius=radius, thickness=thickness, v0=v0, **kw)


def _force_rows() -> tuple[list[str], np.ndarray]:
    """Columns and rows (t in us, then per case the finite plate's and Zener's force in N)."""
    results = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the cases warn about Zener on purpose
        for i in (0, 1):
            sc = case_scene(i)
            results.append((sc.result(model="finite-plate", warn=False),
                            sc.result(model="exact", warn=False)))
    t_end = 1.05 * max(r.contacts[-1].end_s for r, _ in results)
    t = np.arange(0.0, t_end * 1e6 * _PER_US + 1) / (_PER_US * 1e6)
    cols = ["t_us"]
    data = [t * 1e6]
    for (plate, zener), b in zip(results, ("50mm", "100mm")):
        cols += [f"F_plate_{b}_N", f"F_zener_{b}_N"]
        data += [plate.force(t), zener.force(t)]
    return cols, np.column_stack(data)


def force_csv() -> str:
    """The force chart's data as CSV text (module docstring)."""
    cols, rows = _force_rows()
    buf = io.StringIO()
    buf.write(",".join(cols) + "\n")
    for r in rows:
        buf.write(",".join(f"{v:.6g}" for v in r) + "\n")
    return buf.getvalue()


def _read_csv(text: str) -> tuple[list[str], np.ndarray]:
    lines = text.strip().splitlines()
    return lines[0].split(","), np.array([[float(x) for x in ln.split(",")] for ln in lines[1:]])


#: A rebuilt force may move by this much (relative to each column's peak) before the committed
#: data is stale: the solver's own accuracy there (rtol 1e-4 in e) with a margin.
COMPARE_RTOL = 1e-3


def compare_csv(rel: str, old: str, new: str) -> list[str]:
    """Why the committed force data is stale against a rebuild (empty: fresh)."""
    try:
        (c_old, a), (c_new, b) = _read_csv(old), _read_csv(new)
    except ValueError as exc:
        return [f"{rel} does not parse: {exc}"]
    if c_old != c_new or a.shape != b.shape:
        return [f"{rel}: columns or rows differ from a rebuild ({a.shape} against {b.shape})"]
    scale = np.max(np.abs(b), axis=0)
    bad = np.nonzero(np.any(np.abs(a - b) > COMPARE_RTOL * scale, axis=0))[0]
    return [f"{rel}: column {c_new[i]} moved beyond {COMPARE_RTOL:g} of its peak" for i in bad]


def _force_chart(csv_text: str, path: Path) -> None:
    from ..plot.style import COLUMN_WIDTH, label, legend_outside, pyplot, rc, save, style_for

    cols, rows = _read_csv(csv_text)
    pyplot(headless=True)
    with rc() as plt:
        fig, axes = plt.subplots(2, 1, figsize=(COLUMN_WIDTH, 3.6), sharex=True)
        for ax, b, title in zip(axes, ("50mm", "100mm"), ("$b$ = 50 mm", "$b$ = 100 mm")):
            t = rows[:, 0]
            zen = style_for("exact")
            zen["label"] = "Zener, infinite plate (Eq. 10)"
            plate = style_for("finite-plate")
            ax.plot(t, rows[:, cols.index(f"F_zener_{b}_N")], **{**zen, "marker": None})
            ax.plot(t, rows[:, cols.index(f"F_plate_{b}_N")], **{**plate, "marker": None})
            ax.set_ylabel(label("force_N"))
            ax.set_title(f"glass 1 mm, clamped, {title}", loc="left")
        axes[-1].set_xlabel(label("t_us"))
        legend_outside(fig, ncol=1)
        save(fig, path, ("png",))
        plt.close(fig)


def _case_points(support: str) -> list[tuple[str, float, float]]:
    """The issue's scenes on the regime map of ``support``: (label, lambda, beta); the square
    at its equivalent circle's beta (the criterion's reading of a rectangle)."""
    out = []
    for i, (name, *_rest) in enumerate(CASES):
        sc = case_scene(i)
        g = sc.geometry
        assert g is not None and g.support is not None and sc.beta is not None
        if g.support != support:
            continue
        beta = sc.beta * (g.L / g.edge_distance) ** 2
        short = "square" if g.shape == "rectangle" else f"{g.size[0] * 1e3:.0f} mm"
        out.append((short, sc.lam, beta))
    return out


def _regime_chart(path: Path) -> None:
    from matplotlib.colors import TwoSlopeNorm

    from ..plot.style import PAGE_WIDTH, label, legend_outside, pyplot, rc, save
    from ..scene import plate_criterion as crit

    table = crit.load()
    lam, beta = np.array(table["lam"]), np.array(table["beta"])
    pyplot(headless=True)
    with rc() as plt:
        from matplotlib.lines import Line2D
        from matplotlib.patches import Patch

        fig, axes = plt.subplots(1, 2, figsize=(PAGE_WIDTH, 3.0), sharey=True,
                                 layout="constrained")
        mesh = None
        for ax, (support, data) in zip(axes, table["supports"].items()):
            ratio = np.log10(np.array(data["e_ratio"], float)).T  # [beta][lambda]
            norm = TwoSlopeNorm(vmin=min(-0.5, ratio.min()), vcenter=0.0,
                                vmax=max(0.5, ratio.max()))
            mesh = ax.pcolormesh(lam, beta, ratio, cmap="RdBu_r", norm=norm, shading="nearest")
            worst = np.max([np.array(data["difference"][q], float) for q in crit.QUANTITIES],
                           axis=0).T
            ax.contour(lam, beta, worst, levels=[0.01], colors="black", linewidths=1.3)
            several = (np.array(data["contacts"]) > 1).T.astype(float)
            ax.contourf(lam, beta, several, levels=[0.5, 1.5], colors="none", hatches=["////"])
            ax.contour(lam, beta, several, levels=[0.5], colors="#444444", linewidths=0.8,
                       linestyles="--")
            for name, lam_c, beta_c in _case_points(support):
                ax.plot([lam_c], [beta_c], marker="o", markersize=4, color="black",
                        markerfacecolor="white", linestyle="none")
                ax.annotate(name, (lam_c, beta_c), xytext=(-4, 0), textcoords="offset points",
                            ha="right", va="center", fontsize=6)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel(label("lam"))
            ax.set_title(f"circle, {support}, struck at its centre", loc="left")
        axes[0].set_ylabel(r"$\beta = t_0\sqrt{D/\rho h}\,/\,b^2$ (smaller: larger plate)")
        cb = fig.colorbar(mesh, ax=axes, shrink=0.9)
        cb.set_label(r"$\log_{10}(e_{\rm plate}/e_{\rm Zener})$")
        handles = [Line2D([], [], color="black", linewidth=1.3),
                   Patch(facecolor="none", edgecolor="#444444", hatch="////")]
        legend_outside(fig, handles, ["Zener holds to 1 % (every quantity) below this line",
                                      "two or more contacts"], ncol=2)
        save(fig, path, ("png",))
        plt.close(fig)


def write_charts(paths: tuple[Path, Path, Path], csv_text: str | None = None) -> list[Path]:
    """Write the force data and both charts (module docstring).

    Parameters
    ----------
    paths : (Path, Path, Path)
        Where the force data, the force chart and the regime map go.
    csv_text : str, optional
        The force data (default: computed).

    Returns
    -------
    list of Path
        The files written.
    """
    text = force_csv() if csv_text is None else csv_text
    csv_path, force_path, regime_path = paths
    for p in paths:
        p.parent.mkdir(parents=True, exist_ok=True)
    csv_path.write_text(text, encoding="utf-8")
    _force_chart(text, force_path)
    _regime_chart(regime_path)
    return list(paths)


def _contact_rows(res: Any) -> list[list[str]]:
    return [[str(k), f"{c.start_s * 1e6:.2f}", f"{c.end_s * 1e6:.2f}", f"{c.max_force_N:.4g}",
             f"{c.impulse_N_s:.4g}", f"{c.speed_after_m_s:.4g}"]
            for k, c in enumerate(res.contacts, 1)]


def section(out_dir: Path) -> str:
    """The report's finite-plate section: the issue's scenes as the scene answers them."""
    # the solver's loops compile on the first solve of an installation (numba, then cached):
    # timed apart, so that the first case's time is its own
    from ..plate.solver import warm_up

    compile_s = warm_up()
    parts = ["## Finite plates\n\nThe scene chooses: with the plate's size and support, "
             "`Scene.result()` solves the bounded plate (`finite-plate`) where the criterion "
             "finds that Zener's infinite plate may be off by more than rtol "
             "(docs/finite_plates.md). Loading the solver's compiled loops took "
             f"{seconds(compile_s)} (on an installation's first solve this is their compilation, "
             "some seconds; they are cached after), apart from the times below.\n"]
    for i, (name, *_rest) in enumerate(CASES):
        sc = case_scene(i)
        t0 = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            res = sc.result(rtol=1e-3)
            zen = sc.result(model="exact", warn=False)
        dt = time.perf_counter() - t0
        assert res.e is not None and zen.e is not None
        parts.append(
            f"### {name} (steel ball, {CASES[i][3]} radius, {CASES[i][5]})\n\n"
            f"lambda = {sc.lam:.4g}, beta = {sc.beta:.4g}; model `{res.model}` ({res.reason}); "
            f"e = {res.e:.4g} against Zener's {zen.e:.4g} (ratio {res.e / zen.e:.3g}); "
            f"{len(res.contacts)} contact(s); {seconds(dt)}.\n\n"
            + markdown_table(["contact", "start (us)", "end (us)", "max force (N)",
                              "impulse (N s)", "ball speed after (m/s)"], _contact_rows(res)))
    return "\n\n".join(parts)
