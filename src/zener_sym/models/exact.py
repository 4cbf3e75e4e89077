"""The exact model: Chebyshev tables (fast, default in range), direct integration (scipy) or
high precision (mpmath).

``backend``:

``"auto"`` (default)
    summaries and histories for every lambda the model accepts, [0, 1000]
    (``zener_sym.exact.table.LAM_MIN``, ``LAM_MAX``, ``HISTORY_LAM_MAX``), are evaluated from the
    tables (error bounds ``zener_sym.exact.table.SUMMARY_RTOL``, ``HISTORY_ATOL``). Giving
    ``rtol`` or ``method`` (integrator options) integrates all.
``"table"``
    tables only; lambda outside their range is a ValueError (never extrapolated).
``"scipy"``
    direct integration for every lambda (``rtol`` in [2.2e-14, 1), ``method`` one of
    ``zener_sym.exact.solver.METHODS``, as in ``exact.solve``).
``"mpmath"``
    high-precision integration (``dps``, an integer in [15, 100]).

``contact_end``: ``"delta"`` (default, the plate: contact ends at delta = 0) or ``"force"`` (the
viscoelastic-grain reading of Eq. (10): contact ends where delta^{3/2} + lambda (delta^{3/2})'
vanishes; the force, impulse, F_m and int_F2 are then those of the grain contact, see
:mod:`zener_sym.exact.force_end`). ``"force"`` has its own tables
(:mod:`zener_sym.exact.force_table`, same range and error bounds), used as the plate's.

Every option value is validated before any work (``exact.solver.check_options``,
``exact.mp.check_dps``): a bad one is a ValueError naming the allowed values.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any, Protocol

import numpy as np
import numpy.typing as npt

from ..exact import force_end as _force
from ..exact import force_table as _force_fast
from ..exact import mp as _exact_mp
from ..exact import solver as _exact
from ..exact import table as _fast
from ..typing import FloatArray
from .base import FieldValues, Model, register

BACKENDS = ("auto", "table", "scipy", "mpmath")


class _Tables(Protocol):
    """What the model takes of a table module: ``exact.table`` (the plate) or
    ``exact.force_table`` (the force-free end)."""

    def summary(self, lam: FloatArray) -> Mapping[str, Any]: ...

    def history(self, lam: FloatArray, tau: FloatArray) -> Mapping[str, Any]: ...


class _Solution(Protocol):
    """One lambda's integrated solution (scipy or mpmath, either end): the summary fields are
    its attributes."""

    def history(self, tau: FloatArray) -> Mapping[str, Any]: ...


#: The integrator and its options for the lambdas the tables do not answer.
_Integration = tuple[str, dict[str, Any]]


class ExactModel(Model):
    """The model ``"exact"``: Eq. (10) solved exactly (options and backends: module docstring)."""

    name = "exact"
    description = ("Zener's equation (10) solved exactly: Chebyshev tables (summary for "
                   "0 <= lambda <= 1000, summary and history), direct integration on request")
    summary_fields = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m",
                      "impulse", "int_F2", "xi")
    history_fields = ("delta", "velocity", "force", "impulse")
    lam_bound = np.nextafter(_exact.LAMBDA_MAX, np.inf)
    bound_reason = "the range over which the integrator is tested"
    options = ("rtol", "method", "backend", "dps", "contact_end")

    def _split(self, lam: FloatArray, options: Mapping[str, Any], history: bool = False
               ) -> tuple[npt.NDArray[np.bool_], _Integration | None, _Tables]:
        """Mask of lambda to take from the tables, the options left for integration, and the
        table module (the plate's or the force-free end's).

        The summary and history tables both cover [0, 1000] (``history=True``: the history's).
        A lambda broadcast along its last axis (the api's view of a lambda column against a tau
        grid) is checked once per line and gets a broadcast mask, not one of the grid's size."""
        options = dict(options)
        backend = options.pop("backend", "auto")
        tab: _Tables
        check: Callable[[FloatArray], npt.NDArray[np.bool_]]
        end = _force.check_contact_end(options.get("contact_end", "delta"))
        if end == "force":
            tab = _force_fast
            check = _force_fast.in_range
            lo, top = _force_fast.LAM_MIN, _force_fast.LAM_MAX
        else:
            options.pop("contact_end", None)
            tab = _fast
            check = _fast.history_in_range if history else _fast.in_range
            lo, top = _fast.LAM_MIN, _fast.HISTORY_LAM_MAX if history else _fast.LAM_MAX
        column = lam.ndim >= 1 and lam.shape[-1] > 1 and lam.strides[-1] == 0

        def in_range(x: FloatArray) -> npt.NDArray[np.bool_]:
            return np.broadcast_to(check(x[..., :1]), x.shape) if column else check(x)

        if not isinstance(backend, str) or backend not in BACKENDS:
            raise ValueError(f"unknown backend {backend!r} for model 'exact'; allowed: "
                             f"{', '.join(BACKENDS)}")
        # every option's value checked before any work (a NaN rtol used to hang scipy's loop)
        if "rtol" in options or "method" in options:
            rtol, _, method = _exact.check_options(rtol=options.get("rtol", 1e-12),
                                                   method=options.get("method", "DOP853"))
            options.update({k: v for k, v in (("rtol", rtol), ("method", method))
                            if k in options})
        if "dps" in options:
            options["dps"] = _exact_mp.check_dps(options["dps"])
        table_options = {k: v for k, v in options.items() if k != "contact_end"}
        if backend == "table":
            if table_options:
                raise ValueError(f"option {sorted(table_options)[0]!r} does not go with "
                                 f"backend='table'")
            if not np.all(in_range(lam)):
                bad = float(lam[~in_range(lam)].ravel()[0])
                raise ValueError(
                    f"lambda = {bad!r} is outside the exact {'history' if history else 'summary'}"
                    f" table's range [{lo:g}, {top:g}]; use backend='auto' "
                    f"(integrates outside) or 'scipy'")
            return np.broadcast_to(True, lam.shape), None, tab
        if backend == "auto":
            if options.keys() & {"rtol", "method"}:
                backend = "scipy"  # an integrator tolerance was asked for: integrate everything
            else:
                if "dps" in options:
                    raise ValueError("option 'dps' goes with backend='mpmath'")
                return in_range(lam), ("scipy", options), tab
        return np.broadcast_to(False, lam.shape), (backend, options), tab

    def _solutions(self, lam_values: FloatArray, backend: str,
                   options: Mapping[str, Any]) -> dict[float, _Solution]:
        options = dict(options)
        force = options.pop("contact_end", "delta") == "force"
        if backend == "scipy":
            if "dps" in options:
                raise ValueError("option 'dps' goes with backend='mpmath'")
            solve: Callable[..., _Solution] = _force.solve if force else _exact.solve
            return {float(x): solve(x, **options) for x in np.unique(lam_values)}
        bad = set(options) - {"dps"}
        if bad:
            raise ValueError(f"option {sorted(bad)[0]!r} does not go with backend='mpmath'")
        solve_mp: Callable[..., _Solution] = _force.solve_mp if force else _exact_mp.solve
        return {float(x): solve_mp(x, **options) for x in np.unique(lam_values)}

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        fast, rest, tab = self._split(lam, options)
        out = {f: np.empty(lam.shape) for f in self.summary_fields}
        if fast.any():
            v = tab.summary(lam[fast])
            for f in self.summary_fields:
                out[f][fast] = v[f]
        if not fast.all():
            assert rest is not None  # None only with backend="table", where fast is all True
            sols = self._solutions(lam[~fast], *rest)
            for i in zip(*np.nonzero(~fast)):
                s = sols[float(lam[i])]
                for f in self.summary_fields:
                    out[f][i] = float(getattr(s, f))
        return out

    def _history(self, lam: FloatArray, tau: FloatArray, **options: Any) -> FieldValues:
        fast, rest, tab = self._split(lam, options, history=True)
        if fast.all():  # shapes kept (the table sees a broadcast lambda column as such)
            v = tab.history(lam, tau)
            return {f: v[f] for f in self.history_fields}
        out = {f: np.empty(tau.shape) for f in self.history_fields}
        if fast.any():
            v = tab.history(lam[fast], tau[fast])
            for f in self.history_fields:
                out[f][fast] = v[f]
        if not fast.all():
            assert rest is not None  # None only with backend="table", where fast is all True
            sols = self._solutions(lam[~fast], *rest)
            for x, s in sols.items():
                mask = (lam == x) & ~fast
                h = s.history(tau[mask])
                for f in self.history_fields:
                    out[f][mask] = np.asarray(h[f], dtype=float)
        return out


register(ExactModel())
