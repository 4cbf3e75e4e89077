"""``zener-sym scene``: a sphere, a plate and a speed in SI units -> a table (and a plot)."""
from __future__ import annotations

import sys
import warnings

import numpy as np

from ..scene.checks import ZenerWarning
from ..scene.materials import PRESETS, Material
from ..scene.units import parse_quantity

__all__ = ["add_parser", "run", "plot_force"]


def _number(text: str, field: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{field}: {text!r} is not a number") from None


def _material(spec: str, which: str, yield_text: str | None) -> Material:
    """A preset name, or 'E,nu,rho' with units (e.g. '210GPa,0.3,7850')."""
    if spec.lower() in PRESETS:
        mat = PRESETS[spec.lower()]
    else:
        parts = [p.strip() for p in spec.split(",")]
        if len(parts) != 3:
            raise ValueError(f"--{which}: {spec!r} is neither a preset ({', '.join(PRESETS)}) "
                             f"nor 'E,nu,rho' such as '210GPa,0.3,7850kg/m^3'")
        E = parse_quantity(parts[0], "pressure", f"{which} E")
        nu = _number(parts[1], f"{which} nu")
        rho = parse_quantity(parts[2], "density", f"{which} rho")
        mat = Material(E, nu, rho, name=f"{which}")
    if yield_text is not None:
        mat = mat.with_yield(parse_quantity(yield_text, "pressure", f"{which} yield"))
    return mat


def plot_force(result, out: str, n: int = 400) -> str:
    """Plot F(t) of ``result``'s model against exact into ``out`` (needs matplotlib)."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise SystemExit("--plot needs matplotlib: pip install 'zener-sym[plot]'") from None
    exact = result.scene.result(model="exact", warn=False)
    t_end = 1.1 * max(result.contact_duration, exact.contact_duration)
    t = np.linspace(0.0, t_end, n)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(t * 1e6, exact.force(t), "k-", lw=2, label="exact")
    if result.model != "exact":
        ax.plot(t * 1e6, result.force(t), "r--", lw=1.5, label=result.model)
    ax.set_xlabel("t [us]")
    ax.set_ylabel("F [N]")
    ax.set_title(f"lambda = {result.lam:.4g}, model {result.model}")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def run(args, out=print) -> int:
    from ..scene.scene import Scene

    try:
        sphere = _material(args.sphere, "sphere", args.sphere_yield)
        plate = _material(args.plate, "plate", args.plate_yield)
        scene = Scene(
            sphere, plate,
            radius=parse_quantity(args.radius, "length", "radius"),
            thickness=parse_quantity(args.thickness, "length", "thickness"),
            v0=parse_quantity(args.v0, "speed", "v0"),
            plate_radius=(None if args.plate_radius is None else
                          parse_quantity(args.plate_radius, "length", "plate_radius")),
        )
        with warnings.catch_warnings():
            # listed in the table; not printed twice
            warnings.simplefilter("ignore", ZenerWarning)
            res = scene.result(model=args.model, rtol=args.rtol, quantity=args.quantity)
    except ValueError as exc:
        print(f"zener-sym scene: error: {exc}", file=sys.stderr)
        return 2
    out(res.to_markdown() if args.markdown else str(res))
    if args.plot:
        out(f"plot: {plot_force(res, args.plot)}")
    return 0


def add_parser(sub) -> None:
    p = sub.add_parser("scene", help="a sphere hitting a plate, in SI units: cheapest model "
                       "meeting --rtol, dimensional results and validity warnings")
    p.add_argument("--sphere", required=True,
                   help=f"sphere material: {', '.join(PRESETS)} or 'E,nu,rho' (210GPa,0.3,7850)")
    p.add_argument("--plate", required=True, help="plate material (as --sphere)")
    p.add_argument("--radius", required=True, help="sphere radius, e.g. 1mm")
    p.add_argument("--thickness", required=True, help="plate thickness, e.g. 2mm")
    p.add_argument("--v0", required=True, help="impact speed, e.g. 1m/s")
    p.add_argument("--rtol", type=float, default=1e-3,
                   help="relative accuracy the chosen model must meet (default 1e-3)")
    p.add_argument("--quantity", default="all",
                   help="quantity the accuracy is for (default all reported quantities)")
    p.add_argument("--model", default=None, help="force a model instead of choosing one")
    p.add_argument("--plate-radius", default=None, help="radius of a finite plate, e.g. 150mm")
    p.add_argument("--sphere-yield", default=None, help="sphere yield strength, e.g. 1.5GPa")
    p.add_argument("--plate-yield", default=None, help="plate yield strength, e.g. 250MPa")
    p.add_argument("--markdown", action="store_true", help="print the table as markdown")
    p.add_argument("--plot", default=None, metavar="OUT.png",
                   help="plot F(t) of the chosen model against exact (needs matplotlib)")
    p.set_defaults(func=run)
