"""The data of the paper's Figs. 3-15, with the exact solution where the paper has FEM or numerics.

Each figure is a :class:`FigureSpec` whose ``compute(coarse)`` returns its rows as a tidy table
(``panel, series, x, y, error``): one row per point of one curve. ``series`` is a model name (the
style of :mod:`zener_sym.plot.style` draws it), ``error`` the curve's error against the exact
solution at the same x (empty for the exact curve itself), defined per figure in ``error_def``:

* summary quantities (Figs. 3, 6-9, 12, 13, 15): |q - q_exact| / |q_exact|;
* histories (Figs. 4, 5, 10, 11): |q(tau) - q_exact(tau)| / max_tau |q_exact| (a relative error
  is meaningless where the force passes through 0).

Pure numpy: no matplotlib here (the CSVs are regenerated and compared in the tests). Numbers go to
the CSV with 10 significant digits, which every machine reproduces.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

from ..api import Summary, history, summary
from ..models import formulas as fm
from ..models import get_model
from ..scene.materials import TABLE1_PLATE, TABLE1_SPHERE
from ..scene.scene import Scene
from ..scene.stress_waves import stress_wave_k
from ..typing import FloatArray

__all__ = ["Row", "FigureSpec", "FIGURES", "NUMBERS", "COLUMNS", "HISTORY_LAMS", "TABLE1_RADIUS",
           "FIG14_THICKNESS", "FIG14_K", "to_csv", "from_csv"]

COLUMNS = ("panel", "series", "x", "y", "error")
#: One row of a figure's table (:data:`COLUMNS`): panel, series, x, y and the error (None: none).
Row = tuple[str, str, float, float, float | None]
#: The four lambdas of the paper's history figures (Figs. 5, 10, 11).
HISTORY_LAMS = (0.11, 1.01, 1.51, 1.99)
#: Sphere radius of the paper's FEM (Appendix): R = 0.9 mm.
TABLE1_RADIUS = 0.9e-3
#: Plate thicknesses of Fig. 14 [m]: H = 0.4 R and 1.7 R, the two the paper's text discusses.
FIG14_THICKNESS = (0.4 * TABLE1_RADIUS, 1.7 * TABLE1_RADIUS)
_LAM_MAX = 2.4  # the HAM models' range (bound 2.4419, Eq. 81) drawn in the lambda figures


@dataclass
class FigureSpec:
    """One figure: its number, the paper's caption, the axes and the data function."""

    number: int
    caption: str
    x: str               # quantity key of the x axis (plot.style.LABELS)
    y: str               # quantity key of the y axis
    compute: Callable[[bool], list[Row]]  # compute(coarse) -> the rows (COLUMNS)
    panels: tuple[str, ...] = ("",)
    error_def: str = "rel"    # "rel", "max" (history, over the exact maximum) or "" (none)
    xlog: bool = False
    ylog: bool = False
    panel_titles: dict[str, str] = field(default_factory=dict)
    labels: dict[str, str] = field(default_factory=dict)  # series -> legend label in this figure

    @property
    def name(self) -> str:
        return f"fig{self.number:02d}"


def _lam_grid(coarse: bool, lo: float = 0.0, hi: float = _LAM_MAX, n: int = 121) -> FloatArray:
    return np.linspace(lo, hi, 13 if coarse else n)


def _rows(panel: str, series: str, x: FloatArray, y: FloatArray,
          err: FloatArray | Sequence[float | None] | None = None) -> list[Row]:
    err = [None] * len(x) if err is None else err
    return [(panel, series, float(a), float(b), None if c is None else float(c))
            for a, b, c in zip(x, y, err)]


def _vs_lambda(models: Sequence[str], field_: str, lams: FloatArray, panel: str = "",
               ref: Summary | None = None) -> list[Row]:
    """Rows of ``field_`` against lambda for each model (inside its validity), errors vs exact."""
    ref = summary(lams) if ref is None else ref
    rows = _rows(panel, "exact", lams, getattr(ref, field_))
    for m in models:
        bound = get_model(m).lam_bound
        ok = np.ones(lams.shape, bool) if bound is None else lams < bound
        x = lams[ok]
        if x.size == 0:
            continue
        y = np.asarray(getattr(summary(x, model=m), field_), dtype=float)
        r = np.asarray(getattr(ref, field_), dtype=float)[ok]
        with np.errstate(divide="ignore", invalid="ignore"):
            err = np.where(r != 0, np.abs(y - r) / np.abs(r), np.nan)
        rows += _rows(panel, m, x, y, [None if not np.isfinite(v) else v for v in err])
    return rows


def _histories(models: Sequence[str], field_: str, lams: Sequence[float], coarse: bool,
               panels: Sequence[str] | None = None) -> list[Row]:
    """Rows of a history field over [0, 1.1 tau_d] at each lambda (one panel per lambda)."""
    rows: list[Row] = []
    n = 41 if coarse else 241
    for i, lam in enumerate(lams):
        panel = panels[i] if panels else f"lambda={lam:g}"
        tau = np.linspace(0.0, 1.1 * float(summary(lam).tau_d), n)
        ref = getattr(history(lam, tau, model="exact", fields=_hfield(field_)), _hfield(field_))
        if field_ == "velocity":
            ref = np.asarray(ref)
        scale = float(np.max(np.abs(ref)))
        rows += _rows(panel, "exact", tau, ref)
        for m in models:
            bound = get_model(m).lam_bound
            if bound is not None and lam >= bound:
                continue
            y = getattr(history(lam, tau, model=m, fields=_hfield(field_)), _hfield(field_))
            rows += _rows(panel, m, tau, y, np.abs(y - ref) / scale)
    return rows


def _hfield(f: str) -> str:
    return "impulse" if f == "deflection" else f


# --- the figures -------------------------------------------------------------------------

def _fig03(coarse: bool) -> list[Row]:
    # delta_m^{-3/2} over lambda in [0, 100]: the tables to 5, direct integration beyond
    lams = np.concatenate([np.linspace(0.0, 5.0, 6 if coarse else 51),
                           np.geomspace(6.0, 100.0, 3 if coarse else 12)])
    ref = summary(lams)
    y_ref = ref.delta_m ** -1.5
    rows = _rows("", "exact", lams, y_ref)
    y = fm.delta_m_fit_24(lams) ** -1.5
    rows += _rows("", "fits", lams, y, np.abs(y - y_ref) / y_ref)
    return rows


def _fig04(coarse: bool) -> list[Row]:
    return _histories(("ham0", "ham1", "hunter", "reed"), "force", (0.0,), coarse, panels=("",))


def _fig05(coarse: bool) -> list[Row]:
    return _histories(("ham0", "ham1", "hunter", "reed", "linear"), "force", HISTORY_LAMS, coarse)


def _fig06(coarse: bool) -> list[Row]:
    return _vs_lambda(("ham0", "ham1", "linear", "hunter", "reed"), "F_m", _lam_grid(coarse))


def _fig07(coarse: bool) -> list[Row]:
    return _vs_lambda(("ham0", "ham1", "fits", "linear"), "tau_d", _lam_grid(coarse))


def _fig08(coarse: bool) -> list[Row]:
    lams = _lam_grid(coarse)
    ref = summary(lams)
    return (_vs_lambda(("ham0", "ham1"), "tau_dc", lams, "compression", ref)
            + _vs_lambda(("ham0", "ham1"), "tau_dr", lams, "recovery", ref))


def _fig09(coarse: bool) -> list[Row]:
    return _vs_lambda(("ham0", "ham1", "linear"), "impulse", _lam_grid(coarse))


def _fig10(coarse: bool) -> list[Row]:
    return _histories(("ham0", "ham1", "linear"), "velocity", HISTORY_LAMS, coarse)


def _fig11(coarse: bool) -> list[Row]:
    return _histories(("ham0", "ham1", "linear"), "deflection", HISTORY_LAMS, coarse)


def _fig12(coarse: bool) -> list[Row]:
    # xi = 0 at lambda = 0: the grid starts just above it so every point has a relative error
    return _vs_lambda(("ham0", "ham1", "fits", "linear"), "xi", _lam_grid(coarse, lo=0.02))


#: The quadratic of Sec. 3.5 is drawn up to this lambda (it grows as 2.36 lambda^2 beyond, off
#: the scale of every other curve; its error there is in docs/figures.md).
FIG13_FIT_MAX = 1.0


def _fig13(coarse: bool) -> list[Row]:
    rows = _vs_lambda(("ham0", "ham1", "fits", "linear"), "int_F2", _lam_grid(coarse))
    return [r for r in rows if r[1] != "fits" or r[2] <= FIG13_FIT_MAX]


#: Hunter's and Reed's half-space stress-wave loss xi = k V0^{3/5} for the Table 1 pair, k derived
#: in derivation/stress_waves.py (the paper quotes 0.0013 and 0.0058 without a derivation).
FIG14_K = {p: stress_wave_k(TABLE1_SPHERE, TABLE1_PLATE, p) for p in ("hunter", "reed")}


def _fig14(coarse: bool) -> list[Row]:
    """xi against the impact speed V0 for the paper's Table 1 pair (R = 0.9 mm), two plates.

    Besides the Zener loss (exact, Eqs. 70 and 77), Hunter's and Reed's stress-wave loss into a
    glass half-space, k V0^{3/5}: a different mechanism (the plate's flexure is absent from it),
    so it has no error against the exact Zener loss.
    """
    v0 = np.geomspace(0.1, 20.0, 7 if coarse else 41)
    rows: list[Row] = []
    for H in FIG14_THICKNESS:
        panel = f"H={H * 1e3:.3g} mm"
        lam = np.array([Scene(TABLE1_SPHERE, TABLE1_PLATE, TABLE1_RADIUS, H, v).lam for v in v0])
        ref = summary(lam).xi
        rows += _rows(panel, "exact", v0, ref)
        y70 = fm.xi_fit_70(lam)
        rows += _rows(panel, "fits", v0, y70, np.abs(y70 - ref) / ref)
        # Eq. (77): xi = chi V0^{1/5} (R/H)^2 1.78 = 2 lambda 1.78 (Eq. 76 with int F^2 -> 1.78)
        y77 = 2.0 * 1.78 * lam
        rows += _rows(panel, "fit77", v0, y77, np.abs(y77 - ref) / ref)
        for p, k in FIG14_K.items():
            rows += _rows(panel, p, v0, k * v0**0.6)
    return rows


def _fig15(coarse: bool) -> list[Row]:
    return _vs_lambda(("ham0", "ham1", "linear", "raman"), "e", _lam_grid(coarse))


_HP = tuple(f"lambda={x:g}" for x in HISTORY_LAMS)
_HT = {p: rf"$\lambda = {x:g}$" for p, x in zip(_HP, HISTORY_LAMS)}

FIGURES = {f.number: f for f in (
    FigureSpec(3, r"$\bar\delta_m^{-3/2}$ against $\lambda$; error of Eq. (24)", "lam",
               "delta_m_m32", _fig03, labels={"fits": "Eq. (24)"}),
    FigureSpec(4, r"Force history of the Hertzian impact ($\lambda = 0$)", "tau", "force", _fig04,
               error_def="max"),
    FigureSpec(5, "Contact force histories", "tau", "force", _fig05, panels=_HP, error_def="max",
               panel_titles=_HT),
    FigureSpec(6, r"Maximum contact force against $\lambda$", "lam", "F_m", _fig06),
    FigureSpec(7, r"Contact duration against $\lambda$", "lam", "tau_d", _fig07,
               labels={"fits": "Eq. (55)"}),
    FigureSpec(8, r"Compression and recovery durations against $\lambda$", "lam", "tau_dc",
               _fig08, panels=("compression", "recovery"),
               panel_titles={"compression": r"compression $\tau_{dc}$",
                             "recovery": r"recovery $\tau_{dr}$"}),
    FigureSpec(9, r"Impulse against $\lambda$", "lam", "impulse", _fig09),
    FigureSpec(10, "Sphere velocity histories", "tau", "velocity", _fig10, panels=_HP,
               error_def="max", panel_titles=_HT),
    FigureSpec(11, "Plate-centre deflection histories", "tau", "deflection", _fig11, panels=_HP,
               error_def="max", panel_titles=_HT),
    FigureSpec(12, r"Zener loss $\xi$ against $\lambda$", "lam", "xi", _fig12,
               labels={"fits": "Eq. (70)"}),
    FigureSpec(13, r"$\int_0^{\tau_d}\bar F^2\,d\tau$ against $\lambda$ (Eq. 76)", "lam", "int_F2",
               _fig13, labels={"fits": "quadratic fit (Sec. 3.5)"}),
    FigureSpec(14, r"Energy loss against impact speed (Table 1 materials, $R$ = 0.9 mm)", "V0",
               "xi", _fig14, panels=tuple(f"H={H * 1e3:.3g} mm" for H in FIG14_THICKNESS),
               xlog=True, ylog=True,
               labels={"fits": "Eq. (70)",
                       "hunter": rf"Hunter, half-space: $\xi = {FIG14_K['hunter']:.3g}\,V_0^{{3/5}}$",
                       "reed": rf"Reed, half-space: $\xi = {FIG14_K['reed']:.3g}\,V_0^{{3/5}}$"},
               panel_titles={f"H={H * 1e3:.3g} mm": rf"$H = {H / TABLE1_RADIUS:g}R$ "
                             rf"= {H * 1e3:.3g} mm" for H in FIG14_THICKNESS}),
    FigureSpec(15, r"Coefficient of restitution against $\lambda$", "lam", "e", _fig15,
               labels={"ham0": "HAM 0th order = Eq. (80)"}),
)}
#: The figure numbers, 3 to 15.
NUMBERS = tuple(FIGURES)


def _fmt(v: str | float | None) -> str:
    if v is None:
        return ""
    if isinstance(v, str):
        return v
    return f"{v:.10g}"


def to_csv(rows: Iterable[Row]) -> str:
    """The rows as CSV text (header ``COLUMNS``; numbers with 10 significant digits)."""
    lines = [",".join(COLUMNS)]
    lines += [",".join(_fmt(v) for v in r) for r in rows]
    return "\n".join(lines) + "\n"


def from_csv(text: str) -> list[Row]:
    """Rows from :func:`to_csv` text (numbers as floats, empty error as None)."""
    lines = text.strip("\n").split("\n")
    if tuple(lines[0].split(",")) != COLUMNS:
        raise ValueError(f"not a figure CSV: header {lines[0]!r}, expected {','.join(COLUMNS)}")
    out: list[Row] = []
    for ln in lines[1:]:
        p, s, x, y, e = ln.split(",")
        out.append((p, s, float(x), float(y), float(e) if e else None))
    return out
