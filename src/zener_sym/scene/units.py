"""Parsing of quantities with units for the command line: ``"1mm"``, ``"2 m/s"``, ``"73GPa"``.

A bare number is taken in SI units. Only the units listed in ``UNITS`` are accepted, so a typo
(``"1 mn"``) is an error, not a silent factor of 1000.
"""
from __future__ import annotations

import re

__all__ = ["UNITS", "parse_quantity"]

#: Accepted units per kind, as factors to SI.
UNITS = {
    "length": {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "micron": 1e-6,
               "nm": 1e-9, "in": 0.0254},
    "speed": {"m/s": 1.0, "cm/s": 1e-2, "mm/s": 1e-3, "km/h": 1.0 / 3.6},
    "pressure": {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "GPa": 1e9},
    "density": {"kg/m^3": 1.0, "kg/m3": 1.0, "g/cm^3": 1e3, "g/cm3": 1e3},
}

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?inf|nan)\s*(.*?)\s*$",
                     re.IGNORECASE)


def parse_quantity(text, kind: str, field: str | None = None) -> float:
    """The value of ``text`` (number and optional unit of ``kind``) in SI units.

    Parameters
    ----------
    text : str or float
        E.g. ``"1mm"``, ``"0.5 mm"``, ``"1m/s"``, ``"73 GPa"``, ``"2500 kg/m^3"``, or a number (SI).
    kind : {"length", "speed", "pressure", "density"}
    field : str, optional
        Name used in error messages.

    Raises
    ------
    ValueError
        For an unknown kind or unit, or text that is not a number with a unit.
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
        return value
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
