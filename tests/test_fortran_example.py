"""examples/c/zener_sym.f90, the Fortran bindings of the C kernels: built with gfortran's strict
flags together with examples/c/fortran_demo.f90 and run; what Fortran reads through the
``bind(C)`` interfaces (the struct field for field, arguments by value, arrays) is what the Python
package gives for the same calls. gfortran is optional: without it the test skips and says so.
"""
from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

import zener_sym as zs
from conftest import ROOT

GFORTRAN = shutil.which("gfortran")
CC = shutil.which("gcc") or shutil.which("cc")
FIELDS = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2",
          "xi")

pytestmark = pytest.mark.skipif(GFORTRAN is None or CC is None,
                                reason="gfortran and a C compiler are needed for the Fortran "
                                       "example (apt-get install gfortran); not checked here")


@pytest.fixture(scope="module")
def demo_output(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fortran")
    c_dir, ex = ROOT / "generated" / "c", ROOT / "examples" / "c"
    steps = [[CC, "-std=c99", "-O2", "-c", str(c_dir / "zener_sym.c"), "-o", str(tmp / "zs.o")],
             [GFORTRAN, "-std=f2008", "-Wall", "-Wextra", "-Werror", "-O2", "-J", str(tmp),
              str(ex / "zener_sym.f90"), str(ex / "fortran_demo.f90"), str(tmp / "zs.o"), "-lm",
              "-o", str(tmp / "demo")]]
    for args in steps:
        run = subprocess.run(args, capture_output=True, text=True, cwd=tmp)
        assert run.returncode == 0, run.stderr
    run = subprocess.run([str(tmp / "demo")], capture_output=True, text=True, check=True)
    return run.stdout.splitlines()


def _numbers(line: str) -> np.ndarray:
    return np.array([float(x) for x in line.split()])


@pytest.mark.parametrize("block, end", [(0, "delta"), (1, "force")])
def test_fortran_reads_what_python_gives(demo_output, block, end):
    lines = demo_output[8 * block: 8 * block + 8]
    assert lines[0].split() == ["summary", "end", str(block), "rc", "0"]
    got = dict(zip(FIELDS, _numbers(lines[1])))
    ref = zs.summary(0.3, model="exact", contact_end=end)
    for f in FIELDS:
        assert got[f] == pytest.approx(float(getattr(ref, f)), rel=1e-14, abs=0), f
    assert lines[2].split() == ["history", "rc", "0"]
    rows = np.array([_numbers(x) for x in lines[3:7]])
    np.testing.assert_allclose(rows[:, 0], np.array([0.25, 0.5, 1.0, 2.0]) * ref.tau_dc,
                               rtol=1e-15)
    h = zs.history(0.3, rows[:, 0], model="exact", contact_end=end)
    for col, (f, scale) in enumerate((("delta", ref.delta_m), ("velocity", 1.0),
                                      ("force", ref.F_m), ("impulse", 1.0)), start=1):
        assert np.abs(rows[:, col] - getattr(h, f)).max() <= 1e-14 * scale, f
    assert lines[7].split()[0] == "lam_for_e"
    assert float(lines[7].split()[1]) == pytest.approx(0.3, rel=1e-13)


def test_fortran_ham1_and_the_domain_error(demo_output):
    word, rc, code, e, tau_d = demo_output[16].split()
    ref = zs.summary(0.3, model="ham1")
    assert (word, rc, code) == ("ham1", "rc", "0")
    assert float(e) == pytest.approx(ref.e, rel=1e-12)
    assert float(tau_d) == pytest.approx(ref.tau_d, rel=1e-12)
    assert demo_output[17].split() == ["outside", "rc", "1", "e", "is", "NaN", "T"]
