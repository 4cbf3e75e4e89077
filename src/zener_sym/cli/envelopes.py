"""``zener-sym envelopes [--check]``: measure every model's error envelope against exact and
write the table that :func:`zener_sym.select_model` reads (measured by
:mod:`zener_sym.bench.envelopes`, read by :mod:`zener_sym.scene.envelopes`). Deprecated and
hidden from ``--help``: the artefact ``envelopes`` of ``zener-sym regen`` does the same
(:mod:`._deprecated`)."""
from __future__ import annotations

import argparse

from ..bench.envelopes import build
from ..scene.envelopes import compare, load, save
from ._checkout import check_result
from ._deprecated import deprecated, hidden_parser
from ._types import Subparsers


def _run(args: argparse.Namespace) -> int:
    new = build()
    if args.check:
        return check_result(compare(load(), new, decades=args.decades),
                            "envelope table is stale (run 'zener-sym regen envelopes'):",
                            f"envelope table up to date ({len(new['models'])} models)")
    where = save(new)
    print(f"wrote {where} ({len(new['models'])} models: {', '.join(new['models'])})")
    return 0


def add_parser(sub: Subparsers) -> None:
    p = hidden_parser(sub, "envelopes", "regen envelopes")
    p.add_argument("--check", action="store_true",
                   help="rebuild in memory; exit 1 if the committed table is stale")
    p.add_argument("--decades", type=float, default=0.5,
                   help="tolerance of --check in decades of relative error (default 0.5)")
    p.set_defaults(func=deprecated(
        "envelopes", lambda args: f"regen{' --check' if args.check else ''} envelopes", _run))
