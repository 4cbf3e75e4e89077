"""The shared body of the table commands (``exact-table``, ``ham1-table``): build Chebyshev
tables offline into ``generated/``, or rebuild them in memory and compare.

The node values come from floating-point solvers, so ``--check`` compares numerically (the
builder's ``CHECK_RTOL``) and checks the inputs hash, instead of comparing bytes.
"""
from __future__ import annotations

import importlib
import sys
import time
from types import ModuleType

from ..codegen import generated_dir, inputs_hash
from ._checkout import CheckoutError, source_root


def run_table(builder: ModuleType, module: str, command: str, what: str,
              check: bool = False) -> int:
    """Build (or with ``check``, verify) the table of ``builder``.

    Parameters
    ----------
    builder : module
        Has ``BUILDER`` (its file's name), ``build_tables()``, ``compare(stored, fresh)``,
        ``input_files()`` (hashed by ``codegen.inputs_hash``), ``render(tables)`` and
        ``CHECK_RTOL`` (a table builder module: its ``BUILDER``'s methods).
    module : str
        The generated module holding the committed table (``builder.compare`` reads its
        names).
    command : str
        The command's name, for messages (``"exact-table"``).
    what : str
        What the inputs hash covers, for the stale message.
    """
    if not check:
        try:  # writing goes into the checkout's generated/
            source_root(f"zener-sym {command}")
        except CheckoutError as exc:
            print(f"zener-sym {command}: error: {exc}", file=sys.stderr)
            return 2
    t0 = time.perf_counter()
    tables = builder.build_tables()
    dt = time.perf_counter() - t0
    path = generated_dir() / builder.BUILDER.file.filename
    if not check:
        path.write_text(builder.render(tables))
        print(f"wrote {path} (built in {dt:.1f} s)")
        return 0
    try:
        mod = importlib.import_module(module)
    except ImportError:
        print(f"{path} is missing; run `zener-sym {command}`")
        return 1
    problems = builder.compare(vars(mod), tables)
    digest = inputs_hash(builder.input_files())
    if mod.INPUTS_HASH != digest:
        problems.append(f"inputs hash {mod.INPUTS_HASH} != current {digest} "
                        f"({what} changed)")
    for p in problems:
        print(p)
    if problems:
        print(f"{path} is STALE; run `zener-sym {command}` and commit it")
        return 1
    print(f"{path} is up to date (rebuilt in {dt:.1f} s, agrees within "
          f"{builder.CHECK_RTOL:g})")
    return 0
