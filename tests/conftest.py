"""Fixtures shared by the test files: every rubber law of the registry; the property tests' settings under CI.

``rubber`` is each registered law's example rubber (``pocket.core.materials.LAWS``, stresses in Pa), so that a
law added to the registry is checked by every test that takes it (its kernels in both solvers against
finite differences of its energy, its small-strain modulus, ...) without editing a test.

Under ``CI=true`` the property tests run derandomized (the same examples on every run, so a run cannot pass once
and fail the next) with no example database, and a failure prints the blob that reproduces it
(``@reproduce_failure``); elsewhere hypothesis draws afresh and its database (``.hypothesis/``) keeps a falsifying
example, which the next run tries first and prints.

The solvers' compiled kernels are cached on disk (``pocket.core.compiled``), and a fresh installation compiles
them once, in seconds: on a run over two pytest-xdist workers, each worker first compiles one solver's kernels
(``WARM``) and later loads the other's from the cache, where both would compile both.
"""

import contextlib
import importlib
import os

import pytest
from hypothesis import settings

from pocket.core.indenters import Sphere
from pocket.core.materials import LAWS, check

#: pytest-xdist worker -> the solver whose kernels it compiles before it collects (the plate's and the sphere's)
WARM = {"gw0": "shooting", "gw1": "fem"}

if os.environ.get("CI", "").lower() in ("true", "1"):
    settings.register_profile("pocket-ci", derandomize=True, database=None, print_blob=True, deadline=None)
    settings.load_profile("pocket-ci")


def pytest_configure(config):
    """On a worker named in ``WARM``, compile its solver's kernels into the cache before the tests start."""
    solver = WARM.get(os.environ.get("PYTEST_XDIST_WORKER", ""))
    if solver is None:
        return
    module = importlib.import_module(f"pocket.{solver}")
    # a warm-up only: a solver that fails here fails the tests that solve, with their names
    with contextlib.suppress(Exception):
        module.compress(0.3, 0.3, 0.5)
        module.compress(0.3, 0.3, 0.5, indenter=Sphere(0.5))


@pytest.fixture(params=list(LAWS))
def rubber(request):
    """A registered law's example rubber, checked (a Material, stresses in Pa)."""
    law = LAWS[request.param]
    return check(law.name, dict(law.example))
