"""Between contacts: the ball flies freely, the modes ring; the next contact or the proved end.

After a separation at time t_r the ball moves as x = x_r + v (t - t_r) and each mode as
y_n = Re(B_n e^{s_n (t - t_r)}), so the gap g = x - w (w = sum y_n; F = 0 so no static term) is
known in closed form. Two bounds make the search a proof rather than a sampling:

* the end: by Cauchy-Schwarz over the modes, |w| <= sqrt(2 E_p C_N) with
  E_p = sum (y_n'^2 + omega_n^2 y_n^2) / (2 c_n) and C_N = sum c_n / omega_n^2 (<= C_s). E_p is
  constant between contacts (and only decreases with a loss factor), so once the ball moving away
  (v < 0) is below -sqrt(2 E_p C_N) no contact can follow;
* the next contact: |g''| = |w''| <= G2 = sum omega_n^2 |B_n| (|s_n| = omega_n), so on an interval
  of width l between samples g_a, g_b, g <= max(g_a, g_b) + G2 l^2 / 8. Intervals where that is
  not negative are subdivided until g is monotone there (g' > 0 throughout: a single crossing,
  then found by Newton kept in the bracket) or the interval is below 1e-13 of the time scale (a
  graze of depth below G2 l^2/8, negligible: ignored).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..typing import FloatArray
from .kernels import ComplexArray, Rates, compiled

__all__ = ["Flight", "end_bound", "next_contact"]

#: samples evaluated at once
_CHUNK = 2048
#: subdivision of a suspicious interval
_SPLIT = 8


@dataclass
class Flight:
    """The free state at time t_r: ball position and velocity, modal amplitudes."""

    t_r: float
    x_r: float
    v: float
    B: ComplexArray

    def gap_grid(self, r: Rates, t_a: float, ds: float, n: int) -> FloatArray:
        """g at t_a + j ds, j = 0 .. n-1 (t_a >= t_r), the modes' phases by products."""
        out: FloatArray = compiled().gap_grid(r.s, self.B, self.x_r, self.v, t_a - self.t_r,
                                              ds, n)
        return out

    def gap_slope(self, r: Rates, t: float) -> tuple[float, float]:
        """(g(t), g'(t)) from one set of exponentials."""
        g, d = compiled().gap_slope(r.s, self.B, self.x_r, self.v, t - self.t_r)
        return float(g), float(d)

    def slope(self, r: Rates, t: float) -> float:
        """g'(t)."""
        return self.gap_slope(r, t)[1]

    def advanced(self, r: Rates, t: float) -> tuple[float, ComplexArray]:
        """Ball position and modal amplitudes at time t (amplitudes referred to t)."""
        return self.x_r + self.v * (t - self.t_r), self.B * np.exp(r.s * (t - self.t_r))


def end_bound(r: Rates, B: ComplexArray) -> float:
    """sqrt(2 E_p C_N): no deflection of the impact point can exceed it while the plate is free."""
    return math.sqrt(max(2.0 * r.energy(B) * r.compliance, 0.0))


def next_contact(r: Rates, fl: Flight, scale: float) -> float | None:
    """The time of the next contact after t_r, or None when the end is proved.

    Raises RuntimeError if the ball moves towards the plate and yet no contact is found before
    it passes the bound (possible only through a graze below the search's resolution).

    ``scale`` is the problem's time scale (the graze threshold is 1e-13 of it).
    """
    R = end_bound(r, fl.B)
    if fl.v < 0.0 and fl.x_r < -R:
        return None
    if fl.v < 0.0:
        t_w = fl.t_r + (fl.x_r + R) / (-fl.v)
    elif fl.v > 0.0:
        t_w = fl.t_r + (R - fl.x_r) / fl.v + scale * 1e-12
    else:
        raise RuntimeError("the ball is at rest between contacts (speed exactly 0): the next "
                           "contact is not bounded in time")
    amp = np.abs(fl.B)
    G2 = float(np.sum(r.omega**2 * amp)) + 1e-300
    A = float(np.sum(amp)) + abs(fl.x_r) * 1e-12 + 1e-300
    g_r = fl.x_r - float(fl.B.real.sum())                  # at t_r itself: no exponential
    d_r = fl.v - float((r.s * fl.B).real.sum())
    if g_r >= 0.0 and d_r > 0.0:
        return fl.t_r
    # g <= g_r + d_r u + G2 u^2 / 2 < 0 for 0 < u <= |d_r| / G2 when d_r < 0
    t_a = fl.t_r + (abs(d_r) / G2 if d_r < 0.0 else scale * 1e-13)
    spacing = math.sqrt(2.0 * A / G2)     # G2 s^2 / 8 = A / 4
    tiny = scale * 1e-13
    while t_a < t_w:
        n = max(min(_CHUNK, int(math.ceil((t_w - t_a) / spacing)) + 1), 2)
        ds = min(spacing, (t_w - t_a) / (n - 1))
        t = t_a + ds * np.arange(n)
        g = fl.gap_grid(r, t_a, ds, n)
        # the products' rounding (some n ulp of sum |B_n|) is allowed for
        bad = np.nonzero(np.maximum(g[:-1], g[1:]) + (G2 * ds * ds / 8.0 + 1e-13 * n * A)
                         >= 0.0)[0]
        for i in bad:
            hit = _safe_steps(r, fl, G2, float(t[i]), float(t[i + 1]), float(g[i]),
                              float(g[i + 1]), tiny)
            if hit is not None:
                return hit
        t_a = float(t[-1])
    if fl.v > 0.0:
        raise RuntimeError(f"no contact found after tau = {fl.t_r:.6g} although the ball moves "
                           f"towards the plate (a graze below the search's resolution?)")
    return None


#: Safe steps tried in an interval before it is subdivided instead (a graze)
_SAFE_STEPS = 40


def _safe_steps(r: Rates, fl: Flight, G2: float, a: float, b: float, ga: float, gb: float,
                tiny: float) -> float | None:
    """The first crossing of g = 0 in [a, b] (g(a) < 0), or None, by safe steps: from t, with
    g'' <= G2, g(t + u) <= g + g' u + G2 u^2 / 2, which stays negative up to its root u*; so
    t + u* never passes the first crossing, and near a crossing with g' > 0 the steps converge
    to it quadratically. A crossing once bracketed is found by Newton kept in the bracket; where
    the steps stall (a graze), the interval is subdivided (:func:`_refine`). The steps are
    compiled (:func:`.loops.safe_steps`)."""
    if ga >= 0.0:
        return a
    code, t, t2, g = compiled().safe_steps(r.s, fl.B, fl.x_r, fl.v, fl.t_r, G2, a, b, ga, gb,
                                           tiny, _SAFE_STEPS)
    if code == 0:
        return None
    if code == 1:
        return _bracketed(r, fl, float(t), float(t2))
    return _refine(r, fl, G2, float(t), b, float(g), gb, tiny)


def _bracketed(r: Rates, fl: Flight, a: float, b: float) -> float:
    """The crossing in [a, b], g(a) < 0 <= g(b) (:func:`.loops.crossing`)."""
    return float(compiled().crossing(r.s, fl.B, fl.x_r, fl.v, fl.t_r, a, b))


def _refine(r: Rates, fl: Flight, G2: float, a: float, b: float, ga: float, gb: float,
            tiny: float) -> float | None:
    """The first crossing of g = 0 in [a, b] (g(a) < 0), or None."""
    if ga >= 0.0:
        return a
    if max(ga, gb) + G2 * (b - a) ** 2 / 8.0 < 0.0:
        return None
    if gb >= 0.0 and (fl.slope(r, a) - G2 * (b - a) > 0.0 or b - a < tiny):
        return _bracketed(r, fl, a, b)
    if b - a < tiny:
        return None
    t = np.linspace(a, b, _SPLIT + 1)
    g = fl.gap_grid(r, a, (b - a) / _SPLIT, _SPLIT + 1)
    g[0], g[-1] = ga, gb
    for i in range(_SPLIT):
        hit = _refine(r, fl, G2, t[i], t[i + 1], g[i], g[i + 1], tiny)
        if hit is not None:
            return hit
    return None
