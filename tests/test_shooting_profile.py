"""The shooting solver under a user's profile (``pocket.shooting.surface``): every check computes what it compares.

- the sphere given as exact profile functions reproduces the sphere's states (to 1e-9);
- the sphere given as a table reproduces them to the interpolation's error, bounded from the orders
  ``pocket.core.profiles`` documents, and falling at least as h^2 when the rows are doubled;
- the force two ways for a paraboloid: the contact cap's balance (what the solver imposes) against the
  integral of the contact pressure, p_c = P + T_1 kappa_1 + T_2 kappa_2 >= P;
- the range ends at the end of the profile, with the contact edge there.
"""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest
from pocket.shooting.problem import PROFILE_END, ProfileProblem, contact_of
from scipy.integrate import simpson

from pocket import shooting
from pocket.core import profiles
from pocket.core.errors import OutOfRangeError
from pocket.core.indenters import Profile, Sphere
from pocket.core.materials import check

ALPHA, PHAT = 0.1, 0.3
K = 0.4  # a fingertip: R_s = 0.4 R
EXTENT = 0.9 * K  # the profile stops short of the equator, where the sphere's slope is infinite
FORCES = [0.3, 0.8]
SCALARS = ("pressure", "height", "contact_radius", "contact_radius_deformed", "contact_area", "volume",
           "contact_pressure_pole", "contact_pressure_edge")


def _sphere_functions():
    return profiles.functions(lambda r: K - np.sqrt(K * K - r * r), lambda r: r / np.sqrt(K * K - r * r),
                              lambda r: np.full_like(r, 1.0 / K), EXTENT, source="a sphere")


def _sphere_table(rows: int):
    rho = np.linspace(0.0, EXTENT, rows)
    return profiles.table(rho, K - np.sqrt(K * K - rho * rho))


def _errors(indenter) -> np.ndarray:
    """Relative differences of every scalar from the sphere's, shape (len(FORCES), len(SCALARS))."""
    ref = shooting.compression_curve(ALPHA, PHAT, FORCES, indenter=Sphere(K))
    got = shooting.compression_curve(ALPHA, PHAT, FORCES, indenter=Profile(indenter))
    return np.array([[abs(getattr(g, k) / getattr(r, k) - 1.0) for k in SCALARS] for g, r in zip(got, ref,
                                                                                                  strict=True)])


def test_shooting_poses_the_profile():
    assert contact_of(Profile(_sphere_functions())) is ProfileProblem


def test_sphere_as_functions_reproduces_the_sphere():
    errors = _errors(_sphere_functions())
    print("largest relative difference, functions:", errors.max())
    assert errors.max() < 1e-9


def test_sphere_as_table_reproduces_the_sphere_to_the_interpolation_error():
    rows = 40
    coarse, fine = _errors(_sphere_table(rows)), _errors(_sphere_table(2 * rows))
    # profiles.py: the spline g(s) of z(rho) = g(rho^2) errs in g'' by at most 3/8 h^2 M (2.1 times that at
    # its not-a-knot ends), M = max|g''''|, h the row spacing in s; the contact pressure at the edge reads the
    # curvature z'' = 2 g' + 4 s g'' there. The error is local to a few rows, so h and M are taken over the
    # rows up to two past the widest contact edge: g = K - sqrt(K^2 - s), g'''' = 15/16 (K^2 - s)^(-7/2).
    widest = max(s.contact_radius_deformed for s in shooting.compression_curve(ALPHA, PHAT, FORCES,
                                                                                 indenter=Sphere(K)))
    rho = np.linspace(0.0, EXTENT, rows)
    near = rho[: np.searchsorted(rho, widest) + 3] ** 2
    h, m = float(np.max(np.diff(near))), 15.0 / 16.0 * (K * K - near[-1]) ** -3.5
    curvature_bound = 4.0 * near[-1] * 2.1 * 3.0 / 8.0 * h**2 * m * K  # 4 s |g'' - S''| relative to 1/K
    edge = SCALARS.index("contact_pressure_edge")
    print(f"edge pressure: bound {curvature_bound:.3g}, {rows} rows {coarse[:, edge].max():.3g}, "
          f"{2 * rows} rows {fine[:, edge].max():.3g}; all: {coarse.max(axis=0)}, {fine.max(axis=0)}")
    assert coarse[:, edge].max() < curvature_bound
    # the other scalars integrate the curvature to the slope (O(h^3)); doubling the rows halves h, and every
    # error falls at least as h^2 (0.25; measured 0.12-0.22), but for the volume, the liquid's V_I whatever
    # the indenter, held to the root finder's tolerance (1e-13)
    volume = SCALARS.index("volume")
    assert np.all(np.delete(fine, volume, axis=1) <= 0.3 * np.delete(coarse, volume, axis=1))
    assert max(coarse[:, volume].max(), fine[:, volume].max()) < 1e-11
    assert coarse.max() < 1e-3  # and the table of 40 rows is a usable sphere


@pytest.mark.slow
def test_force_two_ways_under_a_paraboloid():
    rc = 0.5  # z = rho^2 / (2 R_c): kappa_1 = (1/R_c) / (1 + rho^2/R_c^2)^(3/2), not constant
    shape = profiles.functions(lambda r: r * r / (2 * rc), lambda r: r / rc,
                               lambda r: (1.0 / rc) / (1.0 + (r / rc) ** 2) ** 1.5, 1.0, source="a paraboloid")
    for force in (0.3, 1.0):
        state = shooting.compress(ALPHA, PHAT, force, indenter=Profile(shape))
        on = state.profile.contact
        pc, rho = state.contact_pressure[on], state.profile.rho[on]
        assert np.all(pc >= state.pressure)  # p_c = P + T1 kappa1 + T2 kappa2, both curvatures >= 0
        # F = int p_c cos(theta) dA = int_0^rho_c 2 pi rho p_c drho; Fhat = F / (pi P_I R^2)
        integral = float(simpson(2.0 * rho * pc, x=rho)) / state.pressure_initial
        assert integral == pytest.approx(force, rel=1e-8)
        # the contact zone is round near the axis: p_c(0) = P + 2 T_0 / R_c
        assert state.contact_pressure_pole == pytest.approx(pc[0], rel=1e-6)


@pytest.mark.slow
def test_range_ends_at_the_end_of_the_profile():
    shape = _sphere_functions()
    end = shooting.range_end(ALPHA, PHAT, indenter=Profile(shape))
    assert end < shooting.range_end(ALPHA, PHAT, indenter=Sphere(K))  # the table stops short of the equator
    state = shooting.compress(ALPHA, PHAT, end, indenter=Profile(shape))
    assert state.contact_radius_deformed == pytest.approx(EXTENT, rel=1e-6)
    with pytest.raises(OutOfRangeError, match=re.escape(PROFILE_END)):
        shooting.compress(ALPHA, PHAT, end * (1 + 1e-6), indenter=Profile(shape))


def test_contact_area_is_the_curved_area():
    state = shooting.compress(ALPHA, PHAT, 0.5, indenter=Profile(_sphere_functions()))
    # a spherical cap reaching rho_c: 2 pi K^2 (1 - cos(phi_c)), sin(phi_c) = rho_c / K, over pi R^2
    phi = math.asin(state.contact_radius_deformed / K)
    assert state.contact_area == pytest.approx(2.0 * K * K * (1.0 - math.cos(phi)), rel=1e-10)


@pytest.mark.slow
def test_a_blunt_profile_ends_with_its_lowest_point_at_the_clamp_plane():
    rc = 0.5  # the paraboloid reaching rho = R: the pole meets the clamp plane before the profile ends
    shape = profiles.functions(lambda r: r * r / (2 * rc), lambda r: r / rc,
                               lambda r: (1.0 / rc) / (1.0 + (r / rc) ** 2) ** 1.5, 1.0, source="a paraboloid")
    end = shooting.range_end(ALPHA, PHAT, indenter=Profile(shape))
    state = shooting.compress(ALPHA, PHAT, end, indenter=Profile(shape))
    assert abs(state.height) < 1e-6 * state.inflated.height
    with pytest.raises(OutOfRangeError, match=re.escape(ProfileProblem.POLE)):
        shooting.compress(ALPHA, PHAT, end * (1 + 1e-6), indenter=Profile(shape))


def test_a_flat_profile_reproduces_the_plate():
    """z(rho) = 0 as a table: the contact zone has no curvature, so psi' = -lambda_1 kappa_1 = 0 keeps it flat
    and p_c = P + T_1 kappa_1 + T_2 kappa_2 = P, the plate's problem integrated by another route (the profile's
    contact zone row by row, DOP853, against the plate's closed form). Every scalar agrees to the root finders'
    tolerance (measured <= 1.4e-13; 1e-10 is the shots' rtol), the contact pressure is P along the zone, and
    the range ends at the same force to the range end's own tolerance (measured 5e-11)."""
    flat = Profile(profiles.table(np.linspace(0.0, 1.0, 5), np.zeros(5)))
    forces = [0.3, 0.8, 2.0]
    keys = ("pressure", "height", "contact_radius", "contact_area", "stretch_contact", "volume", "tension_1_min",
            "tension_2_min")
    for got, ref in zip(shooting.compression_curve(ALPHA, PHAT, forces, indenter=flat),
                        shooting.compression_curve(ALPHA, PHAT, forces), strict=True):
        for key in keys:
            assert getattr(got, key) == pytest.approx(getattr(ref, key), rel=1e-10), key
        on = got.profile.contact
        assert got.contact_pressure[on] == pytest.approx(np.full(on.sum(), ref.pressure), rel=1e-12)
    ends = shooting.range_end(ALPHA, PHAT, indenter=flat), shooting.range_end(ALPHA, PHAT)
    assert ends[0] == pytest.approx(ends[1], rel=1e-9)


@pytest.mark.slow
def test_a_table_is_integrated_compiled_as_scipy_integrates_it():
    """Two integrations of one 40-row table: the compiled integrator, which evaluates the spline itself and ends
    a step on each row it would cross, and scipy's DOP853 on the table's Python functions, stopping at each row
    by an event (the route a profile given as functions takes). Both at rtol 1e-10, against the compiled one at
    rtol 1e-12: measured 8e-11 (compiled) and 5e-9 (scipy, whose restarts at the rows lose more), so they agree
    to 1e-8 and the compiled one stays within 1e-9 of the tighter solve."""
    shape = _sphere_table(40)
    slow = dataclasses.replace(shape, pieces=None)
    keys = SCALARS
    fine = shooting.compression_curve(ALPHA, PHAT, FORCES, indenter=Profile(shape), rtol=1e-12)
    fast = shooting.compression_curve(ALPHA, PHAT, FORCES, indenter=Profile(shape))
    scipy = shooting.compression_curve(ALPHA, PHAT, FORCES, indenter=Profile(slow))
    for a, b, c in zip(fast, scipy, fine, strict=True):
        for key in keys:
            assert getattr(a, key) == pytest.approx(getattr(b, key), rel=1e-8), key
            assert getattr(a, key) == pytest.approx(getattr(c, key), rel=1e-9), key


@pytest.mark.slow
def test_a_sphere_as_functions_on_a_shallow_dome_reproduces_the_sphere():
    """The sphere given as exact profile functions on a shallow dome under a large sphere (Phat_I = 2.26e-4,
    K = 1.379, Fhat = 0.472: a pole strain s_0 ~ 1e-3), where the contact zone's state enters the residuals
    divided by s_0: the profile's contact zone is integrated to the same scaled tolerance as the sphere's, so
    every scalar is the sphere's to 1e-8 (the shots' own error, rtol 1e-10 over s_0, with margin)."""
    k, phat, force = 1.3790245400508674, 0.00022631090533322825, 0.47243114058787555
    material = check("neo-hookean", {"mu": 1.0})
    exact = profiles.functions(lambda r: k - np.sqrt(k * k - r * r), lambda r: r / np.sqrt(k * k - r * r),
                               lambda r: np.full_like(r, 1.0 / k), 0.9 * k, source="a sphere")
    ref = shooting.compress(material, phat, force, indenter=Sphere(k))
    got = shooting.compress(material, phat, force, indenter=Profile(exact))
    for key in SCALARS:
        assert getattr(got, key) == pytest.approx(getattr(ref, key), rel=1e-8), key
