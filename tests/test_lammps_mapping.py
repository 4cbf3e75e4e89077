"""LAMMPS's hertz/material + viscoelastic contact mapped onto Eq. (10): the derivation, the
mapping's round trips, the lines and table of ``zener-sym lammps``, and its refusals.

Nothing here runs LAMMPS (tests/test_lammps_run.py does). LAMMPS's own force law and mixing
rules are written out below from its documentation (pair_granular, fix wall/gran), independently
of the package."""
from __future__ import annotations

import json
import math

import pytest
import sympy as sp

import zener_sym as zs
from zener_sym import cli
from zener_sym.derivation import lammps as dl
from zener_sym.scene.lammps import lammps_contact, lammps_setup, steps_required


# LAMMPS's documented rules, written out here (not from the package):
def lammps_E_mix_pair(E1, nu1, E2, nu2):
    return 1.0 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)


def lammps_E_mix_wall(E, nu):
    return E / (2 * (1 - nu**2))


def lammps_force(E_mix, eta0, m_eff, R_eff, delta, delta_dot):
    a = math.sqrt(R_eff * delta)  # contact radius
    return 4.0 / 3.0 * E_mix * a * delta + eta0 * a * m_eff * delta_dot


def test_the_derivation_passes_and_a_wrong_mapping_fails():
    ctx = dl.derive()
    assert ctx.log.ok, [s for s in ctx.log.steps if not s.passed]
    assert len(ctx.log.steps) >= 9
    P = dl.LAMMPS_SYMBOLS
    # the derived eta_n0 is 2 E* A / m_eff, not the (3/2) rho A / sqrt(R) m of a slip
    assert sp.simplify(ctx.expr["eta0_of_A"] - 2 * P["Estar"] * P["A"] / P["m"]) == 0
    assert sp.simplify(ctx.expr["eta0_of_A"] - P["Estar"] * P["A"] / P["m"]) != 0


@pytest.mark.parametrize("kw", [dict(wall="steel"), dict(), dict(sphere2="steel", radius2="3 mm"),
                                dict(wall="aluminium")])
def test_lammps_force_with_the_lines_constants_is_the_grain_force(kw):
    # the E and eta_n0 written on the line, through LAMMPS's own mixing and force law, give
    # rho (delta^{3/2} + A d/dt delta^{3/2}) of the grain contact at every (delta, delta')
    c = lammps_contact("glass", "1 mm", **kw)
    A = 2.3e-7
    eta = c.damping(A)
    E_mix = (lammps_E_mix_wall(c.E_lammps, c.nu_lammps) if c.geometry == "wall"
             else lammps_E_mix_pair(c.E_lammps, c.nu_lammps, c.E_lammps, c.nu_lammps))
    g = zs.grain_impact("glass", "1 mm", c.mass1, A=A, v0=1.0, **(
        dict(wall=kw["wall"]) if "wall" in kw else
        dict(radius2=kw.get("radius2", "1 mm"), mass2=c.mass2, sphere2=kw.get("sphere2", "glass"))))
    assert E_mix == pytest.approx(g.E_star, rel=1e-14)
    for delta, rate in [(1e-7, 0.5), (3e-6, -0.2), (2e-5, 1.3)]:
        F_grain = g.rho * (delta**1.5 + A * 1.5 * math.sqrt(delta) * rate)
        F_lammps = lammps_force(E_mix, eta, g.m_eff, g.R_eff, delta, rate)
        assert F_lammps == pytest.approx(F_grain, rel=1e-13)


def test_two_materials_line_reproduces_lammps_own_two_type_mixing():
    glass, steel = zs.GLASS, zs.STEEL
    c = lammps_contact("glass", "1 mm", sphere2="steel")
    two_types = lammps_E_mix_pair(glass.E, glass.nu, steel.E, steel.nu)
    one_line = lammps_E_mix_pair(c.E_lammps, c.nu_lammps, c.E_lammps, c.nu_lammps)
    assert one_line == pytest.approx(two_types, rel=1e-14)
    # one material with itself: the line's E is the material's own
    same = lammps_contact("steel", "1 mm")
    assert same.E_lammps == pytest.approx(steel.E, rel=1e-14) and same.nu_lammps == steel.nu


def test_round_trips():
    c = lammps_contact("glass", "0.5 mm", wall="steel")
    for A in (1e-12, 3e-9, 2.4e-7, 1e-4):
        assert c.dissipation(c.damping(A)) == pytest.approx(A, rel=1e-15)
    # lambda from LAMMPS's terms (derivation L3) against the grain reading
    lam_eta = sp.lambdify([dl.LAMMPS_SYMBOLS[k] for k in ("eta0", "m", "Estar", "R", "v")],
                          dl.derive().expr["lam_of_eta0"])
    eta = c.damping(2.4e-7)
    for v in (0.01, 1.0, 30.0):
        lam = zs.lam_from_dissipation(2.4e-7, c.rho, c.m_eff, v)
        assert lam_eta(eta, c.m_eff, c.E_star, c.R_eff, v) == pytest.approx(lam, rel=1e-13)


@pytest.mark.parametrize("end", ["force", "delta"])
def test_measured_e_gives_back_that_e_and_the_grain_answers(end):
    s = lammps_setup("glass", "1 mm", wall="steel", e=0.8, at="1 m/s", contact_end=end)
    row = next(r for r in s.table if r["v_m_s"] == pytest.approx(1.0))
    assert row["e"] == pytest.approx(0.8, abs=1e-10)
    assert len(s.table) == 9 and s.table[0]["v_m_s"] == pytest.approx(0.1)
    c = s.contact
    for r in s.table:
        g = zs.grain_impact("glass", "1 mm", c.mass1, A=s.A_s, v0=r["v_m_s"], wall="steel",
                            contact_end=end)
        assert r["lambda"] == pytest.approx(g.lam, rel=1e-13)
        assert r["e"] == pytest.approx(g.e, rel=1e-12)
        assert r["contact_time_s"] == pytest.approx(g.contact_duration_s, rel=1e-12)
        assert r["max_force_N"] == pytest.approx(g.max_force_N, rel=1e-12)
        assert r["dt_max_s"] is not None and 0 < r["dt_max_s"] < r["contact_time_s"] / 5
    assert ("limit_damping" in s.lines["fix_wall"]) == (end == "force")
    assert s.lines["fix_wall"].endswith("zplane 0.0 NULL")


def test_steps_required_follows_the_law_and_the_tolerance():
    for end in ("force", "delta"):
        n3 = steps_required(1.0, end, 1e-3)
        n4 = steps_required(1.0, end, 1e-4)
        assert 10 <= n3 < n4  # a tighter tolerance needs more steps
    # lambda beyond the measured law: no answer is guessed
    assert math.isnan(steps_required(5000.0, "force"))


def _json(capsys, *argv):
    assert cli.main(["lammps", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_cli_json(capsys):
    d = _json(capsys, "--sphere", "glass", "--radius", "1mm", "--wall", "steel", "--e", "0.8",
              "--at", "1m/s")
    assert {"fix_wall", "A_s", "damping", "contact_end", "table"} <= set(d)
    assert d["fix_wall"].startswith("fix wall all wall/gran granular hertz/material ")
    assert d["contact_end"] == "force" and "limit_damping" in d["fix_wall"]
    assert set(d["table"][0]) == {"v_m_s", "lambda", "e", "contact_time_s", "max_force_N",
                                  "dt_max_s"}
    # the damping coefficient on the line is the one reported, to the last digit
    assert float(d["fix_wall"].split()[7]) == d["damping"]
    p = _json(capsys, "--sphere", "glass", "--radius", "1mm", "--A", "240ns", "--contact-end",
              "delta", "--speeds", "0.1m/s,50cm/s")
    assert p["pair_coeff"].startswith("pair_coeff * * hertz/material ") and "fix_wall" not in p
    assert "limit_damping" not in p["pair_coeff"] and p["A_s"] == pytest.approx(2.4e-7)
    assert [r["v_m_s"] for r in p["table"]] == pytest.approx([0.1, 0.5])


def test_cli_text(capsys):
    assert cli.main(["lammps", "--sphere", "glass", "--radius", "1mm", "--sphere2", "steel",
                     "--radius2", "2mm", "--A", "0.1us"]) == 0
    out = capsys.readouterr().out
    assert "pair_style granular" in out and "pair_coeff * * hertz/material" in out
    assert "set type 2 diameter 0.004 density 7850.0" in out and "| v (m/s) |" in out


@pytest.mark.parametrize("argv, says", [
    (["--sphere", "glass", "--radius", "1", "--A", "1ns"], "give a unit"),
    (["--sphere", "glass", "--radius", "1mm", "--A", "1"], "give a unit"),
    (["--sphere", "glass", "--radius", "1mm", "--A", "1ns", "--speeds", "1,2"], "give a unit"),
    (["--sphere", "unobtainium", "--radius", "1mm", "--A", "1ns"], "neither a preset"),
    (["--sphere", "glass", "--radius", "1mm", "--wall", "steel", "--sphere2", "glass", "--A",
      "1ns"],
     "not both"),
    (["--sphere", "glass", "--radius", "1mm", "--e", "1e-7", "--at", "1m/s"], "reachable"),
    (["--sphere", "glass", "--radius", "1mm", "--e", "1.2", "--at", "1m/s"], "(0, 1]"),
    (["--sphere", "glass", "--radius", "1mm", "--A", "2ms", "--at", "10m/s"], "lambda <= 1000"),
    (["--sphere", "glass", "--radius", "1mm", "--e", "0.5"], "--at"),
    (["--sphere", "glass", "--radius", "1mm"], "either --A"),
])
def test_cli_refusals_one_line_exit_2(capsys, argv, says):
    assert cli.main(["lammps", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("zener-sym lammps: error:") and says in err
