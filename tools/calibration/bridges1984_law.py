"""Write src/zener_sym/data/bridges1984_ice_law.csv: the published fitted law of Bridges, Hatzes &
Lin (1984) for ice spheres, e(v) = (v / v_c)^(-0.234) with v_c = 0.0077 cm/s, evaluated
at 9 speeds spaced evenly in log v from 0.015 to 2 cm/s. These are NOT measured points: the raw
data could not be obtained (see the file's header). Deterministic; run from the checkout:

    python tools/calibration/bridges1984_law.py
"""
from pathlib import Path

import numpy as np

V_C = 0.0077      # cm/s, Bridges, Hatzes & Lin (1984)
EXPONENT = 0.234  # Bridges, Hatzes & Lin (1984)
SPEEDS = np.geomspace(0.015, 2.0, 9)  # cm/s

HEADER = """\
# Bridges, Hatzes & Lin (1984), water-ice spheres at low temperature and low speed:
# F. G. Bridges, A. Hatzes, D. N. C. Lin, "Structure, stability and evolution of Saturn's rings",
# Nature 309, 333-335 (1984), doi:10.1038/309333a0.
#
# NOT MEASURED POINTS. The raw data could not be obtained here; these rows are the published
# fitted law e(v) = (v / v_c)^(-0.234), v_c = 0.0077 cm/s (e = 1 below v_c), evaluated at 9
# speeds evenly spaced in log v from 0.015 to 2 cm/s, e rounded to 4 decimals, by
# tools/calibration/bridges1984_law.py. The law's constants are as quoted in the planetary-ring
# literature and carried by the REBOUND N-body code's ring examples
# (coefficient_of_restitution_bridges: 0.32 (v / 1 cm/s)^-0.234, the same law, since
# 0.0077^0.234 = 0.320). Sphere size, material constants and temperature are not in this file;
# docs/viscoelastic.md states the values assumed for the fit.
# Speed range: 0.015-2 cm/s is the range of the same group's pendulum (Hatzes, Bridges & Lin
# 1988, MNRAS 231; 50 mm ice spheres), as tabulated in A&A 573, A49 (2015), Table 2.
# Bridges et al. (1984)'s own stated range could not be checked here.
"""


def main(path=Path("src/zener_sym/data/bridges1984_ice_law.csv")):
    e = (SPEEDS / V_C) ** -EXPONENT
    rows = "".join(f"{v:.6g},{x:.4f}\n" for v, x in zip(SPEEDS, e))
    path.write_text(HEADER + "v0 [cm/s],e\n" + rows)
    return path


if __name__ == "__main__":
    print(main())
