"""Newton on the bordered system converges like Newton; load stepping cuts steps and says where.

Exact answers: quadratic convergence, ||R_{k+1}|| <= C ||R_k||^2 with a bounded C,
seen in the residual sequence of a compressed state solved from the predictor
of the previous states (a liquid, and a gas whose volume row V/V_I - q(P)
couples the pressure to the volume); the load stepping's bookkeeping on a solver that fails
beyond a known load; an out-of-model Newton iterate is a cut step, not an answer.
"""

import itertools
from dataclasses import replace

import numpy as np
import pytest
from pocket.fem import curves, fitted, inflation, model, steps
from pocket.fem.api import default_mesh
from pocket.fem.continuation import follow
from pocket.fem.gas import sealed
from pocket.fem.newton import Tolerances, newton

from pocket.core.errors import ConvergenceError, OutOfRangeError
from pocket.core.fluids import gas

ALPHA, PHAT = 47 / 160, 0.31


@pytest.fixture(scope="module", params=["liquid", "gas"])
def path(request):
    """Converged edge-fitted states at F = 0.2, 0.3, 0.4 (units E T R), 64 P2 elements, with a liquid or
    a gas at Phat_atm = 0.2, gamma = 1.4 (its pressure rises about half as much as the liquid's)."""
    m = model.discretize(ALPHA, default_mesh(64), 2, 1e5)
    tol = Tolerances(1e-13, 1e-13)
    y_i, _ = inflation.to_pressure(m, PHAT, tol)
    fill = model.Control(volume=inflation.volume(m, y_i),
                         gas=sealed(gas(0.2, 1.4), PHAT) if request.param == "gas" else None)
    y, _ = fitted.first_contact(m, y_i, fill, 0.05, tol)
    out = []
    for force in (0.2, 0.3, 0.4):
        y, _ = fitted.force_path(m, y, fill, force, tol)
        out.append((np.sqrt(force), y))
    return m, fill, out


@pytest.mark.parametrize(("target", "previous"), [(0.5, 3), (0.7, 3), (0.5, 1)])
def test_residuals_fall_quadratically(path, target, previous):
    """From the extrapolation of the last ``previous`` states (one: the last state itself), the
    residual sequence satisfies r_{k+1} <= C r_k^2 with C < 1e3 for every step that ends above
    the round-off floor (measured 2e-12 to 1.3e-11 in the nodal rows by the contact edge, liquid and gas:
    5e-11), and converges in at most 6 iterations to below 2e-11."""
    m, fill, states = path
    control = replace(fill, force=target, scale=target)
    guess = curves.predict(states[-previous:], np.sqrt(target))
    result = newton(lambda z: model.linearize(m, z, model.FITTED, control), guess, Tolerances(1e-13, 1e-13),
                    steps.increment(m, model.FITTED))
    r = np.array(result.residuals)
    assert result.iterations <= 6, f"{result.iterations} iterations, residuals {r}"
    ratios = [b / a**2 for a, b in itertools.pairwise(r) if b > 5e-11]
    assert ratios, f"r_(k+1)/r_k^2 = {ratios}, residuals {r}"
    assert max(ratios) < 1e3, f"r_(k+1)/r_k^2 = {ratios}, residuals {r}"
    assert r[-1] < 2e-11, f"residuals {r}"


def test_predictor_order(path):
    """Extrapolating the fitted states in sigma = sqrt(F) from equally spaced sigma_0 + k d (k = 0, 1,
    2) to sigma_0 + 3 d misses the solution there by O(d^2) linearly (through two states) and O(d^3)
    quadratically (through three): halving d divides the misses by 4 and 8 (observed orders within 0.3)."""
    m, fill, states = path
    tol = Tolerances(1e-13, 1e-13)

    def at(sigma, guess):
        return steps.solve(m, model.FITTED, replace(fill, force=sigma**2), guess, tol)[0]

    sigma0, y0 = states[1]
    misses = []
    for d in (0.04, 0.02):
        known = [(sigma0 + k * d, at(sigma0 + k * d, y0)) for k in range(3)]
        exact = at(sigma0 + 3 * d, y0)
        misses.append([np.abs(curves.predict(known[-2:], sigma0 + 3 * d) - exact).max(),
                       np.abs(curves.predict(known, sigma0 + 3 * d) - exact).max()])
    orders = np.log2(np.array(misses[0]) / np.array(misses[1]))
    assert abs(orders[0] - 2) < 0.3, f"orders {orders}, misses {misses}"
    assert abs(orders[1] - 3) < 0.3, f"orders {orders}, misses {misses}"


def test_load_stepping_cuts_steps_then_says_where():
    """A solve that fails beyond load 0.3: the stepping halves its step until it is below
    min_step, then raises ConvergenceError with the load reached (just under 0.3), the
    iterations and the residual of the last failure."""
    tried = []

    def solve(load, guess):
        tried.append(load)
        if load > 0.3:
            raise ConvergenceError("no", iterations=7, residual=1.5)
        return guess, 2

    with pytest.raises(ConvergenceError) as info:
        list(follow(solve, np.zeros(3), 0.0, 1.0, first_step=0.25, min_step=1e-3))
    err = info.value
    assert 0.29 < err.load <= 0.3
    assert err.iterations == 7
    assert err.residual == 1.5
    assert "gave up at load =" in str(err)
    assert "\n" not in str(err)
    assert min(t for t in tried if t > 0.3) - err.load < 2e-3  # the step was cut down


def test_an_overshooting_step_is_cut_not_reported():
    """Solves whose long steps land outside the model (OutOfRangeError when the step from the
    last converged load exceeds 0.3) while every load up to the target 1 is inside: the stepping
    cuts the steps and reaches the target."""
    last = [0.0]

    def solve(load, guess):
        if load - last[0] > 0.3:
            raise OutOfRangeError("overshot")
        last[0] = load
        return guess, 3

    loads = [load for load, _, _ in follow(solve, np.zeros(2), 0.0, 1.0, first_step=1.0)]
    assert loads[-1] == 1.0
    assert all(b - a <= 0.3 for a, b in zip([0.0, *loads[:-1]], loads, strict=True))


def test_a_target_outside_the_model_is_reported():
    """Every load above 0.6 is outside the model: a target of 1 is OutOfRangeError, not a ConvergenceError."""

    def solve(load, guess):
        if load > 0.6:
            raise OutOfRangeError("outside")
        return guess, 3

    with pytest.raises(OutOfRangeError, match="outside"):
        list(follow(solve, np.zeros(2), 0.0, 1.0))


class _Dense:
    """A dense Newton system with one 'scalar' unknown, in the interface Newton uses."""

    def __init__(self, jacobian):
        self.jacobian, self.B = jacobian, np.zeros((jacobian.shape[0] - 1, 1))

    def solve(self, r, s):
        z = np.linalg.solve(self.jacobian, np.concatenate([r, s]))
        return z[:-1], z[-1:]


_STIFF = np.array([[2.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 4.0]])
_ROOT = np.array([0.3, 0.7, 1.1])


def _join(y, x, s):
    return np.concatenate([x, s])


def test_a_stiff_residual_converges_at_its_round_off_floor():
    """R(y) = k (S y + y^3 - b) with k = 1e12 and b = S y* + y*^3: the terms of R are ~1e12, so no stored y
    gets |R| below about k eps ~ 1e-4, far above the absolute tolerance 1e-10 and its 1e3 floor; once the
    increment has converged, the residual is at the change that a few units in the last place of y make,
    and Newton accepts it: y* to 1e-15."""
    k = 1e12
    b = _STIFF @ _ROOT + _ROOT**3

    def linearize(y):
        return k * (_STIFF @ y + y**3 - b), _Dense(k * (_STIFF + np.diag(3 * y**2)))

    result = newton(linearize, np.array([0.5, 0.5, 0.5]), Tolerances(), _join)
    np.testing.assert_allclose(result.y, _ROOT, rtol=1e-15)
    assert result.residuals[-1] > 1e3 * Tolerances().residual, result.residuals


def test_a_small_increment_with_a_large_residual_is_not_convergence():
    """A jacobian 1e8 times too stiff makes tiny increments (1e-11) from a residual of 1e-3 that no
    round-off explains: Newton does not stop there, and fails (ConvergenceError) rather than return it."""

    def linearize(y):
        return _STIFF @ (y - _ROOT), _Dense(1e8 * _STIFF)

    with pytest.raises(ConvergenceError):
        newton(linearize, _ROOT + 1e-3, Tolerances(), _join)
