"""Eq. (10) as the viscoelastic grain contact: the mapping, the force-free end, the grain front end."""

import mpmath
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.derivation import viscoelastic as dv
from zener_sym.exact import force_end as fe

SUMMARY = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")


def test_mapping_derivation_passes():
    ctx = dv.derive()
    assert ctx.log.ok, [s for s in ctx.log.steps if not s.passed]
    assert len(ctx.log.steps) >= 8


@pytest.mark.parametrize("lam", [0.0, 1e-12, 1e-6, 0.01, 0.3, 1.0, 2.5, 5.0, 10.0, 20.0, 100.0])
def test_force_end_scipy_against_mpmath(lam):
    # every field relative, xi included: it is formed from the grains' energy balance, not as
    # 1 - e^2 (which cancels to a relative error 1e-2 at lambda = 1e-12 and to -3e-14 at 0)
    a, b = fe.solve(lam), fe.solve_mp(lam, dps=30)
    for f in SUMMARY:
        ref = float(getattr(b, f))
        got = float(getattr(a, f))
        if ref == 0.0:  # xi and eta at lambda = 0
            assert got == 0.0, (f, got)
        else:
            assert abs(got - ref) <= 1e-11 * abs(ref), (f, got, ref)


def test_force_end_xi_is_exactly_zero_at_lambda_zero_and_never_negative():
    assert fe.solve(0.0).xi == 0.0 and zs.summary(0.0, model="exact", contact_end="force").xi == 0.0
    lam = np.geomspace(1e-14, 1e-3, 12)
    xi = zs.summary(lam, model="exact", contact_end="force").xi
    # leading term of the energy balance: xi ~ 3 lam int sqrt(delta) delta'^2 of the Hertz orbit
    # = 2 lam int F^2 + O(lam^2), i.e. the plate's xi to first order
    # The force-free end cuts the contact where delta ~ (3/2) lam, so the two criteria differ by
    # O(lam^{5/2}) in xi ~ 3.46 lam: relatively by O(lam^{3/2}) (measured -4.2 lam^{3/2}).
    plate = zs.summary(lam, model="exact").xi
    assert np.all(xi > 0)
    assert np.all(np.abs(xi / plate - 1.0) <= 1e-13 + 10.0 * lam**1.5)


def _force_end_record():
    import json
    import pathlib

    path = pathlib.Path(__file__).resolve().parent / "data" / "force_end_restitution.json"
    return json.loads(path.read_text("utf-8"))["values"]


@pytest.mark.parametrize("lam", [0.5, 1.0, 2.0])
def test_force_end_restitution_matches_independent_integration(lam):
    # e recorded by tools/force_end_reference.py, an integration of Eq. (10) with its own event
    # for the force-free end that imports nothing of zener_sym (tests/data/, 10 digits; its two
    # tolerances agree to 5e-11). Issue 18 quoted the same values to 4 digits.
    rec = _force_end_record()[repr(lam)]
    assert rec["agreement"] < 1e-10
    assert abs(zs.summary(lam, model="exact", contact_end="force").e - rec["e"]) < 1e-9


def test_force_end_is_force_free_and_after_compression():
    lam = 0.8
    s = fe.solve_mp(lam, dps=30)
    # The plate's Taylor solution at tau_d (the grains' end) has delta + 1.5 lam delta' = 0 and the
    # grains' force, evaluated from its own history just before the end, vanishes.
    with mpmath.workdps(45):
        h = s._base.history_mp([s.tau_d])
        d = h["delta"][0]
        v = h["velocity"][0] - lam * d * mpmath.sqrt(d)
        assert abs(d + mpmath.mpf(3) / 2 * lam * v) < 1e-25
    assert -v == s.e and s.tau_d > s.tau_dc
    plate = zs.summary(lam, model="exact")
    assert s.tau_d < plate.tau_d and float(s.e) > plate.e  # separates earlier, faster


def test_force_end_grain_energy_balance():
    # 1 - e^2 = 2 int (3/2) lam sqrt(delta) delta'^2 dtau + (4/5) delta(tau_d)^(5/2): the dashpot's
    # dissipation plus the elastic energy left at separation (derivation/viscoelastic.py).
    lam = 0.7
    s = fe.solve(lam)
    x, w = np.polynomial.legendre.leggauss(80)
    edges = np.linspace(0.0, s.tau_d, 41)
    diss = 0.0
    for a, b in zip(edges[:-1], edges[1:]):
        t = 0.5 * (b - a) * x + 0.5 * (a + b)
        h = s.history(t)
        diss += 0.5 * (b - a) * np.sum(w * 1.5 * lam * np.sqrt(h["delta"]) * h["velocity"] ** 2)
    d_end = s._base.history(np.nextafter(s.tau_d, 0))["delta"]
    assert abs(2 * diss + 0.8 * float(d_end) ** 2.5 - s.xi) < 1e-8


@pytest.mark.parametrize("lam", [1.3, 20.0])
def test_force_end_history_scipy_against_mpmath(lam):
    s = zs.summary(lam, model="exact", contact_end="force")
    tau = np.linspace(0.0, 1.1 * s.tau_d, 61)
    a = zs.history(lam, tau, model="exact", contact_end="force")
    b = zs.history(lam, tau, model="exact", contact_end="force", backend="mpmath")
    for f in ("delta", "velocity", "force", "impulse"):  # 1e-10 of each field's maximum
        ref = getattr(b, f)
        assert np.max(np.abs(getattr(a, f) - ref)) < 1e-10 * np.max(np.abs(ref)), f
    past = tau >= s.tau_d
    assert past.any() and np.all(a.force[past] == 0) and np.allclose(a.impulse[past], 1 + s.e, atol=1e-14)


def test_contact_end_bad_input():
    with pytest.raises(ValueError, match="contact_end.*allowed: 'delta'"):
        zs.summary(1.0, model="exact", contact_end="touch")
    with pytest.raises(ValueError, match="does not go with backend='table'"):
        zs.summary(1.0, model="exact", contact_end="force", backend="table", rtol=1e-10)
    with pytest.raises(ValueError, match="outside the validity"):
        zs.summary(1500.0, model="exact", contact_end="force")


def test_lam_from_dissipation_closed_form_and_bad_input():
    # lambda = A/T with T from the mapping, computed here from its definition
    A, rho, m, v = 2e-7, 3.1e8, 4e-6, 2.5
    T = (m / rho) ** 0.4 * v ** -0.2
    assert abs(zs.lam_from_dissipation(A, rho, m, v) - A / T) < 1e-15 * A / T
    arr = zs.lam_from_dissipation([A, 2 * A], rho, m, v)
    assert arr.shape == (2,) and abs(arr[1] / arr[0] - 2) < 1e-15
    for kw in ({"A": 0.0}, {"rho": -1.0}, {"m_eff": float("inf")}, {"v0": float("nan")}):
        args = {"A": A, "rho": rho, "m_eff": m, "v0": v, **kw}
        name = next(iter(kw))
        with pytest.raises(ValueError, match=f"^{name} .*allowed: 0 < {name}"):
            zs.lam_from_dissipation(**args)


def _si_integration(m, rho, A, v0, end):
    """The grain ODE in SI units, integrated directly (an independent route to grain_impact)."""
    from scipy.integrate import solve_ivp

    def rhs(t, y):
        x, u = max(y[0], 0.0), y[1]
        return [u, -rho * (x**1.5 + 1.5 * A * np.sqrt(x) * u) / m]

    def stop(t, y):
        x = max(y[0], 0.0)
        return x + 1.5 * A * y[1] if end == "force" else y[0]

    stop.terminal, stop.direction = True, -1

    def peak(t, y):  # d/dt of the viscoelastic force rho (xi^3/2 + A d/dt xi^3/2)
        x = max(y[0], 1e-300)
        u = y[1]
        acc = -rho * (x**1.5 + 1.5 * A * np.sqrt(x) * u) / m
        return 1.5 * np.sqrt(x) * u + 1.5 * A * (0.5 * u * u / np.sqrt(x) + np.sqrt(x) * acc)

    peak.direction = -1
    t_guess = 10 * (m / rho) ** 0.4 * v0 ** -0.2
    # start a hair after contact (xi ~ v0 t), where the square root is already resolved
    t0 = 1e-9 * t_guess
    s = solve_ivp(rhs, (t0, t_guess), [v0 * t0, v0 - rho * 1.5 * A * np.sqrt(v0 * t0) * t0 / m],
                  method="DOP853", rtol=1e-12, atol=1e-20, events=[stop, peak])
    te, ye = s.t_events[0][0], s.y_events[0][0]
    tp, yp = s.t_events[1][0], s.y_events[1][0]
    Fp = rho * (yp[0] ** 1.5 + 1.5 * A * np.sqrt(yp[0]) * yp[1])
    return -ye[1] / v0, te, Fp


@pytest.mark.parametrize("end", ["force", "delta"])
def test_grain_impact_against_si_integration(end):
    m1, m2 = 2e-5, 5e-5
    r = zs.grain_impact("glass", 1e-3, m1, A=3e-7, v0=2.0, sphere2="steel", radius2=2e-3, mass2=m2,
                        contact_end=end)
    assert r.contact_end == end and ("force" in r.criterion) == (end == "force")
    e, tc, Fm = _si_integration(r.m_eff, r.rho, 3e-7, 2.0, end)
    assert abs(r.e - e) < 1e-6 * e
    assert abs(r.contact_duration_s - tc) < 1e-6 * tc
    assert abs(r.max_force_N - Fm) < 1e-6 * Fm
    assert r.t_s[-1] == pytest.approx(r.contact_duration_s) and r.force_N.shape == r.t_s.shape
    assert abs(r.force_N.max() - Fm) < 1e-3 * Fm  # the sampled history reaches the peak
    if end == "delta":
        assert r.force_N[-3] < 0  # the attractive tail the grains' criterion cuts off
    else:
        assert np.all(r.force_N[:-1] >= -1e-9 * Fm)


def test_grain_impact_wall_and_bad_input():
    rigid = zs.grain_impact("glass", 1e-3, 1e-5, A=1e-7, v0=1.0)
    soft = zs.grain_impact("glass", 1e-3, 1e-5, A=1e-7, v0=1.0, wall="glass")
    assert rigid.E_star > soft.E_star and rigid.contact_duration_s < soft.contact_duration_s
    with pytest.raises(ValueError, match="A .*allowed: 0 < A"):
        zs.grain_impact("glass", 1e-3, 1e-5, A=-1e-7, v0=1.0)
    with pytest.raises(ValueError, match="v0 .*allowed"):
        zs.grain_impact("glass", 1e-3, 1e-5, A=1e-7, v0=float("inf"))
    with pytest.raises(ValueError, match="contact_end"):
        zs.grain_impact("glass", 1e-3, 1e-5, A=1e-7, v0=1.0, contact_end="zero")
    with pytest.raises(ValueError, match="sphere 2 needs"):
        zs.grain_impact("glass", 1e-3, 1e-5, A=1e-7, v0=1.0, radius2=1e-3)
    with pytest.raises(ValueError, match="exact model accepts 0 <= lambda <= 1000"):
        zs.grain_impact("glass", 1e-3, 1e-5, A=1.0, v0=1.0)


def test_lookup_table_csv_round_trip_against_solvers(capsys):
    from zener_sym.cli import main
    from zener_sym.exact import mp as exact_mp

    assert main(["table", "--quantity", "e,tau_d", "--lam", "0:5:11", "--contact-end", "force",
                 "--csv"]) == 0
    text = capsys.readouterr().out
    lines = text.splitlines()
    assert lines[0] == "lam,e,tau_d" and len(lines) == 12
    arr = np.loadtxt(text.splitlines()[1:], delimiter=",")
    assert np.array_equal(arr[:, 0], np.linspace(0.0, 5.0, 11))
    for row in arr[[2, 5, 10]]:  # lambda = 1, 2.5, 5 against the mpmath force-free end
        s = fe.solve_mp(row[0], dps=25)
        assert abs(row[1] - float(s.e)) < 1e-11 * float(s.e)
        assert abs(row[2] - float(s.tau_d)) < 1e-11 * float(s.tau_d)
    from zener_sym.scene.lookup import lookup_csv, lookup_table

    t = lookup_table(("tau_d", "e"), [1.0], contact_end="delta")
    s = exact_mp.solve(1.0, dps=25)
    assert list(t) == ["lam", "tau_d", "e"] and abs(t["e"][0] - float(s.e)) < 1e-11 * float(s.e)
    assert lookup_csv(t).splitlines()[0] == "lam,tau_d,e"


def test_lookup_table_bad_input(capsys):
    from zener_sym.cli import main
    from zener_sym.scene.lookup import lookup_table

    with pytest.raises(ValueError, match="unknown quantity 'speed'.*allowed: delta_m"):
        lookup_table("e,speed", "0:1:3")
    with pytest.raises(ValueError, match="not understood; allowed: 'start:stop:n'"):
        lookup_table("e", "1:0:3")
    with pytest.raises(ValueError, match="allowed 0 <= lambda <=? 1000"):
        lookup_table("e", "0:2000:3")
    with pytest.raises(ValueError, match="contact_end"):
        lookup_table("e", "0:1:3", contact_end="zero")
    assert main(["table", "--lam", "0:1"]) == 2
    assert "not understood" in capsys.readouterr().err


def test_peers_table_in_docs_is_fresh():
    """docs/viscoelastic.md's peers block is what zener_sym.report.peers measures now
    (regenerate: zener-sym regen peers)."""
    import pathlib

    from zener_sym.report import peers

    doc = (pathlib.Path(__file__).resolve().parents[1] / "docs" / "viscoelastic.md").read_text("utf-8")
    fresh = peers.update_doc(doc, peers.markdown())
    assert fresh == doc, "docs/viscoelastic.md peers table is stale"


def test_toolbox_first_order_constant_is_raman_c1():
    # The toolbox's C0 (Chatterjee, James & Brogliato, a Beta-function closed form of their own)
    # read back from its recorded output, against this package's c1.
    from zener_sym.derivation.lambda_series import raman_c1
    from zener_sym.report import peers

    rows = peers._toolbox_rows()
    C0 = (1 - rows["ord1"][:5]) / rows["lam"][:5]
    assert np.allclose(C0, float(raman_c1()), rtol=1e-14, atol=0)
    # and the literature's x = 1.5 lambda: C1 = 1.15344 is c1 / 1.5 to its printed digits
    assert abs(1.15344 * 1.5 / float(raman_c1()) - 1) < 1e-5
