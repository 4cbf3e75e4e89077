"""The worked calibration of docs/viscoelastic.md: the dissipative constant A fitted to the ice
law of Bridges, Hatzes & Lin (1984) carried in ``data/bridges1984_ice_law.csv``, with the
sphere and wall the page assumes. ``zener-sym regen calibration`` rebuilds the printed fit
(``docs/data/calibration_bridges1984.txt``, compared for freshness) and its chart
(``docs/viscoelastic/calibration_bridges1984.png``); the page's ``zener-sym fit`` command prints
and draws the same."""
from __future__ import annotations

import os
from importlib import resources

from ..scene.calibrate import DissipationFit, fit_dissipation, read_measurements
from ..scene.materials import Material
from ..scene.scaling import sphere_mass

#: The committed files, relative to the repository's root.
TEXT: str = "docs/data/calibration_bridges1984.txt"
CHART: str = "docs/viscoelastic/calibration_bridges1984.png"
DATA: str = "bridges1984_ice_law.csv"

#: What docs/viscoelastic.md assumes: ice (E = 9 GPa, nu = 0.33, 917 kg/m^3), radius 2.5 cm,
#: on an ice wall; the chart's labels as the page's command gives them.
ICE: Material = Material(9e9, 0.33, 917.0, name="ice")
RADIUS: float = 0.025
TITLE: str = "ice: the law of Bridges et al. (1984), fitted"
DATA_LABEL: str = "Bridges et al. (1984) law"


def fit() -> DissipationFit:
    """The page's fit (force-free end), from the packaged data file."""
    data = read_measurements((resources.files("zener_sym") / "data" / DATA).read_text("utf-8"))
    return fit_dissipation(ICE, RADIUS, sphere_mass(RADIUS, ICE.rho), v0=data.v0, e=data.e,
                           sigma=data.sigma, wall=ICE, contact_end="force")


def text(result: DissipationFit | None = None) -> str:
    """The printed fit, as ``zener-sym fit`` prints it (without its first line, which names
    the file as given on the command line)."""
    return str(fit() if result is None else result).rstrip("\n") + "\n"


def write_chart(path: str | os.PathLike[str], result: DissipationFit | None = None) -> None:
    """Draw the page's chart to ``path`` (needs matplotlib)."""
    (fit() if result is None else result).plot(path, title=TITLE, data_label=DATA_LABEL)
