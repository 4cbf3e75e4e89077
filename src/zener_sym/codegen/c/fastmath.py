"""Constants of the C runtime's own ``exp`` over a block of points (``zs__exp_pass`` in
``runtime.c.in``), computed with mpmath so that the emitted file does not depend on the machine.

exp(x) = 2^k exp(r), x = k ln2 + r, |r| <= ln2/2 (Cody and Waite's reduction, ln2 = hi + lo with
k hi exact), k = round(x / ln2) by adding 1.5 2^52 (the low bits of the sum are k, which also
gives 2^k by an integer shift), exp(r) by its Taylor polynomial of degree ``EXP_DEG`` (Horner).
No table and no branch: the compiler pairs the points (SSE2) in a loop where libm's ``exp``, one
call a point, was a fifth of a history's time.
"""
from __future__ import annotations

import mpmath

from .tables import num

#: degree of the Taylor polynomial of exp(r), |r| <= ln2/2: truncation r^14/14! < 5e-18 relative
EXP_DEG = 13
#: |k| <= K_MAX for |x| <= 700 (the pass clamps there and hands larger |x| to libm)
K_MAX = 1010


def _ln2_split() -> tuple[float, float]:
    """ln2 as hi + lo: hi with few enough bits that k hi is exact for |k| <= K_MAX."""
    bits = 53 - K_MAX.bit_length()
    with mpmath.workdps(50):
        c = mpmath.log(2)
        m, e = mpmath.frexp(c)
        hi = float(mpmath.ldexp(mpmath.floor(m * 2 ** bits), e - bits))
        lo = float(c - mpmath.mpf(hi))
    return hi, lo


def taylor_bound() -> float:
    """Relative truncation error of the polynomial on |r| <= ln2/2 (its first omitted term
    over exp(-ln2/2))."""
    with mpmath.workdps(30):
        r = mpmath.log(2) / 2
        return float(r ** (EXP_DEG + 1) / mpmath.factorial(EXP_DEG + 1) / mpmath.exp(-r))


def exp_constants_c() -> str:
    """C text: the macros ``zs__exp_pass`` and ``zs__log1p_pass`` read (correctly rounded)."""
    hi, lo = _ln2_split()
    with mpmath.workdps(50):
        inv = float(1 / mpmath.log(2))
    return (f"/* zs__exp_pass: 1/ln2, ln2 = hi + lo (k hi exact for |k| <= {K_MAX}), 1.5 2^52 */\n"
            f"#define ZS__EXP_INV_LN2 {num(inv)}\n"
            f"#define ZS__LN2_HI {num(hi)}\n"
            f"#define ZS__LN2_LO {num(lo)}\n"
            "#define ZS__EXP_SHIFT 6755399441055744.0\n")


def _estrin(coef: list[float], var: str, out: str, tag: str, indent: str) -> str:
    """C statements: ``out`` = sum coef[j] var^j by Estrin's scheme (pairs c_2i + c_2i+1 var,
    then pairs of those in var^2, var^4, var^8: a chain of about log2(len(coef)) steps instead
    of Horner's len(coef), the limit of a pass over the points)."""
    if len(coef) > 16:
        raise ValueError("_estrin: powers up to var^8 only (at most 16 coefficients)")
    p2, p4, p8 = f"{tag}2", f"{tag}4", f"{tag}8"
    lines = [f"{indent}double {p2} = {var} * {var}, {p4} = {p2} * {p2}, {p8} = {p4} * {p4};"]
    terms = [num(c) for c in coef]
    for level, power in enumerate((var, p2, p4, p8), start=1):
        if len(terms) == 1:
            break
        nxt = [f"{terms[i]} + {terms[i + 1]} * {power}" if i + 1 < len(terms) else terms[i]
               for i in range(0, len(terms), 2)]
        if len(nxt) == 1:
            terms = nxt
            break
        names = [f"{tag}_{level}_{i}" for i in range(len(nxt))]
        lines += [f"{indent}double {n} = {t};" for n, t in zip(names, nxt)]
        terms = names
    lines.append(f"{indent}{out} = {terms[0]};")
    return "\n".join(lines)


def exp_poly_c(indent: str = "        ") -> str:
    """C statements: ``p`` = sum r^j / j!, j <= EXP_DEG (Estrin; coefficients correctly
    rounded)."""
    with mpmath.workdps(50):
        coef = [float(1 / mpmath.factorial(j)) for j in range(EXP_DEG + 1)]
    return _estrin(coef, "r", "p", "r", indent)


#: terms of log's series in z = s^2 after the first: R = z Q(z), Q = sum_n 2 z^(n-1)/(2n+1),
#: n = 1 .. LOG_TERMS; |s| <= 3 - 2 sqrt(2) = 0.1716, so the first term left out,
#: 2 z^(LOG_TERMS+1)/(2 LOG_TERMS+3) s, is below 1e-20 of log(1 + f)
LOG_TERMS = 10


def log_bound() -> float:
    """Relative size of the first omitted term of log(1 + f) = f - f^2/2 + s (f^2/2 + R) at the
    end of the range, |s| = 3 - 2 sqrt(2) (f = sqrt(2) - 1)."""
    with mpmath.workdps(30):
        f = mpmath.sqrt(2) - 1
        s = f / (2 + f)
        z = s * s
        n = LOG_TERMS + 1
        return float(2 * s * z ** n / (2 * n + 1) / mpmath.log(1 + f))


def log_poly_c(indent: str = "        ") -> str:
    """C statements: ``q`` = Q(z) (Estrin; coefficients 2/(2n+1) correctly rounded)."""
    with mpmath.workdps(50):
        coef = [float(mpmath.mpf(2) / (2 * n + 1)) for n in range(1, LOG_TERMS + 1)]
    return _estrin(coef, "z", "q", "z", indent)
