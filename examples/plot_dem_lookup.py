"""
A lookup table for a DEM code
=============================

A discrete-element code that integrates viscoelastic grains needs, for every collision, the
coefficient of restitution e and the contact time. With lambda = A (rho/m_eff)^(2/5) v0^(1/5)
(:func:`zener_sym.lam_from_dissipation`) it can interpolate both in a table over lambda.
:func:`zener_sym.scene.lookup.lookup_table` computes it; ``contact_end="force"`` ends the contact
where the viscoelastic force vanishes, as between grains (docs/viscoelastic.md). The command line
``zener-sym table --quantity e,tau_d --lam 0:5:1001 --contact-end force --csv`` writes the same
table as CSV.
"""
import numpy as np

from zener_sym.plot import style
from zener_sym.scene.lookup import lookup_csv, lookup_table

grains = lookup_table(("e", "tau_d"), "0:3:31", contact_end="force")
plate = lookup_table(("e", "tau_d"), "0:3:31", contact_end="delta")
print(lookup_csv(lookup_table(("e", "tau_d"), "0:1:5", contact_end="force")))

# %%
# A DEM code interpolates in the table; linear interpolation on this coarse grid is already close
# to a direct evaluation at lambda = 0.37:
lam = 0.37
e_interp = np.interp(lam, grains["lam"], grains["e"])
e_direct = lookup_table(("e",), [lam], contact_end="force")["e"][0]
print(f"e({lam}) interpolated {e_interp:.5f}, computed {e_direct:.5f}")

# %%
# The two ends of contact side by side: the grains separate earlier (the force-free end), with a
# higher restitution than the plate criterion delta = 0 gives.
with style.rc() as plt:
    fig, (a, b) = plt.subplots(1, 2, figsize=(style.PAGE_WIDTH, 2.4), layout="constrained")
    for table, ls, what in ((grains, "-", "force-free end (grains)"),
                            (plate, "--", r"$\delta = 0$ end (plate)")):
        a.plot(table["lam"], table["e"], color="black", linestyle=ls, label=what)
        b.plot(table["lam"], table["tau_d"], color="black", linestyle=ls, label=what)
    a.set_xlabel(style.label("lam"))
    a.set_ylabel(style.label("e"))
    b.set_xlabel(style.label("lam"))
    b.set_ylabel(style.label("tau_d"))
    style.legend_outside(fig)
