"""Shared test set-up.

Commands that check the repository's own files (generated/, FORMULAS.md, AUDIT.md) are pointed
at this checkout, found from this file's location, so the suite means the same whether the
package was installed editable or not (as tox and packagers install it).
"""
from __future__ import annotations

import pathlib
import shutil

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]


@pytest.fixture(autouse=True)
def _checkout_is_this_clone(monkeypatch):
    monkeypatch.setenv("ZENER_SYM_SOURCE", str(ROOT))


@pytest.fixture
def fake_tree(tmp_path, monkeypatch):
    """A minimal copy of the checkout's layout (FORMULAS.md and generated/ copied), named by
    ZENER_SYM_SOURCE, for tests that make a committed file stale."""
    tree = tmp_path / "tree"
    (tree / "derivation").mkdir(parents=True)
    (tree / "src" / "zener_sym").mkdir(parents=True)
    shutil.copytree(ROOT / "generated", tree / "generated")
    for name in ("pyproject.toml", "FORMULAS.md", "AUDIT.md"):
        shutil.copy(ROOT / name, tree / name)
    monkeypatch.setenv("ZENER_SYM_SOURCE", str(tree))
    return tree
