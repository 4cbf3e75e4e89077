"""The paper's Figs. 3-15 redrawn against the exact solution (``zener-sym figures``).

:mod:`.data` computes each figure's curves (pure numpy, written as ``figNN.csv``), :mod:`.draw`
draws them in the package style, :mod:`.make` validates the request and writes the files.
"""
from .make import FORMATS, build, stale
from .data import FIGURES, NUMBERS

__all__ = ["FIGURES", "NUMBERS", "FORMATS", "build", "stale"]
