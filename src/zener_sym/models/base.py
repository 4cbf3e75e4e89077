"""The model interface and the registry every model plugs into with one entry."""
from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any, overload

import numpy as np
import numpy.typing as npt

from ..typing import FloatArray, RealArrayLike

__all__ = ["Model", "REGISTRY", "register", "get_model", "SUMMARY_FIELDS", "HISTORY_FIELDS",
           "FieldUnavailableError", "FieldValues", "computed_bound"]

#: Dimensionless summary quantities, in the order tables print them.
SUMMARY_FIELDS: tuple[str, ...] = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e",
                                   "F_m", "impulse", "int_F2", "xi")
#: Dimensionless history quantities (besides tau).
HISTORY_FIELDS: tuple[str, ...] = ("delta", "velocity", "force", "impulse")

#: What a model's ``_summary`` and ``_history`` return: field name -> float array.
FieldValues = dict[str, FloatArray]


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
    the model is valid only below some lambda, ``lam_bound`` (exclusive) with ``bound_reason``
    (a class attribute, or :class:`computed_bound` when it is known only at run time).
    They implement ``_summary(lam_1d, **options) -> FieldValues`` and ``_history(lam, tau,
    **options) -> FieldValues`` on validated float arrays (tau and lam already broadcast to one
    shape); the api calls :meth:`check_options` first, so they see only their own options.
    """

    name: str = ""
    description: str = ""
    summary_fields: tuple[str, ...] = ()
    history_fields: tuple[str, ...] = ()
    lam_bound: float | None = None
    bound_reason: str = ""
    options: tuple[str, ...] = ()  # keyword options the model accepts, e.g. ("rtol", "backend")
    #: False for a model left out of the error-envelope table (so select_model never picks it)
    in_envelopes: bool = True

    def unavailable(self, field: str, kind: str = "summary") -> FieldUnavailableError:
        """The error for a ``field`` this model does not give (returned, for the caller to raise).

        Parameters
        ----------
        field : str
            The field asked for.
        kind : {"summary", "history"}
            Which of the model's field lists the message quotes.

        Returns
        -------
        FieldUnavailableError
            Its message names the model, the field and the fields the model gives.
        """
        have = self.summary_fields if kind == "summary" else self.history_fields
        return FieldUnavailableError(
            f"model {self.name!r} does not give the {kind} field {field!r}; it gives: "
            f"{', '.join(have) or 'nothing'}"
        )

    def check_options(self, options: Mapping[str, object]) -> None:
        """Refuse a keyword option the model does not take.

        Parameters
        ----------
        options : mapping of str
            The keyword options given to ``summary`` or ``history``.

        Raises
        ------
        ValueError
            For an option not in ``self.options``; the message lists the allowed ones.
        """
        unknown = sorted(set(options) - set(self.options))
        if unknown:
            raise ValueError(
                f"model {self.name!r} takes no option {unknown[0]!r}; allowed options: "
                f"{', '.join(self.options) or 'none'}"
            )

    def valid(self, lam: RealArrayLike) -> npt.NDArray[np.bool_]:
        """Mask of the lambdas at which the model answers with its default options (below
        ``lam_bound``); harnesses that measure every model over a grid use it. A model valid on
        a set that is not an interval from 0 overrides it.

        Parameters
        ----------
        lam : float or array_like
            Lambda values (not checked: NaN is simply not valid).

        Returns
        -------
        numpy.ndarray of bool
            Of the shape of ``lam``.
        """
        lam = np.asarray(lam, dtype=float)
        bound = self.lam_bound
        return np.ones(lam.shape, bool) if bound is None else lam < bound

    # The options are each model's own keywords (``stiffness=``, ``rtol=``, ...): ``*args: Any,
    # **options: Any`` is mypy's gradual signature, which any override's keywords satisfy.
    def _summary(self, lam: FloatArray, *args: Any,
                 **options: Any) -> FieldValues:  # pragma: no cover - interface
        raise self.unavailable("summary")

    def _history(self, lam: FloatArray, tau: FloatArray, *args: Any,
                 **options: Any) -> FieldValues:  # pragma: no cover - interface
        raise self.unavailable("history", "history")

    #: True when ``_history`` takes ``fields=`` and computes only those; other models compute
    #: every field and ``history_values`` drops the rest.
    selects_fields: bool = False

    def history_values(self, lam: FloatArray, tau: FloatArray, fields: Sequence[str],
                       **options: Any) -> FieldValues:
        """The history ``fields`` at lam, tau.

        Parameters
        ----------
        lam, tau : numpy.ndarray
            Validated float arrays of one shape (lam may be a broadcast view).
        fields : sequence of str
            A checked subset of ``history_fields``.
        **options
            The model's options (already checked by :meth:`check_options`).

        Returns
        -------
        dict of str to numpy.ndarray
            Exactly ``fields``.
        """
        if self.selects_fields:
            values = self._history(lam, tau, fields=fields, **options)
        else:
            values = self._history(lam, tau, **options)
        return {f: values[f] for f in fields}


class computed_bound:
    """A model's ``lam_bound`` computed when first read, for a bound that cannot be known when
    the model registers (from a generated module, which ``zener-sym regen kernels`` must be able to
    rewrite when it is broken, or from another model's result). Used like ``property``, and
    read-only like it.

    Examples
    --------
    >>> class Half(Model):
    ...     name = "half"
    ...     @computed_bound
    ...     def lam_bound(self) -> float:
    ...         return 0.5
    >>> Half().lam_bound
    0.5
    """

    def __init__(self, compute: Callable[[Any], float]) -> None:
        self._compute = compute
        self.__doc__ = compute.__doc__

    @overload
    def __get__(self, model: None, owner: type[Model] | None = None) -> computed_bound: ...

    @overload
    def __get__(self, model: Model, owner: type[Model] | None = None) -> float: ...

    def __get__(self, model: Model | None,
                owner: type[Model] | None = None) -> float | computed_bound:
        return self if model is None else self._compute(model)

    def __set__(self, model: Model, value: float | None) -> None:
        raise AttributeError(f"lam_bound of model {model.name!r} is computed; it cannot be set")


REGISTRY: dict[str, Model] = {}


def register(model: Model) -> Model:
    """Add ``model`` to the registry under ``model.name`` (one entry per model).

    Parameters
    ----------
    model : Model
        An instance with a ``name`` not registered yet.

    Returns
    -------
    Model
        ``model`` itself.

    Raises
    ------
    ValueError
        For an empty name or one already registered.
    """
    if not model.name or model.name in REGISTRY:
        raise ValueError(f"model name {model.name!r} is empty or already registered")
    REGISTRY[model.name] = model
    return model


def get_model(name: str) -> Model:
    """The registered model called ``name``.

    Parameters
    ----------
    name : str
        One of ``REGISTRY``'s keys (``zener_sym.MODELS``).

    Returns
    -------
    Model

    Raises
    ------
    ValueError
        For any other value; the message lists the allowed names.
    """
    if not isinstance(name, str) or name not in REGISTRY:
        raise ValueError(f"unknown model {name!r}; allowed: {', '.join(REGISTRY)}")
    return REGISTRY[name]
