"""The stored mpmath Taylor-series solutions (tests/data/exact_mp_reference.json, written by
tools/exact_mp_reference.py) at the lambdas where one solve takes minutes.

Each entry reads like the mpmath path's solution: summary fields as floats (the strings hold 25
digits), ``xi_from_w_end`` (1 - w_end^2 at 40 digits, not the energy balance) and the history on
the tool's grid. tests/test_exact_edges.py re-solves one lambda live and checks it against the file,
so a change of the mpmath path that moves the numbers shows up as a stale file.
"""
from __future__ import annotations

import json
import runpy
import types

import numpy as np

from conftest import ROOT

PATH = ROOT / "tests" / "data" / "exact_mp_reference.json"
#: the summary fields stored, as the tool that writes the file lists them
FIELDS: tuple = runpy.run_path(str(ROOT / "tools" / "exact_mp_reference.py"))["FIELDS"]


def _rows() -> dict:
    return json.loads(PATH.read_text())["lambdas"]


def load(lam: float) -> types.SimpleNamespace:
    """The stored solution at ``lam`` (a key of the file, e.g. 1000.0 or 1e-12)."""
    rows = _rows()
    key = next((k for k in rows if float(k) == lam), None)
    assert key is not None, f"lambda = {lam} is not in {PATH.name}: run tools/exact_mp_reference.py"
    row = rows[key]
    ref = types.SimpleNamespace(lam=float(key), dps=row["dps"], text=row,
                                **{f: float(row[f]) for f in FIELDS},
                                xi_from_w_end=float(row["xi_from_w_end"]),
                                history={k: np.array(v) for k, v in row["history"].items()})
    return ref


def lambdas() -> list[float]:
    return [float(k) for k in _rows()]
