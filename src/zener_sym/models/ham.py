"""The homotopy-analysis models ham0 (Eq. 35) and ham1 (Eq. 42) on the generated kernels.

Both take ``backend="numpy"`` (default, float64, vectorised) or ``backend="mpmath"`` with ``dps``
(closed forms in 2F1 and Gamma at any precision; a Python loop over points, slow). Valid for
0 <= lambda < lam_crit = 2.44243892998... where omega0 is real (Eq. 81).

Continuation (first order): past pi/omega0 the zeroth-order compression delta0 is negative, so its
contact force and sqrt(delta0) are zero; the square-root terms of the forcing (36) vanish and the
integrals C11, C12 keep their values at pi/omega0, while the elementary part continues. The
first-order contact ends at the first zero of delta0 + delta1 after its maximum (root finding),
after which delta and the force are 0 and the impulse keeps its final value. ``xi`` is
2 I - I^2 (Eq. 69) with the model's impulse.
"""
from __future__ import annotations

import mpmath
import numpy as np

from ..generated import ham0_mpmath, ham0_numpy, ham1_mpmath, ham1_numpy
from ..ham_numerics import contact_integral_mp
from .base import Model, register

LAM_CRIT = ham1_numpy.LAM_CRIT


def _backend(options):
    backend = options.get("backend", "numpy")
    if backend not in ("numpy", "mpmath"):
        raise ValueError(f"unknown backend {backend!r}; allowed: 'numpy', 'mpmath'")
    dps = options.get("dps")
    if dps is not None and backend != "mpmath":
        raise ValueError("option 'dps' goes with backend='mpmath'")
    if dps is not None and (not isinstance(dps, (int, np.integer)) or dps < 15):
        raise ValueError(f"dps must be an integer >= 15, got {dps!r}")
    return backend, (30 if dps is None else int(dps))


_SUMMARY = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse", "int_F2",
            "xi")


class _HamModel(Model):
    summary_fields = _SUMMARY
    history_fields = ("delta", "velocity", "force", "impulse")
    lam_bound = LAM_CRIT
    bound_reason = ("lam_crit = 2.44243892998...: omega0 = sqrt(4k - k^2 lambda^2)/2 is real only "
                    "below it, Eq. (81)")
    options = ("backend", "dps")

    @staticmethod
    def _finish(d):
        out = {f: np.asarray(d[f], dtype=float) for f in ("delta_m", "tau_dc", "tau_d", "e", "F_m",
                                                           "impulse", "int_F2")}
        out["tau_dr"] = out["tau_d"] - out["tau_dc"]
        out["eta"] = out["tau_dr"] / out["tau_dc"]
        out["xi"] = 2.0 * out["impulse"] - out["impulse"] ** 2
        return out


class Ham0(_HamModel):
    name = "ham0"
    description = "zeroth-order HAM solution, Eq. (35): damped sine, closed forms (54)-(61), (79)"

    def _summary(self, lam, **options):
        backend, dps = _backend(options)
        if backend == "numpy":
            return self._finish(ham0_numpy.summary(lam))
        rows = [ham0_mpmath.summary(float(x), dps) for x in lam]
        return self._finish({f: [float(r[f]) for r in rows] for f in rows[0]})

    def _history(self, lam, tau, **options):
        backend, dps = _backend(options)
        if backend == "numpy":
            k, beta, omega0 = ham0_numpy.params(lam)
            on = omega0 * tau <= np.pi
            d = np.where(on, np.maximum(ham0_numpy.delta(tau, lam), 0.0), 0.0)
            imp = ham0_numpy.impulse(tau, lam)
            force = ham0_numpy.force(tau, lam)
        else:
            d, imp, force = (np.empty(tau.shape) for _ in range(3))
            for i in np.ndindex(tau.shape):
                t, x = float(tau[i]), float(lam[i])
                with mpmath.workdps(dps):
                    k, beta, omega0 = ham0_mpmath.params(x)
                    dd = ham0_mpmath.delta(t, x)
                    d[i] = float(dd) if (omega0 * t <= mpmath.pi and dd > 0) else 0.0
                    imp[i] = float(ham0_mpmath.impulse(t, x))
                    force[i] = float(ham0_mpmath.force(t, x))
        return {"delta": d, "force": force, "impulse": imp, "velocity": 1.0 - imp}


class Ham1(_HamModel):
    name = "ham1"
    description = ("first-order HAM solution, Eq. (42): delta0 + delta1, contact end by root "
                   "finding, impulse by quadrature of the force")

    def _summary(self, lam, **options):
        backend, dps = _backend(options)
        if backend == "numpy":
            return self._finish(ham1_numpy.summary(lam))
        rows = []
        for x in lam:
            with mpmath.workdps(dps):
                tdc = ham1_mpmath.compression_end(float(x))
                td = ham1_mpmath.contact_end(float(x))
                dm = ham1_mpmath.delta(tdc, float(x))
                imp = ham1_mpmath.impulse(td, float(x), tau_d=td)
                k, beta, omega0 = ham1_mpmath.params(float(x))
                tpi = mpmath.pi / omega0
                f2 = lambda t: ham1_mpmath.force(t, float(x)) ** 2  # noqa: E731
                J = contact_integral_mp(f2, 0, min(td, tpi)) + contact_integral_mp(f2, tpi, max(td, tpi))
                rows.append(dict(delta_m=dm, tau_dc=tdc, tau_d=td, e=-ham1_mpmath.delta_dot(td, float(x)),
                                 F_m=dm ** 1.5, impulse=imp, int_F2=J))
        return self._finish({f: [float(r[f]) for r in rows] for f in rows[0]})

    def _history(self, lam, tau, **options):
        backend, dps = _backend(options)
        u, inv = np.unique(lam, return_inverse=True)
        td_u = ham1_numpy.contact_end(u)
        if backend == "numpy":
            td = td_u[inv].reshape(lam.shape)
            on = tau < td
            d = np.where(on, np.maximum(ham1_numpy.delta(tau, lam), 0.0), 0.0)
            imp = ham1_numpy.impulse(tau, lam, tau_d=td)
            return {"delta": d, "force": d**1.5, "impulse": imp, "velocity": 1.0 - imp}
        d, imp = np.empty(tau.shape), np.empty(tau.shape)
        with mpmath.workdps(dps):
            td_mp = {float(x): ham1_mpmath.contact_end(float(x), guess=float(t))
                     for x, t in zip(u, td_u)}
            for i in np.ndindex(tau.shape):
                t, x = float(tau[i]), float(lam[i])
                tdx = td_mp[x]
                dd = ham1_mpmath.delta(t, x) if t < tdx else mpmath.mpf(0)
                d[i] = float(max(dd, 0))
                imp[i] = float(ham1_mpmath.impulse(t, x, tau_d=tdx))
        return {"delta": d, "force": d**1.5, "impulse": imp, "velocity": 1.0 - imp}


register(Ham0())
register(Ham1())
