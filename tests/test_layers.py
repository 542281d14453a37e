"""One installed import name, and layers that point one way.

Layers, lowest first: ``pocket.core`` (vocabulary) < ``pocket.meshes`` < the solvers
(``pocket.shooting``, ``pocket.fem``, ``pocket.analytical``, independent of each other)
< ``pocket.apps`` < ``pocket.validation`` < ``pocket.cli``. Two independent checks:
import-linter's contracts in pyproject.toml (every import statement, deferred ones
included), and each layer imported whole in a fresh interpreter where every higher
layer is made unimportable.
"""

import json
import os
import pathlib
import subprocess
import sys
from importlib import metadata

import pytest

from pocket.apps.provenance import DISTRIBUTION

LAYERS = ["pocket.core", "pocket.meshes", "pocket.shooting | pocket.fem | pocket.solid | pocket.analytical",
          "pocket.apps", "pocket.validation", "pocket.cli"]
ROOT = pathlib.Path(__file__).resolve().parents[1]

_IMPORT_WITH_BLOCKED = r"""
import importlib, importlib.abc, json, pkgutil, sys
blocked, wanted = json.loads(sys.argv[1]), sys.argv[2]

class Block(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if any(name == b or name.startswith(b + ".") for b in blocked):
            raise ImportError(f"{name} is a higher layer than {wanted}")
        return None

sys.meta_path.insert(0, Block())
package = importlib.import_module(wanted)
names = [wanted] + [m.name for m in pkgutil.walk_packages(package.__path__, wanted + ".")
                    if not m.name.endswith("__main__")]
for name in names:
    importlib.import_module(name)
print(len(names))
"""


def _above(layer_index: int) -> list[str]:
    return [m.strip() for layer in LAYERS[layer_index + 1:] for m in layer.split("|")]


@pytest.mark.slow
@pytest.mark.parametrize(("index", "module"), [(i, m.strip()) for i, layer in enumerate(LAYERS)
                                           for m in layer.split("|")])
def test_each_layer_imports_with_the_higher_ones_unavailable(index, module, tmp_path):
    """Exact answer: every module of the layer imports (the count printed) although importing any module
    of a higher layer (or, for a solver, of another solver) raises ImportError."""
    blocked = _above(index)
    if "|" in LAYERS[index]:
        blocked += [m.strip() for m in LAYERS[index].split("|") if m.strip() != module]
    proc = subprocess.run([sys.executable, "-c", _IMPORT_WITH_BLOCKED, json.dumps(blocked), module],
                          capture_output=True, text=True, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert int(proc.stdout) >= 1


def _source_tree(tmp_path) -> pathlib.Path:
    """The package as installed (pyproject's package-dir mapping), assembled from the repository's folders."""
    import shutil
    import tomllib

    mapping = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-dir"]
    for package, folder in sorted(mapping.items()):
        shutil.copytree(ROOT / folder, tmp_path / package.replace(".", "/"), dirs_exist_ok=True,
                        ignore=shutil.ignore_patterns("__pycache__"))
    return tmp_path


@pytest.mark.slow
def test_import_linter_contracts_hold(tmp_path):
    """import-linter's layers and independence contracts (pyproject.toml) are kept by the source: every one of
    them, counted in pyproject.toml, reported kept."""
    import tomllib

    contracts = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]["contracts"]
    tree = _source_tree(tmp_path)
    script = ("import sys; from importlinter.cli import lint_imports; "
              "sys.exit(lint_imports(config_filename=sys.argv[1]))")
    proc = subprocess.run([sys.executable, "-c", script, str(ROOT / "pyproject.toml")], capture_output=True,
                          text=True, cwd=tree, env={**os.environ, "PYTHONPATH": str(tree)})
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert f"Contracts: {len(contracts)} kept, 0 broken." in proc.stdout


def test_the_contracts_cover_the_layers_here():
    """The layers of this test are those of pyproject.toml's contract."""
    import tomllib

    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]["contracts"]
    layers = next(c["layers"] for c in config if c["type"] == "layers")
    assert layers[::-1] == LAYERS


def test_one_top_level_name_installed():
    """The distribution installs the single top-level package ``pocket``."""
    top = metadata.distribution(DISTRIBUTION).read_text("top_level.txt")
    assert top is not None
    assert top.split() == ["pocket"]


_IMPORT_FROM_THE_ROOT = r"""
import importlib, json, sys
name = sys.argv[1]
try:
    importlib.import_module(name)
    message = None
except ImportError as error:
    message = str(error)
print(json.dumps([message, sorted(m for m in sys.modules if m == name or m.startswith(name + "."))]))
"""


@pytest.mark.parametrize("name", ["shooting", "fem", "analytical", "meshes", "validation"])
@pytest.mark.slow
def test_no_second_copy_from_the_repository_root(name):
    """Exact answer: from the repository's root, where the folder ``name`` is on ``sys.path``, ``import name``
    fails with one line that says to import ``pocket.<name>``, and leaves no module of that name loaded;
    ``pocket.<name>`` still imports there."""
    proc = subprocess.run([sys.executable, "-c", _IMPORT_FROM_THE_ROOT, name], capture_output=True, text=True,
                          cwd=ROOT)
    assert proc.returncode == 0, proc.stderr
    message, loaded = json.loads(proc.stdout)
    assert message is not None
    assert message.startswith(f"import pocket.{name}, not {name}:")
    assert "\n" not in message
    assert loaded == []
    proc = subprocess.run([sys.executable, "-c", _IMPORT_FROM_THE_ROOT, f"pocket.{name}"], capture_output=True,
                          text=True, cwd=ROOT)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)[0] is None, proc.stderr


@pytest.mark.slow
def test_generic_names_are_not_importable_and_do_not_shadow(tmp_path):
    """From a neutral folder, ``import fem`` (and the other former top-level names) fails, the
    subpackages import, and a user's own fem.py / validation.py beside the command cannot shadow them."""
    for name in ("fem", "shooting", "analytical", "meshes", "validation"):
        proc = subprocess.run([sys.executable, "-c", f"import {name}"], capture_output=True, text=True,
                              cwd=tmp_path)
        assert proc.returncode == 1
        assert f"No module named '{name}'" in proc.stderr
    proc = subprocess.run([sys.executable, "-c", "import pocket.fem, pocket.shooting, pocket.meshes, "
                           "pocket.validation, pocket.analytical"], capture_output=True, text=True, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    for name in ("fem", "shooting", "analytical", "meshes", "validation"):
        (tmp_path / f"{name}.py").write_text("raise RuntimeError('the user's own module was imported')\n")
    proc = subprocess.run([sys.executable, "-m", "pocket.cli", "inflate", "--alpha", "0.3", "--pressure", "0.3",
                           "--solver", "fem", "--elements", "8", "--json"], capture_output=True, text=True,
                          cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["solver"] == "fem"


def _cycles(package: str) -> list[str]:
    """The modules of ``package`` that import themselves back through a chain of the package's own imports
    (grimp's import graph: every import statement, deferred ones included)."""
    import grimp

    graph = grimp.build_graph("pocket")
    modules = {m for m in graph.modules if m.startswith(package + ".")}
    return sorted(m for m in modules for i in graph.find_modules_directly_imported_by(m)
                  if i in modules and graph.chain_exists(i, m, as_packages=False))


@pytest.mark.parametrize("package", [
    "pocket.core", "pocket.fem", "pocket.solid", "pocket.analytical", "pocket.apps", "pocket.validation",
    "pocket.cli", "pocket.shooting",
])
def test_no_import_cycle_inside_a_package(package):
    """No module of ``package`` imports itself back: each module can be read (and imported) after the ones it
    uses, e.g. the figures' vocabulary before the sections that draw with it and the list that gathers them."""
    assert _cycles(package) == []
