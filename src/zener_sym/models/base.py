"""The model interface and the registry every model plugs into with one entry."""
from __future__ import annotations

import numpy as np

__all__ = ["Model", "REGISTRY", "register", "get_model", "SUMMARY_FIELDS", "HISTORY_FIELDS",
           "FieldUnavailableError"]

#: Dimensionless summary quantities, in the order tables print them.
SUMMARY_FIELDS = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m", "impulse",
                  "int_F2", "xi")
#: Dimensionless history quantities (besides tau).
HISTORY_FIELDS = ("delta", "velocity", "force", "impulse")


class FieldUnavailableError(ValueError):
    """A model was asked for a quantity it cannot give (a ``ValueError``).

    Examples
    --------
    >>> import zener_sym as zs
    >>> try:
    ...     zs.summary(0.1, model="reed").e
    ... except zs.FieldUnavailableError as exc:
    ...     print(exc)
    model 'reed' does not give the summary field 'e'; it gives: lam, delta_m, tau_dc, tau_d, tau_dr, eta, F_m, impulse, int_F2
    """


class Model:
    """Base class: a named way of computing the summary and/or the history of Eq. (10).

    Subclasses set ``name``, ``description``, ``summary_fields``, ``history_fields`` and, when
    the model is valid only below some lambda, ``lam_bound`` (exclusive) with ``bound_reason``.
    They implement ``_summary(lam_1d, **options) -> dict`` and ``_history(lam, tau, **options)
    -> dict`` on validated float arrays (tau and lam already broadcast to one shape).
    """

    name: str = ""
    description: str = ""
    summary_fields: tuple = ()
    history_fields: tuple = ()
    lam_bound: float | None = None
    bound_reason: str = ""
    options: tuple = ()  # keyword options the model accepts, e.g. ("rtol", "backend")
    #: False for a model left out of the error-envelope table (so select_model never picks it)
    in_envelopes: bool = True

    def unavailable(self, field: str, kind: str = "summary") -> FieldUnavailableError:
        have = self.summary_fields if kind == "summary" else self.history_fields
        return FieldUnavailableError(
            f"model {self.name!r} does not give the {kind} field {field!r}; it gives: "
            f"{', '.join(have) or 'nothing'}"
        )

    def check_options(self, options: dict) -> None:
        unknown = sorted(set(options) - set(self.options))
        if unknown:
            raise ValueError(
                f"model {self.name!r} takes no option {unknown[0]!r}; allowed options: "
                f"{', '.join(self.options) or 'none'}"
            )

    def valid(self, lam: np.ndarray) -> np.ndarray:
        """Mask of the lambdas at which the model answers with its default options (below
        ``lam_bound``); harnesses that measure every model over a grid use it. A model valid on
        a set that is not an interval from 0 overrides it."""
        lam = np.asarray(lam, dtype=float)
        return np.ones(lam.shape, bool) if self.lam_bound is None else lam < self.lam_bound

    def _summary(self, lam: np.ndarray, **options) -> dict:  # pragma: no cover - interface
        raise self.unavailable("summary")

    def _history(self, lam: np.ndarray, tau: np.ndarray, **options) -> dict:  # pragma: no cover
        raise self.unavailable("history", "history")

    #: True when ``_history`` takes ``fields=`` and computes only those; other models compute
    #: every field and ``history_values`` drops the rest.
    selects_fields: bool = False

    def history_values(self, lam: np.ndarray, tau: np.ndarray, fields: tuple, **options) -> dict:
        """The history ``fields`` (a checked subset of ``history_fields``) at lam, tau."""
        if self.selects_fields:
            values = self._history(lam, tau, fields=fields, **options)
        else:
            values = self._history(lam, tau, **options)
        return {f: values[f] for f in fields}


REGISTRY: dict[str, Model] = {}


def register(model: Model) -> Model:
    """Add ``model`` to the registry under ``model.name`` (one entry per model)."""
    if not model.name or model.name in REGISTRY:
        raise ValueError(f"model name {model.name!r} is empty or already registered")
    REGISTRY[model.name] = model
    return model


def get_model(name) -> Model:
    """The registered model called ``name``; ValueError listing the allowed names otherwise."""
    if not isinstance(name, str) or name not in REGISTRY:
        raise ValueError(f"unknown model {name!r}; allowed: {', '.join(REGISTRY)}")
    return REGISTRY[name]
