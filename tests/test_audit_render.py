"""AUDIT.md and FORMULAS.md as a reader sees them: every formula renders, nothing is cut.

The rendering check has two parts, both on every math block of the committed files (display
``$$...$$`` and inline ``$...$``, outside code):

1. matplotlib's mathtext parses it (``MathTextParser("path").parse``). mathtext reads a subset of
   LaTeX; the printer (``zener_sym.derivation.printing``) writes only that subset (no
   ``\\begin{...}``, no ``\\middle``, ``\\frac`` for ``\\tfrac``), and GitHub's MathJax reads all
   of it, so a block that passes renders in both.
2. A LaTeX-syntax check that mathtext does not make: braces balance, ``\\left``/``\\right`` pair
   up, and no SymPy or Python syntax (``**``, ``Rational(``, ``sqrt(``, ``I*``, ``Derivative(``)
   appears, in the math or in the prose around it.

A test also shows that the check fails on a broken block, so it cannot pass vacuously. No path of
the machine a file was written on (a home folder, the paper's transcription) appears in the
rendered files or anywhere in the source tree.
"""
from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

import pytest
import sympy as sp

mathtext = pytest.importorskip("matplotlib.mathtext")

ROOT = Path(__file__).resolve().parents[1]
FILES = ("AUDIT.md", "FORMULAS.md")
#: SymPy or Python syntax (a LaTeX command such as \\exp( or \\sqrt is not matched).
PYTHON_SYNTAX = (r"\*\*", r"Rational\(", r"(?<!\\)sqrt\(", r"\bI\*", r"I_\*", r"Derivative\(",
                 r"(?<!\\)atan\(", r"\blam\*", r"omega0\*", r"(?<!\\)exp\(")


#: A path of the machine a file was written on: home folders, the work folder, the paper's
#: transcription (the character classes keep this file from matching itself).
MACHINE_PATH = re.compile(r"/(?:home|Users|root|work)/|[A-Z]:[\\/]Users|shared[/]paper|000[_]0e97")
#: The folders and files of the source tree that the scan reads (built pages and venvs excluded).
TREE = ("src", "derivation", "generated", "tests", "tools", "docs", "examples", "benchmarks", ".ci")


def _strip_code(text: str) -> str:
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    return re.sub(r"`[^`\n]*`", "", text)


def math_blocks(text: str) -> list[str]:
    """Display blocks ``$$...$$`` and inline ``$...$`` of a markdown text, outside code."""
    text = _strip_code(text)
    blocks = [b.strip() for b in re.findall(r"\$\$(.+?)\$\$", text, flags=re.S)]
    rest = re.sub(r"\$\$(.+?)\$\$", " ", text, flags=re.S)
    blocks += re.findall(r"\$([^$\n]+?)\$", rest)
    if rest.count("$") % 2:
        raise AssertionError("an odd number of $ outside display math: an unclosed inline formula")
    return blocks


def syntax_problems(tex: str) -> list[str]:
    """What is wrong with one LaTeX block by the rules of the module docstring ([] if nothing)."""
    out = []
    depth = 0
    for ch in re.sub(r"\\[{}]", "", tex):
        depth += (ch == "{") - (ch == "}")
        if depth < 0:
            break
    if depth != 0:
        out.append("unbalanced braces")
    if len(re.findall(r"\\left\b", tex)) != len(re.findall(r"\\right\b", tex)):
        out.append("\\left and \\right do not pair up")
    out += [f"Python syntax {s!r}" for s in PYTHON_SYNTAX if re.search(s, tex)]
    return out


_PARSER = mathtext.MathTextParser("path")


def mathtext_error(tex: str) -> str:
    """'' if matplotlib's mathtext parses ``tex``, else its error message."""
    try:
        _PARSER.parse("$" + " ".join(tex.split()) + "$")
    except Exception as exc:  # mathtext raises ValueError with the parse position
        return str(exc).splitlines()[-1] if str(exc) else type(exc).__name__
    return ""


@pytest.mark.parametrize("name", FILES)
def test_every_formula_renders(name):
    text = (ROOT / name).read_text(encoding="utf-8")
    blocks = math_blocks(text)
    assert len(blocks) > 100, f"{name}: only {len(blocks)} formulas found"
    bad = []
    for b in blocks:
        why = syntax_problems(b) + ([f"mathtext: {e}"] if (e := mathtext_error(b)) else [])
        if why:
            bad.append(f"{b[:120]!r}: {'; '.join(why)}")
    assert not bad, f"{len(bad)} broken formulas in {name}:\n" + "\n".join(bad[:20])


def test_the_check_fails_on_a_broken_formula():
    good = r"\beta = \frac{\lambda}{2} \left(\lambda + \left(\frac{5}{4}\right)^{-\frac{3}{5}}\right)^{-\frac{1}{3}}"
    assert not syntax_problems(good) and not mathtext_error(good)
    assert syntax_problems(good[:-1])  # a brace missing
    assert mathtext_error(r"\begin{cases} a \\ b \end{cases}")  # not mathtext: must be rewritten
    assert syntax_problems("lam**2 + Rational(5,4)")
    with pytest.raises(AssertionError):
        math_blocks("an $unclosed formula")


@pytest.mark.parametrize("name", FILES)
def test_no_python_syntax_cut_text_or_outside_path(name):
    text = (ROOT / name).read_text(encoding="utf-8")
    prose = _strip_code(text)
    for s in PYTHON_SYNTAX:
        assert not re.search(s, prose), f"{name} has {s!r}: {re.search(s, prose)}"
    assert not MACHINE_PATH.search(text), MACHINE_PATH.search(text)
    # nothing cut: the old table cut long cells with "..." at the end
    assert not [ln for ln in text.splitlines() if ln.rstrip(" |").endswith("...")]


def _tree_files() -> list[Path]:
    files = [p for p in ROOT.iterdir() if p.is_file() and not p.name.startswith(".")]
    for top in TREE:
        files += [p for p in (ROOT / top).rglob("*") if p.is_file()
                  and not {"_build", "__pycache__", ".venv"} & set(p.relative_to(ROOT).parts)]
    return files


def test_no_machine_path_in_the_source_tree():
    found = []
    for path in _tree_files():
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:  # images and other binary files
            continue
        found += [f"{path.relative_to(ROOT)}:{n}: {m.group()}" for n, line in
                  enumerate(text.splitlines(), 1) if (m := MACHINE_PATH.search(line))]
    assert not found, "machine paths in the source tree:\n" + "\n".join(found)


def test_the_machine_path_check_can_fail():
    # the samples are assembled, so that this file's own text passes the scan
    home, work, users, paper = "home", "work", "Users", "shared/" + "paper/000_" + "0e97cc.txt"
    for line in (f"see /{home}/ann/x.txt", f"# (/{work}/{paper})", f"C:\\{users}\\ann",
                 f"/{users}/bob/paper.txt", paper):
        assert MACHINE_PATH.search(line), line
    assert not MACHINE_PATH.search("src/zener_sym/audit/_raw.py, docs/paper.md")
    assert len(_tree_files()) > 100  # the scan reads the tree


@pytest.mark.parametrize("name", FILES)
def test_every_link_has_its_heading(name):
    from zener_sym.audit.markdown import slug

    text = (ROOT / name).read_text(encoding="utf-8")
    headings = [slug(h) for h in re.findall(r"^#+ (.+)$", text, flags=re.M)]
    assert len(headings) == len(set(headings)), "two headings share an anchor"
    targets = re.findall(r"\]\(#([^)]+)\)", text)
    assert targets and not [t for t in targets if t not in headings]


def test_audit_md_layout():
    from zener_sym.audit.markdown import PAPER_TITLE

    text = (ROOT / "AUDIT.md").read_text(encoding="utf-8")
    assert PAPER_TITLE in text
    # the summary table comes first, then one section per item, headed with its number
    assert text.index("| item | kind | verdict | note |") < text.index("## Equations")
    for n in (1, 24, 32, 40, 41, 81):
        assert re.search(rf"^### \({n}\) ", text, flags=re.M), n
    # the (24) and F_m claims: both readings of a printed bound are stated once at the top
    assert "How a printed bound is read" in text
    sec = text[text.index("### Claim on (51)"):]
    sec = sec[:sec.index("\n### ", 5)]
    assert "Read strictly" in sec and "to the printed digits" in sec


def test_formulas_md_has_contents_and_plain_headings():
    text = (ROOT / "FORMULAS.md").read_text(encoding="utf-8")
    assert "## Contents" in text
    for h in re.findall(r"^#+ (.+)$", text, flags=re.M):
        assert not re.search(r"[$\\^]|->|_\d", h), f"heading with ASCII or LaTeX math: {h!r}"


# ---- the printer's rules, against values computed another way -------------------------------
def test_constant_rule_keeps_the_value():
    from zener_sym.derivation.printing import constant_parts

    q = sp.Rational(5, 4)
    for c in (q ** sp.Rational(-3, 5), q ** sp.Rational(2, 5), q ** sp.Rational(1, 10),
              sp.Integer(30) ** sp.Rational(2, 5) / 4, sp.Rational(71289, 62500) * q ** sp.Rational(-2, 5),
              sp.Integer(2) ** sp.Rational(1, 5) * 3 ** sp.Rational(2, 5) / 2):
        coeff, base, g = constant_parts(list(sp.Mul.make_args(c)))
        back = coeff * sp.Rational(base.numerator, base.denominator) ** sp.Rational(g.numerator, g.denominator)
        assert sp.simplify(back / c) == 1, c
    # the paper's constants come out as the paper writes them
    assert constant_parts(list(sp.Mul.make_args(q ** sp.Rational(-3, 5))))[1:] in (
        (Fraction(5, 4), Fraction(-3, 5)), (Fraction(4, 5), Fraction(3, 5)))


@pytest.mark.parametrize("expr, want", [
    ("(lam + (5/4)**(-3/5))**(-1/3)", r"\left(\lambda + \left(\frac{5}{4}\right)^{- \frac{3}{5}}\right)^{- \frac{1}{3}}"),
    ("lam/2*(lam + (5/4)**(-3/5))**(-1/3)",
     r"\frac{\lambda}{2} \left(\lambda + \left(\frac{5}{4}\right)^{- \frac{3}{5}}\right)^{- \frac{1}{3}}"),
    ("1 - nu2**2", r"1 - \nu_2^{2}"),
    ("(5/4)**(1/10)", r"\left(\frac{5}{4}\right)^{\frac{1}{10}}"),
    ("(ms/(4*Es*sqrt(R*V0)/3))**(2/5)", r"\left(\frac{3 m^*}{4 E^* \sqrt{R} \sqrt{V_0}}\right)^{\frac{2}{5}}"),
    # all-negative numerator over a sum: both signs flipped, as a person writes eta (61)
    ("(-2*atan(x) - pi)/(2*atan(x) - pi)",
     r"\frac{2 \arctan{\left(x \right)} + \pi}{\pi - 2 \arctan{\left(x \right)}}"),
    # a sum times a kept negative power: the sum keeps its brackets
    ("(pi - 2*atan(x))*(lam + 1)**(-1/3)",
     r"\left(\pi - 2 \arctan{\left(x \right)}\right) \left(\lambda + 1\right)^{- \frac{1}{3}}"),
])
def test_printer_rules(expr, want):
    from zener_sym.derivation.printing import paper_latex

    ns = {n: sp.Symbol(n, positive=True) for n in ("lam", "nu2", "ms", "Es", "R", "V0", "x", "y")}
    e = sp.sympify(expr.replace("(5/4)", "Rational(5,4)").replace("(-3/5)", "Rational(-3,5)")
                   .replace("(-1/3)", "Rational(-1,3)").replace("(1/10)", "Rational(1,10)")
                   .replace("(2/5)", "Rational(2,5)"), locals=ns)
    assert paper_latex(e) == want
