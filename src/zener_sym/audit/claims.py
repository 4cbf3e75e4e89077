"""The paper's numeric claims, each checked against an independent reference.

The reference is the exact Zener ODE (10) integrated by :mod:`zener_sym.exact.solver` (accurate to about
1e-10), not the paper's FEM: the claims are about approximations of Eq. (10), so the ODE is the
right yardstick; where the paper's wording names its FEM, the note says so. Rounded constants are
compared with the derived value at the printed number of digits. Claims about the HAM models use
the registered ``ham0``/``ham1`` models when present, and are ``not-checkable`` otherwise.
"""
from __future__ import annotations

import functools

import mpmath as mp
import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ..exact import solver as _exact
from . import derived as D
from . import printed as P
from .printed import SYM
from .texts import tex
from .verdicts import rounds_to

lam = SYM["lam"]
CLAIMS: dict = {}

#: lambda grid of the HAM-range claims (the HAM models need lambda below about 2.442).
LAM_HAM = np.round(np.linspace(0.0, 2.4, 25), 10)


def claim(name):
    def deco(fn):
        CLAIMS["claim:" + name] = fn
        return fn
    return deco


@functools.lru_cache(maxsize=None)
def _exact_summary(lams: tuple):
    import zener_sym as zs
    return zs.summary(np.array(lams), model="exact")


def delta_m_exact(lam_value: float, rtol: float = 1e-11) -> float:
    """delta_m of Eq. (10) by integrating the compression phase only (cheap at large lambda).

    Same phases as :func:`zener_sym.exact.solver.solve` (u = sqrt(delta) from the start, then tau), but
    stopping at the end of compression, whose duration stays short when lambda is large.
    """
    lv = float(lam_value)
    atols = np.array([1e-15, 1e-300, 1e-15])
    u_cap = min(1.2, lv ** (-1.0 / 3.0)) if lv > 0 else 1.2

    def v_half(u, y):
        return y[1] - lv * u**3 - 0.5

    v_half.terminal, v_half.direction = True, -1
    s1 = solve_ivp(_exact._rhs_u(lv), (0.0, u_cap), [0.0, 1.0, 0.0], method="DOP853", rtol=rtol,
                   atol=atols, events=v_half)
    u1 = float(s1.t_events[0][0])
    tau1, w1, J1 = s1.y_events[0][0]

    def v_zero(t, y):
        dd = max(y[0], 0.0)
        return y[1] - lv * dd * np.sqrt(dd)

    v_zero.terminal, v_zero.direction = True, -1
    s2 = solve_ivp(_exact._rhs_tau(lv), (tau1, tau1 + 100.0), [u1 * u1, w1, J1], method="DOP853",
                   rtol=rtol, atol=atols, events=v_zero)
    return float(s2.y_events[0][0][0])


def _n(claim_name, i=0) -> str:
    """The i-th printed number of a claim, as printed (a string)."""
    return P.numbers(P.by_id("claim:" + claim_name))[i]


def _f(claim_name, i=0) -> float:
    return float(_n(claim_name, i))


def _printed_fn(item_id):
    """The printed formula of an equation item as a numpy function of lambda."""
    return sp.lambdify(lam, P.parse(P.by_id(item_id)), modules="numpy")


def _np(name):
    expr, src = D.get(name)
    return sp.lambdify(lam, expr, modules="numpy"), src


def _result(holds, derived, evidence, note=""):
    return ("claim-holds" if holds else "claim-fails", derived, evidence, note)


def _pct(x, dec: int) -> str:
    return f"{100 * x:.{dec}f}%"


def bound_readings(worst: float, printed: str) -> tuple[bool, str]:
    """Both readings of a printed bound "less than <printed>" (a fraction such as '0.0290').

    Strict: the largest error, measured to more digits than printed, is below the bound (this
    reading gives the verdict). To the printed digits: the largest error rounded to the printed
    number of decimals equals the printed figure (the paper's figure is then its measurement).
    Returns (strict verdict, one sentence with both readings).
    """
    dec = max(len(printed.split(".")[1]) - 2, 0) if "." in printed else 0  # decimals in percent
    bound = float(printed)
    strict = worst < bound
    shown = _pct(worst, dec)
    agrees = round(100 * worst, dec) == round(100 * bound, dec)
    below = round(100 * worst, dec) <= round(100 * bound, dec)
    text = (f"Read strictly, {_pct(worst, dec + 2)} is {'below' if strict else 'not below'} "
            f"{_pct(bound, dec)}; to the printed digits it is {shown}, "
            + ("the printed figure itself" if agrees else
               "within the printed figure" if below else "above the printed figure"))
    return strict, text


@claim("tau_Hertz")
def _tau_hertz():
    dm0, src = D.get("dm_lam0")
    val = sp.Float("2.94") * dm0  # (2) in the scales (9): t_Hertz / T = 2.94 delta_m / (T V0)
    ok, ev = rounds_to(val, _n("tau_Hertz"))
    ex = _exact_summary((0.0,)).tau_d[0]
    return _result(ok, f"$2.94\\,(5/4)^{{2/5}} = {float(val):.6f}$",
                   f"(2) in the derived scales: {ev}. The exact contact duration of (10) at "
                   f"$\\lambda = 0$ is {float(ex):.6f}. Derived form: {src}.",
                   "holds as arithmetic on (2); the exact Hertz value is 3.218 (2.94 is rounded)")


@claim("tau_d0")
def _tau_d0():
    f, src = D.get("tau_d0_of_lam")
    val = sp.N(f.subs(lam, 0), 20)
    ok, ev = rounds_to(val, _n("tau_d0"))
    return _result(ok, f"$\\pi/\\omega_0(0) = {float(val):.6f}$",
                   f"$\\tau_d = \\pi/\\omega_0$ of (54) at $\\lambda = 0$: {ev}. Derived form: {src}.")


@claim("omega0_lam0")
def _omega0():
    w, src = D.get("omega0_lam0")
    ok, ev = rounds_to(sp.N(w, 20), _n("omega0_lam0"))
    return _result(ok, f"$(5/4)^{{1/10}} = {float(sp.N(w)):.6f}$",
                   f"$\\omega_0 = \\sqrt{{k(0)}}$: {ev}. Derived form: {src}.")


@claim("lambda_bound")
def _lam_bound():
    kl, src = D.get("k_of_lam")
    g = sp.lambdify(lam, 4 / kl - lam**2, modules="mpmath")
    with mp.workdps(30):
        root = mp.findroot(g, 2.4)
    ok, ev = rounds_to(root, _n("lambda_bound"))
    return _result(ok, f"the root of $4/k = \\lambda^2$ is {mp.nstr(root, 15)}",
                   f"mpmath's findroot at 30 digits on $4/k - \\lambda^2 = 0$ with the derived $k$ of "
                   f"(25): {ev}. Derived form: {src}.")


@claim("eq24_5pct")
def _eq24():
    top = _f("eq24_5pct", 1)
    lams = np.unique(np.concatenate([np.linspace(0, 3, 13), np.geomspace(3.5, top, 10)]))
    est, src = _np("dm_interp_m32")
    exact = np.array([delta_m_exact(v) for v in lams]) ** -1.5
    rel = np.abs(est(lams) / exact - 1)
    i = int(np.argmax(rel))
    strict, readings = bound_readings(float(rel.max()), _n("eq24_5pct"))
    return _result(strict, _worst_text(rel.max(), lams[i]),
                   f"(24) with the derived constant $(5/4)^{{-3/5}}$ against "
                   f"$\\bar\\delta_m^{{-3/2}}$ of the exact ODE (compression phase, DOP853, rtol "
                   f"$10^{{-11}}$) at {lams.size} values of $\\lambda$ in [0, {top:g}]: the claim is about "
                   f"$\\bar\\delta_m^{{-3/2}}$, so the error is measured in it. {readings}. "
                   f"Derived form: {src}.")


def _ham_field(model, field, lams):
    import zener_sym as zs
    return getattr(zs.summary(lams, model=model), field)


def _worst_text(worst, at) -> str:
    """The decisive number of an error claim: 'largest relative error 2.905% at lambda = 2.2'."""
    return f"largest relative error {100 * worst:.3f}% at $\\lambda = {at:.3g}$"


def _ham_claim(model, field, printed, lams, label):
    import zener_sym as zs
    if model not in zs.MODELS:
        return ("not-checkable", "", f"Model `{model}` is not registered in zener_sym.MODELS "
                f"(registered: {', '.join(zs.MODELS)}).", "the HAM kernels (issue 4) are needed")
    approx = _ham_field(model, field, lams)
    ex = getattr(_exact_summary(tuple(lams)), field)
    rel = np.abs(approx / ex - 1)
    i = int(np.argmax(rel))
    strict, readings = bound_readings(float(rel.max()), printed)
    return _result(strict, _worst_text(rel.max(), lams[i]),
                   f"{label} of model `{model}` against the exact ODE at {lams.size} values of "
                   f"$\\lambda$ in [{lams[0]:g}, {lams[-1]:g}] (the paper compared with FEM). "
                   f"{readings}.")


@claim("Fm_ham1_2.90pct")
def _fm1():
    return _ham_claim("ham1", "F_m", _n("Fm_ham1_2.90pct"), LAM_HAM, "$\\bar F_m$")


@claim("impulse_ham1_3.95pct")
def _imp1():
    return _ham_claim("ham1", "impulse", _n("impulse_ham1_3.95pct"), LAM_HAM, "The impulse")


@claim("Fm_ham0_5.11pct")
def _fm0():
    lo = _f("Fm_ham0_5.11pct", 1)
    lams = np.round(np.linspace(lo, 2.4, 18)[1:], 10)  # lambda > lo
    d0, src = D.get("delta0")
    tdc, _ = D.get("tau_dc0")
    b, _ = D.get("beta_of_lam")
    w, _ = D.get("omega0_of_lam")
    beta, omega0 = SYM["beta"], SYM["omega0"]
    fm = sp.lambdify(lam, (d0.subs(SYM["tau"], tdc) ** sp.Rational(3, 2)).subs({beta: b, omega0: w}),
                     modules="numpy")
    ex = _exact_summary(tuple(lams)).F_m
    rel = np.abs(fm(lams) / ex - 1)
    i = int(np.argmax(rel))
    strict, readings = bound_readings(float(rel.max()), _n("Fm_ham0_5.11pct"))
    return _result(strict, _worst_text(rel.max(), lams[i]),
                   f"$\\bar F_m = \\bar\\delta_0(\\tau_{{dc}})^{{3/2}}$ of the derived zeroth order against "
                   f"the exact ODE at {lams.size} values of $\\lambda$ in ({lo:g}, 2.4]. {readings}. "
                   f"Derived form: {src}.",
                   "the paper's reference is FEM")


@claim("eq70_10pct_1pct")
def _eq70():
    lams = np.round(np.linspace(0.1, 2.4, 24), 10)
    ex = _exact_summary(tuple(lams)).xi
    fit = _printed_fn("70")(lams)
    mostly, above, lam_from = (_f("eq70_10pct_1pct", i) for i in range(3))
    rel = np.abs(fit / ex - 1)
    hi = lams >= lam_from
    frac10 = float(np.mean(rel < mostly))
    ok = rel[hi].max() < above and frac10 > 0.5
    return _result(ok, f"largest relative error {100 * rel[hi].max():.2f}% for $\\lambda \\geq {lam_from:g}$; "
                       f"{100 * frac10:.0f}% of $\\lambda$ in [0.1, 2.4] within {100 * mostly:g}% "
                       f"(worst {100 * rel.max():.1f}% at $\\lambda = {lams[int(np.argmax(rel))]:.3g}$)",
                   "The printed (70) against $\\xi = 1 - e^2$ of the exact ODE at 24 values of "
                   "$\\lambda$ in [0.1, 2.4]; 'most cases' is read as more than half of that range.",
                   "the paper's reference is FEM")


@claim("eq80_to_1.8")
def _eq80():
    top = _f("eq80_to_1.8")
    lams = np.round(np.linspace(0.0, top, 19), 10)
    e0, src = _np("e0_of_lam")
    ex = _exact_summary(tuple(lams)).e
    err = np.abs(e0(lams) - ex)
    rel = np.abs(e0(lams) / ex - 1)
    i = int(np.argmax(err))
    return _result(err.max() <= 0.03,
                   f"largest error in $e$ {err.max():.4f} at $\\lambda = {lams[i]:.3g}$ (largest relative "
                   f"error {100 * rel.max():.1f}%)",
                   f"Eq. (80) with the derived constant against $e$ of the exact ODE at 19 values of "
                   f"$\\lambda$ in [0, {top:g}]; 'predicts well' is read as an absolute error of at most "
                   f"0.03 (what Fig. 15 can show). Derived form: {src}.")


@claim("mueller_linear")
def _mueller_linear():
    """Mueller et al.'s paper is not available: each natural stiffness of the linear law
    (zener_sym.models.linear.STIFFNESS, derived in derivation/linear.py) is measured against the
    exact ODE on lambda in [0, 2] (below its own bound 2/sqrt(kappa))."""
    import zener_sym as zs
    from ..models.linear import STIFFNESS, linear_summary

    fm_max, imp_lo, imp_hi = (_f("mueller_linear", i) for i in range(3))
    parts, best = [], None
    for name, kappa in STIFFNESS.items():
        lams = np.linspace(0.0, 2.0, 201)
        lams = lams[lams < 2.0 / np.sqrt(kappa) - 1e-9]
        lin = linear_summary(lams, name)
        ex = zs.summary(lams)
        fm = lin["F_m"] / ex.F_m - 1
        imp = np.abs(lin["impulse"] / ex.impulse - 1)
        under = bool(np.all(fm[1:] < 0))
        parts.append(f"`{name}` ($\\kappa = {kappa:.4f}$, $\\lambda \\leq {lams[-1]:.3g}$): $\\bar F_m$ "
                     f"error {100 * fm.min():+.2f}% to {100 * fm.max():+.2f}%, impulse error (absolute "
                     f"value) {100 * imp.min():.2f}% to {100 * imp.max():.2f}%")
        # closeness to the quoted numbers, in log ratio of the worst F_m and impulse errors
        score = abs(np.log(-fm.min() / fm_max)) if fm.min() < 0 else np.inf
        score += abs(np.log(max(imp.max(), 1e-12) / imp_hi))
        if under and (best is None or score < best[0]):
            best = (score, name, fm.min(), imp.max())
    verdict = (f"no stiffness reproduces the quoted errors; the closest with $\\bar F_m$ always under "
               f"is `{best[1]}` ($\\bar F_m$ error down to {100 * best[2]:.2f}%, impulse error at most "
               f"{100 * best[3]:.2f}%)" if best else "no stiffness underestimates $\\bar F_m$ everywhere")
    holds = best is not None and abs(-best[2] - fm_max) < 0.01 and abs(best[3] - imp_hi) < 0.01
    return _result(holds, verdict, "The linear law $F = \\kappa\\bar\\delta$ in Eq. (10), in closed "
                   "form, against the exact ODE at 201 values of $\\lambda$ in [0, 2]: "
                   + "; ".join(parts) + ".",
                   "Mueller et al. (2015) is not available here: its stiffness is unknown, so the "
                   "natural choices were measured (docs/figures.md); the paper's reference is FEM "
                   "and its impulse error never falls to 0, while the linear law's impulse "
                   "$1 + e$ equals the exact 2 at $\\lambda = 0$")


@claim("hunter_reed_k")
def _hunter_reed_k():
    """k of xi = k V0^{3/5} derived in derivation/stress_waves.py (the energy a point force
    radiates into the glass half-space, with Hunter's sine (5) and Reed's sin^{3/2} (6)), then
    the readings that come nearest the printed numbers."""
    from zener_sym.derivation import stress_waves as dsw  # noqa: PLC0415 (offline derivation)

    kh_p, kr_p = _f("hunter_reed_k", 0), _f("hunter_reed_k", 1)
    t = P.TABLE1
    pair = (t["E1"], t["nu1"], t["rho1"], t["E2"], t["nu2"], t["rho2"])
    glass = (t["E2"], t["nu2"], t["rho2"]) * 2
    with mp.workdps(30):
        kh, kr = (float(dsw.k_coefficient(p, *pair)) for p in ("hunter", "reed"))
        kh_gg, kr_gg = (float(dsw.k_coefficient(p, *glass)) for p in ("hunter", "reed"))
        h_ratio = float(dsw.radiation_h(mp.mpf("0.3")) / dsw.radiation_h(mp.mpf(str(t["nu2"]))))
        c_steel = float(dsw.equal_material_constant("hunter", mp.mpf("0.3")))
    # Eq. (53) as printed, sin^3 instead of sin^{3/2}: J = int (d/dtau A sin^3(Omega tau))^2 dtau
    A, Om, ph = sp.symbols("A Omega phi", positive=True)
    j3 = sp.integrate(9 * A**2 * Om * sp.sin(ph) ** 4 * sp.cos(ph) ** 2, (ph, 0, sp.pi))
    k_sin3 = kr * float(j3 / (sp.Rational(3, 2) * A**2 * Om))
    c0 = float(np.sqrt(t["E2"] / t["rho2"]))
    k_104 = 1.04 * c0 ** -0.6  # Hunter's steel constant applied with the glass's bar speed
    first = "rounds" if rounds_to(kh * h_ratio, _n("hunter_reed_k", 0))[0] else "does not round"
    ok_h, ev_h = rounds_to(kh, _n("hunter_reed_k", 0))
    ok_r, ev_r = rounds_to(kr, _n("hunter_reed_k", 1))
    readings = [
        f"the radiation constant of $\\nu = 0.3$ (Hunter's steel) in place of the glass's 0.21: "
        f"$k_{{\\rm Hunter}}$ = {kh * h_ratio:.5f}",
        f"Eq. (53) as printed ($\\sin^3$): $k_{{\\rm Reed}}$ = {k_sin3:.5f}",
        f"a glass sphere on glass (the plate's material for both bodies): {kh_gg:.5f} (Hunter), "
        f"{kr_gg:.5f} (Reed)",
        f"Hunter's steel form $1.04\\,(V_0/c_0)^{{3/5}}$ with the glass's $c_0 = \\sqrt{{E_2/\\rho_2}}$ "
        f"= {c0:.0f} m/s: {k_104:.5f} (the derivation gives {c_steel:.4f} in place of 1.04 for steel)",
    ]
    return _result(ok_h and ok_r,
                   f"$k_{{\\rm Hunter}}$ = {kh:.5f} ({100 * (kh / kh_p - 1):+.0f}% from {kh_p:g}), "
                   f"$k_{{\\rm Reed}}$ = {kr:.5f} ({100 * (kr / kr_p - 1):+.0f}% from {kr_p:g})",
                   f"$W = h(\\nu_2) / (2\\pi\\rho_2 c_2^3) \\int \\dot F^2 dt$ for a normal point force on "
                   f"the glass half-space ($h$ from the Lamb kernel: body waves and the Rayleigh pole), "
                   f"with Hertz's $\\delta_m$ (3), Hunter's sine (5) and Reed's $\\sin^{{3/2}}$ (6), "
                   f"derived and checked in derivation/stress_waves.py; Table 1 values. Hunter: {ev_h}. "
                   f"Reed: {ev_r}. Readings tried: " + "; ".join(readings) + f". The first {first}"
                   f" to {kh_p:g}; the glass-on-glass and $1.04\\,(V_0/c_0)^{{3/5}}$ readings are "
                   f"{100 * min(abs(x / kr_p - 1) for x in (kh_gg, kr_gg, k_104)):.0f}% to "
                   f"{100 * max(abs(x / kr_p - 1) for x in (kh_gg, kr_gg, k_104)):.0f}% from {kr_p:g}; "
                   f"no single reading gives both: with one half-space formula the "
                   f"ratio $k_{{\\rm Reed}}/k_{{\\rm Hunter}}$ is the ratio of the pulses' "
                   f"$\\int \\dot{{\\bar F}}^2 d\\tau$, {kr / kh:.3f} for every material, where the paper "
                   f"has {kr_p / kh_p:.2f}.",
                   "The paper gives no derivation of its two numbers, and Reed (1985) is not "
                   "available here: Reed's pulse is read from the paper's Eq. (6)")


@claim("int_F2_poly")
def _intF2():
    lams = np.round(np.linspace(0.0, 0.5, 11), 10)
    ex = _exact_summary(tuple(lams)).int_F2
    c = [_f("int_F2_poly", i) for i in range(3)]
    poly = c[0] + c[1] * lams + c[2] * lams**2
    fit = np.polyfit(lams, ex, 2)[::-1]
    ok, ev = rounds_to(ex[0], _n("int_F2_poly"))
    rel = np.abs(poly / ex - 1)
    return _result(ok, f"$\\int_0^{{\\tau_d}}\\bar F^2 d\\tau = {ex[0]:.5f}$ at $\\lambda = 0$; the "
                       f"least-squares quadratic on [0, 0.5] is ${fit[0]:.3f} {'-' if fit[1] < 0 else '+'} "
                       f"{abs(fit[1]):.3f}\\lambda {'-' if fit[2] < 0 else '+'} {abs(fit[2]):.3f}\\lambda^2$",
                   f"The exact ODE at 11 values of $\\lambda$ in [0, 0.5]. The value at $\\lambda = 0$ is "
                   f"Hertz's and does not depend on the fitting range: {ev}. The printed polynomial is off "
                   f"by up to {100 * rel.max():.1f}% on [0, 0.5].")


@claim("fit55")
def _fit55():
    import zener_sym as zs
    lams = np.round(np.linspace(0.0, 2.4, 13), 10)
    a, b, c = (_f("fit55", i) for i in range(3))
    fit = a * np.exp(b * lams**c)
    ex = _exact_summary(tuple(lams)).tau_d
    rel_ex = np.abs(fit / ex - 1)
    info = (f"Against the exact ODE its largest relative error is {100 * rel_ex.max():.1f}% at "
            f"$\\lambda = {lams[int(np.argmax(rel_ex))]:.3g}$.")
    if "ham1" not in zs.MODELS:
        return ("not-checkable", info, "The fit is of the first-order solution, and model `ham1` is "
                "not registered. " + info, "the HAM kernels (issue 4) are needed")
    h = _ham_field("ham1", "tau_d", lams)
    rel = np.abs(fit / h - 1)
    return _result(rel.max() < _f("eq24_5pct"), f"largest relative difference {100 * rel.max():.2f}% "
                   f"from the first-order $\\tau_d$",
                   f"(55) against $\\tau_d$ of model `ham1` at 13 values of $\\lambda$ in [0, 2.4] "
                   f"(a fit: 5% tolerance). " + info)


@claim("xi_V0^0.2")
def _xi_v0():
    lp, src = D.get("lam_phys")
    ex = sp.simplify(SYM["V0"] * sp.diff(lp, SYM["V0"]) / lp)
    ok, ev = rounds_to(ex, _n("xi_V0^0.2"))
    return _result(ok, f"$d\\ln\\lambda/d\\ln V_0 = {tex(ex)}$; {ev}",
                   f"$\\xi \\approx 2\\lambda\\int\\bar F^2 d\\tau$ for small $\\lambda$, with the derived "
                   f"$\\lambda$ of (11). Derived form: {src}.")


@claim("table1_lambda_range")
def _table1():
    lp, src = D.get("lam_phys")
    s = SYM
    tb = P.TABLE1
    mat = {s[n]: tb[n] for n in ("E1", "nu1", "rho1", "E2", "nu2", "rho2", "R")}
    f = sp.lambdify((s["H"], s["V0"]), lp.subs(mat), modules="numpy")
    (v_lo, v_hi), (h_lo, h_hi) = tb["V0_range"], tb["H_range"]
    lo, hi = float(f(h_hi, v_lo)), float(f(h_lo, v_hi))
    ok = abs(lo / _f("table1_lambda_range", 0) - 1) < 0.15 and abs(hi / _f("table1_lambda_range", 1) - 1) < 0.15
    return _result(ok, f"$\\lambda$ from {lo:.3g} ($H$ = 0.75 mm, $V_0$ = 1 m/s) to {hi:.3g} "
                       f"($H$ = 0.18 mm, $V_0$ = 20 m/s)",
                   f"The derived $\\lambda$ of (11) with $m^* = \\frac{{4}}{{3}}\\pi R^3\\rho_1$ and the values "
                   f"of Table 1; 'about' is read as within 15%. Derived form: {src}.")


def _fit_claim(item_id):
    """(55) and (70) are fits: their rows take the verdict of the matching claim."""
    name = {"55": "claim:fit55", "70": "claim:eq70_10pct_1pct"}[item_id]
    return CLAIMS[name]()
