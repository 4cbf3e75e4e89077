"""``select_model``: the cheapest model whose measured error envelope meets a tolerance."""
from __future__ import annotations

import math
import numbers
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

from ..typing import RealLike
from . import envelopes as _env

if TYPE_CHECKING:  # annotations only: the models layer is imported where used
    from ..models import Model


class HasLambda(Protocol):
    """A scene, as :func:`select_model` sees it: it carries its own lambda (scene.py imports
    this module, so ``Scene`` is described here rather than imported)."""

    @property
    def lam(self) -> float: ...

__all__ = ["Selection", "select_model", "QUANTITY_ALIASES", "ALL_QUANTITIES"]

#: Scene field names accepted for the quantity, mapped to the table's quantity.
QUANTITY_ALIASES = {
    "contact_duration_s": "tau_d", "max_force_N": "F_m", "max_compression_m": "delta_m",
    "rebound_speed_m_s": "e", "final_deflection_m": "impulse", "force": "force_history",
    "deflection": "impulse_history", "velocity": "impulse_history",
}
#: What quantity="all" asks for: every summary quantity a scene result reports.
ALL_QUANTITIES = ("tau_d", "F_m", "delta_m", "e", "xi", "impulse")


@dataclass(frozen=True)
class Selection:
    """The chosen model, why, and the envelope that decided it (None for the fallback).

    Parameters
    ----------
    model : str
        The chosen model, a name in ``zener_sym.MODELS``.
    reason : str
        Why it was chosen (or why the fallback), a sentence.
    envelope : float or None
        The measured error envelope that decided it; None for the fallback to "exact".

    Attributes
    ----------
    model : str
    reason : str
    envelope : float or None

    Examples
    --------
    >>> import zener_sym as zs
    >>> sel = zs.select_model(0.3, "tau_d", 0.5)
    >>> sel.model in zs.MODELS and "rtol" in sel.reason
    True
    >>> model, reason = sel                     # unpacks as a pair
    """

    model: str
    reason: str
    envelope: float | None = None

    def __iter__(self) -> Iterator[str]:  # model, reason = select_model(...)
        return iter((self.model, self.reason))


def _lambda_of(lam_or_scene: object) -> float:
    from ..params import as_lambda

    lam = getattr(lam_or_scene, "lam", None)  # a Scene carries its own lambda
    if lam is not None:
        return float(lam)
    arr = as_lambda(lam_or_scene)  # type: ignore[arg-type]  # any object: validated there
    if arr.ndim != 0:
        raise ValueError("select_model takes one lambda (a scalar) or a Scene")
    return float(arr)


def _quantities(quantity: object, table: Mapping[str, Any]) -> tuple[str, ...]:
    if not isinstance(quantity, str):
        raise ValueError(f"quantity must be a string, got {quantity!r}")
    if quantity == "all":
        return ALL_QUANTITIES
    q = QUANTITY_ALIASES.get(quantity, quantity)
    if q not in table["quantities"]:
        raise ValueError(f"unknown quantity {quantity!r}; allowed: 'all', "
                         f"{', '.join(table['quantities'])}, {', '.join(QUANTITY_ALIASES)}")
    return (q,)


def _envelope(entry: Mapping[str, Any], qs: Sequence[str], idx: Sequence[int],
              model: Model | None = None) -> tuple[float | None, str | None]:
    """(worst envelope over the quantities qs and the intervals idx, None) or (None, why not)."""
    worst = 0.0
    for q in qs:
        row = entry["envelopes"].get(q)
        field = q.replace("_history", "")
        if model is not None and field not in (model.summary_fields + model.history_fields):
            return None, f"gives no {field}"
        if row is None or any(row[i] is None for i in idx):
            return None, f"{q} not measured at this lambda"
        worst = max(worst, max(row[i] for i in idx))
    return worst, None


def select_model(lam_or_scene: RealLike | HasLambda, quantity: str = "all", rtol: float = 1e-3,
                 table: Mapping[str, Any] | None = None) -> Selection:
    """The cheapest registered model whose measured error envelope meets ``rtol``.

    Parameters
    ----------
    lam_or_scene : float or Scene
        Zener's lambda (scalar) or a scene (its ``lam`` is used).
    quantity : str
        A quantity of the envelope table (``delta_m``, ``tau_d``, ``e``, ``F_m``, ``xi``, ...,
        ``force_history``, ``impulse_history``), a scene field (``contact_duration_s``, ``max_force_N``,
        ...), a history (``force``, ``deflection``, ``velocity``), or ``"all"`` (every summary quantity a
        scene reports).
    rtol : float
        Required accuracy, > 0: relative, except for ``xi``, whose error is absolute (the
        energy loss is a fraction of the impact energy and tends to 0 with lambda).
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

    Raises
    ------
    ValueError
        For a bad lambda, rtol or quantity, or a lambda outside the range of every model.

    Examples
    --------
    >>> import zener_sym as zs
    >>> model, reason = zs.select_model(0.8, "e", 1e-4)
    >>> model
    'exact'
    >>> zs.select_model(2000, "e", 1e-3)
    Traceback (most recent call last):
    ...
    ValueError: lambda = 2000 is outside the measured range [0, 10] of the envelope table and outside the exact model's range (0 <= lambda <= 1000): no model can be chosen for an accuracy there
    """
    from ..models import REGISTRY
    from ..params import bound_text

    rtol_in: object = rtol  # checked at run time, whatever a caller passed
    if isinstance(rtol_in, bool) or not isinstance(rtol_in, numbers.Real) \
            or not math.isfinite(rtol_in) or rtol <= 0:
        raise ValueError(f"rtol must be a finite number > 0, got {rtol!r}")
    table = _env.load() if table is None else table
    lam = _lambda_of(lam_or_scene)
    qs = _quantities(quantity, table)
    what = "every reported quantity" if quantity == "all" else repr(quantity)
    accepting = [m for m in REGISTRY.values() if m.lam_bound is None or lam < m.lam_bound]
    if not accepting:
        # every model has a bound here (one without a bound accepts every lambda)
        bounds = {m.name: m.lam_bound for m in REGISTRY.values() if m.lam_bound is not None}
        widest = max(bounds, key=bounds.__getitem__)
        raise ValueError(f"lambda = {lam:.6g} is outside the range of every model; the widest "
                         f"is {widest!r}: {bound_text(bounds[widest])}")
    idx = [i for i, (lo, hi) in enumerate(table["intervals"]) if lo <= lam <= hi]
    if not idx:
        hi = table["intervals"][-1][1]
        exact = REGISTRY["exact"]
        if exact.lam_bound is not None and lam >= exact.lam_bound:
            raise ValueError(f"lambda = {lam:.6g} is outside the measured range [0, {hi:g}] of "
                             f"the envelope table and outside the exact model's range "
                             f"({bound_text(exact.lam_bound)}): no model can be chosen for an "
                             "accuracy there")
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
        env, why_not = _envelope(entry, qs, idx, REGISTRY[name])
        if env is None:
            rejected.append(f"{name}: {why_not}")
            continue
        if env <= rtol:
            why = (f"cheapest qualifying model (cost rank {entry['cost_rank']}): measured max "
                   f"error (relative; absolute for xi) of {what} for lambda in "
                   f"[{span[0]:g}, {span[1]:g}] is "
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
    env = None if exact_entry is None else _envelope(exact_entry, qs, idx)[0]
    if env is not None and env > rtol:
        why += (f", the most accurate model available; its own measured error {env:.2g} "
                f"exceeds rtol, so that accuracy is not reached")
    return Selection("exact", why)
