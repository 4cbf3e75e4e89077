"""
Work against precision
======================

How long does a model take for a summary, and how far is it from the exact solution? This is a
cheap version of ``zener-sym bench`` (docs/benchmarks.md): a few models timed on 20 lambdas in
[0.05, 2], with their largest relative error in the peak force F_m against a reference: Zener's
equation integrated by scipy at rtol = 1e-13 (independent of the exact model's Chebyshev
tables, which are timed too). The exact model integrated at two looser tolerances shows what
each digit costs.
"""
import time

import numpy as np

import zener_sym as zs
from zener_sym.plot import style

lams = np.linspace(0.05, 2.0, 20)
reference = zs.summary(lams, model="exact", rtol=1e-13).F_m


def timed(fn, repeat):
    """The result of ``fn()`` and the smallest wall time of ``repeat`` calls (the least disturbed
    by other processes)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return out, min(times)


runs = {"exact": {}, "ham0": {}, "ham1": {}, "linear": {}}
for rtol in (1e-6, 1e-9):
    runs[f"exact rtol={rtol:g}"] = {"rtol": rtol}

points = {}
for name, options in runs.items():
    model = name.split()[0]
    # integrations take milliseconds per lambda: one run is timed well enough
    fields, t = timed(lambda: zs.summary(lams, model=model, **options), 1 if options else 5)
    t /= lams.size
    err = np.max(np.abs(fields.F_m - reference) / reference)
    points[name] = (err, t)
    print(f"{name:18s} max rel. error in F_m {err:9.2e}   {t * 1e6:9.2f} us per lambda")

# %%
# The chart: lower left is better. The exact model read from its tables is both the most
# accurate and among the fastest (its error is the tables' and the reference's together);
# direct integration pays for each digit.
with style.rc() as plt:
    fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH, 2.6), layout="constrained")
    for name, (err, t) in points.items():
        kw = style.style_for(name)
        kw.update(marker=kw["marker"] or "o", linestyle="none")
        ax.plot([err], [t * 1e6], **kw)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"max. relative error in $\bar F_m$")
    ax.set_ylabel("time per lambda (µs)")
    style.legend_outside(ax, where="right")
