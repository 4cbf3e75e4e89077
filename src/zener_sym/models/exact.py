"""The exact model: direct integration of Eq. (10) (scipy), or at high precision (mpmath)."""
from __future__ import annotations

import numpy as np

from .. import exact as _exact
from .base import Model, register


class ExactModel(Model):
    name = "exact"
    description = "direct integration of Zener's equation (10) to the end of contact"
    summary_fields = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m",
                      "impulse", "int_F2", "xi")
    history_fields = ("delta", "velocity", "force", "impulse")
    lam_bound = np.nextafter(_exact.LAMBDA_MAX, np.inf)
    bound_reason = "the range over which the integrator is tested"
    options = ("rtol", "method", "backend", "dps")

    def _solutions(self, lam_values, **options):
        backend = options.pop("backend", "scipy")
        if backend == "scipy":
            if "dps" in options:
                raise ValueError("option 'dps' goes with backend='mpmath'")
            return {float(x): _exact.solve(x, **options) for x in np.unique(lam_values)}
        if backend == "mpmath":
            from .. import exact_mp

            bad = set(options) - {"dps"}
            if bad:
                raise ValueError(f"option {sorted(bad)[0]!r} does not go with backend='mpmath'")
            return {float(x): exact_mp.solve(x, **options) for x in np.unique(lam_values)}
        raise ValueError(f"unknown backend {backend!r} for model 'exact'; allowed: scipy, mpmath")

    def _summary(self, lam, **options):
        sols = self._solutions(lam, **options)
        out = {f: np.empty(lam.shape) for f in self.summary_fields}
        for i, x in np.ndenumerate(lam):
            s = sols[float(x)]
            for f in self.summary_fields:
                out[f][i] = float(getattr(s, f))
        return out

    def _history(self, lam, tau, **options):
        sols = self._solutions(lam, **options)
        out = {f: np.empty(tau.shape) for f in self.history_fields}
        for x, s in sols.items():
            mask = lam == x
            h = s.history(tau[mask])
            for f in self.history_fields:
                out[f][mask] = np.asarray(h[f], dtype=float)
        return out


register(ExactModel())
