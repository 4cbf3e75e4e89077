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


@dataclass(frozen=True)
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

    def __post_init__(self):
        object.__setattr__(self, "E", si_value(self.E, "pressure", "E"))
        object.__setattr__(self, "rho", si_value(self.rho, "density", "rho"))
        nu = self.nu
        if isinstance(nu, bool) or not isinstance(nu, numbers.Real) or not math.isfinite(nu) \
                or not -1.0 < float(nu) < 0.5:
            raise ValueError(f"nu (Poisson's ratio) must be a finite real with -1 < nu < 0.5, "
                             f"got {nu!r}")
        object.__setattr__(self, "nu", float(nu))
        if self.yield_strength is not None:
            object.__setattr__(self, "yield_strength", si_value(
                self.yield_strength, "pressure", "yield_strength"))

    @property
    def plane_modulus(self) -> float:
        """E / (1 - nu^2) [Pa], the modulus that enters Hertz contact and plate bending."""
        return self.E / (1.0 - self.nu**2)

    def with_yield(self, yield_strength: float) -> "Material":
        """A copy with the given yield strength [Pa]."""
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


def get_material(name_or_material) -> Material:
    """A ``Material`` unchanged, or the preset of that name; ValueError listing presets otherwise."""
    if isinstance(name_or_material, Material):
        return name_or_material
    if isinstance(name_or_material, str) and name_or_material.lower() in PRESETS:
        return PRESETS[name_or_material.lower()]
    raise ValueError(f"unknown material {name_or_material!r}; give a zener_sym.Material or one "
                     f"of the presets: {', '.join(PRESETS)}")
