"""``zener-sym generate [--check]``: emit generated/ from the derivation, or verify it is fresh."""
from __future__ import annotations

import sys

from . import codegen


def run(check: bool = False) -> int:
    folder = codegen.generated_dir()
    rendered = codegen.render_all()
    if check:
        d = codegen.diff(rendered, folder)
        if d:
            sys.stdout.write(d)
            print(f"generated/ is STALE ({folder}); run `zener-sym generate` and commit the result")
            return 1
        print(f"generated/ is up to date ({len(rendered)} files checked)")
        return 0
    if not (folder.parent / "pyproject.toml").exists():
        print(f"refusing to write into {folder}: not a source checkout (no pyproject.toml beside "
              "it); use an editable install (pip install -e .)", file=sys.stderr)
        return 2
    changed = codegen.write(rendered, folder)
    print(f"wrote {len(changed)} of {len(rendered)} files into {folder}: {', '.join(changed) or '-'}")
    return 0


def add_parser(sub) -> None:
    p = sub.add_parser("generate", help="emit numpy/mpmath kernels into generated/ from the derivation")
    p.add_argument("--check", action="store_true",
                   help="regenerate in memory and fail with a unified diff if generated/ is stale")
    p.set_defaults(func=lambda args: run(check=args.check))
