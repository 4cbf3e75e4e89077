"""Write the API reference page (``docs/reference/index.rst``) from ``zener_sym.__all__``.

Called by ``conf.py`` at every build. Names are grouped by :data:`SECTIONS`; a name of
``__all__`` that no section lists lands in "Other exported names", so the reference always covers
the whole public namespace, whatever the groups say. The page is a build product (ignored by git).
"""
from __future__ import annotations

import shutil
from pathlib import Path

#: section title -> (intro, names of ``zener_sym.__all__``)
SECTIONS = {
    "Dimensionless core": (
        "Zener's equation (10) in the paper's notation: a summary of one impact, its history, "
        "the inverse (the lambda giving a restitution, a loss or a contact time) and the errors "
        "a model may raise.",
        ["summary", "history", "lam_from_summary", "Summary", "History", "MODELS",
         "FieldUnavailableError"]),
    "Models side by side": (
        "Every model against the exact solution, and the cheapest model that meets an accuracy.",
        ["compare", "Comparison", "select_model", "Selection"]),
    "Scenes in SI units": (
        "A sphere dropped on a plate: materials, presets, results in SI units and warnings.",
        ["Scene", "SceneResult", "Material", "ZenerWarning", "STEEL", "GLASS", "ALUMINIUM",
         "TABLE1_SPHERE", "TABLE1_PLATE", "PRESETS"]),
    "Viscoelastic grains": (
        "The grain reading of Zener's equation (DEM codes): lambda of a grain pair, the "
        "dissipative constant or plate thickness that gives a restitution, and the dissipative "
        "constant fitted to measured restitution data.",
        ["lam_from_dissipation", "grain_impact", "GrainImpact", "dissipation_for",
         "thickness_for", "fit_dissipation", "DissipationFit"]),
    "Stress waves": (
        "Hunter's and Reed's stress-wave loss of a sphere on an elastic half-space.",
        ["stress_wave_k", "stress_wave_loss"]),
}

#: Public submodules documented with their own members: module -> (title, intro).
MODULES = {
    "zener_sym.plot": ("Charts (``zener_sym.plot``)",
                       "The package's chart style and its ready-made charts (needs the "
                       "``plot`` extra, matplotlib)."),
    "zener_sym.plot.style": ("Chart style (``zener_sym.plot.style``)",
                             "One look per model, math labels, column-width fonts."),
    "zener_sym.scene.lookup": ("DEM lookup tables (``zener_sym.scene.lookup``)",
                               "Tables of e and the contact time over a lambda grid "
                               "(``zener-sym table``)."),
}

#: Generated kernels (``generated/``, emitted by ``zener-sym regen kernels``; never edited by hand).
GENERATED = ["ham0", "ham1"]

#: Abbreviations after which the one-line summaries of the reference's tables (autosummary's
#: first sentence) do not end: Sphinx's own list and the paper's "Eq. 11", "Fig. 5". conf.py hands
#: it to autosummary; tests/test_api_docs.py applies the same rule to every summary line.
SUMMARY_ABBREVIATIONS = ("et al.", "e.g.", "i.e.", "vs.", "Eq.", "Eqs.", "Fig.", "Figs.", "cf.")

_SKIP = {"__version__"}  # shown in the page text rather than as an object


def _data_doc(name: str, obj) -> str | None:
    """One-line description of an exported constant (autosummary would show its type's
    docstring: a tuple's or a dict's), read off the object at build time; None: not data."""
    if name == "MODELS":
        return ("Names of the registered models, a tuple read from the registry when asked "
                f"(so plug-ins show up): ``{', '.join(obj)}``.")
    if type(obj).__name__ == "Material":
        return (f"Preset :class:`~zener_sym.Material` ``{obj.name!r}``: E = {obj.E:.4g} Pa, "
                f"nu = {obj.nu:g}, rho = {obj.rho:g} kg/m^3. Source: {obj.source}.")
    if name == "PRESETS":
        return ("Preset materials by name (the command line's ``--sphere``/``--plate`` "
                f"choices): ``{', '.join(obj)}``.")
    return None


def _rule(title: str, ch: str) -> str:
    return f"{title}\n{ch * len(title)}\n"


def render(package) -> str:
    """The reST text of the reference page for ``package`` (``zener_sym``)."""
    public = [n for n in package.__all__ if n not in _SKIP]
    listed = {n for _, names in SECTIONS.values() for n in names}
    out = [_rule("API reference", "="),
           "Everything ``import zener_sym as zs`` exports (``zs.__all__``), the chart module "
           "and the generated kernels. Version: |release|.\n",
           ".. currentmodule:: zener_sym\n"]
    sections = dict(SECTIONS)
    other = [n for n in public if n not in listed]
    if other:
        sections["Other exported names"] = ("Exported by the package, not yet grouped.", other)
    for title, (intro, names) in sections.items():
        names = [n for n in names if n in public]
        if not names:
            continue
        data = {n: _data_doc(n, getattr(package, n)) for n in names}
        objects = [n for n in names if data[n] is None]
        out += [_rule(title, "-"), intro + "\n"]
        if objects:
            out += [".. autosummary::", "   :toctree: generated", "   :nosignatures:", ""]
            out += [f"   {n}" for n in objects] + [""]
        for n in names:
            if data[n] is not None:
                out += [f".. data:: {n}", "", f"   {data[n]}", ""]
    for mod, (title, intro) in MODULES.items():
        out += [_rule(title, "-"), intro + "\n", f".. automodule:: {mod}", "   :no-members:", "",
                f".. currentmodule:: {mod}", "", ".. autosummary::", "   :toctree: generated",
                "   :nosignatures:", ""]
        sub = __import__(mod, fromlist=["__all__"])
        out += [f"   {n}" for n in sub.__all__] + [""]
    out += [_rule("Generated kernels (``zener_sym.generated``)", "-"),
            "Emitted from the SymPy derivation by ``zener-sym regen kernels`` (do not edit; "
            "``zener-sym regen --check kernels`` fails when stale): the printed formulas only, "
            "each function taking the math namespace ``xp`` first "
            "(``zener_sym.ham.xp.NUMPY`` or "
            "``MPMATH``). The checked runtime around them (input checks, roots, integrals, "
            "precision) is ``zener_sym.ham.runtime_numpy`` and ``runtime_mpmath``; the models "
            "call that. They are public for users who want the bare closed forms.\n",
            ".. toctree::", "   :maxdepth: 1", ""]
    out += [f"   kernels/{m}" for m in GENERATED] + [""]
    return "\n".join(out)


def kernel_page(module: str) -> str:
    """The reST page of one generated kernel module: its docstring and public members."""
    full = f"zener_sym.generated.{module}"
    return "\n".join([_rule(full, "="), f".. automodule:: {full}", "   :members:", ""])



def write(folder: Path, package) -> Path:
    """Write ``index.rst`` into ``folder``; returns the path.

    When the page changed, the object pages autosummary wrote for the old one
    (``folder/generated``) are removed first: autosummary never deletes a stub, and a stale one
    (a name dropped from ``__all__``) would be a page outside every toctree.
    """
    folder.mkdir(exist_ok=True)
    path = folder / "index.rst"
    text = render(package)
    if not path.exists() or path.read_text() != text:
        shutil.rmtree(folder / "generated", ignore_errors=True)
        path.write_text(text)
    (folder / "kernels").mkdir(exist_ok=True)
    for module in GENERATED:
        page = folder / "kernels" / f"{module}.rst"
        if not page.exists() or page.read_text() != kernel_page(module):
            page.write_text(kernel_page(module))
    return path
