"""The mpmath HAM kernels: the hand-written runtime around the printed formulas.

``generated/ham0.py`` and ``generated/ham1.py`` hold the formulas only; this module
checks the inputs, sets the working precision (``dps`` digits if given, else the caller's
``mpmath.mp.dps``; 10 guard digits for the formulas, more for the square-root integrals near
their ends), evaluates the square-root integrals K from the 2F1 closed forms J, finds the
first-order roots (``mpmath.findroot`` from the numpy kernels' roots) and integrates the contact
force (``numerics.mp.contact_integral_mp``). Results are rounded to the digits asked for. A change
here needs no regeneration.

``ham0`` and ``ham1`` are the kernels of each order, as in :mod:`.runtime_numpy`:
``ham0``: ``params``, ``delta0``/``delta``, ``delta0_dot``/``delta_dot``, ``force``, ``impulse``,
``summary``; ``ham1``: ``params``, ``delta0``, ``delta0_dot``, ``delta1``, ``delta``,
``delta_dot``, ``force``, ``compression_end``, ``contact_end``, ``impulse``.
"""
from __future__ import annotations

import types
from collections.abc import Callable, Iterable
from typing import Any

import mpmath

from ..generated import ham0 as _ham0
from ..generated import ham1 as _ham1
from ..numerics.mp import contact_integral_mp
from .xp import MPMATH, bind, kernel_doc

_f0 = bind(_ham0, MPMATH)  # the formulas, printed once for every backend, on mpmath
_f1 = bind(_ham1, MPMATH)

__all__ = ["LAM_CRIT_DIGITS", "sqrt_integrals_mp", "ham0", "ham1"]

#: Critical lambda (omega0 = 0), to 40 significant digits.
LAM_CRIT_DIGITS: str = _f0.LAM_CRIT_DIGITS

#: A real number for mpmath: an ``mpf`` or what ``mpmath.mpf`` takes (int, float, str). mpmath
#: is untyped, so this is Any; the name says what is meant.
MpReal = Any
#: (tau, lam, dps) -> mpf: a kernel on the contact
_Kernel = Callable[[MpReal, MpReal, "int | None"], Any]


def _prec(dps: int | None) -> int:
    """Working digits: ``dps`` if given, else the caller's mpmath.mp.dps."""
    return int(mpmath.mp.dps) if dps is None else int(dps)


def _out(x: Any, p: int) -> Any:
    """x rounded to p digits (the precision the caller asked for)."""
    with mpmath.workdps(p):
        return +x


def _lam(lam: MpReal) -> Any:
    lam = mpmath.mpf(lam)
    if not mpmath.isfinite(lam) or lam < 0 or lam >= mpmath.mpf(LAM_CRIT_DIGITS):
        raise ValueError(f"lambda = {lam} is outside the HAM solution's range: allowed "
                         f"0 <= lambda < LAM_CRIT = {LAM_CRIT_DIGITS} (omega0 is not real beyond)")
    return lam


def _tau(tau: MpReal) -> Any:
    tau = mpmath.mpf(tau)
    if not mpmath.isfinite(tau) or tau < 0:
        raise ValueError("tau must be finite and >= 0")
    return tau


def params(lam: MpReal, dps: int | None = None) -> tuple[Any, Any, Any]:
    """k (25), beta (32), omega0 (33) at ``dps`` digits.

    Parameters
    ----------
    lam : float, str or mpmath.mpf
        lambda, 0 <= lambda < ``LAM_CRIT_DIGITS`` (Eq. 81).
    dps : int, optional
        Digits of the results; default: the caller's ``mpmath.mp.dps``. The formulas run with
        10 guard digits.

    Returns
    -------
    k, beta, omega0 : mpmath.mpf

    Raises
    ------
    ValueError
        lambda out of range or not finite.

    Examples
    --------
    >>> import mpmath
    >>> from zener_sym.ham.runtime_mpmath import params
    >>> with mpmath.workdps(30):
    ...     k, beta, omega0 = params(0)
    ...     bool(abs(k - (mpmath.mpf(5) / 4) ** (mpmath.mpf(1) / 5)) < 1e-29)  # k(0) = (5/4)^(1/5)
    True
    """
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        k, beta, omega0 = _f0.params(_lam(lam))
    return _out(k, p), _out(beta, p), _out(omega0, p)


def _J(m: int, a: Any, theta: Any) -> Any:
    """J_m(a, theta) = int_0^theta exp((-a + i m) t) sqrt(sin t) dt by its 2F1 closed form
    (theta in [0, pi]); the value at pi uses Gauss's theorem (Gamma functions)."""
    if theta == 0:
        return mpmath.mpc(0)
    if theta >= mpmath.pi:
        return _f0.J_pi(m, a)
    return _f0.J_theta(m, a, theta)


#: K_g from J_0, J_1, J_2: which J each needs, and how it is formed from them.
_K_FROM_J: dict[str, tuple[tuple[int, ...], Callable[[dict[int, Any]], Any]]] = {
    "cc": ((0, 2), lambda J: (J[0].real + J[2].real) / 2),
    "ss": ((0, 2), lambda J: (J[0].real - J[2].real) / 2),
    "sc": ((2,), lambda J: J[2].imag / 2),
    "s": ((1,), lambda J: J[1].imag),
}


def sqrt_integrals_mp(names: Iterable[str], a: MpReal, theta: MpReal) -> dict[str, Any]:
    """K_g(a, theta) from J_0, J_1, J_2 (cc, sc, ss, s), frozen at theta >= pi. Extra digits cover
    the cancellations at small theta (F(theta) - F(0) ~ theta^(3/2), and K_ss ~ theta^(7/2) from
    Re J_0 - Re J_2) and the 2F1 evaluation near z = 1 at theta -> pi.

    K_g(a, theta) = int_0^min(theta, pi) exp(-a t) g(t) sqrt(sin t) dt (36), g = cos^2 (cc),
    sin cos (sc), sin^2 (ss) or sin (s).

    Parameters
    ----------
    names : iterable of str
        Which K: ``"cc"``, ``"sc"``, ``"ss"``, ``"s"``.
    a : float or mpmath.mpf
        Decay rate, >= 0.
    theta : float or mpmath.mpf
        Upper end, >= 0 (values past pi give the value at pi).

    Returns
    -------
    dict of str to mpmath.mpf
        name -> K at the caller's working precision.

    Examples
    --------
    >>> import mpmath
    >>> from zener_sym.ham.runtime_mpmath import sqrt_integrals_mp
    >>> with mpmath.workdps(30):
    ...     K = sqrt_integrals_mp(("s",), 0, mpmath.pi)["s"]
    ...     exact = mpmath.beta(mpmath.mpf(5) / 4, mpmath.mpf(1) / 2)  # int_0^pi sin^(3/2)
    ...     bool(abs(K - exact) < mpmath.mpf(10) ** -28)
    True
    """
    guard = 15
    if 0 < theta < 1:
        guard += int(-3.5 * mpmath.log10(theta)) + 1
    if 0 < mpmath.pi - theta < 1:
        guard += int(-1.5 * mpmath.log10(mpmath.pi - theta)) + 1
    with mpmath.workdps(mpmath.mp.dps + guard):
        theta = min(mpmath.mpf(theta), +mpmath.pi)
        J: dict[int, Any] = {}
        for n in names:
            for m in _K_FROM_J[n][0]:
                if m not in J:
                    J[m] = _J(m, a, theta)
        out = {n: _K_FROM_J[n][1](J) for n in names}
    return out


_KERNEL_PARAMS_DOC = """tau : float, str or mpmath.mpf
    Dimensionless time, finite and >= 0.
lam : float, str or mpmath.mpf
    lambda, 0 <= lambda < LAM_CRIT.
dps : int, optional
    Digits of the result (default: the caller's ``mpmath.mp.dps``); 10 guard digits inside."""


def _contact(formula: Callable[..., Any], with_K: bool = False) -> _Kernel:
    """The kernel (tau, lam, dps) of a formula on the contact: inputs checked at dps + 10 digits,
    k, beta, omega0, and (``with_K``) the square-root integrals K_cc, K_sc, K_ss."""
    def kernel(tau: MpReal, lam: MpReal, dps: int | None = None) -> Any:
        p = _prec(dps)
        with mpmath.workdps(p + 10):
            tau, lam = _tau(tau), _lam(lam)
            k, beta, omega0 = _f0.params(lam)
            K: tuple[Any, ...] = ()
            if with_K:
                Kd = sqrt_integrals_mp(("cc", "sc", "ss"), _f1.a_first(beta, omega0), omega0 * tau)
                K = (Kd["cc"], Kd["sc"], Kd["ss"])
            out = formula(tau, lam, beta, omega0, *K)
        return _out(out, p)

    kernel.__doc__ = kernel_doc(formula, _KERNEL_PARAMS_DOC, "mpmath.mpf\n    At ``dps`` digits.")
    return kernel


delta0 = _contact(_f0.delta0)
delta0_dot = _contact(_f0.delta0_dot)


# ------------------------------------------------------------------------------ zeroth order
def _force0(tau: MpReal, lam: MpReal, dps: int | None = None) -> Any:
    """delta0^(3/2) during 0 <= tau <= pi/omega0, else 0."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        k, beta, omega0 = params(lam, mpmath.mp.dps)
        d = delta0(tau, lam, mpmath.mp.dps)
        out = mpmath.mpf(0) if (omega0 * _tau(tau) > mpmath.pi or d <= 0) else d ** 1.5
    return _out(out, p)


def _impulse0(tau: MpReal, lam: MpReal, dps: int | None = None) -> Any:
    """Impulse (47) = omega0^(-5/2) K_s(3 beta/(2 omega0), omega0 tau) by the 2F1 closed form."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        tau, lam = _tau(tau), _lam(lam)
        k, beta, omega0 = _f0.params(lam)
        Ks = sqrt_integrals_mp(("s",), _f0.a_impulse(beta, omega0), omega0 * tau)["s"]
        out = _f0.impulse(omega0, Ks)
    return _out(out, p)


def _summary0(lam: MpReal, dps: int | None = None) -> dict[str, Any]:
    """Zeroth-order closed forms (see the numpy kernels), impulse by Gamma functions."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        lam = _lam(lam)
        k, beta, omega0 = _f0.params(lam)
        s = _f0.summary(beta, omega0)
        Ks = sqrt_integrals_mp(("s",), s["a_imp"], mpmath.pi)["s"]
        res = dict(k=k, beta=beta, omega0=omega0, tau_d=s["tau_d"], tau_dc=s["tau_dc"],
                   tau_dr=s["tau_dr"], eta=s["eta"], e=s["e"], delta_m=s["delta_m"],
                   F_m=s["delta_m"] ** 1.5, impulse=_f0.impulse(omega0, Ks), int_F2=s["int_F2"])
    return {n: _out(v, p) for n, v in res.items()}


# ------------------------------------------------------------------------------- first order
_delta1 = _contact(_f1.delta, with_K=True)
_delta_dot1 = _contact(_f1.delta_dot, with_K=True)


def _force1(tau: MpReal, lam: MpReal, dps: int | None = None) -> Any:
    """max(delta, 0)^(3/2), meaningful up to the end of contact."""
    with mpmath.workdps(_prec(dps)):
        d = _delta1(tau, lam, mpmath.mp.dps)
        return d ** 1.5 if d > 0 else mpmath.mpf(0)


def _root(f: Callable[[Any], Any], guess: float, p: int) -> Any:
    """The zero of f near ``guess`` (Anderson's method from guess (1 +- 1e-7)), at p digits."""
    with mpmath.workdps(p + 5):
        h = 1e-7 * guess
        root = mpmath.findroot(f, (guess - h, guess + h), solver="anderson")
    return _out(root, p)


def _compression_end(lam: MpReal, dps: int | None = None, guess: float | None = None) -> Any:
    """tau_dc: zero of delta' near ``guess`` (default: the numpy kernel's root)."""
    if guess is None:
        from .runtime_numpy import ham1
        guess = float(ham1.compression_end(float(lam))[0])
    return _root(lambda t: _delta_dot1(t, lam, mpmath.mp.dps), guess, _prec(dps))


def _contact_end(lam: MpReal, dps: int | None = None, guess: float | None = None) -> Any:
    """tau_d: zero of delta after the maximum near ``guess`` (default: the numpy kernel's root)."""
    if guess is None:
        from .runtime_numpy import ham1
        guess = float(ham1.contact_end(float(lam))[0])
    return _root(lambda t: _delta1(t, lam, mpmath.mp.dps), guess, _prec(dps))


def _impulse1(tau: MpReal, lam: MpReal, dps: int | None = None,
              tau_d: MpReal | None = None) -> Any:
    """Impulse (47): int_0^min(tau, tau_d) F dtau, split at pi/omega0, mpmath.quad on the
    smoothstep-mapped pieces (slow: many 2F1 evaluations)."""
    p = _prec(dps)
    with mpmath.workdps(p + 5):
        tau, lam = _tau(tau), _lam(lam)
        k, beta, omega0 = params(lam, mpmath.mp.dps)
        if tau_d is None:
            tau_d = _contact_end(lam, mpmath.mp.dps)
        end = min(tau, mpmath.mpf(tau_d))
        tpi = mpmath.pi / omega0
        def f(t: Any) -> Any:
            return _force1(t, lam, mpmath.mp.dps)

        out = contact_integral_mp(f, 0, min(end, tpi)) + contact_integral_mp(f, tpi, max(end, tpi))
    return _out(out, p)


_COMMON = dict(LAM_CRIT_DIGITS=LAM_CRIT_DIGITS, params=params, delta0=delta0,
               delta0_dot=delta0_dot)

#: The zeroth-order kernels at any precision.
ham0 = types.SimpleNamespace(**_COMMON, delta=delta0, delta_dot=delta0_dot, force=_force0,
                             impulse=_impulse0, summary=_summary0)

#: The first-order kernels at any precision.
ham1 = types.SimpleNamespace(
    **_COMMON, delta1=_contact(_f1.delta1, with_K=True), delta=_delta1, delta_dot=_delta_dot1,
    force=_force1, compression_end=_compression_end, contact_end=_contact_end,
    impulse=_impulse1)
