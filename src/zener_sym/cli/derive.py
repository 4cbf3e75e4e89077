"""``zener-sym derive [--markdown] [--check]``: re-derive the HAM solution, checking every step.

Prints one line per step (equation, PASS/FAIL, time, claim, method, result). ``--markdown``
writes FORMULAS.md at the root of the source checkout; ``--check`` fails with a unified diff
when the committed FORMULAS.md is stale. Imports the derivation only when run (offline code).
"""
from __future__ import annotations

import sys
import time

from ._checkout import CheckoutError, source_root
from ._types import Out, Subparsers

__all__ = ["add_parser", "run"]


def run(markdown: bool = False, check: bool = False, out: Out = print) -> int:
    """Re-derive and print every step; 0 when all pass (and FORMULAS.md is fresh with
    ``check``), 1 otherwise, 2 without the source checkout ``markdown``/``check`` need."""
    from ..derivation import formulas, registry
    from ..derivation.steps import format_step

    root = None
    if check or markdown:
        try:  # before the derivation's minute of work
            root = source_root(f"zener-sym derive --{'check' if check else 'markdown'}")
        except CheckoutError as exc:
            print(f"zener-sym derive: error: {exc}", file=sys.stderr)
            return 2

    t0 = time.perf_counter()
    d = registry.run(checks=True, echo=lambda line: out(line))
    out(f"derivation: {d.summary()}")
    status = 0 if d.ok else 1
    if not d.ok:
        out("derivation FAILED: " + "; ".join(format_step(s) for s in d.steps if not s.passed))
    if check:
        fresh, diff = formulas.check(d, root)
        if fresh:
            out(f"{formulas.formulas_path(root)} is up to date")
        else:
            out(diff)
            out(f"{formulas.FILENAME} is stale: run `zener-sym derive --markdown`")
            status = 1
    if markdown:
        if not d.ok:
            out(f"not writing {formulas.FILENAME}: the derivation has failed steps")
            return 1
        out(f"wrote {formulas.write(d, root)}")
    out(f"total {time.perf_counter() - t0:.1f} s")
    return status


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("derive", help="re-derive the HAM solution with SymPy, checking every step")
    p.add_argument("--markdown", action="store_true",
                   help="write the derived equations to FORMULAS.md at the source checkout's root")
    p.add_argument("--check", action="store_true",
                   help="fail with a diff if the committed FORMULAS.md is stale")
    p.set_defaults(func=lambda args: run(markdown=args.markdown, check=args.check))
