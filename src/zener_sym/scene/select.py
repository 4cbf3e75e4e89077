"""``select_model``: the cheapest model whose measured error envelope meets a tolerance."""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

from . import envelopes as _env

__all__ = ["Selection", "select_model", "QUANTITY_ALIASES", "ALL_QUANTITIES"]

#: Dimensional names accepted for the quantity, mapped to the table's quantity.
QUANTITY_ALIASES = {
    "contact_duration": "tau_d", "max_force": "F_m", "max_compression": "delta_m",
    "restitution": "e", "rebound_velocity": "e", "energy_loss": "xi",
    "final_deflection": "impulse", "force": "force_history", "deflection": "impulse_history",
    "velocity": "impulse_history",
}
#: What quantity="all" asks for: every summary quantity a scene result reports.
ALL_QUANTITIES = ("tau_d", "F_m", "delta_m", "e", "xi", "impulse")


@dataclass(frozen=True)
class Selection:
    """The chosen model, why, and the envelope that decided it (None for the fallback)."""

    model: str
    reason: str
    envelope: float | None = None

    def __iter__(self):  # model, reason = select_model(...)
        return iter((self.model, self.reason))


def _lambda_of(lam_or_scene) -> float:
    from ..params import as_lambda

    lam = getattr(lam_or_scene, "lam", None)  # a Scene carries its own lambda
    if lam is not None:
        return float(lam)
    arr = as_lambda(lam_or_scene)
    if arr.ndim != 0:
        raise ValueError("select_model takes one lambda (a scalar) or a Scene")
    return float(arr)


def _quantities(quantity, table) -> tuple:
    if not isinstance(quantity, str):
        raise ValueError(f"quantity must be a string, got {quantity!r}")
    if quantity == "all":
        return ALL_QUANTITIES
    q = QUANTITY_ALIASES.get(quantity, quantity)
    if q not in table["quantities"]:
        raise ValueError(f"unknown quantity {quantity!r}; allowed: 'all', "
                         f"{', '.join(table['quantities'])}, {', '.join(QUANTITY_ALIASES)}")
    return (q,)


def _envelope(entry, qs, idx):
    """Worst envelope over the quantities qs and the intervals idx; None if any is missing."""
    worst = 0.0
    for q in qs:
        row = entry["envelopes"].get(q)
        if row is None:
            return None
        for i in idx:
            if row[i] is None:
                return None
            worst = max(worst, row[i])
    return worst


def select_model(lam_or_scene, quantity: str = "all", rtol: float = 1e-3, table=None
                 ) -> Selection:
    """The cheapest registered model whose measured error envelope meets ``rtol``.

    Parameters
    ----------
    lam_or_scene : float or Scene
        Zener's lambda (scalar) or a scene (its ``lam`` is used).
    quantity : str
        A quantity of the envelope table (``delta_m``, ``tau_d``, ``e``, ``F_m``, ``xi``, ...,
        ``force_history``, ``impulse_history``), a dimensional alias (``contact_duration``,
        ``max_force``, ``restitution``, ``force``, ...), or ``"all"`` (every summary quantity a
        scene reports).
    rtol : float
        Required relative accuracy, > 0.
    table : dict, optional
        An envelope table (default: the committed ``data/envelopes.json``).

    Returns
    -------
    Selection
        ``model`` (a name in ``zener_sym.MODELS``), ``reason`` (a sentence), ``envelope``.
        Unpacks as ``model, reason``.

    Notes
    -----
    A model qualifies when it is registered, lambda is below its bound, and its envelope on
    every table interval containing lambda (two at an interval edge) is <= rtol. Candidates are
    tried in the table's measured cost order; with none qualifying, or lambda outside the
    table, the answer is "exact".
    """
    from ..models import REGISTRY

    if isinstance(rtol, bool) or not isinstance(rtol, numbers.Real) or not math.isfinite(rtol) \
            or rtol <= 0:
        raise ValueError(f"rtol must be a finite number > 0, got {rtol!r}")
    table = _env.load() if table is None else table
    lam = _lambda_of(lam_or_scene)
    qs = _quantities(quantity, table)
    what = "every reported quantity" if quantity == "all" else repr(quantity)
    idx = [i for i, (lo, hi) in enumerate(table["intervals"]) if lo <= lam <= hi]
    if not idx:
        hi = table["intervals"][-1][1]
        return Selection("exact", f"lambda = {lam:.4g} is outside the measured range "
                         f"[0, {hi:g}] of the envelope table: direct integration ('exact')")
    span = (table["intervals"][idx[0]][0], table["intervals"][idx[-1]][1])
    rejected = []
    ranked = sorted(table["models"].items(), key=lambda kv: kv[1]["cost_rank"])
    for name, entry in ranked:
        if name not in REGISTRY:
            continue
        bound = REGISTRY[name].lam_bound
        if bound is not None and lam >= bound:
            rejected.append(f"{name}: lambda beyond its bound {bound:.4g}")
            continue
        env = _envelope(entry, qs, idx)
        if env is None:
            rejected.append(f"{name}: no measured envelope")
            continue
        if env <= rtol:
            why = (f"cheapest qualifying model (cost rank {entry['cost_rank']}): measured max "
                   f"relative error of {what} for lambda in [{span[0]:g}, {span[1]:g}] is "
                   f"{env:.2g} <= rtol {rtol:g}")
            if rejected:
                why += "; cheaper models rejected: " + "; ".join(rejected)
            return Selection(name, why, env)
        rejected.append(f"{name}: envelope {env:.2g} > rtol")
    why = "no model meets rtol {:g} for {} at lambda = {:.4g}".format(rtol, what, lam)
    if rejected:
        why += " (" + "; ".join(rejected) + ")"
    why += ": falling back to direct integration ('exact')"
    exact_entry = table["models"].get("exact")
    env = None if exact_entry is None else _envelope(exact_entry, qs, idx)
    if env is not None and env > rtol:
        why += (f", the most accurate model available; its own measured error {env:.2g} "
                f"exceeds rtol, so that accuracy is not reached")
    return Selection("exact", why)
