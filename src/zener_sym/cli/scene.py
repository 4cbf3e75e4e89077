"""``zener-sym scene``: a sphere, a plate and a speed in SI units -> a table (and a plot)."""
from __future__ import annotations

import argparse
import json
import os
import sys
import warnings
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

from ..scene.checks import ZenerWarning
from ..scene.materials import PRESETS, Material
from ..scene.units import si_value
from ._types import Out, Subparsers

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..scene.scene import Scene, SceneResult

__all__ = ["add_parser", "run", "plot_force", "scene_from_args", "add_scene_arguments",
           "add_sphere_arguments"]


def _number(text: str, field: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{field}: {text!r} is not a number") from None


def _count(text: str, field: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise ValueError(f"{field}: {text!r} is not a whole number") from None


def _material(spec: str, which: str, yield_text: str | None) -> Material:
    """A preset name, or 'E,nu,rho' with units (e.g. '210GPa,0.3,7850kg/m^3')."""
    if spec.lower() in PRESETS:
        mat = PRESETS[spec.lower()]
    else:
        parts = [p.strip() for p in spec.split(",")]
        if len(parts) != 3:
            raise ValueError(f"--{which} {spec}: neither a preset ({', '.join(PRESETS)}) "
                             f"nor 'E,nu,rho' such as '210GPa,0.3,7850kg/m^3'")
        E = si_value(parts[0], "pressure", f"--{which} E")
        nu = _number(parts[1], f"--{which} nu")
        rho = si_value(parts[2], "density", f"--{which} rho")
        mat = Material(E, nu, rho, name=f"{which}")
    if yield_text is not None:
        mat = mat.with_yield(si_value(yield_text, "pressure", f"--{which}-yield"))
    return mat


def _plot_path(text: str) -> str:
    """``--plot`` checked before any work: a writable folder and a format matplotlib writes."""
    path = Path(text)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in PLOT_FORMATS:
        raise ValueError(f"--plot {text}: give a file name ending in "
                         f"{', '.join('.' + f for f in PLOT_FORMATS)}")
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir() or not os.access(folder, os.W_OK):
        raise ValueError(f"--plot {text}: folder {str(folder)!r} does not exist or is not writable")
    return text


#: Formats ``--plot`` writes (matplotlib's common raster and vector formats).
PLOT_FORMATS: tuple[str, ...] = ("png", "pdf", "svg")


def plot_force(result: SceneResult, out: str, n: int = 400) -> str:
    """Plot F(t) of ``result``'s model against exact into ``out`` (needs matplotlib), with the
    package's chart style (:func:`zener_sym.plot.force_history`)."""
    try:
        from ..plot import force_history
        from ..plot.style import pyplot, rc, save

        pyplot(headless=True)
    except ImportError as exc:
        raise SystemExit(f"--plot: {exc}") from None
    with rc() as plt:
        ax = force_history(result.scene, model=result.model, n=n)
        ax.set_title(rf"$\lambda = {result.lam:.4g}$, model {result.model}")
        p = Path(out)
        fig = cast("Figure", ax.figure)  # force_history drew on a new figure of its own
        save(fig, p.with_suffix(""), (p.suffix.lstrip(".") or "png",))
        plt.close(ax.figure)
    return out


def _lengths(text: str | None, option: str) -> tuple[str, str] | None:
    """'A,B' of an option such as --plate-size: two lengths, each with its unit."""
    if text is None:
        return None
    parts = [p.strip() for p in text.split(",")]
    if len(parts) != 2 or not all(parts):
        raise ValueError(f"{option} {text}: give two lengths with units, e.g. 100mm,50mm")
    si_value(parts[0], "length", option)  # a missing unit is named with the option
    si_value(parts[1], "length", option)
    return (parts[0], parts[1])


def scene_from_args(args: argparse.Namespace) -> Scene:
    """The Scene the scene options describe (ValueError naming the option that is wrong)."""
    from ..scene.scene import Scene

    for name in ("sphere", "plate", "radius", "thickness"):
        if getattr(args, name) is None:
            raise ValueError(f"--{name} is required (see --help)")
    sphere = _material(args.sphere, "sphere", args.sphere_yield)
    plate = _material(args.plate, "plate", args.plate_yield)
    if args.v0 is None and args.drop_height is None:
        raise ValueError("give the impact speed --v0 (e.g. 3m/s) or --drop-height (e.g. 0.5m)")
    return Scene(
        sphere, plate,
        radius=si_value(args.radius, "length", "--radius"),
        thickness=si_value(args.thickness, "length", "--thickness"),
        v0=None if args.v0 is None else si_value(args.v0, "speed", "--v0"),
        drop_height=(None if args.drop_height is None else
                     si_value(args.drop_height, "length", "--drop-height")),
        plate_radius=(None if args.plate_radius is None else
                      si_value(args.plate_radius, "length", "--plate-radius")),
        plate_size=_lengths(args.plate_size, "--plate-size"),
        impact_at=_impact_lengths(args.impact_at),
        support=args.support,
        plate_loss=0.0 if args.plate_loss is None else _number(args.plate_loss, "--plate-loss"),
    )


def _impact_lengths(text: str | None) -> tuple[str, str] | None:
    """--impact-at X,Y: lengths with units, zero allowed (refused by the scene as on the edge)."""
    if text is None:
        return None
    parts = [p.strip() for p in text.split(",")]
    if len(parts) != 2 or not all(parts):
        raise ValueError(f"--impact-at {text}: give two lengths with units from the plate's "
                         "corner, e.g. 30mm,25mm")
    for part in parts:
        si_value(part, "length", "--impact-at", positive=False)
    return (parts[0], parts[1])


def run(args: argparse.Namespace, out: Out = print) -> int:
    """``zener-sym scene``: the scene's table (and ``--plot``); 0, or 2 with one line on
    stderr for bad input."""
    try:
        plot = None if args.plot is None else _plot_path(args.plot)
        scene = scene_from_args(args)
        options: dict[str, Any] = ({} if args.n_modes is None else
                                   {"n_modes": _count(args.n_modes, "--n-modes")})
        if options and args.model != "finite-plate":
            raise ValueError("--n-modes goes with --model finite-plate")
        with warnings.catch_warnings():
            # listed in the table; not printed twice
            warnings.simplefilter("ignore", ZenerWarning)
            res = scene.result(model=args.model, rtol=args.rtol, quantity=args.quantity,
                               **options)
    except ValueError as exc:
        print(f"zener-sym scene: error: {exc}", file=sys.stderr)
        return 2
    if args.json:
        out(json.dumps(res.as_dict()))
    else:
        out(res.to_markdown() if args.markdown else str(res))
    if plot:
        out(f"plot: {plot_force(res, plot)}")
    return 0


def add_sphere_arguments(p: argparse.ArgumentParser, required: bool = True,
                         second: bool = False, example: str = "210GPa,0.3,7850kg/m^3") -> None:
    """``--sphere`` and ``--radius`` (with ``second``, ``--sphere2`` and ``--radius2`` too): a
    sphere's material and radius, under the names of every command that takes a sphere."""
    p.add_argument("--sphere", required=required,
                   help=f"sphere material: {', '.join(PRESETS)} or 'E,nu,rho' with units "
                        f"({example})")
    p.add_argument("--radius", required=required, help="sphere radius with a unit, e.g. 1mm")
    if second:
        p.add_argument("--sphere2", default=None,
                       help="second sphere's material (default --sphere)")
        p.add_argument("--radius2", default=None, help="second sphere's radius (default --radius)")


def add_scene_arguments(p: argparse.ArgumentParser, required: bool = True) -> None:
    """The options that describe a scene (shared by ``scene`` and ``compare``)."""
    add_sphere_arguments(p, required)
    p.add_argument("--plate", required=required, help="plate material (as --sphere)")
    p.add_argument("--thickness", required=required, help="plate thickness with a unit, e.g. 2mm")
    speed = p.add_mutually_exclusive_group()
    speed.add_argument("--v0", default=None, help="impact speed with a unit, e.g. 1m/s")
    speed.add_argument("--drop-height", default=None,
                       help="instead of --v0: drop height from rest, e.g. 0.5m "
                            "(v0 = sqrt(2 g h), g = 9.80665 m/s^2)")
    # checked by the Scene (one line and exit 2), not by argparse (usage text)
    p.add_argument("--plate-radius", default=None,
                   help="radius of a circular plate struck at its centre, e.g. 150mm")
    p.add_argument("--plate-size", default=None, metavar="A,B",
                   help="sides of a rectangular plate (or --plate-radius), e.g. 100mm,50mm")
    p.add_argument("--impact-at", default=None, metavar="X,Y",
                   help="impact point on the rectangle from a corner (default its centre), "
                        "e.g. 30mm,25mm")
    p.add_argument("--support", default=None, metavar="clamped|simply-supported",
                   help="how the plate is held at its edge (no default: without it the answer "
                        "is Zener's infinite plate, with a warning when that is off)")
    p.add_argument("--plate-loss", default=None,
                   help="modal loss factor of the bounded plate, 0 <= loss < 1 (default 0)")
    p.add_argument("--sphere-yield", default=None, help="sphere yield strength, e.g. 1.5GPa")
    p.add_argument("--plate-yield", default=None, help="plate yield strength, e.g. 250MPa")


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("scene", help="a sphere hitting a plate, in SI units: cheapest model "
                       "meeting --rtol, dimensional results and validity warnings")
    add_scene_arguments(p)
    p.add_argument("--rtol", type=float, default=1e-3,
                   help="relative accuracy the chosen model must meet (default 1e-3)")
    p.add_argument("--quantity", default="all",
                   help="quantity the accuracy is for (default all reported quantities)")
    p.add_argument("--model", default=None, help="force a model instead of choosing one")
    p.add_argument("--n-modes", default=None,
                   help="with --model finite-plate: the number of plate modes (default: chosen "
                        "for the accuracy)")
    p.add_argument("--markdown", action="store_true", help="print the table as markdown")
    p.add_argument("--json", action="store_true",
                   help="print one JSON object: model, lam, e, contacts (start_s, end_s, "
                        "max_force_N, impulse_N_s, speed_after_m_s), ...")
    p.add_argument("--plot", default=None, metavar="OUT.png",
                   help="plot F(t) of the chosen model against exact (png, pdf or svg; needs "
                        "matplotlib)")
    p.set_defaults(func=run)
