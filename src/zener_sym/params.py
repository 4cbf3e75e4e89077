"""Validation of the dimensionless inputs: the inelasticity parameter and the time grid.

Every public entry point funnels its inputs through here so that bad input fails early with a
message that says what was wrong and what is allowed, never as a NaN or a numpy traceback.
"""
from __future__ import annotations

import numbers

import numpy as np

from .typing import FloatArray, RealArrayLike

__all__ = ["as_lambda", "as_tau", "check_lambda_bound", "bound_text"]


def _as_float_array(value: object, name: str) -> FloatArray:
    if isinstance(value, (str, bytes)) or value is None:
        raise ValueError(f"{name} must be a real number or an array of real numbers, got {value!r}")
    if isinstance(value, numbers.Complex) and not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be real, got the complex value {value!r}")
    try:
        arr = np.asarray(value)  # object: whatever the user passed, checked here
    except Exception as exc:  # ragged lists and the like
        raise ValueError(f"{name} must be a real number or an array of real numbers: {exc}") from None
    if arr.dtype == object or arr.dtype.kind not in "biuf":
        if arr.dtype.kind == "c":
            raise ValueError(f"{name} must be real, got complex values")
        raise ValueError(
            f"{name} must be a real number or an array of real numbers, got {value!r} "
            f"(dtype {arr.dtype})"
        )
    return arr.astype(float)


def as_lambda(lam: RealArrayLike, *, upper: float | None = None,
              model: str | None = None) -> FloatArray:
    """Validate Zener's inelasticity parameter lambda (Eq. 11) and return it as a float array.

    Parameters
    ----------
    lam : float or array_like
        Inelasticity parameter(s). Must be finite and >= 0.
    upper : float, optional
        Exclusive upper bound of the model's validity, if any.
    model : str, optional
        Model name, used in the error message.

    Raises
    ------
    ValueError
        If lam is not real, is NaN, infinite, negative, or not below ``upper``.
    """
    arr = _as_float_array(lam, "lambda")
    if arr.size == 0:
        raise ValueError("lambda is empty: give at least one value")
    bad = ~np.isfinite(arr)
    if bad.any():
        raise ValueError(
            f"lambda must be finite, got {arr[bad].ravel()[0].item()!r}; allowed: 0 <= lambda < infinity"
        )
    if (arr < 0).any():
        raise ValueError(
            f"lambda must be >= 0 (0 is a rigid half-space), got {arr[arr < 0].ravel()[0].item()!r}"
        )
    if upper is not None:
        check_lambda_bound(arr, upper, model or "this model")
    return arr


def bound_text(upper: float) -> str:
    """The range ``0 <= lambda < upper`` as the check applies it, with digits that round-trip.

    A bound stored as the float just above a round number (``np.nextafter(1000, inf)``, an
    inclusive 1000) reads ``0 <= lambda <= 1000``; any other bound prints its shortest exact
    decimal, so a value typed from the message is judged the way the message says.
    """
    upper = float(upper)
    below = float(np.nextafter(upper, -np.inf))
    if float(f"{below:.12g}") == below and float(f"{upper:.12g}") != upper:
        return f"0 <= lambda <= {below:.12g}"
    return f"0 <= lambda < {upper!r}"


def check_lambda_bound(arr: FloatArray, upper: float, model: str, reason: str = "") -> None:
    """Raise ValueError if any lambda reaches ``upper`` (an exclusive bound of ``model``)."""
    if (arr >= upper).any():
        extra = f" ({reason})" if reason else ""
        raise ValueError(
            f"lambda = {arr[arr >= upper].ravel()[0].item()!r} is outside the validity of model "
            f"{model!r}: allowed {bound_text(upper)}{extra}"
        )


def as_tau(tau: RealArrayLike) -> FloatArray:
    """Validate dimensionless time(s) tau = t / T (Eq. 9); must be finite and >= 0."""
    arr = _as_float_array(tau, "tau")
    bad = ~np.isfinite(arr)
    if bad.any():
        raise ValueError(f"tau must be finite, got {arr[bad].ravel()[0].item()!r}; allowed: tau >= 0")
    if (arr < 0).any():
        raise ValueError(
            f"tau must be >= 0 (contact starts at tau = 0), got {arr[arr < 0].ravel()[0].item()!r}"
        )
    return arr
