"""``python -m zener_sym.derivation [PART]``: run the derivation, or one part of it.

With a part's name (e.g. ``first_order``), the parts before it run unchecked and only that part's
steps are checked; without one, every part runs checked. Lives above the registry, so that the
parts never import the registry that lists them.
"""
from __future__ import annotations

import sys

from . import registry


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    names = [part.__module__.rsplit(".", 1)[-1] for part in registry.PARTS]
    if len(argv) > 1 or (argv and argv[0] not in names):
        print(f"usage: python -m zener_sym.derivation [{'|'.join(names)}]", file=sys.stderr)
        return 2
    d = registry.run(checks=True, echo=print, only=argv[0] if argv else None)
    print(f"{'OK' if d.ok else 'FAILED'}: {d.summary()}")
    return 0 if d.ok else 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
