"""The uniform API: ``summary`` and ``history`` for every registered model."""
from __future__ import annotations

import warnings
from collections.abc import Sequence
from typing import Any, Protocol, TypeVar, cast, overload

import numpy as np

from . import params
from .exact import inverse as _inverse
from .exact.force_end import check_contact_end
from .models import HISTORY_FIELDS, SUMMARY_FIELDS, Model, get_model
from .typing import FloatArray, RealArrayLike

__all__ = ["Summary", "History", "summary", "history", "lam_from_summary", "lam_for"]


_R_co = TypeVar("_R_co", covariant=True)


class SceneLike(Protocol[_R_co]):
    """What :func:`summary` still accepts instead of a lambda, deprecated: an object that
    computes its own result (``zener_sym.Scene``, whose one route to its result is
    ``Scene.result``; this layer does not import the scene layer above it)."""

    def result(self, model: str | None = None, **options: Any) -> _R_co: ...


class _Fields:
    """Named dimensionless fields; asking for one the model cannot give raises a clear error."""

    _all: tuple[str, ...] = ()
    _kind = ""

    def __init__(self, model: Model, values: dict[str, FloatArray], scalar: bool,
                 skipped: tuple[str, ...] = ()) -> None:
        self.model: str = model.name
        self._model = model
        self._values = values
        self._scalar = scalar
        self._skipped = skipped

    def __getattr__(self, name: str) -> Any:
        # Any: a field is a float for a scalar lambda and an array otherwise
        if name.startswith("_"):
            raise AttributeError(name)
        if name in self._values:
            v = self._values[name]
            return float(v.reshape(-1)[0]) if self._scalar else v
        if name in self._skipped:
            asked = tuple(f for f in self.fields if f != "tau")
            raise AttributeError(f"{name!r} was not computed: this history was asked for "
                                 f"fields={asked!r}; include {name!r} in fields= (or leave "
                                 f"fields out for every field)")
        if name in self._all:
            raise self._model.unavailable(name, self._kind)
        raise AttributeError(f"{type(self).__name__} has no field {name!r}; fields: "
                             f"{', '.join(self._all)}")

    @property
    def fields(self) -> tuple[str, ...]:
        """The fields this model gave, in table order.

        Returns
        -------
        tuple of str

        Examples
        --------
        >>> import zener_sym as zs
        >>> zs.summary(0.5, model="hertz").fields
        ('lam', 'delta_m', 'tau_dc', 'tau_d', 'tau_dr', 'eta', 'e', 'F_m', 'impulse', 'int_F2', 'xi')
        >>> zs.history(0.5, [0.0, 1.0], fields="force").fields
        ('tau', 'force')
        """
        return tuple(f for f in self._all if f in self._values)

    def as_dict(self) -> dict[str, Any]:
        """The fields as a dict, in table order (floats for a scalar lambda, arrays otherwise).

        Returns
        -------
        dict
            Field name -> value, for every field in :attr:`fields`.

        Examples
        --------
        >>> import zener_sym as zs
        >>> d = zs.summary(0.5).as_dict()
        >>> list(d)[:4], round(d["e"], 4)
        (['lam', 'delta_m', 'tau_dc', 'tau_d'], 0.4369)
        """
        return {f: getattr(self, f) for f in self.fields}

    def __repr__(self) -> str:
        body = ", ".join(f"{f}={getattr(self, f)!r}" if self._scalar else f"{f}=<array>"
                         for f in self.fields)
        return f"{type(self).__name__}(model={self.model!r}, {body})"


class Summary(_Fields):
    """Dimensionless summary of one impact (or arrays of them): see ``SUMMARY_FIELDS``.

    lam, delta_m (max compression, Eq. 23/24), tau_dc (compression duration), tau_d (contact
    duration), tau_dr = tau_d - tau_dc, eta = tau_dr / tau_dc (Eq. 61), e (restitution,
    -delta'(tau_d)), F_m (maximum of the model's force history: delta_m^{3/2} where the force is
    delta^{3/2}, Hunter's amplitude for hunter), impulse (I at tau_d, Eq. 47), int_F2 (integral of F^2
    over the contact, Eq. 76), xi = 2 I - I^2 (Eq. 69).

    Made by :func:`summary`; a field is a float for a scalar lambda and an array of lambda's
    shape otherwise. A field the model cannot give raises ``FieldUnavailableError``.

    Parameters
    ----------
    model : zener_sym.models.Model
        The registered model that computed the values.
    values : dict of str to numpy.ndarray
        Field name -> array of lambda's shape.
    scalar : bool
        True for a scalar lambda: the fields are then floats.
    skipped : tuple of str
        Not used by summaries (see :class:`History`).

    Attributes
    ----------
    model : str
        The model that computed it.
    fields : tuple of str
        The fields this model gave, in table order.

    Examples
    --------
    >>> import zener_sym as zs
    >>> s = zs.summary(0.5)
    >>> s.model, round(s.e, 4), round(s.xi, 4)
    ('exact', 0.4369, 0.8091)
    >>> round(s.impulse - (1 + s.e), 12)       # the exact model's impulse is 1 + e
    0.0
    >>> zs.summary(0.5, model="hunter").e
    Traceback (most recent call last):
    ...
    zener_sym.models.base.FieldUnavailableError: model 'hunter' does not give the summary field 'e'; it gives: lam, delta_m, tau_dc, tau_d, tau_dr, eta, F_m, impulse, int_F2
    """

    _all = SUMMARY_FIELDS
    _kind = "summary"


class History(_Fields):
    """Dimensionless histories of one impact (or arrays of them) on a time grid.

    The fields: tau, delta, velocity (sphere, 1 - I, Eq. 64), force (the model's contact force:
    delta^{3/2}, Eq. 45, for all but hunter's sine, Eq. 52), impulse (Eq. 47; also the plate
    deflection w-bar, Eq. 66). From the model's tau_d on, delta and the force are exactly 0 and
    the impulse keeps its final value.

    Made by :func:`history`; every field has the broadcast shape of lambda and tau.

    Parameters
    ----------
    model : zener_sym.models.Model
        The registered model that computed the values.
    values : dict of str to numpy.ndarray
        Field name -> array of the broadcast shape, ``tau`` included.
    scalar : bool
        False: history fields stay arrays (0-d for scalar lambda and tau).
    skipped : tuple of str
        History fields the caller left out of ``fields=``; asking for one says how to get it.

    Attributes
    ----------
    model : str
        The model that computed it.
    fields : tuple of str
        ``tau`` and the history fields computed.

    Examples
    --------
    >>> import numpy as np, zener_sym as zs
    >>> h = zs.history(0.5, np.linspace(0.0, 4.0, 5))
    >>> h.fields
    ('tau', 'delta', 'velocity', 'force', 'impulse')
    >>> bool(np.all(h.deflection == h.impulse))      # the plate deflection is the impulse
    True
    """

    _all = ("tau",) + HISTORY_FIELDS
    _kind = "history"

    @property
    def deflection(self) -> FloatArray:
        """Plate deflection w-bar at the centre, equal to the impulse (Eq. 66).

        Returns
        -------
        numpy.ndarray
            w-bar at each time, of the broadcast shape of lambda and tau.

        Examples
        --------
        >>> import zener_sym as zs
        >>> h = zs.history(1.0, [0.0, 10.0])
        >>> [round(float(w), 4) for w in h.deflection]     # 0, then I(tau_d) = 1 + e
        [0.0, 1.1841]
        """
        return cast(FloatArray, self.impulse)


def _validated(model_name: str, lam: RealArrayLike) -> tuple[Model, FloatArray]:
    model = get_model(model_name)
    arr = params.as_lambda(lam)
    if model.lam_bound is not None:
        params.check_lambda_bound(arr, model.lam_bound, model.name, model.bound_reason)
    return model, arr


@overload
def summary(lam: RealArrayLike, model: str | None = None, **options: Any) -> Summary: ...


@overload
def summary(lam: SceneLike[_R_co], model: str | None = None, **options: Any) -> _R_co: ...


def summary(lam: RealArrayLike | SceneLike[Any], model: str | None = None,
            **options: Any) -> Any:
    """Summary quantities of the impact for inelasticity parameter(s) ``lam``, or for a scene.

    Parameters
    ----------
    lam : float or array_like
        Zener's inelasticity parameter lambda >= 0 (Eq. 11). An array gives array fields.
        (A ``zener_sym.Scene`` is still accepted, with a ``DeprecationWarning``: a scene's
        dimensional result is ``Scene.result()``.)
    model : str
        One of ``zener_sym.MODELS`` (default "exact" for a lambda).
    **options
        Model options, e.g. ``rtol`` or ``backend="mpmath", dps=40`` for ``exact``.

    Returns
    -------
    Summary
        The dimensionless summary (for a deprecated ``Scene``, its ``SceneResult``).

    Raises
    ------
    ValueError
        For a bad lambda, an unknown model or option, or lambda outside the model's validity.

    Warns
    -----
    DeprecationWarning
        For a ``Scene`` in place of lambda: use ``scene.result(...)``.

    Examples
    --------
    >>> import zener_sym as zs
    >>> s = zs.summary(1.0)                     # exact model
    >>> round(s.e, 4), round(s.tau_d, 4)
    (0.1841, 4.3876)
    >>> zs.summary([0.5, 1.0]).e.shape
    (2,)
    """
    if callable(getattr(lam, "result", None)):
        # A Scene answers for itself (this layer does not import the scene layer above it).
        warnings.warn("zener_sym.summary(scene) is deprecated: use scene.result(...), the one "
                      "route from a scene to its result", DeprecationWarning, stacklevel=2)
        return cast("SceneLike[Any]", lam).result(model=model, **options)
    if model is None:
        model = "exact"
    m, arr = _validated(model, cast(RealArrayLike, lam))
    m.check_options(options)
    flat = arr.reshape(-1)
    raw = m._summary(flat, **options)
    values = {k: np.asarray(v, dtype=float).reshape(arr.shape) for k, v in raw.items()}
    values["lam"] = arr.copy()
    _no_silent_nan(values, m)
    return Summary(m, values, scalar=arr.ndim == 0)


def history(lam: RealArrayLike, tau: RealArrayLike, model: str = "exact",
            fields: str | Sequence[str] | None = None, **options: Any) -> History:
    """Histories delta, velocity, force and impulse at times ``tau`` for ``lam``.

    Parameters
    ----------
    lam : float or array_like
        Zener's inelasticity parameter lambda >= 0 (Eq. 11).
    tau : float or array_like
        Dimensionless times tau = t / T >= 0 (Eq. 9). ``lam`` and ``tau`` broadcast by numpy
        rules (lam of shape (M, 1) with tau of shape (N,) gives (M, N)); every field has that
        broadcast shape, () for scalars.
    model : str
        One of ``zener_sym.MODELS`` (default "exact", as for ``summary``).
    fields : str or sequence of str, optional
        Only these of ``delta``, ``velocity``, ``force``, ``impulse`` (default: every field the
        model gives). Models that can skip work do: ham1's force alone needs no impulse quadrature.
    **options
        Model options, as for ``summary``.

    Returns
    -------
    History
        ``tau``, ``delta``, ``velocity`` (sphere, 1 - I, Eq. 64), ``force`` (Eq. 45) and
        ``impulse`` (Eq. 47, also the plate deflection). Past the end of contact delta and the
        force are 0 and the impulse keeps its final value.

    Raises
    ------
    ValueError
        For a bad lambda or tau, shapes that do not broadcast, an unknown model, field or
        option, or lambda outside the model's validity.

    Examples
    --------
    >>> import zener_sym as zs
    >>> h = zs.history(1.0, [0.0, 1.0, 2.0])
    >>> h.force.shape
    (3,)
    >>> round(float(h.delta[0]), 12), round(float(h.velocity[0]), 12)   # the start of contact
    (0.0, 1.0)
    >>> zs.history(1.0, 0.5).force.shape   # scalars in, 0-d out
    ()
    """
    m, arr = _validated(model, lam)
    m.check_options(options)
    want = _history_fields(m, fields)
    t = params.as_tau(tau)
    try:
        lam_b, tau_b = np.broadcast_arrays(arr, t)
    except ValueError:
        raise ValueError(
            f"lambda of shape {arr.shape} does not broadcast against tau of shape {t.shape}"
        ) from None
    # lambda stays a broadcast view (a column of lambda against a grid of tau is not copied
    # to the grid's size: models detect it and work per line). tau is the api's own copy
    # (as_tau converts with a copy), so it is History.tau as well, without a second copy; it
    # is read-only while the model runs, so a model cannot change it
    tau_c = np.ascontiguousarray(tau_b) if tau_b.shape != t.shape else t
    tau_c.flags.writeable = False
    raw = m.history_values(lam_b, tau_c, want, **options)
    tau_c.flags.writeable = True
    # every field has the broadcast shape, () for scalar lambda and tau
    values = {k: np.asarray(v, dtype=float).reshape(tau_b.shape) for k, v in raw.items()}
    values["tau"] = tau_c.reshape(tau_b.shape)
    _no_silent_nan(values, m)
    skipped = tuple(f for f in m.history_fields if f not in want)
    return History(m, values, scalar=False, skipped=skipped)


def lam_from_summary(e: RealArrayLike | None = None, xi: RealArrayLike | None = None,
                     tau_d: RealArrayLike | None = None,
                     contact_end: str = "delta") -> float | FloatArray:
    """The lambda whose exact solution has a given restitution, energy loss or contact duration.

    The inverse of :func:`summary` (lambda is Zener's parameter, Eq. 11): lambda from a field of
    the summary (``zener_sym.lam_from_dissipation`` is the grains' forward map, lambda from the
    dissipative constant A). Called ``lam_for`` before (that name still works, with a
    ``DeprecationWarning``). Give exactly one of
    ``e``, ``xi``, ``tau_d``. Solved on the exact model's Chebyshev tables (0 <= lambda <= 1000)
    by a safeguarded Newton iteration whose derivative is the tables' own
    (``zener_sym.exact.table.summary_derivative``), all values at once:
    ``summary(lam_from_summary(e=x)).e`` is within 1e-12 relative of x (the tables' accuracy
    against the true solution is 1e-11).

    Parameters
    ----------
    e : float or array_like, optional
        Coefficient of restitution, e(1000) <= e <= 1 (e = 1 gives lambda = 0).
    xi : float or array_like, optional
        Energy-loss ratio xi = 1 - e^2 (Eq. 69), 0 <= xi <= xi(1000).
    tau_d : float or array_like, optional
        Dimensionless contact duration (Eq. 9), on the range of lambda where tau_d(lambda) is
        monotone (``zener_sym.exact.inverse.tau_d_branch``; the whole table for the plate).
    contact_end : {"delta", "force"}
        The end of contact, as for :func:`summary`.

    Returns
    -------
    float or numpy.ndarray
        lambda, a float for a scalar and an array of the input's shape otherwise.

    Raises
    ------
    ValueError
        None or several quantities given, a value that is not a real number, or a value the
        tables do not reach on [0, 1000] (the message gives the reachable range).

    Examples
    --------
    >>> import zener_sym as zs
    >>> lam = zs.lam_from_summary(e=0.5)
    >>> round(lam, 6), round(zs.summary(lam).e, 12)
    (0.417662, 0.5)
    >>> zs.lam_from_summary(e=[1.0, 0.9]).round(6)
    array([0.      , 0.061501])
    """
    end = check_contact_end(contact_end)
    given = [v for v in (e, xi, tau_d) if v is not None]
    scalar = len(given) == 1 and np.ndim(given[0]) == 0
    lam = np.asarray(_inverse.lam_for(e=e, xi=xi, tau_d=tau_d, contact_end=end), dtype=float)
    return float(lam) if scalar else lam


def lam_for(e: RealArrayLike | None = None, xi: RealArrayLike | None = None,
            tau_d: RealArrayLike | None = None, contact_end: str = "delta") -> float | FloatArray:
    """Deprecated name of :func:`lam_from_summary`, kept for one release: it issues a
    ``DeprecationWarning``, then returns what :func:`lam_from_summary` returns for the same
    arguments."""
    warnings.warn("lam_for is deprecated: use lam_from_summary (lambda from e, xi or tau_d; "
                  "lam_from_dissipation is lambda from the grains' dissipative constant A)",
                  DeprecationWarning, stacklevel=2)
    return lam_from_summary(e=e, xi=xi, tau_d=tau_d, contact_end=contact_end)


def _history_fields(model: Model, fields: object) -> tuple[str, ...]:
    """The history fields asked for, checked against what the model gives."""
    if fields is None:
        return tuple(model.history_fields)
    if isinstance(fields, str):
        fields = (fields,)
    try:
        fields = tuple(cast("Sequence[str]", fields))  # any iterable; else ValueError below
    except TypeError:
        raise ValueError(f"fields must be a field name or a sequence of them, got {fields!r}; "
                         f"allowed: {', '.join(HISTORY_FIELDS)}") from None
    if not fields:
        raise ValueError(f"fields is empty; allowed: {', '.join(HISTORY_FIELDS)}")
    for f in fields:
        if f not in HISTORY_FIELDS:
            raise ValueError(f"unknown history field {f!r}; allowed: {', '.join(HISTORY_FIELDS)}")
        if f not in model.history_fields:
            raise model.unavailable(f, "history")
    return tuple(f for f in model.history_fields if f in fields)


def _no_silent_nan(values: dict[str, FloatArray], model: Model) -> None:
    for k, v in values.items():
        if not np.all(np.isfinite(v)):
            raise FloatingPointError(
                f"model {model.name!r} produced a non-finite {k}; this is a bug, please report "
                f"it with the lambda values used"
            )
