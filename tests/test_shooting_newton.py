"""The shooting solver's small nonlinear solver (``pocket.shooting.newton``) against scipy's MINPACK hybrid
method (``root(method="hybr")``) on standard hard problems (Moré, Garbow & Hillstrom, ACM TOMS 7, 1981)."""

import math

import numpy as np
import pytest
from pocket.shooting import newton
from scipy.optimize import root


def rosenbrock(x):
    return np.array([10 * (x[1] - x[0] ** 2), 1 - x[0]])


def powell_badly_scaled(x):
    return np.array([1e4 * x[0] * x[1] - 1, math.exp(-x[0]) + math.exp(-x[1]) - 1.0001])


def helical_valley(x):
    theta = math.atan2(x[1], x[0]) / (2 * math.pi)
    return np.array([10 * (x[2] - 10 * theta), 10 * (math.hypot(x[0], x[1]) - 1), x[2]])


def freudenstein_roth(x):
    return np.array([-13 + x[0] + ((5 - x[1]) * x[1] - 2) * x[1], -29 + x[0] + ((x[1] + 1) * x[1] - 14) * x[1]])


@pytest.mark.parametrize(("fun", "x0"), [(rosenbrock, [-1.2, 1.0]), (powell_badly_scaled, [1e-5, 8.0]),
                                     (helical_valley, [-1.0, 0.0, 0.0]), (freudenstein_roth, [6.0, 3.0])])
def test_solves_what_hybr_solves(fun, x0):
    """Exact answer: the root hybr finds (to its accuracy, 1e-10 relative), with max |f| <= 1e-12."""
    ours = newton.solve(fun, x0, tol=1e-12)
    ref = root(fun, x0, method="hybr", options=dict(xtol=1e-14))
    assert ref.success, (ours.message, ref.message)
    assert ours.success, (ours.message, ref.message)
    np.testing.assert_allclose(ours.x, ref.x, rtol=1e-9, atol=1e-12)
    assert ours.residual <= 1e-12


def test_badly_scaled_from_afar_is_reported_unsolved():
    """Exact answer: hybr solves Powell's badly scaled function from (0, 1) (a trust region with
    scaling); a line-search Newton crawls along its curved valley (a known limit: the shooting
    residuals are scaled to order one, and continuation starts each solve close). It must say so."""
    ref = root(powell_badly_scaled, [0.0, 1.0], method="hybr")
    ours = newton.solve(powell_badly_scaled, [0.0, 1.0], tol=1e-12)
    assert ref.success
    assert not ours.success
    assert ours.residual > 1e-12


def test_a_local_minimum_of_the_residual_is_a_failure_not_an_answer():
    """Exact answer: from (0.5, -2) Freudenstein-Roth leads Newton methods to its spurious minimum
    near (11.41, -0.897), where f != 0: hybr reports no progress; so must we, with success False."""
    ours = newton.solve(freudenstein_roth, [0.5, -2.0], tol=1e-12)
    ref = root(freudenstein_roth, [0.5, -2.0], method="hybr")
    assert not ref.success
    assert not ours.success
    assert ours.residual > 1.0
    assert "residual" in ours.message


def test_steps_into_an_undefined_region_are_cut():
    """Exact answer: x = (e^-2, 1) for f = (log x_0 + 2, x_1 - 1); from x_0 = 3 the full Newton step lands at
    x_0 < 0, where f is undefined (None): the line search halves it back into the domain."""
    def fun(x):
        return None if x[0] <= 0 else np.array([math.log(x[0]) + 2, x[1] - 1])

    sol = newton.solve(fun, [3.0, 5.0], tol=1e-14)
    assert sol.success
    np.testing.assert_allclose(sol.x, [math.exp(-2), 1.0], rtol=1e-13)


def test_a_given_jacobian_is_used_and_returned_updated():
    """Exact answer: for a linear system f = A x - b, Broyden's update keeps an exact Jacobian exact:
    one step, no difference quotients (2 evaluations: the start and the step)."""
    a, b = np.array([[3.0, 1.0], [1.0, 2.0]]), np.array([9.0, 8.0])
    sol = newton.solve(lambda x: a @ x - b, [0.0, 0.0], tol=1e-12, jacobian=a)
    assert sol.success
    assert sol.evaluations == 2
    np.testing.assert_allclose(sol.x, np.linalg.solve(a, b), rtol=1e-14)
    np.testing.assert_allclose(sol.jacobian, a, rtol=1e-14)


def test_a_given_derivative_replaces_the_differences():
    """Exact answer: on f = A x - b a ``derivative`` giving A is the Jacobian each fresh start takes: one step, no
    difference quotients (2 evaluations); where it gives None the differences are taken (2 more evaluations, and
    their Jacobian, inexact, may take a step more)."""
    a, b = np.array([[3.0, 1.0], [1.0, 2.0]]), np.array([9.0, 8.0])
    calls = []
    sol = newton.solve(lambda x: a @ x - b, [0.0, 0.0], tol=1e-12, derivative=lambda x, f: calls.append(f) or a)
    assert sol.success
    assert (sol.evaluations, len(calls)) == (2, 1)
    np.testing.assert_allclose(calls[0], -b)  # the residual at the start
    np.testing.assert_allclose(sol.x, np.linalg.solve(a, b), rtol=1e-14)
    none = newton.solve(lambda x: a @ x - b, [0.0, 0.0], tol=1e-12, derivative=lambda x, f: None)
    assert none.success
    assert none.evaluations >= 4


def test_start_outside_the_domain():
    sol = newton.solve(lambda x: None, [1.0, 1.0], tol=1e-12)
    assert not sol.success
    assert sol.residual == math.inf
    assert "outside" in sol.message
