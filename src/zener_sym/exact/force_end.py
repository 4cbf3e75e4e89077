"""Eq. (10) read as the viscoelastic contact of two grains: the contact ends where the force vanishes.

Between viscoelastic grains (Kuwabara & Kono 1987; Brilliantov et al. 1996) the contact force is

    F_c = delta^{3/2} + lambda (delta^{3/2})' = sqrt(delta) (delta + (3/2) lambda delta') = -delta'',

which turns attractive in recovery before delta returns to 0. Grains cannot pull, so they separate
where F_c = 0 (Schwager & Poeschel 2008): ``contact_end="force"``, the first time after the end of
compression with delta + (3/2) lambda delta' = 0. The mapping to physical grains is derived in
``zener_sym.derivation.viscoelastic``. In this reading the fields are those of the grain contact:

- ``force`` is F_c (not the plate's Hertz force delta^{3/2}) and ``F_m`` its maximum, which lies
  before the end of compression (during loading at large lambda);
- ``velocity`` is the relative velocity delta' = 1 - impulse and ``impulse`` = int F_c dtau, so
  I(tau_d) = 1 + e with e = -delta'(tau_d);
- ``int_F2`` = int F_c^2 dtau over the contact and ``xi`` = 1 - e^2. This reading has no
  2 lambda int F^2 identity; its energy balance (``derivation/viscoelastic.py``) is

      xi = 1 - e^2 = 3 lambda int_0^tau_d sqrt(delta) delta'^2 dtau + (4/5) delta(tau_d)^{5/2},

  the dashpot's dissipation plus the elastic energy left in the grains at separation (which their
  bulk dissipates later). Both terms are positive, so xi is formed from them without the
  cancellation of 1 - e^2 when e -> 1 (small lambda): exactly 0 at lambda = 0, never negative;
- past tau_d the history has delta = 0, force 0 and the separation velocity.

Two independent paths, as for the plate:

:func:`solve` (scipy)
    the three phases of the plate (u = sqrt(delta) at both ends, tau in the middle), run by the
    phase driver of :mod:`.phases` with this reading's data (``grain_contact``): the force-free
    end as a terminal event (phase 2 or 3), the peak of F_c as an event (phase 1 or 2), int F_c^2
    as the third state and the dissipation int sqrt(delta) delta'^2 as the fourth (for xi).
:func:`solve_mp` (mpmath)
    the plate's Taylor solution of :mod:`.mp`, cut at the force-free end: every step is a
    polynomial, so the end (a root of delta + (3/2) lambda v), the peak (a root of F_c') and
    int F_c^2 (a polynomial integral) come from the stored steps by Newton's method and exact
    integration; xi = 1 - e^2 is formed at the working precision (30 digits and guard digits by
    default), so its cancellation near e = 1 costs nothing a float reference could see.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np

from .. import params
from ..numerics.taylor import derivative, horner, integral, product, root
from ..typing import FloatArray, RealArrayLike, RealLike
from . import mp, solver
from .phases import Contact, Event, Form, Leg, Settings, Terms, Value, integrate, positive
from .solver import ContactTimes, ExactSolution, check_options, restitution

__all__ = ["CONTACT_ENDS", "check_contact_end", "ForceEndSolution", "grain_contact", "solve", "solve_mp"]

#: The accepted end-of-contact criteria.
CONTACT_ENDS = ("delta", "force")


def check_contact_end(contact_end: object) -> str:
    """Validate the end-of-contact criterion: ``"delta"`` (plate, delta = 0) or ``"force"`` (grains).

    Parameters
    ----------
    contact_end : str
        One of ``CONTACT_ENDS``.

    Returns
    -------
    str
        contact_end.

    Raises
    ------
    ValueError
        For any other value, naming the allowed ones.
    """
    if not isinstance(contact_end, str) or contact_end not in CONTACT_ENDS:
        raise ValueError(f"unknown contact_end {contact_end!r}; allowed: 'delta' (the plate: contact "
                         f"ends at delta = 0) or 'force' (viscoelastic grains: contact ends where "
                         f"delta^(3/2) + lambda (delta^(3/2))' = 0)")
    return contact_end


@dataclass
class ForceEndSolution(ContactTimes):
    """Solution of Eq. (10) ended at the force-free point (grain reading, module docstring).

    ``v_end`` is delta'(tau_d) (the separation velocity is -v_end = e); ``xi`` = 1 - e^2 formed
    without cancellation (module docstring). ``_base`` is the plate-style solution object cut at
    tau_d, used for the dense history of delta and w = 1 - int delta^{3/2}.
    """

    # float from solve (scipy), mpmath.mpf from solve_mp
    lam: Any
    delta_m: Any
    tau_dc: Any
    tau_d: Any
    v_end: Any
    int_F2: Any
    F_m: Any
    xi: Any
    _base: ExactSolution | mp.MpSolution | None = None

    @property
    def e(self) -> Any:
        """Coefficient of restitution e = -delta'(tau_d)."""
        return -self.v_end

    @property
    def impulse(self) -> Any:
        """int F_c dtau over the contact, 1 - delta'(tau_d) = 1 + e."""
        return 1 - self.v_end

    def history(self, tau: RealArrayLike) -> dict[str, FloatArray]:
        """delta, velocity delta', force F_c and impulse 1 - delta' at ``tau``, float arrays.

        Parameters
        ----------
        tau : array_like
            Times, finite and >= 0.

        Returns
        -------
        dict of str to ndarray
            "tau", "delta", "velocity", "force", "impulse", each of tau's shape.

        Raises
        ------
        ValueError
            For a negative or non-finite time.
        """
        t: FloatArray = params.as_tau(tau)
        tau_d = float(self.tau_d)
        if self._base is None:
            raise RuntimeError("ForceEndSolution: no dense solution to read the history from")
        h = self._base.history(np.minimum(t, np.nextafter(tau_d, 0.0)))
        lam = float(self.lam)
        d = np.maximum(np.asarray(h["delta"], dtype=float), 0.0)
        v = np.asarray(h["velocity"], dtype=float) - lam * d**1.5  # w - lambda delta^{3/2}
        fc = np.sqrt(d) * (d + 1.5 * lam * v)
        after = t >= tau_d
        d, v, fc = np.where(after, 0.0, d), np.where(after, float(self.v_end), v), np.where(after, 0.0, fc)
        return {"tau": t, "delta": d, "velocity": v, "force": fc, "impulse": 1.0 - v}


# --- scipy path ------------------------------------------------------------------------------

def _u_terms(lam: float) -> Terms:
    """u-form with J = int F_c^2 and D = int sqrt(delta) delta'^2: dtau/du = 2u/v,
    dw/du = -2u^4/v, dJ/du = 2u F_c^2/v, dD/du = 2u^2 v."""

    def f(u: float, y: FloatArray) -> tuple[Value, ...]:
        v = y[1] - lam * u**3
        if abs(v) < 1e-300:
            v = 1e-300 if v >= 0 else -1e-300
        g = 2.0 * u / v
        fc = u**3 + 1.5 * lam * u * v
        return g, -g * u**3, g * fc * fc, 2.0 * u * u * v

    return f


def _tau_terms(lam: float) -> Terms:
    """Middle phase in tau, state (delta, v, g, w, J, D): v = delta' and g = delta + (3/2) lam v
    (F_c = sqrt(delta) g) carried as their own states,

        v' = -sqrt(delta) (delta + (3/2) lam v)   (Eq. 10),   g' = v - (3/2) lam sqrt(delta) g.

    At large lambda the end of compression (v = 0) and the force-free end (g = 0, a short time
    later, where v is small) would otherwise be found on w - lam delta^{3/2} or on delta + (3/2)
    lam v, differences of nearly equal numbers: tau_dc was off by 1.7e-9 relative at lambda =
    1000 and tau_d by 7e-6 (w form) or 1.4e-10 at lambda = 300 (v form), since g crosses 0 with
    slope v = -delta / ((3/2) lam). Each event reads the state that vanishes there, which is
    relatively accurate near its zero (no absolute tolerance), and g's own equation damps errors
    fed in from v (rate (3/2) lam sqrt(delta))."""
    k = 1.5 * lam

    def f(t: float, y: FloatArray) -> tuple[Value, ...]:
        d = positive(y[0])
        s = np.sqrt(d)
        v, g = y[1], y[2]
        fc = s * (d + k * v)
        return v, -fc, v - k * s * g, -d * s, fc * fc, s * v * v

    return f


def grain_contact(lam: float) -> Contact:
    """The grains' contact for the phase driver.

    The plate's phases with the extra states J = int F_c^2 and D = int sqrt(delta) delta'^2,
    one middle form (delta, v, g, w, J, D) through the end of compression, the peak of F_c
    watched in loading and middle, and the force-free end as a terminal event in the middle and
    in unloading.

    Parameters
    ----------
    lam : float
        lambda (Eq. 11), > 0.

    Returns
    -------
    Contact
    """
    k = 1.5 * lam

    def velocity_u(u: float, y: FloatArray) -> Value:
        v: Value = y[1] - lam * u**3
        return v

    def peak_u(u: float, y: FloatArray) -> Value:  # proportional to dF_c/du; F_c = u^3 + k u v
        v = y[1] - lam * u**3
        dv = -2.0 * u**4 / v - 3.0 * lam * u**2
        g: Value = 3.0 * u**2 + k * (v + u * dv)
        return g

    def peak_t(t: float, y: FloatArray) -> Value:
        # proportional to dF_c/dtau: 2 delta v + lam v^2 - 2 lam delta F_c
        d = max(y[0], 0.0)
        v = y[1]
        g: Value = 2.0 * d * v + lam * v * v - 2.0 * lam * d * np.sqrt(d) * y[2]
        return g

    def free_u(u: float, y: FloatArray) -> Value:
        g: Value = u * u + k * (y[1] - lam * u**3)
        return g

    u_form = Form("u", ("tau", "w", "J", "D"), _u_terms(lam), velocity_u, lam)
    # g = delta + (3/2) lam v = 0 is the force-free end; v and g get no absolute tolerance
    middle = Form("tau", ("delta", "v", "g", "w", "J", "D"), _tau_terms(lam), lambda t, y: y[1],
                  lam, derived={"g": lambda q: q["delta"] + k * q["v"]})
    return Contact(u_form, (middle,), {
        "loading": (Event("peak", peak_u, -1),),
        "middle": (Event("peak", peak_t, -1), Event(_FREE, lambda t, y: y[2], -1, True)),
        "unloading": (Event(_FREE, free_u, -1, True),)})


_FREE = "force-free end"


def _peak(legs: tuple[Leg, ...], lam: float) -> float:
    """F_m from the first peak event: in loading (F_c = u^3 + k u v) or else in the middle."""
    hit = legs[0].hit("peak")
    if hit is not None:
        up = float(hit["u"])
        F_m: float = up**3 + 1.5 * lam * up * (hit["w"] - lam * up**3)
        return F_m
    hit = legs[1].hit("peak")
    if hit is None:
        raise RuntimeError(f"exact (force end): no peak of the force found at lambda = {lam}")
    return float(np.sqrt(hit["delta"]) * hit["g"])


def solve(lam: float, rtol: float = 1e-13, atol: float = 1e-16, method: str = "DOP853") -> ForceEndSolution:
    """Integrate Eq. (10) for one lambda to the force-free end (scipy path).

    Options as in :func:`zener_sym.exact.solver.solve` (checked here before any work, with the
    same evaluation budget, so no option makes a call hang); the default tolerance is ten times
    tighter than the plate's. Measured against :func:`solve_mp` (``tests/test_viscoelastic.py``):
    every summary field within 5e-14 relative for 0 <= lambda <= 1000 with these defaults.

    Parameters
    ----------
    lam : float
        lambda (Eq. 11), 0 <= lam <= LAMBDA_MAX (validated by the caller).
    rtol, atol : float
        Tolerances (``solver.check_options``).
    method : str
        Method of ``solve_ivp``, one of ``solver.METHODS``.

    Returns
    -------
    ForceEndSolution
        Fields as floats.

    Raises
    ------
    ValueError
        For a bad option.
    RuntimeError
        When a phase fails or the evaluation budget is spent.
    """
    rtol, atol, method = check_options(rtol, atol, method)
    lam = float(lam)
    if lam == 0.0:  # F_c = delta^{3/2}: the force-free end is delta = 0
        s = solver.solve(0.0, rtol=rtol, atol=atol, method=method)
        return ForceEndSolution(lam=0.0, delta_m=s.delta_m, tau_dc=s.tau_dc, tau_d=s.tau_d,
                                v_end=s.w_end, int_F2=s.int_F2, F_m=s.F_m, xi=0.0, _base=s)
    legs = integrate(grain_contact(lam), Settings(lam, rtol, atol, method, "exact (force end)"))
    dc = legs[1].hit("end of compression")
    if dc is None:  # phases.integrate refuses a middle without it
        raise RuntimeError(f"exact (force end): no end of compression at lambda = {lam}")
    tau_dc, delta_m = float(dc["tau"]), float(dc["delta"])
    end = legs[-1].end  # the force-free end, in the middle (large lambda) or in unloading
    tau_d, w, J, D = float(end["tau"]), float(end["w"]), float(end["J"]), end["D"]
    base = ExactSolution(lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=tau_d, w_end=w,
                         int_F2=J, legs=legs)
    xi = float(3.0 * lam * D + 0.8 * max(end["delta"], 0.0) ** 2.5)
    return ForceEndSolution(lam=lam, delta_m=delta_m, tau_dc=tau_dc, tau_d=tau_d,
                            v_end=-float(restitution(xi, -float(end["v"]))), int_F2=J,
                            F_m=float(_peak(legs, lam)), xi=xi, _base=base)


# --- mpmath path -----------------------------------------------------------------------------

def _fc_poly(ph: Any, st: Any, lam: Any) -> tuple[list[Any], list[Any]]:
    """F_c on one Taylor step as a polynomial in s, and dtau/ds (1 on tau steps)."""
    if ph.kind == "tau":  # F_c = -v'
        return [-x for x in derivative(st.c[1])], [mpmath.mpf(1)]
    u = [st.x0, mpmath.mpf(1)]  # u = x0 + s
    u3 = product(product(u, u), u)
    fc = product(u, [mpmath.mpf(3) / 2 * lam * x for x in st.c[1]])
    fc = [(fc[i] if i < len(fc) else 0) + (u3[i] if i < len(u3) else 0) for i in range(max(len(fc), len(u3)))]
    return fc, derivative(st.c[0])


def solve_mp(lam: RealLike, dps: int = 30) -> ForceEndSolution:
    """High-precision force-free end (mpmath): the plate's Taylor solution cut where F_c = 0.

    Parameters
    ----------
    lam : float
        lambda (Eq. 11), 0 <= lam <= LAMBDA_MAX.
    dps : int
        Decimal digits, DPS_MIN <= dps <= DPS_MAX (:func:`zener_sym.exact.mp.solve`, which
        validates both).

    Returns
    -------
    ForceEndSolution
        Fields as mpf.

    Raises
    ------
    ValueError
        For a bad lambda or dps.
    RuntimeError
        If no force-free point is found (a bug).
    """
    sol = mp.solve(lam, dps=dps)
    with mpmath.workdps(sol.dps + mp.GUARD_WORK):
        L = sol.lam
        k = mpmath.mpf(3) / 2 * L
        if L == 0:
            return ForceEndSolution(lam=L, delta_m=sol.delta_m, tau_dc=sol.tau_dc, tau_d=sol.tau_d,
                                    v_end=sol.v_end, int_F2=sol.int_F2, F_m=sol.F_m,
                                    xi=mpmath.mpf(0), _base=sol)
        F_m = None
        J = mpmath.mpf(0)
        for ph in sol.phases:
            for i, st in enumerate(ph.steps):
                fc, dtau = _fc_poly(ph, st, L)
                t0 = ph.t_start[i]
                # peak of F_c: F_c' (in s) changes sign from + to -
                if F_m is None:
                    dfc = derivative(fc)
                    if horner(dfc, st.h) <= 0:
                        s = root(dfc, 0, st.h) if horner(dfc, 0) > 0 else mpmath.mpf(0)
                        F_m = horner(fc, s)
                # force-free end, after the end of compression
                if ph.kind == "tau":
                    g = [st.c[0][j] + k * st.c[1][j] for j in range(len(st.c[0]))]
                else:
                    g = [k * x for x in st.c[1]]
                    g[0] += st.x0**2
                    g[1] += 2 * st.x0
                    g[2] += 1
                past_dc = t0 >= sol.tau_dc or horner(st.c[1], st.h) < 0
                if F_m is not None and past_dc and horner(g, st.h) <= 0:
                    s = root(g, 0, st.h)
                    J += integral(product(product(fc, fc), dtau), s)
                    v_end = horner(st.c[1], s)
                    tau_d = t0 + s if ph.kind == "tau" else horner(st.c[0], s)
                    return ForceEndSolution(lam=L, delta_m=sol.delta_m, tau_dc=sol.tau_dc, tau_d=tau_d,
                                            v_end=v_end, int_F2=J, F_m=F_m, xi=1 - v_end**2,
                                            _base=sol)
                J += integral(product(product(fc, fc), dtau), st.h)
    raise RuntimeError(f"exact (force end, mpmath): no force-free point found at lambda = {lam}")
