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

import types
from collections.abc import Collection, Mapping
from typing import Any

import mpmath
import numpy as np

from ..numerics.blocks import field_buffers, line_blocks
from ..typing import FloatArray
from .base import FieldValues, Model, computed_bound, register

#: Points per block of ham0's history (about 16 000: each block calls the generated kernels,
#: whose input checks cost about 25 us a call).
_BLOCK = 16384


def _gen(name: str) -> types.SimpleNamespace:
    """The HAM kernels ``name`` ("ham0_numpy", "ham1_mpmath", ...: ``ham0``/``ham1`` of
    ``zener_sym.ham.runtime_numpy`` or ``runtime_mpmath``, namespaces of functions), imported
    on first use: ``zener-sym regen kernels`` must run (and rewrite generated/) even when the
    committed kernels are stale or broken."""
    import importlib

    order, backend = name.split("_")
    module = {"numpy": "zener_sym.ham.runtime_numpy", "mpmath": "zener_sym.ham.runtime_mpmath"}
    kernels: types.SimpleNamespace = getattr(importlib.import_module(module[backend]), order)
    return kernels


def _backend(options: Mapping[str, Any]) -> tuple[str, int]:
    """The checked backend and mpmath digits (30 unless ``dps`` is given)."""
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
    bound_reason = ("lam_crit = 2.44243892998...: omega0 = sqrt(4k - k^2 lambda^2)/2 is real only "
                    "below it, Eq. (81)")
    options = ("backend", "dps")

    @computed_bound
    def lam_bound(self) -> float:
        """lam_crit from the generated module (emitted from the derivation)."""
        bound: float = _gen("ham1_numpy").LAM_CRIT
        return bound

    @staticmethod
    def _finish(d: Mapping[str, Any]) -> FieldValues:
        """The summary fields from the kernels' delta_m, tau_dc, tau_d, e, F_m, impulse, int_F2
        (float arrays, or sequences of mpf)."""
        out = {f: np.asarray(d[f], dtype=float) for f in ("delta_m", "tau_dc", "tau_d", "e", "F_m",
                                                           "impulse", "int_F2")}
        out["tau_dr"] = out["tau_d"] - out["tau_dc"]
        out["eta"] = out["tau_dr"] / out["tau_dc"]
        out["xi"] = 2.0 * out["impulse"] - out["impulse"] ** 2
        return out


class Ham0(_HamModel):
    """The model ``"ham0"``: the zeroth-order HAM solution, Eq. (35)."""

    name = "ham0"
    description = "zeroth-order HAM solution, Eq. (35): damped sine, closed forms (54)-(61), (79)"

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        backend, dps = _backend(options)
        h0, m0 = _gen("ham0_numpy"), _gen("ham0_mpmath")
        if backend == "numpy":
            return self._finish(h0.summary(lam))
        rows = [m0.summary(float(x), dps) for x in lam]
        return self._finish({f: [float(r[f]) for r in rows] for f in rows[0]})

    selects_fields = True

    def _history(self, lam: FloatArray, tau: FloatArray, fields: Collection[str] | None = None,
                 **options: Any) -> FieldValues:
        backend, dps = _backend(options)
        h0, m0 = _gen("ham0_numpy"), _gen("ham0_mpmath")
        want = set(self.history_fields if fields is None else fields)
        if backend == "numpy":
            return self._history_numpy(h0, lam, tau, want)
        else:
            d, imp, force = (np.empty(tau.shape) for _ in range(3))
            for i in np.ndindex(tau.shape):
                t, x = float(tau[i]), float(lam[i])
                with mpmath.workdps(dps):
                    k, beta, omega0 = m0.params(x)
                    dd = m0.delta(t, x)
                    d[i] = float(dd) if (omega0 * t < mpmath.pi and dd > 0) else 0.0
                    imp[i] = float(m0.impulse(t, x))
                    force[i] = d[i] ** 1.5  # delta0^{3/2} (45), 0 from tau_d on
        return {"delta": d, "force": force, "impulse": imp, "velocity": 1.0 - imp}

    @staticmethod
    def _history_numpy(h0: types.SimpleNamespace, lam: FloatArray, tau: FloatArray,
                       want: set[str]) -> FieldValues:
        """The numpy history, one block of lines at a time (``blocks.line_blocks``): the generated
        delta0 (35) on its contact (``delta_contact``), and the impulse (47) omega0^{-5/2}
        K_s(3 beta / (2 omega0), omega0 tau) from the per-rate Chebyshev series of K_s
        (``numerics.sqrt_integrals.KsSeries``, within 1e-13 of the generated h0.impulse's quadrature,
        tests), its rates contracted once for all blocks."""
        from ..numerics.sqrt_integrals import A_SERIES, KsSeries, impulse_s

        shape = tau.shape
        column = lam.ndim >= 1 and lam.shape[-1] > 1 and np.array_equal(
            lam, np.broadcast_to(lam[..., :1], lam.shape))
        # one lambda per line (a broadcast column): the parameters once per line; otherwise
        # every point is a line of its own
        lines = lam[..., 0].ravel() if column else lam.ravel()
        n_col = shape[-1] if column else 1
        t2 = tau.reshape(lines.size, n_col)
        _, beta, omega0 = h0.params(lines)
        # the summary's tau_d (generated: pi * omega0**(-1.0)), so delta is exactly 0 from there
        # on (omega0 tau <= pi left sin(pi) = 1e-16 at tau_d)
        tau_d = np.pi * omega0 ** (-1.0)
        rate = 1.5 * beta / omega0
        scale = omega0 ** -2.5
        series = None
        # lines of several points: the series of their rates once for all blocks; one lambda
        # per point goes through impulse_s, which takes many distinct rates in groups
        if want & {"impulse", "velocity"} and column and np.all(rate <= A_SERIES):
            u, rate_of_line = np.unique(rate, return_inverse=True)
            series = KsSeries(u)
        out = field_buffers(("delta", "force", "impulse", "velocity"), t2.shape)
        for r0, r1, c0, c1 in line_blocks(lines.size, n_col, _BLOCK):
            t = t2[r0:r1, c0:c1]
            if want & {"delta", "force"}:
                d = out["delta"][r0:r1, c0:c1]
                d[...] = h0.delta_contact(t, lines[r0:r1, None])  # >= 0, 0 past pi/omega0
                np.copyto(d, 0.0, where=t >= tau_d[r0:r1, None])
                f = out["force"][r0:r1, c0:c1]
                np.sqrt(d, out=f)
                f *= d
            if series is not None:
                theta = t * omega0[r0:r1, None]
                k = series.at(theta.ravel(), np.repeat(rate_of_line[r0:r1], c1 - c0))
                imp = out["impulse"][r0:r1, c0:c1]
                np.multiply(k.reshape(t.shape), scale[r0:r1, None], out=imp)
                np.subtract(1.0, imp, out=out["velocity"][r0:r1, c0:c1])
        if want & {"impulse", "velocity"} and series is None:
            # one lambda per point, or a rate beyond the series' range (lambda near lam_crit,
            # where impulse_s uses the quadrature)
            out["impulse"] = impulse_s(rate[:, None], t2 * omega0[:, None]) * scale[:, None]
            out["velocity"] = 1.0 - out["impulse"]
        groups = [g for g in (("delta", "force"), ("impulse", "velocity")) if want & set(g)]
        return {f: out[f].reshape(shape) for g in groups for f in g}


class Ham1(_HamModel):
    """The model ``"ham1"``: the first-order HAM solution, Eq. (42)."""

    name = "ham1"
    description = ("first-order HAM solution, Eq. (42): delta0 + delta1, contact end by root "
                   "finding, impulse by quadrature of the force (per-lambda Chebyshev series; "
                   "summary from Chebyshev tables in lambda)")

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        backend, dps = _backend(options)
        h1, m1 = _gen("ham1_numpy"), _gen("ham1_mpmath")
        if backend == "numpy":
            return self._finish(_ham1_summary_numpy(h1, lam))
        rows: list[dict[str, Any]] = []
        for x in lam:
            with mpmath.workdps(dps):
                tdc = m1.compression_end(float(x))
                td = m1.contact_end(float(x))
                dm = m1.delta(tdc, float(x))
                imp = m1.impulse(td, float(x), tau_d=td)
                k, beta, omega0 = m1.params(float(x))
                tpi = mpmath.pi / omega0
                f2 = lambda t: m1.force(t, float(x)) ** 2  # noqa: E731
                from ..numerics.mp import contact_integral_mp

                J = contact_integral_mp(f2, 0, min(td, tpi)) + contact_integral_mp(f2, tpi, max(td, tpi))
                e = -m1.delta_dot(td, float(x))
                rows.append(dict(delta_m=dm, tau_dc=tdc, tau_d=td, e=e, F_m=dm ** 1.5, impulse=imp,
                                 int_F2=J))
        return self._finish({f: [float(r[f]) for r in rows] for f in rows[0]})

    selects_fields = True

    def _history(self, lam: FloatArray, tau: FloatArray, fields: Collection[str] | None = None,
                 **options: Any) -> FieldValues:
        backend, dps = _backend(options)
        h1, m1 = _gen("ham1_numpy"), _gen("ham1_mpmath")
        want = set(self.history_fields if fields is None else fields)
        if backend == "numpy":
            return _ham1_history_numpy(h1, lam, tau, want)
        u, inv = np.unique(lam, return_inverse=True)
        td_u = h1.contact_end(u)
        d, imp = np.empty(tau.shape), np.empty(tau.shape)
        with mpmath.workdps(dps):
            td_mp = {float(x): m1.contact_end(float(x), guess=float(t))
                     for x, t in zip(u, td_u)}
            for i in np.ndindex(tau.shape):
                t, x = float(tau[i]), float(lam[i])
                tdx = td_mp[x]
                dd = m1.delta(t, x) if t < tdx else mpmath.mpf(0)
                d[i] = float(max(dd, 0))
                imp[i] = float(m1.impulse(t, x, tau_d=tdx))
        return {"delta": d, "force": d**1.5, "impulse": imp, "velocity": 1.0 - imp}


def _ham1_summary_numpy(h1: types.SimpleNamespace, lam: FloatArray) -> FieldValues:
    """ham1 summary in float64: the Chebyshev tables in lambda (``zener_sym.ham.table``, relative
    error below ``table.SUMMARY_RTOL``) where they cover lambda, which is all of
    0 <= lambda < lam_crit; elsewhere the per-lambda series of ``zener_sym.ham.spectral``, with the
    quadrature kernels for the lambda values whose series fail their check."""
    from ..ham import spectral as ham1_spectral
    from ..ham import table as ham1_table

    fast = ham1_table.in_range(lam)
    if fast.all():
        return ham1_table.summary(lam)
    out = ham1_spectral.summary_numpy(lam)
    if fast.any():
        v = ham1_table.summary(lam[fast])
        for f in out:
            out[f][fast] = v[f]
    return out


def _ham1_history_numpy(h1: types.SimpleNamespace, lam: FloatArray, tau: FloatArray,
                        want: set[str]) -> FieldValues:
    """ham1 histories in float64: the per-lambda Chebyshev series of ``zener_sym.ham.spectral``,
    and the quadrature kernels for the lambda values whose series fail their own check (near
    the critical lambda).

    The contact ends at the summary's tau_d (the ham1 tables, within 1e-14 of the series' own
    root), so that the history is exactly 0 from the summary's tau_d on."""
    from ..ham import spectral as ham1_spectral
    from ..ham import table as ham1_table

    u, rows = ham1_spectral.rows_of(lam)
    series = ham1_spectral.Ham1Series(u)
    tab = ham1_table.in_range(u)
    td_tab = np.full(u.shape, np.nan)
    if tab.any():
        td_tab[tab] = ham1_table.summary(u[tab])["tau_d"]
    series.tau_d = np.where(series.ok & tab, td_tab, series.tau_d)
    out: FieldValues = {}
    need_imp = bool(want & {"impulse", "velocity"})
    if want & {"delta", "force"}:
        d = series.delta(rows, tau)
        out["delta"], out["force"] = d, d * np.sqrt(d)
    if need_imp:
        out["impulse"] = series.impulse(rows, tau)
    if not series.ok.all():
        slow = ~series.ok.take(rows)
        lam_s, tau_s = lam[slow], tau[slow]
        u_s = u[~series.ok]
        td_s = np.where(tab[~series.ok], td_tab[~series.ok], np.nan)
        if np.isnan(td_s).any():
            td_s[np.isnan(td_s)] = h1.contact_end(u_s[np.isnan(td_s)])
        td = td_s[np.searchsorted(u_s, lam_s)]
        if want & {"delta", "force"}:
            ds = np.where(tau_s < td, np.maximum(h1.delta(tau_s, lam_s), 0.0), 0.0)
            out["delta"][slow], out["force"][slow] = ds, ds * np.sqrt(ds)
        if need_imp:
            out["impulse"][slow] = h1.impulse(tau_s, lam_s, tau_d=td)
    if need_imp:
        out["velocity"] = 1.0 - out["impulse"]
    return out


register(Ham0())
register(Ham1())
