r"""A homotopy of Zener's equation (10) that goes past order 2: strained time (Lindstedt-Poincare).

Not part of the paper's chain. Run as ``python -m zener_sym.derivation.ham_strained``. The
numerics are in ``zener_sym.ham.higher`` (formulation ``"strained"``).

Why: the paper's expansion is about delta0, whose zero pi/omega0 is not the contact end, so
delta_j/delta0 is unbounded there and the forcing of order m goes like (pi/omega0 - tau)^{3/2-m}
(``ham_higher``). If time is strained so that every order vanishes at the same phase, the ratios
stay bounded and no order meets a singularity.

1. With phi = Omega tau and delta(tau) = E(phi)/Omega, Eq. (10) is N[E, Omega] = 0,
   N = Omega E'' + lambda Omega^{-1/2} (E^{3/2})' + Omega^{-3/2} E^{3/2}, with E(0) = 0,
   E'(0) = delta'(0) = 1, and the contact ends at phi = pi: tau_d = pi/Omega.
2. The paper's operator (12) in theta = omega0 tau is omega0^2 L, L = D^2 + 2 b D + (1 + b^2),
   b = beta/omega0; E0 = exp(-b phi) sin phi solves L E0 = 0, E0(0) = 0, E0'(0) = 1, E0(pi) = 0,
   and E0(omega0 tau)/omega0 is the paper's delta0 (35).
3. Homotopy (1 - p) L[E - E0] = c0 p N[E, Omega], E = sum E_m p^m, Omega = sum Omega_m p^m:
   L[E_m - chi_m E_{m-1}] = c0 R_m, R_m = [p^{m-1}] N, E_m(0) = E_m'(0) = 0, and E_m(pi) = 0,
   which fixes Omega_{m-1}: R_m is affine in Omega_{m-1} for m >= 2 (coefficient
   S = E0'' - (lambda/2) Omega0^{-3/2} (E0^{3/2})' - (3/2) Omega0^{-5/2} E0^{3/2}), and at m = 1
   y(pi) = 0 is c1 u^5 + lambda c2 u^2 + c3 = 0 with u^2 = Omega0. Written out for m = 1..4.
4. Local exponents at phi -> pi (s = pi - phi): E0 = a s + O(s^2), E_j = e_j s + g_j s^{5/2}
   (E_j(pi) = 0; its forcing is O(s^{1/2})): every R_m, m = 1..4, is bounded (exponent >= 0),
   against s^{3/2-m} in the paper's formulation.
"""
from __future__ import annotations

import sympy as sp

from .steps import Context, symbolic_zero

__all__ = ["derive", "MAX_ORDER"]

MAX_ORDER = 4


def derive(ctx: Context | None = None, echo=None) -> Context:
    """Derive and check items 1-4 of the module docstring; adds ``strained_R`` ({m: R_m})."""
    if ctx is None:
        ctx = Context()
        ctx.log.echo = echo
    S = ctx.symbols
    lam, k, tau, p = S["lam"], S["k"], S["tau"], S["p"]
    beta, w = S["beta"], S["omega0"]
    c0 = sp.Symbol("c_0", nonzero=True)
    phi = sp.Symbol("phi", positive=True)
    Om = sp.Symbol("Omega", positive=True)
    b = sp.Symbol("b", positive=True)
    three_half = sp.Rational(3, 2)
    M = MAX_ORDER

    # 1. strained time
    E = sp.Function("E")
    delta = E(Om * tau) / Om
    zener = delta.diff(tau, 2) + delta**three_half + lam * (delta**three_half).diff(tau)

    def N_of(f, fp, fpp, Omega):
        return Omega * fpp + lam * Omega ** sp.Rational(-1, 2) * three_half * sp.sqrt(f) * fp \
            + Omega ** sp.Rational(-3, 2) * f**three_half

    x = sp.Symbol("x", positive=True)
    Ef = E(x)
    N_phi = N_of(Ef, Ef.diff(x), Ef.diff(x, 2), Om).subs(x, Om * tau)

    def strain_ok():
        z = sp.powsimp(sp.expand_power_base(sp.expand(zener.doit()), force=True), force=True)
        n = sp.powsimp(sp.expand_power_base(sp.expand(N_phi.doit()), force=True), force=True)
        d = sp.simplify(z - n)
        return d == 0, "Eq. (10) of E(Omega tau)/Omega equals N[E, Omega]" if d == 0 else str(d)[:200]

    ctx.check("10", "delta = E(Omega tau)/Omega turns (10) into Omega E'' + lambda Omega^(-1/2) "
              "(E^(3/2))' + Omega^(-3/2) E^(3/2) = 0", "SymPy substitution", strain_ok)
    ctx.check("10", "delta(0) = E(0)/Omega, delta'(0) = E'(0): the conditions are E(0) = 0, E'(0) = 1",
              "SymPy substitution", lambda: (
                  sp.simplify(delta.diff(tau).subs(tau, 0).doit() - sp.Subs(E(x).diff(x), x, 0).doit()) == 0,
                  "delta'(tau) = E'(Omega tau)"))

    # 2. the operator and E0
    f = sp.Function("f")
    th = sp.Symbol("theta", positive=True)
    L_tau = (f(w * tau).diff(tau, 2) + k * lam * f(w * tau).diff(tau) + k * f(w * tau)).doit()
    Lf = lambda g, v: g.diff(v, 2) + 2 * b * g.diff(v) + (1 + b**2) * g  # noqa: E731
    L_th = Lf(f(th), th).subs(th, w * tau).doit()

    def op_ok():
        sub = {lam: 2 * beta / k, k: beta**2 + w**2}
        d = sp.simplify((L_tau - w**2 * L_th).subs(b, beta / w).subs(lam, 2 * beta / k).subs(sub))
        return d == 0, "L_tau[f(omega0 tau)] = omega0^2 L_theta[f] with k = beta^2 + omega0^2, k lambda = 2 beta"

    ctx.check("12", "the paper's operator (12) in theta = omega0 tau is omega0^2 (D^2 + 2 b D + 1 + b^2), "
              "b = beta/omega0", "SymPy substitution", op_ok)
    E0 = sp.exp(-b * phi) * sp.sin(phi)
    ctx.check("35", "E0 = exp(-b phi) sin phi: L E0 = 0, E0(0) = 0, E0'(0) = 1, E0(pi) = 0, and "
              "E0(omega0 tau)/omega0 = delta0 (35)", "SymPy", lambda: (
                  symbolic_zero(Lf(E0, phi))[0] and E0.subs(phi, 0) == 0
                  and E0.diff(phi).subs(phi, 0) == 1 and E0.subs(phi, sp.pi) == 0
                  and sp.simplify((E0.subs(phi, w * tau) / w).subs(b, beta / w)
                                  - sp.exp(-beta * tau) * sp.sin(w * tau) / w) == 0, "all four hold"))

    # 3. deformation equations, derivatives as symbols (algebraic series in p)
    D = [[sp.Symbol(f"E{j}_{n}", positive=(j == 0 and n == 0)) for n in range(3)] for j in range(M + 1)]
    Oms = [sp.Symbol(f"Omega_{j}", positive=(j == 0)) for j in range(M + 1)]
    ph = [sum(D[j][n] * p**j for j in range(M + 1)) for n in range(3)]
    Omp = sum(Oms[j] * p**j for j in range(M + 1))
    N_alg = N_of(ph[0], ph[1], ph[2], Omp)
    Lj = lambda j: D[j][2] + 2 * b * D[j][1] + (1 + b**2) * D[j][0]  # noqa: E731
    hom = (1 - p) * (sum(Lj(j) * p**j for j in range(M + 1)) - Lj(0)) - c0 * p * N_alg
    ser = sp.expand(sp.series(hom, p, 0, M + 1).removeO())
    N_ser = sp.expand(sp.series(N_alg, p, 0, M).removeO())
    R = {m: N_ser.coeff(p, m - 1) for m in range(1, M + 1)}
    for m in range(1, M + 1):
        want = Lj(m) - (Lj(m - 1) if m >= 2 else 0) - c0 * R[m]
        ctx.check(f"s{m}", f"order p^{m}: L[E_{m} - chi E_{m-1}] = c0 R_{m}, R_{m} = [p^{m-1}] N "
                  f"(uses Omega_0..Omega_{m-1})", "SymPy series in p",
                  lambda m=m, want=want: (symbolic_zero(ser.coeff(p, m) - want)[0]
                                          and all(Oms[j] not in R[m].free_symbols for j in range(m, M + 1)),
                                          "equal; no Omega_j with j >= m"))
    Sm = (D[0][2] - lam / 2 * Oms[0] ** sp.Rational(-3, 2) * three_half * sp.sqrt(D[0][0]) * D[0][1]
          - three_half * Oms[0] ** sp.Rational(-5, 2) * D[0][0] ** three_half)
    for m in range(2, M + 1):
        ctx.check(f"s{m}", f"R_{m} is affine in Omega_{m-1} with coefficient S = E0'' - (lambda/2) "
                  f"Omega0^(-3/2) (E0^(3/2))' - (3/2) Omega0^(-5/2) E0^(3/2)", "SymPy diff",
                  lambda m=m: (sp.diff(R[m], Oms[m - 1], 2) == 0
                               and symbolic_zero(sp.diff(R[m], Oms[m - 1]) - Sm)[0], "affine, slope S"))
    u = sp.Symbol("u", positive=True)
    c1, c2, c3 = sp.symbols("c1 c2 c3")
    # y(pi) of R_1 is linear in the three forcings: Omega0 c1 + lambda Omega0^(-1/2) c2 + Omega0^(-3/2) c3
    r1 = (Oms[0] * c1 + lam * Oms[0] ** sp.Rational(-1, 2) * c2 + Oms[0] ** sp.Rational(-3, 2) * c3)
    ctx.check("s1", "R_1 = Omega0 E0'' + lambda Omega0^(-1/2) (E0^(3/2))' + Omega0^(-3/2) E0^(3/2); "
              "y(pi) = 0 times Omega0^(3/2) is c1 u^5 + lambda c2 u^2 + c3 = 0, u^2 = Omega0",
              "SymPy", lambda: (
                  symbolic_zero(R[1] - (Oms[0] * D[0][2] + lam * Oms[0] ** sp.Rational(-1, 2) * three_half
                                        * sp.sqrt(D[0][0]) * D[0][1] + Oms[0] ** sp.Rational(-3, 2)
                                        * D[0][0] ** three_half))[0]
                  and symbolic_zero(sp.expand((r1 * Oms[0] ** three_half).subs(Oms[0], u**2))
                                    - (c1 * u**5 + lam * c2 * u**2 + c3))[0], "both hold"))

    # 4. boundedness at phi -> pi, s = sigma^2, d/dphi = -(1/(2 sigma)) d/dsigma
    sg = sp.Symbol("sigma", positive=True)
    aa, a2 = sp.Symbol("a", positive=True), sp.Symbol("a_2")
    e_, g_ = sp.symbols(f"e1:{M + 1}"), sp.symbols(f"g1:{M + 1}")
    loc = [aa * sg**2 + a2 * sg**4] + [e_[j - 1] * sg**2 + g_[j - 1] * sg**5 for j in range(1, M + 1)]
    dphi = lambda g: -sp.diff(g, sg) / (2 * sg)  # noqa: E731
    vals = {}
    for j in range(M + 1):
        vals[D[j][0]], vals[D[j][1]], vals[D[j][2]] = loc[j], dphi(loc[j]), dphi(dphi(loc[j]))
    exps = {}

    def bounded(m):
        e = R[m].subs(vals)
        e = sp.powsimp(sp.expand_power_base(e, force=True), force=True)
        lead = sp.expand(sp.series(e, sg, 0, 3).removeO())
        pw = min((t.as_coeff_exponent(sg)[1] for t in sp.Add.make_args(lead) if t != 0), default=3)
        exps[m] = sp.Rational(pw, 2)
        return pw >= 0, f"leading power s^({sp.Rational(pw, 2)}): bounded"

    for m in range(1, M + 1):
        ctx.check(f"s{m}", f"R_{m} is bounded at phi -> pi when every E_j vanishes there", "SymPy "
                  "series in sqrt(s)", lambda m=m: bounded(m))
    ctx.expr.update(strained_R=R, strained_exponents=exps)
    return ctx


if __name__ == "__main__":  # pragma: no cover
    c = derive(echo=print)
    print(f"{'OK' if c.log.ok else 'FAILED'}: {len(c.log.steps)} steps")
