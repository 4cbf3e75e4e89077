"""Work-precision data: each method's error against the reference and its time per lambda."""
from __future__ import annotations

import csv
import pathlib
from collections.abc import Callable, Sequence
from typing import TypedDict

import numpy as np

from ..typing import FloatArray
from . import reference as ref_mod
from .methods import Method
from .timing import timed

CHART_QUANTITIES = ("force_history",) + ref_mod.QUANTITIES


class WorkRow(TypedDict):
    """One method's result on one quantity (a row of work_precision.csv)."""

    method: str
    family: str
    #: one of ``ref_mod.QUANTITIES`` or "force_history"
    quantity: str
    #: NaN when the method failed
    max_rel_error: float
    seconds_per_lambda: float
    #: "ok", "non-finite values" or the exception's "Type: message"
    status: str
    #: how many reference lambdas the error is over
    lambdas: int


def measure(methods: Sequence[Method], ref: ref_mod.Reference, quick: bool = False,
            log: Callable[[str], object] = print) -> list[WorkRow]:
    """Rows (method, family, quantity, max_rel_error, seconds_per_lambda, status, lambdas)."""
    lams = np.array(ref["lambdas"], dtype=float)
    keys = [repr(float(x)) for x in ref["lambdas"]]
    taus = [np.array(ref["tau"][k]) for k in keys]
    rows: list[WorkRow] = []
    min_total = 0.05 if quick else 0.3
    for m in methods:
        summary_fn = m.summary
        if summary_fn is not None:
            vals: dict[str, FloatArray]
            try:
                vals, t = timed(lambda: summary_fn(lams), min_repeats=1 if quick else 3,
                                min_total=min_total)
                status = "ok"
            except Exception as exc:  # recorded, charted as a failure
                vals, t, status = {}, float("nan"), f"{type(exc).__name__}: {exc}"[:200]
            for q in ref_mod.QUANTITIES:
                if q not in vals and status == "ok":
                    continue
                err = float("nan")
                used = len(lams)
                if q in vals:
                    r = np.array([ref["summary"][k][q] for k in keys])
                    v = np.asarray(vals[q], dtype=float)
                    used = int(np.isfinite(v).sum())  # NaN: lambda outside the model's validity
                    err = float(np.nanmax(np.abs(v - r) / np.abs(r))) if used else float("nan")
                rows.append(WorkRow(method=m.name, family=m.family, quantity=q,
                                    max_rel_error=err, seconds_per_lambda=t / max(used, 1),
                                    status=status, lambdas=used))
        force_fn = m.force
        if force_fn is not None:
            stride = m.extra.get("stride", 1)  # slow methods: every stride-th point, time scaled
            sub = [t[::stride] for t in taus]
            try:
                fs, t = timed(lambda: force_fn(lams, sub), min_repeats=1 if quick else 3,
                              min_total=min_total)
                t *= stride
                errs = []
                for k, f in zip(keys, fs):
                    r = np.array(ref["force"][k])
                    errs.append(np.max(np.abs(np.asarray(f) - r[::stride])) / np.max(r))
                err, status = float(np.max(errs)), "ok"
                if not np.isfinite(err):
                    status = "non-finite values"
            except Exception as exc:
                err, t, status = float("nan"), float("nan"), f"{type(exc).__name__}: {exc}"[:200]
            rows.append(WorkRow(method=m.name, family=m.family, quantity="force_history",
                                max_rel_error=err, seconds_per_lambda=t / len(lams),
                                status=status, lambdas=len(lams)))
        log(f"  {m.name}: done")
    return rows


def write_csv(rows: Sequence[WorkRow], path: pathlib.Path) -> None:
    """The rows as CSV (floats to 6 significant digits)."""
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


#: Math-text names of the charted quantities.
_Q_LABEL = {"force_history": r"$\max|\bar F-\bar F_{\rm ref}|/\bar F_m$", "tau_d": r"$\tau_d$",
            "e": r"$e$", "F_m": r"$\bar F_m$", "impulse": r"$\bar I(\tau_d)$",
            "delta_m": r"$\bar\delta_m$", "xi": r"$\xi$"}


def charts(rows: Sequence[WorkRow], out: pathlib.Path, source: str) -> list[pathlib.Path]:
    """One log-log chart per quantity: error (x) against time per lambda (y), in the package
    style (a fixed colour and marker per method family, legend right of the data)."""
    from ..plot import style as st

    plt = st.pyplot(headless=True)

    paths = []
    for q in CHART_QUANTITIES:
        with plt.rc_context(st.RC):
            fig, ax = plt.subplots(figsize=(st.PAGE_WIDTH * 0.62, 3.0))
            fams: dict[str, list[WorkRow]] = {}
            for r in rows:
                if r["quantity"] == q and r["status"] == "ok" and np.isfinite(r["max_rel_error"]):
                    fams.setdefault(r["family"], []).append(r)
            for fam, rs in sorted(fams.items()):
                x = [max(r["max_rel_error"], 1e-17) for r in rs]
                y = [r["seconds_per_lambda"] for r in rs]
                kw = st.style_for(fam)
                if len(rs) == 1:
                    kw["linestyle"] = "none"
                if not kw.get("marker"):
                    kw["marker"] = "o"  # the exact model's line has none; a point needs one
                ax.loglog(x, y, **kw)
            what = _Q_LABEL.get(q, q)
            ax.set_xlabel(f"max relative error of {what}" if q != "force_history" else what
                          + r" over $\lambda\in[0, 2.4]$")
            ax.set_ylabel("seconds per $\\lambda$ (median)")
            ax.set_title(f"Work-precision: {what}   (reference: {source})", fontsize=7)
            ax.grid(True, which="both", alpha=0.25)
            st.legend_outside(ax, where="right")
            p = out / f"work_precision_{q}.png"
            st.save(fig, p.with_suffix(""), ("png",))
            plt.close(fig)
        paths.append(p)
    return paths
