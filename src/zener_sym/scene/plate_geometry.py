"""The bounded plate of a scene: its size, support and impact point, checked, and in Zener's scales.

A scene's plate is infinite (Zener), a circle of radius b struck at its centre, or an a x b
rectangle struck at (x, y) (from one corner; default the centre). In Zener's scales
(:mod:`zener_sym.scene.scaling`; t_0 = T) the bounded plate adds to lambda the plate-size
parameter

    beta = T sqrt(D / (rho_2 H)) / L^2,   L = b (circle) or sqrt(a b) (rectangle),

the support, the aspect a/b and the impact point as fractions (x/a, y/b), and, for the simply
supported circle, Poisson's ratio of the plate (its static compliance has (3 + nu)/(1 + nu)):
the options of the ``finite-plate`` model (:mod:`zener_sym.models.finite_plate`, whose module
docstring has the dimensionless equations). beta is the ratio of the contact's time scale to the
time a flexural wave of that time scale needs to cross the plate: small beta, large plate.
"""
from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ..models.finite_plate import SHAPES, SUPPORTS, check_loss, check_support
from .units import si_value

__all__ = ["SUPPORTS", "SHAPES", "PlateGeometry", "plate_geometry", "check_support",
           "check_loss"]



@dataclass(frozen=True)
class PlateGeometry:
    """A bounded plate's shape, size, support and impact point in SI units.

    Attributes
    ----------
    shape : {"circle", "rectangle"}
    size : tuple of float
        (b,) for the circle (radius, m), (a, b) for the rectangle (sides, m).
    support : str or None
        One of :data:`SUPPORTS`, or None when the scene did not say (Zener's answer then,
        with the criterion's warning judged for every support).
    impact_at : tuple of float
        The impact point (x, y) in metres from the rectangle's corner; (0, 0), the centre, for
        the circle.
    """

    shape: str
    size: tuple[float, ...]
    support: str | None
    impact_at: tuple[float, float]

    @property
    def L(self) -> float:
        """The plate's length scale [m]: the circle's radius b, or sqrt(a b) for the rectangle."""
        return self.size[0] if self.shape == "circle" else math.sqrt(self.size[0] * self.size[1])

    @property
    def aspect(self) -> float:
        """a / b of the rectangle (1 for the circle)."""
        return 1.0 if self.shape == "circle" else self.size[0] / self.size[1]

    @property
    def impact(self) -> tuple[float, float]:
        """The impact point as fractions (x/a, y/b) of the rectangle ((0.5, 0.5) for the
        circle, struck at its centre)."""
        if self.shape == "circle":
            return (0.5, 0.5)
        return (self.impact_at[0] / self.size[0], self.impact_at[1] / self.size[1])

    @property
    def edge_distance(self) -> float:
        """The distance from the impact point to the nearest edge [m]."""
        if self.shape == "circle":
            return self.size[0]
        (x, y), (a, b) = self.impact_at, self.size
        return min(x, a - x, y, b - y)

    def beta(self, T: float, D: float, rho: float, H: float) -> float:
        """beta = T sqrt(D / (rho H)) / L^2 (module docstring).

        Parameters
        ----------
        T : float
            Zener's time scale t_0 [s].
        D, rho, H : float
            The plate's flexural rigidity [N m], density [kg/m^3] and thickness [m].

        Returns
        -------
        float
        """
        return T * math.sqrt(D / (rho * H)) / self.L**2

    def describe(self) -> str:
        """One line for tables: shape, size, support and impact point."""
        mm = [f"{s * 1e3:.6g}" for s in self.size]
        sup = self.support or "support not given"
        if self.shape == "circle":
            return f"circle, radius {mm[0]} mm, {sup}, struck at its centre"
        x, y = (f"{v * 1e3:.6g}" for v in self.impact_at)
        return f"rectangle {mm[0]} x {mm[1]} mm, {sup}, struck at ({x}, {y}) mm"

    def options(self, nu: float) -> dict[str, Any]:
        """The ``finite-plate`` model's geometry options (beta aside): shape, support, aspect,
        impact, nu."""
        return {"shape": self.shape, "support": self.support, "aspect": self.aspect,
                "impact": self.impact, "nu": nu}


def _pair(value: object, field: str) -> tuple[float, float]:
    """Two lengths (numbers in metres or strings with a unit), checked."""
    if isinstance(value, str) or not isinstance(value, Sequence) or len(value) != 2:
        raise ValueError(f"{field} must be a pair of lengths such as ('100 mm', '50 mm'), "
                         f"got {value!r}")
    return (si_value(value[0], "length", f"{field}[0]"),
            si_value(value[1], "length", f"{field}[1]"))


def _impact_point(value: object, a: float, b: float) -> tuple[float, float]:
    if value is None:
        return (a / 2.0, b / 2.0)
    if isinstance(value, str) or not isinstance(value, Sequence) or len(value) != 2:
        raise ValueError(f"impact_at must be a pair of lengths (x, y) from the plate's corner "
                         f"such as ('30 mm', '25 mm'), got {value!r}")
    x = si_value(value[0], "length", "impact_at[0]", positive=False)
    y = si_value(value[1], "length", "impact_at[1]", positive=False)
    if not (math.isfinite(x) and math.isfinite(y) and 0.0 < x < a and 0.0 < y < b):
        raise ValueError(f"impact point ({x:g}, {y:g}) m is not inside the {a:g} x {b:g} m "
                         f"plate; allowed: 0 < x < {a:g} m and 0 < y < {b:g} m (from a corner)")
    return (x, y)


def plate_geometry(sphere_radius: float, plate_radius: object = None, plate_size: object = None,
                   impact_at: object = None, support: object = None) -> PlateGeometry | None:
    """The scene's bounded plate from its inputs, checked (None for Zener's infinite plate).

    Parameters
    ----------
    sphere_radius : float
        The sphere's radius R [m] (the plate must be larger than the ball).
    plate_radius : float or str, optional
        A circle's radius (struck at its centre).
    plate_size : pair of float or str, optional
        A rectangle's sides (a, b).
    impact_at : pair of float or str, optional
        The rectangle's impact point (x, y) from a corner (default the centre).
    support : str, optional
        One of :data:`SUPPORTS` (the rectangle: ``"simply-supported"``); None: not given.

    Returns
    -------
    PlateGeometry or None

    Raises
    ------
    ValueError
        For both a radius and a size, a support or impact point without a plate, an unknown
        support, a length without a unit, an impact point not inside the plate, or a plate
        not larger than the ball.

    Examples
    --------
    >>> g = plate_geometry(2.5e-3, plate_radius="50 mm", support="clamped")
    >>> g.shape, g.L, g.impact
    ('circle', 0.05, (0.5, 0.5))
    >>> g = plate_geometry(5e-3, plate_size=("60 mm", "40 mm"), impact_at=("15 mm", "20 mm"),
    ...                    support="simply-supported")
    >>> round(g.aspect, 6), g.impact
    (1.5, (0.25, 0.5))
    >>> plate_geometry(5e-3, plate_radius="4 mm")
    Traceback (most recent call last):
    ...
    ValueError: plate_radius must exceed the sphere radius 0.005 m, got 0.004 m
    """
    if plate_radius is not None and plate_size is not None:
        raise ValueError("give plate_radius (a circle) or plate_size (a rectangle), not both")
    if plate_radius is None and plate_size is None:
        for name, v in (("support", support), ("impact_at", impact_at)):
            if v is not None:
                raise ValueError(f"{name} needs a bounded plate: give plate_radius (a circle) "
                                 "or plate_size (a rectangle)")
        return None
    if plate_radius is not None:
        if impact_at is not None:
            raise ValueError("impact_at is for a rectangle (plate_size); a circular plate is "
                             "struck at its centre")
        b = si_value(plate_radius, "length", "plate_radius")  # type: ignore[arg-type]
        if b <= sphere_radius:
            raise ValueError(f"plate_radius must exceed the sphere radius {sphere_radius:g} m, "
                             f"got {b:g} m")
        sup = None if support is None else check_support(support, "circle")
        return PlateGeometry("circle", (b,), sup, (0.0, 0.0))
    a, b = _pair(plate_size, "plate_size")
    if min(a, b) <= 2.0 * sphere_radius:
        raise ValueError(f"plate_size ({a:g}, {b:g}) m: both sides must exceed the sphere's "
                         f"diameter {2.0 * sphere_radius:g} m")
    sup = None if support is None else check_support(support, "rectangle")
    return PlateGeometry("rectangle", (a, b), sup, _impact_point(impact_at, a, b))
