"""The linearized contact law (Mueller et al. 2015) and Raman's small-lambda restitution, derived.

Not part of the paper's derivation chain (``registry.PARTS``): the two systems the paper compares
its solution with in Figs. 5, 6, 9 and 15. Run ``python -m zener_sym.derivation.linear``.

Linear law. Replacing the Hertz force delta^{3/2} of Eq. (10) by kappa delta gives the damped
oscillator

    delta'' + kappa lambda delta' + kappa delta = 0,   delta(0) = 0,  delta'(0) = 1,

beta = kappa lambda / 2, omega = sqrt(kappa - beta^2) (underdamped while kappa lambda^2 < 4):

    delta = exp(-beta tau) sin(omega tau) / omega,     tau_d = pi / omega,
    tau_dc = atan2(omega, beta) / omega,               delta_m = exp(-beta tau_dc) / sqrt(kappa),
    e = exp(-pi beta / omega),  F = kappa delta,       F_m = sqrt(kappa) exp(-beta tau_dc),
    I(tau) = 1 - delta'(tau) - lambda kappa delta(tau) (so I(tau_d) = 1 + e),
    int_0^tau_d F^2 dtau = (1 - e^2) / (2 lambda)      (the energy balance, checked by integration).

At kappa lambda^2 >= 4 delta never returns to 0: the contact does not end (e = 0 is no answer of
the model, so the model refuses lambda >= 2 / sqrt(kappa)).

The stiffness kappa is not fixed by the linearization. The natural choices, each matching one
property of the Hertz impact (lambda = 0), all derived here:

    duration     pi / sqrt(kappa) = tau_H = (4/5)(5/4)^{2/5} B(2/5, 1/2)
    compression  1 / sqrt(kappa) = delta_mH = (5/4)^{2/5}   (equivalently the stored energy:
                 kappa delta_mH^2 / 2 = 1/2 = (2/5) delta_mH^{5/2})
    force        kappa / sqrt(kappa) = F_mH = delta_mH^{3/2}
    secant       kappa = delta_mH^{1/2}  (the HAM's k at lambda = 0, Eq. 25)
    unit         kappa = 1 (F-bar = delta-bar in Zener's scaling; bound lambda < 2)
    dissipation  (pi / 2) sqrt(kappa) = c1 (the same small-lambda slope of e as Eq. 10)

Raman. The energy balance of Eq. (10) is exact: 1 - e^2 = 2 lambda int F^2 dtau (the plate takes
lambda F^2 per unit time). At lambda -> 0 the force is the Hertz pulse, so
e = sqrt(1 - 2 lambda (J + O(lambda))) = 1 - c1 lambda + O(lambda^2) with

    c1 = J = int_0^{tau_H} F_H^2 dtau = 2 int_0^{delta_mH} delta^3 / sqrt(1 - (4/5) delta^{5/2}) d delta
       = (5/4)^{3/5} B(8/5, 1/2) = (5/4)^{3/5} sqrt(pi) Gamma(8/5) / Gamma(21/10) = 1.7302...

(the substitution u = (4/5) delta^{5/2} turns the integral into a Beta function).
"""
from __future__ import annotations

import sys

import mpmath
import sympy as sp

from .steps import MP_DPS, Context, mp_max_rel_residual, symbolic_zero

__all__ = ["derive", "RAMAN_C1", "TAU_HERTZ", "DELTA_M_HERTZ", "STIFFNESS", "RAMAN_C1_DIGITS"]

_R = sp.Rational
#: Hertz's maximum compression (Eq. 23): 1 - (4/5) delta^{5/2} = 0.
DELTA_M_HERTZ = _R(5, 4) ** _R(2, 5)
#: Hertz's contact duration tau_H = 2 int_0^dm d delta / sqrt(1 - (4/5) delta^{5/2}).
TAU_HERTZ = _R(4, 5) * _R(5, 4) ** _R(2, 5) * sp.gamma(_R(2, 5)) * sp.sqrt(sp.pi) / sp.gamma(_R(9, 10))
#: Raman's slope: e = 1 - RAMAN_C1 lambda + O(lambda^2); c1 = int F_Hertz^2 dtau.
RAMAN_C1 = _R(5, 4) ** _R(3, 5) * sp.sqrt(sp.pi) * sp.gamma(_R(8, 5)) / sp.gamma(_R(21, 10))
#: c1 to 30 significant digits (checked in ``derive`` against a direct quadrature).
RAMAN_C1_DIGITS = str(sp.N(RAMAN_C1, 30))

#: The linear law's natural stiffness choices (name -> exact kappa), see the module docstring.
STIFFNESS = {
    "duration": (sp.pi / TAU_HERTZ) ** 2,
    "compression": DELTA_M_HERTZ ** -2,
    "force": DELTA_M_HERTZ ** 3,
    "secant": sp.sqrt(DELTA_M_HERTZ),
    "unit": sp.Integer(1),
    "dissipation": (2 * RAMAN_C1 / sp.pi) ** 2,
}


def _hertz_quad(power):
    """2 int_0^dm delta^power / sqrt(1 - (4/5) delta^{5/2}) d delta by mpmath quadrature.

    With delta = dm s, s^{5/2} = 1 - v^2, 1 - v = t^5 the integrand becomes a polynomial in t
    times a smooth power, which tanh-sinh integrates to full precision (an independent route to
    the Beta-function closed forms)."""
    with mpmath.workdps(MP_DPS + 10):
        dm = mpmath.power(mpmath.mpf(5) / 4, mpmath.mpf(2) / 5)
        q = (2 * mpmath.mpf(power) - 3) / 5
        # x = 1 - v = t^5 removes the endpoint power: (x (2 - x))^q dx = 5 t^(5q+4) (2 - t^5)^q dt
        f = lambda t: 5 * t ** (5 * q + 4) * (2 - t**5) ** q  # noqa: E731
        return 2 * dm ** (power + 1) * mpmath.mpf(4) / 5 * mpmath.quad(f, [0, 1])


def derive(ctx: Context | None = None) -> Context:
    """Derive and check the linear law's closed forms and Raman's c1; returns the context with
    ``ctx.expr`` holding ``delta_lin``, ``tau_d_lin``, ``tau_dc_lin``, ``delta_m_lin``,
    ``e_lin``, ``F_m_lin``, ``impulse_lin``, ``int_F2_lin``, ``raman_c1``, ``kappa_<choice>``."""
    ctx = ctx or Context()
    tau = ctx.symbols["tau"]
    lam = sp.Symbol("lambda", positive=True)
    kap = sp.Symbol("kappa", positive=True)
    b, w = sp.symbols("beta omega", positive=True)
    # kappa = beta^2 + omega^2 and lambda = 2 beta / kappa express everything in (beta, omega)
    to_bw = {kap: b**2 + w**2, lam: 2 * b / (b**2 + w**2)}
    E = ctx.expr

    delta = sp.exp(-b * tau) * sp.sin(w * tau) / w
    E["delta_lin"] = delta
    ode = delta.diff(tau, 2) + (kap * lam * delta.diff(tau) + kap * delta).subs(to_bw)
    ctx.check("lin", "delta = exp(-beta tau) sin(omega tau)/omega solves delta'' + kappa lambda "
              "delta' + kappa delta = 0 with beta = kappa lambda/2, omega^2 = kappa - beta^2",
              "SymPy simplification", lambda: symbolic_zero(ode))
    ctx.check("lin", "delta(0) = 0 and delta'(0) = 1", "SymPy substitution",
              lambda: (delta.subs(tau, 0) == 0 and sp.simplify(delta.diff(tau).subs(tau, 0) - 1) == 0,
                       "both hold"))

    tau_d = sp.pi / w
    E["tau_d_lin"] = tau_d
    ctx.check("lin", "delta(pi/omega) = 0 (and sin(omega tau) > 0 before): tau_d = pi/omega",
              "SymPy substitution", lambda: symbolic_zero(delta.subs(tau, tau_d)))
    e = -delta.diff(tau).subs(tau, tau_d)
    e_closed = sp.exp(-sp.pi * b / w)
    E["e_lin"] = e_closed
    ctx.check("lin", "e = -delta'(tau_d) = exp(-pi beta/omega)", "SymPy simplification",
              lambda: symbolic_zero(e - e_closed))

    # compression ends at delta' = 0: there cos(omega t) = beta/sqrt(kappa), sin = omega/sqrt(kappa)
    phi = sp.atan2(w, b)
    tau_dc = phi / w
    E["tau_dc_lin"] = tau_dc
    rk = sp.sqrt(b**2 + w**2)
    ddot = delta.diff(tau)
    at_dc = ddot.subs({sp.cos(w * tau): b / rk, sp.sin(w * tau): w / rk}).subs(tau, tau_dc)
    ctx.check("lin", "delta'(tau_dc) = 0 at tau_dc = atan2(omega, beta)/omega", "SymPy, "
              "cos(omega tau_dc) = beta/sqrt(kappa)", lambda: symbolic_zero(sp.expand(at_dc)))
    delta_m = sp.exp(-b * tau_dc) / rk
    E["delta_m_lin"], E["F_m_lin"] = delta_m, rk**2 * delta_m

    def dm_numeric():
        f = sp.lambdify((b, w, tau), delta, "mpmath")
        pts = [(mpmath.mpf(bb), mpmath.mpf(ww)) for bb, ww in [(0.1, 1.0), (0.5, 0.8), (0.9, 0.3)]]
        worst = 0
        with mpmath.workdps(MP_DPS):
            for bb, ww in pts:
                t = mpmath.atan2(ww, bb) / ww
                worst = max(worst, abs(f(bb, ww, t) - mpmath.exp(-bb * t) / mpmath.sqrt(bb**2 + ww**2)))
        return worst < mpmath.mpf(10) ** (-MP_DPS + 5), f"max |delta(tau_dc) - closed form| = {mpmath.nstr(worst, 3)}"
    ctx.check("lin", "delta_m = delta(tau_dc) = exp(-beta tau_dc)/sqrt(kappa), F_m = kappa delta_m",
              f"mpmath at {MP_DPS} digits, three (beta, omega)", dm_numeric)

    impulse = 1 - delta.diff(tau) - (lam * kap).subs(to_bw) * delta
    E["impulse_lin"] = impulse
    ctx.check("lin", "I(tau) = 1 - delta' - lambda kappa delta has I' = F = kappa delta",
              "SymPy simplification",
              lambda: symbolic_zero(impulse.diff(tau) - (kap * delta).subs(to_bw)))
    ctx.check("lin", "I(0) = 0", "SymPy substitution",
              lambda: symbolic_zero(impulse.subs(tau, 0)))
    ctx.check("lin", "I(tau_d) = 1 + e", "SymPy simplification",
              lambda: symbolic_zero(impulse.subs(tau, tau_d) - 1 - e_closed))

    intF2 = sp.integrate(((kap * delta) ** 2).subs(to_bw), (tau, 0, tau_d))
    intF2 = sp.simplify(intF2)
    E["int_F2_lin"] = intF2
    ctx.check("lin", "int_0^tau_d F^2 dtau = (1 - e^2)/(2 lambda) (energy balance)",
              "SymPy integration and simplification",
              lambda: symbolic_zero(intF2 - ((1 - e_closed**2) / (2 * lam)).subs(to_bw),
                                    rewrite_trig=True))

    # --- Hertz constants and the stiffness choices ---------------------------------------
    def tau_h():
        with mpmath.workdps(MP_DPS):
            ref = _hertz_quad(0)
            val = sp.N(TAU_HERTZ, MP_DPS)
            return mp_max_rel_residual(lambda _: mpmath.mpf(str(val)), lambda _: ref, [0],
                                       1e-30)
    ctx.check("2", "tau_H = (4/5)(5/4)^(2/5) Gamma(2/5) sqrt(pi)/Gamma(9/10) (Hertz duration)",
              f"mpmath quadrature at {MP_DPS} digits", tau_h)
    for name, kappa in STIFFNESS.items():
        E[f"kappa_{name}"] = kappa

    # --- Raman: c1 = J = int F_Hertz^2 ---------------------------------------------------
    u = sp.Symbol("u", positive=True)
    dm = DELTA_M_HERTZ
    # delta = (5u/4)^{2/5}; d delta = (2/5)(5/4)^{2/5} u^{-3/5} du; delta^3 = (5/4)^{6/5} u^{6/5}
    # delta = dm (1 - v^2)... is the quadrature's route; the closed form's route: u = (4/5) delta^{5/2}
    dlt = (_R(5, 4) * u) ** _R(2, 5)
    integrand_u = (2 * dlt**3 / sp.sqrt(1 - _R(4, 5) * dlt ** _R(5, 2)) * dlt.diff(u))
    beta_form = 2 * _R(2, 5) * _R(5, 4) ** _R(8, 5) * u ** _R(3, 5) / sp.sqrt(1 - u)
    ctx.check("raman", "u = (4/5) delta^(5/2) turns 2 delta^3 d delta / sqrt(1 - (4/5) delta^(5/2)) into "
              "(4/5)(5/4)^(8/5) u^(3/5) (1 - u)^(-1/2) du", "SymPy simplification",
              lambda: symbolic_zero(sp.powsimp(integrand_u - beta_form, force=True)))
    ctx.check("raman", "(4/5)(5/4)^(8/5) B(8/5, 1/2) = (5/4)^(3/5) sqrt(pi) Gamma(8/5)/Gamma(21/10)",
              "SymPy gammasimp",
              lambda: symbolic_zero(sp.gammasimp(_R(4, 5) * _R(5, 4) ** _R(8, 5) * sp.gamma(_R(8, 5))
                                                 * sp.gamma(_R(1, 2)) / sp.gamma(_R(21, 10))
                                                 - RAMAN_C1)))
    def c1_quad():
        with mpmath.workdps(MP_DPS):
            ref = _hertz_quad(3)
            val = mpmath.mpf(str(sp.N(RAMAN_C1, MP_DPS)))
            ok, det = mp_max_rel_residual(lambda _: val, lambda _: ref, [0], 1e-30)
            return ok, det + f"; c1 = {mpmath.nstr(ref, 30)}"
    ctx.check("raman", "c1 agrees with a direct quadrature of int F_H^2 over the Hertz pulse to 30 "
              "digits", f"mpmath tanh-sinh at {MP_DPS} digits", c1_quad)

    Jsym, a = sp.symbols("J a", positive=True)
    e_series = sp.series(sp.sqrt(1 - 2 * lam * (Jsym + a * lam)), lam, 0, 2).removeO()
    ctx.check("raman", "e = sqrt(1 - 2 lambda int F^2) with int F^2 = J + O(lambda) gives "
              "e = 1 - J lambda + O(lambda^2)", "SymPy series",
              lambda: symbolic_zero(e_series - (1 - Jsym * lam)))

    def linear_slope():
        # each linear law's own slope: e_lin = exp(-pi beta/omega) = 1 - (pi/2) sqrt(kappa) lambda + ..
        e_l = sp.exp(-sp.pi * (kap * lam / 2) / sp.sqrt(kap - (kap * lam / 2) ** 2))
        s1 = sp.series(e_l, lam, 0, 2).removeO()
        ok, det = symbolic_zero(s1 - (1 - sp.pi * sp.sqrt(kap) / 2 * lam))
        ok2, _ = symbolic_zero(sp.pi * sp.sqrt(STIFFNESS["dissipation"]) / 2 - RAMAN_C1)
        return ok and ok2, det + "; the 'dissipation' stiffness matches c1"
    ctx.check("raman", "linear law: e = 1 - (pi/2) sqrt(kappa) lambda + O(lambda^2)", "SymPy series",
              linear_slope)
    return ctx


def main() -> int:
    from .steps import format_step

    ctx = derive()
    for s in ctx.log.steps:
        print(format_step(s))
    print(f"c1 = {RAMAN_C1_DIGITS}")
    for name, kappa in STIFFNESS.items():
        print(f"kappa_{name} = {sp.N(kappa, 17)}  (lambda bound 2/sqrt(kappa) = "
              f"{sp.N(2 / sp.sqrt(kappa), 12)})")
    print("OK" if ctx.log.ok else "FAILED")
    return 0 if ctx.log.ok else 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
