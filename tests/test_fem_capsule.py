"""The finite-element capsule (``pocket.fem`` with ``geometry="capsule"``) against what it must satisfy.

Exact answers, each computed here: the inflated capsule is a sphere of uniform stretch with
Phat = w'(lambda) / (E lambda^2) (docs: theory, section 12; w the equibiaxial energy, differentiated here from
``pocket.core.materials.energy``); the neo-Hookean balloon's pressure maximum 4/7 7^(-1/6) at 7^(1/6); the plate's
force two ways (the reaction of the contact zone's nodes, and P times the deformed contact area); the fluid held;
the small force's pressure rise by Maxwell-Betti reciprocity, dP/dF = 2 (dH0/dP) / (dV0/dP) (two plates, each
moving by dH, do the work 2 F dH) plus a gas's compliance V / (gamma (P + P_atm)) in the denominator; the section's
equations integrated here from the finite elements' pole stretch, contact radius and pressure; and mesh
convergence at the full order of P2, the contact edge included (a vertex follows it).
"""

import dataclasses
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from pocket import fem
from pocket.core.errors import InputError, OutOfRangeError
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import as_material, check, energy

LAWS = {
    "mooney-rivlin-0": as_material(0.0),
    "mooney-rivlin-0.3": as_material(0.3),
    "neo-hookean": check("neo-hookean", {"mu": 2.0}),
    "yeoh": check("yeoh", {"c10": 0.5, "c20": -0.02, "c30": 0.003}),
    "gent": check("gent", {"mu": 1.0, "jm": 3.0}),
}


def closed_form_stretch(material, pressure: float, prestretch: float = 1.0) -> float:
    """lambda with Phat = w'(lambda) / (E lambda^2), w(lambda) = W(lambda_p lambda, lambda_p lambda) / lambda_p^2 the
    equibiaxial energy of the sheet prestretched by lambda_p (differentiated by central differences, h = 1e-6:
    error ~1e-12), E = 3 mu_0: the first root above the unstressed 1 / lambda_p."""

    def phat(lam):
        h, a, b = 1e-6, prestretch * (lam + 1e-6), prestretch * (lam - 1e-6)
        slope = (energy(material, a, a) - energy(material, b, b)) / (2 * h * prestretch**2)
        return float(slope) / (3.0 * material.mu0 * lam**2) - pressure

    return brentq(phat, 1.0 / prestretch, 1.35, xtol=1e-14)


@pytest.mark.parametrize("name", list(LAWS))
@pytest.mark.parametrize("pressure", [0.1, 0.35])
def test_inflated_capsule_is_the_closed_form_sphere(name, pressure):
    """Pole height, pole stretch, equatorial radius, equator's meridional stretch and (V / (4/3 pi))^(1/3) all equal
    the closed form's lambda to 1e-8 on the default mesh (P2, 256 elements: the O(h^4) error, about 1e-9 by the
    measured rate of ``test_inflation_converges_at_order_4``), and the contract's keys are there."""
    material = LAWS[name]
    lam = closed_form_stretch(material, pressure)
    state = fem.inflate(material, pressure, geometry="capsule")
    found = {"height": state.height, "stretch_pole": state.stretch_pole,
             "radius_equator": state.extra["radius_equator"], "stretch_clamp": state.stretch_clamp,
             "volume": (state.volume / (4.0 / 3.0 * math.pi)) ** (1.0 / 3.0)}
    for key, value in found.items():
        assert abs(value / lam - 1) < 1e-8, f"{key} {value!r} against lambda {lam!r}"
    assert state.extra["geometry"] == "capsule"
    assert state.pressure == pressure
    assert state.profile.r[0] == 0.0
    assert state.profile.r[-1] == math.pi / 2
    assert state.profile.eta[-1] == 0.0


@pytest.mark.parametrize("pressure", [0.05, 0.3])
def test_a_prestretched_capsule_inflates_to_the_prestretched_sphere(pressure):
    """Exact answer: with the prestretch lambda_p the energy per unit area of the reference sphere is
    W(lambda_p l, lambda_p l) / lambda_p^2 (``pocket.fem.laws``), so Phat = d/dl [W / lambda_p^2] / (E l^2), zero at
    l = 1 / lambda_p (the unstressed rubber) and 2 t(1) > 0 at l = 1; the finite-element sphere has that stretch to
    1e-8 (as above), below 1 at a small pressure."""
    lp = 1.1
    rubber = dataclasses.replace(LAWS["neo-hookean"], prestretch=lp)
    lam = closed_form_stretch(LAWS["neo-hookean"], pressure, prestretch=lp)
    state = fem.inflate(rubber, pressure, geometry="capsule")
    for key, value in (("height", state.height), ("stretch_pole", state.stretch_pole),
                       ("radius_equator", state.extra["radius_equator"])):
        assert abs(value / lam - 1) < 1e-8, f"{key} {value!r} against lambda {lam!r}"


def test_an_unpressurised_capsule_is_the_reference_sphere():
    """Exact answer: at Phat = 0 the capsule is its unstressed reference, lambda = 1: height and equatorial radius
    1, volume 4/3 pi to the interpolation of the sphere by P2 (1e-9)."""
    state = fem.inflate(0.2, 0.0, geometry="capsule")
    assert state.height == 1.0
    assert state.extra["radius_equator"] == 1.0
    assert abs(state.volume / (4.0 / 3.0 * math.pi) - 1) < 1e-9


def test_inflation_converges_at_order_4():
    """P2 on the default meshes of 8 to 128 elements: the height, pole stretch, equatorial radius and volume's
    errors against the closed form fall at order >= 3.5 (theory 4; measured 3.9 to 4.1)."""
    lam = closed_form_stretch(LAWS["mooney-rivlin-0.3"], 0.3)
    ns = (8, 16, 32, 64, 128)
    errors = []
    for n in ns:
        s = fem.inflate(LAWS["mooney-rivlin-0.3"], 0.3, geometry="capsule", elements=n)
        errors.append([abs(v / lam - 1) for v in (s.height, s.stretch_pole, s.extra["radius_equator"],
                                                   (s.volume / (4.0 / 3.0 * math.pi)) ** (1.0 / 3.0))])
    errors = np.array(errors)
    for j, key in enumerate(("height", "stretch_pole", "radius_equator", "volume")):
        order = np.polyfit(np.log(1.0 / np.array(ns)), np.log(errors[:, j]), 1)[0]
        assert order >= 3.5, f"{key}: order {order:.3f}, errors {errors[:, j]}"


def test_the_neo_hookean_balloon_has_its_pressure_maximum():
    """Exact answer: the neo-Hookean capsule's pressure is largest at lambda = 7^(1/6), Phat = 4/7 7^(-1/6)
    (0.41322): just below it a state exists, just above it is OutOfRangeError quoting that maximum."""
    peak = 4.0 / 7.0 * 7.0 ** (-1.0 / 6.0)
    below = fem.inflate(0.0, peak * (1 - 1e-4), geometry="capsule")
    assert below.height < 7.0 ** (1.0 / 6.0)
    with pytest.raises(OutOfRangeError, match=rf"pressure maximum Phat = {peak:.6g}"):
        fem.inflate(0.0, peak * (1 + 1e-4), geometry="capsule")


@pytest.mark.parametrize("fluid", [None, gas(1.0, 1.4)], ids=["liquid", "gas"])
@pytest.mark.parametrize("name", ["mooney-rivlin-0.3", "neo-hookean", "yeoh"])
def test_the_plate_force_two_ways_and_the_fluid_held(name, fluid):
    """The nodal reaction of the contact zone and P pi rho_c^2 both equal the force asked, to 1e-9 of it (Newton's
    tolerance); the liquid's volume is the inflated capsule's, the gas's obeys its law; the contract's identities
    hold: contact_area = Fhat / (P / P_I) = rho_c^2, stretch_contact = rho_c / sin a_c, force_ETR = pi Fhat Phat_I."""
    forces = [0.01, 0.3, 2.0]
    states = fem.compression_curve(LAWS[name], 0.2, forces, fluid=fluid, geometry="capsule")
    for force, s in zip(forces, states, strict=True):
        for key in ("force_reaction", "force_pressure_area"):
            assert abs(s.extra[key] / force - 1) < 1e-9, f"{key} {s.extra[key]!r} at Fhat {force}"
        if fluid is None:
            assert abs(s.volume / s.inflated.volume - 1) < 1e-9
        else:
            law = (s.pressure + fluid.ambient) * s.volume**fluid.gamma
            assert abs(law / ((s.pressure_initial + fluid.ambient) * s.inflated.volume**fluid.gamma) - 1) < 1e-9
        assert abs(s.contact_area * s.pressure_ratio / force - 1) < 1e-12
        assert abs(s.contact_radius_deformed**2 / s.contact_area - 1) < 1e-14
        assert abs(s.stretch_contact * math.sin(s.contact_radius) / s.contact_radius_deformed - 1) < 1e-14
        assert abs(s.extra["force_ETR"] / (math.pi * force * 0.2) - 1) < 1e-14
        assert s.extra["geometry"] == "capsule"
        assert s.profile.eta[-1] == 0.0
        assert s.height < s.inflated.height
        assert s.extra["radius_equator"] > s.inflated.extra["radius_equator"]


@pytest.mark.parametrize("fluid", [None, gas(1.0, 1.4)], ids=["liquid", "gas"])
def test_a_small_force_raises_the_pressure_by_reciprocity(fluid):
    """Exact limit (Maxwell-Betti): at F -> 0, dP/dF = 2 (dH0/dP) / (dV0/dP + V / (gamma (P + P_atm))) with
    H0 = lambda, V0 = 4/3 pi lambda^3 of the inflated sphere (lambda'(P) by central differences of the closed
    form), the gas's term absent for a liquid; in Fhat, d(P/P_I)/dFhat = pi dP/dF. The finite elements' (P/P_I - 1) /
    Fhat tends to it: within 1e-3 at Fhat = 1e-5, the deviation falling by more than 5 per decade of force
    (like Fhat ln(1/Fhat): the dent)."""
    material, p_i = LAWS["mooney-rivlin-0.3"], 0.2
    lam = closed_form_stretch(material, p_i)
    dlam = (closed_form_stretch(material, p_i + 1e-5) - closed_form_stretch(material, p_i - 1e-5)) / 2e-5
    volume = 4.0 / 3.0 * math.pi * lam**3
    compliance = 0.0 if fluid is None else volume / (fluid.gamma * (p_i + fluid.ambient))
    slope = math.pi * 2.0 * dlam / (4.0 * math.pi * lam**2 * dlam + compliance)
    forces = [1e-5, 1e-4]
    states = fem.compression_curve(material, p_i, forces, fluid=fluid, geometry="capsule")
    deviation = [abs((s.pressure_ratio - 1) / f / slope - 1) for s, f in zip(states, forces, strict=True)]
    assert deviation[0] < 1e-3, f"deviations {deviation} from {slope!r}"
    assert deviation[1] > 5 * deviation[0], f"deviations {deviation} from {slope!r}"


@pytest.mark.parametrize("force", [0.05, 0.5, 2.0])
def test_compression_converges_at_full_order(force):
    """Edge-fitted P2 on the default meshes of 16 to 128 elements against 1024: pressure ratio, height, contact
    area, contact radius (the edge), contact stretch, pole stretch and equatorial radius converge at order >= 3.5
    (theory 4: a vertex follows the contact edge, where the meridian's curvature jumps), 128 elements within 1e-7."""
    keys = ("pressure_ratio", "height", "contact_area", "contact_radius", "stretch_contact")
    extras = ("stretch_pole", "radius_equator")

    def values(n):
        s = fem.compress(0.1, 0.3, force, geometry="capsule", elements=n)
        return [getattr(s, k) for k in keys] + [s.extra[k] for k in extras]

    ns = (16, 32, 64, 128)
    ref = np.array(values(1024))
    errors = np.array([np.abs(np.array(values(n)) / ref - 1) for n in ns])
    for j, key in enumerate(keys + extras):
        order = np.polyfit(np.log(1.0 / np.array(ns)), np.log(errors[:, j]), 1)[0]
        assert order >= 3.5, f"{key} at Fhat {force}: order {order:.3f}, errors {errors[:, j]}"
        assert errors[-1, j] < 1e-7, f"{key} at Fhat {force}: errors {errors[:, j]}"


def test_the_capsule_is_pressed_by_plates_with_the_fitted_contact_only():
    """Exact answers: a sphere indenter and the penalty contact are refused in one line, before any work."""
    with pytest.raises(InputError, match=r"^the capsule is pressed between two flat plates: the sphere indenter"):
        fem.compress(0.1, 0.2, 0.5, geometry="capsule", indenter=Sphere(0.5))
    with pytest.raises(InputError, match=r"^contact = 'penalty' does not apply to the capsule"):
        fem.compress(0.1, 0.2, 0.5, geometry="capsule", contact="penalty")


def _tension(a, b, alpha):
    """Mooney-Rivlin's T_1(lambda_1 = a, lambda_2 = b) in units of E T (theory, section 3):
    (a/b - a^-3 b^-3)(1 + alpha b^2) / (3 (1 + alpha)); T_2 is T_1(b, a)."""
    return (a / b - 1.0 / (a**3 * b**3)) * (1.0 + alpha * b * b) / (3.0 * (1.0 + alpha))


def _slopes(a, b, alpha, h=1e-7):
    """(dT_1/dlambda_1, dT_1/dlambda_2) by central differences (error ~1e-13)."""
    return ((_tension(a + h, b, alpha) - _tension(a - h, b, alpha)) / (2 * h),
            (_tension(a, b + h, alpha) - _tension(a, b - h, alpha)) / (2 * h))


def _capsule_rhs(s, y, pressure, alpha, contact):
    """The theory's equations (section 12: eq-capsule-ode, eq-capsule-contact-ode, eq-capsule-volume) in S, for
    y = [rho, eta, psi, lambda_1, V], psi = 0 in the contact zone."""
    rho, psi, l1 = y[0], 0.0 if contact else y[2], y[3]
    l2 = rho / math.sin(s)
    drho = l1 * math.cos(psi)
    dl2 = (drho - l2 * math.cos(s)) / math.sin(s)
    t_1, t_2 = _tension(l1, l2, alpha), _tension(l2, l1, alpha)
    a11, a12 = _slopes(l1, l2, alpha)
    dpsi = 0.0 if contact else l1 * (pressure - t_2 * math.sin(psi) / rho) / t_1
    return [drho, -l1 * math.sin(psi), dpsi, ((t_2 - t_1) * drho / rho - a12 * dl2) / a11,
            2.0 * math.pi * rho**2 * l1 * math.sin(psi)]


@pytest.mark.parametrize(("alpha", "pressure", "force"), [(0.0, 0.1, 0.05), (0.2, 0.2, 0.5), (0.3, 0.35, 2.0)])
def test_the_theory_integrated_from_the_pole_lands_on_the_compressed_state(alpha, pressure, force):
    """Independent solution: the section's equations integrated (scipy, rtol 1e-12) from the finite elements' pole
    stretch (the contact zone's series eq-capsule-contact-series at S = 1e-3) over the contact zone to their a_c, then
    from psi = 0 over the free part at their P, reach their rho_c, the meridian vertical at the equator, their height
    H = eta(a_c) - eta(pi/2), equatorial radius and volume, within 1e-6 (the shot from the pole magnifies the pole
    stretch's error, ~1e-10, about e^(pi / (2 sqrt t)), t = lambda Phat_I / 2: section 12; measured 1e-7 at most)."""
    state = fem.compress(alpha, pressure, force, geometry="capsule")
    p, a, l0, s0 = state.pressure, state.contact_radius, state.extra["stretch_pole"], 1e-3
    big_a, big_b = _slopes(l0, l0, alpha)
    l1 = l0 + l0 * (big_a - 3 * big_b) / (16 * big_a) * s0**2
    l2 = l0 + l0 * (3 * big_a - big_b) / (16 * big_a) * s0**2
    zone = solve_ivp(_capsule_rhs, (s0, a), [l2 * math.sin(s0), 0.0, 0.0, l1, 0.0], args=(p, alpha, True),
                     rtol=1e-12, atol=1e-14).y[:, -1]
    free = solve_ivp(_capsule_rhs, (a, math.pi / 2), zone, args=(p, alpha, False), rtol=1e-12, atol=1e-14).y[:, -1]
    found = {"contact_radius_deformed": (zone[0], state.contact_radius_deformed),
             "height": (zone[1] - free[1], state.height), "volume": (free[4], state.volume),
             "radius_equator": (free[0], state.extra["radius_equator"]), "psi(pi/2) / (pi/2)": (free[2], math.pi / 2)}
    for key, (shot, fe) in found.items():
        assert abs(shot / fe - 1) < 1e-6, f"{key}: shot {shot!r}, finite elements {fe!r}"


def _quoted_end(call) -> float:
    """The end force an OutOfRangeError of ``call()`` quotes."""
    with pytest.raises(OutOfRangeError, match=r"the contact patch's tension vanishes at the pole") as caught:
        call()
    return float(str(caught.value).split("ends at force = ")[1].split()[0])


def test_the_range_ends_where_the_patch_goes_slack_at_the_pole():
    """Exact answer: the range ends at the force where the pole's stretch under the plate falls to 1 (no prestretch:
    the tension there vanishes). A gas-filled capsule (Phat_I = 0.1, Phat_atm = 1, gamma 1.4) reaches it below
    Fhat = 0.5: a force past it, alone, in a curve, or a plate height past it, is OutOfRangeError quoting the same
    end to its ten digits (located to 1e-12); there (1e-9 below the ten digits quoted) the pole's stretch is 1 to
    1e-9 (Newton's tolerance on the states it is located from), and further below the state is returned, taut."""
    fluid = gas(1.0, 1.4)
    ends = [_quoted_end(lambda: fem.compress(0.2, 0.1, 0.5, geometry="capsule", fluid=fluid)),
            _quoted_end(lambda: fem.compression_curve(0.2, 0.1, [0.01, 0.3, 2.0], geometry="capsule", fluid=fluid)),
            _quoted_end(lambda: fem.compress_height(0.2, 0.1, 0.5, geometry="capsule", fluid=fluid))]
    assert ends[1:] == ends[:-1], f"ends {ends}"
    at_end = fem.compress(0.2, 0.1, ends[0] * (1 - 1e-9), geometry="capsule", fluid=fluid)  # inside, rounding aside
    assert abs(at_end.extra["stretch_pole"] - 1.0) < 1e-9, f"pole stretch {at_end.extra['stretch_pole']!r}"
    below = fem.compress(0.2, 0.1, 0.99 * ends[0], geometry="capsule", fluid=fluid)
    assert below.extra["stretch_pole"] > 1.0
    assert not below.wrinkled


def test_volume_and_height_control_invert_pressure_and_force_control():
    """Exact answers: the capsule inflated to the volume of the one inflated at Phat = 0.3 is at Phat = 0.3, and the
    plates brought to the height of the capsule pressed by Fhat = 0.7 press with 0.7 (to Newton's tolerance, 1e-9);
    a volume past a Gent rubber's locking (Jm = 3: 2 l^2 + l^-4 - 3 = 3 at l = 1.72) is OutOfRangeError."""
    inflated = fem.inflate(0.2, 0.3, geometry="capsule")
    assert abs(fem.inflate_volume(0.2, inflated.volume, geometry="capsule").pressure / 0.3 - 1) < 1e-9
    pressed = fem.compress(0.2, 0.3, 0.7, geometry="capsule")
    assert abs(fem.compress_height(0.2, 0.3, pressed.height, geometry="capsule").force / 0.7 - 1) < 1e-9
    with pytest.raises(OutOfRangeError, match=r"is not reached before the rubber locks"):
        fem.inflate_volume(LAWS["gent"], 4.0 / 3.0 * math.pi * 1.8**3, geometry="capsule")
