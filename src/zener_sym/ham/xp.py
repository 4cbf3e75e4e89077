"""The math namespaces ``xp`` the generated HAM formulas take, one per backend, and their binding.

``generated/ham0.py`` and ``generated/ham1.py`` print each formula once; every function takes the
namespace first and calls only ``xp.exp``, ``sin``, ``cos``, ``sqrt``, ``atan2``, ``pi``,
``rational(p, q)``, ``p3`` (Eq. 40's cubic), ``half_wave_sin`` (numpy's contact delta0 only) and,
for the 2F1 closed forms J (mpmath only), ``gamma``, ``hyper``, ``re``, ``im``.

Why ``rational``: numpy's p/q is the double division of two small ints, the same double as the
literal the numpy printer used to write, so the numpy results keep their bits; mpmath's is
``mpf(p)/q``, exact at the working precision (a float 1/3 would not be).
"""
from __future__ import annotations

import functools
import inspect
import types
from collections.abc import Callable
from typing import Any

import mpmath
import numpy

from ..numerics.elementary import half_wave_sin, p3
from ..numerics.mp import p3_mp

__all__ = ["NUMPY", "MPMATH", "bind", "kernel_doc"]

#: float64 numpy.
NUMPY = types.SimpleNamespace(
    exp=numpy.exp, sin=numpy.sin, cos=numpy.cos, sqrt=numpy.sqrt, atan2=numpy.arctan2,
    pi=numpy.pi, rational=lambda p, q: p / q, p3=p3, half_wave_sin=half_wave_sin)


class _Mpmath(types.SimpleNamespace):
    """mpmath at the caller's working precision: pi is read when used, so it has that precision."""

    @property
    def pi(self) -> Any:
        return +mpmath.pi


#: mpmath, at the working precision of the call.
MPMATH = _Mpmath(
    exp=mpmath.exp, sin=mpmath.sin, cos=mpmath.cos, sqrt=mpmath.sqrt, atan2=mpmath.atan2,
    rational=lambda p, q: mpmath.mpf(p) / q, p3=p3_mp, gamma=mpmath.gamma, hyper=mpmath.hyper,
    re=mpmath.re, im=mpmath.im)


def bind(module: types.ModuleType, xp: types.SimpleNamespace) -> types.SimpleNamespace:
    """The functions of a generated formula module with ``xp`` given, and its upper-case data.

    Parameters
    ----------
    module : module
        ``zener_sym.generated.ham0`` or ``ham1``.
    xp : types.SimpleNamespace
        ``NUMPY`` or ``MPMATH``.

    Returns
    -------
    types.SimpleNamespace
        The same names; each function takes the arguments after ``xp``.

    Examples
    --------
    >>> from zener_sym.generated import ham0
    >>> from zener_sym.ham.xp import NUMPY, bind
    >>> f = bind(ham0, NUMPY)
    >>> k, beta, omega0 = f.params(0.0)
    >>> f.LAM_CRIT == ham0.LAM_CRIT and float(beta) == 0.0
    True
    """
    names = {n: getattr(module, n) for n in dir(module) if not n.startswith("_")}
    return types.SimpleNamespace(**{
        n: functools.partial(v, xp) if callable(v) and not isinstance(v, type) else v
        for n, v in names.items() if callable(v) or n.isupper()})


def kernel_doc(formula: Callable[..., Any], params: str, returns: str) -> str:
    """The docstring of a runtime kernel that wraps a bound formula of :func:`bind`.

    The formula's summary paragraph (what it computes, with the paper's equation), then the
    kernel's own Parameters and Returns: the formula's describe ``xp`` and the arguments the
    runtime computes itself (beta, omega0, K), and a ``functools.partial`` carries no docstring
    of its function.

    Parameters
    ----------
    formula : callable
        A function of :func:`bind`'s namespace (a ``functools.partial``) or a plain function.
    params : str
        The kernel's numpydoc Parameters entries, unindented.
    returns : str
        Its Returns entries, unindented.

    Returns
    -------
    str

    Examples
    --------
    >>> from zener_sym.generated import ham1
    >>> from zener_sym.ham.xp import NUMPY, bind, kernel_doc
    >>> doc = kernel_doc(bind(ham1, NUMPY).delta, "tau : float", "float")
    >>> doc.splitlines()[0]
    'First-order HAM compression delta0 + delta1 (42).'
    """
    func = getattr(formula, "func", formula)
    summary = (inspect.getdoc(func) or "").split("\n\n")[0]
    return f"{summary}\n\nParameters\n----------\n{params}\n\nReturns\n-------\n{returns}\n"
