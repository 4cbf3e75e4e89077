"""Speed of the emitted C kernels (issue 25), side by side with the numpy path in one run.

A timing driver (C, compiled here with the generated ``generated/c/zener_sym.c``) times the
exact history on a grid of m lambda x k tau and the exact summary per lambda, each the median of
repeated runs measured inside the driver (clock_gettime of the process's CPU time: no process
start-up in the time). The numpy side is the package's own call on the same grid
(``zs.history(..., model="exact")``, ``zs.summary``), timed in alternation with the driver's
runs. Both sides count CPU time of their process (``time.process_time`` in Python): on a shared
machine wall time mostly measures the other processes. Both compute every history field (delta,
velocity, force, impulse).

The driver is built twice (``BUILDS``), and both builds give the same doubles (ISO C: no
contraction into fused multiply-adds; ``tests/test_c_kernels.py`` checks it):

* ``-O3 -march=native``: the instruction set of the machine it runs on, as a simulation code
  builds its production binaries, and as numpy's own loops (exp, log, BLAS) dispatch at run
  time to this processor's vector units. The issue's targets are judged on it: C history per
  point at least 4x faster than numpy's; C summary under 100 ns per lambda.
* ``-O2`` with no ``-march``: the portable baseline (on x86-64, two doubles a vector), shown
  beside it and not judged.

Without a C compiler the rows say so instead of a number.
"""
from __future__ import annotations

import pathlib
import shutil
import statistics
import subprocess
import tempfile
import time
from typing import Any

import numpy as np

from ..codegen import generated_dir

DRIVER = r"""
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "zener_sym.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* argv: m k lam_max_history n_summary lam_max_summary repeats */
int main(int argc, char **argv)
{
    int m = atoi(argv[1]), k = atoi(argv[2]), ns = atoi(argv[4]), reps = atoi(argv[6]);
    double lh = atof(argv[3]), ls = atof(argv[5]), sink = 0.0, th[64], ts[64], te;
    double *tau = malloc(sizeof(double) * (size_t)k * (size_t)m);
    double *force = malloc(sizeof(double) * (size_t)k);
    double *delta = malloc(sizeof(double) * (size_t)k), *vel = malloc(sizeof(double) * (size_t)k);
    double *imp = malloc(sizeof(double) * (size_t)k);
    int r, i, j;
    zs_summary_t s;
    /* the grid before the clock, as the numpy side's: m lambda x k tau up to 1.05 tau_d */
    for (i = 0; i < m; i++) {
        zs_summary(m > 1 ? lh * i / (m - 1) : 0.0, ZS_DELTA, &s);
        for (j = 0; j < k; j++)
            tau[(size_t)i * (size_t)k + (size_t)j] = 1.05 * s.tau_d * j / (k - 1);
    }
    for (r = 0; r < reps && r < 64; r++) {
        double t0 = now();
        for (i = 0; i < m; i++) {
            double lam = m > 1 ? lh * i / (m - 1) : 0.0;
            zs_history(lam, ZS_DELTA, (size_t)k, tau + (size_t)i * (size_t)k, delta, vel, force,
                       imp);
            sink += force[k / 2];
        }
        th[r] = now() - t0;
        t0 = now();
        for (i = 0; i < ns; i++) {
            zs_summary(ls * i / (ns - 1), ZS_DELTA, &s);
            sink += s.e;
        }
        ts[r] = now() - t0;
    }
    {   /* the machine's speed: one libm exp per call, as a yardstick for the numbers above */
        double t0 = now(), x = 0.0;
        for (i = 0; i < 1000000; i++)
            x += exp(-1e-6 * i);
        te = (now() - t0) / 1e6;
        sink += x;
    }
    qsort(th, (size_t)reps, sizeof th[0], cmp);
    qsort(ts, (size_t)reps, sizeof ts[0], cmp);
    printf("%.9e %.9e %.9e %.3f\n", th[reps / 2], ts[reps / 2], te, sink);
    free(tau);
    free(force);
    free(delta);
    free(vel);
    free(imp);
    return 0;
}
"""


#: (name, flags): the driver's builds, the first judged against the targets (module docstring)
BUILDS: list[tuple[str, list[str]]] = [
    ("native", ["-O3", "-march=native"]),
    ("portable", ["-O2"]),
]


def compile_driver(folder: pathlib.Path, flags: list[str] | None = None) -> pathlib.Path | None:
    """The timing driver built in ``folder`` with ``flags`` (default -O2; None without a C
    compiler)."""
    cc = shutil.which("gcc") or shutil.which("cc")
    if cc is None:
        return None
    flags = ["-O2"] if flags is None else flags
    src = folder / "bench_c.c"
    src.write_text(DRIVER)
    exe = folder / ("bench_c_" + "_".join(f.strip("-=").replace("=", "_") for f in flags))
    c_dir = generated_dir() / "c"
    subprocess.run([cc, "-std=c99", *flags, "-I", str(c_dir), str(src),
                    str(c_dir / "zener_sym.c"), "-o", str(exe), "-lm"], check=True,
                   capture_output=True)
    return exe


def run(quick: bool = False, m: int = 200, k: int = 500,
        n_summary: int = 2000) -> list[dict[str, Any]]:
    """The C targets, as rows of the speed-target table: per build (``BUILDS``) the history
    against numpy's and the summary against 100 ns; the portable build's rows carry
    ``required`` None (shown, not judged)."""
    import zener_sym as zs

    rounds = 3 if quick else 7
    with tempfile.TemporaryDirectory() as tmp:
        exes: dict[str, pathlib.Path | None | str] = {}
        for name, flags in BUILDS:
            try:
                exes[name] = compile_driver(pathlib.Path(tmp), flags)
            except subprocess.CalledProcessError as err:  # e.g. a compiler without -march=native
                exes[name] = f"{' '.join(flags)} did not build: {err.stderr.strip()[:120]}"
        if all(v is None for v in exes.values()):
            return [{"target": "C kernels (generated/c)", "grid": "no C compiler found",
                     "fast_s": float("nan"), "slow_s": float("nan"), "ratio": float("nan"),
                     "required": 4.0, "met": False}]
        lams = np.linspace(0.0, 5.0, m)
        tau = zs.summary(lams, model="exact").tau_d[:, None] * 1.05 * np.linspace(0.0, 1.0, k)
        sl = np.linspace(0.0, 1000.0, n_summary)
        args = [str(m), str(k), "5.0", str(n_summary), "1000.0", "5"]
        t_np_hist: list[float] = []
        t_np_sum: list[float] = []
        t_c: dict[str, tuple[list[float], list[float], list[float]]] = {
            name: ([], [], []) for name, exe in exes.items() if isinstance(exe, pathlib.Path)}
        for _ in range(rounds):  # alternation: numpy, then each build of the driver, each round
            t0 = time.process_time()
            zs.history(lams[:, None], tau, model="exact").force
            t_np_hist.append(time.process_time() - t0)
            t0 = time.process_time()
            zs.summary(sl, model="exact")
            t_np_sum.append(time.process_time() - t0)
            for name, (th, ts, te) in t_c.items():
                out = subprocess.run([str(exes[name]), *args], check=True, capture_output=True,
                                     text=True).stdout.split()
                th.append(float(out[0]))
                ts.append(float(out[1]))
                te.append(float(out[2]))
    th_np = statistics.median(t_np_hist)
    ts_np = statistics.median(t_np_sum) / n_summary
    n_pts = m * k
    rows: list[dict[str, Any]] = []
    for name, flags in BUILDS:
        judged = name == BUILDS[0][0]
        label = f"{' '.join(flags)}" + ("" if judged else ", portable baseline: shown, not judged")
        exe = exes[name]
        if not isinstance(exe, pathlib.Path):
            why = exe if isinstance(exe, str) else "no C compiler found"
            rows.append({"target": f"C exact history ({label})", "grid": why,
                         "fast_s": float("nan"), "slow_s": float("nan"), "ratio": float("nan"),
                         "required": 4.0 if judged else None, "met": False if judged else None})
            continue
        th, ts, te = t_c[name]
        th_c = statistics.median(th)
        ts_c = statistics.median(ts) / n_summary
        yard = f"; libm exp {statistics.median(te) * 1e9:.1f} ns a call on this machine"
        rows += [
            {"target": f"C exact history per point (zs_history, {label}) vs numpy's "
                       "(zs.history)",
             "grid": f"{m} lambda in [0, 5] x {k} tau; C {th_c / n_pts * 1e9:.1f} ns/point, "
                     f"numpy {th_np / n_pts * 1e9:.1f} ns/point" + yard,
             "fast_s": th_c, "slow_s": th_np, "ratio": th_np / th_c,
             "required": 4.0 if judged else None},
            {"target": f"C exact summary per lambda (zs_summary, {label}): 100 ns / time",
             "grid": f"{n_summary} lambda in [0, 1000]; C {ts_c * 1e9:.1f} ns, numpy "
                     f"{ts_np * 1e9:.1f} ns per lambda (vectorised call)" + yard,
             "fast_s": ts_c, "slow_s": 100e-9, "ratio": 100e-9 / ts_c,
             "required": 1.0 if judged else None},
        ]
    for r in rows:
        if "met" not in r:
            r["met"] = None if r["required"] is None else r["ratio"] >= r["required"]
    return rows
