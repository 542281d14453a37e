"""Where a result came from: pocket's version and commit, and the libraries and machine it ran on.

A validation report or a results file is evidence only with this next to it:
the same numbers from another version of scipy or numba are another run.
"""

from __future__ import annotations

import datetime
import os
import pathlib
import platform
import subprocess
import sys
from importlib import metadata

__all__ = ["commit", "cpus", "described", "environment", "version"]

#: the name pocket is installed under (the import name is pocket)
DISTRIBUTION = "pocket-mechanics"

#: distributions whose versions change the numbers or the files
LIBRARIES = ("numpy", "scipy", "numba", "scikit-fem", "meshio", "matplotlib", "pint", "pyvista")


def version() -> str:
    """pocket's installed version (``0+unknown`` when run from a source tree not installed)."""
    try:
        return metadata.version(DISTRIBUTION)
    except metadata.PackageNotFoundError:
        return "0+unknown"


def commit() -> str:
    """The git commit pocket's sources are at (hexadecimal, ``+dirty`` after it when tracked files differ
    from it), or ``unknown``. Run from a git checkout (an editable install), git is asked, so the answer
    follows the checkout; otherwise it is the commit recorded when the package was built
    (``pocket._version``, written by setuptools-scm), unknown for a build from sources without git."""
    return _checkout_commit() or _built_commit() or "unknown"


def described() -> str:
    """pocket's version and commit (its first 12 digits) in one line, as ``pocket --version`` prints them."""
    full = commit()
    return f"{version()} (commit {full if full == 'unknown' else full[:12] + full[40:]})"


def _checkout_commit() -> str | None:
    """The commit of the git checkout pocket runs from, or None when pocket's files are not tracked in one."""
    source = pathlib.Path(__file__).resolve().parents[1]  # src/pocket (links resolved: an editable install)

    def git(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run(["git", "-C", str(source), *args], capture_output=True, text=True, timeout=10)

    try:
        if git("ls-files", "--error-unmatch", "__init__.py").returncode != 0:
            return None  # an installed copy (site-packages), perhaps inside some other repository
        head = git("rev-parse", "HEAD")
        dirty = git("status", "--porcelain", "--untracked-files=no")
    except (OSError, subprocess.SubprocessError):  # no git, or it hangs
        return None
    if head.returncode != 0 or dirty.returncode != 0:
        return None
    return head.stdout.strip() + ("+dirty" if dirty.stdout.strip() else "")


def _built_commit() -> str | None:
    """The commit setuptools-scm recorded at build time (its node, ``g<hash>``), or None."""
    try:
        from pocket import _version
    except ImportError:  # sources never built
        return None
    node = getattr(_version, "commit", "None")
    return node.removeprefix("g") if node not in ("None", "") else None


def cpus() -> int:
    """The CPUs this process may use (its affinity set where the OS has one)."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


def environment() -> dict[str, str]:
    """Name -> version or value: pocket, Python, each of ``LIBRARIES`` ("not installed" if
    absent), the platform, the usable CPUs and the UTC time of the call."""
    out = {"pocket": version(), "pocket commit": commit(), "python": sys.version.split()[0]}
    for name in LIBRARIES:
        try:
            out[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            out[name] = "not installed"
    out["platform"] = platform.platform()
    out["cpus"] = str(cpus())
    out["date (UTC)"] = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M:%S")
    return out
