"""The Examples of zener_sym.ham's and zener_sym.codegen's docstrings run as doctests (those of
the generated kernels: tests/test_codegen_ham.py)."""
from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = ["zener_sym.ham.xp", "zener_sym.ham.table", "zener_sym.ham.table_build",
           "zener_sym.ham.spectral", "zener_sym.ham.higher", "zener_sym.ham.runtime_numpy",
           "zener_sym.ham.runtime_mpmath", "zener_sym.codegen", "zener_sym.codegen.tables"]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples_run(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0, f"{name} has no examples"
    assert result.failed == 0
