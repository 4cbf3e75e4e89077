"""Does Zener's infinite plate meet rtol on this bounded plate? The criterion, from a measured table.

Zener's equation assumes that no flexural wave comes back from the plate's edge while the ball
is near the plate. Whether a bounded plate honours that to a relative accuracy rtol depends on
lambda, the plate-size parameter beta (:mod:`zener_sym.scene.plate_geometry`) and the support.
The committed table ``data/plate_criterion.json`` (``zener-sym regen plate-criterion``,
:mod:`zener_sym.scene.plate_criterion_build`) holds, on a grid of (lambda, beta) for each
support of the circle struck at its centre, the ``finite-plate`` model's answer against
Zener's exact one: the relative differences of every quantity a scene reports, and the number
of contacts.

The estimate at a point is conservative by construction:

1. along beta, the table's difference is replaced by its running maximum from small beta up
   (the envelope never decreases as the plate shrinks);
2. inside a grid cell, the estimate is the larger envelope of the two lambda neighbours at the
   upper beta neighbour; below the smallest lambda of the grid, that lambda's column; below the
   smallest beta, the smallest beta's row (the large-plate limit is Zener's);
3. Zener is said to hold when the estimate times :data:`SAFETY` is <= rtol, and only inside the
   grid (lambda above it, or beta above it, is no claim: the finite plate is solved) and for an
   rtol the table resolves (:data:`RESOLUTION` times the accuracy of its solver, times SAFETY).

tests/test_plate_criterion.py runs the ``finite-plate`` model between the grid points and checks
that the criterion never says that Zener holds where the two differ by more than rtol.

A rectangle struck at (x, y) is judged as the simply supported circle whose radius is the
distance d from the impact point to the nearest edge (beta taken with L = d): the nearest edge
sends the first echo, and the circle, whose whole edge is at d, focuses every echo on its
centre at once. The same test checks this on rectangles.
"""
from __future__ import annotations

import bisect
import functools
import json
import math
from dataclasses import dataclass
from importlib import resources
from typing import Any

__all__ = ["Verdict", "zener_error", "judge", "load", "SAFETY", "RESOLUTION", "QUANTITIES", "KNOWN",
           "TABLE"]

#: Zener holds when SAFETY times the estimated difference is <= rtol.
SAFETY = 2.0
#: The smallest difference the table resolves, in units of its solver's rtol: the criterion
#: claims nothing for an rtol below SAFETY x RESOLUTION x solver_rtol.
RESOLUTION = 10.0
#: The quantities the table holds (scene result fields by their summary names; xi absolute).
QUANTITIES = ("tau_d", "F_m", "delta_m", "e", "xi", "impulse")
#: The committed table, in the package's data folder.
TABLE = "plate_criterion.json"
#: Scene field names accepted for the quantity.
_ALIASES = {"contact_duration_s": "tau_d", "max_force_N": "F_m", "max_compression_m": "delta_m",
            "rebound_speed_m_s": "e", "final_deflection_m": "impulse"}
#: Every quantity name the criterion takes.
KNOWN = frozenset(("all",) + QUANTITIES + tuple(_ALIASES))


@functools.lru_cache(maxsize=1)
def load() -> dict[str, Any]:
    """The committed criterion table (``data/plate_criterion.json``)."""
    text = (resources.files("zener_sym") / "data" / TABLE).read_text(encoding="utf-8")
    return dict(json.loads(text))


def _quantities(quantity: str) -> tuple[str, ...]:
    if quantity == "all":
        return QUANTITIES
    q = _ALIASES.get(quantity, quantity)
    if q not in QUANTITIES:
        raise ValueError(f"the finite-plate criterion knows no quantity {quantity!r}; allowed: "
                         f"all, {', '.join(QUANTITIES)}, {', '.join(_ALIASES)}")
    return (q,)


def _envelope(table: dict[str, Any], support: str, q: str) -> list[list[float]]:
    """The running maximum along beta of the table's difference in q, per lambda."""
    rows = table["supports"][support]["difference"][q]
    out = []
    for row in rows:
        worst, env = 0.0, []
        for v in row:
            worst = max(worst, math.inf if v is None else float(v))
            env.append(worst)
        out.append(env)
    return out


def zener_error(lam: float, beta: float, support: str, quantity: str = "all",
                table: dict[str, Any] | None = None) -> float:
    """Conservative estimate of Zener's relative error on the circle (module docstring).

    Parameters
    ----------
    lam : float
        Zener's lambda, >= 0.
    beta : float
        The plate-size parameter, > 0.
    support : {"clamped", "simply-supported"}
    quantity : str
        ``"all"`` (the largest over :data:`QUANTITIES`), one of them, or a scene field name.
    table : dict, optional
        A criterion table (default: the committed one).

    Returns
    -------
    float
        The estimated largest relative difference (absolute for xi) between Zener's answer and
        the finite plate's; ``inf`` where the table makes no claim (lambda or beta beyond it).

    Examples
    --------
    >>> zener_error(2.27, 0.0045, "clamped", "e") > 1.0      # the issue's 50 mm glass plate
    True
    >>> zener_error(0.5, 1e-9, "clamped") < 1e-3             # a very large plate
    True
    """
    table = load() if table is None else table
    lams, betas = table["lam"], table["beta"]
    if not (lam >= 0.0 and beta > 0.0) or lam > lams[-1] or beta > betas[-1]:
        return math.inf
    i = min(max(bisect.bisect_left(lams, lam), 0), len(lams) - 1)  # lams[i] >= lam
    j = min(bisect.bisect_left(betas, beta), len(betas) - 1)       # betas[j] >= beta
    rows = sorted({max(i - 1, 0), i}) if lam > lams[0] else [0]
    worst = 0.0
    for q in _quantities(quantity):
        env = _envelope(table, support, q)
        worst = max(worst, *(env[r][j] for r in rows))
    return worst


@dataclass(frozen=True)
class Verdict:
    """The criterion's answer for one scene.

    Attributes
    ----------
    holds : bool
        Zener's infinite plate meets rtol (for every support judged).
    error : float
        The estimated largest relative difference (``inf``: no claim).
    supports : tuple of str
        The supports judged (both, when the scene did not give one).
    reason : str
        A sentence: the estimate, the rtol and the table's range.
    """

    holds: bool
    error: float
    supports: tuple[str, ...]
    reason: str


def _percent(x: float) -> str:
    """x as a percentage with two significant digits, never in exponent form above 10 %."""
    pct = float(f"{100.0 * x:.2g}")
    return f"{pct:.0f} %" if pct >= 10.0 else f"{pct:.2g} %"


def judge(lam: float, beta: float, supports: tuple[str, ...], quantity: str = "all",
          rtol: float = 1e-3, shape: str = "circle", table: dict[str, Any] | None = None
          ) -> Verdict:
    """Whether Zener's infinite plate meets ``rtol`` (module docstring).

    Parameters
    ----------
    lam : float
        Zener's lambda.
    beta : float
        The plate-size parameter of the circle (for a rectangle: of the equivalent circle, L =
        the distance from the impact point to the nearest edge).
    supports : tuple of str
        The supports to judge (Zener holds only when it holds for each).
    quantity : str
        As :func:`zener_error`.
    rtol : float
        The accuracy asked for.
    shape : {"circle", "rectangle"}
        Only for the sentence.
    table : dict, optional
        A criterion table (default: the committed one).

    Returns
    -------
    Verdict
    """
    table = load() if table is None else table
    err = max(zener_error(lam, beta, s, quantity, table) for s in supports)
    finest = SAFETY * RESOLUTION * float(table["solver_rtol"])
    holds = SAFETY * err <= rtol and rtol >= finest
    what = " or ".join(supports)
    eq = "" if shape == "circle" else " (the rectangle as the circle through its nearest edge)"
    if rtol < finest:
        why = (f"rtol {rtol:g} is finer than the finite-plate criterion resolves ({finest:g}): "
               "no claim that Zener's infinite plate holds")
    elif math.isinf(err):
        why = (f"lambda = {lam:.4g}, beta = {beta:.3g} lie beyond the criterion's table "
               f"(lambda <= {table['lam'][-1]:g}, beta <= {table['beta'][-1]:g}){eq}: no claim "
               "that Zener's infinite plate holds")
    else:
        # a percentage reads at a glance ("error at 62" did not say 62 of what); "up to", as
        # the estimate is a bound (a rectangle's, through its equivalent circle, can exceed the
        # true difference many times: 2100 % where e_plate / e_Zener = 1.22)
        why = (f"the finite-plate criterion{eq} estimates that Zener's infinite plate may be off by "
               f"up to {_percent(err)} (relative) for the {what} plate (lambda = {lam:.4g}, "
               f"beta = {beta:.3g}); {SAFETY:g} x that is {'<=' if holds else '>'} rtol "
               f"{rtol:g}")
    return Verdict(holds, err, tuple(supports), why)
