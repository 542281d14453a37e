"""The consistent tangent is the derivative of the residual (fem/forms.py).

Exact answer: for a smooth residual R and its jacobian J, the Taylor remainder
|R(y + t d) - R(y) - t J d| falls as t^2. Checked at a deformed, compressed
state with the contact penalty active, under both plate controls, and for the
material hessian against central differences of its gradient.
"""

import numpy as np
import pytest
from pocket.fem import compression, inflation, model, post
from pocket.fem.material import MooneyRivlin
from pocket.fem.newton import Tolerances


@pytest.fixture(scope="module")
def pressed():
    """A P2 state at Phat_I = 0.31 pressed by a plate (penalty only, contact active)."""
    m = model.discretize(47 / 160, np.linspace(0.0, 1.0, 31), 2, 1e3)
    lam = m.zero_multiplier()
    y, _ = inflation.to_pressure(m, 0.31, lam, Tolerances())
    volume = post.volume(m, y)
    y, _ = compression.press_to_height(m, np.concatenate([y[:-1], [post.nodal(m, y)[2][0]]]),
                                       volume, 0.42, lam, Tolerances())
    return m, y, volume, lam


@pytest.mark.parametrize("control", ["height", "force"])
def test_taylor_remainder_is_second_order(pressed, control):
    """|R(y + t d) - R(y) - t J d| ~ t^2: fitted slope 2 (tolerance 0.1: a few
    quadrature points may cross the active-set kink of the penalty)."""
    m, y, volume, lam = pressed
    _, chi = model.plate_pressure(m, y, lam)
    assert chi.sum() > 10, "contact must be active for this test"
    ctrl = (model.Control(volume=volume, height=y[-1]) if control == "height"
            else model.Control(volume=volume, height=None, force=post.plate_force(m, y, lam)))
    r0, jac = model.residual(m, y, ctrl, lam), model.jacobian(m, y, ctrl, lam)
    r_grid = m.basis.doflocs[0][m.free]
    direction = np.concatenate([np.sin(3 * r_grid) * 1e-2, [1e-2, 1e-3]])  # smooth, all unknowns
    steps = np.logspace(-2, -5, 7)
    remainders = [np.abs(model.residual(m, y + t * direction, ctrl, lam) - r0 - t * (jac @ direction)).max()
                  for t in steps]
    slope = np.polyfit(np.log(steps), np.log(remainders), 1)[0]
    assert abs(slope - 2.0) < 0.1, f"observed Taylor order {slope:.3f}, remainders {remainders}"


def test_material_hessian_matches_gradient_differences():
    """d2w/dl1dl2 etc. equal central differences of the analytic gradient to O(eps^2)."""
    mat = MooneyRivlin(0.3)
    a, b, eps = np.array([1.3, 0.9]), np.array([1.1, 1.4]), 1e-6
    w11, w12, w22 = mat.hessian(a, b)
    ga_p, gb_p = mat.gradient(a + eps, b)
    ga_m, gb_m = mat.gradient(a - eps, b)
    np.testing.assert_allclose((ga_p - ga_m) / (2 * eps), w11, rtol=1e-8)
    np.testing.assert_allclose((gb_p - gb_m) / (2 * eps), w12, rtol=1e-8)
    ga_p, gb_p = mat.gradient(a, b + eps)
    ga_m, gb_m = mat.gradient(a, b - eps)
    np.testing.assert_allclose((gb_p - gb_m) / (2 * eps), w22, rtol=1e-8)
    wa = (mat.energy(a + eps, b) - mat.energy(a - eps, b)) / (2 * eps)
    np.testing.assert_allclose(wa, mat.gradient(a, b)[0], rtol=1e-8)


def test_tensions_are_the_papers_eq6():
    """T1 = 2 C1 T (l1/l2 - 1/(l1 l2)^3)(1 + alpha l2^2) / (E T), E = 6 (1 + alpha) C1 (eq (6))."""
    alpha, a, b = 0.29375, 1.2, 1.05
    t1, t2 = MooneyRivlin(alpha).tensions(a, b)
    scale = 2.0 / (6.0 * (1.0 + alpha))
    assert t1 == pytest.approx(scale * (a / b - 1 / (a * b) ** 3) * (1 + alpha * b**2), rel=1e-14)
    assert t2 == pytest.approx(scale * (b / a - 1 / (a * b) ** 3) * (1 + alpha * a**2), rel=1e-14)
