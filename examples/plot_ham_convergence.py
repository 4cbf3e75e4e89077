"""
Does the homotopy series converge?
==================================

The paper stops at the first order of the homotopy (HAM) series. The model ``ham`` continues it:
``zs.summary(lam, model="ham", order=M, formulation="strained", c0=-1)`` is the strained-time
homotopy to order M (docs/ham_convergence.md). Here its relative error against the exact solution
in the contact duration tau_d, the restitution e and the peak force F_m, for M = 1 to 8 at
lambda = 1.01.
"""
import numpy as np

import zener_sym as zs
from zener_sym.plot import style

lam = 1.01
exact = zs.summary(lam)
orders = np.arange(1, 9)
quantities = ("tau_d", "e", "F_m")
errors = {q: [] for q in quantities}
for M in orders:
    s = zs.summary(lam, model="ham", order=int(M), formulation="strained", c0=-1.0)
    for q in quantities:
        errors[q].append(abs(getattr(s, q) - getattr(exact, q)) / abs(getattr(exact, q)))
for q in quantities:
    print(q, " ".join(f"{v:.1e}" for v in errors[q]))

# %%
# The errors fall with the order, roughly geometrically: the series converges at this lambda.
markers = {"tau_d": "o", "e": "s", "F_m": "^"}
with style.rc() as plt:
    fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH, 2.4), layout="constrained")
    color = style.style_for("ham")["color"]
    for q in quantities:
        ax.semilogy(orders, errors[q], marker=markers[q], color=color,
                    linestyle={"tau_d": "-", "e": "--", "F_m": ":"}[q], label=style.label(q))
    ax.set_xlabel("order $M$")
    ax.set_ylabel(style.error_label())
    ax.set_title(rf"strained-time HAM, $c_0 = -1$, $\lambda = {lam}$")
    style.legend_outside(ax, where="right")
