"""Speed of the emitted C kernels (issue 25), side by side with the numpy path in one run.

A timing driver (C, compiled here with the generated ``generated/c/zener_sym.c`` at -O2) times
the exact history on a grid of m lambda x k tau and the exact summary per lambda, each the
median of repeated runs measured inside the driver (clock_gettime of the process's CPU time: no
process start-up in the time). The numpy side is the package's own call on the same grid (``zs.history(..., model=
"exact")``, ``zs.summary``), timed in alternation with the driver's runs. Both sides count CPU
time of their process (``time.process_time`` in Python): on a shared machine wall time
mostly measures the other processes. Both compute every history field (delta, velocity, force,
impulse). Targets: C history per point at least 4x faster than numpy's; C summary under 100 ns
per lambda. Without a C compiler the rows say so instead of a number.
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


def compile_driver(folder: pathlib.Path) -> pathlib.Path | None:
    """The timing driver built in ``folder`` (None without a C compiler)."""
    cc = shutil.which("gcc") or shutil.which("cc")
    if cc is None:
        return None
    src = folder / "bench_c.c"
    src.write_text(DRIVER)
    exe = folder / "bench_c"
    c_dir = generated_dir() / "c"
    subprocess.run([cc, "-std=c99", "-O2", "-I", str(c_dir), str(src), str(c_dir / "zener_sym.c"),
                    "-o", str(exe), "-lm"], check=True, capture_output=True)
    return exe


def run(quick: bool = False, m: int = 200, k: int = 500,
        n_summary: int = 2000) -> list[dict[str, Any]]:
    """The two C targets, as rows of the speed-target table."""
    import zener_sym as zs

    rounds = 3 if quick else 7
    with tempfile.TemporaryDirectory() as tmp:
        exe = compile_driver(pathlib.Path(tmp))
        if exe is None:
            return [{"target": "C kernels (generated/c)", "grid": "no C compiler found",
                     "fast_s": float("nan"), "slow_s": float("nan"), "ratio": float("nan"),
                     "required": 4.0, "met": False}]
        lams = np.linspace(0.0, 5.0, m)
        tau = zs.summary(lams, model="exact").tau_d[:, None] * 1.05 * np.linspace(0.0, 1.0, k)
        sl = np.linspace(0.0, 1000.0, n_summary)
        args = [str(exe), str(m), str(k), "5.0", str(n_summary), "1000.0", "5"]
        t_c_hist, t_c_sum, t_np_hist, t_np_sum, t_exp = [], [], [], [], []
        for _ in range(rounds):  # alternation: numpy, then the driver, each round
            t0 = time.process_time()
            zs.history(lams[:, None], tau, model="exact").force
            t_np_hist.append(time.process_time() - t0)
            t0 = time.process_time()
            zs.summary(sl, model="exact")
            t_np_sum.append(time.process_time() - t0)
            out = subprocess.run(args, check=True, capture_output=True, text=True).stdout.split()
            t_c_hist.append(float(out[0]))
            t_c_sum.append(float(out[1]))
            t_exp.append(float(out[2]))
    th_c, th_np = statistics.median(t_c_hist), statistics.median(t_np_hist)
    ts_c = statistics.median(t_c_sum) / n_summary
    ts_np = statistics.median(t_np_sum) / n_summary
    n_pts = m * k
    yard = f"; libm exp {statistics.median(t_exp) * 1e9:.1f} ns a call on this machine"
    rows: list[dict[str, Any]] = [
        {"target": "C exact history per point (zs_history, force) vs numpy's (zs.history)",
         "grid": f"{m} lambda in [0, 5] x {k} tau; C {th_c / n_pts * 1e9:.1f} ns/point, "
                 f"numpy {th_np / n_pts * 1e9:.1f} ns/point" + yard,
         "fast_s": th_c, "slow_s": th_np, "ratio": th_np / th_c, "required": 4.0},
        {"target": "C exact summary per lambda (zs_summary): 100 ns / time",
         "grid": f"{n_summary} lambda in [0, 1000]; C {ts_c * 1e9:.1f} ns, numpy "
                 f"{ts_np * 1e9:.1f} ns per lambda (vectorised call)" + yard,
         "fast_s": ts_c, "slow_s": 100e-9, "ratio": 100e-9 / ts_c, "required": 1.0},
    ]
    for r in rows:
        r["met"] = r["ratio"] >= r["required"]
    return rows
