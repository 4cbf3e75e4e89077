"""
Calibrating the dissipative constant A from measured restitution
================================================================

Between viscoelastic grains, Zener's lambda is lambda = A (rho/m_eff)^(2/5) v0^(1/5)
(:func:`zener_sym.viscoelastic_lambda`), with A the material's dissipative constant [s]. Measure
the coefficient of restitution e at a few impact speeds, and A follows by least squares.

.. note::
   A fitting function, ``zs.fit_dissipation``, is being added to the package; this script does
   the same fit by hand with :func:`scipy.optimize.minimize_scalar`, so that every step shows.

The "measurements" here are made up: e of a 1 mm steel sphere bouncing on a steel wall, computed
with A = 2e-7 s and perturbed by 1 % noise (a fixed seed, so the page is reproducible).
"""
import numpy as np
from scipy.optimize import minimize_scalar

import zener_sym as zs
from zener_sym.plot import style

R = 1e-3                                   # sphere radius [m]
m = zs.STEEL.rho * 4 / 3 * np.pi * R**3    # its mass [kg]
A_true = 2e-7                              # the constant behind the made-up data [s]
v0 = np.array([0.1, 0.3, 1.0, 2.0, 4.0])   # impact speeds [m/s]

# %%
# :func:`zener_sym.grain_impact` gives the contact's constants (effective mass m_eff and Hertz
# constant rho); :func:`zener_sym.viscoelastic_lambda` then maps any A and speed to lambda, and
# the restitution of the grains (force-free end of contact) is one vectorised
# :func:`zener_sym.summary` call per trial A.
contact = zs.grain_impact(R, m, "steel", A=1e-6, v0=1.0, wall="steel")
lam_per_A = zs.viscoelastic_lambda(1.0, contact.rho, contact.m_eff, v0)


def restitution(A):
    return zs.summary(A * lam_per_A, contact_end="force").e


rng = np.random.default_rng(26)
e_measured = restitution(A_true) * (1 + 0.01 * rng.standard_normal(v0.size))
print("v0 [m/s]:  ", v0)
print("e measured:", np.round(e_measured, 4))

# %%
# The fit: minimise the squared misfit in e over log10(A), bounded to a plausible range.
fit = minimize_scalar(lambda logA: np.sum((restitution(10.0**logA) - e_measured) ** 2),
                      bounds=(-8, -4), method="bounded", options={"xatol": 1e-4})
A_fit = 10.0**fit.x
print(f"A fitted = {A_fit:.4g} s (data made with {A_true:g} s), "
      f"rms misfit in e = {np.sqrt(fit.fun / v0.size):.2g}")

# %%
# Measured points and the fitted curve e(v0): restitution falls with speed as v0^(1/5) raises
# lambda.
v = np.geomspace(0.05, 6.0, 25)
lam_v = zs.viscoelastic_lambda(A_fit, contact.rho, contact.m_eff, v)
with style.rc() as plt:
    fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH, 2.4), layout="constrained")
    ax.semilogx(v, zs.summary(lam_v, contact_end="force").e, color="black",
                label=rf"fit, $A = {A_fit * 1e6:.3g}$ µs")
    ax.semilogx(v0, e_measured, "o", color=style.style_for("ham1")["color"],
                label="measured (made up)")
    ax.set_xlabel(style.label("V0"))
    ax.set_ylabel(style.label("e"))
    style.legend_outside(ax)
