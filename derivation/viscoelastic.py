"""Zener's equation (10) read as the viscoelastic Hertz contact of two grains, and its force-free end.

The viscoelastic sphere contact (Kuwabara & Kono 1987; Brilliantov, Spahn, Hertzsch & Poeschel
1996) is

    m_eff xi'' + rho (xi^{3/2} + A d/dt xi^{3/2}) = 0,   xi(0) = 0,  xi'(0) = v0,

with xi the mutual compression (overlap), m_eff the effective mass, rho = (4/3) E* sqrt(R_eff) the
Hertz constant and A (a time, seconds) the dissipative constant of the material. SymPy shows that
xi = X delta(t/T) with

    T = (m_eff/rho)^{2/5} v0^{-1/5},   X = v0 T,   lambda = A/T = A (rho/m_eff)^{2/5} v0^{1/5}

turns it into Eq. (10), delta'' + (1 + lambda d/dtau) delta^{3/2} = 0, delta(0) = 0, delta'(0) = 1,
term for term; the substitution back is checked, and so are the units (lambda dimensionless).

The contact force on a grain is F = rho (xi^{3/2} + A (xi^{3/2})') = (m_eff v0/T) F_c with

    F_c = delta^{3/2} + lambda (delta^{3/2})' = delta^{1/2} (delta + (3/2) lambda delta'),

which is negative (attractive) in recovery once delta < -(3/2) lambda delta'. Grains cannot pull,
so they separate where F_c = 0 (Schwager & Poeschel 2008): the force-free end is the first
tau > tau_dc with delta + (3/2) lambda delta' = 0, and the coefficient of restitution is
e = -delta'(tau_d) there. The plate reading (this package's default) ends at delta = 0, where the
Hertz force delta^{3/2} vanishes; the two ends coincide at lambda = 0. In the grain reading the
impulse is the integral of F_c, 1 - delta'(tau) (because F_c = -delta''), so I(tau_d) = 1 + e
holds at the force-free end too.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from .steps import Context, run_script, symbolic_zero

__all__ = ["derive", "GRAIN_SYMBOLS", "main"]

_pos = dict(positive=True)
#: Physical symbols of the grain contact (SI units).
GRAIN_SYMBOLS = {
    "m": sp.Symbol("m_eff", **_pos), "rho": sp.Symbol("rho", **_pos), "A": sp.Symbol("A", **_pos),
    "v0": sp.Symbol("v_0", **_pos), "Estar": sp.Symbol("E^*", **_pos), "R": sp.Symbol("R_eff", **_pos),
    "t": sp.Symbol("t", **_pos),
}
_M, _L, _S = sp.symbols("M L S", positive=True)
_DIM = {"m": _M, "rho": _M * _L ** sp.Rational(-1, 2) / _S**2, "A": _S, "v0": _L / _S,
        "Estar": _M / _L / _S**2, "R": _L, "t": _S}


def _dimension(expr):
    P = GRAIN_SYMBOLS
    scaled = expr.subs({P[n]: P[n] * d for n, d in _DIM.items()}, simultaneous=True)
    return sp.simplify(sp.powsimp(sp.powdenest(scaled / expr, force=True), force=True))


def derive(ctx: Context | None = None) -> Context:
    """Derive the mapping; adds ``T_grain``, ``X_grain``, ``lam_grain``, ``F_grain_scale``,
    ``rho_hertz``, ``force_free`` to ``ctx.expr`` and returns the context."""
    ctx = ctx if ctx is not None else Context()
    P = GRAIN_SYMBOLS
    m, rho, A, v0, Es, R, t = (P[n] for n in ("m", "rho", "A", "v0", "Estar", "R", "t"))
    T, X, lam = sp.symbols("T X lambda", positive=True)
    D = sp.Function("D")
    x = sp.Symbol("x", positive=True)

    xi = X * D(t / T)
    grain = m * xi.diff(t, 2) + rho * (xi ** sp.Rational(3, 2) + A * (xi ** sp.Rational(3, 2)).diff(t))
    g = sp.expand(grain.subs(t, T * x).doit())
    Dpp, D32, DhDd = D(x).diff(x, 2), D(x) ** sp.Rational(3, 2), sp.sqrt(D(x)) * D(x).diff(x)
    c_pp, c_32, c_d = g.coeff(Dpp), g.coeff(D32), g.coeff(DhDd)
    # delta'(0) = 1 fixes X = v0 T; the coefficients of delta'' and delta^{3/2} equal fixes T.
    T_sol = [r for r in sp.solve(sp.Eq(c_pp.subs(X, v0 * T), c_32.subs(X, v0 * T)), T) if r.is_positive]
    T_expr = (m / rho) ** sp.Rational(2, 5) * v0 ** sp.Rational(-1, 5)
    X_expr = v0 * T_expr
    lam_expr = sp.simplify((c_d / c_32 * sp.Rational(2, 3)).subs({X: X_expr, T: T_expr}))
    lam_closed = A * (rho / m) ** sp.Rational(2, 5) * v0 ** sp.Rational(1, 5)

    ctx.check("10", "xi = X delta(t/T) with X = v0 T maps m xi'' + rho (xi^(3/2) + A (xi^(3/2))') = 0 "
              "onto Eq. (10) iff T = (m/rho)^(2/5) v0^(-1/5)", "SymPy substitution and solve",
              lambda: (len(T_sol) == 1 and sp.simplify(T_sol[0] / T_expr - 1) == 0, f"T = {T_sol}"))
    ctx.check("10", "lambda = A/T = A (rho/m_eff)^(2/5) v0^(1/5)", "SymPy simplify",
              lambda: (sp.simplify(lam_expr - lam_closed) == 0 and sp.simplify(A / T_expr - lam_closed) == 0,
                       f"lambda = {lam_closed}"))

    def back():
        # Substitute back: the grain equation equals (m v0/T) times Eq. (10) with lambda as found.
        d = sp.Function("delta")
        tau = sp.Symbol("tau", positive=True)
        eq10 = d(tau).diff(tau, 2) + d(tau) ** sp.Rational(3, 2) + lam * (d(tau) ** sp.Rational(3, 2)).diff(tau)
        lhs = grain.subs(X, X_expr).subs(T, T_expr).subs(t, T_expr * tau).doit()
        lhs = lhs.subs(D(tau * T_expr / T_expr), d(tau))
        rhs = (m * v0 / T_expr * eq10).subs(lam, lam_closed)
        diff = sp.simplify(sp.powsimp(sp.expand(lhs.subs(D(tau), d(tau)) - rhs), force=True))
        # and the initial slope: xi'(0) = X delta'(0)/T = v0 delta'(0)
        slope = sp.simplify(X_expr / T_expr - v0)
        return diff == 0 and slope == 0, f"difference simplifies to {diff}; xi'(0) - v0 delta'(0) = {slope}"

    ctx.check("10", "substituting back: grain equation = (m v0/T) x Eq. (10), xi'(0) = v0", "SymPy", back)

    F_scale = rho * X_expr ** sp.Rational(3, 2)
    ctx.check("43", "force scale rho X^(3/2) = m_eff v0/T (the impulse scale is m_eff v0)", "SymPy",
              lambda: (sp.simplify(F_scale / (m * v0 / T_expr)) == 1, "equal"))

    units = {"T_grain": (T_expr, _S), "X_grain": (X_expr, _L), "lam_grain": (lam_closed, 1),
             "F_grain_scale": (F_scale, _M * _L / _S**2), "rho_hertz": (sp.Rational(4, 3) * Es * sp.sqrt(R), _DIM["rho"])}

    def units_ok():
        bad = {n: _dimension(e) for n, (e, want) in units.items() if sp.simplify(_dimension(e) / want) != 1}
        return not bad, "all homogeneous with the expected dimension" if not bad else f"wrong: {bad}"

    ctx.check("7-11", "units of T, X, lambda, force scale, rho = (4/3) E* sqrt(R_eff) (A in seconds)",
              "scale every symbol by its dimension, SymPy simplify", units_ok)

    # The force-free end.
    dl, dd = sp.symbols("delta delta_dot", positive=True)
    Fc = dl ** sp.Rational(3, 2) + lam * sp.Rational(3, 2) * sp.sqrt(dl) * (-dd)  # delta' = -dd < 0
    ctx.check("SP08", "F_c = delta^(3/2) + lambda (delta^(3/2))' = sqrt(delta) (delta + (3/2) lambda delta'): "
              "with delta > 0 it vanishes iff delta = -(3/2) lambda delta'", "SymPy factor and solve",
              lambda: (sp.simplify(Fc - sp.sqrt(dl) * (dl - sp.Rational(3, 2) * lam * dd)) == 0
                       and sp.solve(Fc, dl) == [sp.Rational(3, 2) * lam * dd],
                       f"root delta = {sp.solve(Fc, dl)}"))

    # Energy of the grain reading: on solutions of Eq. (10), d/dtau (delta'^2/2 + (2/5) delta^(5/2))
    # = -(3/2) lambda delta^(1/2) delta'^2 <= 0: the dashpot only dissipates, also where F_c < 0.
    tau = sp.Symbol("tau", positive=True)
    dfun = sp.Function("delta")(tau)
    Fc_tau = dfun ** sp.Rational(3, 2) + lam * (dfun ** sp.Rational(3, 2)).diff(tau)
    energy = dfun.diff(tau) ** 2 / 2 + sp.Rational(2, 5) * dfun ** sp.Rational(5, 2)
    rate = energy.diff(tau).subs(dfun.diff(tau, 2), -Fc_tau)
    ctx.check("10", "energy balance of the grain: d/dtau (delta'^2/2 + (2/5) delta^(5/2)) = "
              "-(3/2) lambda sqrt(delta) delta'^2 on solutions of Eq. (10)", "SymPy",
              lambda: symbolic_zero(rate + sp.Rational(3, 2) * lam * sp.sqrt(dfun) * dfun.diff(tau) ** 2))

    def numeric_example():
        # glass beads (Table 1 sphere) 1 mm radius, A = 1e-7 s, 1 m/s: lambda by the closed form
        # against A/T with T from the mapping, at 30 digits.
        vals = {m: mpmath.mpf("5.236e-6"), rho: mpmath.mpf("2.4e8"), A: mpmath.mpf("1e-7"), v0: mpmath.mpf(1)}
        with mpmath.workdps(30):
            a = sp.N(lam_closed.subs(vals), 30)
            b = sp.N((A / T_sol[0]).subs(vals), 30)
        return abs(a - b) < 1e-25 * abs(a), f"lambda = {sp.N(a, 12)} for m = 5.236e-6 kg, rho = 2.4e8, A = 1e-7 s, v0 = 1 m/s"

    ctx.check("10", "closed form and A/T agree numerically", "mpmath at 30 digits", numeric_example)

    ctx.expr.update(T_grain=T_expr, X_grain=X_expr, lam_grain=lam_closed, F_grain_scale=F_scale,
                    rho_hertz=sp.Rational(4, 3) * Es * sp.sqrt(R), force_free=sp.Eq(dl, sp.Rational(3, 2) * lam * dd))
    ctx.eq("G1", sp.Symbol("T"), T_expr, "time scale of the grain contact")
    ctx.eq("G2", sp.Symbol(r"\lambda"), lam_closed, "inelasticity parameter of the grain contact")
    ctx.eq("G3", sp.Symbol(r"\bar F_c"), sp.sqrt(sp.Symbol(r"\delta")) * (sp.Symbol(r"\delta") + sp.Rational(3, 2) * lam * sp.Symbol(r"\delta'")),
           "viscoelastic contact force (zero at the force-free end)")
    return ctx


def main() -> int:  # pragma: no cover - command line
    return run_script(derive)


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
