"""The numpy HAM kernels: the hand-written runtime around the printed formulas.

``generated/ham0.py`` and ``generated/ham1.py`` hold the formulas only (SymPy's
printers, no checks); this module validates and broadcasts the inputs, computes k, beta,
omega0 once per lambda, the square-root integrals K (Gauss-Jacobi quadrature,
:mod:`zener_sym.numerics.sqrt_integrals`), the first-order roots (:func:`numerics.roots.first_root`)
and contact integrals (:mod:`zener_sym.numerics.integrate`). A change here needs no
regeneration.

``ham0`` and ``ham1`` are the kernels of each order (``ham0.delta``, ``ham1.summary``, ...):

- ``ham0``: ``params`` (k, beta, omega0), ``delta0``/``delta``, ``delta0_dot``/``delta_dot``,
  ``force``, ``delta_contact`` (delta0 on its contact, 0 after), ``impulse``, ``summary``
  (closed forms).
- ``ham1``: ``params``, ``delta0``, ``delta0_dot``, ``delta1``, ``delta``, ``delta_dot``,
  ``delta_from_K``, ``delta_dot_from_K`` (given K), ``delta_scaled``, ``delta_dot_scaled``,
  ``force``, ``compression_end``, ``contact_end``, ``impulse``, ``summary``.
"""
from __future__ import annotations

import types
from collections.abc import Callable

import numpy

from ..generated import ham0 as _ham0
from ..generated import ham1 as _ham1
from ..numerics.integrate import cumulative_integral
from ..numerics.roots import first_root
from ..numerics.sqrt_integrals import sqrt_integrals
from ..typing import FloatArray, RealArrayLike
from .xp import NUMPY, bind, kernel_doc

_f0 = bind(_ham0, NUMPY)  # the formulas, printed once for every backend, on numpy
_f1 = bind(_ham1, NUMPY)

__all__ = ["LAM_CRIT", "LAM_CRIT_DIGITS", "ham0", "ham1"]

#: Critical lambda: omega0 = 0 there (Eq. 81); the HAM solution needs 0 <= lambda < LAM_CRIT.
LAM_CRIT: float = _f0.LAM_CRIT
#: LAM_CRIT to 40 significant digits.
LAM_CRIT_DIGITS: str = _f0.LAM_CRIT_DIGITS

#: (tau, lam) -> values: a first-order kernel
_Kernel = Callable[[RealArrayLike, RealArrayLike], FloatArray]


def _lam(lam: RealArrayLike) -> FloatArray:
    la: FloatArray = numpy.asarray(lam, dtype=float)
    if not numpy.all(numpy.isfinite(la)):
        raise ValueError("lambda must be finite; allowed: 0 <= lambda < LAM_CRIT = " + LAM_CRIT_DIGITS)
    if numpy.any(la < 0) or numpy.any(la >= LAM_CRIT):
        bad = la[(la < 0) | (la >= LAM_CRIT)].ravel()[0]
        raise ValueError(f"lambda = {bad!r} is outside the HAM solution's range: allowed "
                         f"0 <= lambda < LAM_CRIT = {LAM_CRIT_DIGITS} (omega0 is not real beyond)")
    return la


def _inputs_narrow(tau: RealArrayLike, lam: RealArrayLike) -> tuple[FloatArray, FloatArray]:
    """Validated tau and lambda; lambda keeps its own shape (its parameters are then computed
    once per lambda, not once per point) and tau takes the common shape, so every term that has
    tau in it does too."""
    lam_a = _lam(lam)
    tau_a = numpy.asarray(tau, dtype=float)
    if not numpy.all(numpy.isfinite(tau_a)) or numpy.any(tau_a < 0):
        raise ValueError("tau must be finite and >= 0")
    return numpy.broadcast_to(tau_a, numpy.broadcast_shapes(tau_a.shape, lam_a.shape)), lam_a


def _inputs(tau: RealArrayLike, lam: RealArrayLike) -> tuple[FloatArray, FloatArray]:
    """Validated tau and lambda, both of the common shape."""
    t, la = numpy.broadcast_arrays(*_inputs_narrow(tau, lam))
    return t, la


def params(lam: RealArrayLike) -> tuple[FloatArray, FloatArray, FloatArray]:
    """k (25), beta (32) and omega0 (33) of the zeroth-order operator, as float arrays.

    Parameters
    ----------
    lam : float or array_like
        lambda, 0 <= lambda < ``LAM_CRIT`` (Eq. 81).

    Returns
    -------
    k, beta, omega0 : ndarray
        Of the shape of ``lam``.

    Raises
    ------
    ValueError
        A lambda outside [0, LAM_CRIT) or not finite.

    Examples
    --------
    >>> from zener_sym.ham.runtime_numpy import params
    >>> k, beta, omega0 = params([0.0, 1.0])
    >>> bool(abs(k[0] - 1.25 ** 0.2) < 1e-15 and beta[0] == 0.0)  # k(0) = delta_m(0)^(1/2)
    True
    """
    k, beta, omega0 = _f0.params(_lam(lam))
    return k, beta, omega0


def delta0(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """Zeroth-order compression delta0 (35), continued analytically (no clipping).

    Parameters
    ----------
    tau : float or array_like
        Dimensionless time, finite and >= 0.
    lam : float or array_like
        lambda, 0 <= lambda < ``LAM_CRIT``; broadcast against ``tau``.

    Returns
    -------
    ndarray
        delta0, of the broadcast shape.

    Raises
    ------
    ValueError
        tau negative or not finite, or lambda out of range.

    Examples
    --------
    >>> import numpy as np
    >>> from zener_sym.ham.runtime_numpy import delta0, params
    >>> k, beta, omega0 = params(0.0)
    >>> bool(abs(delta0(np.pi / (2 * omega0), 0.0) - 1 / omega0) < 1e-15)  # lambda = 0: a sine
    True
    """
    t, la = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(la)
    out: FloatArray = _f0.delta0(t, la, beta, omega0)
    return out


def delta0_dot(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """Zeroth-order relative velocity delta0' (56), continued analytically.

    Parameters
    ----------
    tau : float or array_like
        Dimensionless time, finite and >= 0.
    lam : float or array_like
        lambda, 0 <= lambda < ``LAM_CRIT``; broadcast against ``tau``.

    Returns
    -------
    ndarray
        delta0', of the broadcast shape.

    Raises
    ------
    ValueError
        tau negative or not finite, or lambda out of range.

    Examples
    --------
    >>> from zener_sym.ham.runtime_numpy import delta0_dot
    >>> delta0_dot(0.0, [0.0, 1.0, 2.0]).round(15).tolist()  # (29): delta0'(0) = 1
    [1.0, 1.0, 1.0]
    """
    t, la = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(la)
    out: FloatArray = _f0.delta0_dot(t, la, beta, omega0)
    return out


# ------------------------------------------------------------------------------ zeroth order
def _force0(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """Contact force F = delta0^(3/2) (45) during the zeroth-order contact, 0 after pi/omega0."""
    t, la = _inputs(tau, lam)
    k, beta, omega0 = params(la)
    d = delta0(t, la)
    out: FloatArray = numpy.where(omega0 * t <= numpy.pi, numpy.maximum(d, 0.0), 0.0) ** 1.5
    return out


def _delta_contact(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """delta0 (35) on the zeroth-order contact 0 <= omega0 tau <= pi, 0 after (Eq. 54): the sine
    is its first half wave (``numerics.elementary.half_wave_sin``, vectorized, within 3 ulp)."""
    t, la = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(la)
    out: FloatArray = _f0.delta_contact(t, la, beta, omega0)
    return out


def _impulse0(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """Impulse (47) int_0^tau F dtau = omega0^(-5/2) K_s(3 beta / (2 omega0), omega0 tau), frozen
    after pi/omega0; K_s by Gauss-Jacobi quadrature (``numerics.sqrt_integrals``)."""
    t, la = _inputs(tau, lam)
    k, beta, omega0 = params(la)
    Ks = sqrt_integrals(_f0.a_impulse(beta, omega0), omega0 * t, ("s",))["s"]
    out: FloatArray = _f0.impulse(omega0, Ks)
    return out


def _summary0(lam: RealArrayLike) -> dict[str, FloatArray]:
    """Zeroth-order closed forms: k, beta, omega0, tau_d (54), tau_dc (58), tau_dr (60), eta (61),
    e (79), delta_m = delta0(tau_dc), F_m, impulse (47) at tau_d, int_F2 (integral of F^2)."""
    k, beta, omega0 = params(lam)
    s = _f0.summary(beta, omega0)
    Ks = sqrt_integrals(s["a_imp"], numpy.pi, ("s",))["s"]
    return dict(k=k, beta=beta, omega0=omega0, tau_d=s["tau_d"], tau_dc=s["tau_dc"],
                tau_dr=s["tau_dr"], eta=s["eta"], e=s["e"], delta_m=s["delta_m"],
                F_m=s["delta_m"] ** 1.5, impulse=_f0.impulse(omega0, Ks), int_F2=s["int_F2"])


# ------------------------------------------------------------------------------- first order
def _K(beta: FloatArray, omega0: FloatArray,
       tau: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Square-root integrals K_cc, K_sc, K_ss at a = beta / (2 omega0), theta = omega0 tau, by
    Gauss-Jacobi quadrature (``numerics.sqrt_integrals``: why not scipy hyp2f1 is explained
    there); frozen at theta = pi (delta0 < 0 beyond: its contact force and sqrt(delta0) are
    zero)."""
    K = sqrt_integrals(_f1.a_first(beta, omega0), omega0 * tau, ("cc", "sc", "ss"))
    return K["cc"], K["sc"], K["ss"]


_TAU_LAM_DOC = """tau : float or array_like
    Dimensionless time, finite and >= 0.
lam : float or array_like
    lambda, 0 <= lambda < LAM_CRIT; broadcast against ``tau``."""
_GIVEN_K_DOC = """Kcc, Ksc, Kss : ndarray
    The square-root integrals (36) at omega0 tau (not checked)."""
_ARRAY_OUT_DOC = """ndarray
    Of the broadcast shape."""


def _with_K(formula: Callable[..., FloatArray]) -> _Kernel:
    """The first-order kernel of ``formula`` (tau, lam): validated inputs, K by quadrature."""
    def kernel(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
        t, la = _inputs(tau, lam)
        k, beta, omega0 = params(la)
        return formula(t, la, beta, omega0, *_K(beta, omega0, t))

    kernel.__doc__ = kernel_doc(formula, _TAU_LAM_DOC, _ARRAY_OUT_DOC)
    return kernel


def _given_K(formula: Callable[..., FloatArray]) -> Callable[..., FloatArray]:
    """The first-order kernel of ``formula`` for given square-root integrals K_cc, K_sc, K_ss
    at omega0 tau. The inputs are not checked: ``delta`` passes its quadrature values, and
    ``zener_sym.ham.spectral`` its Chebyshev-series values, both on validated arrays."""
    def kernel(tau: FloatArray, lam: FloatArray, Kcc: FloatArray, Ksc: FloatArray,
               Kss: FloatArray) -> FloatArray:
        k, beta, omega0 = params(lam)
        return formula(tau, lam, beta, omega0, Kcc, Ksc, Kss)

    kernel.__doc__ = kernel_doc(formula, _TAU_LAM_DOC + "\n" + _GIVEN_K_DOC, _ARRAY_OUT_DOC)
    return kernel


_delta1 = _with_K(_f1.delta)
_delta_dot1 = _with_K(_f1.delta_dot)
_delta_scaled = _with_K(_f1.delta_scaled)
_delta_dot_scaled = _with_K(_f1.delta_dot_scaled)


def _force1(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    """max(delta, 0)^(3/2) pointwise (45); meaningful up to the end of contact (contact_end)."""
    out: FloatArray = numpy.maximum(_delta1(tau, lam), 0.0) ** 1.5
    return out


def _force2(tau: RealArrayLike, lam: RealArrayLike) -> FloatArray:
    out: FloatArray = numpy.maximum(_delta1(tau, lam), 0.0) ** 3
    return out


def _compression_end(lam: RealArrayLike) -> FloatArray:
    """tau_dc: first zero of delta' (root finding, vectorised over lambda)."""
    la = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(la)
    out: FloatArray = first_root(_delta_dot_scaled, la, numpy.zeros_like(la), numpy.pi / omega0,
                                 n_scan=64, what="end of compression (delta' = 0)")
    return out


def _contact_end(lam: RealArrayLike, tau_dc: FloatArray | None = None) -> FloatArray:
    """tau_d: first zero of delta after the maximum, searched up to 3 pi/omega0."""
    la = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(la)
    if tau_dc is None:
        tau_dc = _compression_end(la)
    out: FloatArray = first_root(_delta_scaled, la, tau_dc, 3.0 * numpy.pi / omega0, n_scan=192,
                                 what="end of contact (delta = 0)")
    return out


def _contact_integral(fun: _Kernel, tau: FloatArray, lam: FloatArray,
                      tau_d: FloatArray) -> FloatArray:
    """int_0^min(tau, tau_d) fun dtau, split at pi/omega0 (where the sqrt terms switch off); one
    Chebyshev antiderivative per lambda serves every tau (``numerics.integrate``)."""
    k, beta, omega0 = params(lam)
    end = numpy.minimum(tau, tau_d)
    tpi = numpy.pi / omega0
    first = cumulative_integral(fun, 0.0, numpy.minimum(tau_d, tpi), lam, numpy.minimum(end, tpi))
    second = cumulative_integral(fun, tpi, numpy.maximum(tau_d, tpi), lam,
                                 numpy.maximum(end, tpi))
    out: FloatArray = first + second
    return out


def _impulse1(tau: RealArrayLike, lam: RealArrayLike,
              tau_d: FloatArray | None = None) -> FloatArray:
    """Impulse (47): int_0^min(tau, tau_d) max(delta, 0)^(3/2) dtau, a smoothstep-mapped Chebyshev
    antiderivative per lambda (``numerics.integrate.cumulative_integral``); frozen after the end
    of contact."""
    t, la = _inputs(tau, lam)
    if tau_d is None:
        u, inv = numpy.unique(la, return_inverse=True)
        tau_d = _contact_end(u)[inv].reshape(la.shape)
    return _contact_integral(_force1, t, la, tau_d)


def _summary1(lam: RealArrayLike) -> dict[str, FloatArray]:
    """First-order summary by root finding and quadrature on delta0 + delta1: tau_dc, delta_m, F_m,
    tau_d, tau_dr, eta, e = -delta'(tau_d), impulse and int_F2 over the contact."""
    la = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(la)
    tau_dc = _compression_end(la)
    tau_d = _contact_end(la, tau_dc)
    delta_m = _delta1(tau_dc, la)
    imp = _contact_integral(_force1, tau_d, la, tau_d)
    int_F2 = _contact_integral(_force2, tau_d, la, tau_d)
    return dict(k=k, beta=beta, omega0=omega0, tau_d=tau_d, tau_dc=tau_dc, tau_dr=tau_d - tau_dc,
                eta=(tau_d - tau_dc) / tau_dc, e=-_delta_dot1(tau_d, la), delta_m=delta_m,
                F_m=delta_m ** 1.5, impulse=imp, int_F2=int_F2)


_COMMON = dict(LAM_CRIT=LAM_CRIT, LAM_CRIT_DIGITS=LAM_CRIT_DIGITS, params=params, delta0=delta0,
               delta0_dot=delta0_dot)

#: The zeroth-order kernels (35, 45, 47, 54-61, 79).
ham0 = types.SimpleNamespace(
    **_COMMON, delta=delta0, delta_dot=delta0_dot, force=_force0, delta_contact=_delta_contact,
    impulse=_impulse0, summary=_summary0)

#: The first-order kernels (37-42: delta0 + delta1, its roots and contact integrals).
ham1 = types.SimpleNamespace(
    **_COMMON, delta1=_with_K(_f1.delta1), delta=_delta1, delta_dot=_delta_dot1,
    delta_from_K=_given_K(_f1.delta), delta_dot_from_K=_given_K(_f1.delta_dot),
    delta_scaled=_delta_scaled, delta_dot_scaled=_delta_dot_scaled, force=_force1,
    compression_end=_compression_end, contact_end=_contact_end, impulse=_impulse1,
    summary=_summary1)
