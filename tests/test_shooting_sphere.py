"""The shooting solver under a sphere (``pocket.shooting.surface``): every check computes what it compares.

- R_s -> infinity recovers the flat plate at first order in R/R_s (the fitted rate is printed);
- the force two ways: the contact cap as a free body (what the solver imposes) against the integral of
  the contact pressure over the curved contact area, F = int p_c 2 pi rho drho (p_c cos(phi) dA, with
  cos(phi) dA = 2 pi rho drho its projection);
- the virtual work, F = (-dU + P dV) / dh along the path, by central differences of the stored energy
  U = 2 pi int W r dr T R^2 between nearby states;
- at small force (P/P_I - 1)/Fhat tends to pi (dH0/dP)/(dV0/dP) of the inflated pocket for sphere and
  plate alike (reciprocity; a gas adds its compliance V/(gamma (P + P_atm)) to the denominator);
- p_c >= 0 and no free sheet inside the sphere in every returned state, and a state breaking either
  refused by name;
- the range's ends: the equator (a small sphere), the pole at the clamp plane, the free sheet at the
  clamp plane (a large one, where F = P pi R^2 gives the end independently);
- Mooney-Rivlin, neo-Hookean, Yeoh and a gas.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from pocket.shooting.laws import law_of
from pocket.shooting.problem import EQUATOR, SphereProblem, contact_of
from scipy.integrate import simpson

from pocket import fem, shooting
from pocket.core.errors import CLAMP_PLANE, OutOfRangeError
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import check, energy

ALPHA, PHAT = 0.1, 0.3
GAS = gas(1.0, 1.4)
LAWS = {
    "mooney-rivlin": ALPHA,
    "neo-hookean": check("neo-hookean", {"mu": 0.4e6}),
    "yeoh": check("yeoh", {"c10": 85e3, "c20": -2e3, "c30": 0.2e3}),
}


def _physical(state):
    """Assert p_c >= 0 on the contact zone and the free sheet outside the sphere (within rtol-sized noise)."""
    profile = state.profile
    assert np.all(state.contact_pressure[profile.contact] >= 0.0)
    free = ~profile.contact & (profile.rho < state.indenter.reach)
    surface = state.height + state.indenter.height(profile.rho[free])
    assert np.all(profile.eta[free] <= surface + 1e-9)


def _force_from_pressure(state) -> float:
    """Fhat = int_0^rho_c 2 pi rho p_c drho / (P_I pi R^2), Simpson's rule on the contact zone's samples."""
    profile = state.profile
    on = profile.contact
    return float(simpson(2.0 * profile.rho[on] * state.contact_pressure[on], x=profile.rho[on])) \
        / state.pressure_initial


def _energy(state) -> float:
    """U / (E T R^2) = 2 pi int_0^1 W(l1, l2) / E r dr: Simpson's rule on the profile, on each side of the
    contact edge apart (lambda_1' jumps there with the curvature)."""
    material, profile = state.material, state.profile
    w = energy(material, profile.stretch_1, profile.stretch_2) / material.modulus * profile.r
    edge = int(np.flatnonzero(profile.contact)[-1])
    parts = (slice(0, edge + 1), slice(edge, None))
    return float(2.0 * math.pi * sum(simpson(w[part], x=profile.r[part]) for part in parts))


def test_large_sphere_recovers_the_plate_at_first_order():
    force = 0.5
    plate = shooting.compress(ALPHA, PHAT, force)
    radii = np.array([4.0, 8.0, 16.0, 32.0])
    for key in ("pressure_ratio", "height", "contact_radius"):
        gaps = [abs(getattr(shooting.compress(ALPHA, PHAT, force, indenter=Sphere(k)), key) - getattr(plate, key))
                for k in radii]
        rates = -np.diff(np.log(gaps)) / np.diff(np.log(radii))  # the rate between successive radii
        print(f"{key}: |sphere - plate| ~ (R/R_s)^rate, rates for R_s/R = 4-8, 8-16, 16-32: "
              + ", ".join(f"{r:.4f}" for r in rates))
        # first order: the rate tends to 1, its O(R/R_s) departure halving with each doubling of R_s
        assert np.all(np.diff(np.abs(rates - 1.0)) < 0.0)
        assert rates[-1] == pytest.approx(1.0, abs=0.05)


@pytest.mark.parametrize("law", list(LAWS))
def test_force_two_ways_and_virtual_work(law):
    material, radius = LAWS[law], 2.0
    forces = [0.3, 0.6, 1.2]
    delta = 1e-3
    states = shooting.compression_curve(material, PHAT, [f * s for f in forces for s in (1 - delta, 1, 1 + delta)],
                                        indenter=Sphere(radius))
    for k, force in enumerate(forces):
        below, state, above = states[3 * k:3 * k + 3]
        for s in (below, state, above):
            _physical(s)
        # the profile samples the contact zone at the integrator's steps: Simpson's error is far below 1e-9
        assert _force_from_pressure(state) == pytest.approx(force, rel=1e-9)
        # F dh = -dU + P dV, V fixed (a liquid): F / (E T R) = -dU/dh, and Fhat = F / (pi P_I R^2); central
        # differences over +-delta err by O(delta^2) = 1e-6 relative, hence 1e-5
        work = -(_energy(above) - _energy(below)) / (above.height - below.height)
        assert work / (math.pi * PHAT) == pytest.approx(force, rel=1e-5)
        assert state.contact_pressure_edge > state.pressure
        assert state.contact_pressure_pole > state.pressure


def test_neo_hookean_is_mooney_rivlin_without_c2_under_a_sphere():
    mu = 0.4e6
    forces = [0.2, 0.8]
    nh = shooting.compression_curve(check("neo-hookean", {"mu": mu}), PHAT, forces, indenter=Sphere(1.5))
    mr = shooting.compression_curve(check("mooney-rivlin", {"c1": mu / 2, "c2": 0.0}), PHAT, forces,
                                    indenter=Sphere(1.5))
    for a, b in zip(nh, mr, strict=True):
        for key in ("pressure", "height", "contact_radius", "contact_area", "contact_pressure_edge"):
            assert getattr(a, key) == pytest.approx(getattr(b, key), rel=1e-8)


def test_gas_force_two_ways_and_virtual_work():
    forces = [0.5 * (1 - 1e-3), 0.5, 0.5 * (1 + 1e-3)]
    below, state, above = shooting.compression_curve(ALPHA, PHAT, forces, fluid=GAS, indenter=Sphere(2.0))
    for s in (below, state, above):
        _physical(s)
    assert _force_from_pressure(state) == pytest.approx(0.5, rel=1e-9)
    assert state.volume < state.inflated.volume  # the gas is compressed
    work = (-(_energy(above) - _energy(below)) + state.pressure * (above.volume - below.volume)) \
        / (above.height - below.height)
    assert work / (math.pi * PHAT) == pytest.approx(0.5, rel=1e-5)


def _small_force_limit(fluid, indenter) -> float:
    """lim (P/P_I - 1)/Fhat as Fhat -> 0, Richardson-extrapolated from Fhat = 1e-4 and 2e-4 (linear in Fhat)."""
    small, double = shooting.compression_curve(ALPHA, PHAT, [1e-4, 2e-4], fluid=fluid, indenter=indenter)
    slope = [(s.pressure_ratio - 1.0) / s.force for s in (small, double)]
    return 2.0 * slope[0] - slope[1]


@pytest.mark.parametrize("fluid", [None, GAS], ids=["liquid", "gas"])
def test_small_force_pressure_rise_is_reciprocity_for_sphere_and_plate(fluid):
    step = 1e-4 * PHAT
    up, down = (shooting.inflate(ALPHA, PHAT + s) for s in (step, -step))
    dh = (up.height - down.height) / (2 * step)
    dv = (up.volume - down.volume) / (2 * step)
    if fluid is not None:
        dv += shooting.inflate(ALPHA, PHAT).volume / (fluid.gamma * (PHAT + fluid.ambient))
    expected = math.pi * dh / dv
    for indenter in (None, Sphere(0.5), Sphere(3.0)):
        assert _small_force_limit(fluid, indenter) == pytest.approx(expected, rel=1e-4)


@pytest.mark.parametrize(("radius", "reason"), [(0.05, EQUATOR), (0.2, SphereProblem.POLE), (4.0, CLAMP_PLANE)])
def test_range_ends_are_named_with_their_force(radius, reason):
    end = shooting.range_end(ALPHA, PHAT, indenter=Sphere(radius))
    state = shooting.compress(ALPHA, PHAT, end, indenter=Sphere(radius))
    _physical(state)
    if reason == EQUATOR:
        assert state.contact_radius_deformed == pytest.approx(radius, rel=1e-6)
    elif reason == SphereProblem.POLE:
        assert state.height == pytest.approx(0.0, abs=1e-8)
    else:  # the clamp carries no vertical force: F = P pi R^2
        assert end == pytest.approx(state.pressure_ratio, rel=1e-8)
    with pytest.raises(OutOfRangeError, match=f"ends at force = {end:.10g}.*there {reason}"):
        shooting.compress(ALPHA, PHAT, end * (1 + 1e-6), indenter=Sphere(radius))


def test_a_state_with_negative_contact_pressure_or_penetration_is_refused_by_name():
    state = shooting.compress(ALPHA, PHAT, 0.5, indenter=Sphere(1.0))
    problem = contact_of(state.indenter)(state.inflated, 1e-10, law_of(state.material), state.fluid,
                                         state.indenter)
    profile = state.profile
    problem.check(profile, state.contact_pressure, state.height, 0.5)  # the solver's own state passes
    with pytest.raises(OutOfRangeError, match="contact pressure would be negative"):
        problem.check(profile, np.where(profile.contact, -1.0, np.nan), state.height, 0.5)
    near = ~profile.contact & (profile.rho < 1.0)
    inside = dataclasses.replace(profile, eta=np.where(near, state.height + 1.0, profile.eta))
    with pytest.raises(OutOfRangeError, match=SphereProblem.TOUCH):
        problem.check(inside, state.contact_pressure, state.height, 0.5)


@pytest.mark.slow
@pytest.mark.parametrize("radius", [0.5, 2.0])
def test_a_force_maximum_under_a_sphere_ends_the_range(radius):
    """A softening rubber (alpha = -0.5, Phat_I = 0.1; under the plate its range ends at a fold too) under a
    sphere: the force has a maximum before any other end. Shooting finds it by continuing in the indenter's
    height past the stall; it must be a maximum of F(h), which the FE shows independently by holding the
    indenter at heights on either side of it (its load is the height, so it passes the fold): the FE force is
    lower on both sides, and at the fold's height equals shooting's end to the FE's floor at 128 elements
    (measured 2e-8; the sides are 1e-5 lower, F'' h^2 / 2 at 0.2 % of h). Forces just below the end solve
    (near the fold, on the height branch), just above are out of range by the fold's name, not the touch's."""
    alpha, phat, indenter = -0.5, 0.1, Sphere(radius)
    end = shooting.range_end(alpha, phat, indenter=indenter)
    at_end = shooting.compress(alpha, phat, end, indenter=indenter)
    assert shooting.compress(alpha, phat, end * (1 - 1e-8), indenter=indenter).height > at_end.height
    fe = [fem.compress_height(alpha, phat, at_end.height * (1 + d), indenter=indenter, elements=128).force
          for d in (-2e-3, 0.0, 2e-3)]
    print(f"K = {radius}: shooting's end {end:.12g}; FE at its height and 0.2 % either side: {fe}")
    assert fe[1] == pytest.approx(end, rel=1e-7)
    assert fe[0] < end * (1 - 1e-6)
    assert fe[2] < end * (1 - 1e-6)
    with pytest.raises(OutOfRangeError, match=f"ends at force = {end:.10g}.*there the force has a maximum"):
        shooting.compress(alpha, phat, end * (1 + 1e-9), indenter=indenter)
