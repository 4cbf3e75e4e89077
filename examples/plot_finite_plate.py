"""
A ball dropped on a 100 mm plate
================================

A steel ball (radius 2.5 mm) falls 5 cm onto a 1 mm glass plate clamped at radius 100 mm.
Zener's model assumes an infinite plate. Given the plate's size and support,
:meth:`zener_sym.Scene.result` checks whether that assumption holds to the accuracy asked for.
Where it does not, it solves the bounded plate (model ``finite-plate``) and reports every contact.
"""
import numpy as np

import zener_sym as zs
from zener_sym.plot import style

scene = zs.Scene("steel", "glass", radius="2.5 mm", thickness="1 mm", drop_height="5 cm",
                 plate_radius="100 mm", support="clamped")
r = scene.result(rtol=1e-3)
zener = scene.result(model="exact", warn=False)
print(f"lambda = {scene.lam:.3g}, beta = {scene.beta:.3g}: model {r.model!r}")
print(r.reason)
print(f"e = {r.e:.3f} after {len(r.contacts)} contacts; Zener's infinite plate: e = {zener.e:.4f}")
for k, c in enumerate(r.contacts, 1):
    print(f"  contact {k}: {c.start_s * 1e6:7.1f} to {c.end_s * 1e6:7.1f} us, "
          f"peak {c.max_force_N:6.2f} N, ball leaves at {c.speed_after_m_s:.4f} m/s")

# %%
# The first contact is Zener's. Then the plate, which Zener's model lets absorb the impact for
# good, rings: its centre comes back up and strikes the slowly receding ball again, several
# times, before the ball leaves for good.
t = np.linspace(0.0, 1.05 * r.contacts[-1].end_s, 3000)
with style.rc() as plt:
    fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH, 2.4), layout="constrained")
    zen = style.style_for("exact")
    zen["label"] = "Zener, infinite plate"
    ax.plot(t * 1e6, zener.force(t), **{**zen, "marker": None})
    ax.plot(t * 1e6, r.force(t), **{**style.style_for("finite-plate"), "marker": None})
    ax.set_xlabel(style.label("t_us"))
    ax.set_ylabel(style.label("force_N"))
    ax.set_title(f"glass 1 mm clamped at 100 mm: $e$ = {r.e:.3f} (Zener {zener.e:.3f})")
    ax.set_xlim(left=0.0)
    style.legend_outside(ax)
