"""``zener-sym compare``: every model side by side for one lambda or one scene
(:func:`zener_sym.compare`)."""
from __future__ import annotations

import argparse
import sys

from ..scene.compare import compare
from ._types import Out, Subparsers
from .scene import add_scene_arguments, scene_from_args

__all__ = ["add_parser", "run"]


def _names(text: str | None) -> list[str] | None:
    return None if text is None else [x.strip() for x in text.split(",") if x.strip()]


def run(args: argparse.Namespace, out: Out = print) -> int:
    """``zener-sym compare``: the table of :func:`zener_sym.compare` for ``--lam`` or a scene;
    0, or 2 with one line on stderr for bad input."""
    try:
        if args.lam is not None:
            if any(getattr(args, k) is not None for k in ("sphere", "plate", "radius",
                                                           "thickness", "v0", "drop_height")):
                raise ValueError("give either --lam or a scene (--sphere, --plate, ...), not both")
            what = args.lam
        else:
            what = scene_from_args(args)
        c = compare(what, models=_names(args.models), quantities=_names(args.quantities))
        if args.csv:
            c.to_csv(args.csv)
    except ValueError as exc:
        print(f"zener-sym compare: error: {exc}", file=sys.stderr)
        return 2
    out(c.to_markdown())
    if args.csv:
        out(f"csv: {args.csv}")
    return 0


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("compare", help="every model side by side for one lambda or one scene, "
                       "with its relative error against exact")
    p.add_argument("--lam", type=float, default=None, help="Zener's lambda (instead of a scene)")
    add_scene_arguments(p, required=False)
    p.add_argument("--models", default=None, help="comma-separated model names (default: all "
                   "that accept this lambda)")
    p.add_argument("--quantities", default=None, help="comma-separated fields (default: all)")
    p.add_argument("--csv", default=None, metavar="FILE", help="also write the table as CSV")
    p.set_defaults(func=run)
