"""``zener-sym generate [--check]``: emit generated/ and FORMULAS.md from the derivation, or
verify that both are fresh. Deprecated and hidden from ``--help``: ``zener-sym regen kernels
formulas`` does the same (:mod:`._deprecated`)."""
from __future__ import annotations

import sys
from pathlib import Path

from .. import codegen
from ._checkout import CheckoutError, source_root
from ._deprecated import deprecated, hidden_parser
from ._types import Subparsers


def _formulas(check: bool, root: Path) -> int:
    """FORMULAS.md (the derived equations, at the checkout root) travels with generated/."""
    from ..derivation import formulas, registry

    d = registry.derive(checks=False)
    if check:
        fresh, diff = formulas.check(d, root)
        if not fresh:
            sys.stdout.write(diff)
            print("FORMULAS.md is STALE; run `zener-sym generate` and commit the result")
            return 1
        print(f"{formulas.formulas_path(root)} is up to date")
        return 0
    print(f"wrote {formulas.write(d, root)}")
    return 0


def run(check: bool = False) -> int:
    """Emit generated/ and FORMULAS.md (or with ``check``, compare them): 0 fresh or
    written, 1 stale, 2 without a source checkout."""
    try:  # before any work
        root = source_root(f"zener-sym generate{' --check' if check else ''}")
    except CheckoutError as exc:
        print(f"zener-sym generate: error: {exc}", file=sys.stderr)
        return 2
    folder = root / "generated"
    rendered = codegen.render_all()
    if check:
        d = codegen.diff(rendered, folder)
        status = 0
        if d:
            sys.stdout.write(d)
            print(f"generated/ is STALE ({folder}); run `zener-sym generate` and commit the result")
            status = 1
        else:
            print(f"{folder} is up to date ({len(rendered)} files checked)")
        return max(status, _formulas(True, root))
    changed = codegen.write(rendered, folder)
    print(f"wrote {len(changed)} of {len(rendered)} files into {folder}: {', '.join(changed) or '-'}")
    return _formulas(False, root)


def add_parser(sub: Subparsers) -> None:
    p = hidden_parser(sub, "generate", "regen kernels formulas")
    p.add_argument("--check", action="store_true",
                   help="regenerate in memory and fail with a unified diff if generated/ is stale")
    p.set_defaults(func=deprecated(
        "generate", lambda args: f"regen{' --check' if args.check else ''} kernels formulas",
        lambda args: run(check=args.check)))
