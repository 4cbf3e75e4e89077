"""Quantities with units: ``"1mm"``, ``"2 m/s"``, ``"73GPa"``, for scenes and the command line.

A number (``int`` or ``float``) is taken in SI units; a string must carry its unit, so ``"2.5"``
is refused rather than guessed (is it metres or millimetres?). Only the units listed in
``UNITS`` are accepted, so a typo (``"1 mn"``) is an error, not a silent factor of 1000. Values
outside ``PLAUSIBLE`` (a 1e300 m sphere, a 250 Pa yield strength) are refused with the range.
"""
from __future__ import annotations

import math
import numbers
import re

__all__ = ["UNITS", "EXAMPLES", "PLAUSIBLE", "parse_quantity", "si_value"]

#: Accepted units per kind, as factors to SI.
UNITS = {
    "length": {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "micron": 1e-6,
               "nm": 1e-9, "in": 0.0254},
    "speed": {"m/s": 1.0, "cm/s": 1e-2, "mm/s": 1e-3, "km/h": 1.0 / 3.6},
    "pressure": {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "GPa": 1e9},
    "density": {"kg/m^3": 1.0, "kg/m3": 1.0, "g/cm^3": 1e3, "g/cm3": 1e3},
    "time": {"s": 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6, "ns": 1e-9},
}

#: One example per kind, for messages.
EXAMPLES = {"length": "1mm or 0.001m", "speed": "3m/s or 300cm/s", "pressure": "210GPa or 250MPa",
            "density": "7850kg/m^3 or 7.85g/cm^3", "time": "25us or 2.5e-5s"}

#: Ranges (SI) outside which a value is taken for a slip, not a scene: what the scaling and the
#: solvers are meant for, with wide margins.
PLAUSIBLE = {"length": (1e-9, 1e3), "speed": (1e-6, 1e4), "pressure": (1e3, 1e13),
             "density": (1.0, 1e5), "time": (1e-12, 1e3)}

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?inf|nan)\s*(.*?)\s*$",
                     re.IGNORECASE)


def parse_quantity(text: str | float, kind: str, field: str | None = None) -> float:
    """The value of ``text`` (number and optional unit of ``kind``) in SI units.

    Parameters
    ----------
    text : str or float
        E.g. ``"1mm"``, ``"0.5 mm"``, ``"1m/s"``, ``"73 GPa"``, ``"2500 kg/m^3"``, or a number
        (taken in SI units). A string without a unit is refused.
    kind : {"length", "speed", "pressure", "density", "time"}
    field : str, optional
        Name used in error messages.

    Raises
    ------
    ValueError
        For an unknown kind or unit, or text that is not a number with a unit.

    Examples
    --------
    >>> parse_quantity("2.5 mm", "length")
    0.0025
    >>> parse_quantity("2.5", "length", "radius")
    Traceback (most recent call last):
    ...
    ValueError: radius 2.5: give a unit, e.g. 1mm or 0.001m
    """
    if kind not in UNITS:
        raise ValueError(f"unknown kind of quantity {kind!r}; allowed: {', '.join(UNITS)}")
    name = field or kind
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        return float(text)
    if not isinstance(text, str):
        raise ValueError(f"{name}: expected a number with a unit, got {text!r}")
    m = _NUMBER.match(text)
    if not m:
        raise ValueError(f"{name}: {text!r} is not a number with a unit; e.g. "
                         f"'1{next(iter(UNITS[kind]))}'")
    value, unit = float(m.group(1)), m.group(2)
    if not unit:
        raise ValueError(f"{name} {text.strip()}: give a unit, e.g. {EXAMPLES[kind]}")
    table = UNITS[kind]
    factor = table.get(unit)
    if factor is None:
        # "gpa", "MM": accept a different case only when it matches exactly one unit
        hits = [v for k, v in table.items() if k.lower() == unit.lower()]
        factor = hits[0] if len(hits) == 1 else None
    if factor is None:
        raise ValueError(f"{name}: unknown {kind} unit {unit!r} in {text!r}; allowed: "
                         f"{', '.join(table)}")
    # NaN and infinities pass through: the scene's validation names the field and its range
    return value * factor


def si_value(value: float | str, kind: str, field: str, *, positive: bool = True) -> float:
    """``value`` (a number in SI units or a string with a unit) in SI, checked.

    Parameters
    ----------
    value : float or str
        E.g. ``0.0025`` or ``"2.5 mm"``.
    kind : {"length", "speed", "pressure", "density", "time"}
    field : str
        Name used in error messages (e.g. ``"radius"`` or ``"--radius"``).
    positive : bool
        Require a finite value > 0 inside ``PLAUSIBLE[kind]`` (default).

    Returns
    -------
    float

    Raises
    ------
    ValueError
        Saying what was wrong and what is allowed.

    Examples
    --------
    >>> si_value("3 m/s", "speed", "v0")
    3.0
    >>> si_value(1e300, "length", "radius")
    Traceback (most recent call last):
    ...
    ValueError: radius = 1e+300 m is outside the plausible range; allowed: 1e-09 m <= radius <= 1000 m
    """
    unit = next(iter(UNITS[kind]))
    lo, hi = PLAUSIBLE[kind]
    allowed = f"allowed: {lo:g} {unit} <= {field} <= {hi:g} {unit}"
    if isinstance(value, bool) or not isinstance(value, (numbers.Real, str)):
        raise ValueError(f"{field} must be a number in {unit} or a string with a unit "
                         f"(e.g. {EXAMPLES[kind]}), got {value!r}; {allowed}")
    v = parse_quantity(value if isinstance(value, str) else float(value), kind, field)
    if positive:
        if not math.isfinite(v) or v <= 0:
            raise ValueError(f"{field} must be finite and > 0, got {value!r}; {allowed}")
        if not lo <= v <= hi:
            raise ValueError(f"{field} = {v:g} {unit} is outside the plausible range; {allowed}")
    return v
