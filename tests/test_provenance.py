"""Provenance: the versions a report records are the ones that ran."""

import pathlib
import shutil
import subprocess
import sys

import numpy
import scipy

import pocket
from pocket.apps.provenance import LIBRARIES, commit, described, environment, version


def test_environment_names_the_libraries_that_ran():
    """Exact answer: each library's own __version__, read from the imported module."""
    env = environment()
    assert {"pocket", "pocket commit", "python", "platform", "cpus", "date (UTC)", *LIBRARIES} <= set(env)
    assert env["numpy"] == numpy.__version__
    assert env["scipy"] == scipy.__version__
    assert env["python"] == sys.version.split()[0]
    assert int(env["cpus"]) >= 1


def test_version_on_the_command_line():
    """Exact answer: `pocket --version` prints the installed distribution's version and the first 12 digits
    of pocket's commit (with +dirty if so)."""
    proc = subprocess.run([sys.executable, "-m", "pocket.cli", "--version"], capture_output=True, text=True)
    short = commit()[:12] + commit()[40:]
    assert proc.returncode == 0
    assert proc.stdout.strip() == f"pocket {version()} (commit {short})"
    assert proc.stdout.strip() == f"pocket {described()}"


def _git(*args: str) -> str:
    return subprocess.run(["git", "-C", str(pathlib.Path(pocket.__file__).resolve().parent), *args],
                          capture_output=True, text=True).stdout.strip()


def test_the_commit_is_the_checkouts_or_the_one_built():
    """Exact answer: run from a git checkout (pocket's files tracked there), the commit is git's HEAD,
    followed by +dirty exactly when tracked files differ from it; run from an installed copy, the commit
    setuptools-scm wrote into pocket._version when it built pocket (its node g<hash>, the g removed)."""
    if _git("ls-files", "--error-unmatch", "__init__.py"):
        dirty = "+dirty" if _git("status", "--porcelain", "--untracked-files=no") else ""
        assert commit() == _git("rev-parse", "HEAD") + dirty
    else:
        from pocket import _version
        assert commit() == _version.commit.removeprefix("g")
    assert len(commit().removesuffix("+dirty")) == 40 or shutil.which("git") is None
