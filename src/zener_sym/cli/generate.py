"""``zener-sym generate [--check]``: emit generated/ and FORMULAS.md from the derivation, or
verify that both are fresh."""
from __future__ import annotations

import sys

from .. import codegen


def _formulas(check: bool) -> int:
    """FORMULAS.md (the derived equations, at the checkout root) travels with generated/."""
    from ..derivation import formulas, registry

    try:
        formulas.repo_root()
    except Exception as exc:  # a plain (non-editable) install has no FORMULAS.md to keep fresh
        print(f"FORMULAS.md not checked: {exc}")
        return 0
    d = registry.derive(checks=False)
    if check:
        fresh, diff = formulas.check(d)
        if not fresh:
            sys.stdout.write(diff)
            print("FORMULAS.md is STALE; run `zener-sym generate` and commit the result")
            return 1
        print("FORMULAS.md is up to date")
        return 0
    print(f"wrote {formulas.write(d)}")
    return 0


def run(check: bool = False) -> int:
    folder = codegen.generated_dir()
    rendered = codegen.render_all()
    if check:
        d = codegen.diff(rendered, folder)
        status = 0
        if d:
            sys.stdout.write(d)
            print(f"generated/ is STALE ({folder}); run `zener-sym generate` and commit the result")
            status = 1
        else:
            print(f"generated/ is up to date ({len(rendered)} files checked)")
        return max(status, _formulas(check=True))
    if not (folder.parent / "pyproject.toml").exists():
        print(f"refusing to write into {folder}: not a source checkout (no pyproject.toml beside "
              "it); use an editable install (pip install -e .)", file=sys.stderr)
        return 2
    changed = codegen.write(rendered, folder)
    print(f"wrote {len(changed)} of {len(rendered)} files into {folder}: {', '.join(changed) or '-'}")
    return _formulas(check=False)


def add_parser(sub) -> None:
    p = sub.add_parser("generate", help="emit numpy/mpmath kernels into generated/ from the derivation")
    p.add_argument("--check", action="store_true",
                   help="regenerate in memory and fail with a unified diff if generated/ is stale")
    p.set_defaults(func=lambda args: run(check=args.check))
