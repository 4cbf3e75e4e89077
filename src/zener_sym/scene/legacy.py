"""The grain functions' old call forms, kept for one release with a ``DeprecationWarning``.

The grain functions now name a sphere's inputs as :class:`~zener_sym.Scene` does (``sphere``
for its material, ``radius``, and ``mass``; ``sphere2``, ``radius2``, ``mass2`` for a second
sphere), take them first, in that order, and take the measured arrays by keyword only, speed
first (``v0=..., e=...``), so that a swapped pair of arrays cannot pass silently. Calls in the
old forms (``R1, m1, material1``, and ``dissipation_for(e, v0, ...)`` against
``fit_dissipation(v0, e, ...)``) still work: :func:`accepts_old_call` recognises them,
translates them and warns.

An old call is told apart from a new one by what stands where: the new first argument is a
material (a :class:`~zener_sym.Material` or a preset name) and the new third one a mass (a
number), while the old forms put a radius, a speed or an e first and a material third, or use
an old keyword. A new-form call with too many positional arguments is left to fail as such.
"""
from __future__ import annotations

import functools
import warnings
from collections.abc import Callable, Mapping, Sequence
from typing import Any, ParamSpec, TypeVar, cast

from .materials import Material

__all__ = ["OLD_NAMES", "is_old_call", "translate", "accepts_old_call"]

#: Old keyword -> new keyword of the grain functions.
OLD_NAMES = {"R1": "radius", "m1": "mass", "material1": "sphere", "R2": "radius2",
             "m2": "mass2", "material2": "sphere2"}

_P = ParamSpec("_P")
_R = TypeVar("_R")


def _is_material(x: object) -> bool:
    return isinstance(x, (Material, str))


def is_old_call(args: Sequence[object], kwargs: Mapping[str, object]) -> bool:
    """Whether ``(args, kwargs)`` is a call in an old form (module docstring).

    Examples
    --------
    >>> is_old_call(("glass", "1 mm", 1e-5), {})       # sphere, radius, mass
    False
    >>> is_old_call(("1 mm", 1e-5, "glass"), {})       # R1, m1, material1
    True
    >>> is_old_call((0.8, 1.0, "1 mm", 1e-5, "glass"), {})   # e, v0, R1, m1, material1
    True
    """
    if any(k in OLD_NAMES for k in kwargs):
        return True
    if args and not _is_material(args[0]):
        return True
    return len(args) >= 3 and _is_material(args[2])


def translate(func: str, old_order: Sequence[str], new_form: str, args: Sequence[object],
              kwargs: Mapping[str, object]) -> dict[str, object]:
    """The keyword arguments of the new form for an old call, with a ``DeprecationWarning``.

    Parameters
    ----------
    func : str
        The function's name, for messages.
    old_order : sequence of str
        The old positional parameters, in order.
    new_form : str
        The new call form, for the warning.
    args, kwargs
        The old call's arguments.

    Returns
    -------
    dict
        Every argument by its new keyword.

    Raises
    ------
    TypeError
        For more positional arguments than the old form took, or one argument given twice.
    """
    if len(args) > len(old_order):
        raise TypeError(f"{func}() takes at most {len(old_order)} positional arguments in its "
                        f"old form ({', '.join(old_order)}), got {len(args)}; use {new_form}")
    named: dict[str, object] = dict(zip(old_order, args))
    for k, v in kwargs.items():
        if k in named:
            raise TypeError(f"{func}() got multiple values for argument {k!r}")
        named[k] = v
    out: dict[str, object] = {}
    for k, v in named.items():
        new = OLD_NAMES.get(k, k)
        if new in out:
            raise TypeError(f"{func}() got {k!r} and {new!r}, the same argument by its old and "
                            f"its new name; give {new!r} only")
        out[new] = v
    old = ", ".join(old_order)
    warnings.warn(f"{func}({old}, ...) is deprecated (the old names R1, m1, material1, R2, m2, "
                  f"material2 are now radius, mass, sphere, radius2, mass2, sphere2, and the "
                  f"measured arrays are keyword-only): use {new_form}; the old form will be "
                  f"removed in the next release", DeprecationWarning, stacklevel=3)
    return out


def accepts_old_call(old_order: Sequence[str],
                     new_form: str) -> Callable[[Callable[_P, _R]], Callable[_P, _R]]:
    """Decorate a grain function so that calls in its old form still work, with a warning.

    Parameters
    ----------
    old_order : sequence of str
        The function's old positional parameters, in order (old names).
    new_form : str
        The new call form, for the warning.

    Returns
    -------
    callable
        The decorator; the function keeps its signature (``inspect.signature`` and type
        checkers see the new form only).
    """
    def decorate(func: Callable[_P, _R]) -> Callable[_P, _R]:
        @functools.wraps(func)
        def call(*args: Any, **kwargs: Any) -> Any:
            if is_old_call(args, kwargs):
                new = translate(func.__name__, old_order, new_form, args, kwargs)
                return cast("Callable[..., _R]", func)(**new)
            return func(*args, **kwargs)
        return cast("Callable[_P, _R]", call)
    return decorate
