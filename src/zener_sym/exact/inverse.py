"""The inverse of the tabulated summary: the lambda (Eq. 11) that gives a coefficient of
restitution e, an energy-loss ratio xi (Eq. 69) or a contact duration tau_d.

Each target is solved on the Chebyshev tables (:mod:`zener_sym.exact.table`) by a safeguarded
Newton iteration, all targets at once:

- a bracket [lo, hi] from a fixed grid of lambda on which the quantity is tabulated once, and a
  first guess interpolated there (log lambda against log q: the quantities behave like powers
  of lambda at both ends);
- Newton steps on h(lambda) = ln q(lambda) - ln q_target with h' = q' / q, q' from
  :func:`zener_sym.exact.table.summary_derivative` (the series' own derivative, not a finite
  difference); a step that leaves the bracket is replaced by a bisection (geometric while the
  bracket spans more than a factor 4, halving towards 0 while lo = 0), so every iteration
  shrinks the bracket;
- stop where |h| <= ``H_TOL`` (q within 1e-15 relative) or the bracket is a few ulps wide
  (at a lambda-piece edge, where the tables' two interpolants differ by < 1e-12 relative).

e is solved through xi = 1 - e^2 = (1 - e)(1 + e) while that is below 1/2 (e close to 1), the
form the tables use there (``solver.restitution``), so lambda keeps its relative accuracy as
e -> 1; below, through e itself. e = 1 and xi = 0 give lambda = 0 exactly.
"""
from __future__ import annotations

import functools
from types import ModuleType

import numpy as np

from .. import params
from ..typing import FloatArray, RealArrayLike
from . import force_table as _force_table
from . import table as _table

__all__ = ["QUANTITIES", "lam_for", "reachable", "tau_d_branch"]

#: The quantities lambda can be solved for.
QUANTITIES = ("e", "xi", "tau_d")
#: Newton stops where |ln q - ln q_target| is below this (q within ~1e-15 relative).
H_TOL = 4.0 * np.finfo(float).eps
#: Iteration cap: the bisection fallback alone halves a bracket of [0, 1000] to a few ulps in
#: well under this many steps (geometrically, then arithmetically).
MAX_ITER = 200


def _tab(contact_end: str) -> ModuleType:
    """The table module of an end of contact."""
    return _force_table if contact_end == "force" else _table


@functools.cache
def _grid(contact_end: str) -> tuple[FloatArray, dict[str, FloatArray]]:
    """The bracketing grid of lambda (dense near 0, where the force end goes like sqrt(lambda),
    geometric above 5) and the summary tabulated on it."""
    lam = np.unique(np.concatenate([
        [0.0], np.geomspace(1e-16, 1e-2, 57), np.linspace(1e-2, 5.0, 500),
        np.geomspace(5.0, _table.LAM_MAX, 400)]))
    lam = lam[lam <= _table.LAM_MAX]
    s = _tab(contact_end).summary(lam)
    return lam, {k: np.asarray(s[k], dtype=float) for k in ("e", "xi", "tau_d")}


@functools.cache
def tau_d_branch(contact_end: str = "delta") -> tuple[float, float, int]:
    """The range of lambda on which tau_d(lambda) is monotone, which :func:`lam_for` inverts.

    Found on the tables: the sign of d tau_d / d lambda (``summary_derivative``) on the
    bracketing grid; where it changes, the run that reaches LAM_MAX is kept (the other branch's
    values are refused as ambiguous).

    Parameters
    ----------
    contact_end : str
        "delta" (the plate) or "force" (the grains' force-free end).

    Returns
    -------
    tuple
        (lambda_lo, lambda_hi, direction): direction +1 increasing, -1 decreasing.
    """
    lam, _ = _grid(contact_end)
    pos = lam[lam > 0]  # the force end has no derivative at 0 (its variable is sqrt(lambda))
    sign = np.sign(_table.summary_derivative(pos, "tau_d", contact_end=contact_end))
    sign[sign == 0] = sign[np.flatnonzero(sign)[-1]]
    change = np.flatnonzero(sign[1:] != sign[:-1])
    start = 0.0 if change.size == 0 else float(pos[change[-1] + 1])
    return start, float(lam[-1]), int(sign[-1])


def reachable(quantity: str, contact_end: str = "delta") -> tuple[float, float]:
    """(smallest, largest) value of ``quantity`` the tables reach on the lambda it is solved on.

    e: [e(LAM_MAX), 1]; xi: [0, xi(LAM_MAX)]; tau_d: over ``tau_d_branch``.

    Parameters
    ----------
    quantity : str
        One of ``QUANTITIES``.
    contact_end : str
        "delta" or "force".

    Returns
    -------
    tuple of float
        (smallest, largest).
    """
    lam, q = _grid(contact_end)
    v = q[quantity]
    if quantity == "tau_d":
        lo, hi, _ = tau_d_branch(contact_end)
        v = v[(lam >= lo) & (lam <= hi)]
    return float(v.min()), float(v.max())


def _targets(value: RealArrayLike, name: str) -> FloatArray:
    arr: FloatArray = params._as_float_array(value, name)
    if arr.size == 0:
        raise ValueError(f"{name} is empty: give at least one value")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite, got {arr[~np.isfinite(arr)].ravel()[0].item()!r}")
    return arr


def lam_for(e: RealArrayLike | None = None, xi: RealArrayLike | None = None,
            tau_d: RealArrayLike | None = None, contact_end: str = "delta") -> FloatArray:
    """The lambda (Eq. 11) in [0, LAM_MAX] whose tabulated summary has the given e, xi or tau_d.

    Parameters
    ----------
    e : float or array_like, optional
        Coefficient of restitution, in (0, 1].
    xi : float or array_like, optional
        Energy-loss ratio 1 - e^2 (Eq. 69), in [0, 1).
    tau_d : float or array_like, optional
        Contact duration, > 0.
    contact_end : str
        "delta" (the plate) or "force" (the grains' force-free end).

    Exactly one of ``e``, ``xi``, ``tau_d`` is given.

    Returns
    -------
    ndarray
        lambda, of the given quantity's shape.

    Raises
    ------
    ValueError
        None or more than one quantity given; a value outside what the tables reach on
        [0, LAM_MAX] (the message gives the reachable range); tau_d where tau_d(lambda) is not
        monotone (``tau_d_branch``).
    """
    given = {k: v for k, v in (("e", e), ("xi", xi), ("tau_d", tau_d)) if v is not None}
    if len(given) != 1:
        raise ValueError(f"give exactly one of e=, xi=, tau_d= (got {', '.join(given) or 'none'})")
    (name, value), = given.items()
    if contact_end not in ("delta", "force"):
        raise ValueError(f"unknown contact_end {contact_end!r}; allowed: 'delta', 'force'")
    x = _targets(value, name)
    lam_max = _table.LAM_MAX
    lo_v, hi_v = reachable(name, contact_end)
    if name == "e":
        bad = (x <= 0.0) | (x > 1.0)
        if bad.any():
            raise ValueError(f"e must be in (0, 1], got {x[bad].ravel()[0].item()!r}")
        low = x < lo_v
        if low.any():
            raise ValueError(
                f"e = {x[low].ravel()[0].item()!r} is below e(lambda = {lam_max:g}) = {lo_v:.17g}, "
                f"the smallest restitution the tables reach (contact_end={contact_end!r}); "
                f"reachable: {lo_v:.6g} <= e <= 1")
        # close to e = 1 through xi = (1 - e)(1 + e): no cancellation, as the tables' e there
        xi_t = (1.0 - x) * (1.0 + x)
        via_xi = xi_t < 0.5
        out = np.zeros(x.shape)
        for mask, quantity, t in ((via_xi & (xi_t > 0), "xi", xi_t), (~via_xi, "e", x)):
            if mask.any():
                out[mask] = _solve(quantity, t[mask], contact_end)
        return out
    if name == "xi":
        bad = (x < 0.0) | (x >= 1.0)
        if bad.any():
            raise ValueError(f"xi must be in [0, 1), got {x[bad].ravel()[0].item()!r}")
        high = x > hi_v
        if high.any():
            raise ValueError(
                f"xi = {x[high].ravel()[0].item()!r} is above xi(lambda = {lam_max:g}) = "
                f"{hi_v:.17g}, the largest energy loss the tables reach "
                f"(contact_end={contact_end!r}); reachable: 0 <= xi <= {hi_v:.17g}")
        out = np.zeros(x.shape)
        pos = x > 0
        if pos.any():
            out[pos] = _solve("xi", x[pos], contact_end)
        return out
    a, b, direction = tau_d_branch(contact_end)
    bad = x <= 0.0
    if bad.any():
        raise ValueError(f"tau_d must be > 0, got {x[bad].ravel()[0].item()!r}")
    out_of = (x < lo_v) | (x > hi_v)
    if out_of.any():
        where = (f"tau_d(lambda) is monotone only for {a:.6g} <= lambda <= {b:g} (it "
                 f"{'increases' if direction > 0 else 'decreases'} there); below lambda = "
                 f"{a:.6g} the same tau_d is reached twice and is refused" if a > 0 else
                 f"tau_d(lambda) is monotone on [0, {b:g}] "
                 f"({'increasing' if direction > 0 else 'decreasing'})")
        raise ValueError(f"tau_d = {x[out_of].ravel()[0].item()!r} is outside the reachable range "
                         f"[{lo_v:.17g}, {hi_v:.17g}] (contact_end={contact_end!r}): {where}")
    return _solve("tau_d", x, contact_end)


def _log_quantity(quantity: str, lam: FloatArray,
                  contact_end: str) -> tuple[FloatArray, FloatArray]:
    """(ln q, d ln q / d lambda) from the tables' one series behind q."""
    if contact_end == "force":
        return _force_table.log_quantity(lam, quantity)
    return _table.log_quantity(lam, quantity)


def _solve(quantity: str, target: FloatArray, contact_end: str) -> FloatArray:
    """lambda with q(lambda) = target (> 0, inside the reachable range), safeguarded Newton on
    h = ln q - ln target (module docstring). Returns an array of target's shape."""
    shape = target.shape
    t = target.reshape(-1)
    lam_g, q = _grid(contact_end)
    qg = q[quantity]
    if quantity == "tau_d":
        a, b, _ = tau_d_branch(contact_end)
        keep = (lam_g >= a) & (lam_g <= b)
        lam_g, qg = lam_g[keep], qg[keep]
    increasing = qg[-1] > qg[0]
    key = qg if increasing else -qg
    # bracket [lam_g[i - 1], lam_g[i]] holding the target (key non-decreasing)
    i = np.clip(np.searchsorted(key, t if increasing else -t, side="left"), 1, len(lam_g) - 1)
    lo, hi = lam_g[i - 1].copy(), lam_g[i].copy()
    q_lo, q_hi = qg[i - 1], qg[i]
    # first guess: ln lambda linear in ln q inside the bracket (a power law); from 0 the
    # power read off the next interval
    with np.errstate(divide="ignore", invalid="ignore"):
        frac = np.log(t / q_lo) / np.log(q_hi / q_lo)
        guess = np.exp(np.log(lo) + frac * (np.log(hi) - np.log(lo)))
        j = np.minimum(i + 1, len(lam_g) - 1)
        p = np.log(qg[j] / q_hi) / np.log(lam_g[j] / hi)
        from_zero = hi * (t / q_hi) ** (1.0 / p)
        lin = lo + (hi - lo) * (t - q_lo) / (q_hi - q_lo)
    guess = np.where(lo > 0, guess, np.where(qg[0] == 0.0, from_zero, lin))
    guess = np.where(np.isfinite(guess) & (guess > lo) & (guess < hi), guess, 0.5 * (lo + hi))
    lam: FloatArray = guess
    sign = 1.0 if increasing else -1.0
    log_t = np.log(t)
    active = np.arange(t.size)
    for _ in range(MAX_ITER):
        x = lam[active]
        ln_q, dln_q = _log_quantity(quantity, x, contact_end)
        h = ln_q - log_t[active]
        # the bracket shrinks to the side the sign of h says
        above = sign * h > 0  # lambda too large
        lo_a, hi_a = lo[active], hi[active]
        hi_a = np.where(above, x, hi_a)
        lo_a = np.where(above, lo_a, x)
        lo[active], hi[active] = lo_a, hi_a
        done = (np.abs(h) <= H_TOL) | (hi_a - lo_a <= 4.0 * np.spacing(np.maximum(hi_a, 1e-300)))
        with np.errstate(divide="ignore", invalid="ignore"):
            step = x - h / dln_q
        ok = np.isfinite(step) & (step > lo_a) & (step < hi_a)
        bisect = np.where(lo_a > 0,
                          np.where(hi_a > 4.0 * lo_a, np.sqrt(lo_a * hi_a), 0.5 * (lo_a + hi_a)),
                          hi_a / 16.0)
        nxt = np.where(ok, step, bisect)
        lam[active] = np.where(done, x, nxt)
        active = active[~done]
        if active.size == 0:
            break
    else:
        raise RuntimeError(f"exact.inverse.lam_for: no convergence for {quantity} = "
                           f"{t[active[0]]!r} (contact_end={contact_end!r}); this is a bug")
    return lam.reshape(shape)
