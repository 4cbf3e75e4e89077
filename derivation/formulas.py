"""FORMULAS.md: the derived (corrected) equations as LaTeX, numbered as in the paper.

Written by ``zener-sym derive --markdown`` at the root of a source checkout (next to
pyproject.toml) and kept fresh by ``zener-sym derive --check`` (and the test suite): after a change
to the derivation, regenerate it like generated/. The output is deterministic: equations are
sorted by number and printed by ``sympy.latex`` with fixed settings; no timings or measured
floats go in.
"""
from __future__ import annotations

import difflib
import re
from pathlib import Path

import sympy as sp

__all__ = ["render", "repo_root", "formulas_path", "write", "check", "FILENAME"]

FILENAME = "FORMULAS.md"


def _eq_key(number: str):
    m = re.match(r"(\d+)(.*)", number)
    return (int(m.group(1)), m.group(2)) if m else (10**9, number)


#: Sections of FORMULAS.md: (title, equation numbers in the paper's order of the argument).
GROUPS = (
    ("Hertz, Zener and the physical scales", ("3", "7a", "9", "11", "11a")),
    ("The homotopy", ("12", "13", "14", "16", "26", "27", "28", "29", "30", "31")),
    ("The maximum compression and k", ("17", "18", "19", "20", "21", "22", "23", "24", "25")),
    ("The zeroth-order solution", ("32", "33", "34", "35", "54", "54a", "56", "57", "58", "59",
                                   "60", "61", "78", "79", "80", "81")),
    ("The first-order solution", ("36", "37", "38", "39a", "39b", "40", "40a", "40b", "40c", "40d",
                                  "40e", "41", "41a", "42", "42a", "42b", "42c")),
    ("The rigid limit, lambda = 0", ("49a", "49b", "49c", "50", "51", "52", "53")),
    ("Force, impulse, deflection and energy", ("43", "44", "48", "66", "75", "75a", "76")),
)

#: Headings in plain words (their anchors stay predictable) and, where it helps, a line of text
#: with LaTeX under the heading. An equation missing here is listed under "Other equations" with
#: the description its derivation part gave.
TITLES = {
    "3": ("Hertz's maximum compression", r"With $m = m^*$."),
    "7a": ("Zener's coefficient", ""),
    "9": ("the characteristic time", r"With $m = m^*$; $\bar\delta = \delta/(T V_0)$, $\tau = t/T$."),
    "11": ("the inelasticity parameter",
           r"$\lambda = \alpha m_1/T$ with $m_1 = \frac{4}{3}\pi R^3\rho_1$."),
    "11a": ("the wave speed of the plate", "Quasi-longitudinal waves."),
    "12": ("the auxiliary linear operator", ""),
    "13": ("the nonlinear operator", "Zener's equation (10)."),
    "14": ("the zero-order deformation equation", ""),
    "16": ("the homotopy series", ""),
    "17": ("Zener's equation in the velocity", r"Eq. (10) with $y = d\bar\delta/d\tau$ as a function of $\bar\delta$."),
    "18": ("large lambda", r"(17) divided by $y$, for $\lambda \to \infty$."),
    "19": ("the velocity for large lambda", r"The asymptote $\lambda \to \infty$, $y(0) = 1$."),
    "20": ("the maximum compression for large lambda", r"The root of (19), $\lambda \to \infty$."),
    "21": ("small lambda", r"(17) with $\lambda \to 0$."),
    "22": ("the velocity for small lambda", r"The asymptote $\lambda \to 0$, $y(0) = 1$."),
    "23": ("the maximum compression at lambda = 0", "The root of (22)."),
    "24": ("the interpolation of the asymptotes", r"(20) plus the value of (23) to the power $-3/2$."),
    "25": ("the coefficient of the linear operator", r"$k = \sqrt{\bar\delta_m}$ with (24)."),
    "26": ("the Taylor expansion of the square root", ""),
    "27": ("the Taylor expansion of the 3/2 power", ""),
    "28": ("order 0 in p", r"With (29): $\bar\delta_0(0) = 0$, $\dot{\bar\delta}_0(0) = 1$."),
    "29": ("initial conditions at order 0", ""),
    "30": ("order 1 in p", r"With (31): $\bar\delta_1(0) = \dot{\bar\delta}_1(0) = 0$."),
    "31": ("initial conditions at order 1", ""),
    "32": ("the damping rate", r"$\beta = k\lambda/2$ with $k$ of (25)."),
    "33": ("the frequency", r"$\omega_0 = \sqrt{4k - k^2\lambda^2}/2$ with $k$ of (25)."),
    "34": ("the general solution of (28)", r"(29) gives $c_1 = 1/\omega_0$, $c_2 = 0$."),
    "35": ("the zeroth-order solution", ""),
    "36": ("the forcing of (30)", r"Valid for $0 < \omega_0\tau < \pi$."),
    "37": ("variation of constants", ""),
    "38": ("the variation-of-constants system", ""),
    "39a": ("C11 prime", "Solved from (38)."),
    "39b": ("C12 prime", "Solved from (38)."),
    "40": ("C11", r"The antiderivative of $C_{11}'$; the paper's $C_{114}$ is ours divided by $\omega_0$."),
    "40a": ("the elementary part of C11", ""),
    "40b": ("the hypergeometric integral K",
            r"$K' = e^{-\beta\tau/2}\sin^{1/2}(\omega_0\tau)$; principal ${}_2F_1$ on $|z| = 1$."),
    "40c": ("C124 through K", ""),
    "40d": ("C113 through K", ""),
    "40e": ("C114 through C124", r"By parts; $C_{123} = C_{114}$."),
    "41": ("C12", r"The antiderivative of $C_{12}'$; the paper's $C_{124}$ is ours divided by $\omega_0$."),
    "41a": ("the elementary part of C12", ""),
    "42": ("the first-order solution", ""),
    "42a": ("K at the start", r"$\tau \to 0^+$, by Gauss's sum."),
    "42b": ("C11 at the start", r"The value at $\tau \to 0^+$."),
    "42c": ("C12 at the start", r"The value at $\tau \to 0^+$."),
    "43": ("the contact force", ""),
    "44": ("the dimensionless force", ""),
    "48": ("the dimensionless impulse", ""),
    "49a": ("the frequency at lambda = 0", ""),
    "49b": ("the zeroth order at lambda = 0", ""),
    "49c": ("the first-order correction at lambda = 0", ""),
    "50": ("the zeroth-order force at lambda = 0", ""),
    "51": ("the first-order force at lambda = 0", r"With $\bar\delta_1$ of (49c)."),
    "52": ("Hunter's pulse, dimensionless", "Eqs. (4) and (5) in the scales (9), (44)."),
    "53": ("Reed's pulse, dimensionless", "Eq. (6) in the scales (9), (44)."),
    "54": ("the zeroth-order contact duration", ""),
    "54a": ("the zeroth-order contact duration in lambda", ""),
    "56": ("the zeroth-order velocity", ""),
    "57": ("the end of compression", ""),
    "58": ("the compression duration", ""),
    "59": ("the compression duration in lambda", ""),
    "60": ("the recovery duration in lambda", ""),
    "61": ("the asymmetry index", ""),
    "66": ("the dimensionless plate deflection", ""),
    "75": ("the energy lost by the sphere", r"With $m = m^*$."),
    "75a": ("the material coefficient", ""),
    "76": ("the ratio of energy loss", r"$\xi = 2\lambda\int\bar F^2 d\tau$."),
    "78": ("the velocity at the end of contact", ""),
    "79": ("the zeroth-order restitution", ""),
    "80": ("the zeroth-order restitution in lambda", ""),
    "81": ("the validity bound", r"$4(\lambda + (5/4)^{-3/5})^{1/3} > \lambda^2$, i.e. "
           r"$\lambda^6 < 64(\lambda + (5/4)^{-3/5})$, holds for $\lambda < \lambda_{crit}$."),
}


def slug(text: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    s = re.sub(r"[^\w\- ]", "", text.strip().lower())
    return s.replace(" ", "-")


def heading(number: str, description: str) -> str:
    return f"({number}) {TITLES[number][0] if number in TITLES else description}"


def render(derivation) -> str:
    """The markdown text of FORMULAS.md for a :class:`~.registry.Derivation`."""
    eqs = derivation.equations
    listed = {n for _, ns in GROUPS for n in ns}
    groups = [(title, [n for n in ns if n in eqs]) for title, ns in GROUPS]
    others = sorted((n for n in eqs if n not in listed), key=_eq_key)
    if others:
        groups.append(("Other equations", others))
    groups = [(t, ns) for t, ns in groups if ns]
    lines = [
        "# Derived equations",
        "",
        "<!-- Generated by `zener-sym derive --markdown` from zener_sym.derivation "
        f"(SymPy {sp.__version__.rsplit('.', 1)[0]}.x). Do not edit by hand. -->",
        "",
        "The homotopy-analysis solution of Zener's impact equation, re-derived with SymPy; every",
        "equation below was checked by `zener-sym derive` (symbolic simplification or mpmath at",
        "40 digits). Numbers are the paper's; a letter suffix marks an intermediate result the",
        "paper does not number. Where the transcription of the paper differs, these are the",
        "derived forms (AUDIT.md compares the two). Notation: $\\bar\\delta$ dimensionless",
        "compression, $\\tau$ dimensionless time, $\\lambda$ Zener's inelasticity parameter,",
        "${}_2F_1(a, b; c; z)$ the Gauss hypergeometric function (principal branch).",
        "",
        "## Contents",
        "",
    ]
    for title, ns in groups:
        links = ", ".join(f"[({n})](#{slug(heading(n, eqs[n][1]))})" for n in ns)
        lines.append(f"- [{title}](#{slug(title)}): {links}")
    lines.append("")
    for title, ns in groups:
        lines += [f"## {title}", ""]
        for number in ns:
            tex, description = eqs[number]
            lines += [f"### {heading(number, description)}", ""]
            note = TITLES[number][1] if number in TITLES else ""
            if note:
                lines += [note, ""]
            lines += ["$$", tex, "$$", ""]
    return "\n".join(lines)


def repo_root() -> Path:
    """The source checkout's root (the folder holding pyproject.toml next to derivation/).

    Raises
    ------
    RuntimeError
        When zener_sym.derivation is not imported from a source checkout (a plain install).
    """
    root = Path(__file__).resolve().parent.parent
    if not (root / "pyproject.toml").is_file() or not (root / "derivation").is_dir():
        raise RuntimeError(
            f"FORMULAS.md lives at the root of a source checkout, but zener_sym.derivation was "
            f"imported from {Path(__file__).resolve().parent}, which is not inside one; run this "
            f"from a checkout installed with `pip install -e .`"
        )
    return root


def formulas_path(root: Path | None = None) -> Path:
    """FORMULAS.md in ``root`` (default: the checkout this module runs from)."""
    return (repo_root() if root is None else Path(root)) / FILENAME


def write(derivation, root: Path | None = None) -> Path:
    """Write FORMULAS.md at the checkout root (or ``root``); returns its path."""
    path = formulas_path(root)
    path.write_text(render(derivation), encoding="utf-8")
    return path


def check(derivation, root: Path | None = None) -> tuple[bool, str]:
    """Compare the committed FORMULAS.md (in ``root``, default the checkout) with a fresh
    rendering.

    Returns
    -------
    (fresh, diff)
        ``diff`` is a unified diff (committed -> regenerated), empty when fresh.
    """
    path = formulas_path(root)
    new = render(derivation)
    old = path.read_text(encoding="utf-8") if path.is_file() else ""
    if old == new:
        return True, ""
    diff = "".join(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                        f"{FILENAME} (committed)", f"{FILENAME} (regenerated)"))
    if not old:
        diff = f"{path} does not exist; run `zener-sym derive --markdown`\n" + diff
    return False, diff
