"""Deprecated: moved to :mod:`zener_sym.bench.lammps.run` (issue 36); this name goes in the next
release."""
from .lammps._moved import moved

__getattr__ = moved(__name__, "zener_sym.bench.lammps.run")
