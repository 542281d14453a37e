"""Fixtures shared by the test files: every rubber law of the registry.

``rubber`` is each registered law's example rubber (``pocket.core.materials.LAWS``, stresses in Pa), so that a
law added to the registry is checked by every test that takes it (its kernels in both solvers against
finite differences of its energy, its small-strain modulus, ...) without editing a test.
"""

import pytest

from pocket.core.materials import LAWS, check


@pytest.fixture(params=list(LAWS))
def rubber(request):
    """A registered law's example rubber, checked (a Material, stresses in Pa)."""
    law = LAWS[request.param]
    return check(law.name, dict(law.example))
