"""``zener-sym table``: a lookup table of e, tau_d, ... over a lambda grid (for DEM codes).

    zener-sym table --quantity e,tau_d --lam 0:5:1001 --contact-end force --csv > e_tau.csv
"""
from __future__ import annotations

import argparse
import sys

from ..scene.lookup import lookup_csv, lookup_table
from ._types import Subparsers


def _run(args: argparse.Namespace) -> int:
    try:
        t = lookup_table(args.quantity, args.lam, contact_end=args.contact_end, model=args.model)
    except ValueError as exc:
        print(f"zener-sym table: error: {exc}", file=sys.stderr)
        return 2
    if args.csv:
        sys.stdout.write(lookup_csv(t))
        return 0
    names = list(t)
    print(f"# model {args.model!r}, contact_end {args.contact_end!r} "
          f"({'force-free end, grains' if args.contact_end == 'force' else 'delta = 0, plate'})")
    print("  ".join(f"{n:>22}" for n in names))
    for row in zip(*(t[n] for n in names)):
        print("  ".join(f"{x:22.15g}" for x in row))
    return 0


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("table", help="lookup table of summary quantities over a lambda grid "
                       "(e.g. e and tau_d for DEM codes)")
    p.add_argument("--quantity", default="e,tau_d",
                   help="comma-separated summary fields (default e,tau_d)")
    p.add_argument("--lam", default="0:5:1001",
                   help="grid start:stop:n, ends included (default 0:5:1001)")
    p.add_argument("--contact-end", dest="contact_end", default="delta", choices=("delta", "force"),
                   help="end of contact: delta = 0 (plate, default) or force-free (grains)")
    p.add_argument("--model", default="exact", help="model (default exact)")
    p.add_argument("--csv", action="store_true", help="CSV: a header line, then one row per lambda")
    p.set_defaults(func=_run)
