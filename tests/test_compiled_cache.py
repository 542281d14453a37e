"""The compiled code's on-disk cache: outside the package, fresh after an edit, never a stop (``pocket.core.compiled``).

Each case runs a copy of pocket (its folders placed as the installation maps them; a
solver answers only to its name ``pocket.<solver>``), first on the path, in a fresh
process whose home and temporary folder are the test's: compiling there takes seconds,
so these are slow tests. The child prints where the cache of its main kernel lives, that
kernel's cache hits and misses, and its result. Folders are made unusable in a way that
holds for root too (CI may run as root, for whom permission bits do not stop writes): the
cache locators create their folder with os.makedirs, which fails where a file of that name is in the way.
"""

import json
import os
import pathlib
import shutil
import site
import stat
import subprocess
import sys
import sysconfig
import tomllib

import pytest

from pocket.apps.provenance import version

pytestmark = pytest.mark.slow

REPOSITORY = pathlib.Path(__file__).resolve().parents[1]
# the installed pocket's version names the cache's subfolder (the copies run by these tests are of it)
VERSION = version()
# a build from a copy of the sources without git history: setuptools-scm's fallback_version, no commit
FALLBACK = tomllib.loads((REPOSITORY / "pyproject.toml").read_text())["tool"]["setuptools_scm"]["fallback_version"]
# each child: a small kernel of the solver's package (the cache is one mechanism for every kernel: a small one
# compiles in a second where the integrator or the element loop takes ten), its cache folder, hits and misses,
# and a result to compare bit for bit
CHILDREN = {
    "shooting": """
import json
import numpy as np
from {package}.equations import pole_state, rhs as kernel
from {package}.laws import law_of
law = law_of(0.3)
y = pole_state(1.1, law, 1.0, 1e-2)
out = np.zeros_like(y)
kernel(1e-2, y, law.code, law.params, 1.0, out)
result = out.tolist()
""",
    "fem": """
import json
import numpy as np
from {package}.laws import evaluate as kernel
from {package}.material import law_of
law = law_of(0.3)
result = kernel(law.code, law.params, np.array([1.1, 1.2]), np.array([1.05, 1.1])).ravel().tolist()
""",
}
REPORT = """
stats = kernel.stats
print(json.dumps([stats.cache_path, sum(stats.cache_hits.values()), sum(stats.cache_misses.values()), result]))
"""
# a source file of the kernel's package other than the kernel's own, which numba's own stamp (the kernel's file
# alone) does not see: shooting's kernel (the equations' right-hand side) inlines it (the law's tensions); the
# finite elements' (the law's derivatives) does not, but the element loop that inlines the law is in it
CALLEES = {"shooting": "tensions.py", "fem": "loops.py"}


def _copy(folder: pathlib.Path, solver: str) -> pathlib.Path:
    """A copy of pocket in ``folder``, each package where pyproject's mapping installs it; returns the
    copy of ``solver``'s folder (``folder/pocket/<solver>``)."""
    mapping = tomllib.loads((REPOSITORY / "pyproject.toml").read_text())["tool"]["setuptools"]["package-dir"]
    for name in sorted(mapping, key=len):  # pocket before the folders it holds
        shutil.copytree(REPOSITORY / mapping[name], folder / name.replace(".", "/"),
                        ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    return folder / "pocket" / solver


def _files(folder: pathlib.Path) -> set:
    return {path.relative_to(folder) for path in folder.rglob("*")}


def _blocked(path: pathlib.Path) -> None:
    """Make ``path`` a file, so that no folder can be created there."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("not a folder")


def _read_only(folder: pathlib.Path) -> None:
    for path in [folder, *folder.rglob("*")]:
        path.chmod(path.stat().st_mode & ~(stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH))


def _environment(home, tmp, **extra):
    env = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME", "POCKET_CACHE_DIR")}
    env.update(HOME=str(home), TMPDIR=str(tmp), PYTHONDONTWRITEBYTECODE="1", **extra)
    return env


def _run(package, home, tmp, **extra):
    """Run the child of the solver copied to ``package`` (a ``_copy``) in a fresh process, that copy of pocket
    first on the path; returns (cache path, hits, misses, result)."""
    folder = package.parents[1]
    env = _environment(home, tmp, PYTHONPATH=str(folder), **extra)
    code = CHILDREN[package.name].format(package=f"pocket.{package.name}") + REPORT
    done = subprocess.run([sys.executable, "-c", code], env=env, cwd=folder,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _folders(tmp_path):
    home, tmp = tmp_path / "home", tmp_path / "tmp"
    home.mkdir()
    tmp.mkdir()
    return home, tmp


def _homeless(tmp_path):
    """A home folder whose cache folder (~/.cache) cannot be created, read-only besides; and a temp folder."""
    home, tmp = _folders(tmp_path)
    _blocked(home / ".cache")
    _read_only(home)
    return home, tmp


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_the_cache_is_in_the_users_cache_folder_and_nothing_is_written_into_the_package(tmp_path, solver):
    """Exact answer: the cache is ~/.cache/pocket-mechanics/<version>/..., the package's files are those
    copied (bytecode off: nothing of numba's), and a second process loads the kernel (hits, no miss) and
    computes the same numbers, bit for bit, as the compiled code did."""
    package = _copy(tmp_path / "site", solver)
    before = _files(package)
    home, tmp = _folders(tmp_path)
    first = _run(package, home, tmp)
    second = _run(package, home, tmp)
    assert first[0].startswith(str(home / ".cache" / "pocket-mechanics" / VERSION))
    assert first[2] >= 1
    assert second[0] == first[0]
    assert second[1] >= 1
    assert second[2] == 0
    assert second[3] == first[3]
    assert _files(package) == before


def test_the_cache_folder_can_be_chosen_by_environment(tmp_path):
    """Exact answer: with POCKET_CACHE_DIR set, the cache is there, in the version's subfolder."""
    package = _copy(tmp_path / "site", "shooting")
    home, tmp = _folders(tmp_path)
    chosen = tmp_path / "chosen"
    path = _run(package, home, tmp, POCKET_CACHE_DIR=str(chosen))[0]
    assert path.startswith(str(chosen / VERSION))


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_without_a_writable_cache_folder_the_cache_is_a_private_temp_folder(tmp_path, solver):
    """Exact answer: the package and the home are read-only, so the cache is <TMPDIR>/pocket-numba-<uid>,
    mode 0700, and a second process loads it and computes the same numbers, bit for bit."""
    package = _copy(tmp_path / "site", solver)
    _read_only(package.parents[1])
    home, tmp = _homeless(tmp_path)
    first = _run(package, home, tmp)
    private = tmp / f"pocket-numba-{os.getuid()}"
    assert first[0].startswith(str(private))
    assert first[2] >= 1
    assert stat.S_IMODE(private.stat().st_mode) == 0o700
    second = _run(package, home, tmp)
    assert second[1] >= 1
    assert second[2] == 0
    assert second[3] == first[3]


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_nowhere_to_cache_compiles_without_a_cache(tmp_path, solver):
    """Exact answer: with the home and the private temp folder unusable, the kernel still runs, uncached
    (no cache path, no hit; numba's own njit(cache=True) raised "no locator available" at import here)."""
    package = _copy(tmp_path / "site", solver)
    home, tmp = _homeless(tmp_path)
    _blocked(tmp / f"pocket-numba-{os.getuid()}")
    path, hits, _, result = _run(package, home, tmp)
    assert path is None
    assert hits == 0
    assert result


def test_a_damaged_entry_is_compiled_afresh(tmp_path):
    """Exact answer: with every data file of the cache overwritten by junk, the next process has a miss
    (compiles afresh) and computes the same numbers, bit for bit."""
    package = _copy(tmp_path / "site", "shooting")
    home, tmp = _folders(tmp_path)
    first = _run(package, home, tmp)
    damaged = list(pathlib.Path(first[0]).glob("*.nbc"))
    for path in damaged:
        path.write_bytes(b"junk")
    second = _run(package, home, tmp)
    assert damaged
    assert second[2] >= 1
    assert second[3] == first[3]


def test_a_cached_solve_loads_no_compiler_and_no_scipy_solvers(tmp_path):
    """Exact answer: with the cache warm, a whole compression in a fresh process imports neither
    scipy.optimize, scipy.integrate nor scipy.linalg (numba's compiler would import the last), and
    none of numba's typing registries (numba.np.arraymath is one)."""
    script = ("import sys; from pocket import shooting; shooting.compression_curve(0.3, 0.31, [0.1, 0.5]); "
              "print(' '.join(m for m in ('scipy.optimize', 'scipy.integrate', 'scipy.linalg', "
              "'numba.np.arraymath') if m in sys.modules))")
    env = _environment(*_folders(tmp_path))
    for _ in range(2):  # the first run compiles (a cold cache); the second loads
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=600, env=env)
        assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == ""


@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_editing_a_compiled_callee_makes_the_cache_stale(tmp_path, solver):
    """Exact answer: the second run of the same package loads the cached kernel (hits, 0 misses); after another
    file of its package is edited (``CALLEES``: shooting's tensions.py, which its kernel inlines; fem's loops.py,
    which inlines the kernel's laws; a comment: same code, other contents), the entry is stale and the kernel is
    compiled afresh (0 hits, a miss), where numba's own stamp (the kernel's file alone) would have loaded the old
    machine code."""
    package = _copy(tmp_path / "site", solver)
    home, tmp = _folders(tmp_path)
    _run(package, home, tmp)
    warm = _run(package, home, tmp)
    assert warm[1] >= 1
    assert warm[2] == 0
    with (package / CALLEES[solver]).open("a") as handle:
        handle.write("\n# an edit\n")
    edited = _run(package, home, tmp)
    assert edited[1] == 0
    assert edited[2] >= 1
    assert edited[3] == warm[3]


def _copy_repository(target: pathlib.Path) -> pathlib.Path:
    """The files a build of pocket reads, copied to ``target`` (the build writes beside its sources); not
    ``_version.py``, which an earlier build of the checkout wrote (it would lend the copy the checkout's commit)."""
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(REPOSITORY / name, target / name)
    for name in ("src", "shooting", "fem", "solid", "analytical", "meshes", "validation"):
        shutil.copytree(REPOSITORY / name, target / name,
                        ignore=shutil.ignore_patterns("__pycache__", "*.egg-info", "_version.py"))
    return target


def _without_pocket(packages: pathlib.Path, target: pathlib.Path) -> pathlib.Path:
    """A folder of links to the entries of the folder ``packages`` but pocket's own (a regular install of the
    test run's pocket there would otherwise stand before the new venv's, and be the one tested)."""
    target.mkdir()
    for entry in packages.iterdir() if packages.is_dir() else ():
        if not entry.name.lower().startswith(("pocket", "__editable__.pocket", "__editable___pocket")):
            (target / entry.name).symlink_to(entry)
    return target


def test_an_editable_install_over_an_uninstalled_regular_one_runs(tmp_path):
    """Exact answer: in a fresh virtual environment (the test's dependencies reached through a .pth file),
    pocket installed from a copy of the sources, run once (it compiles and caches), uninstalled and installed
    again in editable mode, answers ``pocket --version`` and prints the same compression, character for
    character. A cache written into site-packages used to survive the uninstall and shadow the editable
    install as a namespace package ("module 'pocket.shooting' has no attribute 'SOLVER'")."""
    source = tmp_path / "source"
    source.mkdir()
    _copy_repository(source)
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True, timeout=600)
    python = venv / "bin" / "python"
    purelib = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                             capture_output=True, text=True, check=True).stdout.strip()
    ours = [str(_without_pocket(pathlib.Path(folder), tmp_path / f"dependencies-{k}"))
            for k, folder in enumerate(dict.fromkeys([sysconfig.get_paths()["purelib"], *site.getsitepackages()]))]
    pathlib.Path(purelib, "dependencies.pth").write_text("\n".join(ours) + "\n")
    env = _environment(*_folders(tmp_path))
    pip = [sys.executable, "-m", "pip", "--python", str(python), "-q", "--disable-pip-version-check"]
    install = [*pip, "install", "--no-deps"]  # the build backend as a user gets it (build isolation)

    def run(*args):
        done = subprocess.run([*args], capture_output=True, text=True, env=env, cwd=tmp_path, timeout=600)
        assert done.returncode == 0, done.stdout + done.stderr
        return done.stdout

    solve = (str(venv / "bin" / "pocket"), "compress", "--alpha", "0.3", "--pressure", "0.31", "--force", "0.19",
             "--json")
    run(*install, str(source))
    regular = run(*solve)
    run(*pip, "uninstall", "-y", "pocket-mechanics")
    run(*install, "-e", str(source))
    assert run(str(venv / "bin" / "pocket"), "--version").strip() == f"pocket {FALLBACK} (commit unknown)"
    assert run(*solve) == regular
