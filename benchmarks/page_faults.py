"""Page faults and wall time per history call, in fresh processes (docs/benchmarks.md).

    python benchmarks/page_faults.py                 # exact, 9 processes
    python benchmarks/page_faults.py --model ham0 --runs 5

Each process computes the 200 lambda x 500 tau history of the issue-14 target eight times in a
row and prints, per call, the minor page faults (``getrusage``) and the milliseconds. A fresh page
costs about 1.5 us on the machine these docs were measured on, so whether glibc's allocator keeps
freed memory (faults drop to 0 after the first calls) or returns it to the system every call
decides much of a history's time. It keeps it when a call's peak memory stays below its trim
threshold; when the exact history's peak was 6 MB, two processes in nine (depending on their
address-space layout) returned it every call (docs/benchmarks.md).
"""
from __future__ import annotations

import argparse
import subprocess
import sys

_CHILD = """
import resource, time
import numpy as np
import zener_sym as zs
lams = np.linspace(0.0, {top}, 200)
tau = zs.summary(lams, model={model!r}).tau_d[:, None] * 1.05 * np.linspace(0.0, 1.0, 500)
out = []
for _ in range(8):
    r0 = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    t0 = time.perf_counter()
    zs.history(lams[:, None], tau, model={model!r})
    ms = 1e3 * (time.perf_counter() - t0)
    out.append((resource.getrusage(resource.RUSAGE_SELF).ru_minflt - r0, round(ms, 2)))
print(out)
"""


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--model", default="exact")
    ap.add_argument("--runs", type=int, default=9)
    a = ap.parse_args(argv)
    top = 5.0 if a.model == "exact" else 2.4
    for _ in range(a.runs):
        r = subprocess.run([sys.executable, "-c", _CHILD.format(top=top, model=a.model)],
                           capture_output=True, text=True, check=True)
        print(r.stdout.strip())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
