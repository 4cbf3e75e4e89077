"""``zener-sym fit``: fits A from a CSV, writes the chart, refuses with one line and exit code 2."""
from __future__ import annotations

import re

import numpy as np
import pytest

import zener_sym as zs
from zener_sym import cli

A_TRUE = 3e-7
SPEEDS = np.array([20.0, 50.0, 100.0, 200.0, 400.0])  # cm/s


def _csv(tmp_path, header="v0 [cm/s],e", reverse_e=False):
    e = [zs.grain_impact("glass", "1 mm", 1e-5, A=A_TRUE, v0=float(v) / 100.0, wall="steel",
                         contact_end="delta").e for v in SPEEDS]
    if reverse_e:  # e rising with speed
        e = e[::-1]
    path = tmp_path / "drops.csv"
    path.write_text("# synthetic\n" + header + "\n"
                    + "".join(f"{float(v)!r},{float(x)!r}\n" for v, x in zip(SPEEDS, e)))
    return path


def _argv(path, *extra):
    return ["fit", "--data", str(path), "--sphere", "glass", "--radius", "1mm", "--mass",
            "0.01g", "--wall", "steel", "--contact-end", "delta", *extra]


def test_fit_prints_A_and_writes_the_chart(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out_png = tmp_path / "fit.png"
    assert cli.main(_argv(_csv(tmp_path), "--plot", str(out_png))) == 0
    out = capsys.readouterr().out
    A = float(re.search(r"A = (\S+) s", out).group(1))
    assert A == pytest.approx(A_TRUE, rel=1e-5)  # printed to 6 digits
    assert "speeds read in cm/s" in out and f"plot: {out_png}" in out
    assert out_png.stat().st_size > 0


@pytest.mark.parametrize("header,message", [
    ("v0,e", "has no unit"),
    ("v0 [m/h],e", "is not one of"),
    ("speed,e", "no speed column"),
])
def test_fit_refuses_a_speed_without_a_clear_unit(tmp_path, capsys, header, message):
    assert cli.main(_argv(_csv(tmp_path, header=header))) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1, err


@pytest.mark.parametrize("extra,message", [
    (("--mass", "10"), "--mass 10: give a number with a unit"),
    (("--mass", "-1g"), "--mass must be finite and > 0"),
    (("--radius", "1"), "--radius 1: give a unit"),
    (("--plot", "out.gif"), "--plot out.gif: give a file name ending in"),
    (("--radius2", "1mm"), "give either --wall or a second sphere"),
])
def test_fit_refuses_bad_options(tmp_path, capsys, extra, message):
    assert cli.main(_argv(_csv(tmp_path), *extra)) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1, err


def test_fit_refuses_a_missing_file_and_rising_e(tmp_path, capsys):
    assert cli.main(_argv(tmp_path / "none.csv")) == 2
    assert "cannot read" in capsys.readouterr().err
    assert cli.main(_argv(_csv(tmp_path, reverse_e=True))) == 2
    assert "e rises with speed" in capsys.readouterr().err


def test_fit_two_spheres_matches_the_python_fit(tmp_path, capsys):
    path = _csv(tmp_path)
    argv = ["fit", "--data", str(path), "--sphere", "glass", "--radius", "1mm", "--mass", "0.01g",
            "--sphere2", "steel", "--radius2", "2mm", "--mass2", "0.05g", "--contact-end", "delta"]
    assert cli.main(argv) == 0
    A_cli = float(re.search(r"A = (\S+) s", capsys.readouterr().out).group(1))
    m = zs.scene.calibrate.read_measurements(path)
    fit = zs.fit_dissipation("glass", "1 mm", 1e-5, v0=m.v0, e=m.e, sphere2="steel",
                             radius2="2 mm", mass2=5e-5, contact_end="delta")
    assert A_cli == pytest.approx(fit.A, rel=1e-5)
