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

import numpy

from ..generated import ham0 as _ham0
from ..generated import ham1 as _ham1
from ..numerics.integrate import cumulative_integral
from ..numerics.roots import first_root
from ..numerics.sqrt_integrals import sqrt_integrals
from .xp import NUMPY, bind

_f0 = bind(_ham0, NUMPY)  # the formulas, printed once for every backend, on numpy
_f1 = bind(_ham1, NUMPY)

__all__ = ["LAM_CRIT", "LAM_CRIT_DIGITS", "ham0", "ham1"]

#: Critical lambda: omega0 = 0 there (Eq. 81); the HAM solution needs 0 <= lambda < LAM_CRIT.
LAM_CRIT = _f0.LAM_CRIT
#: LAM_CRIT to 40 significant digits.
LAM_CRIT_DIGITS = _f0.LAM_CRIT_DIGITS


def _lam(lam):
    lam = numpy.asarray(lam, dtype=float)
    if not numpy.all(numpy.isfinite(lam)):
        raise ValueError("lambda must be finite; allowed: 0 <= lambda < LAM_CRIT = " + LAM_CRIT_DIGITS)
    if numpy.any(lam < 0) or numpy.any(lam >= LAM_CRIT):
        bad = lam[(lam < 0) | (lam >= LAM_CRIT)].ravel()[0]
        raise ValueError(f"lambda = {bad!r} is outside the HAM solution's range: allowed "
                         f"0 <= lambda < LAM_CRIT = {LAM_CRIT_DIGITS} (omega0 is not real beyond)")
    return lam


def _inputs_narrow(tau, lam):
    """Validated tau and lambda; lambda keeps its own shape (its parameters are then computed
    once per lambda, not once per point) and tau takes the common shape, so every term that has
    tau in it does too."""
    lam = _lam(lam)
    tau = numpy.asarray(tau, dtype=float)
    if not numpy.all(numpy.isfinite(tau)) or numpy.any(tau < 0):
        raise ValueError("tau must be finite and >= 0")
    return numpy.broadcast_to(tau, numpy.broadcast_shapes(tau.shape, lam.shape)), lam


def _inputs(tau, lam):
    """Validated tau and lambda, both of the common shape."""
    return numpy.broadcast_arrays(*_inputs_narrow(tau, lam))


def params(lam):
    """k (25), beta (32) and omega0 (33) of the zeroth-order operator, as float arrays."""
    return _f0.params(_lam(lam))


def delta0(tau, lam):
    """Zeroth-order compression delta0 (35), continued analytically (no clipping)."""
    tau, lam = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(lam)
    return _f0.delta0(tau, lam, beta, omega0)


def delta0_dot(tau, lam):
    """Zeroth-order relative velocity delta0' (56), continued analytically."""
    tau, lam = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(lam)
    return _f0.delta0_dot(tau, lam, beta, omega0)


# ------------------------------------------------------------------------------ zeroth order
def _force0(tau, lam):
    """Contact force F = delta0^(3/2) (45) during the zeroth-order contact, 0 after pi/omega0."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    d = delta0(tau, lam)
    return numpy.where(omega0 * tau <= numpy.pi, numpy.maximum(d, 0.0), 0.0) ** 1.5


def _delta_contact(tau, lam):
    """delta0 (35) on the zeroth-order contact 0 <= omega0 tau <= pi, 0 after (Eq. 54): the sine
    is its first half wave (``numerics.elementary.half_wave_sin``, vectorized, within 3 ulp)."""
    tau, lam = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(lam)
    return _f0.delta_contact(tau, lam, beta, omega0)


def _impulse0(tau, lam):
    """Impulse (47) int_0^tau F dtau = omega0^(-5/2) K_s(3 beta / (2 omega0), omega0 tau), frozen
    after pi/omega0; K_s by Gauss-Jacobi quadrature (``numerics.sqrt_integrals``)."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    Ks = sqrt_integrals(_f0.a_impulse(beta, omega0), omega0 * tau, ("s",))["s"]
    return _f0.impulse(omega0, Ks)


def _summary0(lam):
    """Zeroth-order closed forms: k, beta, omega0, tau_d (54), tau_dc (58), tau_dr (60), eta (61),
    e (79), delta_m = delta0(tau_dc), F_m, impulse (47) at tau_d, int_F2 (integral of F^2)."""
    k, beta, omega0 = params(lam)
    s = _f0.summary(beta, omega0)
    Ks = sqrt_integrals(s["a_imp"], numpy.pi, ("s",))["s"]
    return dict(k=k, beta=beta, omega0=omega0, tau_d=s["tau_d"], tau_dc=s["tau_dc"],
                tau_dr=s["tau_dr"], eta=s["eta"], e=s["e"], delta_m=s["delta_m"],
                F_m=s["delta_m"] ** 1.5, impulse=_f0.impulse(omega0, Ks), int_F2=s["int_F2"])


# ------------------------------------------------------------------------------- first order
def _K(beta, omega0, tau):
    """Square-root integrals K_cc, K_sc, K_ss at a = beta / (2 omega0), theta = omega0 tau, by
    Gauss-Jacobi quadrature (``numerics.sqrt_integrals``: why not scipy hyp2f1 is explained
    there); frozen at theta = pi (delta0 < 0 beyond: its contact force and sqrt(delta0) are
    zero)."""
    K = sqrt_integrals(_f1.a_first(beta, omega0), omega0 * tau, ("cc", "sc", "ss"))
    return K["cc"], K["sc"], K["ss"]


def _with_K(formula):
    """The first-order kernel of ``formula`` (tau, lam): validated inputs, K by quadrature."""
    def kernel(tau, lam):
        tau, lam = _inputs(tau, lam)
        k, beta, omega0 = params(lam)
        return formula(tau, lam, beta, omega0, *_K(beta, omega0, tau))

    kernel.__doc__ = formula.__doc__
    return kernel


def _given_K(formula):
    """The first-order kernel of ``formula`` for given square-root integrals K_cc, K_sc, K_ss
    at omega0 tau. The inputs are not checked: ``delta`` passes its quadrature values, and
    ``zener_sym.ham.spectral`` its Chebyshev-series values, both on validated arrays."""
    def kernel(tau, lam, Kcc, Ksc, Kss):
        k, beta, omega0 = params(lam)
        return formula(tau, lam, beta, omega0, Kcc, Ksc, Kss)

    kernel.__doc__ = formula.__doc__
    return kernel


_delta1 = _with_K(_f1.delta)
_delta_dot1 = _with_K(_f1.delta_dot)
_delta_scaled = _with_K(_f1.delta_scaled)
_delta_dot_scaled = _with_K(_f1.delta_dot_scaled)


def _force1(tau, lam):
    """max(delta, 0)^(3/2) pointwise (45); meaningful up to the end of contact (contact_end)."""
    return numpy.maximum(_delta1(tau, lam), 0.0) ** 1.5


def _force2(tau, lam):
    return numpy.maximum(_delta1(tau, lam), 0.0) ** 3


def _compression_end(lam):
    """tau_dc: first zero of delta' (root finding, vectorised over lambda)."""
    lam = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(lam)
    return first_root(_delta_dot_scaled, lam, numpy.zeros_like(lam), numpy.pi / omega0,
                      n_scan=64, what="end of compression (delta' = 0)")


def _contact_end(lam, tau_dc=None):
    """tau_d: first zero of delta after the maximum, searched up to 3 pi/omega0."""
    lam = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(lam)
    if tau_dc is None:
        tau_dc = _compression_end(lam)
    return first_root(_delta_scaled, lam, tau_dc, 3.0 * numpy.pi / omega0, n_scan=192,
                      what="end of contact (delta = 0)")


def _contact_integral(fun, tau, lam, tau_d):
    """int_0^min(tau, tau_d) fun dtau, split at pi/omega0 (where the sqrt terms switch off); one
    Chebyshev antiderivative per lambda serves every tau (``numerics.integrate``)."""
    k, beta, omega0 = params(lam)
    end = numpy.minimum(tau, tau_d)
    tpi = numpy.pi / omega0
    first = cumulative_integral(fun, 0.0, numpy.minimum(tau_d, tpi), lam, numpy.minimum(end, tpi))
    second = cumulative_integral(fun, tpi, numpy.maximum(tau_d, tpi), lam,
                                 numpy.maximum(end, tpi))
    return first + second


def _impulse1(tau, lam, tau_d=None):
    """Impulse (47): int_0^min(tau, tau_d) max(delta, 0)^(3/2) dtau, a smoothstep-mapped Chebyshev
    antiderivative per lambda (``numerics.integrate.cumulative_integral``); frozen after the end
    of contact."""
    tau, lam = _inputs(tau, lam)
    if tau_d is None:
        u, inv = numpy.unique(lam, return_inverse=True)
        tau_d = _contact_end(u)[inv].reshape(lam.shape)
    return _contact_integral(_force1, tau, lam, tau_d)


def _summary1(lam):
    """First-order summary by root finding and quadrature on delta0 + delta1: tau_dc, delta_m, F_m,
    tau_d, tau_dr, eta, e = -delta'(tau_d), impulse and int_F2 over the contact."""
    lam = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(lam)
    tau_dc = _compression_end(lam)
    tau_d = _contact_end(lam, tau_dc)
    delta_m = _delta1(tau_dc, lam)
    imp = _contact_integral(_force1, tau_d, lam, tau_d)
    int_F2 = _contact_integral(_force2, tau_d, lam, tau_d)
    return dict(k=k, beta=beta, omega0=omega0, tau_d=tau_d, tau_dc=tau_dc, tau_dr=tau_d - tau_dc,
                eta=(tau_d - tau_dc) / tau_dc, e=-_delta_dot1(tau_d, lam), delta_m=delta_m,
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
