"""A solver failure inside the validation suite says where: the case, the study, the mesh and the force.

Exact answer: the failure is forced (the solver replaced by one that raises), so the only
thing under test is the message the suite builds around it; the solver's own message and its
numbers are kept.
"""

import pytest
from pocket.fem import penalty
from pocket.validation import compute, convergence
from pocket.validation.plan import FEM_COLUMNS
from pocket.validation.suite import headline, load

from pocket import fem
from pocket.core.errors import ConvergenceError, exit_status

FAILURE = ConvergenceError("Newton failed after 1 iterations, residual 1.287e-04", iterations=1, residual=1.287e-4)


def _fail(*args, **kwargs):
    raise FAILURE


@pytest.fixture(scope="module")
def pocket():
    return headline(load()[0])


def test_a_convergence_sequence_names_case_study_mesh_and_force(pocket, monkeypatch):
    monkeypatch.setattr(fem, "compress", _fail, raising=False)
    with pytest.raises(ConvergenceError) as caught:
        convergence.sequence(pocket, "compression", 2, "uniform", (16, 32))
    message = str(caught.value)
    assert message.startswith(f"case {pocket.case.name!r}, convergence study (compression, FEM P2 on uniform meshes), "
                              f"uniform mesh of 16 elements, penalty contact, Fhat = {convergence.FORCE}: ")
    assert message.endswith(str(FAILURE))
    assert "\n" not in message
    assert (caught.value.iterations, caught.value.residual) == (1, 1.287e-4)
    assert exit_status(caught.value) == 1


def test_a_solver_column_names_case_column_mesh_and_forces(pocket, monkeypatch):
    monkeypatch.setattr(fem, "compression_curve", _fail, raising=False)
    column = FEM_COLUMNS[1]
    with pytest.raises(ConvergenceError) as caught:
        compute.column_curve(pocket, column, [0.0, 0.19, 1.0])
    message = str(caught.value)
    assert message.startswith(f"case {pocket.case.name!r}, {column.label} column, the default P2 mesh, fitted "
                              "contact, 3 forces Fhat = 0 to 1: ")
    assert message.endswith(str(FAILURE))


def test_a_penalty_curve_names_the_force_that_failed(monkeypatch):
    """The FE curve itself says which of its forces failed (the suite's message then holds it too)."""
    monkeypatch.setattr(penalty, "press_to_force", _fail)
    with pytest.raises(ConvergenceError, match=r"^compression at Fhat = 0\.19: Newton failed after 1 iterations"):
        fem.compression_curve(47 / 160, 0.31, [0.0, 0.19], elements=16, contact="penalty")
