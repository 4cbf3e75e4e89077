"""The ``series`` model: Eq. (10) at both ends of lambda, from the derived series and asymptotics.

Small lambda (``zener_sym.derivation.lambda_series``): the perturbation hierarchy gives

    plate end (delta = 0):      e = sum_k c_k lambda^k,       tau_d likewise (17 terms);
    grains' force-free end:     e = sum_j a_j lambda^(j/2),   tau_d likewise (20 terms),

every coefficient verified to >= 20 digits by two routes (``data/lambda_series.json``, written by
``python -m zener_sym.derivation.lambda_series --write``). Large lambda, plate end only:

    e = K_delta lambda^-5 (exponentially small remainder),
    tau_d = lambda (5 ln lambda + C_delta) + 3 lambda^(-2/3)   (remainder ~ lambda^(-7/3)).

(The grains' large-lambda limit e lambda^(5/3) -> 2/3 converges too slowly to be useful here.)
impulse = 1 + e in both readings and xi = 1 - e^2 (from the series of 1 - e, without cancellation).

The option ``rtol`` (1e-3, 1e-6 default, or 1e-9) picks crossovers at which every field is within
``rtol`` (relative) of the exact model, measured on a fine grid (tests/test_lambda_series.py);
lambda between the small-lambda range and the large-lambda range is refused, as is the large
range with ``contact_end="force"``.
"""
from __future__ import annotations

import functools
import json
from importlib import resources
from typing import TypedDict

import numpy as np
import numpy.typing as npt

from ..exact.force_end import check_contact_end
from ..exact.solver import LAMBDA_MAX
from ..numerics.taylor import horner
from ..typing import FloatArray, RealArrayLike
from .base import FieldValues, Model, register

__all__ = ["SeriesModel", "CROSSOVERS", "RTOLS", "coefficients"]

#: rtol -> contact_end -> (largest lambda of the small-lambda series, smallest lambda of the
#: large-lambda asymptotics or None). Chosen where the largest relative error of e, tau_d, impulse
#: and xi against the exact model (rtol 1e-13), on a grid of step 0.001, is below rtol/2; the
#: large side from the size of the first neglected term of tau_d, 0.96 lambda^(-7/3).
CROSSOVERS: dict[float, dict[str, tuple[float, float | None]]] = {
    1e-3: {"delta": (0.58, 6.0), "force": (0.36, None)},
    1e-6: {"delta": (0.39, 40.0), "force": (0.16, None)},
    1e-9: {"delta": (0.26, 300.0), "force": (0.075, None)},
}
RTOLS = tuple(CROSSOVERS)


class Coefficients(TypedDict):
    """The series' committed coefficients (``data/lambda_series.json``)."""

    #: name (``e_delta``, ``tau_d_force``, ...) -> coefficients, constant term first
    small: dict[str, FloatArray]
    #: name (``K_delta``, ``C_delta``, ``tau_d_corr``) -> constant of the large-lambda forms
    large: dict[str, float]


def coefficients() -> Coefficients:
    """The committed coefficients, read once.

    Every call shares the same arrays, so they are read-only (a caller that wrote to one would
    change every later answer); the dicts are the caller's own.

    Returns
    -------
    Coefficients
        ``small[name]``: read-only array of float, constant term first; ``large[name]``: float.

    Examples
    --------
    >>> from zener_sym.models.series import coefficients
    >>> c = coefficients()["small"]["e_delta"]
    >>> float(c[0]), c.flags.writeable
    (1.0, False)
    """
    small, large = _read()
    return {"small": dict(small), "large": dict(large)}


@functools.cache
def _read() -> tuple[dict[str, FloatArray], dict[str, float]]:
    raw = json.loads((resources.files("zener_sym") / "data" / "lambda_series.json").read_text("utf-8"))
    small = {n: np.array([float(c) for c in v["c"]]) for n, v in raw["small"].items()}
    for arr in small.values():
        arr.flags.writeable = False
    return small, {n: float(v) for n, v in raw["large"].items()}


def _poly(c: FloatArray, x: FloatArray) -> FloatArray:
    """sum_{k>=1} c_k x^k (the constant term left out, so 1 - e keeps its relative accuracy)."""
    out: FloatArray = horner(c[1:], x) * x
    return out


class SeriesModel(Model):
    """The model ``"series"``: small-lambda series and large-lambda asymptotics of e and tau_d."""

    name = "series"
    description = ("Small-lambda series (perturbation hierarchy) and large-lambda asymptotics of "
                   "e and tau_d; refuses the middle where neither meets rtol")
    summary_fields = ("lam", "e", "tau_d", "impulse", "xi")
    history_fields = ()
    lam_bound = np.nextafter(LAMBDA_MAX, np.inf)
    bound_reason = "the range of the exact model it is measured against"
    options = ("contact_end", "rtol")

    def valid(self, lam: RealArrayLike) -> npt.NDArray[np.bool_]:
        """Where the default options (plate end, rtol 1e-6) answer: both ends, not the middle.

        Parameters
        ----------
        lam : float or array_like
            Lambda values.

        Returns
        -------
        numpy.ndarray of bool
            Of the shape of ``lam``.
        """
        x: FloatArray = np.asarray(lam, dtype=float)
        lo, hi = CROSSOVERS[1e-6]["delta"]
        assert hi is not None and self.lam_bound is not None  # the plate end has both ranges
        ok: npt.NDArray[np.bool_] = (x <= lo) | ((x >= hi) & (x < self.lam_bound))
        return ok

    def _summary(self, lam: FloatArray, contact_end: str = "delta",
                 rtol: float = 1e-6) -> FieldValues:
        end = check_contact_end(contact_end)
        if rtol not in CROSSOVERS:
            raise ValueError(f"rtol={rtol!r} is not one of the measured tolerances of model 'series'; "
                             f"allowed: {', '.join(f'{r:g}' for r in RTOLS)}")
        lo, hi = CROSSOVERS[rtol][end]
        small = lam <= lo
        large = np.zeros_like(small) if hi is None else lam >= hi
        bad = ~(small | large)
        if bad.any():
            x0 = float(lam[bad].ravel()[0])
            where = (f"[0, {lo:g}] (small-lambda series) or [{hi:g}, {LAMBDA_MAX:g}] (large-lambda "
                     f"asymptotics)" if hi is not None else
                     f"[0, {lo:g}] (small-lambda series; no large-lambda form for contact_end='force')")
            raise ValueError(f"lambda = {x0!r} is outside the range where model 'series' meets "
                             f"rtol={rtol:g} with contact_end={end!r}: allowed {where}; use model "
                             f"'exact' there")
        C = coefficients()
        e, xi, tau_d = (np.empty(lam.shape) for _ in range(3))
        if small.any():
            x = lam[small] if end == "delta" else np.sqrt(lam[small])
            ce, ct = C["small"][f"e_{end}"], C["small"][f"tau_d_{end}"]
            d = _poly(ce, x)  # e - 1, kept apart so that xi = 1 - e^2 = -d (2 + d) does not cancel
            e[small], xi[small] = 1.0 + d, -d * (2.0 + d)
            tau_d[small] = ct[0] + _poly(ct, x)
        if large.any():
            x = lam[large]
            L = C["large"]
            e[large] = L["K_delta"] * x**-5.0
            xi[large] = 1.0 - e[large] ** 2
            tau_d[large] = x * (5.0 * np.log(x) + L["C_delta"]) + L["tau_d_corr"] * x ** (-2.0 / 3.0)
        return {"lam": lam.copy(), "e": e, "tau_d": tau_d, "impulse": 1.0 + e, "xi": xi}


register(SeriesModel())
