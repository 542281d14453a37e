"""The shooting solver's closed capsule between two plates: the inflated sphere against its closed form, the
balances every state must satisfy, the limits with known answers, the end of the range, and the refusals."""

import dataclasses
import math
import re

import numpy as np
import pytest
from pocket.shooting.capsule import amplification

from pocket import fem, shooting
from pocket.cli import main
from pocket.core.errors import UNINFLATED_CAPSULE, ConvergenceError, InputError, OutOfRangeError
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import check, energy, mooney_rivlin

NEO = check("neo-hookean", {"mu": 1.0})
YEOH = check("yeoh", {"c10": 1.0, "c20": -0.05, "c30": 0.01})
KEYS = ("pressure_ratio", "height", "volume", "contact_area", "contact_radius", "contact_radius_deformed")
EULER = 0.5772156649015329


def _values(state):
    return np.array([getattr(state, k) for k in KEYS] + [state.extra["stretch_pole"], state.extra["radius_equator"]])


@pytest.mark.parametrize("alpha", [0.0, 0.1, 0.3, -0.1])
def test_inflated_capsule_is_laplace_for_mooney_rivlin(alpha):
    """Exact answer: Phat = 2 (1 - l^-6)(1 + alpha l^2) / (3 (1 + alpha) l) (the theory's closed form, from
    w'(l) of the Mooney-Rivlin energy), V = 4 pi l^3 / 3, H = l, at the stretch the solver found, to 1e-12."""
    for phat in (0.05, 0.2, 0.33):
        state = shooting.inflate(alpha, phat, geometry="capsule")
        stretch = state.stretch_pole
        closed = 2.0 * (1.0 - stretch**-6) * (1.0 + alpha * stretch**2) / (3.0 * (1.0 + alpha) * stretch)
        assert closed == pytest.approx(phat, rel=1e-12, abs=0.0)
        assert state.volume == pytest.approx(4.0 * math.pi * stretch**3 / 3.0, rel=1e-15)
        assert state.height == stretch == state.extra["radius_equator"]
        np.testing.assert_allclose(state.profile.rho, stretch * np.sin(state.profile.r), rtol=0, atol=1e-15)


@pytest.mark.parametrize("material", [NEO, YEOH, check("gent", {"mu": 1.0, "jm": 20.0}),
                                      check("ogden", {"mu": [1.2, -0.2], "exponents": [2.0, -2.0]})])
def test_inflated_capsule_is_the_energy_balance(material):
    """Independent computation: P dV = the strain energy's change, Phat = w'(l) / (E l^2) with w(l) = W(l, l) from
    ``pocket.core.materials.energy`` by a 4th-order central difference (E = 3 mu_0), to 1e-9."""
    mu0 = material.mu0
    for phat in (0.05, 0.2):
        stretch = shooting.inflate(material, phat, geometry="capsule").stretch_pole
        h = 1e-3

        def w(x):
            return float(energy(material, x, x))

        slope = (8.0 * (w(stretch + h) - w(stretch - h)) - (w(stretch + 2 * h) - w(stretch - 2 * h))) / (12 * h)
        assert slope / (3.0 * mu0 * stretch**2) == pytest.approx(phat, rel=1e-9)


def test_an_unpressurised_capsule_is_the_reference_sphere():
    """Exact answer: at Phat = 0 the capsule is the unit sphere; with a prestretch lambda_p (inflated from the
    radius R / lambda_p) the sphere whose material stretch is 1, lambda = 1 / lambda_p."""
    assert shooting.inflate(0.2, 0.0, geometry="capsule").stretch_pole == 1.0
    prestretched = dataclasses.replace(mooney_rivlin(0.2), prestretch=1.1)
    assert shooting.inflate(prestretched, 0.0, geometry="capsule").stretch_pole == pytest.approx(1 / 1.1, rel=1e-15)
    # inflated, it is the capsule of radius R / 1.1 at the same P: material stretch 1.1 lambda, Phat 1.1 times
    plain = shooting.inflate(0.2, 0.2, geometry="capsule").stretch_pole
    taut = shooting.inflate(prestretched, 0.2 * 1.1, geometry="capsule").stretch_pole
    assert 1.1 * taut == pytest.approx(plain, rel=1e-12)


@pytest.mark.parametrize("solver", [shooting, fem])
def test_an_uninflated_capsule_is_not_pressed(solver, capsys):
    """Both solvers, the API and the command line: a capsule at P_I = 0 is refused before any solve, in one line
    saying why (``UNINFLATED_CAPSULE``: its compression's range ends ever sooner as P_I falls; the figures it
    quotes are benchmarks/capsule_low_pressure.py's)."""
    with pytest.raises(InputError, match=f"^pressure = 0: {re.escape(UNINFLATED_CAPSULE)}$"):
        solver.compression_curve(0.2, 0.0, [0.1], geometry="capsule")
    name = solver.__name__.rsplit(".", 1)[-1]
    assert main(["compress", "--geometry", "capsule", "--solver", name, "--alpha", "0.2", "--pressure", "0",
                 "--force", "0.1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert UNINFLATED_CAPSULE in err


def test_the_pressure_maximum_is_refused():
    """Exact answer: a neo-Hookean balloon's pressure peaks at lambda = 7^(1/6), Phat = (4/7) 7^(-1/6) (the
    theory's closed form): above it no inflated capsule, quoting the maximum; just below, one."""
    peak = 4.0 / 7.0 * 7.0 ** (-1.0 / 6.0)
    with pytest.raises(OutOfRangeError, match=f"maximum Phat = {peak:.6g}"):
        shooting.inflate(0.0, 1.001 * peak, geometry="capsule")
    assert shooting.inflate(0.0, 0.999 * peak, geometry="capsule").stretch_pole < 7.0 ** (1.0 / 6.0)


CASES = [(0.2, 0.1, None), (NEO, 0.35, None), (NEO, 0.2, gas(10.0, 1.4)), (YEOH, 0.15, None), (0.3, 0.25, None)]


@pytest.fixture(scope="module", params=range(len(CASES)))
def curve(request):
    material, phat, fluid = CASES[request.param]
    forces = [0.01, 0.2, 1.0, 2.0]
    return material, phat, fluid, forces, shooting.compression_curve(material, phat, forces, fluid=fluid,
                                                                     geometry="capsule")


def test_force_is_pressure_times_contact_area(curve):
    """Conservation: F = P A_c on each plate (Fhat = (P/P_I) rho_c^2), and rho_c^2 is the contact area."""
    _, _, _, forces, states = curve
    for force, state in zip(forces, states, strict=False):
        assert state.pressure_ratio * state.contact_area == pytest.approx(force, rel=1e-10)
        assert state.contact_area == state.contact_radius_deformed**2
        assert state.extra["force_ETR"] == pytest.approx(math.pi * force * state.pressure_initial, rel=1e-15)


def test_the_vertical_balance_at_the_equator(curve):
    """Conservation, independent of the residuals solved: the first integral 2 pi rho T_1 sin psi = P pi rho^2 - F
    at the equator (psi = pi/2), in units E T with F = pi Fhat Phat_I, from the profile's tension there."""
    _, _, _, _, states = curve
    for state in states:
        rho = state.extra["radius_equator"]
        pull = 2.0 * math.pi * rho * state.profile.tension_1[-1]
        assert pull == pytest.approx(math.pi * (state.pressure * rho**2 - state.force * state.pressure_initial),
                                     rel=1e-9)


def test_the_fluid_closes_the_capsule(curve):
    """Conservation: a liquid's volume is held, a gas's follows its polytropic law (the whole capsule's)."""
    _, phat, fluid, _, states = curve
    for state in states:
        expected = state.inflated.volume * (1.0 if fluid is None else fluid.volume_ratio(state.pressure, phat))
        assert state.volume == pytest.approx(expected, rel=1e-10)


def test_the_profile_is_closed_by_the_equators_symmetry(curve):
    """The meridian ends on the equatorial plane (eta = 0) at rho = radius_equator, flat on the plate (eta = H) up
    to the contact edge, and its hoop stretch at the edge is stretch_contact."""
    _, _, _, _, states = curve
    for state in states:
        profile = state.profile
        assert profile.r[-1] == pytest.approx(math.pi / 2, abs=1e-15)
        assert abs(profile.eta[-1]) < 1e-15  # the profile's own shot (finer steps) within rtol of the state's
        assert profile.rho[-1] == pytest.approx(state.extra["radius_equator"], rel=1e-9)
        np.testing.assert_allclose(profile.eta[profile.contact], state.height, rtol=1e-9)
        edge = np.flatnonzero(profile.contact)[-1]
        assert profile.r[edge] == pytest.approx(state.contact_radius, abs=1e-14)
        assert state.stretch_contact == pytest.approx(profile.stretch_2[edge], rel=1e-9)


def test_converged_in_the_integration_tolerance():
    """Convergence: every reported key at rtol 1e-10 (the default) within 1e-9 of rtol 1e-13."""
    forces = [0.01, 0.5, 2.0]
    for material, phat, fluid in CASES[:3]:
        coarse = shooting.compression_curve(material, phat, forces, fluid=fluid, geometry="capsule")
        fine = shooting.compression_curve(material, phat, forces, fluid=fluid, geometry="capsule", rtol=1e-13)
        for a, b in zip(coarse, fine, strict=False):
            np.testing.assert_allclose(_values(a), _values(b), rtol=1e-9)


def test_a_vanishing_force_is_a_point_contact():
    """Limit: as Fhat -> 0 the contact shrinks to a point, rho_c^2 -> Fhat (P -> P_I), the plate touches the
    sphere's pole (H -> lambda_I) and the pole's stretch is the sphere's."""
    inflated = shooting.inflate(0.2, 0.2, geometry="capsule")
    forces = [1e-8, 1e-6, 1e-4]
    states = shooting.compression_curve(0.2, 0.2, forces, geometry="capsule")
    gaps = [abs(s.contact_area / f - 1.0) for f, s in zip(forces, states, strict=False)]
    assert gaps[0] < gaps[1] < gaps[2]
    assert gaps[1] / gaps[0] == pytest.approx(100.0, rel=0.05)
    assert all(s.contact_radius < 2 * math.sqrt(f) for f, s in zip(forces, states, strict=False))
    assert inflated.height - states[0].height < 1e-6
    assert states[0].extra["stretch_pole"] == pytest.approx(inflated.stretch_pole, rel=1e-5)


def test_the_small_force_law():
    """Limit (the theory's dent): delta/R = (Fhat / 2 lambda) [ln(2 lambda^3 Phat_I / Fhat) + 1 - 2 gamma] for
    Fhat << Phat_I << 1. The bracket's error, (delta - law) 2 lambda / Fhat, tends to a limit as Fhat -> 0 (the
    corrections in Fhat / Phat_I vanish) which falls with Phat_I (those in Phat_I vanish)."""
    limits = []
    for phat in (0.06, 0.12, 0.24):
        states = shooting.compression_curve(0.0, phat, [1e-7, 1e-6, 1e-5], geometry="capsule")
        lam = states[0].inflated.stretch_pole
        errors = [(lam - s.height) * 2 * lam / s.force - (math.log(2 * lam**3 * phat / s.force) + 1 - 2 * EULER)
                  for s in states]
        assert abs(errors[0] - errors[1]) < abs(errors[1] - errors[2])  # settling as Fhat -> 0
        limits.append(errors[0])
    assert 0 < limits[0] < limits[1] < limits[2] < 0.5


def test_height_control_is_force_controls_inverse():
    """Two routes: the state at the height a force gave has that force back (travel control by Brent)."""
    state = shooting.compress(0.2, 0.2, 0.7, geometry="capsule")
    back = shooting.compress_height(0.2, 0.2, state.height, geometry="capsule")
    assert back.force == pytest.approx(0.7, rel=1e-8)


def test_a_slack_patch_is_returned_flagged_wrinkled():
    """At a low Phat_I the pole's stretch under the plate falls below 1 (its tension compressive): the state is
    returned, flagged wrinkled with a warning, and it is still a solution (F = P A_c, the volume held)."""
    taut, slack = shooting.compression_curve(0.0, 0.05, [0.1, 0.5], geometry="capsule")
    assert taut.extra["stretch_pole"] > 1.0
    assert not taut.wrinkled
    assert slack.extra["stretch_pole"] < 1.0
    assert slack.wrinkled
    assert slack.tension_1_min < 0.0
    assert any("compressive tension" in w for w in slack.warnings)
    assert slack.pressure_ratio * slack.contact_area == pytest.approx(0.5, rel=1e-10)
    assert slack.volume == pytest.approx(slack.inflated.volume, rel=1e-10)


@pytest.mark.slow
def test_the_range_ends_where_the_edge_goes_slack():
    """The end of the range at Phat_I = 0.01: the meridional tension at the contact edge falls to 0 (below 1 % of
    the inflated capsule's at the end quoted); a force above it is refused naming that, one below it solves."""
    end = shooting.range_end(0.0, 0.01, geometry="capsule")
    assert math.isfinite(end)
    with pytest.raises(OutOfRangeError, match="tension at the contact edge vanishes"):
        shooting.compress(0.0, 0.01, end * 1.001, geometry="capsule")
    last = shooting.compress(0.0, 0.01, end * (1 - 1e-3), geometry="capsule")
    edge = np.flatnonzero(last.profile.contact)[-1]
    assert 0.0 < last.profile.tension_1[edge] < 1e-2 * 0.5 * 0.01 * last.inflated.stretch_pole


def test_refusals():
    """One line each: a sphere between the plates is not posed; a pressure so low that even the most shooting
    segments cannot hold the amplification of the pole's errors fails with that reason."""
    with pytest.raises(InputError, match="between two flat plates"):
        shooting.compress(0.2, 0.2, 0.1, geometry="capsule", indenter=Sphere(0.5))
    assert amplification(0.02, 1.005) > 1e6 > amplification(0.1, 1.025)
    with pytest.raises(ConvergenceError, match="amplifies its errors"):
        shooting.compress(0.2, 1e-4, 1e-3, geometry="capsule")


@pytest.mark.slow  # the slow lane: each segment adds three unknowns to every Newton iteration
@pytest.mark.parametrize("phat", [0.02, 0.05])
def test_multiple_shooting_at_low_pressure(phat):
    """At low Phat_I the free part is shot in segments (each amplifying errors at most 100-fold): the states still
    hold F = P A_c, the equator's vertical balance and the volume, and converge in the integration tolerance."""
    forces = [0.1 * phat, 0.5 * phat]
    coarse = shooting.compression_curve(0.0, phat, forces, geometry="capsule")
    fine = shooting.compression_curve(0.0, phat, forces, geometry="capsule", rtol=1e-12)
    for force, a, b in zip(forces, coarse, fine, strict=True):
        np.testing.assert_allclose(_values(a), _values(b), rtol=1e-8)
        assert a.pressure_ratio * a.contact_area == pytest.approx(force, rel=1e-10)
        rho = a.extra["radius_equator"]
        pull = 2.0 * math.pi * rho * a.profile.tension_1[-1]
        assert pull == pytest.approx(math.pi * (a.pressure * rho**2 - force * phat), rel=1e-8)
        assert a.volume == pytest.approx(a.inflated.volume, rel=1e-10)
