"""The emitted C kernels (generated/c) against the Python package.

The C library is compiled here with the strict flags of the issue (C99, -Wall -Wextra -Werror
-pedantic; and as C++), once as a shared library called through ctypes, once with
-fsanitize=address,undefined into a driver that runs every entry point. References:

* exact summaries and histories: the exact model's table backend through the public api
  (``zs.summary``/``zs.history``, ``backend="table"``): same coefficients, so within 1e-14
  relative (histories: 1e-14 of the value, with a floor of 1e-14 of the field's scale where the
  value is far below it), at every lambda-piece edge, random lambda in [0, 1000], and the ends
  of every time piece with their neighbouring doubles;
* the inverse: lambda from a bracketing root finder (scipy brentq) on the Python e(lambda) or
  xi(lambda), and ``zs.lam_for`` where the tree has it;
* ham0/ham1: the generated numpy kernels (quadrature) and the models' numpy histories, 1e-12.

A missing compiler skips with that reason.
"""
from __future__ import annotations

import ctypes
import math
import pathlib
import re
import shutil
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
C_DIR = ROOT / "generated" / "c"
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
CC = shutil.which("gcc") or shutil.which("cc")
CXX = shutil.which("g++")

pytestmark = pytest.mark.skipif(CC is None, reason="no C compiler (gcc or cc) on PATH: the C "
                                                   "kernels cannot be built here")


# --- the Python side, imported in one place ---------------------------------------------------
def _python():
    """The Python references (one place: these imports may move). ``exact`` is the exact model's
    table backend through the public api; ``table`` the generated table module, read as data
    (piece ends, layout constants)."""
    from zener_sym import api
    from zener_sym.generated import exact_table

    # the numpy HAM kernels (the runtime around the formula-only generated files) and the
    # Gauss-Jacobi rule of the first-order integrals
    from zener_sym.ham.runtime_numpy import ham0 as ham0_numpy
    from zener_sym.ham.runtime_numpy import ham1 as ham1_numpy
    from zener_sym.numerics import sqrt_integrals as quadrature

    def exact_summary(lam):
        return api.summary(np.atleast_1d(lam), model="exact", backend="table")

    def exact_history(lam, tau):
        return api.history(lam, tau, model="exact", backend="table")

    return {"api": api, "exact_summary": exact_summary, "exact_history": exact_history,
            "table": exact_table, "ham0": ham0_numpy, "ham1": ham1_numpy,
            "quadrature": quadrature}


PY = _python()
FIELDS = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2",
          "xi")


class Summary(ctypes.Structure):
    _fields_ = [(f, ctypes.c_double) for f in FIELDS]


def _compile(args, cwd):
    r = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(args)} failed:\n{r.stderr}"
    return r


def _load(d, name, flags, cc=None):
    """generated/c/zener_sym.c built in ``d`` as a shared library with ``flags`` (by ``cc``,
    default CC), loaded through ctypes with the API's signatures."""
    so = d / f"lib{name}.so"
    _compile([cc or CC, *flags, "-fPIC", "-shared", str(C_DIR / "zener_sym.c"), "-o", str(so),
              "-lm"], d)
    L = ctypes.CDLL(str(so))
    P = ctypes.POINTER(ctypes.c_double)
    L.zs_summary.argtypes = [ctypes.c_double, ctypes.c_int, ctypes.POINTER(Summary)]
    L.zs_history.argtypes = [ctypes.c_double, ctypes.c_int, ctypes.c_size_t, P, P, P, P, P]
    L.zs_lam_for_e.argtypes = [ctypes.c_double, ctypes.c_int]
    L.zs_lam_for_e.restype = ctypes.c_double
    for f in ("zs_ham0_history", "zs_ham1_history"):
        getattr(L, f).argtypes = [ctypes.c_double, ctypes.c_size_t, P, P, P]
    L.zs_ham1_summary.argtypes = [ctypes.c_double, ctypes.POINTER(Summary)]
    return L


@pytest.fixture(scope="module")
def lib(tmp_path_factory):
    return _load(tmp_path_factory.mktemp("zs_c"), "zener_sym", [*STRICT, "-O2"])


def _ptr(a):
    return None if a is None else a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


def c_summary(lib, lam, end=0, ham1=False):
    s = Summary()
    rc = lib.zs_ham1_summary(lam, ctypes.byref(s)) if ham1 else lib.zs_summary(lam, end,
                                                                               ctypes.byref(s))
    return rc, {f: getattr(s, f) for f in FIELDS}


def c_history(lib, lam, tau, end=0):
    tau = np.ascontiguousarray(tau, dtype=float)
    out = {f: np.empty(tau.size) for f in ("delta", "velocity", "force", "impulse")}
    rc = lib.zs_history(lam, end, tau.size, _ptr(tau), _ptr(out["delta"]), _ptr(out["velocity"]),
                        _ptr(out["force"]), _ptr(out["impulse"]))
    return rc, out


def c_ham(lib, order, lam, tau):
    tau = np.ascontiguousarray(tau, dtype=float)
    d, f = np.empty(tau.size), np.empty(tau.size)
    fn = lib.zs_ham0_history if order == 0 else lib.zs_ham1_history
    return fn(lam, tau.size, _ptr(tau), _ptr(d), _ptr(f)), d, f


# --- compilation -----------------------------------------------------------------------------
def test_strict_c99_and_cxx(tmp_path):
    """The header and the source compile clean with the strict flags, and as C++."""
    src = tmp_path / "use.c"
    src.write_text('#include "zener_sym.h"\nint main(void) { zs_summary_t s; '
                   'return zs_summary(1.0, ZS_DELTA, &s); }\n')
    _compile([CC, *STRICT, "-O2", "-I", str(C_DIR), str(src), str(C_DIR / "zener_sym.c"), "-o",
              str(tmp_path / "use"), "-lm"], tmp_path)
    if CXX is None:
        pytest.skip("no C++ compiler (g++): the C++ build is not checked here")
    _compile([CXX, "-Wall", "-Wextra", "-Werror", "-pedantic", "-O1", "-x", "c++", "-I",
              str(C_DIR), str(src), "-x", "c++", str(C_DIR / "zener_sym.c"), "-o",
              str(tmp_path / "use_cxx")], tmp_path)


# --- the runtime's own exp and log1p passes (codegen/c/fastmath.py) --------------------------
PASS_DRIVER = r"""
#include "zener_sym.c"
#include <stdio.h>
/* stdin: n (even), then n doubles; stdout: zs__exp_pass of them, then zs__log1p_pass */
int main(void)
{
    static double x[ZS__BLOCK], y[ZS__BLOCK], one[ZS__BLOCK];
    size_t n, i;
    if (fread(&n, sizeof n, 1, stdin) != 1 || n % 2 || n > ZS__BLOCK
        || fread(x, sizeof x[0], n, stdin) != n)
        return 2;
    for (i = 0; i < n; i++) {
        y[i] = x[i];
        one[i] = 1.0;
    }
    zs__exp_pass(n / 2, y);
    fwrite(y, sizeof y[0], n, stdout);
    for (i = 0; i < n; i++)
        y[i] = x[i];
    zs__log1p_pass(n / 2, y, one);
    fwrite(y, sizeof y[0], n, stdout);
    return 0;
}
"""


def _run_passes(exe, x):
    """zs__exp_pass and zs__log1p_pass of x (in blocks of 256), by the compiled driver."""
    out_e, out_l = [], []
    for i in range(0, x.size, 256):
        blk = np.ascontiguousarray(x[i:i + 256], dtype=float)
        inp = np.array([blk.size], dtype=np.uintp).tobytes() + blk.tobytes()
        r = subprocess.run([str(exe)], input=inp, capture_output=True, check=True)
        y = np.frombuffer(r.stdout, dtype=float)
        out_e.append(y[:blk.size])
        out_l.append(y[blk.size:])
    return np.concatenate(out_e), np.concatenate(out_l)


def _ulps(got, ref):
    """|got - ref| / |ref| in units of 2^-53, ref an mpmath number."""
    import mpmath

    return float(abs(mpmath.mpf(float(got)) - ref) / abs(ref) * mpmath.mpf(2) ** 53)


def test_exp_and_log1p_passes_against_mpmath(tmp_path):
    """The history's own exp (Cody-Waite reduction, Taylor by Estrin) and log1p (fdlibm's
    reduction, atanh series, Goldberg's correction) within 4 units of 2^-53 relative of mpmath
    at 40 digits (the constants come from fastmath.py; the formulas are checked here by their
    results), over the ranges the history feeds them and beyond; exp hands |x| >= 700 to libm."""
    import mpmath

    src = tmp_path / "passes.c"
    src.write_text(PASS_DRIVER)
    exe = tmp_path / "passes"
    _compile([CC, *STRICT, "-O2", "-I", str(C_DIR), str(src), "-o", str(exe), "-lm"], tmp_path)
    rng = np.random.default_rng(26)
    xe = np.concatenate([rng.uniform(-40, 40, 1000), rng.uniform(-699.9, 699.9, 500),
                         [0.0, -0.0, 1e-300, -1e-17, 0.5 * math.log(2), -0.5 * math.log(2),
                          699.99, -699.99, 705.0, -705.0]])
    xl = np.concatenate([rng.uniform(-1e-3, 1e-3, 400), rng.uniform(-1e-12, 1e-12, 200),
                         rng.uniform(-0.9, 3.0, 600), rng.uniform(3.0, 1e6, 300),
                         [0.0, 1e-300, -0.5, math.sqrt(2) - 1, 1 / math.sqrt(2) - 1, 1.0, 2.0,
                          1e300, 0.0]])
    n = max(xe.size, xl.size) + (max(xe.size, xl.size) % 2)
    xe = np.resize(xe, n)
    xl = np.resize(xl, n)
    ye, _ = _run_passes(exe, xe)
    _, yl = _run_passes(exe, xl)
    with mpmath.workdps(40):
        worst_e = max(_ulps(y, mpmath.exp(mpmath.mpf(float(x)))) for x, y in zip(xe, ye))
        worst_l = max(_ulps(y, mpmath.log1p(mpmath.mpf(float(x)))) for x, y in zip(xl, yl)
                      if x != 0.0)
    assert worst_e <= 4.0, worst_e
    assert worst_l <= 4.0, worst_l
    assert np.all(yl[xl == 0.0] == 0.0)


# --- exact model -----------------------------------------------------------------------------
def _table_edges(t):
    """A generated table's piece ends and where its ln-lambda pieces start, read from its
    description (TABLE_PIECES: (kind, start, end) per lambda piece)."""
    edges = [float(a) for _, a, _ in t.TABLE_PIECES] + [float(t.TABLE_PIECES[-1][2])]
    return edges, min(float(a) for k, a, _ in t.TABLE_PIECES if k == "log")


def _edges():
    return _table_edges(PY["table"])[0]


def _lams():
    rng = np.random.default_rng(25)
    return sorted(set(_edges()) | {float(x) for x in rng.uniform(0, 1000, 12)}
                  | {float(x) for x in rng.uniform(0, 5, 6)} | {1e-9, 0.3, 4.999999})


def test_exact_summary_matches_python(lib):
    for lam in _lams():
        rc, c = c_summary(lib, lam)
        assert rc == 0
        py = PY["exact_summary"](lam)
        for f in FIELDS:
            want = float(getattr(py, f)[0])
            assert c[f] == pytest.approx(want, rel=1e-14, abs=1e-300), (lam, f)


def _piece_times(lam):
    """Times at the ends of every time piece (tau_dc; tau_s and tau_w0 of the recovery pieces;
    tau_d), their neighbouring doubles and a grid over the contact. The ends are evaluated here
    from the generated table's coefficients with numpy's chebval and the table's layout
    constants (tau_w0 = tau_dc + lambda rest_over_lam; above LOG_FROM tau_s = tau_dc + lambda
    (S_ORBIT + S_TRANSIENT lambda^(-5/3)), table_build.split_time), not by the code under test."""
    t = PY["table"]
    edges, log_from = _table_edges(t)
    i = min(int(np.searchsorted(edges, lam, side="right")) - 1, len(edges) - 2)
    a, b = edges[i], edges[i + 1]
    log = a >= log_from
    g, ga, gb = (np.log(lam), np.log(a), np.log(b)) if log else (lam, a, b)
    x = np.clip((2 * g - ga - gb) / (gb - ga), -1, 1)
    v = {k: float(np.polynomial.chebyshev.chebval(x, t.SUMMARY[k][i])) for k in t.SUMMARY}
    tau_dc, tau_d = v["tau_dc"], float(np.exp(v["log_tau_d"]))
    tau_w0 = tau_dc + lam * v["rest_over_lam"]
    tau_s = (tau_dc + lam * (t.S_ORBIT + t.S_TRANSIENT * lam ** (-5 / 3))) if log else tau_w0
    ends = [0.0, tau_dc, tau_s, tau_w0, tau_d]
    pts = list(ends) + [np.nextafter(x, 0) for x in ends[1:]] + [np.nextafter(x, np.inf)
                                                                  for x in ends]
    pts += list(np.linspace(0, 1.05 * tau_d, 400))
    return np.array(sorted(pts)), v


#: ulps of tau_d within which a time may fall on either side of the end of contact: C forms
#: tau_d = exp(log tau_d) with libm's exp, Python with numpy's, and their last bits differ on
#: some processors (numpy's AVX-512 exp and glibc's disagree on about 5% of arguments)
TAU_D_ULPS = 4


def _tau_d_sides(tau, td):
    """Times within TAU_D_ULPS ulps of tau_d (a mask), and a time just inside and just past
    the end: where the two tau_d differ by an ulp, such a time is inside the contact for one
    side and past its end for the other, and either value is right."""
    near = np.abs(tau - td) <= TAU_D_ULPS * np.spacing(td)
    lo, hi = td - 2 * TAU_D_ULPS * np.spacing(td), td + 2 * TAU_D_ULPS * np.spacing(td)
    return near, lo, hi


def test_exact_history_matches_python(lib):
    for lam in _lams():
        tau, v = _piece_times(lam)
        rc, c = c_history(lib, lam, tau)
        assert rc == 0
        py = PY["exact_history"](lam, tau)
        near, lo, hi = _tau_d_sides(tau, float(np.exp(v["log_tau_d"])))
        ends = PY["exact_history"](lam, np.array([lo, hi]))
        dm = v["delta_m"]
        scale = {"delta": dm, "force": dm**1.5, "impulse": 1.0, "velocity": 1.0}
        for f, s in scale.items():
            err = np.abs(c[f] - getattr(py, f))
            # at tau_d (to its last bit) the value just inside or just past the end
            for ref in getattr(ends, f):
                err[near] = np.minimum(err[near], np.abs(c[f][near] - ref))
            # relative to the value where it is of the field's scale, to the scale near the
            # zeros (tau = 0, tau_d), where the value is ill-conditioned for any evaluation
            bad = err > 1e-14 * np.maximum(np.abs(getattr(py, f)), s)
            assert not bad.any(), (lam, f, tau[bad][:3], c[f][bad][:3], getattr(py, f)[bad][:3])


def _every_output(L):
    """Everything the library computes on a common set of inputs, as one array per entry point
    (summaries and histories of both ends of contact at the test's lambda and piece ends, the
    inverse, the HAM kernels), for comparing builds."""
    out = []
    for lam in _lams():
        tau, _ = _piece_times(lam)
        out.append(np.array(list(c_summary(L, lam, 0)[1].values())))
        out.append(np.concatenate(list(c_history(L, lam, tau, 0)[1].values())))
    for lam in _force_lams():
        tau, _ = _force_piece_times(lam)
        out.append(np.array(list(c_summary(L, lam, 1)[1].values())))
        out.append(np.concatenate(list(c_history(L, lam, tau, 1)[1].values())))
    out.append(np.array([L.zs_lam_for_e(e, end) for e in np.linspace(0.05, 0.999, 40)
                         for end in (0, 1)]))
    tau = np.linspace(0.0, 3.5, 300)
    for lam in (0.0, 0.3, 1.2):
        out += list(c_ham(L, 0, lam, tau)[1:]) + list(c_ham(L, 1, lam, tau)[1:])
        out.append(np.array(list(c_summary(L, lam, ham1=True)[1].values())))
    return out


CLANG = shutil.which("clang")


@pytest.mark.parametrize("cc, flags", [
    ("gcc", ["-O3", "-march=native"]),  # the bench's judged build: this machine's vector units
    ("gcc", ["-O3"]),                   # a CMake Release build
    ("gcc", ["-O2", "-U__SSE2__", "-U__AVX__"]),  # the contraction's plain C loops
    # GNU C contracts a * b + c into fused multiply-adds where the processor has them (moving a
    # history by up to 2.5e-11 before the source turned contraction off); and where the processor
    # has AVX512-FP16, GNU C says FLT_EVAL_METHOD 16 (the exp pass once took that for x87 and
    # fell back to libm's exp, a last bit apart)
    ("gcc", ["-std=gnu11", "-O3", "-march=native", "-ffp-contract=fast"]),
    ("clang", ["-O3", "-march=native"]),
    # clang's default contraction (-ffp-contract=on) obeys the source's STDC FP_CONTRACT OFF;
    # an explicit -ffp-contract=fast overrides any pragma (clang's rule; examples/c/README.md)
    ("clang", ["-std=gnu11", "-O3", "-march=native"]),
], ids=["gcc-O3-native", "gcc-O3", "gcc-O2-no-vector-types", "gcc-gnu11-O3-native-fp-contract",
        "clang-O3-native", "clang-gnu11-O3-native"])
def test_builds_give_the_same_doubles(tmp_path, lib, cc, flags):
    """At any optimisation, instruction set and contraction setting: the same doubles as the
    -O2 build the other tests check against Python, bit for bit (the contraction's vector and
    scalar loops add the same terms in the same order; the source turns off fused
    multiply-adds). The clang builds run where clang is installed (CI has gcc only)."""
    if cc == "clang" and CLANG is None:
        pytest.skip("clang is not installed: its builds are not compared here")
    if cc == "gcc" and shutil.which("gcc") is None:
        pytest.skip("gcc is not installed (the -O2 reference build used another cc)")
    std = [] if any(f.startswith("-std=") for f in flags) else STRICT
    other = _load(tmp_path, "other", [*std, *flags], cc=shutil.which(cc))
    for a, b in zip(_every_output(lib), _every_output(other), strict=True):
        np.testing.assert_array_equal(b, a)


def test_fast_math_build_is_refused(tmp_path):
    """-ffast-math would drop the NaN checks (ZS_EDOM) and the exp pass's rounding step: the
    source refuses it at compile time with a message that says so, instead of building
    something that answers wrongly."""
    r = subprocess.run([CC, "-std=c99", "-O2", "-ffast-math", "-c", str(C_DIR / "zener_sym.c"),
                        "-o", str(tmp_path / "fm.o")], capture_output=True, text=True)
    assert r.returncode != 0
    assert "without -ffast-math" in r.stderr


def test_exact_history_pointwise_relative(lib):
    """delta relative pointwise (1e-14) away from the zeros at tau = 0 and tau_d, plus what an
    ulp of tau_d moves it by: near the end delta is (tau_d - tau) times a smooth factor, so
    libm's and numpy's exp, differing in tau_d's last bit (TAU_D_ULPS), differ in delta by
    spacing(tau_d) / (tau_d - tau) relative (1e-13 at 0.999 tau_d)."""
    for lam in (0.0, 0.7, 3.0, 42.0, 1000.0):
        tau, v = _piece_times(lam)
        td = float(np.exp(v["log_tau_d"]))
        tau = tau[(tau > 1e-3 * td) & (tau < 0.999 * td)]
        _, c = c_history(lib, lam, tau)
        py = PY["exact_history"](lam, tau)
        rtol = 1e-14 + np.spacing(td) / (td - tau)
        bad = ~(np.abs(c["delta"] - py.delta) <= rtol * np.abs(py.delta))
        assert not bad.any(), (lam, tau[bad][:3], c["delta"][bad][:3], py.delta[bad][:3])
        np.testing.assert_allclose(c["impulse"], py.impulse, rtol=1e-14, atol=0)


def test_force_end_summary_matches_python(lib):
    """ZS_FORCE summaries against the force-free end's tables in Python (same coefficients), and
    the inverse at that end against zs.lam_from_summary. The tables are part of the tree: if they cannot
    answer, the test fails (it used to skip)."""
    api = PY["api"]
    for lam in _lams() + [1e-12, 0.25, 0.01]:
        rc, c = c_summary(lib, lam, 1)
        assert rc == 0
        py = api.summary(lam, model="exact", contact_end="force", backend="table")
        for f in FIELDS:
            assert c[f] == pytest.approx(float(getattr(py, f)), rel=1e-14, abs=1e-300), (lam, f)
    for e in (1 - 1e-9, 0.9, 0.5, 0.1, 1e-3):
        assert lib.zs_lam_for_e(e, 1) == pytest.approx(
            api.lam_from_summary(e=e, contact_end="force"), rel=1e-12), e


def _force_piece_times(lam):
    """The force-free end's time-piece ends (0, tau_dc, tau_d), their neighbouring doubles and a
    grid to past the end of contact; the ends from the generated force table's coefficients
    (numpy's chebval in the piece's variable: sqrt(lambda) below LOG_FROM, ln lambda above), not
    by the code under test."""
    from zener_sym.generated import exact_force_table as t

    edges, log_from = _table_edges(t)
    i = min(int(np.searchsorted(edges, lam, side="right")) - 1, len(edges) - 2)
    a, b = edges[i], edges[i + 1]
    f = np.log if a >= log_from else np.sqrt
    x = np.clip((2 * f(lam) - f(a) - f(b)) / (f(b) - f(a)), -1, 1)
    v = {k: float(np.polynomial.chebyshev.chebval(x, t.SUMMARY[k][i])) for k in t.SUMMARY}
    tau_dc, tau_d = v["tau_dc"], float(np.exp(v["log_tau_d"]))
    ends = [0.0, tau_dc, tau_d]
    pts = list(ends) + [np.nextafter(x, 0) for x in ends[1:]] + [np.nextafter(x, np.inf)
                                                                  for x in ends]
    pts += list(np.linspace(0, 1.1 * tau_d, 400))
    return np.array(sorted(pts)), v


def _force_lams():
    from zener_sym.generated import exact_force_table as t

    rng = np.random.default_rng(2025)
    return sorted(set(_table_edges(t)[0]) | {float(x) for x in rng.uniform(0, 1000, 12)}
                  | {float(x) for x in rng.uniform(0, 5, 6)} | {1e-12, 1e-9, 0.01, 4.999999})


def test_force_end_history_matches_python(lib):
    """ZS_FORCE histories against the force-free end's tables in Python (same coefficients):
    within 1e-14 of the value, with a floor of 1e-14 of each field's scale (delta_m, F_m, 1 for
    the velocity and the impulse), at every lambda piece's edge and random lambda, at the ends
    of the time pieces C and R with their neighbouring doubles, and past the end of contact."""
    api = PY["api"]
    for lam in _force_lams():
        tau, v = _force_piece_times(lam)
        rc, c = c_history(lib, lam, tau, 1)
        assert rc == 0
        py = api.history(lam, tau, model="exact", contact_end="force", backend="table")
        dm, fm = v["delta_m"], float(np.exp(v["log_F_m"]))
        scale = {"delta": dm, "force": fm, "impulse": 1.0, "velocity": 1.0}
        for f, s in scale.items():
            want = getattr(py, f)
            err = np.abs(c[f] - want)
            bad = ~(err <= 1e-14 * np.maximum(np.abs(want), s))
            assert not bad.any(), (lam, f, tau[bad][:3], c[f][bad][:3], want[bad][:3])
        # past the end of contact: no contact left, the velocity -e (the Python history's)
        past = tau > np.exp(v["log_tau_d"]) * (1 + 1e-12)
        assert past.any() and np.all(c["delta"][past] == 0.0)
        e = float(api.summary(lam, model="exact", contact_end="force", backend="table").e)
        np.testing.assert_allclose(c["velocity"][past], -e, rtol=1e-15, atol=0)
        np.testing.assert_allclose(c["impulse"][past], 1.0 + e, rtol=1e-15, atol=0)
        # unsorted times and NULL outputs give the same numbers
        perm = np.random.default_rng(7).permutation(tau.size)
        tp = np.ascontiguousarray(tau[perm])
        d = np.empty(tau.size)
        n = ctypes.POINTER(ctypes.c_double)()
        assert lib.zs_history(lam, 1, tau.size, _ptr(tp), _ptr(d), n, n, n) == 0
        np.testing.assert_array_equal(d, c["delta"][perm])


def test_force_end_history_pointwise_relative(lib):
    """delta and the velocity relative pointwise (1e-14) inside the contact, away from the zeros
    of delta (tau = 0, tau_d) and of the velocity (near tau_dc)."""
    api = PY["api"]
    for lam in (0.0, 0.7, 3.0, 42.0, 1000.0):
        tau, v = _force_piece_times(lam)
        td, tdc = float(np.exp(v["log_tau_d"])), v["tau_dc"]
        tau = tau[(tau > 1e-3 * td) & (tau < 0.999 * td) & (np.abs(tau - tdc) > 0.05 * tdc)]
        _, c = c_history(lib, lam, tau, 1)
        py = api.history(lam, tau, model="exact", contact_end="force", backend="table")
        np.testing.assert_allclose(c["delta"], py.delta, rtol=1e-14, atol=0)
        np.testing.assert_allclose(c["velocity"], py.velocity, rtol=1e-14, atol=0)


def test_lam_for_e_inverts_python_e(lib):
    """lambda(e) against brentq on the Python table's e(lambda), and the round trip."""
    from scipy.optimize import brentq

    e_of = lambda x: float(PY["exact_summary"](x).e[0])  # noqa: E731
    xi_of = lambda x: float(PY["exact_summary"](x).xi[0])  # noqa: E731
    for e in (1 - 1e-12, 0.999999, 0.999, 0.95, 0.8, 0.5, 0.2, 0.05, 1e-3, 1e-6):
        lam = lib.zs_lam_for_e(e, 0)
        xi = (1 - e) * (1 + e)
        if xi < 0.5:  # near e = 1 lambda is conditioned by xi = 1 - e^2, not by e
            ref = brentq(lambda x: xi_of(x) - xi, 0.0, 1000.0, xtol=1e-300, rtol=8.9e-16)
            assert xi_of(lam) == pytest.approx(xi, rel=1e-14)
        else:
            ref = brentq(lambda x: e_of(x) - e, 0.0, 1000.0, xtol=1e-17, rtol=8.9e-16)
            assert e_of(lam) == pytest.approx(e, rel=1e-14)
        assert lam == pytest.approx(ref, rel=1e-12), e
    assert lib.zs_lam_for_e(1.0, 0) == 0.0


def test_lam_for_e_matches_python_inverse(lib):
    """Against the package's own inverse (``zs.lam_from_summary``, the exact tables' safeguarded
    Newton)."""
    lam_for = PY["api"].lam_from_summary
    for e in (1 - 1e-9, 0.99, 0.9, 0.7, 0.5, 0.3, 0.1, 0.01, 1e-5):
        assert lib.zs_lam_for_e(e, 0) == pytest.approx(lam_for(e=e), rel=1e-12), e


# --- HAM kernels -----------------------------------------------------------------------------
def _ham_lams():
    lc = PY["ham1"].LAM_CRIT
    return [0.0, 0.1, 0.5, 1.0, 1.5, 2.0, 2.03, 2.2, 2.4, 0.999 * lc]


def test_ham0_history_matches_numpy(lib):
    h0 = PY["ham0"]
    for lam in _ham_lams():
        _, _, omega0 = h0.params(lam)
        td = math.pi / float(omega0)
        tau = np.concatenate([np.linspace(0, 1.1 * td, 300), [td, np.nextafter(td, 0)]])
        rc, d, f = c_ham(lib, 0, lam, tau)
        assert rc == 0
        ref = np.where(tau < td, np.maximum(h0.delta(tau, lam), 0.0), 0.0)
        np.testing.assert_allclose(d, ref, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(f, ref**1.5, rtol=1e-12, atol=1e-12)
        m = PY["api"].history(lam, tau, model="ham0", fields=("delta", "force"))
        np.testing.assert_allclose(d, m.delta, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(f, m.force, rtol=1e-12, atol=1e-12)


def test_ham1_history_matches_numpy(lib):
    h1 = PY["ham1"]
    for lam in _ham_lams():
        rc, s = c_summary(lib, lam, ham1=True)
        td = s["tau_d"]
        tau = np.concatenate([np.linspace(0, 1.1 * td, 120), [np.nextafter(td, 0)]])
        rc, d, f = c_ham(lib, 1, lam, tau)
        assert rc == 0
        ref = np.where(tau < td, np.maximum(h1.delta(tau, lam), 0.0), 0.0)
        np.testing.assert_allclose(d, ref, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(f, ref**1.5, rtol=1e-12, atol=1e-12)
        m = PY["api"].history(lam, tau, model="ham1", fields=("delta", "force"))
        np.testing.assert_allclose(d, m.delta, rtol=1e-12, atol=1e-12)


def test_ham1_rule_is_the_numpy_kernels(lib):
    """The C file's Gauss-Jacobi rule has the numpy kernels' size and cut (codegen cannot import
    that helper, so it keeps its own copy of the two numbers)."""
    text = (C_DIR / "zener_sym.c").read_text()
    q = PY["quadrature"]
    assert f"#define ZS__GJ_N {q.N_NODES}\n" in text
    assert f"#define ZS__GJ_CUT {float(q.CUT)!r}\n" in text


def test_ham1_summary_matches_python(lib):
    for lam in _ham_lams() + list(np.random.default_rng(3).uniform(0, 2.44, 8)):
        rc, c = c_summary(lib, float(lam), ham1=True)
        assert rc == 0
        py = PY["api"].summary(float(lam), model="ham1")
        for f in FIELDS:
            assert c[f] == pytest.approx(float(getattr(py, f)), rel=1e-12, abs=1e-300), (lam, f)
    # the one table evaluator: the stored fields are Python's to the last bit (zs__eval in order
    # of degree, as numerics.cheb_table.SummaryTable)
    from zener_sym.ham import table as ham1_table

    lams = np.concatenate([np.linspace(0.0, 2.44, 301), _ham_lams()])
    py = ham1_table.summary(lams)
    got = np.array([[c_summary(lib, float(lam), ham1=True)[1][f]
                     for f in ("delta_m", "tau_dc", "impulse", "int_F2")] for lam in lams])
    for j, f in enumerate(("delta_m", "tau_dc", "impulse", "int_F2")):
        np.testing.assert_array_equal(got[:, j], py[f], err_msg=f)
    # against the root finding and quadrature of the numpy kernels (the tables' own accuracy)
    k = PY["ham1"].summary(np.array([0.5, 1.7]))
    for i, lam in enumerate((0.5, 1.7)):
        _, c = c_summary(lib, lam, ham1=True)
        for f in ("tau_dc", "tau_d", "e", "delta_m", "impulse", "int_F2"):
            assert c[f] == pytest.approx(float(k[f][i]), rel=1e-11), (lam, f)


# --- ZS_EDOM ---------------------------------------------------------------------------------
NAN = float("nan")


def _all_nan(values):
    return all(math.isnan(v) for v in values)


def test_edom_cases(lib):
    lc = PY["ham1"].LAM_CRIT
    tau_ok = np.array([0.0, 1.0])
    for lam in (NAN, -1e-300, -1.0, 1000.0000000001, 1001.0, float("inf")):
        rc, s = c_summary(lib, lam)
        assert rc == 1 and _all_nan([s[f] for f in FIELDS if f != "lam"]), lam
        rc, h = c_history(lib, lam, tau_ok)
        assert rc == 1 and all(_all_nan(v) for v in h.values()), lam
    for end in (-1, 2, 7):
        assert c_summary(lib, 1.0, end)[0] == 1
        assert c_history(lib, 1.0, tau_ok, end)[0] == 1
        assert math.isnan(lib.zs_lam_for_e(0.5, end))
    # the force-free end: its range and its times checked as the plate's
    assert c_summary(lib, 1.0, 1)[0] == 0 and c_history(lib, 1.0, tau_ok, 1)[0] == 0
    for lam in (NAN, -1.0, 1000.0000000001, 1001.0, float("inf")):
        rc, s = c_summary(lib, lam, 1)
        assert rc == 1 and _all_nan([s[f] for f in FIELDS if f != "lam"]), lam
        rc, h = c_history(lib, lam, tau_ok, 1)
        assert rc == 1 and all(_all_nan(v) for v in h.values()), lam
    for tau in ([NAN], [-1.0], [1.0, float("inf")], [0.5, -0.0 - 1e-300]):
        rc, h = c_history(lib, 1.0, np.array(tau), 1)
        assert rc == 1 and all(_all_nan(v) for v in h.values()), tau
    for tau in ([NAN], [-1.0], [1.0, float("inf")], [0.5, -0.0 - 1e-300]):
        rc, h = c_history(lib, 1.0, np.array(tau))
        assert rc == 1 and all(_all_nan(v) for v in h.values()), tau
        for order in (0, 1):
            rc, d, f = c_ham(lib, order, 1.0, np.array(tau))
            assert rc == 1 and _all_nan(d) and _all_nan(f)
    for lam in (NAN, -1.0, lc, np.nextafter(lc, 3), 3.0, 1001.0):
        for order in (0, 1):
            rc, d, f = c_ham(lib, order, lam, tau_ok)
            assert rc == 1 and _all_nan(d) and _all_nan(f), (order, lam)
        rc, s = c_summary(lib, lam, ham1=True)
        assert rc == 1 and _all_nan([s[f] for f in FIELDS if f != "lam"])
    for e in (NAN, 0.0, -0.1, 1.0 + 1e-15, 2.0, float("inf"), 1e-300):
        assert math.isnan(lib.zs_lam_for_e(e, 0)), e
    s = ctypes.POINTER(Summary)()
    assert lib.zs_summary(1.0, 0, s) == 1 and lib.zs_ham1_summary(1.0, s) == 1  # NULL out
    n = ctypes.POINTER(ctypes.c_double)()
    assert lib.zs_history(1.0, 0, 3, n, n, n, n, n) == 1  # NULL tau with n > 0
    assert lib.zs_history(1.0, 0, 0, n, n, n, n, n) == 0  # nothing to do


# --- sanitizers ------------------------------------------------------------------------------
DRIVER = r"""
#include <math.h>
#include <stdio.h>
#include "zener_sym.h"

int main(void)
{
    static const double lams[] = {0.0, 1e-9, 0.5, 1.0, 2.0, 3.5, 4.9, 5.0, 7.0, 10.0, 25.0,
                                  80.0, 300.0, 999.0, 1000.0};
    static const double bad[] = {-1.0, 1001.0, 1e308};
    double tau[700], d[700], v[700], f[700], I[700];
    zs_summary_t s;
    size_t i, j, n = 700;
    int rc = 0;
    for (j = 0; j < sizeof lams / sizeof lams[0]; j++) {
        rc |= zs_summary(lams[j], ZS_DELTA, &s);
        for (i = 0; i < n; i++)
            tau[i] = 1.1 * s.tau_d * (double)i / (double)(n - 1);
        rc |= zs_history(lams[j], ZS_DELTA, n, tau, d, v, f, I);
        rc |= zs_history(lams[j], ZS_DELTA, n, tau, NULL, NULL, f, NULL);
        printf("%.17g %.17g %.17g %.17g\n", s.e, s.tau_d, d[n / 3], I[n / 2]);
        printf("%.17g\n", zs_lam_for_e(s.e, ZS_DELTA));
        rc |= zs_summary(lams[j], ZS_FORCE, &s);
        for (i = 0; i < n; i++)
            tau[i] = 1.1 * s.tau_d * (double)(n - 1 - i) / (double)(n - 1);
        rc |= zs_history(lams[j], ZS_FORCE, n, tau, d, v, f, I);
        rc |= zs_history(lams[j], ZS_FORCE, n, tau, NULL, v, NULL, NULL);
        printf("%.17g %.17g %.17g %.17g %.17g\n", s.e, s.tau_d, d[n / 3], v[n / 2], f[n / 4]);
        if (lams[j] < ZS_LAM_CRIT) {
            rc |= zs_ham0_history(lams[j], n, tau, d, f);
            rc |= zs_ham1_history(lams[j], 60, tau, d, f);
            rc |= zs_ham1_summary(lams[j], &s);
            printf("%.17g %.17g\n", d[20], s.e);
        }
    }
    if (rc != 0)
        return 3;
    for (j = 0; j < sizeof bad / sizeof bad[0]; j++) {
        if (zs_summary(bad[j], ZS_DELTA, &s) != ZS_EDOM || !isnan(s.e))
            return 4;
        if (zs_history(bad[j], ZS_DELTA, n, tau, d, v, f, I) != ZS_EDOM || !isnan(d[0]))
            return 5;
        if (zs_ham1_history(bad[j], n, tau, d, f) != ZS_EDOM || !isnan(f[n - 1]))
            return 6;
        if (zs_history(bad[j], ZS_FORCE, n, tau, d, v, f, I) != ZS_EDOM || !isnan(v[0]))
            return 8;
    }
    if (zs_summary(1.0, ZS_FORCE + 1, &s) != ZS_EDOM || !isnan(zs_lam_for_e(2.0, ZS_DELTA)))
        return 7;
    return 0;
}
"""


def test_sanitized_driver(tmp_path, lib):
    """Every entry point under -fsanitize=address,undefined (any report aborts the run), and the
    values it prints equal the optimized library's."""
    (tmp_path / "driver.c").write_text(DRIVER)
    exe = tmp_path / "driver"
    _compile([CC, *STRICT, "-O1", "-g", "-fsanitize=address,undefined",
              "-fno-sanitize-recover=all", "-I", str(C_DIR), str(tmp_path / "driver.c"),
              str(C_DIR / "zener_sym.c"), "-o", str(exe), "-lm"], tmp_path)
    r = subprocess.run([str(exe)], capture_output=True, text=True,
                       env={"ASAN_OPTIONS": "detect_leaks=1", "PATH": "/usr/bin:/bin"})
    assert r.returncode == 0, f"sanitized driver failed ({r.returncode}):\n{r.stderr[-3000:]}"
    assert "runtime error" not in r.stderr and "AddressSanitizer" not in r.stderr
    first = [float(x) for x in r.stdout.split("\n")[0].split()]
    _, s = c_summary(lib, 0.0)
    assert first[:2] == pytest.approx([s["e"], s["tau_d"]], rel=1e-15)
    # the ZS_FORCE line of lambda = 0 (third line): the optimized library's summary and history
    third = [float(x) for x in r.stdout.split("\n")[2].split()]
    _, s = c_summary(lib, 0.0, 1)
    tau = 1.1 * s["tau_d"] * np.arange(699, -1, -1) / 699.0
    _, h = c_history(lib, 0.0, tau, 1)
    assert third == pytest.approx([s["e"], s["tau_d"], h["delta"][700 // 3],
                                   h["velocity"][350], h["force"][175]], rel=1e-15, abs=1e-300)


# --- the DEM example -------------------------------------------------------------------------
def test_dem_wall_example_converges_at_second_order(tmp_path):
    """examples/c/dem_wall.c: its velocity Verlet e and contact time against zs_summary's; the
    error of e falls about 4x when dt halves (the stepper's O(dt^2)), the contact time's stays
    within the same O(dt^2) bound."""
    exe = tmp_path / "dem_wall"
    _compile([CC, *STRICT, "-O2", "-I", str(C_DIR), str(ROOT / "examples" / "c" / "dem_wall.c"),
              str(C_DIR / "zener_sym.c"), "-o", str(exe), "-lm"], tmp_path)
    rows = {}
    for steps in (200, 400):
        r = subprocess.run([str(exe), str(steps)], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        vals = [float(x) for x in r.stdout.strip().splitlines()[-1].split()]
        rows[steps] = vals
        e, e_zs, t, t_zs = vals[1], vals[2], vals[4], vals[5]
        assert abs(e - e_zs) / e_zs < 10.0 / steps**2
        assert abs(t - t_zs) / t_zs < 10.0 / steps**2
    err = {n: abs(v[1] - v[2]) for n, v in rows.items()}
    assert 3.5 < err[200] / err[400] < 4.6, err
    # the grain reading (force never attractive, contact ends at its zero) against the
    # force-free end's summary: an independent check of ZS_FORCE
    r = subprocess.run([str(exe), "400", "force"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    v = [float(x) for x in r.stdout.strip().splitlines()[-1].split()]
    assert abs(v[1] - v[2]) / v[2] < 10.0 / 400**2 and abs(v[4] - v[5]) / v[5] < 10.0 / 400**2
    # the Python summary at the example's lambda (printed first) agrees with the C one it used
    r = subprocess.run([str(exe), "200"], capture_output=True, text=True)
    lam = float(r.stdout.split()[1])
    assert rows[200][2] == pytest.approx(float(PY["exact_summary"](lam).e[0]), rel=1e-5)


def test_bench_driver_runs(tmp_path):
    """The bench's timing driver builds against generated/c and reports its numbers (what it
    measures is read by ``zener-sym bench``, not asserted here)."""
    from zener_sym.bench import c_targets

    exe = c_targets.compile_driver(tmp_path)
    r = subprocess.run([str(exe), "3", "20", "5.0", "10", "1000.0", "3"], capture_output=True,
                       text=True, check=True)
    vals = [float(x) for x in r.stdout.split()]
    assert len(vals) == 4 and all(v > 0 for v in vals[:3])


# --- one table evaluator in C: a new table is a configuration ------------------------------------
#: A table the package does not ship: three fields (the runtime's any-count sum; the shipped
#: tables have 6 and 8) on one lambda piece of every kind of Chebyshev variable.
TOY_PIECES = (("lam", 0.0, 2.0), ("sqrt", 2.0, 3.0), ("sqrt_lam", 3.0, 5.0), ("log", 5.0, 400.0))


def _toy_fields(lam):
    lam = np.asarray(lam, dtype=float)
    s = np.sqrt(np.maximum(lam - 2.0, 0.0))
    return {"a": np.log1p(lam), "b": 1.0 / (1.0 + lam / 10.0),
            "c": np.where(lam < 2.0, lam**2, 4.0 + s**3)}


def test_a_new_table_is_a_configuration_in_c(tmp_path):
    """A table built from a configuration by the Python engine, emitted by the C emitter
    (``codegen.c.tables.summary_c``) and evaluated by the runtime's one evaluator ``zs__eval``
    compiled with the shipped tables: in order (a history's mode) the same doubles as Python's
    ``SummaryTable.values``; in a summary's mode (other dependency chains) within a few ulps of
    each series' scale; and
    both within the fit's accuracy of the closed forms the table was built from."""
    from zener_sym.codegen.c import build_source
    from zener_sym.codegen.c.tables import summary_c
    from zener_sym.numerics import cheb_table_build as engine
    from zener_sym.numerics.cheb_table import SummaryTable, TableSpec

    spec = TableSpec(pieces=TOY_PIECES, fields=("a", "b", "c"), nodes=(30, 30, 30, 40),
                     trim=1e-15, check_rtol=1e-12)
    built = engine.build_tables(spec, lambda p, lam: [
        {k: float(v) for k, v in _toy_fields(x).items()} for x in lam])
    text, init, deg = summary_c("zs__toy", {"TABLE_PIECES": spec.pieces,
                                            "SUMMARY": built["summary"]}, spec.fields)
    lam = np.concatenate([np.linspace(0.0, 400.0, 801), [2.0, 2.0 + 1e-12, 3.0, 5.0],
                          np.random.default_rng(7).uniform(0, 6, 200)])
    driver = (text + f"static const zs__sumtab zs__toy = {init};\n"
              "#include <stdio.h>\nint main(void)\n{\n    double lam, v[3], x;\n    int o;\n"
              "    while (scanf(\"%lf\", &lam) == 1)\n        for (o = 1; o >= 0; o--) {\n"
              "            zs__eval(&zs__toy, lam, zs__toy.pieces.n - 1, o, v, &x);\n"
              "            printf(\"%a %a %a\\n\", v[0], v[1], v[2]);\n        }\n"
              "    return 0;\n}\n")
    src = tmp_path / "toy.c"
    # the runtime's buffers sized for every table, this one too (what build_source does for
    # a table it emits)
    shipped = build_source()
    top = int(re.search(r"#define ZS__MAX_SUM (\d+)", shipped).group(1))
    assert deg > top  # the toy's log piece is longer than any shipped series: the sizing matters
    src.write_text(shipped.replace(f"#define ZS__MAX_SUM {top} ", f"#define ZS__MAX_SUM {deg} ")
                   + driver, encoding="utf-8")
    _compile([CC, *STRICT, "-Wno-unused-function", "-O2", f"-I{C_DIR}", str(src), "-o",
              str(tmp_path / "toy"), "-lm"], tmp_path)
    run = subprocess.run([str(tmp_path / "toy")], input="\n".join(repr(float(x)) for x in lam),
                         capture_output=True, text=True, check=True)
    got = np.array([[float.fromhex(w) for w in line.split()] for line in run.stdout.splitlines()])
    in_order, summary_mode = got[0::2], got[1::2]
    py, _, _, _ = SummaryTable(spec.pieces, spec.fields, built["summary"], "toy").values(lam)
    want = np.column_stack([py[k] for k in spec.fields])
    np.testing.assert_array_equal(in_order, want)
    # the summary's chains: a few ulps of each series' scale (its largest value)
    scale = np.abs(want).max(axis=0)
    assert np.all(np.abs(summary_mode - want) <= 4e-15 * scale), np.abs(summary_mode - want).max(
        axis=0) / scale
    exact = _toy_fields(lam)
    for j, k in enumerate(spec.fields):
        np.testing.assert_allclose(in_order[:, j], exact[k], rtol=1e-12,
                                   atol=1e-13 * np.abs(exact[k]).max())
