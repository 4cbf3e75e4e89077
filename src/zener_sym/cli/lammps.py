"""``zener-sym lammps``: LAMMPS input lines for a grain contact, and the exact answers to check
them by.

    zener-sym lammps --sphere glass --radius 1mm --wall steel --e 0.8 --at 1m/s

Prints the ``pair_coeff * * hertz/material ...`` line (two spheres) or the
``fix wall/gran granular hertz/material ... zplane 0.0 NULL`` line (``--wall``), A, the damping
coefficient, and a table over the speeds: lambda, e, the contact duration, the peak force and
the largest timestep that keeps LAMMPS's e within 1e-3 of the exact one (``--json``: one JSON
object). Nothing here runs LAMMPS: the lines are for the user's deck.
"""
from __future__ import annotations

import argparse
import json
import sys

from ..scene.lammps import lammps_setup
from ._types import Out, Subparsers
from .scene import _material, add_sphere_arguments

__all__ = ["add_parser", "run"]


def _e_value(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"--e {text}: give a number in (0, 1], e.g. 0.8") from None


def run(args: argparse.Namespace, out: Out = print) -> int:
    """``zener-sym lammps``: 0, or 2 with one line on stderr for bad input."""
    try:
        if args.wall is not None and (args.sphere2 is not None or args.radius2 is not None):
            raise ValueError("give either --wall or a second sphere (--sphere2, --radius2), "
                             "not both")
        if (args.A is None) == (args.e is None):
            raise ValueError("give either --A TIME or --e E with --at SPEED")
        if args.e is not None and args.at is None:
            raise ValueError("--e needs --at, the speed it is measured at (e.g. --at 1m/s)")
        mat1 = _material(args.sphere, "sphere", None)
        mat2 = None if args.sphere2 is None else _material(args.sphere2, "sphere2", None)
        wall = None if args.wall is None else _material(args.wall, "wall", None)
        speeds = None if args.speeds is None else [t for t in args.speeds.split(",") if t.strip()]
        s = lammps_setup(mat1, args.radius, sphere2=mat2, radius2=args.radius2, wall=wall,
                         A=args.A, e=None if args.e is None else _e_value(args.e), at=args.at,
                         contact_end=args.contact_end, speeds=speeds)
    except ValueError as exc:
        print(f"zener-sym lammps: error: {exc}", file=sys.stderr)
        return 2
    if args.json:
        out(json.dumps(s.to_json(), indent=1, allow_nan=False))
    else:
        for line in s.text():
            out(line)
    return 0


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("lammps", help="LAMMPS input (pair_coeff or fix wall/gran, hertz/material "
                       "with viscoelastic damping) for a dissipative constant or a measured e, "
                       "with the exact e, contact time, peak force and timestep per speed")
    add_sphere_arguments(p, second=True, example="9GPa,0.33,917kg/m^3")
    p.add_argument("--wall", default=None, help="a flat wall's material (as --sphere) instead of "
                   "a second sphere")
    p.add_argument("--A", dest="A", default=None, metavar="TIME",
                   help="dissipative constant with a unit, e.g. 240ns")
    p.add_argument("--e", dest="e", default=None, metavar="E",
                   help="coefficient of restitution to reach at --at")
    p.add_argument("--at", default=None, metavar="SPEED",
                   help="normal impact speed of --e, with a unit (e.g. 1m/s); with --A the "
                        "centre of the default speeds (1 m/s)")
    p.add_argument("--contact-end", dest="contact_end", default="force", choices=("force", "delta"),
                   help="force: limit_damping, no attractive force (default); delta: contact "
                        "lasts to zero overlap")
    p.add_argument("--speeds", default=None, metavar="V1,V2,...",
                   help="speeds of the table, each with a unit (default: nine over a decade on "
                        "each side of --at)")
    p.add_argument("--json", action="store_true", help="one JSON object instead of text")
    p.set_defaults(func=run)
