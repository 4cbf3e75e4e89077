"""``zener-sym audit [--json] [--check]``: the paper audit as a table or JSON, or AUDIT.md checked.

``--write`` (rewrite AUDIT.md) is deprecated and hidden from ``--help``: ``zener-sym regen
audit`` does the same (:mod:`._deprecated`)."""
from __future__ import annotations

import argparse
import difflib
import json
import sys

from ..audit.markdown import audit_md_path, cached_results, markdown
from ..audit.run import summary_line
from ._checkout import CheckoutError, source_root
from ._deprecated import note
from ._types import Subparsers

__all__ = ["add_parser"]


def _run(args: argparse.Namespace) -> int:
    root = None
    if args.write:
        note("audit --write", "regen audit")
    if args.check or args.write:
        try:  # before any work: the audit takes a while
            root = source_root(f"zener-sym audit --{'check' if args.check else 'write'}")
        except CheckoutError as exc:
            print(f"zener-sym audit: error: {exc}", file=sys.stderr)
            return 2
    results = cached_results()
    if args.json:
        print(json.dumps([r.as_dict() for r in results], indent=1))
        return 0
    text = markdown(results)
    if args.check:
        path = audit_md_path(root)
        old = path.read_text() if path.exists() else ""
        if old == text:
            print(f"{path} is up to date ({summary_line(results)})")
            return 0
        sys.stdout.writelines(difflib.unified_diff(
            old.splitlines(True), text.splitlines(True), f"{path.name} (committed)",
            f"{path.name} (regenerated)"))
        print(f"\n{path.name} is stale: run `zener-sym regen audit`", file=sys.stderr)
        return 1
    if args.write:
        path = audit_md_path(root)
        path.write_text(text)
        print(f"wrote {path} ({summary_line(results)})")
        return 0
    print(text)
    return 0


def add_parser(sub: Subparsers) -> None:
    p = sub.add_parser("audit", help="check the paper's printed equations and claims")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--json", action="store_true", help="print a JSON list of the items")
    # deprecated (zener-sym regen audit): still accepted, no longer listed
    g.add_argument("--write", action="store_true", help=argparse.SUPPRESS)
    g.add_argument("--check", action="store_true", help="fail with a diff if AUDIT.md is stale")
    p.set_defaults(func=_run)
