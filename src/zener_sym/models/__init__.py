"""Every model of the impact behind one interface; each registers itself in ``REGISTRY``."""
from .base import (HISTORY_FIELDS, REGISTRY, SUMMARY_FIELDS, FieldUnavailableError, FieldValues,
    Model, computed_bound, get_model, register)
from . import exact  # noqa: F401  (registers "exact")
from . import ham0_ham1  # noqa: F401  (registers "ham0", "ham1")
from . import ham_any_order  # noqa: F401  (registers "ham": any order, Liao's c0)
from . import pulses  # noqa: F401  (registers "hertz", "hunter", "reed", "oneway")
from . import linear  # noqa: F401  (registers "linear", "raman")
from . import fits  # noqa: F401  (registers "fits")
from . import series  # noqa: F401  (registers "series")
from . import finite_plate  # noqa: F401  (registers "finite-plate")

__all__ = ["Model", "REGISTRY", "register", "get_model", "SUMMARY_FIELDS", "HISTORY_FIELDS",
           "FieldUnavailableError", "FieldValues", "computed_bound"]
