"""A new convex indenter is posed by the one formulation of every curved indenter (``pocket.shooting.surface``)
through its generic path (scipy on the indenter's curvature) with nothing added to the solver but a
``CONTACTS`` entry: a rounded cone, registered here only, z = sqrt(b^2 + rho^2) - b (tip radius b, flanks at
45 degrees), read through its height, slope and curvature alone."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from pocket.fem import api as fem_api
from pocket.shooting.problem import CONTACTS, contact_of
from pocket.shooting.surface import SurfaceProblem
from pocket.shooting.surfaces import Surface, surface_of
from scipy.integrate import simpson

from pocket import fem, shooting
from pocket.core import profiles
from pocket.core.errors import OutOfRangeError
from pocket.core.indenters import INDENTERS, Indenter, Profile, register

ALPHA, PHAT = 0.1, 0.3
TIP = 0.2  # b, the tip's radius of curvature (units R)
REACH = 0.3  # the cone's base radius: the largest rho it stands above (units R)
SCALARS = ("pressure", "height", "contact_radius", "contact_radius_deformed", "contact_area", "volume",
           "contact_pressure_pole", "contact_pressure_edge")


def _height(rho):
    return np.sqrt(TIP * TIP + rho * rho) - TIP


def _slope(rho):
    return rho / np.sqrt(TIP * TIP + rho * rho)


def _curvature(rho):
    """z'' / (1 + z'^2)^(3/2) = b^2 / (b^2 + 2 rho^2)^(3/2)."""
    return TIP * TIP / (TIP * TIP + 2.0 * rho * rho) ** 1.5


@dataclasses.dataclass(frozen=True)
class HyperbolicCone(Indenter):
    """The rounded cone z = sqrt(b^2 + rho^2) - b (b = ``TIP``) up to rho = ``REACH``, a class of this test only."""

    name = "hyperbolic-cone"
    summary = "a cone rounded at its tip, registered by this test only"

    def height(self, rho):
        return _height(np.asarray(rho, dtype=float))

    def slope(self, rho):
        return _slope(np.asarray(rho, dtype=float))

    def second(self, rho):
        rho = np.asarray(rho, dtype=float)
        return TIP * TIP / (TIP * TIP + rho * rho) ** 1.5

    @property
    def reach(self) -> float:
        return REACH


@pytest.fixture
def cone(monkeypatch):
    """The rounded cone registered, with its one entry in the shooting solver's table, for one test."""
    register(HyperbolicCone)
    monkeypatch.setitem(CONTACTS, HyperbolicCone, SurfaceProblem)
    monkeypatch.setitem(fem_api.CONTACTS, HyperbolicCone, fem_api.CONTACTS[Profile])
    yield HyperbolicCone()
    del INDENTERS[HyperbolicCone.name]


def test_a_new_convex_indenter_takes_the_generic_path(cone):
    """Exact answer: its problem is the curved indenters' formulation in its generic words, its surface the
    generic one (scipy on the indenter's curvature), whose curvature is the cone's closed form
    b^2 / (b^2 + 2 rho^2)^(3/2) to round-off (the kind gives z'' and z'), read at the reach past it."""
    assert contact_of(cone) is SurfaceProblem
    surface = surface_of(cone)
    assert type(surface) is Surface
    assert surface.reach == REACH
    rho = np.linspace(0.0, REACH, 7)
    assert surface.curvature(rho) == pytest.approx(_curvature(rho), rel=1e-14)
    assert surface.curvature(2.0 * REACH) == pytest.approx(_curvature(REACH), rel=1e-14)
    assert surface.pole_radius == pytest.approx(TIP, rel=1e-15)


def test_a_new_convex_indenter_balances_the_force_two_ways(cone):
    """Exact answer: the force the solver imposes (the contact cap's balance) is the integral of the contact
    pressure's vertical component, F = int p_c cos(theta) dA = int_0^rho_c 2 pi rho p_c drho, to the error of
    Simpson's rule over the stored profile's points, of order (h / b)^4 for steps h on a surface whose
    curvature varies over the tip radius b (bounded here by 10 times that: 8e-6 at h = 0.006; the same
    estimate gives 1e-8 under the paraboloid of ``tests/test_shooting_profile.py``), with
    p_c = P + T_1 kappa_1 + T_2 kappa_2 >= P (both curvatures of a convex surface >= 0); on the axis
    p_c = P + 2 T_0 / b."""
    for force in (0.1, 0.3):
        state = shooting.compress(ALPHA, PHAT, force, indenter=cone)
        on = state.profile.contact
        pc, rho = state.contact_pressure[on], state.profile.rho[on]
        assert np.all(pc >= state.pressure)
        simpson_error = 10.0 * (float(np.max(np.diff(rho))) / TIP) ** 4
        integral = float(simpson(2.0 * rho * pc, x=rho)) / state.pressure_initial
        assert integral == pytest.approx(force, rel=simpson_error), (integral / force - 1.0, simpson_error)
        assert state.contact_pressure_pole == pytest.approx(pc[0], rel=1e-6)


def test_a_new_convex_indenter_is_posed_as_the_same_surface_given_as_a_profile(cone):
    """Exact answer: the cone and the same surface given as profile functions (its height, slope and
    curvature) are one problem integrated the same way, their curvatures equal to round-off: every scalar
    agrees within the shots' own error (rtol 1e-10, with margin: 1e-9)."""
    shape = profiles.functions(_height, _slope, _curvature, REACH, source="the rounded cone")
    forces = [0.1, 0.3]
    for got, ref in zip(shooting.compression_curve(ALPHA, PHAT, forces, indenter=cone),
                        shooting.compression_curve(ALPHA, PHAT, forces, indenter=Profile(shape)), strict=True):
        for key in SCALARS:
            assert getattr(got, key) == pytest.approx(getattr(ref, key), rel=1e-9), key


@pytest.mark.slow
def test_a_new_convex_indenter_ends_at_its_reach(cone):
    """Exact answer: pressed on, the sheet wraps the cone up to its reach, where the range ends with the
    contact edge there (to the shots' error at the end, 1e-6), and a force past it is refused in the
    formulation's generic words."""
    end = shooting.range_end(ALPHA, PHAT, indenter=cone)
    state = shooting.compress(ALPHA, PHAT, end, indenter=cone)
    assert state.contact_radius_deformed == pytest.approx(REACH, rel=1e-6)
    with pytest.raises(OutOfRangeError, match=SurfaceProblem.END):
        shooting.compress(ALPHA, PHAT, end * (1 + 1e-6), indenter=cone)
    assert math.isfinite(end)


def _worst(left, right, keys) -> dict[str, float]:
    """{key: largest relative difference between two curves' states} over ``keys``."""
    return {key: max(abs(getattr(b, key) / getattr(a, key) - 1.0) for a, b in zip(left, right, strict=True))
            for key in keys}


def test_both_membrane_solvers_agree_on_a_new_convex_indenter(cone):
    """The cone, registered with one entry in each solver's table, is posed by both membrane solvers, and what
    separates them is the FE's discretisation error: on twice the elements the difference falls at least 8-fold
    (the P2 elements' O(h^4) gives 16), as under a sphere (``tests/test_sphere_agree.py``), or is below 1e-10."""
    forces = [0.1, 0.3]
    reference = shooting.compression_curve(ALPHA, PHAT, forces, indenter=cone)
    coarse, fine = (_worst(reference, fem.compression_curve(ALPHA, PHAT, forces, indenter=cone, elements=n), SCALARS)
                    for n in (128, 256))
    for key in SCALARS:
        assert fine[key] < coarse[key] / 8 or fine[key] < 1e-10, (key, coarse[key], fine[key])
    print({key: f"{coarse[key]:.1e} -> {fine[key]:.1e}" for key in SCALARS})
