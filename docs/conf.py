"""Sphinx configuration of the zener-sym documentation site.

Build (after ``pip install -e '.[docs]'``)::

    python -m sphinx -W --keep-going -b html docs docs/_build/html
    python docs/check_links.py docs/_build/html

The markdown pages in ``docs/`` stay the source (GitHub renders them too); MyST parses them here.
The site-only pages are the ``.rst`` files beside them; the API reference page is written by this
file from ``zener_sym.__all__`` at every build, so a name added to ``__all__`` is documented
without editing the docs. The gallery runs ``examples/plot_*.py`` (sphinx-gallery).
"""
from __future__ import annotations

import os
import re
import shutil
import sys
from pathlib import Path

import zener_sym
from zener_sym.bench.lammps import run as _lammps_run

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
os.environ.setdefault("MPLBACKEND", "Agg")  # the gallery draws into files, never a window
sys.path.insert(0, str(DOCS))  # apiref.py, gallery_order.py

import apiref  # noqa: E402  (needs DOCS on sys.path)

project = "zener-sym"
author = "zener-sym developers"
copyright = "zener-sym developers (MIT licence)"
release = zener_sym.__version__
version = release

extensions = [
    "myst_parser",
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx_copybutton",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
templates_path = ["_templates"]
# Data and chart folders are not pages (docs/benchmarks/BENCHMARKS.md is a run's raw output,
# linked as a download from benchmarks.md); the gallery's sources are .py, not pages.
exclude_patterns = ["_build", "benchmarks", "data", "figures", "auto_examples/*.ipynb",
                    "auto_examples/*.py", "auto_examples/*.zip", "auto_examples/*.json",
                    "auto_examples/*.md5", "**/sg_execution_times.rst"]
nitpicky = False
# Docstrings write code in single backticks (`zener-sym generate --check`); reST's default role
# would set it in italics and turn "--" into a dash.
default_role = "literal"

# --- MyST: the existing markdown pages -------------------------------------------------------
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
# GitHub-style heading anchors, so links such as AUDIT.md#81-the-validity-bound resolve here too
myst_heading_anchors = 4

# Links between repository files that are pages of the site under another name. GitHub renders
# the markdown as written; the site rewrites these link targets as the pages are read.
REPO_LINKS = {
    "AUDIT.md": "audit_report.rst",
    "FORMULAS.md": "formulas.rst",
    "CHANGELOG.md": "changelog.rst",
    "CITATION.cff": "citing.rst",
    "LICENSE": "citing.rst#licence",
    "examples/c/README.md": "c_kernels.rst",
}


def _rewrite_links(text: str, prefix: str) -> str:
    """Point ``](prefix + FILE)`` links at the site page that shows FILE."""
    for src, dst in REPO_LINKS.items():
        text = text.replace(f"]({prefix}{src}", f"]({dst}")
    return text


#: Markdown files in folders that are not pages (exclude_patterns): linked as downloads.
DOWNLOADS = ("benchmarks/BENCHMARKS.md",)


def _source_read(app, docname, source):
    # a docs/*.md page links the top-level files as ../AUDIT.md
    text = _rewrite_links(source[0], "../")
    for path in DOWNLOADS:
        text = text.replace(f"]({path})", f"](path:{path})")
    source[0] = text


def _include_read(app, relative_path, parent_docname, content):
    # README.md included from docs/: its links are relative to the repository root
    if Path(relative_path).name == "README.md":
        text = _rewrite_links(content[0], "")
        content[0] = re.sub(r"\]\(docs/", "](", text)


def setup(app):
    app.connect("source-read", _source_read)
    app.connect("include-read", _include_read)


# --- API reference ----------------------------------------------------------------------------
apiref.write(DOCS / "reference", zener_sym)
# "(Eq. 66)" inside a summary line must not end the line in the reference's tables
from sphinx.ext import autosummary as _autosummary  # noqa: E402

_autosummary.WELL_KNOWN_ABBREVIATIONS = apiref.SUMMARY_ABBREVIATIONS
autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {"member-order": "bysource"}
autodoc_typehints = "none"  # numpydoc's Parameters section carries the types
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
# Many docstrings predate numpydoc's validator; the sweep over src/ (issue 26) turns checks on.
numpydoc_validation_checks: set = set()
numpydoc_xref_param_type = False

# --- Gallery ------------------------------------------------------------------------------------
# The gallery is the top level of examples/ only: examples/c/ (the C kernels' examples, a page of
# its own) would be taken for a sub-gallery, so the scripts are staged in the build folder.
GALLERY_SRC = DOCS / "_build" / "gallery_src"
shutil.rmtree(GALLERY_SRC, ignore_errors=True)
GALLERY_SRC.mkdir(parents=True)
for _f in sorted((ROOT / "examples").glob("*")):
    if _f.is_file() and (_f.name == "GALLERY_HEADER.rst" or _f.name.startswith("plot_")):
        shutil.copy2(_f, GALLERY_SRC / _f.name)

# The scripts that run LAMMPS (they import zener_sym.bench.lammps; the lammps extra is not part
# of the docs extra) are shown without being run where it is missing: the documented build needs
# only the docs extra.
_LAMMPS_SCRIPTS = sorted(f.stem for f in GALLERY_SRC.glob("plot_*.py")
                         if "zener_sym.bench.lammps" in f.read_text(encoding="utf-8"))
if not _LAMMPS_SCRIPTS or _lammps_run.available():
    _RUN = r"[\\/]plot_"
else:
    _RUN = r"[\\/](?!(?:" + "|".join(map(re.escape, _LAMMPS_SCRIPTS)) + r")\.py$)plot_"
    print(f"docs: {', '.join(_LAMMPS_SCRIPTS)} shown, not run: {_lammps_run.HINT}")

sphinx_gallery_conf = {
    "examples_dirs": str(GALLERY_SRC),
    "gallery_dirs": "auto_examples",
    # the scripts run at build time (the others are shown with their code only)
    "filename_pattern": _RUN,
    # only the top level of examples/: examples/c/ holds the C kernels' examples, not gallery scripts
    "ignore_pattern": r"[\\/]c[\\/]|__init__\.py",
    "within_subsection_order": "gallery_order.key",
    # legends sit outside the axes (the package style): save with bbox_inches="tight"
    "image_scrapers": ("gallery_scraper.tight",),
    "download_all_examples": False,
    "reset_modules": ("matplotlib",),
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "show_memory": False,
    "remove_config_comments": True,
    "write_computation_times": False,
    "min_reported_time": 1,
    "default_thumb_file": None,
    "thumbnail_size": (400, 280),
}

# --- HTML ---------------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"zener-sym {release}"
html_static_path: list = []
html_show_sourcelink = False
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version", "theme-version"],
}
html_context = {"default_mode": "light"}
# pages without sub-pages: no empty "Section Navigation" column beside them
html_sidebars = {"index": [], "getting_started": [], "changelog": [], "citing": []}
copybutton_prompt_text = r">>> |\.\.\. |\$ "
copybutton_prompt_is_regexp = True
