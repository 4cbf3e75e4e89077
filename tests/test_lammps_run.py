"""LAMMPS itself, run through its Python interface with the lines ``zener-sym lammps`` prints,
against the exact model: e at a fine timestep within LAMMPS's own measured discretization error,
first-order convergence, the timestep promise of the table, and the stability limit.

LAMMPS is part of the test extra: in CI nothing here skips."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

import zener_sym as zs
from zener_sym import cli
from zener_sym.bench.lammps import run as lr
from zener_sym.bench.lammps import studies as lv
from zener_sym.scene.lammps import lammps_contact


@pytest.fixture(scope="module")
def session():
    with lr.Session() as s:
        yield s


def _from_cli(capsys, *argv):
    assert cli.main(["lammps", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def _run(session, setup_json, c, row, end, steps, phase=0.5):
    """One LAMMPS run with the lines the CLI printed: the runner's deck carries these very lines
    (checked here character for character), with the damping coefficient read from them."""
    line = setup_json.get("fix_wall") or setup_json["pair_coeff"]
    eta = float(line.split()[line.split().index("hertz/material") + 2])
    key = "fix_wall" if "fix_wall" in setup_json else "pair_coeff"
    assert lr.input_lines(c, eta, end)[key] == line
    t_c = row["contact_time_s"]
    return lr.collide(session, c, eta, end, row["v_m_s"], t_c / steps, t_c, phase=phase,
                      e_exact=row["e"])


CASES = [  # (CLI geometry arguments, the same contact for the runner)
    (("--wall", "steel"), dict(wall="steel")),
    ((), dict()),
    (("--sphere2", "steel", "--radius2", "2mm"), dict(sphere2="steel", radius2="2 mm")),
]


@pytest.mark.parametrize("end", ["force", "delta"])
@pytest.mark.parametrize("geo", range(len(CASES)))
def test_cli_lines_reproduce_the_exact_e_within_lammps_discretization_error(capsys, session, end,
                                                                           geo):
    cli_args, kw = CASES[geo]
    c = lammps_contact("glass", "1 mm", **kw)
    # three lambdas across the table: A fixed by e = 0.8 at 1 m/s is lambda ~ 0.13; the speeds
    # 1e-4 and 1e4 times... stay in range, so A is given for lambda ~ 0.01, 0.5, 5 at 1 m/s
    for lam in (0.01, 0.5, 5.0):
        A = lam / c.rate(1.0)
        d = _from_cli(capsys, "--sphere", "glass", "--radius", "1mm", *cli_args,
                      "--A", f"{A * 1e9!r}ns", "--contact-end", end, "--speeds", "0.3m/s,1m/s,3m/s")
        for row in d["table"]:
            n = 2000 * (25 if end == "delta" and row["lambda"] > 3 else 1)  # creeping recovery
            fine = _run(session, d, c, row, end, n)
            finer = _run(session, d, c, row, end, 2 * n)
            assert fine.status == finer.status == "ok"
            # first order (tested below): e_2n - e_exact ~ (e_n - e_2n); allow twice that
            disc = abs(fine.e - finer.e)
            assert abs(finer.e - row["e"]) <= 2.0 * disc + 1e-13, (row, fine.e, finer.e)
            assert finer.contact_time_s == pytest.approx(row["contact_time_s"], rel=2e-3)
            assert finer.max_force_N == pytest.approx(row["max_force_N"], rel=2e-3)


@pytest.mark.parametrize("end", ["force", "delta"])
def test_error_falls_at_first_order(session, end):
    c = lammps_contact("glass", "1 mm", wall="aluminium")
    for lam in (0.1, 1.0):
        errs = []
        for n in (100, 200, 400, 800):
            r = lv.run_lam(session, c, lam, end, n)
            errs.append(abs(r.e - float(zs.summary(lam, contact_end=end).e)))
        orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
        assert np.all((orders > 0.8) & (orders < 1.6)), (lam, end, errs, orders)


def test_pair_and_wall_are_the_same_collision(session):
    # dimensionless, two glass spheres and a glass sphere on a steel wall are one problem
    cs = lv.contacts()
    for end in ("force", "delta"):
        a = lv.run_lam(session, cs["wall"], 0.3, end, 300)
        b = lv.run_lam(session, cs["pair"], 0.3, end, 300)
        assert a.e == pytest.approx(b.e, rel=1e-9) and a.tau_d == pytest.approx(b.tau_d, rel=1e-9)


@pytest.mark.parametrize("end", ["force", "delta"])
def test_the_tables_timestep_keeps_e_within_its_tolerance(capsys, session, end):
    # dt_max_s from the error law: LAMMPS's e at that timestep, at every contact phase, within 1e-3
    c = lammps_contact("glass", "1 mm", wall="steel")
    d = _from_cli(capsys, "--sphere", "glass", "--radius", "1mm", "--wall", "steel", "--A",
                  "300ns", "--contact-end", end, "--speeds", "0.05m/s,0.7m/s,4m/s,20m/s")
    for row in d["table"]:
        assert row["dt_max_s"] > 0
        for phase in (0.1, 0.6, 0.9):
            r = lr.collide(session, c, d["damping"], end, row["v_m_s"], row["dt_max_s"],
                           row["contact_time_s"], phase=phase, e_exact=row["e"])
            assert r.status == "ok" and abs(r.e - row["e"]) <= d["e_tolerance"], (row, r)


def test_beyond_the_stability_limit_lammps_loses_the_collision(session):
    c = lv.contacts()["wall"]
    rows = {(r["contact_end"], r["lambda"]): r for r in lv.stability(lams=(1.0, 10.0))}
    for (end, lam), r in rows.items():
        lim = r["steps_at_limit"]
        assert math.isfinite(lim)
        assert lv.run_lam(session, c, lam, end, lim).status == "ok"
        worse = lv.run_lam(session, c, lam, end, lim / 2)
        assert worse.status != "ok"


def test_classify():
    assert lr.classify(float("nan"), 0.5) == "blow-up"
    assert lr.classify(-0.1, 0.5) == "missed contact"
    assert lr.classify(0.5, 0.5, touched=False) == "missed contact"
    assert lr.classify(1.01, 0.99) == "energy gain"
    assert lr.classify(0.44, 0.5) == "e off >10%"
    assert lr.classify(0.46, 0.5) == "ok"


def test_missing_lammps_is_one_line_naming_the_extra(monkeypatch):
    import builtins

    real_import = builtins.__import__

    def no_lammps(name, *a, **k):
        if name == "lammps":
            raise ImportError("No module named 'lammps'")
        return real_import(name, *a, **k)

    lr.load.cache_clear()  # the next load() imports again (and the patched import fails)
    monkeypatch.setattr(builtins, "__import__", no_lammps)
    monkeypatch.setattr(lr.importlib, "import_module", lambda name: no_lammps(name))
    with pytest.raises(lr.LammpsMissing, match=r"zener-sym\[lammps\]"):
        lr.load()
    lr.load.cache_clear()


def test_mpi_deck_same_e_on_one_and_two_ranks_and_within_the_promise(tmp_path):
    from zener_sym.bench.lammps import mpi as lm

    deck = lm.write_deck(tmp_path, n=400)
    for ranks in (1, 2):
        lm.run(tmp_path, ranks=ranks, dump=f"final{ranks}.dump")
    e1, e2 = lm.read_e(tmp_path, "final1.dump"), lm.read_e(tmp_path, "final2.dump")
    # each grain meets only the wall: its force is computed on whichever rank owns it, by the
    # same arithmetic, so the decomposition changes no bit
    assert np.array_equal(e1, e2)
    cmp = lm.compare(deck, e2)
    assert np.max(np.abs(cmp.error)) <= 1e-3
    # and the deck's grains did span two decades of speed
    assert deck.v.min() < 0.15 and deck.v.max() > 7.0


def test_report_section_runs_the_lines_in_lammps(tmp_path):
    from zener_sym.report.build import lammps_section

    text = lammps_section(tmp_path)
    assert "fix wall all wall/gran granular hertz/material" in text
    rows = [line for line in text.splitlines() if line.startswith("| ") and line.endswith("|")
            and line.count("|") == 6 and "exact e" not in line]
    assert len(rows) == 5 and all(line.rstrip(" |").endswith("ok") for line in rows)
    # each LAMMPS e within the table's tolerance of the exact e
    assert all(abs(float(line.split("|")[4])) <= 1e-3 for line in rows)
