"""A new indenter is a class and one entry in a solver's table: a cone with a rounded (spherical) tip, defined here
with its own height, slope, second derivative and reach, is registered, added to a solver's ``CONTACTS`` as that
solver poses a profile, and compressed, with no edit to the solver.

Independent answers: while the contact stays on the tip the cone is the sphere of the tip's radius, so its
states are that sphere's to the solver's tolerance; once the contact reaches the cone's flank, the contact
pressure at each node is P + kappa_1 T_1 + kappa_2 T_2 with the curvatures written here from the geometry
(1/R_t both on the tip; 0 and sin(beta)/rho on the flank), and the force balances the cap as a free body and the
solver's reaction.
"""

import dataclasses
import math

import numpy as np
import pytest
from pocket.fem import api as fem_api
from pocket.shooting import problem as shooting_problem

from pocket import fem, shooting
from pocket.core.indenters import INDENTERS, Indenter, Profile, Sphere, register

ALPHA, PRESSURE = 47 / 160, 0.31
#: the flank's angle beta above the horizontal: the flank starts at rho_t = R_t sin(beta); a tip as large as the
#: sphere of test_fem_sphere (the contact stays on it at Fhat = 0.19) and one small enough that the contact passes
#: onto the flank at Fhat = 1
ANGLE, LARGE_TIP, SMALL_TIP = math.radians(30.0), 1.0, 0.4


@dataclasses.dataclass(frozen=True)
class RoundedCone(Indenter):
    """A cone of half-angle 90 deg - ``angle`` (its flank rising at ``angle`` above the horizontal) whose tip is a
    sphere of radius ``tip`` (units R), tangent to the flank at rho_t = tip sin(angle), drawn out to rho = 1.5."""

    tip: float
    angle: float
    name = "rounded-cone"
    summary = "a cone with a spherical tip"

    @property
    def joint(self) -> float:
        """rho_t, where the tip meets the flank (units R)."""
        return self.tip * math.sin(self.angle)

    def height(self, rho):
        rho = np.asarray(rho, dtype=float)
        on_tip = rho <= self.joint
        cap = self.tip - np.sqrt(np.maximum(self.tip**2 - rho**2, 0.0))
        flank = self.tip * (1.0 - math.cos(self.angle)) + math.tan(self.angle) * (rho - self.joint)
        return np.where(rho <= self.reach, np.where(on_tip, cap, flank), np.nan)

    def slope(self, rho):
        rho = np.asarray(rho, dtype=float)
        on_tip = rho <= self.joint
        cap = rho / np.sqrt(np.maximum(self.tip**2 - np.minimum(rho, self.joint) ** 2, 0.0))
        return np.where(rho <= self.reach, np.where(on_tip, cap, math.tan(self.angle)), np.nan)

    def second(self, rho):
        rho = np.asarray(rho, dtype=float)
        on_tip = rho <= self.joint
        cap = self.tip**2 / (self.tip**2 - np.minimum(rho, self.joint) ** 2) ** 1.5
        return np.where(rho <= self.reach, np.where(on_tip, cap, 0.0), np.nan)

    @property
    def reach(self) -> float:
        return 1.5

    @property
    def knots(self) -> tuple[float, ...]:
        return (self.joint,)


@pytest.fixture
def registered():
    """The rounded cone's class, registered for one test."""
    register(RoundedCone)
    yield RoundedCone
    del INDENTERS[RoundedCone.name]


#: each solver and its table of contact formulations, in which the cone is posed as that solver poses a profile
SOLVERS = [
    pytest.param(fem, fem_api.CONTACTS, id="fem"),
    pytest.param(shooting, shooting_problem.CONTACTS, id="shooting"),
]


def test_the_rounded_cone_is_tangent_continuous_and_its_slope_that_of_its_height(registered):
    """Exact answers to the finite differences' error (central, step 1e-6: h^2 z'''/6 < 1e-10 here, rounding
    eps z / h < 1e-9): the slope is that of the height on both sides of the joint, and the flank leaves the tip
    tangent to it, z'(rho_t) = tan(beta), at the tip's height there R_t (1 - cos(beta))."""
    cone = registered(LARGE_TIP, ANGLE)
    rho, h = np.array([0.0, 0.2, cone.joint - 0.01, cone.joint + 0.01, 1.0]), 1e-6
    numeric = (cone.height(rho + h) - cone.height(np.abs(rho - h))) / (2 * h)
    assert np.allclose(cone.slope(rho), numeric, rtol=1e-8, atol=1e-9)
    tip = Sphere(LARGE_TIP)
    assert cone.slope(cone.joint) == pytest.approx(math.tan(ANGLE), rel=1e-14)
    assert cone.height(cone.joint) == pytest.approx(tip.height(cone.joint), rel=1e-14)
    assert np.allclose(cone.curvature(rho[:3]), 1.0 / LARGE_TIP, rtol=1e-12)
    assert np.all(cone.curvature(rho[3:]) == 0.0)
    assert INDENTERS["rounded-cone"] is RoundedCone


@pytest.mark.parametrize(("solver", "contacts"), SOLVERS)
def test_a_new_indenter_on_its_tip_is_the_sphere_of_its_tip(registered, solver, contacts, monkeypatch):
    """While the contact stays on the tip (rho_c < rho_t), the rounded cone is the sphere of radius R_t: the
    same state, each scalar to 1e-8 relative (both solved on the same mesh to the Newton tolerance 1e-10; only
    the tangent's third derivative, by differences, and the curved area, by quadrature to 1e-13, are computed
    otherwise on the cone)."""
    monkeypatch.setitem(contacts, RoundedCone, contacts[Profile])
    cone = registered(LARGE_TIP, ANGLE)
    toy, ball = (solver.compress(ALPHA, PRESSURE, 0.19, indenter=indenter) for indenter in (cone, Sphere(LARGE_TIP)))
    assert toy.contact_radius_deformed < cone.joint
    assert toy.indenter is cone
    for name, value in ball.scalars().items():
        if isinstance(value, float):
            assert toy.scalars()[name] == pytest.approx(value, rel=1e-8, abs=1e-12), name


#: the FE only: the shooting solver's generic path (scipy on the indenter's curvature) does not get past the
#: tip's jump in curvature at rho_t in useful time; its own toy (``test_shooting_surface``) is smooth
@pytest.mark.parametrize(("solver", "contacts"), SOLVERS[:1])
def test_a_new_indenter_on_its_flank_carries_the_force_of_its_contact_pressure(registered, solver, contacts,
                                                                               monkeypatch):
    """Once the contact reaches the flank (rho_c > rho_t): at each node inside the contact zone (not its edge),
    p_c = P + kappa_1 T_1 + kappa_2 T_2 with kappa_1 = kappa_2 = 1/R_t on the tip, kappa_1 = 0 and kappa_2 =
    sin(beta)/rho on the flank (the curvatures of the geometry, not the indenter's methods), to rounding; the force
    is the cap's balance P pi rho_c^2 + 2 pi rho_c T_1 sin(theta_c) and the reaction at the edge, each exact to the
    Newton tolerance (1e-9 relative, as on a sphere)."""
    monkeypatch.setitem(contacts, RoundedCone, contacts[Profile])
    cone = registered(SMALL_TIP, ANGLE)
    state = solver.compress(ALPHA, PRESSURE, 1.0, indenter=cone)
    profile, pc = state.profile, state.contact_pressure
    assert state.contact_radius_deformed > cone.joint
    inner = profile.contact & (profile.r < state.contact_radius)
    rho, t1, t2 = profile.rho[inner], profile.tension_1[inner], profile.tension_2[inner]
    on_tip = rho <= cone.joint
    flank = state.pressure + t2 * math.sin(ANGLE) / np.maximum(rho, cone.joint)
    expected = np.where(on_tip, state.pressure + (t1 + t2) / SMALL_TIP, flank)
    assert np.any(on_tip)
    assert not np.all(on_tip)
    assert pc[inner] == pytest.approx(expected, rel=1e-12)
    for key in ("force_cap", "force_reaction"):
        assert state.extra[key] == pytest.approx(state.force, rel=1e-9), key
