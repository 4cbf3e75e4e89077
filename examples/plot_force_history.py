"""
Force history charts
====================

:func:`zener_sym.plot.force_history` draws the contact force of several models over the contact,
with the exact solution as the black reference line. Given a lambda it draws the dimensionless
force F-bar = delta^(3/2) (Eq. 45) against tau; given a :class:`zener_sym.Scene` it draws newtons
against microseconds.
"""
import zener_sym as zs
from zener_sym.plot import force_history, style

ax = force_history(1.51, model=("ham0", "ham1", "linear"))

# %%
# The same chart for a scene: the paper's Table 1 pair (an alumina sphere of radius 0.9 mm on a
# 0.5 mm glass plate at 5 m/s), where the first-order HAM solution is close to the exact one.
scene = zs.Scene("table1-sphere", "table1-plate", radius="0.9 mm", thickness="0.5 mm",
                 v0="5 m/s")
print(f"lambda = {scene.lam:.4f}")
ax = force_history(scene, model=("ham1", "hunter"))

# %%
# Both panels in one figure: pass the axes to draw on.
with style.rc() as plt:
    fig, (a, b) = plt.subplots(1, 2, figsize=(style.PAGE_WIDTH, 2.6), layout="constrained")
    force_history(0.11, model="ham1", ax=a, legend=False)
    force_history(1.99, model="ham1", ax=b, legend=False)
    style.legend_outside(fig)
