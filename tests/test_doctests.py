"""The examples in the docstrings of the documented modules run, and print what they show.

Each module of the API reference (docs/api/) is imported as installed (``pocket.*``, not the source files) and
every example found in its docstrings is run by ``doctest``: those of the objects it defines, and those of the
public names it re-exports (``__all__``: a solver's package re-exports its ``api``'s entry points, defined in the
solver's modules). A module without any example fails: its page would show none.
"""

import doctest
import importlib
import inspect
import pathlib
import re

import pytest

#: the modules whose objects docs/api/ documents
MODULES = (
    "pocket.shooting",
    "pocket.fem",
    # a solid solve takes a second even on its coarsest mesh (its five examples about 4 s): the slow lane
    pytest.param("pocket.solid", marks=pytest.mark.slow),
    "pocket.analytical",
    "pocket.core.states",
    "pocket.core.materials",
    "pocket.core.fluids",
    "pocket.core.indenters",
    "pocket.core.profiles",
    "pocket.core.geometries",
    "pocket.core.errors",
    "pocket.core.units",
    "pocket.apps.cases",
    "pocket.apps.casefile",
    "pocket.apps.physical",
    "pocket.apps.design",
    "pocket.apps.sense",
    "pocket.apps.fit.case",
    "pocket.apps.fit.data",
    # a fit is seconds of solves (each example makes one): the slow lane
    pytest.param("pocket.apps.fit.leastsquares", marks=pytest.mark.slow),
    pytest.param("pocket.apps.fit.report", marks=pytest.mark.slow),
    "pocket.apps.fit.capsuledata",
    pytest.param("pocket.apps.fit.capsuletest", marks=pytest.mark.slow),
    "pocket.apps.sweep.grid",
    "pocket.apps.sweep.workers",
    "pocket.apps.vtk.files",
)

#: the API reference's pages, where the repository holds them (not in an installed copy)
PAGES = pathlib.Path(__file__).resolve().parents[1] / "docs" / "api"

_NAMES = {getattr(entry, "values", (entry,))[0] for entry in MODULES}
_FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def _examples(name: str) -> list[doctest.DocTest]:
    """The doctests of module ``name``: its own objects' and its public re-exports', each once, each run in
    a namespace of its own (an example imports what it uses, as a reader would)."""
    module = importlib.import_module(name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    tests = finder.find(module, name, globs={})
    for public in getattr(module, "__all__", ()):
        obj = getattr(module, public)
        if (inspect.isfunction(obj) or inspect.isclass(obj)) and obj.__module__ != name:
            tests += finder.find(obj, f"{name}.{public}", module=False, globs={})
    unique = {(test.filename, test.lineno, test.name.rsplit(".", 1)[-1]): test for test in tests if test.examples}
    return sorted(unique.values(), key=lambda test: test.name)


@pytest.mark.parametrize("name", MODULES)
def test_api_examples_print_what_they_show(name):
    """Every example of module ``name`` prints exactly what its docstring shows (up to ``...`` and
    whitespace), and the module has at least one: a reader can copy any of them and get that answer."""
    tests = _examples(name)
    assert tests, f"{name}: no example in its docstrings"
    runner = doctest.DocTestRunner(optionflags=_FLAGS)
    report = []
    for test in tests:
        runner.run(test, out=report.append)
    assert runner.failures == 0, "".join(report)


def _documented() -> list[str]:
    """The functions and classes the API reference's pages document (``autofunction``, ``autoclass``)."""
    found = re.compile(r"^\.\. auto(?:function|class):: +(\S+)", re.MULTILINE)
    return sorted({name for page in PAGES.glob("*.md") for name in found.findall(page.read_text())})


def test_every_documented_entry_point_has_an_example():
    """Each function and class the API pages document carries an example (``>>>``) in its docstring, and
    comes from one of ``MODULES`` (so the test above runs it): a page shows no entry point without one."""
    if not PAGES.is_dir():
        pytest.skip("the API reference's pages are not in this copy of pocket")
    names = _documented()
    assert names, f"no autofunction or autoclass in {PAGES}"
    missing, unrun = [], []
    for name in names:
        module, _, attr = name.rpartition(".")
        obj = getattr(importlib.import_module(module), attr)
        if ">>>" not in (inspect.getdoc(obj) or ""):
            missing.append(name)
        if module not in _NAMES:
            unrun.append(name)
    assert not missing, f"documented without an example: {missing}"
    assert not unrun, f"documented from a module whose examples are not run here: {unrun}"
