"""Error messages that start with a name ("exact.mp: ...") name something that exists now: a
function or class of the module that raises, a module of the package (optionally with one of its
functions), or a registered model. A message naming a module by an old name (``exact_mp``, the
module before it became ``exact/mp.py``) fails here.
"""
from __future__ import annotations

import ast
import importlib
import re
from pathlib import Path

import zener_sym
from zener_sym.models import REGISTRY

SRC = Path(zener_sym.__file__).parent
_PREFIX = re.compile(r"^([A-Za-z_][A-Za-z0-9_.]*): ")


def _message_prefixes(tree: ast.AST) -> list[tuple[int, str]]:
    out = []
    for n in ast.walk(tree):
        if not (isinstance(n, ast.Raise) and isinstance(n.exc, ast.Call) and n.exc.args):
            continue
        a = n.exc.args[0]
        if isinstance(a, ast.JoinedStr) and a.values:
            a = a.values[0]
        if isinstance(a, ast.Constant) and isinstance(a.value, str):
            m = _PREFIX.match(a.value)
            if m:
                out.append((n.lineno, m.group(1)))
    return out


def _exists(name: str, defined: set[str], package: str = "") -> bool:
    """Whether ``name`` is defined in the raising module, a model, or a module of the package
    (from the top, or from the raising module's own subpackage ``package``)."""
    if name in defined or name in REGISTRY:
        return True
    head, _, attr = name.rpartition(".")
    bases = ["zener_sym"] + ([f"zener_sym.{package}"] if package else [])
    for module, attr in ((name, None), (head, attr)):
        if not module:
            continue
        for base in bases:
            try:
                mod = importlib.import_module(f"{base}.{module}")
            except ImportError:
                continue
            if attr is None or hasattr(mod, attr):
                return True
    return False


def test_messages_name_what_exists():
    stale = []
    for path in sorted(SRC.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        defined = {n.name for n in ast.walk(tree)
                   if isinstance(n, (ast.FunctionDef, ast.ClassDef, ast.AsyncFunctionDef))}
        # derivation/ and generated/ sit inside the package in an installed copy (not in src/)
        package = ".".join(path.relative_to(SRC).parts[:-1])
        stale += [f"{path.relative_to(SRC)}:{line}: {name!r}"
                  for line, name in _message_prefixes(tree)
                  if not _exists(name, defined, package)]
    assert not stale, "messages name what does not exist:\n" + "\n".join(stale)


def test_the_check_sees_an_old_module_name():
    tree = ast.parse('raise RuntimeError(f"exact_mp: did not converge at {lam}")')
    assert _message_prefixes(tree) == [(1, "exact_mp")]
    assert not _exists("exact_mp", set()) and _exists("exact.mp", set())
