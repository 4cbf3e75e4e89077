"""Builder of generated/plate.py: the bounded plate's mode formulas, printed once for every backend.

The expressions come from ``zener_sym.derivation.plate`` (checked there): the circle's frequency
equations and their derivatives in x = k b (scaled by e^{-x}, with i0e = e^{-x} I0 and
i1e = e^{-x} I1, so nothing overflows for x in the thousands), Omega_n and psi_n of the circle
and of the Navier rectangle, and the static compliances S. The printing machinery is the HAM
kernels' (:mod:`.ham`): one documented function per formula, the math namespace ``xp`` first
(``zener_sym.plate.formulas``: ``XP_NUMPY`` or ``XP_MPMATH``), common subexpressions shared,
rationals as ``xp.rational(p, q)``; Bessel functions print as ``xp.j0``, ``xp.j1``, ``xp.i0e``,
``xp.i1e`` and zeta(3) as ``xp.zeta(3)``. Root finding, mode selection and input checks are plain
code in ``zener_sym.plate.modes``.
"""
from __future__ import annotations

from typing import Any

from . import header
from .ham import _ARG_DOCS, _Doc, _function, _NeutralPrinter

__all__ = ["build_plate"]

_SOURCES = ("zener_sym.codegen.plate", "zener_sym.derivation.plate")


class _PlatePrinter(_NeutralPrinter):
    """The HAM printer plus the plate's special functions, all read from ``xp``."""

    def _print_besselj(self, e: Any) -> str:
        order = int(e.args[0])
        if order not in (0, 1):
            raise ValueError(f"only J0 and J1 are printed, got order {order}")
        return f"xp.j{order}({self._print(e.args[1])})"

    def _print_Function(self, e: Any) -> str:
        name = type(e).__name__
        if name not in ("i0e", "i1e"):
            raise ValueError(f"no printing for the function {name}")
        return f"xp.{name}({', '.join(self._print(a) for a in e.args)})"

    def _print_zeta(self, e: Any) -> str:
        return f"xp.zeta({self._print(e.args[0])})"


_FLOATS = "float or ndarray"
#: argument name -> (type, description)
_ARGS: dict[str, tuple[str, str]] = {
    "xp": ("types.SimpleNamespace", "The math namespace: ``zener_sym.plate.formulas.XP_NUMPY`` "
           "(float64, arrays broadcast) or ``XP_MPMATH`` (at the working precision)."),
    "x": (_FLOATS, "The circle's root variable x = k b > 0 (k the wavenumber, b the radius)."),
    "nu": (_FLOATS, "Poisson's ratio of the plate, -1 < nu < 0.5."),
    "m": (_FLOATS, "The mode number along the side a, m >= 1."),
    "k": (_FLOATS, "The mode number along the side b, k >= 1."),
    "s": (_FLOATS, "The rectangle's aspect s = a/b > 0."),
    "u": (_FLOATS, "m xi reduced to (-1/2, 1/2] (sin^2 has period 1 in it)."),
    "v": (_FLOATS, "k eta reduced to (-1/2, 1/2]."),
    "xi": (_FLOATS, "The impact point's x/a, 0 < xi < 1."),
    "eta": (_FLOATS, "The impact point's y/b, 0 < eta < 1."),
    "cl3": (_FLOATS, "Cl_3 = sum_m cos(2 pi m xi)/m^3 = Re Li_3(exp(2 pi i xi))."),
}
assert "xp" in _ARG_DOCS  # the HAM kernels' xp is the same convention

_IMPORT = [">>> from zener_sym.generated import plate",
           ">>> from zener_sym.plate.formulas import XP_NUMPY as xp"]

#: name -> (arguments, summary, paragraph, returns, example lines)
_FORMULAS: dict[str, tuple[tuple[str, ...], str, str, str, list[str]]] = {
    "freq_clamped": (("x",), "The clamped circle's frequency equation, scaled: e^{-x} (J0 I1 + "
                     "J1 I0) = 0.", "W'(b) = 0 for W = J0(kr)/J0(kb) - I0(kr)/I0(kb); its n-th "
                     "root x_n gives Omega_n = x_n^2.", "e^{-x} (J0 I1 + J1 I0) at x.",
                     [">>> abs(float(plate.freq_clamped(xp, 3.1962206165))) < 1e-10", "True"]),
    "freq_clamped_dx": (("x",), "The x-derivative of ``freq_clamped``.", "For Newton's method.",
                        "d/dx of e^{-x} (J0 I1 + J1 I0).",
                        [">>> round(float(plate.freq_clamped_dx(xp, 2.2)), 6)", "-0.205326"]),
    "freq_ss": (("x", "nu"), "The simply supported circle's frequency equation, scaled: "
                "e^{-x} ((1 - nu)(J1 I0 + J0 I1) - 2 x J0 I0) = 0.", "W(b) = 0 and zero radial "
                "moment W'' + nu W'/r at b; its n-th root gives Omega_n = x_n^2.",
                "The scaled left-hand side at x.",
                [">>> abs(float(plate.freq_ss(xp, 2.2215195, 0.3))) < 1e-7", "True"]),
    "freq_ss_dx": (("x", "nu"), "The x-derivative of ``freq_ss``.", "For Newton's method.",
                   "d/dx of the scaled left-hand side.",
                   [">>> round(float(plate.freq_ss_dx(xp, 2.2, 0.3)), 6)", "0.543076"]),
    "Omega_circle": (("x",), "The circle's dimensionless frequency Omega = omega b^2 sqrt(rho h "
                     "/ D) = x^2.", "", "Omega at the root x.",
                     [">>> float(plate.Omega_circle(xp, 3.0))", "9.0"]),
    "psi_circle": (("x",), "The circle's participation at its centre, psi = W(0)^2 rho h b^2 / "
                   "M.", "M = pi rho h b^2 (2 + t_J^2 - t_I^2 - 2 (t_J + t_I)/x) (Lommel), "
                   "t_J = J1/J0, t_I = I1/I0, valid at every root of either support.",
                   "psi at the root x.",
                   [">>> round(float(plate.psi_circle(xp, 3.1962206165)), 6)", "1.740975"]),
    "Omega_rect": (("m", "k", "s"), "The simply supported rectangle's Omega = omega a b "
                   "sqrt(rho h / D) = pi^2 (m^2/s + k^2 s).", "Navier's mode sin(m pi x/a) "
                   "sin(k pi y/b).", "Omega of the mode (m, k).",
                   [">>> round(float(plate.Omega_rect(xp, 1.0, 1.0, 1.0)), 6)", "19.739209"]),
    "psi_rect": (("u", "v"), "The rectangle's participation psi = 4 sin^2(m pi xi) sin^2(k pi "
                 "eta), from the reduced u = m xi, v = k eta.", "", "psi of the mode.",
                 [">>> float(plate.psi_rect(xp, 0.5, 0.5))", "4.0"]),
    "S_circle_clamped": ((), "The clamped circle's static compliance at its centre, S = C_s D "
                         "/ b^2 = 1/(16 pi).", "", "S.",
                         [">>> round(float(plate.S_circle_clamped(xp)) * 16 * 3.141592653589793, 12)",
                          "1.0"]),
    "S_circle_ss": (("nu",), "The simply supported circle's static compliance at its centre, "
                    "S = (3 + nu)/(16 pi (1 + nu)).", "", "S.",
                    [">>> round(float(plate.S_circle_ss(xp, 0.0)) * 16 * 3.141592653589793, 12)",
                     "3.0"]),
    "S_rect_algebraic": (("s", "cl3"), "The algebraic part of the rectangle's static "
                         "compliance, s (zeta(3) - Cl_3)/(4 pi^3).", "The sum over m of the "
                         "inner sum's 1/m^3 part.", "The part of S = C_s D / (a b).",
                         [">>> round(float(plate.S_rect_algebraic(xp, 1.0, -0.75 * 1.2020569031595942)), 6)",
                          "0.016961"]),
    "S_rect_term": (("m", "s", "xi", "eta"), "The m-th exponentially small term of the "
                    "rectangle's static compliance.", "sin^2(m pi xi) g'(c)/(pi^4 s^2 c), "
                    "c = m/s, g the inner sum over n beyond its algebraic part.",
                    "The term.", [">>> float(plate.S_rect_term(xp, 1.0, 1.0, 0.5, 0.5)) < 0",
                                  "True"]),
}


def build_plate() -> str:
    """generated/plate.py: the plate's mode formulas, for any math namespace ``xp``.

    Returns
    -------
    str
        The module text: the header and one documented function per formula.
    """
    from ..derivation.plate import expressions

    e = expressions()
    p = _PlatePrinter()
    text = header(_SOURCES, "The bounded Kirchhoff plate's mode formulas (issue 37), printed "
                  "once for every backend: each function takes the math namespace xp first (the "
                  "runtime: zener_sym.plate.modes; the namespaces: zener_sym.plate.formulas).")
    for name, (args, summary, extended, returns, examples) in _FORMULAS.items():
        doc = _Doc(summary, extended, [("out", _FLOATS, returns)], _IMPORT + examples)
        text += _function(p, name, args, doc, [("out", e[name])], "out", arg_docs=_ARGS)
    return text
