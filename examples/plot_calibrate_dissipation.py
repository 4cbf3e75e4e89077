"""
Calibrating the dissipative constant A from measured restitution
================================================================

Between viscoelastic grains, Zener's lambda is lambda = A (rho/m_eff)^(2/5) v0^(1/5)
(:func:`zener_sym.lam_from_dissipation`), with A the material's dissipative constant [s]. Measure
the coefficient of restitution e at a few impact speeds, and :func:`zener_sym.fit_dissipation`
gives A by least squares, with its standard error and 95 % interval.

The "measurements" here are made up: e of a 1 mm steel sphere bouncing on a steel wall, computed
with A = 2e-7 s and perturbed by 1 % noise (a fixed seed, so the page is reproducible).
"""
import numpy as np

import zener_sym as zs

R = 1e-3                                   # sphere radius [m]
m = zs.STEEL.rho * 4 / 3 * np.pi * R**3    # its mass [kg]
A_true = 2e-7                              # the constant behind the made-up data [s]
v0 = np.array([0.1, 0.3, 1.0, 2.0, 4.0])   # impact speeds [m/s]

# %%
# The made-up data: the restitution of the grains (force-free end of contact) at A_true, from
# :func:`zener_sym.grain_impact`, with 1 % noise.
e_true = np.array([zs.grain_impact("steel", R, m, A=A_true, v0=v, wall="steel").e for v in v0])
rng = np.random.default_rng(26)
e_measured = e_true * (1 + 0.01 * rng.standard_normal(v0.size))
print("v0 [m/s]:  ", v0)
print("e measured:", np.round(e_measured, 4))

# %%
# The fit: least squares in ln A, the Jacobian from the exact model's Chebyshev tables. The
# sphere goes first (material, radius, mass, as in a Scene), the measured pairs by keyword.
fit = zs.fit_dissipation("steel", R, m, v0=v0, e=e_measured, wall="steel")
print(fit)
print(f"A fitted = {fit.A:.4g} s (data made with {A_true:g} s), "
      f"95 % interval {fit.A_ci[0]:.3g} .. {fit.A_ci[1]:.3g} s")

# %%
# The same A predicts e and the contact time at other speeds.
p = fit.predict(10.0)
print(f"at 10 m/s: e = {p['e']:.4f} (interval {p['e_low']:.4f} .. {p['e_high']:.4f})")

# %%
# Measured points, the fitted curve e(v0) with the band of A's interval, and the residuals, in
# the package's chart style.
fig = fit.plot(title="made-up data, 1 mm steel sphere on steel", data_label="measured (made up)")
