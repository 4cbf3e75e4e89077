"""Builders of the HAM kernels in generated/: numpy and mpmath, orders 0 and 1.

Every formula in the emitted files is printed by SymPy's code printers from the expressions of
``ham_exprs.ham_expressions()`` (with common subexpressions shared through ``sympy.cse``); the
surrounding templates here only hold signatures, input checks and calls into the hand-written
numerics (``zener_sym.ham.quadrature`` for the square-root integrals, ``zener_sym.ham.chebyshev`` for
root finding and contact integrals). Output is deterministic: cse uses numbered symbols and its
canonical order, and nothing is printed from an unordered container.
"""
from __future__ import annotations

import sympy as sp
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.pycode import MpmathPrinter

from . import header
from .ham_exprs import REGISTRY_SOURCES
from .ham_exprs import SYMBOLS as Y
from .ham_exprs import ham_expressions

__all__ = ["build_ham0_numpy", "build_ham1_numpy", "build_ham0_mpmath", "build_ham1_mpmath"]

_SOURCES = ("zener_sym.codegen.ham", "zener_sym.codegen.ham_exprs") + REGISTRY_SOURCES


class _NumpyPrinter(NumPyPrinter):
    def _print_P3(self, e):
        return f"_p3({self._print(e.args[0])})"

    def _print_Atan2(self, e):
        return f"numpy.arctan2({self._print(e.args[0])}, {self._print(e.args[1])})"


class _HalfWavePrinter(_NumpyPrinter):
    """For delta0 on its contact only: its one sine, of the phase omega0 tau, is printed as the
    first half wave (``ham.chebyshev.half_wave_sin``: sin on [0, pi], 0 beyond; vectorized)."""

    def _print_sin(self, e):
        return f"_el.half_wave_sin({self._print(e.args[0])})"


class _MpPrinter(MpmathPrinter):
    def _print_P3(self, e):
        return f"_p3({self._print(e.args[0])})"

    def _print_Atan2(self, e):
        return f"mpmath.atan2({self._print(e.args[0])}, {self._print(e.args[1])})"

    def _print_re(self, e):
        return f"mpmath.re({self._print(e.args[0])})"

    def _print_im(self, e):
        return f"mpmath.im({self._print(e.args[0])})"


def _block(printer, outputs, indent="    ", prefix="_x"):
    """Assignments computing ``outputs`` [(name, expr)] with shared subexpressions."""
    exprs = [ex for _, ex in outputs]
    reps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix), order="canonical")
    lines = [f"{indent}{printer.doprint(s)} = {printer.doprint(v)}" for s, v in reps]
    lines += [f"{indent}{name} = {printer.doprint(r)}" for (name, _), r in zip(outputs, reduced)]
    return "\n".join(lines)


def _common():
    e = ham_expressions()
    lam_crit = sp.Float(e["lam_crit"], 40)
    return e, lam_crit


def _params_outputs(e):
    return [("k", e["k_of_lam"]), ("beta", e["beta_of_lam"]), ("omega0", e["omega0_of_lam"])]


def _scaled(expr):
    """exp(beta tau) * expr, with the exponentials merged (avoids underflow in root finding)."""
    return sp.expand(sp.powsimp(sp.expand(expr * sp.exp(Y["beta"] * Y["tau"]))))


def _summary0_outputs(e):
    return [("tau_d", e["tau_d0"]), ("tau_dc", e["tau_dc0"]), ("tau_dr", e["tau_dr0"]),
            ("eta", e["eta0"]), ("e", e["e0"]), ("delta_m", e["delta_m0"]),
            ("int_F2", e["int_F2_0"]), ("a_imp", e["a_impulse0"])]


# ------------------------------------------------------------------------------------- numpy
_NP_PRELUDE = '''
import numpy

from zener_sym.numerics import elementary as _el
from zener_sym.numerics import integrate as _int
from zener_sym.numerics.roots import first_root
from zener_sym.numerics.sqrt_integrals import sqrt_integrals

_p3 = _el.p3

#: Critical lambda: omega0 = 0 there (Eq. 81); the HAM solution needs 0 <= lambda < LAM_CRIT.
LAM_CRIT = {lam_crit_float}
#: LAM_CRIT to 40 significant digits (root of {lam_crit_eq} = 0)
LAM_CRIT_DIGITS = "{lam_crit_str}"


def _lam(lam):
    lam = numpy.asarray(lam, dtype=float)
    if not numpy.all(numpy.isfinite(lam)):
        raise ValueError("lambda must be finite; allowed: 0 <= lambda < LAM_CRIT = " + LAM_CRIT_DIGITS)
    if numpy.any(lam < 0) or numpy.any(lam >= LAM_CRIT):
        bad = lam[(lam < 0) | (lam >= LAM_CRIT)].ravel()[0]
        raise ValueError(f"lambda = {{bad!r}} is outside the HAM solution's range: allowed "
                         f"0 <= lambda < LAM_CRIT = {{LAM_CRIT_DIGITS}} (omega0 is not real beyond)")
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
    lam = _lam(lam)
{params_block}
    return k, beta, omega0


def delta0(tau, lam):
    """Zeroth-order compression delta0 (35), continued analytically (no clipping)."""
    tau, lam = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(lam)
{delta0_block}
    return out


def delta0_dot(tau, lam):
    """Zeroth-order relative velocity delta0' (56), continued analytically."""
    tau, lam = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(lam)
{delta0_dot_block}
    return out
'''

_NP_HAM0 = '''

def delta(tau, lam):
    """delta0 (35) on the zeroth-order contact 0 <= tau <= pi/omega0 (analytic continuation beyond)."""
    return delta0(tau, lam)


def delta_dot(tau, lam):
    """delta0' (56)."""
    return delta0_dot(tau, lam)


def force(tau, lam):
    """Contact force F = delta0^(3/2) (45) during the zeroth-order contact, 0 after pi/omega0."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    d = delta0(tau, lam)
    return numpy.where(omega0 * tau <= numpy.pi, numpy.maximum(d, 0.0), 0.0) ** 1.5


def delta_contact(tau, lam):
    """delta0 (35) on the zeroth-order contact 0 <= omega0 tau <= pi, 0 after (Eq. 54): the sine
    is its first half wave (zener_sym.ham.chebyshev.half_wave_sin, vectorized, within 3 ulp)."""
    tau, lam = _inputs_narrow(tau, lam)
    k, beta, omega0 = params(lam)
{delta_contact_block}
    return out


def impulse(tau, lam):
    """Impulse (47) int_0^tau F dtau = omega0^(-5/2) K_s(3 beta / (2 omega0), omega0 tau), frozen
    after pi/omega0; K_s by Gauss-Jacobi quadrature (zener_sym.ham.quadrature)."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
{a_imp_block}
    Ks = sqrt_integrals(a_imp, omega0 * tau, ("s",))["s"]
{impulse_block}
    return out


def summary(lam):
    """Zeroth-order closed forms: k, beta, omega0, tau_d (54), tau_dc (58), tau_dr (60), eta (61),
    e (79), delta_m = delta0(tau_dc), F_m, impulse (47) at tau_d, int_F2 (integral of F^2)."""
    k, beta, omega0 = params(lam)
{summary_block}
    Ks = sqrt_integrals(a_imp, numpy.pi, ("s",))["s"]
{impulse_block}
    return dict(k=k, beta=beta, omega0=omega0, tau_d=tau_d, tau_dc=tau_dc, tau_dr=tau_dr, eta=eta,
                e=e, delta_m=delta_m, F_m=delta_m ** 1.5, impulse=out, int_F2=int_F2)
'''

_NP_HAM1 = '''

def _K(beta, omega0, tau):
    """Square-root integrals K_cc, K_sc, K_ss at a = beta / (2 omega0), theta = omega0 tau, by
    Gauss-Jacobi quadrature (zener_sym.ham.quadrature: why not scipy hyp2f1 is explained there); frozen at
    theta = pi (delta0 < 0 beyond: its contact force and sqrt(delta0) are zero)."""
{a_block}
    K = sqrt_integrals(a, omega0 * tau, ("cc", "sc", "ss"))
    return K["cc"], K["sc"], K["ss"]


def delta1(tau, lam):
    """First-order correction delta1 (37)-(42): variation of constants, C(tau) - C(0)."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    Kcc, Ksc, Kss = _K(beta, omega0, tau)
{delta1_block}
    return out


def delta(tau, lam):
    """First-order HAM compression delta0 + delta1 (42), with the continuation past pi/omega0."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    return delta_from_K(tau, lam, *_K(beta, omega0, tau))


def delta_dot(tau, lam):
    """d/dtau of delta0 + delta1 (the C' terms cancel by Eq. 38)."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    return delta_dot_from_K(tau, lam, *_K(beta, omega0, tau))


def delta_from_K(tau, lam, Kcc, Ksc, Kss):
    """delta0 + delta1 (42) for given square-root integrals K_cc, K_sc, K_ss at omega0 tau.

    The inputs are not checked: ``delta`` passes its quadrature values, and
    ``zener_sym.ham.spectral`` its Chebyshev-series values, both on validated arrays."""
    k, beta, omega0 = params(lam)
{delta_block}
    return out


def delta_dot_from_K(tau, lam, Kcc, Ksc, Kss):
    """d/dtau of delta0 + delta1 for given K_cc, K_sc, K_ss (inputs not checked, as above)."""
    k, beta, omega0 = params(lam)
{delta_dot_block}
    return out


def delta_scaled(tau, lam):
    """exp(beta tau) * delta: same sign as delta, no underflow (used for root finding)."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    Kcc, Ksc, Kss = _K(beta, omega0, tau)
{delta_scaled_block}
    return out


def delta_dot_scaled(tau, lam):
    """exp(beta tau) * delta' (same sign, no underflow)."""
    tau, lam = _inputs(tau, lam)
    k, beta, omega0 = params(lam)
    Kcc, Ksc, Kss = _K(beta, omega0, tau)
{delta_dot_scaled_block}
    return out


def force(tau, lam):
    """max(delta, 0)^(3/2) pointwise (45); meaningful up to the end of contact (contact_end)."""
    return numpy.maximum(delta(tau, lam), 0.0) ** 1.5


def compression_end(lam):
    """tau_dc: first zero of delta' (root finding, vectorised over lambda)."""
    lam = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(lam)
    return first_root(delta_dot_scaled, lam, numpy.zeros_like(lam), numpy.pi / omega0,
                          n_scan=64, what="end of compression (delta' = 0)")


def contact_end(lam, tau_dc=None):
    """tau_d: first zero of delta after the maximum, searched up to 3 pi/omega0."""
    lam = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(lam)
    if tau_dc is None:
        tau_dc = compression_end(lam)
    return first_root(delta_scaled, lam, tau_dc, 3.0 * numpy.pi / omega0, n_scan=192,
                          what="end of contact (delta = 0)")


def _contact_integral(fun, tau, lam, tau_d):
    """int_0^min(tau, tau_d) fun dtau, split at pi/omega0 (where the sqrt terms switch off); one
    Chebyshev antiderivative per lambda serves every tau (zener_sym.ham.chebyshev)."""
    k, beta, omega0 = params(lam)
    end = numpy.minimum(tau, tau_d)
    tpi = numpy.pi / omega0
    first = _int.cumulative_integral(fun, 0.0, numpy.minimum(tau_d, tpi), lam,
                                    numpy.minimum(end, tpi))
    second = _int.cumulative_integral(fun, tpi, numpy.maximum(tau_d, tpi), lam,
                                     numpy.maximum(end, tpi))
    return first + second


def _force2(tau, lam):
    return numpy.maximum(delta(tau, lam), 0.0) ** 3


def impulse(tau, lam, tau_d=None):
    """Impulse (47): int_0^min(tau, tau_d) max(delta, 0)^(3/2) dtau, a smoothstep-mapped Chebyshev
    antiderivative per lambda (zener_sym.ham.chebyshev.cumulative_integral); frozen after the end
    of contact."""
    tau, lam = _inputs(tau, lam)
    if tau_d is None:
        u, inv = numpy.unique(lam, return_inverse=True)
        tau_d = contact_end(u)[inv].reshape(lam.shape)
    return _contact_integral(force, tau, lam, tau_d)


def summary(lam):
    """First-order summary by root finding and quadrature on delta0 + delta1: tau_dc, delta_m, F_m,
    tau_d, tau_dr, eta, e = -delta'(tau_d), impulse and int_F2 over the contact."""
    lam = numpy.atleast_1d(_lam(lam)).astype(float).ravel()
    k, beta, omega0 = params(lam)
    tau_dc = compression_end(lam)
    tau_d = contact_end(lam, tau_dc)
    delta_m = delta(tau_dc, lam)
    imp = _contact_integral(force, tau_d, lam, tau_d)
    int_F2 = _contact_integral(_force2, tau_d, lam, tau_d)
    return dict(k=k, beta=beta, omega0=omega0, tau_d=tau_d, tau_dc=tau_dc, tau_dr=tau_d - tau_dc,
                eta=(tau_d - tau_dc) / tau_dc, e=-delta_dot(tau_d, lam), delta_m=delta_m,
                F_m=delta_m ** 1.5, impulse=imp, int_F2=int_F2)
'''


def _np_prelude(e, lam_crit, desc, extra_sources=()):
    p = _NumpyPrinter()
    return header(_SOURCES + tuple(extra_sources), desc) + _NP_PRELUDE.format(
        lam_crit_float=repr(float(lam_crit)), lam_crit_str=str(lam_crit),
        lam_crit_eq=str(e["lam_crit_eq"]),
        params_block=_block(p, _params_outputs(e)),
        delta0_block=_block(p, [("out", e["delta0"])]),
        delta0_dot_block=_block(p, [("out", e["delta0_dot"])]),
    ), p


def build_ham0_numpy() -> str:
    """generated/ham0_numpy.py: zeroth-order kernels and closed forms, float64 numpy."""
    e, lam_crit = _common()
    text, p = _np_prelude(e, lam_crit, "Zeroth-order HAM kernels of Zener's equation (10), numpy float64.")
    sines = e["delta0"].atoms(sp.sin)
    if len(sines) != 1 or next(iter(sines)).args[0] != Y["omega0"] * Y["tau"]:
        raise ValueError(f"delta_contact expects one sine of omega0*tau in delta0, got {sines}")
    return text + _NP_HAM0.format(
        delta_contact_block=_block(_HalfWavePrinter(), [("out", e["delta0"])]),
        a_imp_block=_block(p, [("a_imp", e["a_impulse0"])]),
        impulse_block=_block(p, [("out", e["impulse0"])]),
        summary_block=_block(p, _summary0_outputs(e)),
    )


def build_ham1_numpy() -> str:
    """generated/ham1_numpy.py: first-order kernels (delta0 + delta1), float64 numpy."""
    e, lam_crit = _common()
    text, p = _np_prelude(e, lam_crit, "First-order HAM kernels of Zener's equation (10), numpy float64.")
    d = e["delta0"] + e["delta1"]
    dd = e["delta0_dot"] + e["delta1_dot"]
    return text + _NP_HAM1.format(
        a_block=_block(p, [("a", e["a_first"])]),
        delta1_block=_block(p, [("out", e["delta1"])]),
        delta_block=_block(p, [("out", d)]),
        delta_dot_block=_block(p, [("out", dd)]),
        delta_scaled_block=_block(p, [("out", _scaled(d))]),
        delta_dot_scaled_block=_block(p, [("out", _scaled(dd))]),
    )


# ------------------------------------------------------------------------------------ mpmath
_MP_PRELUDE = '''
import mpmath

from zener_sym.numerics import mp as _hn

_p3 = _hn.p3_mp

#: Critical lambda (omega0 = 0), to 40 significant digits.
LAM_CRIT_DIGITS = "{lam_crit_str}"


def _prec(dps):
    """Working digits: ``dps`` if given, else the caller's mpmath.mp.dps."""
    return mpmath.mp.dps if dps is None else int(dps)


def _out(x, p):
    """x rounded to p digits (the precision the caller asked for)."""
    with mpmath.workdps(p):
        return +x


def _lam(lam):
    lam = mpmath.mpf(lam)
    if not mpmath.isfinite(lam) or lam < 0 or lam >= mpmath.mpf(LAM_CRIT_DIGITS):
        raise ValueError(f"lambda = {{lam}} is outside the HAM solution's range: allowed "
                         f"0 <= lambda < LAM_CRIT = {{LAM_CRIT_DIGITS}} (omega0 is not real beyond)")
    return lam


def _tau(tau):
    tau = mpmath.mpf(tau)
    if not mpmath.isfinite(tau) or tau < 0:
        raise ValueError("tau must be finite and >= 0")
    return tau


def params(lam, dps=None):
    """k (25), beta (32), omega0 (33) at ``dps`` digits."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        lam = _lam(lam)
{params_block}
    return _out(k, p), _out(beta, p), _out(omega0, p)


def _J(m, a, theta):
    """J_m(a, theta) = int_0^theta exp((-a + i m) t) sqrt(sin t) dt by its 2F1 closed form
    (theta in [0, pi]); the value at pi uses Gauss's theorem (Gamma functions)."""
    if theta == 0:
        return mpmath.mpc(0)
    if theta >= mpmath.pi:
{J_pi_block}
        return out
{J_theta_block}
    return out


def _K(names, a, theta):
    """K_g(a, theta) from J_0, J_1, J_2 (cc, sc, ss, s), frozen at theta >= pi. Extra digits cover
    the cancellations at small theta (F(theta) - F(0) ~ theta^(3/2), and K_ss ~ theta^(7/2) from
    Re J_0 - Re J_2) and the 2F1 evaluation near z = 1 at theta -> pi."""
    guard = 15
    if 0 < theta < 1:
        guard += int(-3.5 * mpmath.log10(theta)) + 1
    if 0 < mpmath.pi - theta < 1:
        guard += int(-1.5 * mpmath.log10(mpmath.pi - theta)) + 1
    with mpmath.workdps(mpmath.mp.dps + guard):
        theta = min(mpmath.mpf(theta), +mpmath.pi)
        J = {{}}
        out = {{}}
        for n in names:
            if n in ("cc", "ss") and 0 not in J:
                J[0] = _J(0, a, theta)
            if n in ("cc", "ss", "sc") and 2 not in J:
                J[2] = _J(2, a, theta)
            if n == "s" and 1 not in J:
                J[1] = _J(1, a, theta)
        for n in names:
            out[n] = {{"cc": lambda: (J[0].real + J[2].real) / 2,
                      "ss": lambda: (J[0].real - J[2].real) / 2,
                      "sc": lambda: J[2].imag / 2,
                      "s": lambda: J[1].imag}}[n]()
    return out


def delta0(tau, lam, dps=None):
    """Zeroth-order delta0 (35), analytic continuation (no clipping)."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        tau, lam = _tau(tau), _lam(lam)
{params_block_2}
{delta0_block}
    return _out(out, p)


def delta0_dot(tau, lam, dps=None):
    """delta0' (56)."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        tau, lam = _tau(tau), _lam(lam)
{params_block_2}
{delta0_dot_block}
    return _out(out, p)
'''

_MP_HAM0 = '''

def delta(tau, lam, dps=None):
    """delta0 (35)."""
    return delta0(tau, lam, dps)


def delta_dot(tau, lam, dps=None):
    """delta0' (56)."""
    return delta0_dot(tau, lam, dps)


def force(tau, lam, dps=None):
    """delta0^(3/2) during 0 <= tau <= pi/omega0, else 0."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        k, beta, omega0 = params(lam, mpmath.mp.dps)
        d = delta0(tau, lam, mpmath.mp.dps)
        out = mpmath.mpf(0) if (omega0 * _tau(tau) > mpmath.pi or d <= 0) else d ** 1.5
    return _out(out, p)


def impulse(tau, lam, dps=None):
    """Impulse (47) = omega0^(-5/2) K_s(3 beta/(2 omega0), omega0 tau) by the 2F1 closed form."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        tau, lam = _tau(tau), _lam(lam)
{params_block_2}
{a_imp_block}
        Ks = _K(("s",), a_imp, omega0 * tau)["s"]
{impulse_block}
    return _out(out, p)


def summary(lam, dps=None):
    """Zeroth-order closed forms (see the numpy module), impulse by Gamma functions."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        lam = _lam(lam)
{params_block_2}
{summary_block}
        Ks = _K(("s",), a_imp, mpmath.pi)["s"]
{impulse_block}
        res = dict(k=k, beta=beta, omega0=omega0, tau_d=tau_d, tau_dc=tau_dc, tau_dr=tau_dr,
                   eta=eta, e=e, delta_m=delta_m, F_m=delta_m ** 1.5, impulse=out, int_F2=int_F2)
    return {{n: _out(v, p) for n, v in res.items()}}
'''

_MP_HAM1 = '''

def _Ks(beta, omega0, tau):
{a_block}
        K = _K(("cc", "sc", "ss"), a, omega0 * tau)
        return K["cc"], K["sc"], K["ss"]


def delta1(tau, lam, dps=None):
    """First-order correction delta1 (37)-(42) with C(tau) - C(0) in closed form (2F1, Gamma)."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        tau, lam = _tau(tau), _lam(lam)
{params_block_2}
        Kcc, Ksc, Kss = _Ks(beta, omega0, tau)
{delta1_block}
    return _out(out, p)


def delta(tau, lam, dps=None):
    """delta0 + delta1 (42), continued past pi/omega0 with the sqrt integrals frozen."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        tau, lam = _tau(tau), _lam(lam)
{params_block_2}
        Kcc, Ksc, Kss = _Ks(beta, omega0, tau)
{delta_block}
    return _out(out, p)


def delta_dot(tau, lam, dps=None):
    """d/dtau (delta0 + delta1)."""
    p = _prec(dps)
    with mpmath.workdps(p + 10):
        tau, lam = _tau(tau), _lam(lam)
{params_block_2}
        Kcc, Ksc, Kss = _Ks(beta, omega0, tau)
{delta_dot_block}
    return _out(out, p)


def force(tau, lam, dps=None):
    """max(delta, 0)^(3/2), meaningful up to the end of contact."""
    with mpmath.workdps(_prec(dps)):
        d = delta(tau, lam, mpmath.mp.dps)
        return d ** 1.5 if d > 0 else mpmath.mpf(0)


def compression_end(lam, dps=None, guess=None):
    """tau_dc: zero of delta' near ``guess`` (default: the numpy kernel's root)."""
    if guess is None:
        from zener_sym.generated import ham1_numpy
        guess = float(ham1_numpy.compression_end(float(lam))[0])
    p = _prec(dps)
    with mpmath.workdps(p + 5):
        f = lambda t: delta_dot(t, lam, mpmath.mp.dps)
        h = 1e-7 * guess
        root = mpmath.findroot(f, (guess - h, guess + h), solver="anderson")
    return _out(root, p)


def contact_end(lam, dps=None, guess=None):
    """tau_d: zero of delta after the maximum near ``guess`` (default: the numpy kernel's root)."""
    if guess is None:
        from zener_sym.generated import ham1_numpy
        guess = float(ham1_numpy.contact_end(float(lam))[0])
    p = _prec(dps)
    with mpmath.workdps(p + 5):
        f = lambda t: delta(t, lam, mpmath.mp.dps)
        h = 1e-7 * guess
        root = mpmath.findroot(f, (guess - h, guess + h), solver="anderson")
    return _out(root, p)


def impulse(tau, lam, dps=None, tau_d=None):
    """Impulse (47): int_0^min(tau, tau_d) F dtau, split at pi/omega0, mpmath.quad on the
    smoothstep-mapped pieces (slow: many 2F1 evaluations)."""
    p = _prec(dps)
    with mpmath.workdps(p + 5):
        tau, lam = _tau(tau), _lam(lam)
        k, beta, omega0 = params(lam, mpmath.mp.dps)
        if tau_d is None:
            tau_d = contact_end(lam, mpmath.mp.dps)
        end = min(tau, mpmath.mpf(tau_d))
        tpi = mpmath.pi / omega0
        f = lambda t: force(t, lam, mpmath.mp.dps)
        out = _hn.contact_integral_mp(f, 0, min(end, tpi)) + _hn.contact_integral_mp(f, tpi, max(end, tpi))
    return _out(out, p)
'''


def _mp_prelude(e, lam_crit, desc):
    p = _MpPrinter()
    J = e["J_theta"]
    Jpi = e["J_pi"]
    return header(_SOURCES, desc) + _MP_PRELUDE.format(
        lam_crit_str=str(lam_crit),
        params_block=_block(p, _params_outputs(e), indent="        "),
        params_block_2=_block(p, _params_outputs(e), indent="        ", prefix="_p"),
        J_pi_block=_block(p, [("out", Jpi)], indent="        "),
        J_theta_block=_block(p, [("out", J)], indent="    "),
        delta0_block=_block(p, [("out", e["delta0"])], indent="        "),
        delta0_dot_block=_block(p, [("out", e["delta0_dot"])], indent="        "),
    ), p


def build_ham0_mpmath() -> str:
    """generated/ham0_mpmath.py: zeroth-order kernels at any precision (2F1, Gamma)."""
    e, lam_crit = _common()
    text, p = _mp_prelude(e, lam_crit, "Zeroth-order HAM kernels of Zener's equation (10), mpmath.")
    return text + _MP_HAM0.format(
        params_block_2=_block(p, _params_outputs(e), indent="        ", prefix="_p"),
        a_imp_block=_block(p, [("a_imp", e["a_impulse0"])], indent="        "),
        impulse_block=_block(p, [("out", e["impulse0"])], indent="        "),
        summary_block=_block(p, _summary0_outputs(e), indent="        "),
    )


def build_ham1_mpmath() -> str:
    """generated/ham1_mpmath.py: first-order kernels at any precision (2F1, Gamma)."""
    e, lam_crit = _common()
    text, p = _mp_prelude(e, lam_crit, "First-order HAM kernels of Zener's equation (10), mpmath.")
    return text + _MP_HAM1.format(
        a_block=_block(p, [("a", e["a_first"])], indent="        "),
        params_block_2=_block(p, _params_outputs(e), indent="        ", prefix="_p"),
        delta1_block=_block(p, [("out", e["delta1"])], indent="        "),
        delta_block=_block(p, [("out", e["delta0"] + e["delta1"])], indent="        "),
        delta_dot_block=_block(p, [("out", e["delta0_dot"] + e["delta1_dot"])], indent="        "),
    )
