"""``zener-sym report``: the main job. Each part of the project contributes one section."""
from __future__ import annotations

import os
import time
from collections.abc import Callable, Collection
from pathlib import Path

import numpy as np

from .format import PAPER_LAMBDAS, fmt, markdown_table, seconds


def exact_section(out_dir: Path) -> str:
    """The exact solution's summary at the paper's lambdas, with its time."""
    from ..api import summary
    from ..models import SUMMARY_FIELDS

    t0 = time.perf_counter()
    s = summary(np.array(PAPER_LAMBDAS), model="exact", backend="scipy")
    dt = time.perf_counter() - t0
    rows = [[fmt(getattr(s, f)[i]) for f in SUMMARY_FIELDS] for i in range(len(PAPER_LAMBDAS))]
    return (
        "## Exact solution of Zener's equation (10)\n\n"
        "Direct integration (scipy DOP853, rtol 1e-12, analytic phases in u = sqrt(delta) at both\n"
        f"ends of contact); {len(PAPER_LAMBDAS)} lambda values in {seconds(dt)}.\n\n"
        + markdown_table(SUMMARY_FIELDS, rows)
    )


def scene_section(out_dir: Path) -> str:
    """The paper's Table 1 pair as a scene in SI units, the cheapest model meeting 1e-3."""
    import warnings

    from ..scene.scene import Scene

    sc = Scene("table1-sphere", "table1-plate", radius=0.9e-3, thickness=0.5e-3, v0=1.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # listed in the table
        res = sc.result(rtol=1e-3)
    return (
        "## A scene in SI units\n\n"
        "The paper's Table 1 pair (sphere 'gamma-Al2O3' 12.23 GPa, 0.21, 879 kg/m^3 as printed; "
        "glass plate)\nat V0 = 1 m/s, R = 0.9 mm, H = 0.5 mm; the model is the cheapest one "
        "meeting rtol = 1e-3\n(`zener-sym scene --sphere table1-sphere --plate table1-plate "
        "--radius 0.9mm --thickness 0.5mm --v0 1m/s`).\n\n" + res.to_markdown()
    )


def _finite_plate_section(out_dir: Path) -> str:
    from .finite_plate import section

    return section(out_dir)


def _exact_fast_section(out_dir: Path) -> str:
    from .exact_fast import section

    return section()


def bench_section(out_dir: Path) -> str:
    """Work-precision charts and the stability map (``zener-sym bench --quick``) into
    ``out_dir/bench``."""
    from ..bench import suite as cmd

    folder = Path(out_dir) / "bench"
    text = cmd.run(folder, quick=True, log=lambda *a: None)
    keep = text.split("## Best accuracy")[0].split("## Work-precision charts")[0]
    tail = text.split("## Speed targets")[1] if "## Speed targets" in text else ""
    return ("## Speed against accuracy (quick benchmark)\n\n" + keep.split("\n", 2)[2].strip()
            + f"\n\nCharts, CSV tables and the full summary: `{folder}/` (BENCHMARKS.md, "
            "work_precision_*.png, stability.png).\n\n### Speed targets" + tail)


def model_comparison_section(out_dir: Path) -> str:
    """Every model against exact at the paper's lambdas, then the HAM error envelopes."""
    from .ham_envelopes import comparison_markdown, envelope_markdown

    t0 = time.perf_counter()
    env = envelope_markdown()
    dt = time.perf_counter() - t0
    return (comparison_markdown(PAPER_LAMBDAS) + "\n\n### Error envelopes of ham0 and ham1\n\n"
            "Largest relative error against exact over lambda = 0, 0.1, ..., 2.4 (force history: "
            f"max |F - F_exact| over the contact / exact F_m); {seconds(dt)}.\n\n" + env)


def derivation_section(out_dir: Path) -> str:
    """Pass/fail summary of the derivation with timing."""
    # imported when the section runs: the derivation is offline code, not on the runtime path
    from ..derivation import registry

    t0 = time.perf_counter()
    d = registry.derive()
    dt = time.perf_counter() - t0
    failed = [s for s in d.steps if not s.passed]
    verdict = ("every step passed" if not failed else
               f"{len(failed)} FAILED: " + "; ".join(f"({s.eq}) {s.what}" for s in failed))
    return (
        "## Derivation (SymPy re-derivation of Eqs. 12-81)\n\n"
        f"{len(d.steps)} checked steps, {verdict}; derivation time {seconds(d.seconds)}"
        f"{'' if dt > 1 else ' (cached in this process)'}. lambda_crit (omega0 = 0) = "
        f"{float(d.expr['lam_crit']):.10f}. The 2F1 antiderivatives of (40)-(41) are proved by "
        "differentiation at 40 digits (residual <= 1e-25 required). The accuracy of the "
        "interpolation (24) is a claim of the paper: the audit measures it."
    )


def _audit_section(out_dir: Path) -> str:
    """The audit's summary line."""
    from ..audit.markdown import cached_results
    from ..audit.run import summary_line

    return ("## Paper audit\n\n" + summary_line(cached_results()) + " Details: `zener-sym "
            "audit` (AUDIT.md).")


#: Where report sections write files (charts) unless ``run`` is told otherwise.
DEFAULT_OUT_DIR: Path = Path("zener-sym-report")

#: A report section: the folder for its files -> its markdown.
Section = Callable[[Path], str]

#: (title, callable(out_dir) returning markdown; ``out_dir`` is the folder for its files).
#: Later parts of the project append their section here.
def lammps_section(out_dir: Path) -> str:
    """The LAMMPS lines of the docs' workflow (glass on steel, e = 0.8 at 1 m/s), and, where
    LAMMPS is installed, LAMMPS run with them at the table's timestep."""
    from ..bench.lammps import run as lammps_run
    from ..scene.lammps import lammps_setup

    s = lammps_setup("glass", "1 mm", wall="steel", e=0.8, at="1 m/s",
                     speeds=[0.1, 0.3, 1.0, 3.0, 10.0])
    text = ("## LAMMPS\n\n`zener-sym lammps --sphere glass --radius 1mm --wall steel --e 0.8 "
            "--at 1m/s --speeds 0.1m/s,...` (docs/lammps.md):\n\n    "
            + "\n    ".join(s.text()) + "\n")
    try:
        lammps_run.load()
    except lammps_run.LammpsMissing as exc:
        return text + f"\nThe lines were not run: {exc}."
    rows = []
    t0 = time.perf_counter()
    with lammps_run.Session() as ses:
        for r in s.table:
            v, e, dt, t_c = (r[k] for k in ("v_m_s", "e", "dt_max_s", "contact_time_s"))
            assert v is not None and e is not None and dt is not None and t_c is not None
            c = lammps_run.collide(ses, s.contact, s.damping, s.contact_end, v, dt, t_c,
                                   phase=0.5, e_exact=e)
            rows.append([fmt(v), fmt(e), fmt(c.e), f"{c.e - e:.2e}", c.status])
    took = seconds(time.perf_counter() - t0)
    return (text + f"\nLAMMPS itself, run with these lines at `dt_max` ({took}):\n\n"
            + markdown_table(["v (m/s)", "exact e", "LAMMPS e", "difference", "status"], rows))


SECTIONS: list[tuple[str, Section]] = [
    ("exact", exact_section),
    ("derivation", derivation_section),
    ("audit", _audit_section),
    ("model comparison", model_comparison_section),
    ("scene", scene_section),
    ("finite plates", _finite_plate_section),
    ("exact-fast", _exact_fast_section),
    ("lammps", lammps_section),
    ("bench", bench_section),
]


def run(out: Callable[[str], object] = print, out_dir: str | os.PathLike[str] | None = None,
        skip: Collection[str] = ()) -> int:
    """Print every section; files (charts) go to ``out_dir`` (default :data:`DEFAULT_OUT_DIR`).
    ``skip``: section names to leave out. Returns 0, or 1 when a section failed."""
    folder = DEFAULT_OUT_DIR if out_dir is None else Path(out_dir)
    import datetime
    import platform

    from .. import __version__

    out(f"# zener-sym report\n\nzener-sym {__version__}, {datetime.date.today().isoformat()}, "
        f"Python {platform.python_version()} on {platform.machine()}.\n")
    status = 0
    for name, section in SECTIONS:
        if name in skip:
            continue
        try:
            out(section(folder))
        except Exception as exc:  # a failing section must not hide the others
            status = 1
            out(f"## {name}: FAILED\n\n{type(exc).__name__}: {exc}")
        out("")
    return status
