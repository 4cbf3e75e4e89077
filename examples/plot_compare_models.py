"""
Comparing the models
====================

:func:`zener_sym.compare` evaluates every model at one lambda, side by side, with each value's
relative error against the exact solution of Zener's equation (10). Here at lambda = 1.01, one of
the paper's history figures.
"""
import numpy as np

import zener_sym as zs
from zener_sym.plot import style

cmp = zs.compare(1.01, quantities=("tau_d", "e", "F_m", "xi"))
print(cmp.to_markdown())

# %%
# The relative errors as a chart: one group of bars per quantity, one colour per model (the
# package style fixes a model's colour in every chart). A missing bar is a quantity the model
# cannot give (Hunter's and Reed's pulses have no restitution).
models = [row.model for row in cmp if row.model != "exact"]
quantities = cmp.quantities
width = 0.8 / len(models)
with style.rc() as plt:
    fig, ax = plt.subplots(figsize=(style.PAGE_WIDTH, 2.6), layout="constrained")
    x = np.arange(len(quantities))
    for i, name in enumerate(models):
        err = [cmp[name].errors.get(q) for q in quantities]
        err = np.array([np.nan if v is None else v for v in err], dtype=float)
        kw = style.style_for(name)
        ax.bar(x + (i - (len(models) - 1) / 2) * width, err, width, color=kw["color"],
               label=kw["label"])
    ax.set_yscale("log")
    ax.set_xticks(x, [style.label(q) for q in quantities])
    ax.set_ylabel(style.error_label())
    ax.set_title(r"every model against the exact solution, $\lambda = 1.01$")
    style.legend_outside(ax, where="right")
