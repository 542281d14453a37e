"""Provenance: the versions a report records are the ones that ran."""

import subprocess
import sys

import numpy
import scipy

from pocket.apps.provenance import LIBRARIES, environment, version


def test_environment_names_the_libraries_that_ran():
    """Exact answer: each library's own __version__, read from the imported module."""
    env = environment()
    assert {"pocket", "python", "platform", "cpus", "date (UTC)", *LIBRARIES} <= set(env)
    assert env["numpy"] == numpy.__version__ and env["scipy"] == scipy.__version__
    assert env["python"] == sys.version.split()[0] and int(env["cpus"]) >= 1


def test_version_on_the_command_line():
    """Exact answer: `pocket --version` prints the installed distribution's version."""
    proc = subprocess.run([sys.executable, "-m", "pocket.cli", "--version"], capture_output=True, text=True)
    assert proc.returncode == 0 and proc.stdout.strip() == f"pocket {version()}"
