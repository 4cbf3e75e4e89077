"""The order of the gallery: from a first impact to the studies (sphinx-gallery's
``within_subsection_order`` takes :func:`key` by its dotted name). A script not listed here
comes after these, by file name."""
from __future__ import annotations

from pathlib import Path

ORDER = ("plot_drop_ball.py", "plot_finite_plate.py", "plot_force_history.py", "plot_compare_models.py",
         "plot_work_precision.py", "plot_paper_figure.py", "plot_dem_lookup.py",
         "plot_calibrate_dissipation.py", "plot_lammps.py", "plot_ham_convergence.py")


def key(filename) -> tuple:
    """Sort key of a gallery script's file name."""
    name = Path(filename).name
    return (ORDER.index(name) if name in ORDER else len(ORDER), name)
