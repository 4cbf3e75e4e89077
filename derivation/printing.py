"""LaTeX in the paper's notation and in the form a person writes: FORMULAS.md and AUDIT.md.

SymPy's own ``latex`` prints what SymPy stores: ``2*2**(1/5)*5**(2/5)/5`` where the paper writes
``(5/4)^{-3/5}``, ``-nu_2^2 + 1`` for ``1 - nu_2^2``, ``1/(lambda + c)^{1/3}`` for
``(lambda + c)^{-1/3}``, tenth roots for a common exponent. :class:`PaperPrinter` changes only
the printing, never the expression, with a few rules:

- a number made of powers of primes (``2**(1/5)*5**(2/5)/2``) is printed as one rational base
  to one exponent, ``(5/4)^{2/5}`` (the rational part of the exponents stays a coefficient);
  bases made of 2 and 5 only are written 5/4, as the paper does;
- a product with two or more factors raised to powers that are not multiples of 1/2 is printed
  with one common exponent: ``(15 m V_0^2 / (16 E^* \\sqrt{R}))^{2/5}``;
- a sum raised to a negative fraction keeps its negative exponent, after the rest of the
  product: ``\\frac{\\lambda}{2} (\\lambda + (5/4)^{-3/5})^{-1/3}``;
- in a sum the positive terms come first: ``1 - \\nu_2^2``, ``\\omega_0^2 - \\beta^2``;
- fractional powers other than 1/2 are written as exponents, not roots;
- ``2F1`` is written ``{}_2F_1(a, b; c; z)``, ``atan`` ``\\arctan``, ``re``/``im`` ``Re``/``Im``;
- the output uses only commands that both GitHub's MathJax and matplotlib's mathtext read
  (``\\tfrac`` -> ``\\frac``, no ``\\begin{matrix}``, no ``\\middle``).

``names`` maps a symbol's name (or an undefined function's name) to its LaTeX, so that code
names such as ``lam``, ``omega0``, ``Es`` print as the paper's lambda, omega_0, E^*.
"""
from __future__ import annotations

import itertools
from fractions import Fraction
from math import gcd

import sympy as sp
from sympy.core.function import _coeff_isneg
from sympy.printing.latex import LatexPrinter

__all__ = ["PaperPrinter", "paper_latex", "NAMES", "FUNCTIONS", "mathtext_safe"]

#: Symbol names (the derivation's and the audit's) -> LaTeX in the paper's notation.
NAMES = {
    "lam": r"\lambda", "lambda": r"\lambda", "tau": r"\tau", "beta": r"\beta",
    "omega0": r"\omega_0", "omega_0": r"\omega_0", "dm": r"\delta_m", "ms": "m^*", "Es": "E^*",
    "E^*": "E^*", "m1": "m_1", "mh": "m_h", "m2": "m_2", "E1": "E_1", "E2": "E_2", "E_1": "E_1",
    "E_2": "E_2", "nu1": r"\nu_1", "nu2": r"\nu_2", "nu_1": r"\nu_1", "nu_2": r"\nu_2",
    "rho1": r"\rho_1", "rho2": r"\rho_2", "rho_1": r"\rho_1", "rho_2": r"\rho_2", "V0": "V_0",
    "V_0": "V_0", "V_W": "V_W", "kc": "k_c", "alpha": r"\alpha", "chi": r"\chi", "xi": r"\xi",
    "tau_d": r"\tau_d", "eta": r"\eta", "delta0": r"\bar\delta_0", "delta1": r"\bar\delta_1",
}

#: Undefined functions -> (LaTeX, print the argument?).
FUNCTIONS = {
    "d": (r"\bar\delta", False), "d0": (r"\bar\delta_0", False), "d1": (r"\bar\delta_1", False),
    "yf": ("y", False), "Ff": ("F", True), "C11": ("C_{11}", True), "C12": ("C_{12}", True),
    "A": ("C_{11}", True), "B": ("C_{12}", True),
}


def mathtext_safe(tex: str) -> str:
    """Replace the few commands matplotlib's mathtext lacks by equivalents both renderers read."""
    for a, b in ((r"\tfrac", r"\frac"), (r"\ge ", r"\geq "), (r"\ge1", r"\geq 1"),
                 (r"\le ", r"\leq "), (r"\operatorname{atan}", r"\arctan")):
        tex = tex.replace(a, b)
    return tex


def _frac(r) -> Fraction:
    r = sp.Rational(r)
    return Fraction(int(r.p), int(r.q))


def _fgcd(values) -> Fraction:
    """The greatest common divisor of fractions (positive)."""
    num = 0
    den = 1
    for v in values:
        num = gcd(num, abs(v.numerator))
        den = den * v.denominator // gcd(den, v.denominator)
    return Fraction(num, den) if num else Fraction(0)


def _prime_exponents(factors):
    """{prime: Fraction exponent} of a product of rationals and powers of rationals, or None."""
    out: dict = {}
    for f in factors:
        base, ex = f.as_base_exp()
        if not (base.is_Rational and ex.is_Rational):
            return None
        for part, sign in ((base.p, 1), (base.q, -1)):
            for p, n in sp.factorint(int(part)).items():
                if p == -1:
                    return None  # negative numbers: leave them to SymPy
                out[p] = out.get(p, Fraction(0)) + sign * n * _frac(ex)
    return {p: e for p, e in out.items() if e != 0}


def _is_number_factor(f) -> bool:
    base, ex = f.as_base_exp()
    return bool(base.is_Rational and ex.is_Rational)


def constant_parts(factors):
    """A product of powers of rationals as (rational coefficient, base p/q, exponent g), with
    ``coefficient * base**g`` equal to the product; None when no exponent is a fraction other than
    a half (SymPy's own printing is then fine) or the factors are not such powers."""
    ex = _prime_exponents(factors)
    if ex is None or all((2 * e).denominator == 1 for e in ex.values()):
        return None
    g = _fgcd(ex.values())
    inner = Fraction(1)
    for p, e in ex.items():
        inner *= Fraction(p) ** int(e / g)
    if inner.numerator * inner.denominator < 10**4:  # a pure power of a small rational
        return sp.Integer(1), inner, g
    frac_primes = [p for p, e in ex.items() if e.denominator != 1]
    best = None
    for choice in itertools.product((0, -1), repeat=len(frac_primes)):
        # fractional part of each exponent in [0, 1) or (-1, 0]
        fr = {}
        for p, c in zip(frac_primes, choice):
            e = ex[p]
            fr[p] = e - (e.numerator // e.denominator) + c
        g = _fgcd(fr.values())
        inner = Fraction(1)
        for p, f in fr.items():
            inner *= Fraction(p) ** int(f / g)
        key = (inner.numerator * inner.denominator, 0 if g > 0 else 1)
        if best is None or key < best[0]:
            best = (key, inner, g, fr)
    _, inner, g, fr = best
    coeff = sp.Integer(1)
    for p, e in ex.items():
        rest = e - fr.get(p, Fraction(0))
        coeff *= sp.Integer(p) ** sp.Rational(rest.numerator, rest.denominator)
    return coeff, inner, g


def _flat_mul(e) -> list:
    """The factors of a (possibly nested, unevaluated) product, in order."""
    out = []
    for a in e.args:
        out += _flat_mul(a) if a.is_Mul else [a]
    return out


def _negative_fraction_of_sum(f) -> bool:
    """(a + b)^{-p/q} with q > 2: printed with its negative exponent, as the paper does."""
    return bool(f.is_Pow and f.base.is_Add and f.exp.is_Rational and f.exp.is_negative
                and not (2 * f.exp).is_integer)


class PaperPrinter(LatexPrinter):
    """SymPy's LaTeX printer with the paper's notation and ordering rules (module docstring)."""

    def __init__(self, names=None, functions=None, literal=False, **settings):
        base = dict(ln_notation=False, mul_symbol=None, inv_trig_style="full",
                    root_notation=False, fold_short_frac=False)
        if literal:
            base["order"] = "none"
        base.update(settings)
        super().__init__(base)
        self._literal = literal
        self._names = dict(NAMES)
        self._names.update(names or {})
        self._functions = dict(FUNCTIONS)
        self._functions.update(functions or {})
        self._placeholders: dict = {}

    # -- symbols and functions -------------------------------------------------------------
    def _print_Symbol(self, expr, style="plain"):
        if expr in self._placeholders:
            return self._placeholders[expr]
        name = expr.name
        if name in self._names:
            return self._names[name]
        if name.startswith("\\int"):
            return r"\left(%s\right)" % name  # an integral as a factor: its extent made clear
        if "\\" in name or "^" in name or "{" in name:
            return name  # already LaTeX (the derivation's display symbols)
        return super()._print_Symbol(expr, style=style)

    _print_Dummy = _print_Symbol

    def _print_Function(self, expr, exp=None):
        name = type(expr).__name__
        if name in self._functions:
            name_tex, with_args = self._functions[name]
        elif name in self._names:
            name_tex, with_args = self._names[name], True
        elif name == "G" and len(expr.args) == 4:  # the paper's G(a, b; c; z) = 2F1
            return self._hyp(expr.args[:2], expr.args[2:3], expr.args[3], exp)
        else:
            return super()._print_Function(expr, exp)
        tex = name_tex
        if with_args:
            tex += r"\left(" + ", ".join(self._print(a) for a in expr.args) + r"\right)"
        if exp is not None:
            tex = (r"\left(%s\right)^{%s}" % (tex, exp)) if with_args else f"{tex}^{{{exp}}}"
        return tex

    def _hyp(self, ap, bq, z, exp=None):
        a = ", ".join(self._print(x) for x in ap)
        b = ", ".join(self._print(x) for x in bq)
        tex = r"{}_{%d}F_{%d}\left(%s; %s; %s\right)" % (len(ap), len(bq), a, b, self._print(z))
        return tex if exp is None else r"\left(%s\right)^{%s}" % (tex, exp)

    def _print_hyper(self, expr, exp=None):
        return self._hyp(expr.ap, expr.bq, expr.argument, exp)

    def _print_re(self, expr, exp=None):
        tex = r"\operatorname{Re}\left(%s\right)" % self._print(expr.args[0])
        return tex if exp is None else r"%s^{%s}" % (tex, exp)

    def _print_im(self, expr, exp=None):
        tex = r"\operatorname{Im}\left(%s\right)" % self._print(expr.args[0])
        return tex if exp is None else r"%s^{%s}" % (tex, exp)

    def _print_Derivative(self, expr):
        # d^n f / d x^n with the function printed in the paper's notation (no argument)
        f = expr.expr
        (var, n), = expr.variable_count if len(expr.variable_count) == 1 else ((None, None),)
        if var is None:
            return super()._print_Derivative(expr)
        top = "d" if n == 1 else f"d^{{{n}}}"
        bottom = f"d{self._print(var)}" if n == 1 else f"d{self._print(var)}^{{{n}}}"
        body = self.parenthesize(f, sp.printing.precedence.PRECEDENCE["Mul"], strict=True)
        if isinstance(f, sp.core.function.AppliedUndef):
            return r"\frac{%s %s}{%s}" % (top, body, bottom)
        return r"\frac{%s}{%s} %s" % (top, bottom, body)

    # -- sums: positive terms first ----------------------------------------------------------
    def _print_Add(self, expr, order=None):
        if self._literal:  # a transcription: its terms in the printed order
            return super()._print_Add(expr, order="none")
        terms = list(self._as_ordered_terms(expr, order=order))
        syms = expr.free_symbols
        if len(syms) == 1 and len(terms) >= 3 and all(
                t.is_number or t.as_coeff_Mul()[1].as_base_exp()[0] in syms
                                  for t in terms):
            # a polynomial in one symbol: ascending powers, as the paper writes a series
            x = next(iter(syms))
            terms.sort(key=lambda t: sp.degree(t, x) if t.as_coeff_Mul()[1].as_base_exp()[1].is_Integer
                       else 0)
            return super()._print_Add(sp.Add(*terms, evaluate=False), order="none")
        order = [t for t in terms if isinstance(t, sp.Order)]  # O(p^3) stays last
        terms = [t for t in terms if not isinstance(t, sp.Order)]
        pos = [t for t in terms if not _coeff_isneg(t)]
        neg = [t for t in terms if _coeff_isneg(t)] + order
        tex = ""
        for i, term in enumerate(pos + neg):
            if i == 0:
                pass
            elif _coeff_isneg(term):
                tex += " - "
                term = -term
            else:
                tex += " + "
            if i == 0 and _coeff_isneg(term):
                tex += "- "
                term = -term
            term_tex = self._print(term)
            if self._needs_add_brackets(term):
                term_tex = r"\left(%s\right)" % term_tex
            tex += term_tex
        return tex

    # -- powers ------------------------------------------------------------------------------
    def _print_Pow(self, expr):
        base, ex = expr.base, expr.exp
        if ex == sp.S.Half and not base.is_Integer:
            return r"\sqrt{%s}" % self._print(base)
        if ex == -sp.S.Half and not base.is_Integer:
            return r"\frac{1}{\sqrt{%s}}" % self._print(base)
        if ex.is_Rational and (2 * ex).is_integer and base.is_Integer:
            return super()._print_Pow(sp.Pow(base, ex)) if ex != sp.S.Half else r"\sqrt{%s}" % base
        if base.is_Rational and ex.is_Rational and not ex.is_Integer:
            if base.is_Integer:
                return self._constant([expr])
            return r"\left(%s\right)^{%s}" % (self._print(base), self._print(ex))
        if ex.is_Rational and ex.is_negative and not ex.is_Integer and (
                base.is_Add or base.is_Rational):
            return r"\left(%s\right)^{%s}" % (self._print(base), self._print(ex))
        if base.is_Rational and not base.is_Integer and ex.is_Integer and ex.is_negative:
            return r"\left(%s\right)^{%s}" % (self._print(base), self._print(ex))
        return super()._print_Pow(expr)

    def _constant(self, factors) -> str:
        """A product of powers of rationals, as coefficient times (p/q)^r (see module doc)."""
        parts = constant_parts(factors)
        if parts is None:
            if len(factors) > 1:
                return super()._print_Mul(sp.Mul(*factors))
            return super()._print_Pow(factors[0]) if factors[0].is_Pow else self._print(factors[0])
        coeff, inner, g = parts
        ctex = self._power_tex(inner, g)
        if coeff == 1:
            return ctex
        ph = sp.Symbol("0const%d" % len(self._placeholders))
        self._placeholders[ph] = ctex
        return self._print_Mul_plain(sp.Mul(coeff, ph, evaluate=False))

    def _power_tex(self, inner: Fraction, g: Fraction) -> str:
        """(p/q)^g with a positive exponent, except that 4/5 is written (5/4)^{-g}."""
        if g < 0:
            inner, g = 1 / inner, -g
        primes = set(sp.factorint(inner.numerator)) | set(sp.factorint(inner.denominator))
        if inner < 1 and primes <= {2, 5}:
            inner, g = 1 / inner, -g
        base = sp.Rational(inner.numerator, inner.denominator)
        power = sp.Rational(g.numerator, g.denominator)
        if base.is_Integer:
            return "%s^{%s}" % (self._print(base), self._print(power))
        return r"\left(%s\right)^{%s}" % (self._print(base), self._print(power))

    # -- products ----------------------------------------------------------------------------
    def _print_Mul_plain(self, expr):
        return super()._print_Mul(expr)

    def _print_Mul(self, expr):
        if self._literal and expr.is_Mul:
            # a transcription: flatten the products SymPy's parser nests, and drop the 1 and -1
            # factors it leaves unevaluated (the sign goes in front)
            flat = _flat_mul(expr)
            args = [a for a in flat if a != 1 and a != -1]
            neg = sum(a == -1 for a in flat) % 2 == 1
            if len(args) != len(expr.args) or len(flat) != len(expr.args):
                inner = args[0] if len(args) == 1 else sp.Mul(*args, evaluate=False)
                body = self._print_factor(inner) if args else "1"
                return ("- " if neg else "") + body
        if self._literal and expr.is_Mul:
            kept = [f for f in expr.args if _negative_fraction_of_sum(f)]
            if kept and len(kept) < len(expr.args):
                others = [f for f in expr.args if f not in kept]
                rest = others[0] if len(others) == 1 else sp.Mul(*others, evaluate=False)
                return " ".join([self._print_factor(rest)] + [self._print(f) for f in kept])
        if not expr.is_Mul or self._literal:  # SymPy's Pow printer sends 1/x here
            return super()._print_Mul(expr)
        if _coeff_isneg(expr):
            return "- " + self._print_Mul(-expr)
        nums = [f for f in expr.args if f.is_Add]
        dens = [f for f in expr.args if f.is_Pow and f.exp == -1 and f.base.is_Add]
        if len(nums) == 1 and len(dens) == 1 and all(_coeff_isneg(t) for t in nums[0].args):
            # (-a - b)/(c - d) is written (a + b)/(d - c)
            others = [f for f in expr.args if f is not nums[0] and f is not dens[0]]
            flipped = sp.Mul(*others, -nums[0], sp.Pow(-dens[0].base, -1, evaluate=False),
                             evaluate=False)
            return self._print_Mul_plain(flipped)
        factors = list(expr.args)
        numeric = [f for f in factors if _is_number_factor(f)]
        other = [f for f in factors if not _is_number_factor(f)]
        if not other:
            return self._constant(numeric)

        def fractional(f):
            b, e = f.as_base_exp()
            return e.is_Rational and not (2 * e).is_integer

        frac_other = [f for f in other if fractional(f)]
        ex = _prime_exponents(numeric) or {}
        frac_nums = {p: e for p, e in ex.items() if (2 * e).denominator != 1}
        if len(frac_other) >= 2:
            # one common exponent r = 2 gcd(exponents): every inner exponent a multiple of 1/2
            exps = [_frac(f.as_base_exp()[1]) for f in frac_other] + list(frac_nums.values())
            r = 2 * _fgcd(exps)
            rr = sp.Rational(r.numerator, r.denominator)
            inner = sp.Mul(*[b ** (e / rr) for b, e in (f.as_base_exp() for f in frac_other)])
            inner *= sp.Mul(*[sp.Integer(p) ** (sp.Rational(e.numerator, e.denominator) / rr)
                              for p, e in frac_nums.items()])
            rest_num = sp.Mul(*[sp.Integer(p) ** sp.Rational(e.numerator, e.denominator)
                                for p, e in ex.items() if p not in frac_nums])
            rest = rest_num * sp.Mul(*[f for f in other if f not in frac_other])
            group = r"\left(%s\right)^{%s}" % (self._print(inner), self._print(rr))
            sign = ""
            if _coeff_isneg(rest):
                sign, rest = "- ", -rest
            coeff, rest2 = rest.as_coeff_Mul()
            parts = []
            if coeff.is_Float:  # a decimal factor first (0.735 ...); fractions stay in the rest
                parts, rest = [self._print(coeff)], rest2
            parts.append(group)
            if rest != 1:
                parts.append(self._print_factor(rest))
            return sign + " ".join(parts)
        # sums raised to a negative fraction: kept as such, after the rest of the product
        kept = [f for f in other if _negative_fraction_of_sum(f)]
        rest_factors = [f for f in factors if f not in kept]
        # numbers with fractional prime exponents: one constant, printed (p/q)^r
        if frac_nums:
            const = sp.Mul(*numeric)
            ph = sp.Symbol("0const%d" % len(self._placeholders))
            self._placeholders[ph] = self._constant(numeric)
            rest_factors = [f for f in rest_factors if f not in numeric] + [ph]
            del const
        if not kept and not frac_nums:
            return self._print_Mul_plain(expr)
        rest = sp.Mul(*rest_factors)
        parts = []
        if rest != 1:
            parts.append(self._print_Mul_plain(rest) if rest.is_Mul else self._print_factor(rest))
        for f in kept:
            parts.append(self._print(f))
        return " ".join(parts)

    def _print_factor(self, e):
        if e.is_Add:
            return r"\left(%s\right)" % self._print(e)
        return self._print(e)


def paper_latex(expr, names=None, functions=None, literal=False) -> str:
    """LaTeX of ``expr`` in the paper's notation (see :class:`PaperPrinter`); strings pass through
    :func:`mathtext_safe` only. ``literal``: an unevaluated transcription, printed with its own
    order and grouping (no collecting, no reordering)."""
    if isinstance(expr, str):
        return mathtext_safe(expr)
    return mathtext_safe(PaperPrinter(names, functions, literal=literal).doprint(expr))
