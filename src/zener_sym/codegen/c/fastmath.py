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
    """C text: the macros ``zs__exp_pass`` reads (correctly rounded)."""
    hi, lo = _ln2_split()
    with mpmath.workdps(50):
        inv = float(1 / mpmath.log(2))
    return (f"/* zs__exp_pass: 1/ln2, ln2 = hi + lo (k hi exact for |k| <= {K_MAX}), 1.5 2^52 */\n"
            f"#define ZS__EXP_INV_LN2 {num(inv)}\n"
            f"#define ZS__EXP_LN2_HI {num(hi)}\n"
            f"#define ZS__EXP_LN2_LO {num(lo)}\n"
            "#define ZS__EXP_SHIFT 6755399441055744.0\n")


def exp_poly_c(indent: str = "        ") -> str:
    """C statements: ``p`` = sum r^j / j!, j <= EXP_DEG, by Estrin's scheme (pairs c_2i +
    c_2i+1 r, then pairs of those in r^2, r^4, ...: a chain of about log2(EXP_DEG) steps
    instead of Horner's EXP_DEG, the pass's limit; coefficients correctly rounded)."""
    with mpmath.workdps(50):
        coef = [float(1 / mpmath.factorial(j)) for j in range(EXP_DEG + 1)]
    terms = [num(c) for c in coef]
    lines = [f"{indent}double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;"]
    if EXP_DEG >= 16:
        raise ValueError("exp_poly_c: powers of r up to r^8 only")
    level, power = 0, "r"
    while len(terms) > 1:
        nxt = []
        for i in range(0, len(terms), 2):
            if i + 1 < len(terms):
                nxt.append(f"({terms[i]} + {terms[i + 1]} * {power})")
            else:
                nxt.append(terms[i])
        terms = nxt
        level += 1
        power = ("r2", "r4", "r8")[level - 1] if level <= 3 else "?"
        if len(terms) > 1:  # name the level's terms (readable C, one statement each)
            names = [f"e{level}_{i}" for i in range(len(terms))]
            lines += [f"{indent}double {n} = {t};" if t.startswith("(") else
                      f"{indent}double {n} = {t};" for n, t in zip(names, terms)]
            terms = names
    lines.append(f"{indent}p = {terms[0]};")
    return "\n".join(lines)
