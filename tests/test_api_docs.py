"""The public API is documented as scientific Python users expect (issue 26).

For every public object of :data:`MODULES` (what each module's ``__all__`` exports; for a class
also its public methods and properties, inherited ones from the package included), numpydoc's
``docscrape`` must find the sections a reader looks for:

- ``Parameters`` when the signature has parameters, each parameter named there (a class may
  name its fields under ``Attributes`` instead: result records are made by the package);
- ``Returns`` (or ``Yields``) for a function or method that returns something (its return
  annotation, or a ``return <value>`` in its source when it has none);
- ``Raises`` for a function whose own body has a ``raise`` statement;
- ``Examples`` always.

Every ``Examples`` doctest runs, each docstring in fresh globals (an example imports what it
uses, as a user would), and a failure is reported with the object's name. Constants (``STEEL``,
``PRESETS``, ``__version__``) are documented by ``docs/apiref.py`` and skipped here.
"""
from __future__ import annotations

import ast
import doctest
import importlib
import importlib.util
import inspect
import io
import re
import textwrap
import warnings
from collections.abc import Callable, Iterator

import pytest

from conftest import ROOT
from numpydoc.docscrape import ClassDoc, FunctionDoc, NumpyDocString

#: Modules whose public objects are the documented API (the coordinator adds zener_sym.plot,
#: zener_sym.plot.style and the generated kernels here).
MODULES = ["zener_sym", "zener_sym.scene.lookup", "zener_sym.plot", "zener_sym.plot.style",
           "zener_sym.plot.curves", "zener_sym.plot.calibration"]

OPTIONFLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


# -- what is public ---------------------------------------------------------------------------
def _is_documentable(obj: object) -> bool:
    return inspect.isfunction(obj) or inspect.isclass(obj) or isinstance(obj, property)


def public_objects(module_name: str) -> Iterator[tuple[str, object]]:
    """``(qualified name, object)`` of every public function, class, method and property of a
    module (its ``__all__``); a class's members come from the package's own classes in its MRO
    (not from ``object``, ``Exception`` or ``ValueError``)."""
    module = importlib.import_module(module_name)
    for name in module.__all__:
        obj = getattr(module, name)
        if not _is_documentable(obj):
            continue
        yield f"{module_name}.{name}", obj
        if not inspect.isclass(obj):
            continue
        seen = set()
        for klass in obj.__mro__:
            if not klass.__module__.startswith("zener_sym"):
                continue
            for attr, member in vars(klass).items():
                if attr.startswith("_") or attr in seen:
                    continue
                seen.add(attr)
                if inspect.isfunction(member) or isinstance(member, property):
                    yield f"{module_name}.{name}.{attr}", member


def _all_objects() -> list[tuple[str, object]]:
    return [item for mod in MODULES for item in public_objects(mod)]


# -- the section check ------------------------------------------------------------------------
def _own_nodes(func: Callable[..., object]) -> list[ast.AST]:
    """The AST nodes of ``func``'s body, not descending into nested functions or classes."""
    try:
        source = textwrap.dedent(inspect.getsource(func))
    except (OSError, TypeError):
        return []
    tree = ast.parse(source)
    top = tree.body[0]
    out: list[ast.AST] = []
    stack = list(ast.iter_child_nodes(top))
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
            continue
        out.append(node)
        stack.extend(ast.iter_child_nodes(node))
    return out


def _returns_something(func: Callable[..., object]) -> bool:
    ann = inspect.signature(func).return_annotation
    if ann is not inspect.Signature.empty:
        return ann not in (None, "None")
    return any((isinstance(n, ast.Return) and n.value is not None)
               or isinstance(n, (ast.Yield, ast.YieldFrom)) for n in _own_nodes(func))


def _raises(func: Callable[..., object]) -> bool:
    return any(isinstance(n, ast.Raise) for n in _own_nodes(func))


def _documented_names(doc: NumpyDocString, *sections: str) -> set[str]:
    names = set()
    for section in sections:
        for entry in doc[section]:
            for part in entry.name.split(","):
                names.add(part.strip().lstrip("*"))
    return names


def _signature_params(obj: Callable[..., object]) -> list[str]:
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):  # builtins without a signature
        return []
    return [p for p in sig.parameters if p not in ("self", "cls")]


def missing_sections(name: str, obj: object) -> list[str]:
    """What the docstring of ``obj`` lacks, as readable lines naming ``name`` (empty: fine)."""
    if not inspect.getdoc(obj):
        return [f"{name}: no docstring"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # docscrape warns about sections it does not know
        if inspect.isclass(obj):
            doc: NumpyDocString = ClassDoc(obj, config={"show_class_members": False})
        elif isinstance(obj, property):
            doc = NumpyDocString(inspect.getdoc(obj) or "")
        else:
            doc = FunctionDoc(obj)
    problems = []
    if not doc["Summary"]:
        problems.append("a summary line")
    if inspect.isclass(obj):
        params = [] if issubclass(obj, BaseException) else _signature_params(obj)
        named = _documented_names(doc, "Parameters", "Attributes", "Other Parameters")
        if params and not (doc["Parameters"] or doc["Attributes"]):
            problems.append("Parameters (or Attributes)")
        problems += [f"parameter {p!r} in Parameters or Attributes" for p in params
                     if p not in named]
    elif inspect.isfunction(obj):
        params = _signature_params(obj)
        named = _documented_names(doc, "Parameters", "Other Parameters")
        if params and not doc["Parameters"]:
            problems.append("Parameters")
        else:
            problems += [f"parameter {p!r} in Parameters" for p in params if p not in named]
        if _returns_something(obj) and not (doc["Returns"] or doc["Yields"]):
            problems.append("Returns")
        if _raises(obj) and not doc["Raises"]:
            problems.append("Raises")
    if not doc["Examples"]:
        problems.append("Examples")
    return [f"{name}: lacks {p}" for p in problems]


# -- the doctest run --------------------------------------------------------------------------
def run_examples(name: str, obj: object) -> tuple[int, str]:
    """Run the doctests of ``obj``'s own docstring in fresh globals: ``(attempted, report)``,
    the report empty when every example printed what it shows."""
    finder = doctest.DocTestFinder(recurse=False)
    target = obj.fget if isinstance(obj, property) else obj
    module = inspect.getmodule(target)
    tests = finder.find(obj, name, module=module, globs={"__name__": "__main__"})
    out = io.StringIO()
    runner = doctest.DocTestRunner(verbose=False, optionflags=OPTIONFLAGS)  # not -v from sys.argv
    attempted = 0
    for test in tests:
        if test.name != name:  # recurse=False still lists nothing else, but be sure
            continue
        result = runner.run(test, out=out.write, clear_globs=True)
        attempted += result.attempted
    return attempted, out.getvalue()


@pytest.fixture(autouse=True, scope="module")
def _agg_backend() -> None:
    # chart examples (zener_sym.plot, once listed in MODULES) must not open windows
    try:
        import matplotlib
    except ImportError:
        return
    matplotlib.use("Agg")


# -- the tests --------------------------------------------------------------------------------
def test_the_list_covers_the_api() -> None:
    """The check sees every callable of ``zener_sym.__all__`` and their members (a bug in
    :func:`public_objects` would otherwise pass an empty list)."""
    import zener_sym as zs

    names = {n for n, _ in _all_objects()}
    for n in zs.__all__:
        if callable(getattr(zs, n)):
            assert f"zener_sym.{n}" in names
    for member in ("Scene.result", "Scene.lam", "SceneResult.history", "Summary.as_dict",
                   "Summary.fields", "History.deflection", "Comparison.to_markdown",
                   "DissipationFit.predict", "Material.with_yield"):
        assert f"zener_sym.{member}" in names
    assert "zener_sym.scene.lookup.lookup_table" in names
    assert "zener_sym.FieldUnavailableError.with_traceback" not in names  # Exception's own


def test_every_public_object_has_its_numpydoc_sections() -> None:
    problems = [p for name, obj in _all_objects() for p in missing_sections(name, obj)]
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("name, obj", [pytest.param(n, o, id=n) for n, o in _all_objects()])
def test_examples_run(name: str, obj: object) -> None:
    attempted, report = run_examples(name, obj)
    assert attempted > 0, f"{name}: no doctest in its Examples"
    assert not report, f"{name}: an example does not print what it shows\n{report}"


# -- the checks can fail ----------------------------------------------------------------------
def _good(lam: float, n: int = 2) -> float:
    """Twice lambda.

    Parameters
    ----------
    lam : float
        Zener's lambda.
    n : int
        The factor.

    Returns
    -------
    float

    Raises
    ------
    ValueError
        For a negative lambda.

    Examples
    --------
    >>> 2 * 0.5
    1.0
    """
    if lam < 0:
        raise ValueError("lambda must be >= 0")
    return n * lam


def _no_sections(lam: float, n: int = 2) -> float:
    """Twice lambda, documented in prose only."""
    if lam < 0:
        raise ValueError("lambda must be >= 0")
    return n * lam


def _one_parameter_missing(lam: float, n: int = 2) -> float:
    """Twice lambda.

    Parameters
    ----------
    lam : float
        Zener's lambda.

    Returns
    -------
    float

    Examples
    --------
    >>> 1 + 1
    2
    """
    return n * lam


def _wrong_example() -> None:
    """Nothing.

    Examples
    --------
    >>> 1 + 1
    3
    """


def test_a_complete_docstring_passes() -> None:
    assert missing_sections("_good", _good) == []
    assert run_examples("_good", _good) == (1, "")


def test_a_docstring_without_sections_fails_naming_each() -> None:
    got = missing_sections("_no_sections", _no_sections)
    assert got == ["_no_sections: lacks Parameters", "_no_sections: lacks Returns",
                   "_no_sections: lacks Raises", "_no_sections: lacks Examples"]


def test_an_undocumented_parameter_fails() -> None:
    assert missing_sections("_one", _one_parameter_missing) == [
        "_one: lacks parameter 'n' in Parameters"]


def test_a_wrong_example_is_reported_by_name() -> None:
    attempted, report = run_examples("zener_sym.fake._wrong_example", _wrong_example)
    assert attempted == 1
    assert "zener_sym.fake._wrong_example" in report and "Expected:\n    3" in report


def test_a_class_without_examples_fails() -> None:
    class Bare:
        """A record.

        Attributes
        ----------
        x : float
        """

        def __init__(self, x: float) -> None:
            self.x = x

    assert missing_sections("Bare", Bare) == ["Bare: lacks Examples"]


# -- dir(zener_sym) ---------------------------------------------------------------------------
def test_dir_shows_only_the_documented_names() -> None:
    import zener_sym as zs

    assert sorted(dir(zs)) == sorted(zs.__all__)
    for leak in ("api", "blocks", "params", "REGISTRY", "scene", "models", "exact"):
        assert leak not in zs.__all__ and leak not in dir(zs)
    # the subpackages stay importable by their full names (existing users' imports)
    import zener_sym.api
    import zener_sym.exact
    import zener_sym.params

    assert zs.exact is zener_sym.exact and zs.api.summary is zs.summary
    assert zener_sym.params.as_lambda(0.5).item() == 0.5
    assert set(zs.MODELS) >= {"exact", "hertz"}


# -- the one-line summaries of the reference's tables -----------------------------------------
def _abbreviations() -> tuple[str, ...]:
    spec = importlib.util.spec_from_file_location("_docs_apiref", ROOT / "docs" / "apiref.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return tuple(module.SUMMARY_ABBREVIATIONS)


#: autosummary's first-sentence rule (sphinx.ext.autosummary.extract_summary: a period and a space
#: end the sentence unless it ends with one of the abbreviations docs/conf.py gives it), which cut
#: "The lambda (Eq. 11) whose ..." to "The lambda (Eq." when "Eq." was not among them
_PERIOD = re.compile(r"\.(?:\s+)")


#: a summary that ends in an abbreviation ("Eq.", "Fig.", "Ref.") or leaves a bracket open was cut
#: inside its sentence; a whole first sentence of a longer paragraph is fine
_ABBREVIATED_END = re.compile(r"\b[A-Z][a-z]{0,3}\.$")


def _cut_summary(doc: str, abbreviations: tuple[str, ...]) -> str | None:
    """The summary line when autosummary would cut it inside a sentence, else None."""
    first = " ".join(doc.strip().split("\n\n")[0].split())
    sentences = _PERIOD.split(first)
    shown = first
    for i in range(len(sentences)):
        shown = ". ".join(sentences[: i + 1]).rstrip(".") + "."
        if not shown.endswith(abbreviations):
            break
    unbalanced = shown.count("(") != shown.count(")") or shown.count("[") != shown.count("]")
    return first if unbalanced or _ABBREVIATED_END.search(shown) else None


def test_reference_tables_show_whole_summary_lines() -> None:
    abbreviations = _abbreviations()
    cut = {name: s for name, obj in _all_objects()
           if (s := _cut_summary(inspect.getdoc(obj) or "", abbreviations)) is not None}
    assert not cut, cut


def test_a_summary_cut_at_an_abbreviation_is_found() -> None:
    line = "The lambda (Eq. 11) whose e is given.\n\nMore."
    assert _cut_summary(line, ("e.g.",)) is not None
    assert _cut_summary(line, _abbreviations()) is None
    assert _cut_summary("One sentence. And a second one.", _abbreviations()) is None
    assert _cut_summary("Force (in N. per unit) at t.", _abbreviations()) is not None
    assert _cut_summary("The lambda whose e is given.\n\nSee Eq. 11.", ("e.g.",)) is None
