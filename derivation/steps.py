"""The step record of the derivation, the shared symbols, and the checking helpers.

Every claim of the derivation is checked by one of the helpers below and recorded as a
:class:`Step`: the paper's equation number, what was checked, how, whether it passed, a short
detail (a residual, a simplified difference) and the time it took. A failed check does not stop
the derivation: it is recorded, and :attr:`Log.ok` becomes False.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import mpmath
import sympy as sp

__all__ = ["Step", "Log", "Context", "SYMBOLS", "symbolic_zero", "max_rel_residual", "mp_max_rel_residual",
           "MP_DPS", "latex"]

#: Working precision (decimal digits) of every mpmath check.
MP_DPS = 40

#: The symbols shared by every part of the derivation (paper notation, dimensionless core).
SYMBOLS = {
    "lam": sp.Symbol("lambda", real=True, nonnegative=True),
    "tau": sp.Symbol("tau", real=True, nonnegative=True),
    "k": sp.Symbol("k", positive=True),
    "beta": sp.Symbol("beta", positive=True),
    "omega0": sp.Symbol("omega_0", positive=True),
    "p": sp.Symbol("p", real=True),
}


@dataclass
class Step:
    """One checked claim of the derivation.

    Attributes
    ----------
    eq : str
        Paper equation number(s) the step reproduces, e.g. ``"35"`` or ``"28-31"``.
    what : str
        The claim.
    how : str
        The method of the check (symbolic simplification, mpmath at N digits, ...).
    passed : bool
    detail : str
        The measured residual or the reason of a failure.
    seconds : float
        Wall time of the check.
    """

    eq: str
    what: str
    how: str
    passed: bool
    detail: str
    seconds: float


@dataclass
class Log:
    """The ordered list of steps, with a printer for ``zener-sym derive``."""

    steps: list = field(default_factory=list)
    echo: object = None  # callable(str) printing each step as it is recorded, or None

    def check(self, eq: str, what: str, how: str, fn) -> bool:
        """Run ``fn() -> (passed, detail)``, time it and record the step.

        An exception inside ``fn`` is a failed step (its message is the detail), so one broken
        check cannot hide the others.
        """
        t0 = time.perf_counter()
        try:
            passed, detail = fn()
        except Exception as exc:  # recorded as a failure, never swallowed silently
            passed, detail = False, f"{type(exc).__name__}: {exc}"
        step = Step(eq, what, how, bool(passed), str(detail), time.perf_counter() - t0)
        self.steps.append(step)
        if self.echo is not None:
            self.echo(format_step(step))
        return step.passed

    @property
    def ok(self) -> bool:
        return all(s.passed for s in self.steps)


def format_step(s: Step) -> str:
    """One line per step: equation, verdict, time, claim, method and detail."""
    flag = "PASS" if s.passed else "FAIL"
    return f"[{flag}] ({s.eq:>7}) {s.seconds:6.2f} s  {s.what}  -- {s.how}: {s.detail}"


def symbolic_zero(expr, *, rewrite_trig: bool = False) -> tuple[bool, str]:
    """Whether ``expr`` simplifies to exactly 0, with the simplified form as detail."""
    e = sp.expand(expr)
    if e != 0:
        e = sp.simplify(e)
    if e != 0 and rewrite_trig:
        e = sp.simplify(sp.expand(e.rewrite(sp.exp)))
    return e == 0, "simplifies to 0" if e == 0 else f"left over: {sp.sstr(e)[:200]}"


def max_rel_residual(lhs, rhs, points):
    """Largest |lhs(x) - rhs(x)| / |rhs(x)| over ``points`` (absolute where rhs(x) is 0)."""
    worst = mpmath.mpf(0)
    for x in points:
        a, b = lhs(x), rhs(x)
        worst = max(worst, abs(a - b) / (abs(b) if b != 0 else 1))
    return worst


def mp_max_rel_residual(lhs, rhs, points, tol) -> tuple[bool, str]:
    """:func:`max_rel_residual` against ``tol``, as (passed, detail)."""
    worst = max_rel_residual(lhs, rhs, points)
    return worst <= tol, f"max rel residual {mpmath.nstr(worst, 3)} over {len(points)} points (tol {tol:g})"


@dataclass
class Context:
    """What each part of the derivation reads and extends: named expressions, LaTeX equations
    (paper number -> (latex, description)), the step log, and whether to run the checks."""

    expr: dict = field(default_factory=dict)
    equations: dict = field(default_factory=dict)
    log: Log = field(default_factory=Log)
    checks: bool = True
    symbols: dict = field(default_factory=lambda: dict(SYMBOLS))

    def eq(self, number: str, lhs, rhs, description: str) -> None:
        """Record the derived equation ``lhs = rhs`` under the paper's number."""
        self.equations[number] = (f"{latex(lhs)} = {latex(rhs)}", description)

    def check(self, eq, what, how, fn) -> bool:
        if not self.checks:
            return True
        return self.log.check(eq, what, how, fn)


def latex(e) -> str:
    """LaTeX in the paper's notation (:mod:`.printing`), deterministic, so FORMULAS.md is
    byte-for-byte reproducible."""
    from .printing import paper_latex  # noqa: PLC0415 (printing imports sympy only)

    return paper_latex(e)


def run_script(derive) -> int:  # pragma: no cover - command line of a standalone derivation
    """``python -m zener_sym.derivation.NAME``: run ``derive`` with every step echoed; 0 when
    every step passed, else 1."""
    ctx = Context()
    ctx.log.echo = print
    derive(ctx)
    print(f"{'OK' if ctx.log.ok else 'FAILED'}: {len(ctx.log.steps)} steps")
    return 0 if ctx.log.ok else 1
