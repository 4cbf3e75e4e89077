"""Examples cannot rot: the docstring Examples run as doctests, the README's Python blocks run,
and the README's printed numbers are the ones the code gives."""
from __future__ import annotations

import doctest
import importlib
import re

import pytest

from conftest import ROOT

#: Public modules whose docstring examples are part of the documentation.
DOCTEST_MODULES = ["zener_sym", "zener_sym.api", "zener_sym.models.base", "zener_sym.scene.scene",
                   "zener_sym.scene.compare", "zener_sym.scene.units", "zener_sym.scene.checks",
                   "zener_sym.scene.materials", "zener_sym.scene.select",
                   "zener_sym.scene.grains", "zener_sym.scene.lookup",
                   "zener_sym.scene.stress_waves", "zener_sym.scene.calibrate"]


@pytest.mark.parametrize("name", DOCTEST_MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0


def _readme_blocks():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_readme_python_blocks_run_and_print_what_they_say(monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)  # the quick start saves force.png
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    monkeypatch.setattr(plt, "show", lambda *a, **k: None)
    blocks = _readme_blocks()
    assert len(blocks) >= 3
    scope: dict = {}
    checked = 0
    for block in blocks:
        exec(compile(block, "README.md", "exec"), scope)  # noqa: S102 - our own README
        # "expr   # 0.306  comment": the shown numbers are what the expression gives
        for line in block.splitlines():
            m = re.match(r"^(\S.*?)\s+# ((?:[-0-9.]+|'[^']*')(?:, (?:[-0-9.]+|'[^']*'))*)\s{2}",
                         line + "  ")
            if not m or "=" in m.group(1).split("(")[0]:
                continue
            shown = [x.strip() for x in m.group(2).split(",")]
            value = eval(m.group(1), scope)  # noqa: S307
            values = value if isinstance(value, tuple) else (value,)
            assert len(values) == len(shown), line
            checked += 1
            for v, s in zip(values, shown):
                if s.startswith("'"):
                    assert v == s.strip("'"), line
                else:
                    digits = len(s.split(".")[1]) if "." in s else 0
                    assert round(float(v), digits) == float(s), (line, v)
    plt.close("all")
    assert checked >= 4  # the quick start's numbers were compared
    assert (tmp_path / "force.png").stat().st_size > 10_000  # the plot was drawn


def test_readme_is_for_users():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 300
    assert "Elastic impact of sphere on large plate" in text
    for word in ("issue ", "this branch", "load average"):
        assert word not in text
    for link in re.findall(r"\]\(([^)#]+)\)", text):
        if not link.startswith("http"):
            assert (ROOT / link).exists(), link


def test_readme_model_table_quotes_the_measured_envelopes():
    """The 'Which model' table's numbers are the committed envelopes' maxima over lambda <= 2
    (where each model answers), to the digits shown."""
    from zener_sym.scene import envelopes

    table = envelopes.load()
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    columns = ("e", "tau_d", "F_m", "force_history")
    checked = 0
    for line in text.splitlines():
        m = re.match(r"^\| `(\w+)` \|[^|]*\|" + r"([^|]*)\|" * 4, line)
        if not m or m.group(1) not in table["models"]:
            continue
        env = table["models"][m.group(1)]["envelopes"]
        for q, cell in zip(columns, m.groups()[1:]):
            cell = cell.strip()
            num = re.fullmatch(r"([0-9.]+)(%|e-(\d+))", cell)
            if not num:
                continue  # a dash, "far off", a range
            shown = float(num.group(1)) / 100 if num.group(2) == "%" else float(cell)
            worst = max(v for (lo, hi), v in zip(table["intervals"], env[q])
                        if hi <= 2.0 and v is not None)
            mant = num.group(1)
            mant = mant.replace(".", "").lstrip("0") if "." in mant else mant.strip("0")
            digits = len(mant) or 1
            assert float(f"{worst:.{digits}g}") == pytest.approx(shown, rel=1e-9), (line, q, worst)
            checked += 1
    assert checked >= 15


def test_public_api_has_numpydoc_sections():
    """Every public function of ``zener_sym`` documents Parameters, Returns, Raises and
    Examples; every public class has Examples."""
    import inspect

    import zener_sym as zs

    missing = []
    for name in zs.__all__:
        obj = getattr(zs, name)
        doc = inspect.getdoc(obj) or ""
        if inspect.isfunction(obj):
            need = ("Parameters", "Returns", "Raises", "Examples")
        elif inspect.isclass(obj):
            need = ("Examples",)
        else:
            continue
        missing += [f"{name}: {s}" for s in need if f"\n{s}\n" not in "\n" + doc]
    assert not missing, missing


def test_ci_runs_the_readmes_test_command():
    """.ci/run calls the README's install-and-test command verbatim (the README says it is what
    CI runs), flags included: a change to one without the other fails here."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    commands = re.findall(r"^    (python3 -m venv .*-m pytest.*)$", readme, flags=re.M)
    assert len(commands) == 1, commands
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    assert commands[0] in ci


def _prose(text: str) -> list[tuple[int, str]]:
    """The lines of a MyST page outside code and math, each with its number: fenced blocks,
    indented code blocks, display math ($$...$$), inline code and inline math are blanked."""
    lines = text.splitlines()
    out: list[tuple[int, str]] = []
    fence = None
    display = False
    prev_blank = True
    in_indented = False
    for no, line in enumerate(lines, 1):
        stripped = line.strip()
        if fence:
            if stripped.startswith(fence):
                fence = None
            prev_blank = False
            continue
        m = re.match(r"^\s*(```+|~~~+|:::+)", line)
        if m:
            fence = m.group(1)
            continue
        if display:
            display = not stripped.endswith("$$")
            continue
        if stripped.startswith("$$"):
            display = not (len(stripped) > 2 and stripped.endswith("$$"))
            continue
        # an indented code block: 4+ spaces after a blank line (or continuing one)
        if line.startswith("    ") and (prev_blank or in_indented):
            in_indented = True
            continue
        in_indented = in_indented and not stripped
        prev_blank = not stripped
        out.append((no, line))
    # inline code and inline math may span lines of a paragraph: blank them over the joined text
    joined = "\n".join(f"{no}\x00{line}" for no, line in out)
    def blank(m: re.Match[str]) -> str:  # keep the line marks inside a span
        return "".join(re.findall(r"\n\d+\x00", m.group(0)))

    joined = re.sub(r"(`+)(?:(?!\1).)+?\1", blank, joined, flags=re.S)
    joined = re.sub(r"(?<![\\$])\$(?!\$)[^$]+?(?<!\\)\$", blank, joined, flags=re.S)
    return [(int(no), rest) for no, _, rest in (part.partition("\x00")
                                                for part in joined.split("\n") if "\x00" in part)]


#: The hand-written pages of the site (FORMULAS.md and AUDIT.md are generated, with their own
#: tests).
MD_PAGES = sorted((ROOT / "docs").glob("*.md"))


def test_prose_checker_sees_what_is_code_and_math():
    page = ("text δ^{3/2} here\n\n    code x^{2}\n\n```\nfenced y^{2}\n```\n"
            "inline `z^{2}` and $a^{2}$ and\n$$\nb^{2}\n$$\n"
            "math $c^{2}\nacross$ lines, then w^{2}\n")
    found = [no for no, line in _prose(page) if "^{" in line]
    assert found == [1, 13]


@pytest.mark.parametrize("page", MD_PAGES, ids=lambda p: p.name)
def test_math_is_dollarmath_not_caret_text(page):
    """Formulas are written as MyST dollarmath ($...$, $$...$$) so that the site renders them:
    a raw ``^{`` outside code and math is caret text a reader sees as such."""
    raw = [f"{page.name}:{no}: {line.strip()}" for no, line in _prose(page.read_text("utf-8"))
           if "^{" in line]
    assert not raw, "caret math outside $...$:\n" + "\n".join(raw)
