"""Isotropic elastic materials for scenes: ``Material(E, nu, rho)`` and a few sourced presets.

Values are numbers in SI units (Pa, -, kg/m^3) or strings with a unit ("210 GPa"). ``yield_strength`` (Pa, optional) enables the yield
warning of a scene.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

from .units import si_value

__all__ = ["Material", "STEEL", "GLASS", "ALUMINIUM", "TABLE1_SPHERE", "TABLE1_PLATE", "PRESETS",
           "get_material"]


@dataclass(frozen=True, init=False)
class Material:
    """An isotropic linear-elastic material.

    Parameters
    ----------
    E : float or str
        Young's modulus: Pa, or a string with a unit (``"210 GPa"``).
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (the range in which the bulk and shear moduli are positive).
    rho : float or str
        Density: kg/m^3, or a string with a unit (``"7.85 g/cm^3"``).
    name : str, optional
        Label used in tables.
    source : str, optional
        Where the values come from.
    yield_strength : float or str, optional
        Uniaxial yield stress Y (Pa, or with a unit); when given, scenes warn at the onset of
        yield.

    Raises
    ------
    ValueError
        For a string without a unit, or a value outside
        ``zener_sym.scene.units.PLAUSIBLE``, or nu outside (-1, 0.5).

    Examples
    --------
    >>> from zener_sym import Material
    >>> Material("210 GPa", 0.3, "7850 kg/m^3", name="steel").plane_modulus / 1e9
    230.76923076923077
    """

    E: float
    nu: float
    rho: float
    name: str = "custom"
    source: str = "user"
    yield_strength: float | None = None

    # An __init__ of our own (not the dataclass's): E, rho and the yield strength accept a
    # string with a unit, and the stored fields are floats in SI units.
    def __init__(self, E: float | str, nu: float, rho: float | str, name: str = "custom",
                 source: str = "user", yield_strength: float | str | None = None) -> None:
        nu_in: object = nu  # checked at run time, whatever a caller passed
        if isinstance(nu_in, bool) or not isinstance(nu_in, numbers.Real) \
                or not math.isfinite(nu_in) or not -1.0 < float(nu_in) < 0.5:
            raise ValueError(f"nu (Poisson's ratio) must be a finite real with -1 < nu < 0.5, "
                             f"got {nu!r}")
        object.__setattr__(self, "E", si_value(E, "pressure", "E"))
        object.__setattr__(self, "nu", float(nu_in))
        object.__setattr__(self, "rho", si_value(rho, "density", "rho"))
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "source", source)
        object.__setattr__(self, "yield_strength", None if yield_strength is None else
                           si_value(yield_strength, "pressure", "yield_strength"))

    @property
    def plane_modulus(self) -> float:
        """E / (1 - nu^2) [Pa], the modulus that enters Hertz contact and plate bending.

        Returns
        -------
        float

        Examples
        --------
        >>> import zener_sym as zs
        >>> f"{zs.GLASS.plane_modulus / 1e9:.4g} GPa"
        '76.37 GPa'
        """
        return self.E / (1.0 - self.nu**2)

    def with_yield(self, yield_strength: float | str) -> Material:
        """A copy with the given yield strength (enables the scene's yield warning).

        Parameters
        ----------
        yield_strength : float or str
            Uniaxial yield stress Y: Pa, or a string with a unit (``"250 MPa"``).

        Returns
        -------
        Material
            The same material with ``yield_strength`` set.

        Raises
        ------
        ValueError
            For a string without a unit or a value outside the plausible range.

        Examples
        --------
        >>> import zener_sym as zs
        >>> soft = zs.STEEL.with_yield("250 MPa")
        >>> soft.yield_strength, soft.E == zs.STEEL.E, zs.STEEL.yield_strength
        (250000000.0, True, None)
        """
        return Material(self.E, self.nu, self.rho, self.name, self.source, yield_strength)


# Handbook values: typical, not any particular alloy's certificate. Yield strengths are left out
# on purpose (they vary by a factor of several with grade and treatment); give them per scene.
STEEL = Material(210e9, 0.30, 7850.0, "steel",
                 "typical handbook value for steel (e.g. Ashby & Jones, Engineering "
                 "Materials 1: E ~ 210 GPa, rho ~ 7800-7900 kg/m^3)")
GLASS = Material(73e9, 0.21, 2500.0, "glass",
                 "soda-lime glass; the same values as the paper's Table 1 glass "
                 "(73 GPa, 0.21, 2500 kg/m^3)")
ALUMINIUM = Material(70e9, 0.33, 2700.0, "aluminium",
                     "typical handbook value for aluminium alloys (e.g. Ashby & Jones, "
                     "Engineering Materials 1: E ~ 69-70 GPa, rho ~ 2700 kg/m^3)")
# The paper's FEM pair, exactly as printed in Table 1. The gamma-Al2O3 values (12.23 GPa,
# 879 kg/m^3) are far below bulk alumina (~380 GPa, ~3900 kg/m^3); we keep them as printed.
TABLE1_SPHERE = Material(12.23e9, 0.21, 879.0, "table1-sphere",
                         "paper, Appendix, Table 1: sphere 'gamma-Al2O3' as printed")
TABLE1_PLATE = Material(73e9, 0.21, 2500.0, "table1-plate",
                        "paper, Appendix, Table 1: plate 'glass' as printed")

#: Preset materials by name (the CLI's --sphere/--plate choices).
PRESETS = {m.name: m for m in (STEEL, GLASS, ALUMINIUM, TABLE1_SPHERE, TABLE1_PLATE)}
PRESETS["aluminum"] = ALUMINIUM


def get_material(name_or_material: Material | str) -> Material:
    """A ``Material`` unchanged, or the preset of that name; ValueError listing presets otherwise."""
    if isinstance(name_or_material, Material):
        return name_or_material
    if isinstance(name_or_material, str) and name_or_material.lower() in PRESETS:
        return PRESETS[name_or_material.lower()]
    raise ValueError(f"unknown material {name_or_material!r}; give a zener_sym.Material or one "
                     f"of the presets: {', '.join(PRESETS)}")
