"""Record the mpmath Taylor-series solution of Eq. (10) (plate end, zener_sym.exact.mp) at the
lambdas where computing it takes minutes, so that the tests compare the scipy path and the
tables against it without re-running it (at lambda = 1000 one solve takes 3-7 minutes on the
2-core CI machine, more than the rest of its test file together).

The reference is the package's second method, independent of what the tests check (the scipy
DOP853 path of exact/solver.py and the Chebyshev tables of generated/exact_table.py): Taylor
steps in mpmath arithmetic at ``dps`` digits, tau_dc by Newton's method on the Taylor polynomial
of delta', xi written as 1 - w_end^2 from the state w at 40 digits (not the energy balance the
scipy path uses). Each summary field is stored as a decimal string with 25 significant digits;
the history at the listed tau as floats (the mpmath path's own double evaluation).

Run from the repository root (minutes; prints the JSON):

    python tools/exact_mp_reference.py > tests/data/exact_mp_reference.json
"""
import json
import sys

import mpmath
import numpy as np

from zener_sym.exact import mp as exact_mp

#: lambda -> dps (digits of the Taylor steps)
LAMBDAS = {"1e-12": 30, "1e-06": 30, "0.001": 30, "0.7": 30, "30.0": 30, "100.0": 30, "1000.0": 20}
FIELDS = ("delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2")


def history_grid(tau_dc, tau_d):
    """tau across the compression and the recovery, past the end of contact (the test's grid)."""
    return np.concatenate([np.linspace(0.0, 3 * tau_dc, 40), np.linspace(0.0, 1.02 * tau_d, 160)[1:]])


def record(lam, dps):
    r = exact_mp.solve(float(lam), dps=dps)
    row = {"dps": dps}
    with mpmath.workdps(dps + 10):  # derived fields (tau_dr, eta, F_m) at the solve's digits
        for f in FIELDS:
            row[f] = mpmath.nstr(getattr(r, f), 25)
    with mpmath.workdps(40):
        row["xi_from_w_end"] = mpmath.nstr(1 - r.w_end ** 2, 25)
    tau = history_grid(float(r.tau_dc), float(r.tau_d))
    h = r.history(tau)
    row["history"] = {k: [float(x) for x in np.asarray(h[k])]
                      for k in ("tau", "delta", "impulse", "velocity", "force")}
    return row


def main():
    rows = {}
    for lam, dps in LAMBDAS.items():
        print(f"lambda = {lam} ...", file=sys.stderr, flush=True)
        rows[lam] = record(lam, dps)
    print(json.dumps({
        "what": "mpmath Taylor-series solution of Eq. (10), plate end (contact ends at delta = 0)",
        "made_by": "python tools/exact_mp_reference.py (zener_sym.exact.mp.solve; "
                   f"mpmath {mpmath.__version__})",
        "lambdas": rows,
    }, indent=1))


if __name__ == "__main__":
    main()
