"""Error of the ham1 summary tables (``zener_sym.ham.table``) against the mpmath closed forms.

    python benchmarks/ham1_table_error.py            # 41 lambda, dps 30 (about two minutes)
    python benchmarks/ham1_table_error.py --n 10     # quicker

The grid lambda = lam_crit (i + 0.37) / (n + 1), i = 0..n, plus lam_cont +- 1e-5 and
lam_crit - 3e-5, is not aligned with the table's Chebyshev nodes. For each lambda the reference is
``zs.summary(lam, model="ham1", backend="mpmath", dps=dps)``; the error is relative per field.
The same is printed for the float64 path the table was built from
(``zener_sym.ham.spectral.summary_numpy``), so the two can be compared. These numbers back
``zener_sym.ham.table.SUMMARY_RTOL``.
"""
from __future__ import annotations

import argparse

import numpy as np

import zener_sym as zs
from zener_sym.ham.runtime_numpy import ham1 as h1
from zener_sym.generated import ham1_table
from zener_sym.ham import spectral

FIELDS = ("delta_m", "tau_dc", "tau_d", "e", "F_m", "impulse", "int_F2")
DERIVED = ("tau_dr", "eta", "xi")


def measure(n: int = 40, dps: int = 30) -> dict:
    lc = h1.LAM_CRIT
    lams = np.concatenate([lc * (np.arange(n + 1) + 0.37) / (n + 1),
                           [ham1_table.LAM_CONT - 1e-5, ham1_table.LAM_CONT + 1e-5, lc - 3e-5]])
    tab = zs.summary(lams, model="ham1")
    src = spectral.summary_numpy(lams)
    worst = {f: [0.0, 0.0, 0.0] for f in FIELDS + DERIVED}  # table error, its lambda, source error
    for i, x in enumerate(lams):
        r = zs.summary(float(x), model="ham1", backend="mpmath", dps=dps)
        for f in FIELDS + DERIVED:
            ref = float(getattr(r, f))
            err = abs(getattr(tab, f)[i] / ref - 1)
            if err > worst[f][0]:
                worst[f][:2] = err, float(x)
            if f in src:
                worst[f][2] = max(worst[f][2], abs(src[f][i] / ref - 1))
    return {"lams": lams.size, "worst": worst}


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n", type=int, default=40)
    p.add_argument("--dps", type=int, default=30)
    a = p.parse_args()
    out = measure(a.n, a.dps)
    print(f"{out['lams']} lambda in [0, lam_crit), mpmath dps {a.dps}")
    print(f"{'field':8s} {'table':>9s} {'at lambda':>10s} {'source':>9s}")
    for f, (e, x, s) in out["worst"].items():
        print(f"{f:8s} {e:9.1e} {x:10.5f} " + (f"{s:9.1e}" if f in FIELDS else f"{'':9s}"))


if __name__ == "__main__":
    main()
