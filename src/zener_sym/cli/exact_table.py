"""``zener-sym exact-table [--check]``: build the fast exact model's tables, or verify them.

The tables come from a floating-point integrator, so ``--check`` compares numerically
(``table_build.CHECK_RTOL``) and checks the inputs hash, instead of comparing bytes.
"""
from __future__ import annotations

import importlib
import sys
import time

from ..exact import table_build as b


def _stored() -> dict:
    mod = importlib.import_module("zener_sym.generated.exact_table")
    return {"summary": mod.SUMMARY, "history": mod.HISTORY, "hash": mod.INPUTS_HASH}


def run(check: bool = False) -> int:
    t0 = time.perf_counter()
    tables = b.build_tables()
    dt = time.perf_counter() - t0
    path = b.table_path()
    if check:
        try:
            stored = _stored()
        except ImportError:
            print(f"{path} is missing; run `zener-sym exact-table`")
            return 1
        problems = b.compare(stored, tables)
        if stored["hash"] != b.inputs_hash():
            problems.append(f"inputs hash {stored['hash']} != current {b.inputs_hash()} (the "
                            "builder or the solver changed)")
        for p in problems:
            print(p)
        if problems:
            print(f"exact table is STALE ({path}); run `zener-sym exact-table` and commit it")
            return 1
        print(f"exact table is up to date (rebuilt in {dt:.1f} s, agrees within "
              f"{b.CHECK_RTOL:g})")
        return 0
    if not (path.parent.parent / "pyproject.toml").exists():
        print(f"refusing to write into {path.parent}: not a source checkout", file=sys.stderr)
        return 2
    path.write_text(b.render(tables))
    print(f"wrote {path} (built in {dt:.1f} s)")
    return 0


def add_parser(sub) -> None:
    p = sub.add_parser("exact-table", help="build the Chebyshev tables of the fast exact model")
    p.add_argument("--check", action="store_true",
                   help="rebuild in memory and fail if the committed table differs numerically")
    p.set_defaults(func=lambda args: run(check=args.check))
