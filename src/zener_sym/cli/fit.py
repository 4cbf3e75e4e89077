"""``zener-sym fit``: the dissipative constant A of viscoelastic grains from measured (v0, e).

    zener-sym fit --data drops.csv --sphere glass --radius 1mm --wall steel --plot fit.png

The CSV has a speed column with its unit in the header (``v0_m_s``, ``v0 [cm/s]``), a column
``e`` and optionally ``sigma_e``; ``#`` lines are comments.
"""
from __future__ import annotations

import argparse
import sys

from ..scene.calibrate import fit_dissipation, read_measurements
from ..scene.materials import Material
from ..scene.scaling import sphere_mass
from ..scene.units import si_value
from ._types import Out, Subparsers
from .scene import _material, _plot_path, add_sphere_arguments

__all__ = ["add_parser", "run"]


def _mass(text: str | None, radius: float, material: Material, which: str) -> float:
    if text is None:
        return sphere_mass(radius, material.rho)
    return _kg(text, which)


def _kg(text: str, which: str) -> float:
    """A mass with its unit: kg or g (e.g. '10g', '0.01kg')."""
    t = text.strip().lower().replace(" ", "")
    for unit, f in (("kg", 1.0), ("mg", 1e-6), ("g", 1e-3)):
        if t.endswith(unit):
            try:
                value = float(t[: -len(unit)]) * f
            except ValueError:
                break
            if not 0.0 < value < float("inf"):
                raise ValueError(f"{which} must be finite and > 0, got {text!r}")
            return value
    raise ValueError(f"{which} {text}: give a number with a unit, e.g. 10g or 0.01kg")


def run(args: argparse.Namespace, out: Out = print) -> int:
    """``zener-sym fit``: read the CSV, fit A, print the fit (and ``--plot`` it); 0, or 2 with
    one line on stderr for bad input."""
    try:
        plot = None if args.plot is None else _plot_path(args.plot)
        data = read_measurements(args.data)
        sphere = _material(args.sphere, "sphere", None)
        radius = si_value(args.radius, "length", "--radius")
        mass = _mass(args.mass, radius, sphere, "--mass")
        # a second sphere, or a wall; neither: a rigid wall (fit_dissipation's defaults, None)
        radius2: float | None = None
        mass2: float | None = None
        sphere2: Material | None = None
        wall: Material | None = None
        if any(x is not None for x in (args.sphere2, args.radius2, args.mass2)):
            if args.wall is not None:
                raise ValueError("give either --wall or a second sphere (--sphere2, --radius2), "
                                 "not both")
            sphere2 = _material(args.sphere2 or args.sphere, "sphere2", None)
            radius2 = si_value(args.radius2 or args.radius, "length", "--radius2")
            mass2 = _mass(args.mass2, radius2, sphere2, "--mass2")
        elif args.wall is not None and args.wall.lower() != "rigid":
            wall = _material(args.wall, "wall", None)
        fit = fit_dissipation(sphere, radius, mass, v0=data.v0, e=data.e, sigma=data.sigma,
                              sphere2=sphere2, radius2=radius2, mass2=mass2, wall=wall,
                              contact_end=args.contact_end)
    except ValueError as exc:
        print(f"zener-sym fit: error: {exc}", file=sys.stderr)
        return 2
    out(f"# {args.data}: speeds read in {data.unit}, shown in m/s")
    out(str(fit))
    if plot:
        try:
            fit.plot(plot, title=args.title, data_label=args.data_label)
        except ImportError as exc:
            print(f"zener-sym fit: error: --plot: {exc}", file=sys.stderr)
            return 2
        out(f"plot: {plot}")
    return 0


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("fit", help="fit the dissipative constant A of viscoelastic grains to "
                       "measured (v0, e) pairs from a CSV file")
    p.add_argument("--data", required=True, metavar="FILE.csv",
                   help="CSV with a speed column and its unit (v0_m_s, 'v0 [cm/s]'), a column e "
                        "and optionally sigma_e; '#' lines are comments")
    add_sphere_arguments(p, second=True, example="9GPa,0.33,917kg/m^3")
    p.add_argument("--mass", default=None,
                   help="sphere mass with a unit (g, kg); default from the radius and density")
    p.add_argument("--wall", default=None,
                   help="the flat wall's material (as --sphere), or 'rigid' (default)")
    p.add_argument("--mass2", default=None, help="second sphere's mass (default from density)")
    p.add_argument("--contact-end", dest="contact_end", default="force",
                   choices=("force", "delta"),
                   help="end of contact: force-free (grains, default) or delta = 0")
    p.add_argument("--plot", default=None, metavar="OUT.png",
                   help="write the chart (png, pdf or svg; needs matplotlib)")
    p.add_argument("--title", default=None, help="title of the chart")
    p.add_argument("--data-label", dest="data_label", default="measured",
                   help="legend entry of the points (default 'measured')")
    p.set_defaults(func=run)
