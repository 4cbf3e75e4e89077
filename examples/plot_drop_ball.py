"""
A steel ball dropped on a glass plate
=====================================

A 5 mm steel ball (radius 2.5 mm) falls 0.5 m onto a 2 mm glass plate. :class:`zener_sym.Scene`
turns the sphere, the plate and the drop height into Zener's lambda, picks the cheapest model
that meets the accuracy asked for, and gives the results in SI units.
"""
import numpy as np

import zener_sym as zs
from zener_sym.plot import style

scene = zs.Scene("steel", "glass", radius="2.5 mm", thickness="2 mm", drop_height="0.5 m")
r = scene.result()
print(f"lambda = {r.lam:.4g}, model {r.model!r}")
print(f"e = {r.e:.4f}, contact {r.contact_duration_s * 1e6:.2f} us, peak force {r.max_force_N:.1f} N")

# %%
# The force history in newtons, against time in microseconds, drawn in the package style
# (:func:`zener_sym.plot.style.style_for` gives the exact solution's black line and label).
t = np.linspace(0.0, 1.1 * r.contact_duration_s, 400)
with style.rc() as plt:
    fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH, 2.4), layout="constrained")
    ax.plot(t * 1e6, r.force(t), **style.style_for("exact"))
    ax.set_xlabel(style.label("t_us"))
    ax.set_ylabel(style.label("force_N"))
    ax.set_title(rf"steel on glass, $\lambda = {r.lam:.3g}$, $e = {r.e:.3f}$")
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
