"""Where a result came from: pocket's version and the libraries and machine it ran on.

A validation report or a results file is evidence only with this next to it:
the same numbers from another version of scipy or numba are another run.
"""

from __future__ import annotations

import datetime
import os
import platform
import sys
from importlib import metadata

__all__ = ["version", "cpus", "environment"]

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


def cpus() -> int:
    """The CPUs this process may use (its affinity set where the OS has one)."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


def environment() -> dict[str, str]:
    """Name -> version or value: pocket, Python, each of ``LIBRARIES`` ("not installed" if
    absent), the platform, the usable CPUs and the UTC time of the call."""
    out = {"pocket": version(), "python": sys.version.split()[0]}
    for name in LIBRARIES:
        try:
            out[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            out[name] = "not installed"
    out["platform"] = platform.platform()
    out["cpus"] = str(cpus())
    out["date (UTC)"] = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M:%S")
    return out
