"""C text of the HAM kernels: the formulas of ``codegen.ham_exprs`` printed by SymPy's C99 printer
(with common subexpressions shared through ``sympy.cse``), and the Gauss-Jacobi rule the
first-order square-root integrals need (the numpy kernels' rule, ``numerics.sqrt_integrals``:
64 nodes, weight u^{1/2} on [0, 1]), its nodes computed here at 40 digits so the file does not
depend on the machine's LAPACK.
"""
from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Any

import mpmath
import sympy as sp
from sympy.printing.c import C99CodePrinter

from ..ham_exprs import SYMBOLS as Y
from ..ham_exprs import ham_expressions
from .tables import num

#: Gauss-Jacobi nodes and the cut of the left piece, as in ``zener_sym.numerics.sqrt_integrals``
#: (N_NODES, CUT; codegen cannot import that leaf helper, tests compare the two).
N_NODES = 64
CUT = 60.0
#: Terms of P3's Taylor series in x^2 used for |x| < 1/2 (as ``numerics.elementary.p3``).
P3_TERMS = 12


class CPrinter(C99CodePrinter):  # type: ignore[misc]  # sympy is untyped: its classes are Any
    """C99 printer for the kernels: pi as a literal macro (M_PI is not ISO C), P3 and Atan2 as
    the runtime's helpers."""

    def _print_Pi(self, e: Any) -> str:
        return "ZS__PI"

    def _print_P3(self, e: Any) -> str:
        return f"zs__p3({self._print(e.args[0])})"

    def _print_Atan2(self, e: Any) -> str:
        return f"atan2({self._print(e.args[0])}, {self._print(e.args[1])})"


class HalfWavePrinter(CPrinter):
    """delta0 on its contact: its one sine, of omega0 tau, is the first half wave (0 past pi)."""

    def _print_sin(self, e: Any) -> str:
        return f"zs__half_wave_sin({self._print(e.args[0])})"


def block(printer: CPrinter, outputs: Sequence[tuple[str, Any]], indent: str = "    ",
          prefix: str = "x") -> str:
    """C statements computing ``outputs`` [(lvalue, expr)] with shared subexpressions."""
    reps, reduced = sp.cse([ex for _, ex in outputs], symbols=sp.numbered_symbols(prefix),
                           order="canonical")
    lines = [f"{indent}const double {printer.doprint(s)} = {printer.doprint(v)};" for s, v in reps]
    lines += [f"{indent}{name} = {printer.doprint(r)};" for (name, _), r in zip(outputs, reduced)]
    return "\n".join(lines)


def lam_crit() -> sp.Float:
    return sp.Float(ham_expressions()["lam_crit"], 30)


@functools.cache
def gauss_jacobi(n: int = N_NODES) -> tuple[list[float], list[float]]:
    """Nodes u in (0, 1) and weights of int_0^1 u^{1/2} h(u) du (Gauss-Jacobi, alpha = 0,
    beta = 1/2 on [-1, 1] mapped to [0, 1]), by Newton's method at 40 digits from the
    Chebyshev-like initial guesses of the roots."""
    from scipy.special import roots_jacobi

    x0, _ = roots_jacobi(n, 0.0, 0.5)
    al, be = mpmath.mpf(0), mpmath.mpf(1) / 2
    us, ws = [], []
    with mpmath.workdps(40):
        for g in x0:
            x = mpmath.mpf(float(g))
            for _ in range(100):
                p = mpmath.jacobi(n, al, be, x)
                dp = (n + al + be + 1) / 2 * mpmath.jacobi(n - 1, al + 1, be + 1, x)
                dx = p / dp
                x -= dx
                if abs(dx) < mpmath.mpf(10) ** -36:
                    break
            dp = (n + al + be + 1) / 2 * mpmath.jacobi(n - 1, al + 1, be + 1, x)
            c = (mpmath.gamma(n + al + 1) * mpmath.gamma(n + be + 1)
                 / (mpmath.gamma(n + al + be + 1) * mpmath.factorial(n)) * 2 ** (al + be + 1))
            w = c / ((1 - x * x) * dp * dp)
            us.append(float((1 + x) / 2))
            ws.append(float(w / mpmath.mpf(2) ** mpmath.mpf(1.5)))
    return us, ws


def p3_coefficients() -> list[float]:
    """Taylor coefficients of P3(x) = (sin x - x cos x)/x^3 in x^2 (derived with SymPy)."""
    x = sp.Symbol("x")
    ser = sp.series((sp.sin(x) - x * sp.cos(x)) / x**3, x, 0, 2 * P3_TERMS).removeO()
    return [float(ser.coeff(x, 2 * k)) for k in range(P3_TERMS)]


def ham_c() -> str:
    """The printed HAM functions and the quadrature data (static, internal to zener_sym.c)."""
    e = ham_expressions()
    p, hw = CPrinter(), HalfWavePrinter()
    sines = e["delta0"].atoms(sp.sin)
    if len(sines) != 1 or next(iter(sines)).args[0] != Y["omega0"] * Y["tau"]:
        raise ValueError(f"delta0 has other sines than sin(omega0 tau): {sines}")
    us, ws = gauss_jacobi()
    p3 = p3_coefficients()
    params = [("const double k", e["k_of_lam"]), ("const double beta", e["beta_of_lam"]),
              ("const double omega0", e["omega0_of_lam"])]
    out = [
        "/* ---- HAM kernels, printed by SymPy's C99 printer from codegen.ham_exprs ---- */\n",
        f"static const double zs__p3_coef[{len(p3)}] = {{{', '.join(num(c) for c in p3)}}};\n",
        f"static const double zs__gj_u[{N_NODES}] = {{\n    "
        + ",\n    ".join(", ".join(num(v) for v in us[i:i + 4]) for i in range(0, N_NODES, 4))
        + "\n};\n",
        f"static const double zs__gj_w[{N_NODES}] = {{\n    "
        + ",\n    ".join(", ".join(num(v) for v in ws[i:i + 4]) for i in range(0, N_NODES, 4))
        + "\n};\n",
        f"#define ZS__GJ_N {N_NODES}\n#define ZS__GJ_CUT {num(CUT)}\n\n",
        "/* P3(x) = (sin x - x cos x)/x^3, P3(0) = 1/3: Taylor series in x^2 below |x| = 1/2 */\n"
        "static double zs__p3(double x)\n{\n"
        "    if (fabs(x) < 0.5) {\n"
        "        double x2 = x * x, s = 0.0;\n"
        f"        int i;\n        for (i = {len(p3) - 1}; i >= 0; i--)\n"
        "            s = s * x2 + zs__p3_coef[i];\n        return s;\n    }\n"
        "    return (sin(x) - x * cos(x)) / (x * x * x);\n}\n\n",
        "/* k (25), beta (32), omega0 (33) */\n"
        "static void zs__ham_params(double lam, double *k_out, double *beta_out, double *omega0_out)\n{\n"
        + block(p, params) + "\n    *k_out = k;\n    *beta_out = beta;\n    *omega0_out = omega0;\n}\n\n",
        "/* sin on the first half wave [0, pi], 0 beyond (numerics.elementary.half_wave_sin) */\n"
        "static double zs__half_wave_sin(double theta)\n{\n"
        "    return theta < ZS__PI ? sin(theta) : 0.0;\n}\n\n",
        "/* delta0 (35) on the zeroth-order contact 0 <= omega0 tau <= pi, 0 after (Eq. 54) */\n"
        "static double zs__ham0_delta(double tau, double beta, double omega0)\n{\n"
        "    double out;\n" + block(hw, [("out", e["delta0"])]) + "\n    return out;\n}\n\n",
        "/* delta0 + delta1 (42) from the square-root integrals Kcc, Ksc, Kss at omega0 tau */\n"
        "static double zs__ham1_delta(double tau, double lam, double k, double beta, double omega0,\n"
        "                             double Kcc, double Ksc, double Kss)\n{\n"
        "    double out;\n    (void)k; (void)lam;\n"
        + block(p, [("out", e["delta0"] + e["delta1"])]) + "\n    return out;\n}\n\n",
        "/* decay rate a = beta / (2 omega0) of the first-order integrals */\n"
        "static double zs__ham1_rate(double beta, double omega0)\n{\n    double out;\n"
        + block(p, [("out", e["a_first"])]) + "\n    return out;\n}\n\n",
    ]
    return "".join(out)
