"""The solver's loops over modes and nodes, compiled by numba.

Each function is one loop of :mod:`.kernels`, :mod:`.stepping` or :mod:`.flight` written out:
the same sums in numpy cost one call per operation (2-20 µs each with a few hundred modes), which
was most of the solver's time, and the march over the nodes was a Python loop (2-4 µs a node).
The callers keep the method; this module only runs its arithmetic. Powers of e^{s h} are taken
by repeated products, as before (a complex exponential costs some twenty products; the rounding
of z^j grows as j ulp, as that of e^{s j h} from its rounded argument does).

Compiled on first use and cached beside this file (numba's ``cache=True``; where that folder is
not writable, in numba's user-wide cache). Imported lazily by its callers, since importing numba
costs some 0.3 s that a command not solving a plate should not pay.
"""
from __future__ import annotations

import cmath
import math

import numpy as np
from numba import njit

#: Below this |x| phi2 and psi2 are summed as series (12 terms: the next is below 1e-17 there),
#: where their closed forms would lose digits to cancellation.
SERIES = 0.25
_TERMS = 12
PHI2_COEF = np.array([1.0 / math.factorial(n) for n in range(2, 2 + _TERMS)])
PSI2_COEF = np.array([(n - 1) / math.factorial(n) for n in range(2, 2 + _TERMS)])


@njit(cache=True)
def _series(coef, x):
    out = 0j
    for i in range(len(coef) - 1, -1, -1):
        out = out * x + coef[i]
    return out


@njit(cache=True)
def psi2_e(x, e):
    """psi2(x) = (1 + (x - 1) e^x) / x^2 given e = e^x (the series for small |x|)."""
    if abs(x) < SERIES:
        return _series(PSI2_COEF, x)
    return (1.0 + (x - 1.0) * e) / (x * x)


@njit(cache=True)
def phi2_e(x, e):
    """phi2(x) = (e^x - 1 - x) / x^2 given e = e^x (the series for small |x|)."""
    if abs(x) < SERIES:
        return _series(PHI2_COEF, x)
    return (e - 1.0 - x) / (x * x)


@njit(cache=True)
def coefficients(s, cw, h):
    """The exact step of every mode under a force linear from F_k to F_{k+1} over h:
    B_{k+1} = E B_k + P F_k + Q F_{k+1}, with E = e^{s h}, P = -i cw h psi2(s h) and
    Q = -i cw h phi2(s h) (cw = c / omega_d; y = Re B, y' = Re(s B)). Returns (E, P, Q)."""
    n = len(s)
    E = np.empty(n, dtype=np.complex128)
    P = np.empty(n, dtype=np.complex128)
    Q = np.empty(n, dtype=np.complex128)
    for i in range(n):
        x = s[i] * h
        e = cmath.exp(x)
        E[i] = e
        P[i] = -1j * cw[i] * h * psi2_e(x, e)
        Q[i] = -1j * cw[i] * h * phi2_e(x, e)
    return E, P, Q


#: The loops over the modes may sum in any order (numba's fastmath 'reassoc': vectorised sums,
#: 3-4 times faster; the rounding then depends on the machine's vector width, some ulp of the
#: sums), and may fuse a product into an add ('contract'). No flag that assumes finite numbers.
SUMS = {"reassoc", "contract", "nsz"}


@njit(cache=True, fastmath=SUMS)
def march(E, P, Q, B, x, v, h, c_res, capacity, max_nodes):
    """The nodes of one contact from its start (F_0 = 0, ball at x, v, modes B): the forces up
    to the first node k whose approach, with F_k = 0, is not positive, and the state at node
    k - 1. Returns (k, F[0..k], x, v, B, D): F[k] = 0, x, v and B at node k - 1, and D the approach
    at node k with F_k = 0 (the end lies between: D <= 0 < the approach at k - 1). k = -1 if the
    force has not vanished by node max_nodes.

    Node k + 1's approach is delta = D - a F_{k+1}: D from the state at node k (ball, modes
    advanced by E and the force F_k's share P), a = h^2/6 + sum Re Q + C_res. F_{k+1} solves
    F = delta^{3/2} by Newton on u = F^{1/3} (u^2 + a u^3 = D, convex: from above, Newton
    decreases monotonically; from below, its first step lands above), started from the forces'
    quadratic extrapolation. The amplitudes are kept as real and imaginary parts (the loop over
    the modes then vectorises); B is not changed.
    """
    n = len(E)
    Er, Ei = E.real.copy(), E.imag.copy()
    Pr, Pi = P.real.copy(), P.imag.copy()
    Qr, Qi = Q.real.copy(), Q.imag.copy()
    Br, Bi = B.real.copy(), B.imag.copy()
    a = h * h / 6.0 + c_res
    rp = 0.0
    fb = 0.0                 # sum Re(E B): the modes' free share of the next approach
    for i in range(n):
        a += Qr[i]
        rp += Pr[i]
        fb += Er[i] * Br[i] - Ei[i] * Bi[i]
    F = np.zeros(max(capacity, 4))
    f1 = f2 = f3 = 0.0
    k = 0
    while True:
        # D: the approach at node k + 1 with F_{k+1} = 0
        D = x + v * h - h * h * f1 / 3.0 - f1 * rp - fb
        if D <= 0.0 or k + 1 > max_nodes:
            out = np.empty(n, dtype=np.complex128)
            for i in range(n):
                out[i] = Br[i] + 1j * Bi[i]
            if D > 0.0:
                return -1, F[:k + 1].copy(), x, v, out, D
            return k + 1, F[:k + 2].copy(), x, v, out, D
        u = math.sqrt(D)                 # above the root: Newton from there is monotone
        g = 3.0 * (f1 - f2) + f3         # the quadratic extrapolation of the forces
        if k + 1 > 3 and g > 0.0 and g ** (1.0 / 3.0) < u:
            u = g ** (1.0 / 3.0)         # if below the root, one step brings it above
        for _ in range(60):
            du = (u * u * (1.0 + a * u) - D) / (u * (2.0 + 3.0 * a * u))
            u -= du
            # Newton's next correction is about du^2 / (2 u): below 1e-16 u from here
            if abs(du) <= 1e-8 * u:
                break
        f = u * u * u
        # the step to node k + 1, and the free share of node k + 2's approach
        x = x + v * h - h * h * (f1 / 3.0 + f / 6.0)
        v = v - 0.5 * h * (f1 + f)
        fb = 0.0
        for i in range(n):
            br, bi = Br[i], Bi[i]
            nr = Er[i] * br - Ei[i] * bi + Pr[i] * f1 + Qr[i] * f
            ni = Er[i] * bi + Ei[i] * br + Pi[i] * f1 + Qi[i] * f
            Br[i] = nr
            Bi[i] = ni
            fb += Er[i] * nr - Ei[i] * ni
        f3, f2, f1 = f2, f1, f
        k += 1
        if k + 1 >= len(F):
            G = np.zeros(2 * len(F))
            G[:len(F)] = F
            F = G
        F[k] = f


@njit(cache=True)
def replay(E, P, Q, B, F):
    """The modes' amplitudes after the forces F[0..] (node 0 holds B): B updated in place."""
    for k in range(len(F) - 1):
        for i in range(len(E)):
            B[i] = E[i] * B[i] + P[i] * F[k] + Q[i] * F[k + 1]
    return B


@njit(cache=True, fastmath=SUMS)
def delta_end(s, B1, cw1, x1, v1, f1, w):
    """(delta, d delta / dw) a time w after node k-1, the force falling linearly from f1 to 0
    over that same w (with q(w) = w psi2(s w), q'(w) = e^{s w} - psi2(s w))."""
    d = x1 + v1 * w - f1 * w * w / 3.0
    dd = v1 - 2.0 * f1 * w / 3.0
    for i in range(len(s)):
        x = s[i] * w
        e = cmath.exp(x)
        p = psi2_e(x, e)
        be = B1[i] * e
        d -= be.real + w * (cw1[i] * p).imag
        dd -= (s[i] * be).real + (cw1[i] * (e - p)).imag
    return d, dd


@njit(cache=True, fastmath=SUMS)
def contact_end(s, B1, cw, x1, v1, f1, h, d_h):
    """The end of a contact inside the step after node k - 1 and the modes there.

    The approach, the force falling linearly from f1 to 0 over a width w, is delta(w)
    (:func:`delta_end`); it is positive at w = 0 and d_h at w = h. Returns (w, y, u): w = h when
    d_h >= 0, else the root in (0, h) by Newton from the secant's point, kept inside the bracket
    (bisection when a step would leave it); y, u the modes' displacements and velocities at w.
    """
    n = len(s)
    cw1 = f1 * cw
    w = h
    if d_h < 0.0:
        # the start: the root of the quadratic through delta(0), delta'(0) (q'(0) = 1/2: no
        # exponential needed) and delta(h), which is within O(h^3) of the end (two or three
        # Newton steps from there, against four from the secant's point)
        d_0 = x1
        dd_0 = v1
        for i in range(n):
            d_0 -= B1[i].real
            dd_0 -= (s[i] * B1[i]).real + 0.5 * cw1[i].imag
        lo, hi = 0.0, h
        w = h * d_0 / (d_0 - d_h)
        c2 = (d_h - d_0 - dd_0 * h) / (h * h)
        disc = dd_0 * dd_0 - 4.0 * c2 * d_0
        if c2 != 0.0 and disc >= 0.0:
            r1 = (-dd_0 - math.sqrt(disc)) / (2.0 * c2)
            r2 = (-dd_0 + math.sqrt(disc)) / (2.0 * c2)
            if lo < r1 < hi:
                w = r1
            elif lo < r2 < hi:
                w = r2
        if not lo < w < hi:
            w = 0.5 * h
        for _ in range(100):
            d, dd = delta_end(s, B1, cw1, x1, v1, f1, w)
            if d == 0.0:
                break
            if d > 0.0:
                lo = w
            else:
                hi = w
            step = d / dd if dd != 0.0 else math.inf
            w_new = w - step
            if lo < w_new < hi:
                # quadratic convergence: the next step would be about step^2 / h, below rounding
                if abs(step) <= 1e-9 * h:
                    w = w_new
                    break
            else:
                w_new = 0.5 * (lo + hi)
            if hi - lo <= 1e-15 * h:
                w = w_new
                break
            w = w_new
    y = np.empty(n)
    u = np.empty(n)
    for i in range(n):
        x = s[i] * w
        e = cmath.exp(x)
        load = w * psi2_e(x, e) * cw1[i]
        be = B1[i] * e
        y[i] = be.real + load.imag
        u[i] = (s[i] * be).real + (s[i] * load).imag
    return w, y, u


@njit(cache=True, fastmath=SUMS)
def energy(s, omega, c, B):
    """E_p = sum (y'^2 + omega^2 y^2) / (2 c_n) of the modes in state B."""
    out = 0.0
    for i in range(len(s)):
        y = B[i].real
        v = (s[i] * B[i]).real
        out += (v * v + omega[i] * omega[i] * y * y) / (2.0 * c[i])
    return out


@njit(cache=True, fastmath=SUMS)
def gap_grid(s, B, x_r, v, dt0, ds, n):
    """g = x_r + v dt - sum_n Re(B_n e^{s_n dt}) at dt = dt0 + j ds, j = 0 .. n-1 (the phases
    advanced by products, the modes in the inner loop so that it vectorises)."""
    m = len(s)
    zr = np.empty(m)
    zi = np.empty(m)
    sr = np.empty(m)
    si = np.empty(m)
    for i in range(m):
        z = B[i] * cmath.exp(s[i] * dt0)
        st = cmath.exp(s[i] * ds)
        zr[i], zi[i], sr[i], si[i] = z.real, z.imag, st.real, st.imag
    out = np.empty(n)
    for j in range(n):
        acc = 0.0
        for i in range(m):
            acc += zr[i]
            a, b = zr[i], zi[i]
            zr[i] = a * sr[i] - b * si[i]
            zi[i] = a * si[i] + b * sr[i]
        out[j] = x_r + v * (dt0 + ds * j) - acc
    return out


@njit(cache=True, fastmath=SUMS)
def gap_slope(s, B, x_r, v, dt):
    """(g, g') a time dt after the separation."""
    g = x_r + v * dt
    d = v
    for i in range(len(s)):
        be = B[i] * cmath.exp(s[i] * dt)
        g -= be.real
        d -= (s[i] * be).real
    return g, d


@njit(cache=True, fastmath=SUMS)
def safe_steps(s, B, x_r, v, t_r, G2, a, b, ga, gb, tiny, max_steps):
    """Safe steps towards the first crossing of g = 0 in [a, b] from g(a) = ga < 0
    (:func:`zener_sym.plate.flight._safe_steps`). Returns (code, t, t2, g): code 0, no crossing
    in [a, b]; 1, a crossing bracketed in [t, t2]; 2, the steps stalled at t (g there): the
    caller subdivides [t, b]."""
    t, g = a, ga
    for _ in range(max_steps):
        d = gap_slope(s, B, x_r, v, t - t_r)[1]
        root = math.sqrt(d * d - 2.0 * G2 * g)
        u = -2.0 * g / (d + root) if d > 0.0 else (root - d) / G2
        t_new = t + u
        if t_new >= b:
            if gb < 0.0:
                return 0, t, b, g
            return 1, t, b, g
        g_new = gap_slope(s, B, x_r, v, t_new - t_r)[0]
        if g_new >= 0.0:
            return 1, t, t_new, g
        if u < tiny:
            break
        t, g = t_new, g_new
    return 2, t, b, g


@njit(cache=True, fastmath=SUMS)
def crossing(s, B, x_r, v, t_r, a, b):
    """The crossing of g = 0 in [a, b], g(a) < 0 <= g(b): Newton with g' kept inside the bracket
    (bisection when a step would leave it), until the bracket or the step is below
    1e-15 max(|b|, 1) + 8.9e-16 |t| (brentq's tolerances as the search used them)."""
    lo, hi = a, b
    xtol = 1e-15 * max(abs(b), 1.0)
    t = 0.5 * (lo + hi)
    for _ in range(200):
        g, d = gap_slope(s, B, x_r, v, t - t_r)
        if g == 0.0:
            return t
        if g < 0.0:
            lo = t
        else:
            hi = t
        tol = xtol + 8.9e-16 * abs(t)
        if hi - lo <= 2.0 * tol:
            return 0.5 * (lo + hi)
        t_new = t - g / d if d != 0.0 else lo - 1.0
        if not lo < t_new < hi:
            t_new = 0.5 * (lo + hi)
        elif abs(t_new - t) <= tol:
            return t_new
        t = t_new
    return t
