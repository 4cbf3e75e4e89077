"""LAMMPS's viscoelastic Hertz contact (``hertz/material`` with ``damping viscoelastic``) mapped
onto Zener's equation (10) in its grain reading, both directions.

LAMMPS's GRANULAR package (``pair_style granular`` and ``fix wall/gran granular``) computes the
normal force of a contact with overlap delta, overlap rate delta' = -v_n (v_n = (v_i - v_j).n),
contact radius a = sqrt(R_eff delta), effective radius R_eff (R_i on a flat wall) and effective
mass m_eff = m_i m_j/(m_i + m_j) (m_i on a wall) as

    F = (4/3) E_mix a delta + eta_n0 m_eff a delta',

with the ``hertz/material`` coefficients (E, eta_n0, nu) of the ``pair_coeff`` or ``fix`` line:
E_mix = 1/((1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j) between two types, E/(2 (1 - nu^2)) for one type
with itself and for a wall (LAMMPS takes the wall to be of the particle's material), and the
damping coefficient eta_n0 [1/(s m)] mixed between types as sqrt(eta_i eta_j). The grain contact
that ``derivation.viscoelastic`` maps onto Eq. (10) is

    F = rho (delta^{3/2} + A d/dt delta^{3/2}),   rho = (4/3) E* sqrt(R_eff).

SymPy shows, term for term, that the two are the same force iff E_mix = E* and

    eta_n0 = 2 E* A / m_eff,   A = eta_n0 m_eff / (2 E*),

so lambda(v) = A (rho/m_eff)^{2/5} v^{1/5} in LAMMPS's terms. A ``pair_coeff * *`` or wall line
with (E_L, nu_L) has E_mix = E_L/(2 (1 - nu_L^2)); E_L = 2 (1 - nu_L^2) E* gives any E* (a pair
of two materials, or a sphere on a wall of another material), and E_L = E for a sphere of one
material on itself. ``limit_damping`` clips a negative (attractive) total force to 0: after the
force first vanishes in recovery, the free flight keeps delta + (3/2) A delta' < 0 until
delta = 0, so the grains leave with the speed they had where the force vanished: the force-free
end (``contact_end="force"``). Without it, contact lasts to delta = 0 (``"delta"``).
"""
from __future__ import annotations

import sympy as sp

from .steps import Context, run_script, symbolic_zero

__all__ = ["derive", "LAMMPS_SYMBOLS", "main"]

_pos = dict(positive=True)
#: The symbols of LAMMPS's contact and of the grain reading (SI units).
LAMMPS_SYMBOLS = {
    "E_L": sp.Symbol("E_L", **_pos), "nu_L": sp.Symbol("nu_L", positive=True),
    "eta0": sp.Symbol("eta_n0", **_pos), "m": sp.Symbol("m_eff", **_pos),
    "R": sp.Symbol("R_eff", **_pos), "Estar": sp.Symbol("E^*", **_pos),
    "A": sp.Symbol("A", **_pos), "v": sp.Symbol("v", **_pos),
    "E1": sp.Symbol("E_1", **_pos), "E2": sp.Symbol("E_2", **_pos),
    "nu1": sp.Symbol("nu_1", **_pos), "nu2": sp.Symbol("nu_2", **_pos),
}
_M, _L, _S = sp.symbols("M L S", positive=True)
_DIM = {"E_L": _M / _L / _S**2, "Estar": _M / _L / _S**2, "E1": _M / _L / _S**2,
        "E2": _M / _L / _S**2, "eta0": 1 / (_L * _S), "m": _M, "R": _L, "A": _S, "v": _L / _S}


def _dimension(expr: sp.Expr) -> sp.Expr:
    P = LAMMPS_SYMBOLS
    scaled = expr.subs({P[n]: P[n] * d for n, d in _DIM.items()}, simultaneous=True)
    return sp.simplify(sp.powsimp(sp.powdenest(scaled / expr, force=True), force=True))


def mix_pair(E1, nu1, E2, nu2):
    """LAMMPS's ``mix_stiffnessE``: the effective modulus of two particle types."""
    return 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)


def mix_wall(E, nu):
    """LAMMPS's ``mix_stiffnessE_wall``: a particle on a wall of its own material."""
    return E / (2 * (1 - nu**2))


def derive(ctx: Context | None = None) -> Context:
    """Derive the mapping; adds ``eta0_of_A``, ``A_of_eta0``, ``lam_of_eta0``, ``E_lammps`` to
    ``ctx.expr`` and returns the context."""
    ctx = ctx if ctx is not None else Context()
    P = LAMMPS_SYMBOLS
    E_L, nu_L, eta0, m, R, Es, A, v = (P[n] for n in ("E_L", "nu_L", "eta0", "m", "R", "Estar",
                                                        "A", "v"))
    E1, E2, nu1, nu2 = P["E1"], P["E2"], P["nu1"], P["nu2"]
    d, dd = sp.symbols("delta delta_dot", real=True)
    dpos = sp.Symbol("delta", positive=True)
    E_mix, rho, eta = sp.symbols("E_mix rho eta", positive=True)

    # LAMMPS (hertz/material + damping viscoelastic): k = (4/3) E_mix, a = sqrt(R delta),
    # F = k a delta + eta0 m_eff a delta'.
    a = sp.sqrt(R * dpos)
    F_lammps = sp.Rational(4, 3) * E_mix * a * dpos + eta * m * a * dd
    # The grain reading: rho (delta^{3/2} + A d/dt delta^{3/2}), with
    # d/dt delta^{3/2} = (3/2) sqrt(delta) delta'.
    F_grain = rho * (dpos ** sp.Rational(3, 2) + A * sp.Rational(3, 2) * sp.sqrt(dpos) * dd)
    diff = sp.expand(F_lammps - F_grain)
    c32 = diff.coeff(dpos ** sp.Rational(3, 2)).subs(dd, 0)
    c12 = sp.expand(diff).coeff(sp.sqrt(dpos) * dd)
    sol = sp.solve([c32, c12], [rho, eta], dict=True)
    rho_sol = sol[0][rho] if len(sol) == 1 else None
    eta_sol = sol[0][eta] if len(sol) == 1 else None
    eta_of_A = 2 * Es * A / m
    A_of_eta = eta0 * m / (2 * Es)

    ctx.check("L1", "LAMMPS's F = (4/3) E_mix sqrt(R delta) delta "
              "+ eta_n0 m_eff sqrt(R delta) delta' "
              "equals rho (delta^(3/2) + A (delta^(3/2))') for every (delta, delta') iff "
              "rho = (4/3) E_mix sqrt(R_eff) and eta_n0 = 2 E_mix A / m_eff",
              "SymPy: coefficients of delta^(3/2) and sqrt(delta) delta' solved",
              lambda: (rho_sol is not None
                       and sp.simplify(rho_sol - sp.Rational(4, 3) * E_mix * sp.sqrt(R)) == 0
                       and sp.simplify(eta_sol - eta_of_A.subs(Es, E_mix)) == 0,
                       f"rho = {rho_sol}, eta_n0 = {eta_sol}"))

    def substitution():
        back = (F_lammps - F_grain).subs({rho: sp.Rational(4, 3) * E_mix * sp.sqrt(R),
                                          eta: eta_of_A.subs(Es, E_mix)})
        return symbolic_zero(back)

    ctx.check("L1", "substituting back: F_LAMMPS - F_grain = 0 identically", "SymPy simplify",
              substitution)
    ctx.check("L2", "inverse: A = eta_n0 m_eff / (2 E*), and the round trips A -> eta_n0 -> A and "
              "eta_n0 -> A -> eta_n0 are the identity", "SymPy simplify",
              lambda: (sp.simplify(A_of_eta.subs(eta0, eta_of_A) - A) == 0
                       and sp.simplify(eta_of_A.subs(A, A_of_eta) - eta0) == 0, "identity"))

    rho_h = sp.Rational(4, 3) * Es * sp.sqrt(R)
    lam_grain = A * (rho_h / m) ** sp.Rational(2, 5) * v ** sp.Rational(1, 5)
    lam_eta = sp.simplify(lam_grain.subs(A, A_of_eta))
    lam_closed = (eta0 / 2 * (sp.Rational(4, 3)) ** sp.Rational(2, 5) * m ** sp.Rational(3, 5)
                  * Es ** sp.Rational(-3, 5) * R ** sp.Rational(1, 5) * v ** sp.Rational(1, 5))
    ctx.check("L3", "lambda in LAMMPS's terms: lambda = (eta_n0/2) (4/3)^(2/5) m_eff^(3/5) "
              "E*^(-3/5) "
              "R_eff^(1/5) v^(1/5)", "SymPy simplify of A (rho/m_eff)^(2/5) v^(1/5)",
              lambda: (sp.simplify(sp.powsimp(lam_eta / lam_closed, force=True)) == 1,
                       f"lambda = {lam_closed}"))

    E_lammps = 2 * (1 - nu_L**2) * Es
    ctx.check("L4", "a pair_coeff * * or wall line with E_L = 2 (1 - nu_L^2) E* has E_mix = E* "
              "(LAMMPS's mix_stiffnessE(E_L, E_L, nu_L, nu_L) and mix_stiffnessE_wall(E_L, nu_L))",
              "SymPy simplify",
              lambda: (sp.simplify(mix_pair(E_lammps, nu_L, E_lammps, nu_L) - Es) == 0
                       and sp.simplify(mix_wall(E_lammps, nu_L) - Es) == 0, "both equal E*"))
    ctx.check("L4", "a sphere of one material (E, nu) on itself or on a wall of that material: "
              "E_L = 2 (1 - nu^2) E* = E", "SymPy simplify",
              lambda: (sp.simplify(E_lammps.subs({Es: mix_pair(E1, nu1, E1, nu1), nu_L: nu1})
                                   - E1) == 0
                       and sp.simplify(E_lammps.subs({Es: mix_wall(E1, nu1), nu_L: nu1}) - E1) == 0,
                       "E_L = E"))
    ctx.check("L4", "two materials: E_L = 2 (1 - nu_L^2) / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) "
              "reproduces LAMMPS's own two-type mixing", "SymPy simplify",
              lambda: symbolic_zero(mix_wall(E_lammps.subs(Es, mix_pair(E1, nu1, E2, nu2)), nu_L)
                                    - mix_pair(E1, nu1, E2, nu2)))

    units = {"eta_n0": (eta_of_A, _DIM["eta0"]), "A": (A_of_eta, _S), "lambda": (lam_closed, 1),
             "E_L": (E_lammps, _DIM["E_L"])}

    def units_ok():
        bad = {n: _dimension(e) for n, (e, want) in units.items()
               if sp.simplify(_dimension(e) / want) != 1}
        return not bad, "all homogeneous" if not bad else f"wrong: {bad}"

    ctx.check("L2", "units: eta_n0 in 1/(s m) (LAMMPS's doc), A in s, lambda dimensionless, "
              "E_L in Pa",
              "scale every symbol by its dimension, SymPy simplify", units_ok)

    # limit_damping: LAMMPS sets a negative total force to 0. Where the force first vanishes in
    # recovery (delta1 > 0, delta' = u < 0, delta1 = -(3/2) A u), free flight delta = delta1 + u s
    # keeps delta + (3/2) A delta' = u s < 0 for s > 0: the force stays clipped until delta = 0.
    u = sp.Symbol("u", negative=True)
    s = sp.Symbol("s", positive=True)
    delta1 = -sp.Rational(3, 2) * A * u
    free = (delta1 + u * s) + sp.Rational(3, 2) * A * u
    ctx.check("L5", "limit_damping is the force-free end: after F = 0 in recovery, free flight "
              "keeps "
              "delta + (3/2) A delta' = u s < 0 (u < 0 the rate), so F stays clipped to 0 until "
              "delta = 0 and e is the speed where F vanished", "SymPy simplify and sign",
              lambda: (sp.simplify(free - u * s) == 0 and (u * s).is_negative is True,
                       f"delta + (3/2) A delta' = {sp.simplify(free)}"))

    ctx.expr.update(eta0_of_A=eta_of_A, A_of_eta0=A_of_eta, lam_of_eta0=lam_closed,
                    E_lammps=E_lammps)
    ctx.eq("L1", sp.Symbol(r"\eta_{n0}"), eta_of_A, "LAMMPS's viscoelastic damping coefficient")
    ctx.eq("L2", sp.Symbol("A"), A_of_eta, "the dissipative constant of a LAMMPS contact")
    ctx.eq("L4", sp.Symbol("E_L"), E_lammps,
           "the E of a pair_coeff * * or wall line for a given E*")
    return ctx


def main() -> int:  # pragma: no cover - command line
    return run_script(derive)


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
