"""numba's on-disk cache never stops the solver (``pocket.shooting.compiled``).

Each case runs a copy of the solver package, under a name of its own, in a fresh
process: compiling the integrator there takes seconds, so these are slow tests.
Folders are made unwritable in a way that holds for root too (CI may run as root,
for whom permission bits do not stop writes): numba's cache locators create their
folder with os.makedirs, which fails where a file of that name is in the way.
"""

import os
import pathlib
import shutil
import stat
import subprocess
import sys

import pocket.shooting
import pytest

pytestmark = pytest.mark.slow

SOURCE = pathlib.Path(pocket.shooting.__file__).parent
CHILD = """
import {package}.integrator as integrator
from {package}.equations import pole_state
from {package}.laws import law_of
law = law_of(0.3)
status, r, y, _ = integrator.integrate(pole_state(1.1, law, 1.0, 1e-5), 1e-5, law, 1.0, rtol=1e-10)
stats = integrator._integrate.stats
print(status, r, stats.cache_path, sum(stats.cache_hits.values()), sum(stats.cache_misses.values()),
      ",".join(map(repr, y)))
"""


def _copy(folder: pathlib.Path, package: str) -> pathlib.Path:
    target = folder / package
    shutil.copytree(SOURCE, target, ignore=shutil.ignore_patterns("__pycache__"))
    return target


def _blocked(path: pathlib.Path) -> None:
    """Make ``path`` a file, so that no folder can be created there."""
    path.write_text("not a folder")


def _read_only(folder: pathlib.Path) -> None:
    for path in [folder, *folder.rglob("*")]:
        path.chmod(path.stat().st_mode & ~(stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH))


def _run(folder, package, home, tmp):
    """Run CHILD in a fresh process; returns (status, r_end, cache_path, hits, misses, y(1) as text)."""
    env = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME")}
    env.update(HOME=str(home), TMPDIR=str(tmp), PYTHONPATH=str(folder))
    done = subprocess.run([sys.executable, "-c", CHILD.format(package=package)], env=env, cwd=folder,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    status, r_end, path, hits, misses, y = done.stdout.split()
    return int(status), float(r_end), path, int(hits), int(misses), y


def _homeless(tmp_path):
    """A home folder whose cache folder (~/.cache) cannot be created, read-only besides."""
    home = tmp_path / "home"
    home.mkdir()
    _blocked(home / ".cache")
    _read_only(home)
    return home


def test_read_only_package_without_a_writable_home_caches_in_a_private_temp_folder(tmp_path):
    """Exact answer: the integrator runs (status 0 at r = 1); numba could not cache in the package or
    the home, so the cache is <TMPDIR>/pocket-numba-<uid>, mode 0700, and a second process loads it
    and computes the same numbers, bit for bit, as the compiled code did."""
    package = _copy(tmp_path / "site", "shooting_ro")
    _blocked(package / "__pycache__")
    _read_only(package.parent)
    home, tmp = _homeless(tmp_path), tmp_path / "tmp"
    tmp.mkdir()
    first = _run(package.parent, "shooting_ro", home, tmp)
    private = tmp / f"pocket-numba-{os.getuid()}"
    assert first[:2] == (0, 1.0) and first[2].startswith(str(private)) and first[4] == 1
    assert stat.S_IMODE(private.stat().st_mode) == 0o700
    second = _run(package.parent, "shooting_ro", home, tmp)
    assert second[:2] == (0, 1.0) and (second[3], second[4]) == (1, 0) and second[5] == first[5]


def test_nowhere_to_cache_compiles_without_a_cache(tmp_path):
    """Exact answer: with the package, the home and the private temp folder all unusable, the
    integrator still runs, uncached (numba's own njit(cache=True) raises at import here)."""
    package = _copy(tmp_path / "site", "shooting_nowhere")
    _blocked(package / "__pycache__")
    home, tmp = _homeless(tmp_path), tmp_path / "tmp"
    tmp.mkdir()
    _blocked(tmp / f"pocket-numba-{os.getuid()}")
    status, r_end, path, hits, misses, _ = _run(package.parent, "shooting_nowhere", home, tmp)
    assert (status, r_end, hits) == (0, 1.0, 0) and not path.startswith(str(tmp_path))


def test_a_cache_left_by_a_module_that_moved_is_recompiled(tmp_path):
    """Exact answer: the same files under another package name find the old cache entry (numba keys
    it by file name and contents), whose pickled data names the old module; numba's own cache then
    raises ModuleNotFoundError at the first call. Here the entry is a miss: compiled afresh."""
    site, home, tmp = tmp_path / "site", _homeless(tmp_path), tmp_path / "tmp"
    tmp.mkdir()
    package = _copy(site, "shooting_before")
    first = _run(site, "shooting_before", home, tmp)
    assert first[:2] == (0, 1.0) and first[2] == str(package / "__pycache__")
    package.rename(site / "shooting_after")
    second = _run(site, "shooting_after", home, tmp)
    assert second[:2] == (0, 1.0) and second[4] == 1


def test_a_cached_solve_loads_no_compiler_and_no_scipy_solvers(tmp_path):
    """Exact answer: with the cache warm, a whole compression in a fresh process imports neither
    scipy.optimize, scipy.integrate nor scipy.linalg (numba's compiler would import the last), and
    none of numba's typing registries (numba.np.arraymath is one)."""
    script = ("import sys; from pocket import shooting; shooting.compression_curve(0.3, 0.31, [0.1, 0.5]); "
              "print(' '.join(m for m in ('scipy.optimize', 'scipy.integrate', 'scipy.linalg', "
              "'numba.np.arraymath') if m in sys.modules))")
    for _ in range(2):  # the first run may compile (a cold cache); the second loads
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == ""


def test_editing_a_compiled_callee_makes_the_cache_stale(tmp_path):
    """Exact answer: the second run of the same package loads the cached integrator (1 hit, 0 misses);
    after tensions.py, which the integrator inlines, is edited (a comment: same code, another size and
    time), the entry is stale and the integrator is compiled afresh (0 hits, 1 miss), where numba's own
    stamp (the integrator's file alone) would have loaded the old machine code."""
    site, home, tmp = tmp_path / "site", _homeless(tmp_path), tmp_path / "tmp"
    tmp.mkdir()
    package = _copy(site, "shooting_edited")
    _run(site, "shooting_edited", home, tmp)
    warm = _run(site, "shooting_edited", home, tmp)
    assert (warm[3], warm[4]) == (1, 0)
    with (package / "tensions.py").open("a") as handle:
        handle.write("\n# an edit\n")
    edited = _run(site, "shooting_edited", home, tmp)
    assert (edited[3], edited[4]) == (0, 1) and edited[5] == warm[5]
