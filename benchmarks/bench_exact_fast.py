"""Fast exact model (Chebyshev tables) vs a per-lambda scipy DOP853 loop, side by side in one run.

    python benchmarks/bench_exact_fast.py            # full: 2000 lambda (about a minute)
    python benchmarks/bench_exact_fast.py --n 400    # quicker
    python benchmarks/bench_exact_fast.py --plot wp.png   # also draw the work-precision chart

Prints (1) the summary speed ratio for n lambda in [0, 5] against ``exact.solve`` (DOP853 with the
end-of-compression event) at rtol 1e-10, (2) the history ratio for many lambda at once against the
scipy loop at rtol 1e-8 (both timed by ``zener_sym.bench.exact_fast_targets``, as ``zener-sym
bench`` times them), with the history errors of both against scipy at rtol 1e-13, (3) work-precision points (seconds per lambda, worst relative error of
every summary field against the mpmath reference ``exact_mp`` at dps 20) for the table and for
scipy at several tolerances. ``work_precision()`` returns those rows for the benchmark charts.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

import zener_sym as zs
from zener_sym.exact import solver as exact, mp as exact_mp
from zener_sym.bench import exact_fast_targets

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")


def _best(f, repeat=5):
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return best, out


def history_errors(m: int, k: int) -> dict:
    """Worst history error (delta over delta_m, impulse) of the tables and of the scipy loop at
    rtol 1e-8, against scipy at rtol 1e-13, on every (m // 10)-th of m lambda in [0, 5] and k tau
    up to 1.05 tau_d."""
    lams = np.linspace(0.0, 5.0, m)
    tau_d = zs.summary(lams, model="exact", backend="scipy", rtol=1e-10).tau_d
    tau = np.linspace(0.0, 1.0, k)[None, :] * 1.05 * tau_d[:, None]
    h = zs.history(lams[:, None], tau, model="exact")
    err_fast = err_loop = 0.0
    for j in range(0, m, max(1, m // 10)):
        ref = exact.solve(lams[j], rtol=1e-13)
        g = ref.history(tau[j])
        lo = exact.solve(lams[j], rtol=1e-8).history(tau[j])
        err_fast = max(err_fast, np.abs(h.delta[j] - g["delta"]).max() / ref.delta_m,
                       np.abs(h.impulse[j] - g["impulse"]).max())
        err_loop = max(err_loop, np.abs(lo["delta"] - g["delta"]).max() / ref.delta_m,
                       np.abs(lo["impulse"] - g["impulse"]).max())
    return {"err_fast": err_fast, "err_loop": err_loop}


def _worst(vals: dict, refs: list) -> float:
    worst = 0.0
    for f in FIELDS:
        ref = np.array([float(getattr(r, f)) for r in refs])
        v = np.asarray(vals[f], dtype=float)
        nz = ref != 0
        worst = max(worst, float(np.max(np.abs(v[nz] / ref[nz] - 1))),
                    float(np.max(np.abs(v[~nz]), initial=0.0)))
    return worst


def work_precision(n_ref: int = 12) -> list[dict]:
    """(method, seconds per lambda, worst relative error over all summary fields) rows.

    The reference is ``exact_mp.solve(lam, dps=20)`` at n_ref lambda in (0, 5] that are not
    table nodes.
    """
    lams = np.linspace(0.0, 5.0, n_ref + 1)[1:] - 0.0123
    refs = [exact_mp.solve(float(x), dps=20) for x in lams]
    rows = []
    t, s = _best(lambda: zs.summary(lams, model="exact"))
    big = np.linspace(0.0, 5.0, 2000)
    t_big, _ = _best(lambda: zs.summary(big, model="exact"))
    rows.append({"method": "exact table (2000 lambda per call)", "s_per_lam": t_big / big.size,
                 "err": _worst(s.as_dict(), refs)})
    rows.append({"method": f"exact table ({len(lams)} lambda per call)",
                 "s_per_lam": t / len(lams), "err": _worst(s.as_dict(), refs)})
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
        t, s = _best(lambda: zs.summary(lams, model="exact", backend="scipy", rtol=rtol), 1)
        rows.append({"method": f"scipy DOP853 rtol {rtol:g}", "s_per_lam": t / len(lams),
                     "err": _worst(s.as_dict(), refs)})
    return rows


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=2000, help="lambda values for the summary timing")
    p.add_argument("--m", type=int, default=200, help="lambda values for the history timing")
    p.add_argument("--k", type=int, default=200, help="tau values per lambda for the history")
    p.add_argument("--plot", help="write the work-precision chart to this PNG")
    a = p.parse_args(argv)
    s = exact_fast_targets.summary_target(a.n)
    print(f"summary, {a.n} lambda in [0, 5]: table {s['fast_s'] * 1e3:.2f} ms, scipy DOP853 "
          f"loop rtol 1e-10 {s['slow_s']:.2f} s, ratio {s['ratio']:.0f}x")
    h = exact_fast_targets.history_target(a.m, a.k)
    e = history_errors(a.m, a.k)
    print(f"history, {a.m} lambda x {a.k} tau: table {h['fast_s'] * 1e3:.1f} ms "
          f"(error {e['err_fast']:.1e}), scipy loop rtol 1e-8 {h['slow_s']:.2f} s "
          f"(error {e['err_loop']:.1e}), ratio {h['ratio']:.0f}x")
    rows = work_precision()
    print("\nwork-precision (summary, worst relative error of all fields vs exact_mp dps 20):")
    print("| method | s per lambda | worst rel. error |\n|---|---|---|")
    for r in rows:
        print(f"| {r['method']} | {r['s_per_lam']:.2e} | {r['err']:.1e} |")
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(5, 4))
        for r in rows:
            ax.loglog(r["err"], r["s_per_lam"], "o" if "table" in r["method"] else "s",
                      label=r["method"])
        ax.set_xlabel("worst relative error of the summary fields")
        ax.set_ylabel("seconds per lambda")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
        print(f"wrote {a.plot}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
