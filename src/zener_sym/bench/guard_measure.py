"""The speed guard's measurements: each guarded operation timed against a reference operation of
similar work, side by side in one process (issue 36, section 3).

A guarded operation is a call of the package's public API (``zs.summary``, ``zs.history``,
``zs.lam_from_summary``) or of the emitted C library; its reference is numpy's ``chebval`` of a
comparable degree and field count on an array of the same length, which no change to this
project can slow down. What is kept is the ratio guarded time / reference time: the load of a
shared machine and the speed of its processor fall on both sides alike.

This module imports nothing of the package but its public API, and that inside the functions,
so that it can measure any checkout: ``python guard_measure.py`` run with another tree's package
first on the import path (``zener_sym.bench.guard.measure_tree`` arranges it) prints that tree's
ratios as JSON. It is a script as well as a module for that reason: no relative imports.

Each entry is measured in a child forked for it (``in_child``), so that the entries before it
leave no trace in its time. How time is taken (``ratio``): one warm-up call of each side; then ``rounds`` rounds, each timing
the guarded and the reference side once, in alternating order, each sample a batch of calls long
enough (about ``SAMPLE_S``) for the clock; the CPU time of this process (``time.process_time``),
since on a shared machine wall time mostly measures the other processes. The ratio is that of
the fastest samples: load only ever adds time, so the fastest sample is the least disturbed.
"""
from __future__ import annotations

import ctypes
import functools
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.polynomial import chebyshev

#: The length of one timed sample, seconds of CPU time (a batch of calls at least this long).
SAMPLE_S = 2e-3

#: Rounds of (guarded, reference) samples per entry.
ROUNDS = 15


@dataclass(frozen=True)
class Pair:
    """A guarded operation and its reference, both callables without arguments."""

    guarded: Callable[[], object]
    reference: Callable[[], object]


#: Points per ``chebval`` call of a reference: cache-sized, as the package's histories evaluate
#: their points in blocks of 8192 (``numerics.blocks``). Over a whole 100 000-point grid chebval
#: streams memory, and its time then follows the other processes' use of the memory bus more than
#: the guarded side's does (the C history's ratio moved from 0.36 to 0.49 with the load).
REFERENCE_BLOCK = 8192


def chebval_reference(n: int, degree: int, fields: int) -> Callable[[], object]:
    """numpy's ``chebval`` of ``fields`` series of ``degree`` on ``n`` points in [-1, 1], in
    blocks of ``REFERENCE_BLOCK`` points (the reference side of every entry)."""
    x = np.linspace(-1.0, 1.0, n)
    c = np.random.default_rng(36).standard_normal((degree + 1, fields))
    blocks = [x[a:a + REFERENCE_BLOCK] for a in range(0, n, REFERENCE_BLOCK)]
    return lambda: [chebyshev.chebval(b, c) for b in blocks]


def _summary_lambdas(n: int) -> np.ndarray:
    """n lambda over the tables' whole range: half on [0, 5], half geometric on [5, 1000]."""
    return np.concatenate([np.linspace(0.0, 5.0, n // 2), np.geomspace(5.0, 1000.0, n - n // 2)])


# --- the entries: name -> builder of its Pair ------------------------------------------------
def exact_summary(contact_end: str, n: int) -> Callable[[], Pair]:
    """``zs.summary`` of n lambda on [0, 1000], exact model, at one contact end, against
    chebval of the tables' six fields at degree 21 (22 nodes a lambda piece)."""
    def build() -> Pair:
        import zener_sym as zs

        lams = _summary_lambdas(n)
        return Pair(lambda: zs.summary(lams, model="exact", contact_end=contact_end),
                    chebval_reference(n, 21, 6))
    return build


def exact_history(contact_end: str, m: int = 200, k: int = 500) -> Callable[[], Pair]:
    """``zs.history`` (every field) on m lambda in [0, 5] x k tau over 1.05 of each contact,
    against chebval of two series (f and I) of degree 12 on the m k points."""
    def build() -> Pair:
        import zener_sym as zs

        lams = np.linspace(0.0, 5.0, m)
        tau = (zs.summary(lams, contact_end=contact_end).tau_d[:, None] * 1.05
               * np.linspace(0.0, 1.0, k))
        return Pair(lambda: zs.history(lams[:, None], tau, model="exact",
                                       contact_end=contact_end),
                    chebval_reference(m * k, 12, 2))
    return build


def lam_from_e(contact_end: str, n: int = 2000) -> Callable[[], Pair]:
    """``zs.lam_from_summary(e=...)`` (``zs.lam_for`` in trees before its rename) on n
    restitution values over [0.05, 1) of the range, against chebval of six fields, degree 21."""
    def build() -> Pair:
        import zener_sym as zs

        inverse = getattr(zs, "lam_from_summary", None) or getattr(zs, "lam_for")
        e = np.exp(np.random.default_rng(24).uniform(np.log(0.05), np.log(0.999), n))
        return Pair(lambda: inverse(e=e, contact_end=contact_end), chebval_reference(n, 21, 6))
    return build


def ham1_summary(n: int = 2000) -> Callable[[], Pair]:
    """``zs.summary(model="ham1")`` of n lambda in [0, 2.4] (its Chebyshev tables in lambda),
    against chebval of six fields, degree 21."""
    def build() -> Pair:
        import zener_sym as zs

        lams = np.linspace(0.0, 2.4, n)
        return Pair(lambda: zs.summary(lams, model="ham1"), chebval_reference(n, 21, 6))
    return build


def ham0_history(m: int = 200, k: int = 500) -> Callable[[], Pair]:
    """``zs.history(model="ham0")`` (every field) on m lambda in [0, 2.4] x k tau over 1.05 of
    ham0's contact, against chebval of two series of degree 12 on the m k points."""
    def build() -> Pair:
        import zener_sym as zs

        lams = np.linspace(0.0, 2.4, m)
        tau = zs.summary(lams, model="ham0").tau_d[:, None] * 1.05 * np.linspace(0.0, 1.0, k)
        return Pair(lambda: zs.history(lams[:, None], tau, model="ham0"),
                    chebval_reference(m * k, 12, 2))
    return build


def plate_one_collision() -> Callable[[], Pair]:
    """The finite-plate solver (``zener_sym.plate.solver.solve``) on the benchmark's one
    collision (the paper's FEM plate, 400 modes) at rtol 1e-3, its cheapest run to 1e-6 in e,
    against scipy's DOP853 on the same modal system at rtol 1e-5, DOP853's cheapest run to that
    error (``python -m zener_sym.bench.plate``). Issue 37 promises 100x: the ratio is about
    1/250 where it was recorded, and the reference is scipy's integrator, which a change to the
    solver cannot slow down."""
    def build() -> Pair:
        from zener_sym.bench.plate import CASES, clamped_circle, dop853_impact
        from zener_sym.plate.solver import solve

        _name, lam, beta, n = CASES[0]
        plate = clamped_circle(lam, beta, n)
        return Pair(lambda: solve(plate, rtol=1e-3), lambda: dop853_impact(plate, rtol=1e-5))
    return build


C_WRAPPER = r"""
#include <stddef.h>
#include "zener_sym.h"
/* m exact histories at the plate end, lambda i on its own row of k times (the Python loop of
   ctypes calls would add a microsecond a lambda) */
int guard_history(size_t m, const double *lam, size_t k, const double *tau, double *delta,
                  double *velocity, double *force, double *impulse)
{
    size_t i;
    for (i = 0; i < m; i++) {
        int rc = zs_history(lam[i], ZS_DELTA, k, tau + i * k, delta + i * k, velocity + i * k,
                            force + i * k, impulse + i * k);
        if (rc != 0)
            return rc;
    }
    return 0;
}
"""

#: The C library's build: the portable flags (no -march), so that the ratio moves less between
#: processors than that of a native build would.
C_FLAGS = ("-std=c99", "-O2")


def c_source_dir() -> pathlib.Path:
    """generated/c of the package that ``import zener_sym`` finds."""
    import zener_sym.generated as generated

    return pathlib.Path(generated.__file__).resolve().parent / "c"


def c_history(m: int = 200, k: int = 500) -> Callable[[], Pair]:
    """The emitted C ``zs_history`` (every field, plate end) on the grid of ``exact_history``,
    built here as a shared library, against chebval of two series of degree 12 on the m k
    points (numpy, as the C kernels' promise is a ratio to numpy)."""
    def build() -> Pair:
        import zener_sym as zs

        lib = build_c_library(c_source_dir())
        lams = np.linspace(0.0, 5.0, m)
        tau = np.ascontiguousarray(zs.summary(lams).tau_d[:, None] * 1.05
                                   * np.linspace(0.0, 1.0, k))
        out = np.empty((4, m, k))
        ptr = ctypes.POINTER(ctypes.c_double)
        args = [m, lams.ctypes.data_as(ptr), k, tau.ctypes.data_as(ptr),
                *(o.ctypes.data_as(ptr) for o in out)]

        def run() -> object:
            rc = lib.guard_history(*args)
            if rc != 0:
                raise RuntimeError(f"zs_history returned {rc}")
            return out
        return Pair(run, chebval_reference(m * k, 12, 2))
    return build


def build_c_library(c_dir: pathlib.Path) -> Any:
    """``c_dir/zener_sym.c`` with ``C_WRAPPER`` built as a shared library and loaded."""
    cc = shutil.which("gcc") or shutil.which("cc")
    if cc is None:
        raise RuntimeError("no C compiler (gcc or cc) on PATH: the C history cannot be built")
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="zs_guard_"))
    (tmp / "guard.c").write_text(C_WRAPPER)
    so = tmp / "libzs_guard.so"
    r = subprocess.run([cc, *C_FLAGS, "-fPIC", "-shared", "-I", str(c_dir), str(tmp / "guard.c"),
                        str(c_dir / "zener_sym.c"), "-o", str(so), "-lm"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"building the C library failed: {r.stderr.strip()[:300]}")
    lib = ctypes.CDLL(str(so))
    ptr = ctypes.POINTER(ctypes.c_double)
    lib.guard_history.argtypes = [ctypes.c_size_t, ptr, ctypes.c_size_t, ptr, ptr, ptr, ptr, ptr]
    lib.guard_history.restype = ctypes.c_int
    shutil.rmtree(tmp)  # the loaded library stays mapped
    return lib


#: Every guarded entry: name -> (what it times, builder of its Pair).
ENTRIES: dict[str, tuple[str, Callable[[], Pair]]] = {
    "exact_summary_plate_1k": ("zs.summary, exact, plate end, 1000 lambda in [0, 1000]",
                               exact_summary("delta", 1000)),
    "exact_summary_force_1k": ("zs.summary, exact, force-free end, 1000 lambda in [0, 1000]",
                               exact_summary("force", 1000)),
    "exact_history_plate": ("zs.history, exact, plate end, 200 lambda x 500 tau",
                            exact_history("delta")),
    "exact_history_force": ("zs.history, exact, force-free end, 200 lambda x 500 tau",
                            exact_history("force")),
    "lam_from_e_plate": ("zs.lam_from_summary(e=...), plate end, 2000 values",
                         lam_from_e("delta")),
    "lam_from_e_force": ("zs.lam_from_summary(e=...), force-free end, 2000 values",
                         lam_from_e("force")),
    "ham1_summary": ("zs.summary, ham1, 2000 lambda in [0, 2.4]", ham1_summary()),
    "ham0_history": ("zs.history, ham0, 200 lambda x 500 tau", ham0_history()),
    "c_history_plate": ("C zs_history (-O2), plate end, 200 lambda x 500 tau", c_history()),
    "plate_one_collision": ("zener_sym.plate solve, one collision, 400 modes, rtol 1e-3, "
                            "against DOP853 at rtol 1e-5 on the same modes",
                            plate_one_collision()),
}


def _sample(fn: Callable[[], object], calls: int) -> float:
    """CPU seconds per call of ``fn``, over a batch of ``calls`` calls."""
    t0 = time.process_time()
    for _ in range(calls):
        fn()
    return (time.process_time() - t0) / calls


def _calls_for(fn: Callable[[], object]) -> int:
    """Calls in a batch of about SAMPLE_S (from one timed call after the warm-up)."""
    fn()
    one = _sample(fn, 1)
    return max(1, min(1000, int(SAMPLE_S / max(one, 1e-7))))


def ratio(pair: Pair, rounds: int = ROUNDS) -> dict[str, float]:
    """The guarded time over the reference time, from the fastest of ``rounds`` samples each,
    taken in alternation (module docstring): ``ratio``, ``guarded_s``, ``reference_s``."""
    cg, cr = _calls_for(pair.guarded), _calls_for(pair.reference)
    g: list[float] = []
    r: list[float] = []
    for i in range(rounds):
        if i % 2 == 0:
            g.append(_sample(pair.guarded, cg))
            r.append(_sample(pair.reference, cr))
        else:
            r.append(_sample(pair.reference, cr))
            g.append(_sample(pair.guarded, cg))
    return {"ratio": min(g) / min(r), "guarded_s": min(g), "reference_s": min(r)}


def measure_one(name: str, rounds: int = ROUNDS) -> dict[str, Any]:
    """One entry's ``ratio``; ``error`` instead when the measured tree cannot run it (no such
    API, no C compiler)."""
    what, build = ENTRIES[name]
    try:
        pair = build()
    except Exception as err:  # noqa: BLE001  an old tree may lack the API: say so, go on
        return {"what": what, "error": f"{type(err).__name__}: {err}"}
    return {"what": what, **ratio(pair, rounds)}


def in_child(fn: Callable[[], dict[str, Any]]) -> dict[str, Any]:
    """``fn()`` in a forked child (where fork exists): each entry starts from the same state of
    the allocator, whatever the entries before it freed. An entry's time depends on it: glibc
    raises its mmap threshold once a large block is freed, after which temporaries of a few
    MB stop faulting in fresh pages; measured after the 100 000-point histories, c2ea95c's
    summary of 1000 lambda took half the time it takes in a fresh process."""
    if not hasattr(os, "fork"):
        return fn()
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: measure, send, leave without running the parent's clean-up
        try:
            text = json.dumps(fn())
        except BaseException as err:  # noqa: BLE001  the parent reports it
            text = json.dumps({"error": f"{type(err).__name__}: {err}"})
        with os.fdopen(write, "w") as f:
            f.write(text)
        os._exit(0)
    os.close(write)
    with os.fdopen(read) as f:
        text = f.read()
    os.waitpid(pid, 0)
    result: dict[str, Any] = json.loads(text) if text else {"error": "the measuring child died"}
    return result


def measure(names: list[str] | None = None, rounds: int = ROUNDS) -> dict[str, dict[str, Any]]:
    """Each named entry (default: every entry) measured by ``measure_one``, each in a child of
    this process (``in_child``), with the package imported once before."""
    import zener_sym  # noqa: F401  imported here once, not in every child

    return {name: in_child(functools.partial(measure_one, name, rounds))
            for name in names or list(ENTRIES)}


if __name__ == "__main__":  # the measurement of whatever tree ``import zener_sym`` finds
    args = sys.argv[1:]
    rounds = int(args.pop(0)) if args and args[0].isdigit() else ROUNDS
    print(json.dumps(measure(args or None, rounds)))
