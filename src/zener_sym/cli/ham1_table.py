"""``zener-sym ham1-table [--check]``: build the ham1 summary's Chebyshev tables, or verify them.

The node values come from floating-point root finding and quadrature, so ``--check`` compares
numerically (``ham.table_build.CHECK_RTOL``) and checks the inputs hash, instead of comparing
bytes.
"""
from __future__ import annotations

import importlib
import sys
import time

from ..ham import table_build as b


def _stored() -> dict:
    mod = importlib.import_module("zener_sym.generated.ham1_table")
    return {"LAM_CONT": mod.LAM_CONT, "PIECES": mod.PIECES, "COEF": mod.COEF,
            "hash": mod.INPUTS_HASH}


def run(check: bool = False) -> int:
    t0 = time.perf_counter()
    tables = b.build_tables()
    dt = time.perf_counter() - t0
    path = b.table_path()
    if check:
        try:
            stored = _stored()
        except ImportError:
            print(f"{path} is missing; run `zener-sym ham1-table`")
            return 1
        problems = b.compare(stored, tables)
        if stored["hash"] != b.inputs_hash():
            problems.append(f"inputs hash {stored['hash']} != current {b.inputs_hash()} (the "
                            "builder, the ham1 series or the generated ham1 kernels changed)")
        for p in problems:
            print(p)
        if problems:
            print(f"ham1 table is STALE ({path}); run `zener-sym ham1-table` and commit it")
            return 1
        print(f"ham1 table is up to date (rebuilt in {dt:.1f} s, agrees within "
              f"{b.CHECK_RTOL:g})")
        return 0
    if not (path.parent.parent / "pyproject.toml").exists():
        print(f"refusing to write into {path.parent}: not a source checkout", file=sys.stderr)
        return 2
    path.write_text(b.render(tables))
    print(f"wrote {path} (built in {dt:.1f} s)")
    return 0


def add_parser(sub) -> None:
    p = sub.add_parser("ham1-table", help="build the Chebyshev tables of the ham1 summary")
    p.add_argument("--check", action="store_true",
                   help="rebuild in memory and fail if the committed table differs numerically")
    p.set_defaults(func=lambda args: run(check=args.check))
