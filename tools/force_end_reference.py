"""Record the coefficient of restitution of the force-free end of contact (the viscoelastic-grain
reading of Eq. 10) at a few lambda, by an integration written here from scratch, independent of
zener_sym (it imports nothing of the package).

Eq. (10) as a first-order system: delta' = w - lambda delta^(3/2), w' = -delta^(3/2) (w = 1 - the
impulse), delta(0) = 0, w(0) = 1. The grains' contact force is delta^(3/2) + lambda (delta^(3/2))'
= sqrt(delta) (delta + (3/2) lambda delta'); it ends (after the maximum compression) at the first
zero of g = delta + (3/2) lambda delta', and e = -delta' there. The start is singular (delta^(3/2)
has unbounded derivatives at tau = 0), so the integration starts at tau0 = 1e-12 from
delta = tau0, w = 1 (the neglected terms are O(tau0^(5/2))). scipy's DOP853 with an event, at
two tolerances: the digits recorded are those on which both agree.

Run from the repository root:

    python tools/force_end_reference.py > tests/data/force_end_restitution.json
"""
import json

import numpy as np
import scipy
from scipy.integrate import solve_ivp

LAMBDAS = (0.5, 1.0, 2.0)
TAU0 = 1e-12


def restitution(lam, rtol):
    def rhs(t, y):
        d = max(y[0], 0.0)
        f = d * np.sqrt(d)
        return [y[1] - lam * f, -f]

    def separation(t, y):  # g = delta + (3/2) lambda delta'
        d = max(y[0], 0.0)
        return y[0] + 1.5 * lam * (y[1] - lam * d * np.sqrt(d))

    def compressing(t, y):  # delta' = 0: the maximum compression
        d = max(y[0], 0.0)
        return y[1] - lam * d * np.sqrt(d)

    compressing.terminal, compressing.direction = True, -1
    a = solve_ivp(rhs, (TAU0, 50.0), [TAU0, 1.0], method="DOP853", rtol=rtol, atol=rtol * 1e-3,
                  events=compressing)
    separation.terminal, separation.direction = True, -1
    b = solve_ivp(rhs, (a.t[-1], 200.0), a.y[:, -1], method="DOP853", rtol=rtol,
                  atol=rtol * 1e-3, events=separation)
    assert b.status == 1, f"no force-free end found at lambda = {lam}"
    d, w = b.y_events[0][0]
    return -(w - lam * max(d, 0.0) ** 1.5)


def main():
    rows = {}
    for lam in LAMBDAS:
        fine, coarse = restitution(lam, 1e-13), restitution(lam, 1e-10)
        rows[repr(lam)] = {"e": float(f"{fine:.10g}"), "agreement": abs(fine - coarse)}
    print(json.dumps({
        "what": "e of the force-free end of contact (grain reading of Eq. 10)",
        "made_by": "python tools/force_end_reference.py (scipy DOP853, rtol 1e-13 and 1e-10, "
                   f"start at tau0 = {TAU0:g}; imports nothing of zener_sym)",
        "scipy": scipy.__version__,
        "values": rows}, indent=1, sort_keys=True))


if __name__ == "__main__":
    main()
