"""The references the numeric claims are measured against, and how a printed bound is read.

The reference is the exact Zener ODE (10): the exact model's tables (``zs.summary(model="exact")``,
accurate to about 1e-10) and, for delta_m up to lambda = 100, the audit's own integration of the
compression phase (:func:`delta_m_exact`), not the paper's FEM: the claims are about
approximations of Eq. (10), so the ODE is the right yardstick.
"""
from __future__ import annotations

import functools
from typing import TYPE_CHECKING

import numpy as np
from scipy.integrate import solve_ivp

from zener_sym.typing import FloatArray, RealArrayLike, RealLike

from . import printed

if TYPE_CHECKING:  # the facade is imported lazily (it imports this layer's modules lazily too)
    from zener_sym.api import Summary

__all__ = ["exact_summary", "delta_m_exact", "printed_number", "printed_value", "bound_readings",
           "worst_text", "ham_field", "pct"]


@functools.lru_cache(maxsize=None)
def exact_summary(lams: tuple[float, ...]) -> Summary:
    """``zs.summary`` of the exact model at the lambdas ``lams`` (cached: several claims share grids)."""
    import zener_sym as zs  # noqa: PLC0415 (the facade imports the audit's layer lazily)
    out: Summary = zs.summary(np.array(lams), model="exact")
    return out


def ham_field(model: str, field: str, lams: RealArrayLike) -> FloatArray:
    """One summary field (``F_m``, ``impulse``, ``tau_d``, ...) of a registered model."""
    import zener_sym as zs  # noqa: PLC0415
    values: FloatArray = getattr(zs.summary(lams, model=model), field)
    return values


def delta_m_exact(lam_value: RealLike, rtol: float = 1e-11) -> float:
    """delta_m of Eq. (10) by integrating the compression phase only (DOP853, cheap at large lambda).

    Eq. (10) integrated once with Eq. (47): delta' + lambda delta^(3/2) = 1 - I-bar = w and
    w' = -delta^(3/2), from delta = 0, w = 1 to the end of compression, delta' = 0. This route is
    the audit's own: it shares no code with the exact model (its tables are the other route).
    """
    lv = float(lam_value)

    def rhs(t: float, y: FloatArray) -> list[float]:
        d = max(y[0], 0.0)  # guard: a trial step may dip below 0
        F = d * np.sqrt(d)
        return [y[1] - lv * F, -F]

    def v_zero(t: float, y: FloatArray) -> float:
        d = max(y[0], 0.0)
        speed: float = y[1] - lv * d * np.sqrt(d)  # delta' (Eq. 10 integrated once)
        return speed

    # solve_ivp reads these two attributes of an event function; mypy knows no such attributes
    v_zero.terminal, v_zero.direction = True, -1  # type: ignore[attr-defined]
    sol = solve_ivp(rhs, (0.0, 100.0), [0.0, 1.0], method="DOP853", rtol=rtol, atol=1e-15,
                    events=v_zero)
    if sol.status != 1:
        raise RuntimeError(f"no end of compression at lambda = {lv}: {sol.message}")
    return float(sol.y_events[0][0][0])


def printed_number(claim_name: str, i: int = 0) -> str:
    """The i-th printed number of claim ``claim:<claim_name>``, as printed (a string)."""
    return printed.numbers(printed.by_id("claim:" + claim_name))[i]


def printed_value(claim_name: str, i: int = 0) -> float:
    """The i-th printed number of claim ``claim:<claim_name>`` as a float."""
    return float(printed_number(claim_name, i))


def pct(x: float, dec: int) -> str:
    """A fraction as a percentage with ``dec`` decimals."""
    return f"{100 * x:.{dec}f}%"


def worst_text(worst: float, at: float) -> str:
    """The decisive number of an error claim: 'largest relative error 2.905% at lambda = 2.2'."""
    return f"largest relative error {100 * worst:.3f}% at $\\lambda = {at:.3g}$"


def bound_readings(worst: float, bound_text: str) -> tuple[bool, str]:
    """Both readings of a printed bound "less than <bound_text>" (a fraction such as '0.0290').

    Strict: the largest error, measured to more digits than printed, is below the bound (this
    reading gives the verdict). To the printed digits: the largest error rounded to the printed
    number of decimals equals the printed figure (the paper's figure is then its measurement).
    Returns (strict verdict, one sentence with both readings).
    """
    dec = max(len(bound_text.split(".")[1]) - 2, 0) if "." in bound_text else 0  # decimals in percent
    bound = float(bound_text)
    strict = worst < bound
    shown = pct(worst, dec)
    agrees = round(100 * worst, dec) == round(100 * bound, dec)
    below = round(100 * worst, dec) <= round(100 * bound, dec)
    text = (f"Read strictly, {pct(worst, dec + 2)} is {'below' if strict else 'not below'} "
            f"{pct(bound, dec)}; to the printed digits it is {shown}, "
            + ("the printed figure itself" if agrees else
               "within the printed figure" if below else "above the printed figure"))
    return strict, text
