"""The finite elements under a user's profile: the edge-fitted contact wrapped on any convex z(rho).

A sphere given as a profile table reproduces the sphere to the interpolation's error, and as exact
functions to round-off; the flat plate given as a profile reproduces the plate; the force on a
paraboloid is the integral of its contact pressure.
"""

import numpy as np
import pytest
from pocket.fem import api

from pocket import fem
from pocket.core import profiles
from pocket.core.indenters import Profile, Sphere

ALPHA, PRESSURE, RADIUS = 47 / 160, 0.31, 1.0
FORCES = [0.05, 0.19, 1.0]
QUANTITIES = ("height", "pressure", "contact_area", "contact_radius", "contact_radius_deformed",
              "contact_pressure_pole", "contact_pressure_edge")
ELEMENTS = 64


def _worst(states, reference, quantities=QUANTITIES):
    """The largest relative difference over the quantities and the states of two curves."""
    return max(abs(getattr(s, q) / getattr(r, q) - 1.0) for s, r in zip(states, reference, strict=True)
               for q in quantities)


def _sphere_table(rows: int):
    """The sphere of radius RADIUS as a table of ``rows`` rows evenly spaced up to 0.9 RADIUS."""
    rho = np.linspace(0.0, 0.9 * RADIUS, rows)
    return Profile(profiles.table(rho, RADIUS - np.sqrt(RADIUS**2 - rho**2)))


def _curve(indenter, elements=ELEMENTS):
    return fem.compression_curve(ALPHA, PRESSURE, FORCES, indenter=indenter, elements=elements)


def test_the_profile_indenter_is_posed_by_both_contact_methods():
    assert api.CONTACTS[Profile] == api.CONTACTS[Sphere]


def test_a_sphere_as_a_table_reproduces_the_sphere_to_the_interpolation_error():
    """The difference stays below the table's curvature error over the contact zone (O(h^2) in the
    spacing h of the rows, measured here) and falls each time the spacing halves."""
    exact = _curve(Sphere(RADIUS))
    errors = []
    for rows in (40, 79, 157):  # the spacing 0.9 R / (rows - 1) halves each time
        table = _sphere_table(rows)
        shape = table.shape
        rho = np.linspace(0.0, max(s.contact_radius_deformed for s in exact), 2001)
        curvature = shape.second(rho) / (1.0 + shape.slope(rho) ** 2) ** 1.5
        interpolation = float(np.max(np.abs(curvature * RADIUS - 1.0)))
        errors.append(_worst(_curve(table), exact))
        print(f"{rows} rows: states within {errors[-1]:.3g}, the table's curvature within {interpolation:.3g}")
        assert errors[-1] < interpolation
    assert errors[0] > errors[1] > errors[2]


def test_a_sphere_as_exact_functions_reproduces_the_sphere():
    difference = _worst(_curve(_exact_sphere()), _curve(Sphere(RADIUS)))
    print(f"sphere as functions: within {difference:.3g}")
    assert difference < 1e-9


def test_a_flat_profile_reproduces_the_plate():
    """The plate's edge-fitted formulation and the wrapped one at zero curvature are two discretisations
    of one problem: their difference is discretisation error, falling at the elements' order (P2: h^4)."""
    flat = Profile(profiles.table(np.linspace(0.0, 1.0, 5), np.zeros(5)))
    quantities = ("height", "pressure", "contact_area", "contact_radius")
    differences = [_worst(_curve(flat, n), _curve(None, n), quantities) for n in (32, 64)]
    print(f"flat profile against the plate on 32 and 64 elements: {differences}")
    assert differences[0] / differences[1] > 2.0**3.5
    assert differences[1] < 1e-8


def test_the_force_on_a_paraboloid_is_the_integral_of_its_contact_pressure():
    """z = rho^2 / (2 R_c): the indenter's reaction (the free sheet's pull at the contact edge) against
    F = int p_c 2 pi rho drho over the zone (Simpson on the nodes, O(h^4)), both over P_I pi R^2."""
    from scipy.integrate import simpson

    rc = 0.7
    shape = profiles.functions(lambda r: r * r / (2.0 * rc), lambda r: r / rc,
                               lambda r: (1.0 / rc) / (1.0 + (r / rc) ** 2) ** 1.5, 1.0)
    for force in (0.19, 1.0):
        state = fem.compress(ALPHA, PRESSURE, force, indenter=Profile(shape))
        on = state.profile.contact
        rho, pc = state.profile.rho[on], state.contact_pressure[on]
        assert np.all(pc >= 0.0)
        assert pc[0] > state.pressure
        integral = simpson(2.0 * rho * pc, x=rho) / state.pressure_initial
        print(f"Fhat = {force}: reaction {state.force!r}, integral of p_c {integral!r}")
        assert state.force == pytest.approx(force, rel=1e-12)
        assert integral == pytest.approx(state.force, rel=1e-4)


def _exact_sphere():
    k = RADIUS
    return Profile(profiles.functions(lambda r: k - np.sqrt(k * k - r * r), lambda r: r / np.sqrt(k * k - r * r),
                                      lambda r: np.full_like(r, 1.0 / k), 0.9 * k))


def test_the_penalty_method_poses_a_profile_as_it_poses_the_sphere():
    quantities = ("height", "pressure", "contact_area")
    states = [fem.compress(ALPHA, PRESSURE, 0.19, indenter=ind, contact="penalty")
              for ind in (_exact_sphere(), Sphere(RADIUS))]
    assert _worst(states[:1], states[1:], quantities) < 1e-9


def test_a_sheet_wrapping_past_the_end_of_a_profile_is_out_of_range():
    """A paraboloid tabled up to rho = 0.3 R: a force that would wrap the sheet past its last row is
    refused by name, quoting the force where the range ends (below the force asked)."""
    from pocket.core.errors import OutOfRangeError

    rho = np.linspace(0.0, 0.3, 20)
    with pytest.raises(OutOfRangeError, match="wraps past the end of the indenter's profile") as err:
        fem.compression_curve(ALPHA, PRESSURE, [0.19, 1.0], indenter=Profile(profiles.table(rho, rho**2 / 2.0)))
    assert str(err.value).startswith("force = 1 is beyond the model's range, which ends near force = 0.")
