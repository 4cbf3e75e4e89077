"""The model ``finite-plate``: the sphere on a bounded Kirchhoff plate, every contact to the end.

Zener's plate (Eq. 10) is infinite: the load point answers the force with the velocity
lambda F. A bounded plate rings: in Zener's scales (:mod:`zener_sym.plate.modal`)

    x'' = -F,   y_n'' + omega_n^2 y_n = c_n F,   w = sum_n y_n + C_res F,
    delta = x - w,   F = max(delta, 0)^{3/2},

with omega_n = beta Omega_n and c_n = 8 lambda beta psi_n, where beta = t_0 sqrt(D/(rho h))/L^2
is the plate-size parameter (L the circle's radius, or sqrt(a b) for an a x b rectangle), and
Omega_n, psi_n belong to the shape, the support and the impact point alone
(:func:`zener_sym.plate.modes.modal_plate`). As beta -> 0 the modal kernel becomes Zener's
dashpot and this model becomes ``exact``. :func:`zener_sym.plate.solver.solve` integrates it
contact by contact, to the proved end (the ball beyond the largest deflection the plate's
energy allows).

Options (``summary(lam, model="finite-plate", beta=..., support=..., ...)``):

``beta``
    the plate-size parameter, > 0 (required);
``support``
    ``"clamped"`` or ``"simply-supported"`` (required; the rectangle: simply supported);
``shape``
    ``"circle"`` (default, struck at its centre) or ``"rectangle"``;
``aspect``
    a/b of the rectangle (default 1);
``impact``
    the rectangle's impact point as fractions (x/a, y/b), each in (0, 1) (default the centre);
``nu``
    Poisson's ratio of the plate (default 0.3; only the simply supported circle depends on it);
``rtol``
    the accuracy asked of the solver in e (default 1e-6): it chooses the modes and the step;
``loss``
    a modal loss factor in [0, 1) (default 0, undamped);
``n_modes``
    the number of modes (default: the solver's choice for ``rtol``).

The summary: ``e`` is the ball's restitution after the last contact, ``impulse`` = 1 + e its
whole impulse, ``xi`` = 1 - e^2 the energy left in the plate; ``tau_d``, ``tau_dc``, ``tau_dr``,
``eta`` and ``delta_m`` are those of the first contact (Zener's quantities, to compare), ``F_m``
the largest force of every contact. :func:`impact` gives every contact.
"""
from __future__ import annotations

import functools
import math
import numbers
import os
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..plate.modal import ModalPlate
from ..plate.modes import modal_plate
from ..plate.result import PlateImpact
from ..plate.solver import RTOL_MAX, RTOL_MIN, choose_modes, solve
from ..typing import FloatArray
from .base import FieldValues, Model, register

__all__ = ["FinitePlate", "impact", "summary_of", "history_of", "check_plate_options",
           "check_support", "check_loss", "max_modes", "SUPPORTS", "SHAPES",
           "DEFAULT_RTOL"]

SUPPORTS = ("clamped", "simply-supported")
SHAPES = ("circle", "rectangle")
#: The solver's accuracy unless asked otherwise.
DEFAULT_RTOL = 1e-6
#: Bytes the solver keeps per mode (a few float arrays of the modes' size, with margin).
_BYTES_PER_MODE = 64 * 8


def max_modes() -> int:
    """The most modes this machine can hold: a quarter of its physical memory at
    ``_BYTES_PER_MODE`` bytes per mode (where the memory is not known, 2**24)."""
    try:
        memory = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):  # no sysconf on this platform
        return 2**24
    return max(1, int(memory // 4 // _BYTES_PER_MODE))


def _real(value: object, name: str, lo: float, hi: float, lo_open: bool = True,
          hi_open: bool = True) -> float:
    ok = not isinstance(value, bool) and isinstance(value, numbers.Real) \
        and math.isfinite(value)
    if ok:
        v = float(value)  # type: ignore[arg-type]
        ok = (v > lo if lo_open else v >= lo) and (v < hi if hi_open else v <= hi)
    if not ok:
        rng = f"{lo:g} {'<' if lo_open else '<='} {name} {'<' if hi_open else '<='} {hi:g}"
        raise ValueError(f"model 'finite-plate': {name} must be a finite real with {rng}, "
                         f"got {value!r}")
    return float(value)  # type: ignore[arg-type]


def check_support(support: object, shape: str = "circle") -> str:
    """``support`` checked: one of :data:`SUPPORTS` (for a rectangle, ``"simply-supported"``).

    Parameters
    ----------
    support : object
        The support asked for.
    shape : {"circle", "rectangle"}
        The plate's shape.

    Returns
    -------
    str
        ``support`` itself; a ValueError naming the allowed ones for any other.

    Examples
    --------
    >>> check_support("clamped")
    'clamped'
    >>> check_support("pinned")
    Traceback (most recent call last):
    ...
    ValueError: unknown support 'pinned'; allowed: clamped, simply-supported
    """
    allowed = SUPPORTS if shape == "circle" else ("simply-supported",)
    if not isinstance(support, str) or support not in SUPPORTS:
        raise ValueError(f"unknown support {support!r}; allowed: {', '.join(allowed)}")
    if support not in allowed:
        raise ValueError(f"support {support!r} is not modelled for a {shape}; allowed: "
                         f"{', '.join(allowed)} (its Navier modes)")
    return support


def check_loss(loss: object) -> float:
    """A modal loss factor checked: a finite real in [0, 1).

    Parameters
    ----------
    loss : object
        The loss factor asked for (0: undamped).

    Returns
    -------
    float
        ``loss`` as a float; a ValueError for anything else.

    Examples
    --------
    >>> check_loss(0.01)
    0.01
    >>> check_loss(1.0)
    Traceback (most recent call last):
    ...
    ValueError: loss factor must be a finite real with 0 <= loss < 1, got 1.0
    """
    if isinstance(loss, bool) or not isinstance(loss, numbers.Real) \
            or not math.isfinite(loss) or not 0.0 <= float(loss) < 1.0:
        raise ValueError(f"loss factor must be a finite real with 0 <= loss < 1, got {loss!r}")
    return float(loss)


def check_plate_options(options: Mapping[str, Any]) -> dict[str, Any]:
    """The ``finite-plate`` options checked, with their defaults (module docstring).

    Parameters
    ----------
    options : mapping
        The keyword options given to the model.

    Returns
    -------
    dict
        beta, support, shape, aspect, impact, nu, rtol, loss, n_modes.

    Raises
    ------
    ValueError
        For a missing beta or support, an unknown support or shape, an impact point outside
        the plate, a loss factor outside [0, 1), or a mode count that is not a positive
        integer this machine can hold (:func:`max_modes`).
    """
    if "beta" not in options or "support" not in options:
        raise ValueError("model 'finite-plate' needs, besides lambda, the options beta (the "
                         "plate-size parameter, > 0) and support (clamped or simply-supported)")
    beta = _real(options["beta"], "beta", 0.0, math.inf)
    shape = options.get("shape", "circle")
    if not isinstance(shape, str) or shape not in SHAPES:
        raise ValueError(f"model 'finite-plate': unknown shape {shape!r}; allowed: "
                         f"{', '.join(SHAPES)}")
    support = check_support(options["support"], shape)
    aspect = _real(options.get("aspect", 1.0), "aspect", 0.0, math.inf)
    imp = options.get("impact", (0.5, 0.5))
    if isinstance(imp, str) or not isinstance(imp, (tuple, list, np.ndarray)) or len(imp) != 2:
        raise ValueError(f"model 'finite-plate': impact must be a pair (x/a, y/b), got {imp!r}")
    impact_fr = (_real(imp[0], "impact x/a", 0.0, 1.0), _real(imp[1], "impact y/b", 0.0, 1.0))
    if shape == "circle" and impact_fr != (0.5, 0.5):
        raise ValueError("model 'finite-plate': the circle is struck at its centre; impact is "
                         "for the rectangle")
    nu = _real(options.get("nu", 0.3), "nu", -1.0, 0.5)
    rtol = _real(options.get("rtol", DEFAULT_RTOL), "rtol", RTOL_MIN, RTOL_MAX, lo_open=False,
                 hi_open=False)
    loss = check_loss(options.get("loss", 0.0))
    n_modes = options.get("n_modes")
    if n_modes is not None:
        top = max_modes()
        if isinstance(n_modes, bool) or not isinstance(n_modes, numbers.Integral) \
                or not 1 <= int(n_modes) <= top:
            raise ValueError(f"model 'finite-plate': n_modes must be an integer with 1 <= "
                             f"n_modes <= {top} (what this machine's memory holds), got "
                             f"{n_modes!r}")
        n_modes = int(n_modes)
    return {"beta": beta, "support": support, "shape": shape, "aspect": aspect,
            "impact": impact_fr, "nu": nu, "rtol": rtol, "loss": loss, "n_modes": n_modes}


def _key(lam: float, options: Mapping[str, Any]) -> tuple[Any, ...]:
    lam_v = _real(lam, "lambda", 0.0, math.inf, lo_open=False)
    o = check_plate_options(options)
    return (lam_v, o["beta"], o["support"], o["shape"], o["aspect"], o["impact"], o["nu"],
            o["rtol"], o["loss"], o["n_modes"])


def impact(lam: float, **options: Any) -> PlateImpact:
    """The finite plate's impact at one lambda, with every contact
    (:class:`zener_sym.plate.solver.PlateImpact`).

    Parameters
    ----------
    lam : float
        Zener's lambda (Eq. 11), >= 0.
    **options
        As the model's (module docstring); beta and support are required.

    Returns
    -------
    zener_sym.plate.solver.PlateImpact
        ``contacts`` (one per contact, dimensionless) and ``e`` (after the last contact).

    Raises
    ------
    ValueError
        For a bad lambda or option (:func:`check_plate_options`).
    """
    return _impact(*_key(lam, options))


@functools.lru_cache(maxsize=256)
def _solved(lam: float, beta: float, support: str, shape: str, aspect: float,
            impact_fr: tuple[float, float], nu: float, rtol: float, loss: float,
            n_modes: int | None) -> tuple[ModalPlate, PlateImpact]:
    # one solve serves the summary, the history and a scene's contacts
    def make(n: int) -> ModalPlate:
        return modal_plate(lam, beta, shape=shape, support=support, n_modes=n, aspect=aspect,
                           impact=impact_fr, nu=nu)

    try:
        if n_modes is None:
            return choose_modes(make, rtol=rtol, loss=loss)
        plate = make(n_modes)
        return plate, solve(plate, rtol=rtol, loss=loss)
    except RuntimeError as exc:  # the solver's limits (mode count, steps): say which input
        raise ValueError(f"model 'finite-plate' cannot solve lambda = {lam:g}, beta = {beta:g} "
                         f"({shape}, {support}) to rtol {rtol:g}: {exc}; a larger rtol or "
                         "plate-size parameter beta (a smaller plate) is within reach") from None


def _impact(*args: Any) -> PlateImpact:
    return _solved(*args)[1]


def _force_nodes(*args: Any) -> tuple[FloatArray, FloatArray]:
    """The force on the solver's finest grid: node times and forces, every contact (0 between
    contacts), piecewise linear in between (the solver's own force representation)."""
    res = _solved(*args)[1]
    return res.force_time, res.force


def history_of(t_nodes: FloatArray, f_nodes: FloatArray, tau: FloatArray) -> FieldValues:
    """Force, impulse, velocity and compression at ``tau`` from a piecewise-linear force.

    The force is linear between the nodes (0 before the first, after the last and between
    contacts); the impulse I is its exact integral and the ball's velocity 1 - I (in units of
    v_0); the compression is F^{2/3} (Hertz: F = delta^{3/2} in contact, 0 outside).
    """
    tau = np.asarray(tau, float)
    force = np.interp(tau, t_nodes, f_nodes, left=0.0, right=0.0)
    steps = np.diff(t_nodes)
    cum = np.concatenate(([0.0], np.cumsum(0.5 * (f_nodes[1:] + f_nodes[:-1]) * steps)))
    k = np.clip(np.searchsorted(t_nodes, tau, side="right") - 1, 0, len(t_nodes) - 1)
    u = np.clip(tau - t_nodes[k], 0.0, None)
    inside = (tau >= t_nodes[0]) & (tau < t_nodes[-1])
    impulse = np.where(inside, cum[k] + 0.5 * (f_nodes[k] + force) * u,
                       np.where(tau >= t_nodes[-1], cum[-1], 0.0))
    return {"force": force, "impulse": impulse, "velocity": 1.0 - impulse,
            "delta": np.power(force, 2.0 / 3.0)}


def summary_of(res: Any) -> dict[str, float]:
    """The model's summary fields from a :class:`zener_sym.plate.result.PlateImpact` (module
    docstring): the first contact's duration, compression time and largest compression
    (delta_m = F_peak^{2/3}: F = delta^{3/2} at every instant), every contact's largest force,
    and the restitution after the last contact."""
    first = res.contacts[0]
    tau_d, tau_dc = first.end - first.start, first.max_force_time - first.start
    e = float(res.e)
    return {"delta_m": first.max_force ** (2.0 / 3.0), "tau_dc": tau_dc, "tau_d": tau_d,
            "tau_dr": tau_d - tau_dc, "eta": (tau_d - tau_dc) / tau_dc, "e": e,
            "F_m": max(c.max_force for c in res.contacts), "impulse": 1.0 + e,
            "xi": 1.0 - e * e}


class FinitePlate(Model):
    """The model ``"finite-plate"`` (module docstring)."""

    name = "finite-plate"
    description = ("the sphere on a bounded Kirchhoff plate (circle clamped or simply "
                   "supported, or simply supported rectangle): modes plus the static "
                   "correction, every contact to the proved end (options beta, support, ...)")
    summary_fields = ("lam", "delta_m", "tau_dc", "tau_d", "tau_dr", "eta", "e", "F_m",
                      "impulse", "xi")
    history_fields = ("delta", "velocity", "force", "impulse")
    options = ("beta", "support", "shape", "aspect", "impact", "nu", "rtol", "loss", "n_modes")
    in_envelopes = False  # select_model never picks it: the scene's criterion does

    def valid(self, lam: Any) -> Any:
        """No lambda: the model needs the plate's options (beta, support), it has no defaults
        for them, so harnesses that run every model with its defaults leave it out."""
        return np.zeros(np.shape(lam), bool)

    def _summary(self, lam: FloatArray, **options: Any) -> FieldValues:
        out = {f: np.empty(lam.shape) for f in self.summary_fields if f != "lam"}
        for i, x in np.ndenumerate(lam):
            s = summary_of(impact(float(x), **options))
            for f in out:
                out[f][i] = s[f]
        return out

    def _history(self, lam: FloatArray, tau: FloatArray, **options: Any) -> FieldValues:
        out = {f: np.empty(tau.shape) for f in self.history_fields}
        for x in np.unique(lam):
            mask = lam == x
            h = history_of(*_force_nodes(*_key(float(x), options)), tau[mask])
            for f in out:
                out[f][mask] = h[f]
        return out


register(FinitePlate())
