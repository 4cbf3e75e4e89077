"""The verdict machinery: printed vs derived, symbolically, then at high precision, and units.

Verdicts: ``consistent`` (the printed form equals the derived one), ``typo`` (readable, but it
disagrees), ``garbled`` (the transcription cannot be read as a formula), ``claim-holds`` /
``claim-fails`` (numeric claims and printed rounded constants), ``not-checkable`` (no derived
form or reference available; the note says why).
"""
from __future__ import annotations

import random
from collections.abc import Callable, Iterable, Mapping
from dataclasses import asdict, dataclass
from typing import NamedTuple, SupportsFloat

import mpmath as mp
import sympy as sp

from .printed import SYM, Expr

__all__ = ["Result", "Verdict", "VERDICTS", "compare", "equal_up_to_factor", "dimension", "rounds_to",
           "DIMS", "MASS", "LENGTH", "TIME", "sample_point", "sci"]

VERDICTS = ("consistent", "typo", "garbled", "claim-holds", "claim-fails", "not-checkable")


@dataclass
class Result:
    """One row of the audit."""

    id: str
    kind: str
    verdict: str
    printed: str
    derived: str
    evidence: str
    note: str

    def __post_init__(self) -> None:
        if self.verdict not in VERDICTS:
            raise ValueError(f"verdict {self.verdict!r} is not one of {VERDICTS}")

    def as_dict(self) -> dict[str, str]:
        return asdict(self)


class Verdict(NamedTuple):
    """What a check returns: the verdict (one of :data:`VERDICTS`), the derived form as LaTeX
    (empty when there is none), the evidence in sentences and a one-line note for the summary."""

    verdict: str
    derived: str = ""
    evidence: str = ""
    note: str = ""

    @classmethod
    def form(cls, ok: bool, derived: str, evidence: str, note_bad: str = "",
             note_ok: str = "") -> "Verdict":
        """A printed form's verdict: ``consistent`` when ``ok``, else ``typo`` with ``note_bad``."""
        return cls("consistent" if ok else "typo", derived, evidence, note_ok if ok else note_bad)

    @classmethod
    def claim(cls, holds: bool, derived: str, evidence: str, note: str = "") -> "Verdict":
        """A numeric claim's verdict: ``claim-holds`` or ``claim-fails``."""
        return cls("claim-holds" if holds else "claim-fails", derived, evidence, note)


# Sampling ranges: physical ranges of each symbol, so that square roots stay real
# (0 < omega0 tau < pi, lam below the critical 2.44, Poisson ratios in (0, 1/2)).
_RANGES: dict[str, tuple[float, float]] = {
    "lam": (0.05, 2.3), "tau": (0.05, 1.2), "k": (0.6, 1.1), "beta": (0.05, 0.9),
    "omega0": (0.3, 1.1), "p": (0.1, 0.9), "x": (0.05, 0.9), "y": (0.1, 1.0),
    "dm": (0.5, 1.5), "nu1": (0.1, 0.45), "nu2": (0.1, 0.45), "t": (0.05, 1.0)}
_DEFAULT_RANGE = (0.5, 3.0)

# Test functions for unknown functions of tau in relations: smooth, positive on the sample range.
_TEST_FUNCS: dict[str, Callable[[Expr], Expr]] = {
    "d": lambda s: 0.3 + s / 2 + s**2 / 7, "d0": lambda s: 0.4 + s / 3 + s**2 / 5,
    "d1": lambda s: 0.1 + s / 9 - s**2 / 11, "yf": lambda s: 1 - s**2 / 3,
    "C11": lambda s: 0.2 + s / 5, "C12": lambda s: -0.3 + s**2 / 6}


def sample_point(symbols: Iterable[Expr], rng: random.Random) -> dict[Expr, Expr]:
    """A random point (mpmath 30-digit values) for ``symbols`` in their physical ranges."""
    pt: dict[Expr, Expr] = {}
    for s in sorted(symbols, key=lambda s: s.name):
        lo, hi = _RANGES.get(s.name, _DEFAULT_RANGE)
        pt[s] = sp.Float(rng.uniform(lo, hi), 30)
    return pt


def _with_test_functions(expr: Expr) -> Expr:
    """Replace applied undefined functions (d(tau), C11(tau), ...) by explicit test functions."""
    rep = {}
    for f in expr.atoms(sp.core.function.AppliedUndef):
        name = f.func.__name__
        if name in _TEST_FUNCS and len(f.args) == 1:
            rep[f] = _TEST_FUNCS[name](f.args[0])
    return expr.subs(rep).doit() if rep else expr


def _num(expr: Expr, pt: Mapping[Expr, Expr]) -> complex | None:
    with mp.workdps(30):
        v = sp.N(expr.subs(pt), 30)
    return complex(v) if v.is_number else None


def compare(printed: Expr, derived: Expr, n_points: int = 6, seed: int = 12345, rtol: float = 1e-20,
            symbolic: bool = True) -> tuple[bool, str]:
    """Compare two SymPy expressions: (equal: bool, evidence: str).

    Symbolic first (``simplify(printed - derived) == 0``); otherwise high-precision (30 digits)
    values at ``n_points`` random points of the free symbols in their physical ranges. Applied
    unknown functions are replaced by the same smooth test functions on both sides.
    """
    P, D = _with_test_functions(sp.sympify(printed)), _with_test_functions(sp.sympify(derived))
    # simplify is tried on small expressions only (it can take minutes on the first-order ones)
    if symbolic and sp.count_ops(P) + sp.count_ops(D) <= 300:
        try:
            diff = sp.simplify(P - D)
            if diff == 0:
                return True, "SymPy simplifies printed minus derived to 0"
        except Exception:  # simplify can fail on odd printed forms; fall through to numbers
            pass
    rng = random.Random(seed)
    syms = (P.free_symbols | D.free_symbols)
    worst = 0.0
    where: tuple[dict[Expr, Expr], complex, complex] | None = None
    for _ in range(n_points):
        pt = sample_point(syms, rng)
        a, b = _num(P, pt), _num(D, pt)
        if a is None or b is None:
            return False, "the forms could not be evaluated at a sample point"
        err = abs(a - b) / max(abs(b), 1e-300)
        if err > worst:
            worst, where = err, (pt, a, b)
    if worst <= rtol:
        return True, (f"30-digit values agree at {n_points} random points (largest relative "
                      f"difference {sci(worst)})")
    assert where is not None  # worst > rtol >= 0, so some point set it
    pt, a, b = where
    return False, (f"at {_at(pt)} the printed form gives {_fmt(a)} and the derived one {_fmt(b)} "
                   f"(relative difference {sci(worst)})")


def equal_up_to_factor(printed: Expr, derived: Expr, n_points: int = 6, seed: int = 7,
                       rtol: float = 1e-20) -> tuple[bool, str]:
    """For relations (residuals = 0): is printed = c * derived with one constant c != 0?"""
    P, D = _with_test_functions(sp.sympify(printed)), _with_test_functions(sp.sympify(derived))
    rng = random.Random(seed)
    syms = (P.free_symbols | D.free_symbols)
    ratios: list[complex] = []
    for _ in range(n_points):
        pt = sample_point(syms, rng)
        a, b = _num(P, pt), _num(D, pt)
        if a is None or b is None or b == 0:
            return False, "the residuals could not be evaluated at a sample point"
        ratios.append(a / b)
    c = ratios[0]
    spread = max(abs(r - c) for r in ratios) / max(abs(c), 1e-300)
    if abs(c) > 0 and spread <= rtol:
        return True, (f"the printed residual is {_fmt(c)} times the derived one at {n_points} "
                      f"random points with test functions (spread {sci(spread)})")
    return False, (f"the ratio of the printed to the derived residual varies between "
                   f"{_fmt(ratios[0])} and {_fmt(ratios[-1])} at random points (spread "
                   f"{sci(spread)}), so the two equations differ")


def _fmt(z: complex) -> str:
    z = complex(z)
    if abs(z.imag) <= 1e-25 * max(1.0, abs(z.real)):
        return f"{z.real:.10g}"
    sign = "+" if z.imag >= 0 else "-"
    return f"{z.real:.6g} {sign} {abs(z.imag):.6g}i"


def sci(x: SupportsFloat) -> str:
    """A small number for a reader: 3.2e-25 -> $3.2 \\times 10^{-25}$, 0.221 -> 0.221."""
    x = float(x)
    if x == 0:
        return "0"
    if 1e-3 <= abs(x) < 1e4:
        return f"{x:.3g}"
    mant, ex = f"{x:.1e}".split("e")
    return f"${mant} \\times 10^{{{int(ex)}}}$"


def _at(pt: Mapping[Expr, Expr]) -> str:
    from zener_sym.derivation.printing import NAMES  # noqa: PLC0415

    return "$" + ", ".join(f"{NAMES.get(s.name, s.name)} = {float(v):.4g}" for s, v in pt.items()) + "$"


# ---- units: each physical symbol as a monomial in the base dimensions M, L, Ts -----------------
MASS, LENGTH, TIME = sp.symbols("M L Ts", positive=True)
_P = MASS / (LENGTH * TIME**2)  # pressure, modulus
DIMS = {"m1": MASS, "mh": MASS, "m2": MASS, "ms": MASS, "Es": _P, "E1": _P, "E2": _P,
        "rho1": MASS / LENGTH**3, "rho2": MASS / LENGTH**3, "R": LENGTH, "H": LENGTH,
        "V0": LENGTH / TIME, "V": LENGTH / TIME, "V_W": LENGTH / TIME, "t": TIME, "T": TIME,
        "alpha": TIME / MASS, "I": MASS * LENGTH / TIME, "F": MASS * LENGTH / TIME**2,
        "W": MASS * LENGTH**2 / TIME**2, "w": LENGTH, "dm": LENGTH, "kc": 1 / (LENGTH**2 * TIME**2)}
#: Dimensionless symbols get a generic number, so that 1 - nu**2 does not vanish.
_DIMLESS = {"nu1": sp.Rational(2, 7), "nu2": sp.Rational(3, 11)}


def dimension(expr: Expr, extra: Mapping[Expr, Expr] | None = None) -> Expr | None:
    """The dimension of ``expr`` as a monomial in M, L, Ts, or None if its terms disagree.

    Symbols not in :data:`DIMS` must be dimensionless (or given in ``extra``). A sum whose terms
    have different dimensions has no dimension (returns None).
    """
    # Each symbol also gets its own generic numeric factor, so that a difference of two terms of
    # the same dimension (m1 V0 - I) does not cancel to 0.
    primes = (3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83)
    dims = {SYM[n]: sp.Rational(primes[i % len(primes)], 97) * v
            for i, (n, v) in enumerate(sorted(DIMS.items())) if n in SYM}
    dims.update({SYM[n]: v for n, v in _DIMLESS.items()})
    if extra:
        dims.update(extra)
    e = sp.sympify(expr)
    # An integral has the dimension of integrand times variable.
    e = e.replace(lambda a: isinstance(a, sp.Integral),
                  lambda a: a.function * sp.Mul(*[lim[0] for lim in a.limits]))
    # d/dt -> 1/t: a derivative has the dimension of its argument over the variable's.
    e = e.replace(lambda a: isinstance(a, sp.Derivative),
                  lambda a: a.expr / sp.Mul(*[v**n for v, n in a.variable_count]))
    for f in e.atoms(sp.core.function.AppliedUndef):  # delta(t) has dimension L, F(t) a force
        e = e.subs(f, MASS * LENGTH / TIME**2 if f.func.__name__ == "Ff" else LENGTH)
    e = e.subs(dims)
    e = sp.powsimp(sp.powdenest(sp.factor(sp.simplify(e)), force=True), force=True)
    mono = sp.Integer(1)
    for fac in sp.Mul.make_args(e):
        base, ex = fac.as_base_exp()
        if base in (MASS, LENGTH, TIME):
            mono *= fac
        elif fac.free_symbols & {MASS, LENGTH, TIME}:
            return None
    return mono


def rounds_to(value: SupportsFloat, printed: str) -> tuple[bool, str]:
    """Does ``value`` round to the printed decimal string (to its number of decimals)?

    Truncation is accepted too (the paper sometimes truncates): |value - printed| < 1 unit in
    the last printed place.
    """
    dec = len(printed.split(".")[1]) if "." in printed else 0
    ulp = 10.0 ** (-dec)
    diff = abs(float(value) - float(printed))
    ok = diff < ulp
    how = "rounds" if round(float(value), dec) == float(printed) else (
        "truncates" if ok else "does not round")
    return ok, (f"{float(value):.{dec + 3}f} {how} to {printed} (difference {diff:.2g}, one unit "
                f"of the last printed digit is {ulp:g})")
