"""The registry of named, checked expressions that codegen and the audit consume.

    >>> from zener_sym.derivation.registry import derive
    >>> d = derive()                      # cached per process
    >>> d.ok, d.expr["k_of_lam"]

Parts run in the paper's order; each extends one shared :class:`~.steps.Context`.
"""
from __future__ import annotations

import functools
import time
from dataclasses import dataclass

from . import delta_m, first_order, hertz_limit, homotopy, scaling, zeroth_order
from .steps import Context

__all__ = ["Derivation", "derive", "PARTS", "REQUIRED"]

#: The parts, in order (each may use what the previous ones added).
PARTS = (homotopy.derive, delta_m.derive, zeroth_order.derive, first_order.derive,
         scaling.derive, hertz_limit.derive)

#: Names every consumer may rely on (the contract with codegen and the audit).
REQUIRED = (
    "k_of_lam", "beta_of_lam", "omega0_of_lam", "lam_crit", "lam_crit_eq", "delta0", "delta0_dot",
    "tau_d0", "tau_dc0", "tau_dr0", "eta0", "e0", "tau_d0_of_lam", "tau_dc0_of_lam",
    "tau_dr0_of_lam", "eta0_of_lam", "e0_of_lam", "forcing", "forcing_elem", "forcing_sqrt",
    "C11_prime", "C12_prime", "C11_prime_elem", "C11_prime_sqrt", "C12_prime_elem",
    "C12_prime_sqrt", "C11_elem", "C12_elem", "C11_hyp", "C12_hyp", "C113", "C114", "C123", "C124",
    "C11_0", "C12_0", "delta1", "delta_ham1", "delta0_lam0", "delta1_lam0", "omega0_lam0",
    "F_hunter", "F_reed", "T", "lam_phys", "alpha", "V_W", "F_scale", "I_scale", "w_scale", "chi",
    "xi_energy",
)


@dataclass
class Derivation:
    """Result of the whole derivation.

    Attributes
    ----------
    steps : list of Step
    symbols : dict
        ``lam``, ``tau``, ``k``, ``beta``, ``omega0``, ``p`` and the physical symbols of
        :mod:`.scaling` (``E1``, ``nu1``, ``rho1``, ``E2``, ``nu2``, ``rho2``, ``R``, ``H``,
        ``V0``, ``m``, ``Estar``, ``int_F2``).
    expr : dict
        name -> SymPy expression (see ``REQUIRED``).
    equations : dict
        paper equation number -> (LaTeX of the derived equation, description).
    seconds : float
        Wall time of the whole derivation.
    """

    steps: list
    symbols: dict
    expr: dict
    equations: dict
    seconds: float

    @property
    def ok(self) -> bool:
        return all(s.passed for s in self.steps)

    def summary(self) -> str:
        n_fail = sum(not s.passed for s in self.steps)
        return (f"{len(self.steps)} steps, {len(self.steps) - n_fail} passed, {n_fail} failed, "
                f"{self.seconds:.1f} s")


def run(checks: bool = True, echo=None, only: str | None = None) -> Derivation:
    """Run every part (uncached); ``echo`` prints each step as it is checked.

    ``only``: the name of one part (e.g. ``"first_order"``); the parts before it run unchecked,
    only its steps are checked, and the parts after it do not run.
    """
    t0 = time.perf_counter()
    ctx = Context(checks=checks)
    ctx.log.echo = echo
    for part in PARTS:
        mine = part.__module__.rsplit(".", 1)[-1] == only
        ctx.checks = checks and (only is None or mine)
        part(ctx)
        if mine:
            break
    missing = [n for n in REQUIRED if n not in ctx.expr]
    if missing and only is None:
        raise RuntimeError(f"derivation did not produce {missing}")
    return Derivation(ctx.log.steps, ctx.symbols, ctx.expr, ctx.equations,
                      time.perf_counter() - t0)


def derive(checks: bool = True) -> Derivation:
    """The whole derivation, cached per process (``derive()`` and ``derive(checks=True)`` share
    one entry). See :class:`Derivation`."""
    return _derive_cached(bool(checks))


@functools.lru_cache(maxsize=None)
def _derive_cached(checks: bool) -> Derivation:
    return run(checks=checks)
