"""``zener-sym report``: the main job. Each part of the project contributes one section."""
from __future__ import annotations

import time

import numpy as np

#: The lambda values of the paper's figures 5, 10 and 11 (and 0, Hertz's rigid half-space).
PAPER_LAMBDAS = (0.0, 0.11, 1.01, 1.51, 1.99)


def fmt(x, digits=10) -> str:
    return f"{x:.{digits}g}"


def markdown_table(header, rows) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def exact_section() -> str:
    from .api import summary
    from .models import SUMMARY_FIELDS

    t0 = time.perf_counter()
    s = summary(np.array(PAPER_LAMBDAS), model="exact")
    dt = time.perf_counter() - t0
    rows = [[fmt(getattr(s, f)[i]) for f in SUMMARY_FIELDS] for i in range(len(PAPER_LAMBDAS))]
    return (
        "## Exact solution of Zener's equation (10)\n\n"
        "Direct integration (scipy DOP853, rtol 1e-12, analytic phases in u = sqrt(delta) at both\n"
        f"ends of contact); {len(PAPER_LAMBDAS)} lambda values in {dt:.2f} s.\n\n"
        + markdown_table(SUMMARY_FIELDS, rows)
    )


def model_comparison_section() -> str:
    """Every model against exact at the paper's lambdas, then the HAM error envelopes."""
    from .envelopes import comparison_markdown, envelope_markdown

    t0 = time.perf_counter()
    env = envelope_markdown()
    dt = time.perf_counter() - t0
    return (comparison_markdown(PAPER_LAMBDAS) + "\n\n### Error envelopes of ham0 and ham1\n\n"
            "Largest relative error against exact over lambda = 0, 0.1, ..., 2.4 (force history: "
            f"max |F - F_exact| over the contact / exact F_m); {dt:.1f} s.\n\n" + env)


def derivation_section() -> str:
    # imported when the section runs: the derivation is offline code, not on the runtime path
    from .derive_cmd import report_section

    return report_section()


#: (title, callable returning markdown). Later parts of the project append their section here.
SECTIONS = [
    ("exact", exact_section),
    ("derivation", derivation_section),
    ("model comparison", model_comparison_section),
]


def run(out=print) -> int:
    out("# zener-sym report\n")
    status = 0
    for name, section in SECTIONS:
        try:
            out(section())
        except Exception as exc:  # a failing section must not hide the others
            status = 1
            out(f"## {name}: FAILED\n\n{type(exc).__name__}: {exc}")
        out("")
    return status


def add_parser(sub) -> None:
    p = sub.add_parser("report", help="the main job: every part of the project, summarised")
    p.set_defaults(func=lambda args: run())
