"""How time is taken: the first call gives the values and serves as warm-up; if it took less than
``min_total`` seconds, further calls are timed until ``min_total`` seconds have passed (at least
``min_repeats`` of them) and the median is reported; a call slower than that is timed once.
Side-by-side comparisons run in one process, one after the other, so they see the same load."""
from __future__ import annotations

import statistics
import time
from collections.abc import Callable, Sequence
from typing import TypeVar

_T = TypeVar("_T")


def timed(fn: Callable[[], _T], min_repeats: int = 3, min_total: float = 0.2,
          max_repeats: int = 200) -> tuple[_T, float]:
    """(value of the first call, median seconds per call)."""
    t0 = time.perf_counter()
    value = fn()
    first = time.perf_counter() - t0
    if first >= min_total:
        return value, first
    times: list[float] = []
    start = time.perf_counter()
    while len(times) < min_repeats or (time.perf_counter() - start < min_total
                                       and len(times) < max_repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return value, statistics.median(times)


def median_time(fn: Callable[[], object], min_repeats: int = 3, min_total: float = 0.2,
                max_repeats: int = 200) -> float:
    """Median wall time of ``fn()`` in seconds (see ``timed``)."""
    return timed(fn, min_repeats, min_total, max_repeats)[1]


def alternating_median_times(fns: Sequence[Callable[[], object]], rounds: int = 15) -> list[float]:
    """Median wall time in seconds of each of ``fns``, timed in alternation (f0, f1, ..., f0, f1,
    ...) after one warm-up call each, so that drifts in load, clock or allocator state fall on
    every side of a ratio alike rather than on whichever was timed first."""
    for fn in fns:
        fn()
    times: list[list[float]] = [[] for _ in fns]
    for _ in range(rounds):
        for fn, t in zip(fns, times):
            t0 = time.perf_counter()
            fn()
            t.append(time.perf_counter() - t0)
    return [statistics.median(t) for t in times]
