"""Every model of the impact behind one interface; each registers itself in ``REGISTRY``."""
from .base import (HISTORY_FIELDS, REGISTRY, SUMMARY_FIELDS, FieldUnavailableError, Model,
                   get_model, register)
from . import exact  # noqa: F401  (registers "exact")

__all__ = ["Model", "REGISTRY", "register", "get_model", "SUMMARY_FIELDS", "HISTORY_FIELDS",
           "FieldUnavailableError"]
