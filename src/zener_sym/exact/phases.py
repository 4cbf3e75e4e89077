"""The phase driver of the scipy path: loading in u = √δ, the middle in τ, unloading in u.

Every reading of the contact integrates Eq. (10) in the same three phases (see
:mod:`.solver`); what differs is data: the equations of each phase (a :class:`Form`: its states by
name and their rates, with any extra states such as ∫F_c² dτ), and the events each phase
watches (:class:`Event`), as scipy's ``OdeSolver`` takes a step rule. :func:`integrate` runs
the phases for a :class:`Contact` and returns the integrated :class:`Leg` objects, which the
solution objects read through public accessors (``Leg.delta_w``, ``Leg.end``, ``Leg.hit``).

- loading: u from 0 until v = δ' = 1/2 (``V_SWITCH``);
- middle: the contact's τ-forms in order; the first watches the end of compression v = 0
  (terminal when a second form takes over there), the last ends at the hand-over to u,
  v² >= 2δ^{5/2}, where the u-form is no longer stiff (or runs a fixed span: ``span``);
- unloading: u from √δ down to the fixed endpoint u = 0.

A terminal extra event (the force-free end of the grain reading) ends the contact in the phase
where it fires; the phases after it are not integrated.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Union, overload

import numpy as np
from scipy.integrate import solve_ivp

from ..typing import FloatArray

if TYPE_CHECKING:
    from scipy.integrate import OdeSolution

__all__ = ["eval_budget", "Budget", "Settings", "Event", "Form", "Leg", "Contact", "integrate",
           "run_leg", "positive", "V_SWITCH"]

#: Relative velocity at which loading hands over from u to τ.
V_SWITCH = 0.5
#: States that get no absolute tolerance: relative control down to their zeros (e = −w(τ_d),
#: τ_dc at v = 0, the force-free end at g = 0).
FREE_STATES = ("v", "w", "g")

#: A state or rate: a float in scipy's right-hand sides, an array of points in the table
#: builder's re-integration (``table_build._from_steps``).
Value = Union[float, FloatArray]
#: The rates of a form, f(x, y) -> (dy_0/dx, dy_1/dx, ...), y the state vector (or [state, point]).
Terms = Callable[[float, FloatArray], tuple[Value, ...]]
#: A function of the point (x, y): the velocity delta' of a form, an event's g.
PointFunction = Callable[[float, FloatArray], Value]
#: Named values at one point (``Leg.values``): the states, x ("u" or "tau"), delta and v.
Values = dict[str, float]


def eval_budget(lam: float) -> int:
    """Most right-hand-side evaluations one solve may spend before it gives up (RuntimeError).

    DOP853 at rtol 1e-13 needs about 2000 + 2000 lambda; the budget is a few times that, so a
    slow combination of options (RK23 at the smallest rtol at lambda = 1000) ends in seconds
    with an error instead of running for hours.

    Parameters
    ----------
    lam : float
        lambda of the solve (Eq. 11).

    Returns
    -------
    int
        The budget.
    """
    return int(500_000 + 2500 * lam)


class Budget:
    """Counts right-hand-side evaluations against ``eval_budget``.

    Parameters
    ----------
    lam : float
        lambda of the solve (Eq. 11), which sets the budget.
    method, rtol : str, float
        The solve's options, named in the error message.
    """

    def __init__(self, lam: float, method: str, rtol: float) -> None:
        self.left, self.lam, self.method, self.rtol = eval_budget(lam), lam, method, rtol

    def spend(self) -> None:
        """Count one evaluation.

        Raises
        ------
        RuntimeError
            When the budget is spent.
        """
        self.left -= 1
        if self.left < 0:
            raise RuntimeError(
                f"exact solver: more than {eval_budget(self.lam)} right-hand-side evaluations at "
                f"lambda = {self.lam} with method={self.method!r}, rtol={self.rtol:g}; use the "
                f"default method (DOP853), LSODA, or a looser rtol")


@overload
def positive(d: float) -> float: ...


@overload
def positive(d: FloatArray) -> FloatArray: ...


def positive(d: Value) -> Value:
    """δ guarded to >= 0 (the contact force of a negative trial δ is zero).

    Parameters
    ----------
    d : float or ndarray
        δ: a scalar in the solver's right-hand sides (cheap), an array in the table builder's
        re-integration.

    Returns
    -------
    float or ndarray
        max(δ, 0), of d's type.
    """
    if isinstance(d, np.ndarray):
        return np.maximum(d, 0.0)
    return d if d > 0.0 else 0.0


@dataclass(frozen=True)
class Settings:
    """Options of one solve: tolerances, method, the evaluation budget and the caller's name."""

    lam: float
    rtol: float
    atol: float
    method: str
    who: str = "exact solver"
    budget: Budget = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "budget", Budget(self.lam, self.method, self.rtol))


@dataclass(frozen=True)
class Event:
    """A named event g(x, y) = 0 of one phase, callable as scipy expects (``direction``,
    ``terminal`` attributes)."""

    name: str
    fn: PointFunction
    direction: int = 0
    terminal: bool = False

    def __call__(self, x: float, y: FloatArray) -> Value:
        return self.fn(x, y)


@dataclass(frozen=True)
class Form:
    """The equations of one phase.

    ``kind`` "u" (x = u = √δ, states start with τ) or "tau" (x = τ, states start with δ);
    ``states`` their names ("w" = 1 − Ī among them); ``terms(x, y)`` the rates as a tuple, written
    elementwise so that a τ-form also takes arrays of points (``table_build._from_steps``);
    ``velocity(x, y)`` v = δ'; ``derived`` the initial value of a state that is not carried over
    from the previous phase, from the named values there.
    """

    kind: str
    states: tuple[str, ...]
    terms: Terms
    velocity: PointFunction
    lam: float
    derived: Mapping[str, Callable[[Mapping[str, float]], float]] = field(default_factory=dict)

    def rhs(self, budget: Budget | None = None) -> Callable[[float, FloatArray], FloatArray]:
        """The right-hand side f(x, y) for ``solve_ivp``, spending ``budget`` per call.

        Parameters
        ----------
        budget : Budget, optional
            Charged one evaluation per call (none: free).

        Returns
        -------
        callable
            f(x, y) -> the rates as an array.
        """
        terms = self.terms
        if budget is None:
            return lambda x, y: np.array(terms(x, y))

        def f(x: float, y: FloatArray) -> FloatArray:
            budget.spend()
            return np.array(terms(x, y))

        return f

    def atol(self, atol: float) -> FloatArray:
        """Absolute tolerance per state: ``atol``, none (1e-300) for ``FREE_STATES``.

        Parameters
        ----------
        atol : float
            The solve's absolute tolerance.

        Returns
        -------
        ndarray
            One tolerance per state.
        """
        return np.array([1e-300 if s in FREE_STATES else atol for s in self.states])

    def pack(self, values: Mapping[str, float]) -> list[float]:
        """The initial state from named values (``Leg.values``) and ``derived``.

        Parameters
        ----------
        values : mapping of str to float
            Named values where the previous phase ended.

        Returns
        -------
        list of float
            The state in ``states`` order.
        """
        return [values[s] if s in values else self.derived[s](values) for s in self.states]

    @property
    def w_row(self) -> int:
        """Index of the state w = 1 − Ī."""
        return self.states.index("w")


@dataclass(frozen=True)
class Leg:
    """One integrated phase: its form, dense output ``sol``, accepted steps (``x``, ``y`` as
    solve_ivp's t, y), the events found (name -> list of (x, y)) and the event that ended it."""

    name: str
    form: Form
    sol: OdeSolution
    x: FloatArray
    y: FloatArray
    hits: dict[str, list[tuple[float, FloatArray]]]
    ended_by: str | None

    def values(self, x: float, y: FloatArray) -> Values:
        """Named values at one point: the states, x ("u" or "tau"), δ and v.

        Parameters
        ----------
        x : float
            The independent variable.
        y : ndarray
            The state there.

        Returns
        -------
        dict of str to float
        """
        xf = float(x)
        out: Values = dict(zip(self.form.states, y))
        out[self.form.kind] = xf
        if self.form.kind == "u":
            out["delta"] = xf * xf
        if "v" not in out:
            v: float = self.form.velocity(xf, y)  # type: ignore[assignment]  # y is one point
            out["v"] = v
        return out

    def hit(self, name: str) -> Values | None:
        """``values`` at the first occurrence of the event ``name``.

        Parameters
        ----------
        name : str
            The event's name.

        Returns
        -------
        dict of str to float or None
            None if the event did not fire.
        """
        found = self.hits.get(name, [])
        return self.values(*found[0]) if len(found) else None

    @property
    def end(self) -> Values:
        """``values`` where the leg ended: the ending event's point, else the span's end."""
        if self.ended_by is not None:
            found = self.hit(self.ended_by)
            assert found is not None  # run_leg sets ended_by to an event that fired
            return found
        return self.values(self.x[-1], self.y[:, -1])

    @property
    def tau_start(self) -> float:
        """τ at the leg's start."""
        return float(self.y[0, 0] if self.form.kind == "u" else self.x[0])

    def delta_w(self, tau: FloatArray) -> tuple[FloatArray, FloatArray]:
        """(δ, w) at the times ``tau`` inside this leg (a u-leg inverts τ(u) by Newton).

        Parameters
        ----------
        tau : ndarray
            Times inside the leg.

        Returns
        -------
        tuple of ndarray
            δ and w = 1 − Ī, tau's shape.
        """
        if self.form.kind == "tau":
            y = self.sol(tau)
            return y[0], y[self.form.w_row]
        u, y = self._invert(tau)
        return u**2, y[self.form.w_row]

    def _invert(self, tau: FloatArray) -> tuple[FloatArray, FloatArray]:
        """u with τ(u) = tau: interpolate u² against τ on the steps, then Newton."""
        u_grid, tau_grid, lam = self.x, self.y[0], self.form.lam
        order = np.argsort(tau_grid)
        u = np.sqrt(np.interp(tau, tau_grid[order], (u_grid**2)[order]))
        lo, hi = min(u_grid[0], u_grid[-1]), max(u_grid[0], u_grid[-1])
        for _ in range(40):
            y = self.sol(u)
            v = y[1] - lam * u**3
            dtau = 2.0 * u / v
            resid = y[0] - tau
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(dtau != 0.0, resid / dtau, 0.0)
            u = np.clip(u - step, lo, hi)
            if np.all(np.abs(resid) <= 4e-16 * np.maximum(1.0, np.abs(tau))):
                break
        return u, self.sol(u)


def run_leg(name: str, form: Form, span: tuple[float, float], y0: Sequence[float],
            opts: Settings, events: Sequence[Event] = (),
            first_step: float | None = None) -> Leg:
    """Integrate one phase with ``solve_ivp`` (dense output).

    Parameters
    ----------
    name : str
        The phase's name ("loading", "middle", "unloading"), for messages.
    form : Form
        Its equations.
    span : tuple of float
        (x_start, x_end).
    y0 : sequence of float
        The initial state, in ``form.states`` order.
    opts : Settings
        Tolerances, method and budget.
    events : sequence of Event
        The events watched.
    first_step : float, optional
        ``solve_ivp``'s first step.

    Returns
    -------
    Leg

    Raises
    ------
    RuntimeError
        If the phase does not end at one of its terminal events (if it has any) or at the
        span's end, or scipy fails.
    """
    kw: dict[str, float] = {} if first_step is None else {"first_step": first_step}
    try:
        r = solve_ivp(form.rhs(opts.budget), span, y0, method=opts.method, rtol=opts.rtol,
                      atol=form.atol(opts.atol), events=list(events) or None, dense_output=True,
                      **kw)
    except (ValueError, ZeroDivisionError, FloatingPointError) as exc:
        # scipy's own failures (e.g. LSODA's dense output on repeated times) are not input errors
        raise RuntimeError(f"{opts.who}: scipy {opts.method} failed at lambda = {opts.lam}, rtol = "
                           f"{opts.rtol:g}: {exc}; the default method DOP853 does not") from exc
    hits = {e.name: list(zip(r.t_events[i], r.y_events[i])) for i, e in enumerate(events)}
    stops = [e.name for e in events if e.terminal]
    ended_by = next((s for s in stops if hits[s]), None)  # scipy stops at the first terminal one
    done = r.status == 1 and ended_by is not None if stops else r.status == 0
    if not done:
        want = " or ".join(stops) if stops else "its end"
        raise RuntimeError(f"{opts.who}: the {name} phase did not reach {want} at lambda = "
                           f"{opts.lam}: {r.message}")
    return Leg(name, form, r.sol, r.t, r.y, hits, ended_by)


@dataclass(frozen=True)
class Contact:
    """One reading of the contact as data: the u-form of loading and unloading, the τ-forms of
    the middle in order, and extra events per phase ("loading", "middle", "unloading"); a
    terminal extra event ends the contact where it fires."""

    u_form: Form
    middle: tuple[Form, ...]
    events: Mapping[str, Sequence[Event]] = field(default_factory=dict)

    def extra(self, phase: str) -> tuple[Event, ...]:
        """The extra events of a phase.

        Parameters
        ----------
        phase : str
            "loading", "middle" or "unloading".

        Returns
        -------
        tuple of Event
        """
        return tuple(self.events.get(phase, ()))


def _v_half(form: Form) -> Event:
    return Event("v = 1/2", lambda u, y: form.velocity(u, y) - V_SWITCH, -1, True)


def _compression_end(terminal: bool) -> Event:
    # on the state v (every middle form carries it second): relatively accurate near its zero
    return Event("end of compression", lambda t, y: y[1], -1, terminal)


def _hand_over(form: Form) -> Event:
    # |∂(dw/du)/∂w|·u = 2u⁵/v² <= 1: v² >= 2δ^{5/2}; after the end of compression v² − 2δ^{5/2}
    # only increases, so the rising crossing is unique
    def g(t: float, y: FloatArray) -> Value:
        d = max(y[0], 0.0)
        v = form.velocity(t, y)
        out: Value = v * v - 2.0 * d * d * np.sqrt(d)
        return out

    return Event("hand-over", g, 1, True)


def _ends(leg: Leg, contact: Contact, phase: str) -> bool:
    return any(e.terminal and e.name == leg.ended_by for e in contact.extra(phase))


def integrate(contact: Contact, opts: Settings, span: float | None = None) -> tuple[Leg, ...]:
    """The legs of one contact in order (module docstring).

    Parameters
    ----------
    contact : Contact
        The reading of the contact (its forms and events).
    opts : Settings
        Options of the solve.
    span : float, optional
        With it, the middle's last form runs for ``span`` past its start and there is no
        unloading (``solver.solve_early``).

    Returns
    -------
    tuple of Leg
        The integrated phases in order.

    Raises
    ------
    RuntimeError
        If a phase fails (``run_leg``) or the middle finds no end of compression.
    """
    lam, u_form = opts.lam, contact.u_form
    u_cap = min(1.2, lam ** (-1.0 / 3.0)) if lam > 0 else 1.2  # δ_m^{3/2} < 1/λ; δ_m < 1.1 at 0
    y0: list[float] = [0.0, 1.0] + [0.0] * (len(u_form.states) - 2)  # τ = 0, w = 1, extras 0
    leg = run_leg("loading", u_form, (0.0, u_cap), y0, opts,
                  (_v_half(u_form),) + contact.extra("loading"))
    legs = [leg]
    if _ends(leg, contact, "loading"):  # a terminal extra event of loading ends the contact
        return tuple(legs)
    t_cap = leg.end["tau"] + 100.0 + 100.0 * lam
    n = len(contact.middle)
    for i, form in enumerate(contact.middle):
        start = leg.end
        t0 = float(start["tau"])
        last = i == n - 1
        events: tuple[Event, ...] = (_compression_end(n > 1),) if i == 0 else ()
        if last and span is None:
            events += (_hand_over(form),)
        t_end = t0 + span if last and span is not None else t_cap
        # first_step: LSODA's own first step from the end of compression (δ' = 0) can have zero
        # length, which its dense output refuses; the other methods' error control corrects it
        leg = run_leg("middle", form, (t0, t_end), form.pack(start), opts,
                      events + contact.extra("middle"), first_step=1e-3 * t0 if i else None)
        legs.append(leg)
        if i == 0 and leg.hit("end of compression") is None:
            raise RuntimeError(f"{opts.who}: no end of compression at lambda = {lam}")
        if _ends(leg, contact, "middle"):
            return tuple(legs)
    if span is not None:
        return tuple(legs)
    end = leg.end
    legs.append(run_leg("unloading", u_form, (np.sqrt(end["delta"]), 0.0), u_form.pack(end),
                        opts, contact.extra("unloading")))
    return tuple(legs)
