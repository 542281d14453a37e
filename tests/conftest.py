"""Fixtures shared by the test files: every rubber law of the registry; the property tests' settings under CI.

``rubber`` is each registered law's example rubber (``pocket.core.materials.LAWS``, stresses in Pa), so that a
law added to the registry is checked by every test that takes it (its kernels in both solvers against
finite differences of its energy, its small-strain modulus, ...) without editing a test.

Under ``CI=true`` the property tests run derandomized (the same examples on every run, so a run cannot pass once
and fail the next) with no example database, and a failure prints the blob that reproduces it
(``@reproduce_failure``); elsewhere hypothesis draws afresh and its database (``.hypothesis/``) keeps a falsifying
example, which the next run tries first and prints.
"""

import os

import pytest
from hypothesis import settings

from pocket.core.materials import LAWS, check

if os.environ.get("CI", "").lower() in ("true", "1"):
    settings.register_profile("pocket-ci", derandomize=True, database=None, print_blob=True, deadline=None)
    settings.load_profile("pocket-ci")


@pytest.fixture(params=list(LAWS))
def rubber(request):
    """A registered law's example rubber, checked (a Material, stresses in Pa)."""
    law = LAWS[request.param]
    return check(law.name, dict(law.example))
