"""``zs.summary`` per lambda of several source trees of zener-sym, side by side in one process
(issue 36: the exact summary against 8251530, before the table engine, and c2ea95c).

    git worktree add --detach ../old-8251530 8251530
    git worktree add --detach ../old-c2ea95c c2ea95c
    python benchmarks/summary_versions.py 8251530=../old-8251530/src c2ea95c=../old-c2ea95c/src \\
        now=src

Each tree is imported in turn (``sys.modules`` cleared between), its tables loaded; then every
(number of lambdas, contact end, tree) is timed interleaved, best of ``--repeats``, so a shared
machine's load falls on every tree alike. It prints ns per lambda, each tree's ratio to the
first, whether each tree gives the first's doubles, and the force-free end's time over the
plate end's per tree.
"""
from __future__ import annotations

import argparse
import importlib
import sys
import time

import numpy as np

FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2", "xi")


def _load(src: str):
    for k in [k for k in sys.modules if k == "zener_sym" or k.startswith("zener_sym.")]:
        del sys.modules[k]
    sys.path.insert(0, src)
    try:
        zs = importlib.import_module("zener_sym")
    finally:
        sys.path.remove(src)
    lam = np.linspace(0.0, 1000.0, 50)
    zs.summary(lam), zs.summary(lam, contact_end="force")  # the tables load on first use
    return zs


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trees", nargs="+", help="LABEL=SRC_DIR (the first is the reference)")
    ap.add_argument("--sizes", default="100,1000,2000,10000,100000")
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()
    trees = dict(a.split("=", 1) for a in args.trees)
    mods = {label: _load(src) for label, src in trees.items()}
    ref = next(iter(mods))
    rng = np.random.default_rng(0)
    best: dict[tuple[int, str, str], float] = {}
    for n in (int(s) for s in args.sizes.split(",")):
        lam = rng.uniform(0.0, 1000.0, n)
        number = max(1, 200_000 // n)
        for end in ("delta", "force"):
            out = {}
            for _ in range(args.repeats):
                for label, zs in mods.items():
                    t0 = time.perf_counter()
                    for _ in range(number):
                        out[label] = zs.summary(lam, contact_end=end)
                    ns = (time.perf_counter() - t0) / number / n * 1e9
                    best[n, end, label] = min(best.get((n, end, label), np.inf), ns)
            same = {label: all(np.array_equal(getattr(out[label], f), getattr(out[ref], f))
                               for f in FIELDS) for label in mods}
            print(f"{n:7d} {end:5s} " + "  ".join(
                f"{label} {best[n, end, label]:6.0f} ns ({best[n, end, label] / best[n, end, ref]:.2f})"
                for label in mods) + f"  same doubles as {ref}: "
                + ", ".join(label for label, s in same.items() if s), flush=True)
            if end == "force":
                print(f"{n:7d} force/delta " + "  ".join(
                    f"{label} {best[n, 'force', label] / best[n, 'delta', label]:.2f}"
                    for label in mods), flush=True)


if __name__ == "__main__":
    main()
