"""The shooting solver's capsule against an independent reference written here from the theory alone.

The reference shares no code with the solver: its tensions are the Mooney-Rivlin membrane's closed form (the paper's
eq (6), in units of E T) with their derivatives by complex steps; its equations are integrated by scipy's DOP853; and
it is posed the other way round: the free part is shot BACKWARDS from the equator (rho_eq, lambda_1 at the equator,
psi = pi/2, eta = 0) to the contact edge, the contact zone forwards from the pole's series, and the two are matched
at the edge (rho and lambda_1 continuous, psi = 0 there), with F = P pi rho_c^2 and the fluid's volume: five unknowns
(rho_eq, lambda_1 at the equator, lambda_0, a_c, Phat), five conditions, solved by scipy's fsolve. Shot from the
equator, the dent's growing mode decays, so this reference is also better conditioned at small Phat_I.
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from pocket import shooting
from pocket.core.fluids import gas

pytestmark = pytest.mark.slow


def _t1(l1, l2, alpha):
    """T_1 / (E T) of a Mooney-Rivlin membrane: (l1/l2 - 1/(l1 l2)^3)(1 + alpha l2^2) / (3 (1 + alpha))."""
    return (l1 / l2 - 1.0 / (l1 * l2) ** 3) * (1.0 + alpha * l2 * l2) / (3.0 * (1.0 + alpha))


def _tensions(l1, l2, alpha):
    """(T_1, T_2, dT_1/dl1, dT_1/dl2), the derivatives by complex steps (exact to rounding)."""
    h = 1e-30
    return (_t1(l1, l2, alpha), _t1(l2, l1, alpha), _t1(l1 + 1j * h, l2, alpha).imag / h,
            _t1(l1, l2 + 1j * h, alpha).imag / h)


def _free(arc, y, alpha, pressure):
    """d/dS of (rho, eta, psi, lambda_1, v) on the sphere S in (0, pi/2], r0 = sin S."""
    rho, _, psi, l1, _ = y
    l2 = rho / math.sin(arc)
    t1, t2, a, b = _tensions(l1, l2, alpha)
    drho = l1 * math.cos(psi)
    dl2 = (drho - l2 * math.cos(arc)) / math.sin(arc)
    return [drho, -l1 * math.sin(psi), l1 * (pressure - t2 * math.sin(psi) / rho) / t1,
            ((t2 - t1) * drho / rho - b * dl2) / a, math.pi * rho * rho * l1 * math.sin(psi)]


def _zone(arc, y, alpha):
    """d/dS of (rho, lambda_1) flat on the plate."""
    rho, l1 = y
    l2 = rho / math.sin(arc)
    t1, t2, a, b = _tensions(l1, l2, alpha)
    dl2 = (l1 - l2 * math.cos(arc)) / math.sin(arc)
    return [l1, ((t2 - t1) * l1 / rho - b * dl2) / a]


START = 1e-4  # the contact zone's series start: its error O(S^4)
TOL = {"rtol": 1e-12, "atol": 1e-14, "method": "DOP853"}


def _residuals(z, alpha, force_etr, volume, ratio):
    rho_eq, l1_eq, l0, a, phat = z
    _, _, a_, b_ = _tensions(l0, l0, alpha)
    c1, c2 = l0 * (a_ - 3 * b_) / (16 * a_), l0 * (3 * a_ - b_) / (16 * a_)
    zone = solve_ivp(_zone, (START, a), [(l0 + c2 * START**2) * math.sin(START), l0 + c1 * START**2],
                     args=(alpha,), **TOL)
    free = solve_ivp(_free, (math.pi / 2, a), [rho_eq, 0.0, math.pi / 2, l1_eq, 0.0], args=(alpha, phat), **TOL)
    rho_c, l1_c = zone.y[:, -1]
    rho_b, height, psi, l1_b, v = free.y[:, -1]
    return np.array([psi, rho_b - rho_c, l1_b - l1_c, phat * math.pi * rho_c**2 - force_etr,
                     -2.0 * v / volume - ratio(phat)]), height


@pytest.mark.parametrize(("alpha", "phat_i", "fluid"), [(0.0, 0.1, None), (47 / 160, 0.25, None),
                                                        (0.1, 0.35, gas(5.0, 1.4)), (0.3, 0.15, None)])
def test_shooting_agrees_with_the_backward_reference(alpha, phat_i, fluid):
    """Two independent solutions of the same problem agree to 1e-9 in every key the states report."""
    forces = [0.02, 0.3, 1.0, 2.0]
    states = shooting.compression_curve(alpha, phat_i, forces, fluid=fluid, geometry="capsule")
    lam = states[0].inflated.stretch_pole
    volume = 4.0 * math.pi * lam**3 / 3.0
    closed = 2.0 * (1.0 - lam**-6) * (1.0 + alpha * lam**2) / (3.0 * (1.0 + alpha) * lam)
    assert closed == pytest.approx(phat_i, rel=1e-12)  # the inflated sphere: Laplace

    def ratio(phat):
        return 1.0 if fluid is None else fluid.volume_ratio(phat, phat_i)

    for force, state in zip(forces, states, strict=True):
        guess = np.array([state.extra["radius_equator"], state.profile.stretch_1[-1], state.extra["stretch_pole"],
                          state.contact_radius, state.pressure]) * (1.0 + 1e-6)
        # started 1e-6 off the solver's state: at small forces both formulations are ill-conditioned (the dent's
        # modes grow one way or the other), so fsolve needs a start near the root; it converges to its own
        load = math.pi * force * phat_i
        z = fsolve(lambda v, load=load: _residuals(v, alpha, load, volume, ratio)[0], guess, xtol=1e-13)
        residual, height = _residuals(z, alpha, math.pi * force * phat_i, volume, ratio)
        assert np.max(np.abs(residual)) < 1e-10, residual  # solved (fsolve may stop at rounding with a warning)
        rho_eq, _, l0, a, phat = z
        rho_c = math.sqrt(math.pi * force * phat_i / (math.pi * phat))
        reference = {"pressure_ratio": phat / phat_i, "height": height, "contact_area": rho_c**2,
                     "contact_radius": a, "contact_radius_deformed": rho_c}
        for key, value in reference.items():
            assert getattr(state, key) == pytest.approx(value, rel=1e-9), key
        assert state.extra["stretch_pole"] == pytest.approx(l0, rel=1e-9)
        assert state.extra["radius_equator"] == pytest.approx(rho_eq, rel=1e-9)
        assert state.volume == pytest.approx(volume * ratio(phat), rel=1e-9)
