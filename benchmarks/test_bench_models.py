"""Benchmark suite (pytest-benchmark), kept apart from the unit tests.

    pip install -e '.[bench]'
    python -m pytest benchmarks/ --benchmark-only --benchmark-group-by=group

Each group holds the methods a speed target compares, so their ratio is read off one run:
- "history 200x200": ham1 (numpy) force history on 200 lambda x 200 tau (``fields="force"``),
  against a per-lambda scipy DOP853 solve with dense output at rtol 1e-6 (target: ham1 50x
  faster); also ham1 with every history field, for scale.
- "per point": ham1 numpy against ham1 mpmath per point (target: 1000x).
- "summary 2000": the exact model's summary for 2000 lambda in [0, 5], against a per-lambda
  scipy DOP853 loop with events at rtol 1e-10 (target: 50x).
"""
import numpy as np
import pytest

import zener_sym as zs
from zener_sym.bench.methods import naive_solve
from zener_sym.bench.methods import dop853_force_loop
from zener_sym.models import REGISTRY

LAMS = np.linspace(0.0, 2.4, 200)
S = np.linspace(0.0, 1.0, 200)
needs_ham1 = pytest.mark.skipif("ham1" not in REGISTRY, reason="ham1 model not registered")


def _tau_grid():
    return zs.summary(LAMS, model="ham0").tau_d[:, None] * 1.6 * S


@needs_ham1
@pytest.mark.benchmark(group="history 200x200")
def test_ham1_numpy_history(benchmark):
    tau = _tau_grid()
    out = benchmark(lambda: zs.history(LAMS[:, None], tau, model="ham1", fields="force").force)
    assert out.shape == (200, 200)


@needs_ham1
@pytest.mark.benchmark(group="history 200x200")
def test_ham1_numpy_history_every_field(benchmark):
    """Not the target's comparison (DOP853 gives the force only): delta, force, impulse and
    velocity, the impulse by one Chebyshev antiderivative per lambda."""
    tau = _tau_grid()
    out = benchmark(lambda: zs.history(LAMS[:, None], tau, model="ham1").impulse)
    assert out.shape == (200, 200)


@needs_ham1
@pytest.mark.benchmark(group="history 200x200")
def test_scipy_dop853_loop_history(benchmark):
    tau = _tau_grid()

    out = benchmark.pedantic(lambda: dop853_force_loop(LAMS, tau), rounds=3, iterations=1)
    assert out.shape == (200, 200)


@needs_ham1
@pytest.mark.benchmark(group="per point")
def test_ham1_numpy_per_point(benchmark):
    tau = _tau_grid()
    benchmark.extra_info["points"] = tau.size
    benchmark(lambda: zs.history(LAMS[:, None], tau, model="ham1").force)


@needs_ham1
@pytest.mark.benchmark(group="per point")
def test_ham1_mpmath_per_point(benchmark):
    pts = np.array([0.3, 1.1, 2.0])
    benchmark.extra_info["points"] = pts.size
    benchmark.pedantic(lambda: zs.history(1.01, pts, model="ham1", backend="mpmath").force,
                       rounds=2, iterations=1)


@pytest.mark.benchmark(group="summary 2000")
def test_exact_summary_2000(benchmark):
    lams = np.linspace(0.0, 5.0, 2000)
    s = benchmark(lambda: zs.summary(lams, model="exact"))
    assert s.e.shape == (2000,)


@pytest.mark.benchmark(group="summary 2000")
def test_scipy_dop853_loop_summary(benchmark):
    lams = np.linspace(0.0, 5.0, 2000)
    benchmark.pedantic(lambda: [naive_solve(x, 1e-10, "DOP853") for x in lams], rounds=1,
                       iterations=1)


# --- issue 14, item 8: each group holds both sides of one ratio --------------------------------
# (the same comparisons as zener_sym.bench.exact_fast_targets.issue14_targets, which
# `zener-sym bench` reports as ratios)

H_LAMS = np.linspace(0.0, 5.0, 200)
H_S = np.linspace(0.0, 1.0, 500)


@pytest.mark.benchmark(group="exact history 200x500")
def test_exact_history_200x500(benchmark):
    tau = zs.summary(H_LAMS, model="exact").tau_d[:, None] * 1.05 * H_S
    out = benchmark(lambda: zs.history(H_LAMS[:, None], tau, model="exact").force)
    assert out.shape == (200, 500)


@pytest.mark.benchmark(group="exact history 200x500")
def test_scipy_dop853_loop_history_rtol_1e10(benchmark):
    tau = zs.summary(H_LAMS, model="exact").tau_d[:, None] * 1.05 * H_S
    out = benchmark.pedantic(lambda: dop853_force_loop(H_LAMS, tau, rtol=1e-10), rounds=1,
                             iterations=1)
    assert out.shape == (200, 500)


@pytest.mark.parametrize("model", ["exact", "ham1"])
@pytest.mark.benchmark(group="scalar summary")
def test_scalar_summary(benchmark, model):
    if model not in REGISTRY:
        pytest.skip(f"{model} not registered")
    lams = iter(np.tile(np.linspace(0.05, 2.43, 97), 1000))  # a new lambda every call
    benchmark(lambda: zs.summary(float(next(lams)), model=model))


P_LAMS = np.linspace(0.0, 2.4, 200)


@pytest.mark.parametrize("model", ["exact", "ham0", "hunter", "reed"])
@pytest.mark.benchmark(group="history 200x500, lambda in [0, 2.4]")
def test_model_history_200x500(benchmark, model):
    tau = zs.summary(P_LAMS, model="ham0").tau_d[:, None] * 1.05 * H_S
    out = benchmark(lambda: zs.history(P_LAMS[:, None], tau, model=model).force)
    assert out.shape == (200, 500)


@pytest.mark.parametrize("where", ["[0, 5]", "(5, 1000]"])
@pytest.mark.benchmark(group="exact summary per lambda, 2000 lambda")
def test_exact_summary_small_and_large_lambda(benchmark, where):
    lams = np.linspace(0.0, 5.0, 2000) if where == "[0, 5]" else np.geomspace(5.0 + 1e-9, 1000.0,
                                                                               2000)
    s = benchmark(lambda: zs.summary(lams, model="exact"))
    assert s.tau_d.shape == (2000,)
