"""The clamp's upper jaw (``pocket.solid.jaw``): its gap, its rows, and the states it holds.

Exact answers: the gap's gradient and Hessian are the limits of central difference quotients of the gap (and
of the gradient), the bordered Jacobian with the jaw's rows that of the residual; the gap is the distance to
the jaw's boundary, computed here from the geometry (a point on the edge's arc, on the side, on the face);
a converged state has no node inside the jaw (its gaps >= 0 to the tolerance), the jaw's forces are >= 0 and
push away from it, and the fluid's upward resultant p_f pi R^2 is the clamp's reaction plus the jaw's vertical
forces. ``clamp_radius = 0`` is no jaw: the solver's path without the jaw's rows, bit for bit.
"""

import numpy as np
import pytest
from pocket.solid import DEFAULT_CLAMP_RADIUS, DEFAULT_CORNER, contact, jaw, laws, mesh, model
from pocket.solid.equations import Control
from pocket.solid.model import split
from solidstates import bent, check_jacobian

from pocket import solid
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.indenters import Sphere
from pocket.core.materials import mooney_rivlin

MATERIAL = mooney_rivlin(47 / 160)
TOP, RADIUS = 0.01, 0.02  # the jaw's face z = TOP, its edge's radius (units R)
COARSE = {"elements": 8, "layers": 2}


def _points(rng, n=200):
    """Points (rho, z) in each region of the gap's formula, kept 1e-3 R off the regions' borders (where the
    Hessian jumps): the edge's sector (in and out of the circle), above it beside the side, beyond r = 1."""
    centre = TOP + RADIUS
    angle = np.pi + 0.5 * np.pi * rng.uniform(0.05, 0.95, n)
    d = RADIUS * rng.uniform(0.3, 3.0, n)
    edge = np.stack([1.0 + d * np.cos(angle), centre + d * np.sin(angle)], axis=1)
    side = np.stack([1.0 - RADIUS * rng.uniform(-0.9, 3.0, n), centre + rng.uniform(1e-3, 0.1, n)], axis=1)
    face = np.stack([1.0 + rng.uniform(1e-3, 0.1, n), TOP + rng.uniform(-0.1, 0.1, n)], axis=1)
    return np.concatenate([edge, side, face])


def test_the_gap_derivatives_are_the_difference_quotients():
    """grad_x g and d2g/dx2 of ``jaw.local`` equal the central difference quotients of g and of grad_x g (step
    1e-6 R: O(1e-12 / RADIUS^3) truncation, ~1e-10 round-off; a wrong term is off by O(1 / RADIUS))."""
    x = _points(np.random.default_rng(3))
    _g, grad, hess = jaw.local(x[:, 0], x[:, 1], TOP, RADIUS)
    step = 1e-6
    for axis in range(2):
        e = np.zeros(2)
        e[axis] = step
        gp, grad_p, _ = jaw.local(x[:, 0] + e[0], x[:, 1] + e[1], TOP, RADIUS)
        gm, grad_m, _ = jaw.local(x[:, 0] - e[0], x[:, 1] - e[1], TOP, RADIUS)
        np.testing.assert_allclose(grad[:, axis], (gp - gm) / (2 * step), rtol=0, atol=1e-7)
        np.testing.assert_allclose(hess[:, :, axis], (grad_p - grad_m) / (2 * step), rtol=0, atol=1e-4 / RADIUS)


def test_the_gap_is_the_distance_to_the_jaw():
    """Outside the jaw g is the distance to its boundary, the smallest of the distances to the edge's quarter
    arc (sampled finely), to the side r = 1 - a above it and to the face z = t/2 beyond r = 1; inside it, below 0.
    The gap and its gradient are continuous across the regions' borders."""
    x = _points(np.random.default_rng(4))
    g = jaw.local(x[:, 0], x[:, 1], TOP, RADIUS)[0]
    phi = np.linspace(np.pi, 1.5 * np.pi, 20001)
    arc = np.stack([1.0 + RADIUS * np.cos(phi), TOP + RADIUS + RADIUS * np.sin(phi)], axis=1)
    to_arc = np.min(np.hypot(x[:, None, 0] - arc[None, :, 0], x[:, None, 1] - arc[None, :, 1]), axis=1)
    to_side = np.hypot(x[:, 0] - (1.0 - RADIUS), np.maximum(TOP + RADIUS - x[:, 1], 0.0))
    to_face = np.hypot(np.maximum(1.0 - x[:, 0], 0.0), x[:, 1] - TOP)
    inside = ((x[:, 0] > 1.0) & (x[:, 1] > TOP)) | (np.hypot(x[:, 0] - 1.0, x[:, 1] - TOP - RADIUS) < RADIUS) | (
        (x[:, 0] > 1.0 - RADIUS) & (x[:, 1] > TOP + RADIUS))
    outside = ~inside
    # the arc sampled every dphi = pi/2 / 20000: the nearest sample is off by at most dphi / 2 in angle, which
    # lengthens the distance by about |x - c| RADIUS (dphi / 2)^2 / (2 g) (twice that allowed, and round-off); a
    # wrong centre or radius is off by ~RADIUS
    sampling = np.hypot(x[:, 0] - 1.0, x[:, 1] - TOP - RADIUS) * RADIUS * (np.pi / 80000) ** 2 / np.abs(g)
    distance = np.minimum(np.minimum(to_arc, to_side), to_face)
    assert np.all(np.abs(g - distance)[outside] <= (sampling + 1e-15)[outside])
    assert np.all(g[inside] < 0.0)
    for a, b in (((1.0, TOP - 0.05), (1.0, TOP - 0.05)), ((1.0 - 3 * RADIUS, TOP + RADIUS),) * 2):
        near = jaw.local(np.array([a[0] - 1e-12, b[0] + 1e-12]), np.array([a[1] - 1e-12, b[1] + 1e-12]), TOP,
                         RADIUS)
        np.testing.assert_allclose(near[0][0], near[0][1], atol=1e-11)
        np.testing.assert_allclose(near[1][0], near[1][1], atol=1e-9)


def test_the_jacobian_with_the_jaw_is_the_derivative_of_the_residual():
    """The bordered Jacobian with the jaw's rows (active nodes on its edge, inactive ones, and a sphere's rows
    before them) applied to a random direction is the central difference quotient of the residual along it."""
    t = 0.05
    m = model.discretize(t, mesh.section(t, 8, 2, DEFAULT_CORNER), laws.derivatives(MATERIAL.scaled()))
    rng = np.random.default_rng(6)
    u = bent(m, rng)
    candidates = jaw.candidates(m)
    active = np.zeros(candidates.size, bool)
    active[-3:] = True  # the three nodes beside the clamp: in the edge's sector of a jaw of radius t
    mu = np.where(active, 0.5 + rng.random(candidates.size), 0.0)
    lam = 0.5 + rng.random(2)
    y = np.concatenate([u, 0.1 * rng.standard_normal(m.basis_p.N), [0.02, 0.33], lam, mu])
    control = Control(pressure=0.1, active=np.array([0, 1]), surface=contact.Surface(Sphere(0.5)), force=0.5,
                      jaw=jaw.Jaw(t, active))
    rho, z = contact.positions(m, y, candidates[active])
    assert np.all((rho <= 1.0) & (z <= 0.5 * t + t))  # the edge's sector: its curvature terms are exercised
    check_jacobian(m, y, control, rng)


@pytest.fixture(scope="module")
def jawed():
    """The headline pocket (alpha = 47/160, T/R = 0.0125) inflated to Phat = 1 against a jaw of radius T, on the
    coarsest mesh: (model, y, jaw radius)."""
    from pocket.solid import api, inflation

    t = solid.DEFAULT_THICKNESS
    section = mesh.section(t, COARSE["elements"], COARSE["layers"], DEFAULT_CORNER)
    m = model.discretize(t, section, laws.derivatives(MATERIAL.scaled()))
    clamp = api._jaw(1.0, m)
    y, _ = inflation.to_pressure(m, 3.0 * t * 1.0, 1e-10, clamp)
    return m, y, clamp.radius


def test_no_node_is_inside_the_jaw_and_its_forces_push_out(jawed):
    """At the converged state every upper-surface node is outside the jaw (by the geometry: not above its face
    beyond r = 1, not inside its edge's circle nor beside its side; to 1e-12 R), some touch it, and the forces
    the rubber and the fluid exert on the touching nodes (minus the residual without the jaw's terms) point into
    the jaw: the jaw's reaction on them points out of it (away from its edge's centre on the edge, towards the axis
    on its side: the sheet, past a hemisphere at Phat = 1, lies against it), mu >= 0."""
    m, y, a = jawed
    t = m.thickness
    rho, z = contact.positions(m, y, np.arange(m.top_r.size))
    depth = np.maximum.reduce([np.minimum(rho - 1.0, z - 0.5 * t), a - np.hypot(rho - 1.0, z - 0.5 * t - a),
                               np.minimum(rho - (1.0 - a), z - 0.5 * t - a)])
    print(f"deepest node inside the jaw: {depth.max():.3g} R (the clamped node on its face: 0)")
    assert depth[m.top_r < 1.0].max() <= 1e-12
    mu = jaw.multipliers(m, y)
    on = jaw.candidates(m)[mu > 1e-12]
    print(f"nodes on the jaw: {on.size}, at {(1.0 - m.top_r[on]) / t} T from the clamp, mu = {mu[mu > 1e-12]}")
    assert on.size > 0
    assert mu.min() >= -1e-12
    u, p = split(m, y)
    residual = model.solid(m, u, p)[0] - y[m.size] * model.fluid(m, u)[1]
    # the residual of the rubber and the fluid, dPi/du, is minus their force on a node: the jaw's reaction
    reaction = np.stack([residual[m.top_radial[on]], residual[m.top_z[on]]], axis=1)
    rho, z = contact.positions(m, y, on)
    outward = np.stack([rho - 1.0, z - 0.5 * t - a], axis=1)  # from the edge's centre ...
    outward[z > 0.5 * t + a] = [-1.0, 0.0]  # ... or, above it, from the side
    assert np.all(np.einsum("ij,ij->i", reaction, outward) > 0.0)


def test_no_state_on_the_inflation_path_sinks_into_the_jaw():
    """The path's states are solved loosely (Newton's step to ``inflation.PATH_TOL``, 1e-3 R: 8 % of T at T/R =
    0.0125), but the jaw's active set is not: a node joins once it is ``SWEEP_TOL`` inside the jaw, whatever the
    tolerance, so no free node of any state on the path lies deeper. (Joining at the path's tolerance let the
    corner's nodes sink up to 0.07 T into the jaw, which folded a mesh of short corner elements.)"""
    from pocket.solid import api, inflation
    from pocket.solid.newton import SWEEP_TOL

    t = solid.DEFAULT_THICKNESS
    section = mesh.section(t, COARSE["elements"], COARSE["layers"], DEFAULT_CORNER)
    m = model.discretize(t, section, laws.derivatives(MATERIAL.scaled()))
    deepest = []
    for _, y, _, held in inflation._path(m, 0.9, 1e-10, api._jaw(DEFAULT_CLAMP_RADIUS, m)):
        gap = jaw._gaps(m, held, y)[0]
        deepest.append(gap[~held.mask(m)].min(initial=np.inf))
    print(f"the deepest free node of each path state inside the jaw: {np.array(deepest) / t} T")
    assert min(deepest) >= -SWEEP_TOL


def test_the_fluid_is_held_by_the_clamp_and_the_jaw(jawed):
    """Global vertical equilibrium: p_f pi R^2 equals the clamp's reaction plus the jaw's downward forces
    -sum_k mu_k dg_k/dz (the clamp's reaction read from its dofs' residual, as under the plate)."""
    m, y, a = jawed
    u, p = split(m, y)
    pf = y[m.size]
    residual = model.solid(m, u, p)[0] - pf * model.fluid(m, u)[1]
    clamp = -residual[m.basis_u.get_dofs("right").all("u^2")].sum()
    nodes = jaw.candidates(m)
    rho, z = contact.positions(m, y, nodes)
    grad = jaw.local(rho, z, 0.5 * m.thickness, a)[1]
    held = -np.sum(jaw.multipliers(m, y) * grad[:, 1])
    print(f"p_f pi = {pf * np.pi:.15g}, clamp + jaw = {clamp + held:.15g} (the jaw's part {held:.3g})")
    assert held > 0.0  # the jaw holds the sheet down
    # Newton's last increment is below 1e-10 R, the residual quadratically smaller
    assert abs(pf * np.pi - (clamp + held)) <= 1e-9 * pf * np.pi


def test_no_jaw_is_the_solver_without_the_jaw():
    """clamp_radius = 0 is the clamp without a jaw: the same state, bit for bit, as the inflation without the
    jaw's rows; the default jaw (DEFAULT_CLAMP_RADIUS) holds the inflated headline pocket (its sheet touches the
    edge), so its state differs."""
    from pocket.solid import api, inflation, results

    plain = solid.inflate(MATERIAL, 0.31, clamp_radius=0, **COARSE)
    t = solid.DEFAULT_THICKNESS
    m = model.discretize(t, mesh.section(t, COARSE["elements"], COARSE["layers"], DEFAULT_CORNER),
                         laws.derivatives(MATERIAL.scaled()))
    assert api._jaw(0.0, m) is None
    y, iterations = inflation.to_pressure(m, 3.0 * t * 0.31, 1e-10, None)
    without = results.inflated(m, MATERIAL, y, iterations, pressure=0.31)
    assert (without.volume, without.height) == (plain.volume, plain.height)
    assert solid.inflate(MATERIAL, 0.31, **COARSE).volume != plain.volume
    assert DEFAULT_CLAMP_RADIUS > 0.0


def test_a_bad_clamp_radius_is_an_input_error():
    """A negative radius, or one of half the clamp's radius or more, is refused in one line; on the command line
    with exit status 2."""
    with pytest.raises(InputError, match="clamp_radius"):
        solid.inflate(MATERIAL, 0.31, clamp_radius=-1.0, **COARSE)
    with pytest.raises(InputError, match="half the clamp's radius"):
        solid.inflate(MATERIAL, 0.31, clamp_radius=40.0, **COARSE)
    assert main(["inflate", "--solver", "solid", "--alpha", "0.3", "--pressure", "0.3", "--clamp-radius", "-1"]) == 2


@pytest.mark.slow
def test_the_range_command_reaches_the_last_force(capsys):
    """The range command that stops at Fhat = 5.43 without a jaw (``test_solid_stop``, ``--clamp-radius 0``)
    solves all five forces to Fhat = 9 with the default jaw (radius T/2, which the default corner elements, T/2
    long, resolve), its pressure rising with the force, every state reached at its force."""
    import json

    args = ["compress", "--solver", "solid", "--thickness-ratio", "0.0125", "--alpha", "0.3", "--pressure", "0.3",
            "--force", "1", "3", "5", "7", "9", "--json"]
    assert main(args) == 0
    out = capsys.readouterr().out
    print(out[-2000:])
    states = json.loads(out)
    assert [s["force"] for s in states] == [1, 3, 5, 7, 9]
    ratios = [s["pressure_ratio"] for s in states]
    assert np.all(np.diff(ratios) > 0.0)


def test_a_failed_landing_on_the_pressure_is_narrowed_in_volume(monkeypatch):
    """Newton failing from the interpolated bracket (told to fail, twice: the jaw's first contact within the
    bracket made it fail at finer corners) lands all the same, by narrowing the bracket in volume: the same state
    as the direct landing, to the Newton tolerance (1e-10 R: 1e-8 relative in V is a hundred times that)."""
    from pocket.solid import inflation

    from pocket.core.errors import ConvergenceError

    plain = solid.inflate(MATERIAL, 0.31, clamp_radius=1.0, **COARSE)
    real, failed = inflation._solve, []

    def solve(model, y, control, tol):
        if control.pressure is not None and len(failed) < 2:
            failed.append(control.pressure)
            raise ConvergenceError("told to fail", iterations=1)
        return real(model, y, control, tol)

    monkeypatch.setattr(inflation, "_solve", solve)
    landed = solid.inflate(MATERIAL, 0.31, clamp_radius=1.0, **COARSE)
    assert len(failed) == 2
    assert abs(landed.volume / plain.volume - 1.0) < 1e-8
    assert abs(landed.height / plain.height - 1.0) < 1e-8


@pytest.mark.slow
def test_the_jaw_pressing_the_sheet_below_the_clamp_plane_is_not_the_range_end():
    """Under a jaw of radius T, at corner elements T/16, the jaw presses the mid-surface's node beside the clamp a
    little below the clamp plane already when inflated; the range's end (the free sheet reaching the plane) is
    not there: the free part ends where the jaw's edge begins, and Fhat = 1 solves."""
    t = solid.DEFAULT_THICKNESS
    state = solid.compress(0.3, 0.3, 1.0, thickness_ratio=t, clamp_radius=1.0, corner=0.0625)
    profile = state.inflated.profile
    beneath = profile.r > 1.0 - t
    print(f"inflated mid-surface beneath the jaw's edge, lowest: {profile.eta[beneath][:-1].min() / t:.3g} T; "
          f"free part, lowest: {profile.eta[~beneath].min() / t:.3g} T")
    assert profile.eta[beneath][:-1].min() < 0.0
    assert profile.eta[~beneath].min() > 0.0
    assert state.force == 1.0
