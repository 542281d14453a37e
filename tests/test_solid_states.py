"""The solid's states: equilibrium, contact, incompressibility and its input checks.

Exact answers: global vertical equilibrium (the fluid's upward resultant p_f pi R^2, the lower
surface spanning rho in [0, R], equals the clamp's reaction plus the plate's force); the
plate's reaction is the force asked; the sheet's volume is kept (the constant is a bilinear
pressure, so int (J - 1) dV = 0 is one of the constraint's equations); the contact is
complementary (active nodes on the plate with forces >= 0, the rest below it).
"""

import dataclasses

import numpy as np
import pytest
from pocket.solid import DEFAULT_CORNER, compression, inflation, kinematics, laws, mesh, model, post
from pocket.solid.model import split

from pocket import shooting, solid
from pocket.cli import main
from pocket.core.errors import InputError
from pocket.core.materials import mooney_rivlin

T, ELEMENTS, PHAT, FORCE = 0.0125, 32, 0.31, 0.5
TOL = 1e-10


@pytest.fixture(scope="module")
def pressed():
    """The headline pocket (alpha = 47/160, Phat_I = 0.31) pressed at Fhat = 0.5: (model, y, control)."""
    m = model.discretize(T, mesh.section(T, ELEMENTS, 2, DEFAULT_CORNER),
                         laws.derivatives(mooney_rivlin(47 / 160).scaled()))
    p_i = 3.0 * T * PHAT
    y, _ = inflation.to_pressure(m, p_i, TOL)
    v_i = model.fluid(m, split(m, y)[0])[0]
    y, control = compression.first_contact(m, y, compression.fluid_control(m, solid_fluid(), PHAT, v_i))
    y, control, _ = compression.to_force(m, y, control, FORCE * np.pi * p_i, np.pi * p_i, TOL)
    return m, y, control, v_i


def solid_fluid():
    from pocket.core.fluids import LIQUID

    return LIQUID


def test_global_vertical_equilibrium(pressed):
    """p_f pi R^2 = clamp reaction + plate force, the clamp's reaction read from the residual of its dofs."""
    m, y, _control, _ = pressed
    u, p = split(m, y)
    r_u = model.solid(m, u, p)[0]
    pf = y[m.size]
    residual = r_u - pf * model.fluid(m, u)[1]
    clamp_z = m.basis_u.get_dofs("right").all("u^2")
    # the free dofs' rows (with the contact forces) vanish and the rubber's rows sum to 0 over all z dofs (a
    # rigid lift costs no energy), so minus the clamp rows' sum is the force holding the sheet down there
    clamp = -residual[clamp_z].sum()
    plate = y[m.size + 2:].sum()
    print(f"p_f pi = {pf * np.pi:.15g}, plate + clamp = {plate + clamp:.15g}")
    # Newton's last increment is below 1e-10 R, the residual quadratically smaller; forces here are ~0.1
    assert abs(pf * np.pi - (plate + clamp)) <= 1e-9 * pf * np.pi


def test_the_reaction_is_the_force_and_the_contact_is_complementary(pressed):
    """The contact forces sum to the force asked; active nodes lie on the plate, carry forces >= 0; the rest
    are below it; a liquid keeps its volume."""
    m, y, control, v_i = pressed
    lam, h = y[m.size + 2:], y[m.size + 1]
    z = 0.5 * T + y[m.top_z]
    unit = np.pi * 3.0 * T * PHAT
    assert lam.sum() == pytest.approx(FORCE * unit, rel=1e-12)  # one equation of the Newton system
    assert np.all(lam >= 0.0)
    assert np.abs(z[control.active] - h).max() <= TOL  # the contact rows, to the Newton tolerance
    free = np.setdiff1d(np.arange(z.size), control.active)
    assert np.all(z[free] <= h + 1e-7)  # the active set's test (newton.SWEEP_TOL)
    assert model.fluid(m, split(m, y)[0])[0] == pytest.approx(v_i, rel=1e-10)


def test_the_contact_edge_lies_in_the_bracket_of_the_active_set(pressed):
    """The state's contact radius lies within a node of the active set's edge: between the last active node but
    one and the first free node."""
    from pocket.solid.results import contact_radius

    m, y, control, _ = pressed
    edge = int(np.max(control.active))
    r_c = contact_radius(m, y, control.active)
    assert m.top_r[edge - 1] <= r_c <= m.top_r[edge + 1]


@pytest.mark.parametrize("exponent", [2.0, 1.5])
def test_the_contact_edge_from_the_gaps_beyond_it(exponent):
    """Exact answer: a gap g = c (r - r_c)^2 beyond the edge gives r_c back to round-off (g^(1/2) is linear
    in r there); a Hertz-like gap (r - r_c)^(3/2) gives r_c within the bracket and closer than the outermost
    active node (the estimate's bias, not its exactness)."""
    import types

    from pocket.solid.results import contact_radius

    r = np.linspace(0.0, 1.0, 41)
    r_true, h, c = 0.4371, 0.3, 0.8
    active = np.flatnonzero(r <= r_true)
    z = h - c * np.maximum(r - r_true, 0.0) ** exponent  # the upper surface; on the plate inside the edge
    fake = types.SimpleNamespace(top_r=r, top_z=np.arange(r.size), thickness=0.02, size=r.size)
    y = np.concatenate([z - 0.01, [0.0, h]])  # u_z = z - t/2, then p_f and the plate's height
    r_c = contact_radius(fake, y, active)
    if exponent == 2.0:
        assert r_c == pytest.approx(r_true, abs=1e-12)
    else:
        assert r[active[-2]] <= r_c <= r[active[-1] + 1]
        assert abs(r_c - r_true) < r_true - r[active[-1]]


def test_the_bisected_active_set_is_the_update_rules_set(pressed, monkeypatch):
    """Bisecting the contact disc's edge (``newton._bisect``) only shortens the search: with the plain update
    rules (every negative force leaves, every node above the plate joins) the same force reaches the same active
    set and the same state, to the Newton tolerance."""
    from pocket.solid import newton

    m, y, control, v_i = pressed
    unit = np.pi * 3.0 * T * PHAT
    start = compression.first_contact(m, inflation.to_pressure(m, 3.0 * T * PHAT, TOL)[0],
                                      compression.fluid_control(m, solid_fluid(), PHAT, v_i))
    monkeypatch.setattr(newton, "_bisect", lambda active, new, *rest: new)
    y_plain, control_plain, _ = compression.to_force(m, *start, FORCE * unit, unit, TOL)
    np.testing.assert_array_equal(control_plain.active, control.active)
    # both converged to 1e-10 R in the displacement increment: states agree to a few times that
    assert np.abs(y_plain[:m.size + 2] - y[:m.size + 2]).max() <= 1e-9 * max(1.0, np.abs(y).max())


@pytest.mark.parametrize("known", ["right", "too_many"])
def test_a_disc_known_in_contact_only_shortens_the_search(pressed, known):
    """The hint ``Control.known`` (the first nodes known to touch the plate, carried to the next load by
    ``edgemesh.transfer``) narrows the search of the active set but does not decide it: pressed on from
    Fhat = 0.5 to 0.6, the state and its set are the same with no hint, the right one (the disc in contact at
    0.5, still pressed at 0.6) and a wrong one (ten nodes more than touch at 0.6), to the Newton tolerance."""
    m, y, control, _ = pressed
    unit = np.pi * 3.0 * T * PHAT
    plain, plain_control, _ = compression.to_force(m, y, control, 1.2 * FORCE * unit, unit, TOL)
    count = len(control.active) if known == "right" else len(plain_control.active) + 10
    hinted, hinted_control, _ = compression.to_force(m, y, dataclasses.replace(control, known=count),
                                                     1.2 * FORCE * unit, unit, TOL)
    np.testing.assert_array_equal(hinted_control.active, plain_control.active)
    assert hinted_control.known == 0  # a hint holds for one load: the state returned carries none
    # both converged to 1e-10 R in the displacement increment: states agree to a few times that
    assert np.abs(hinted[:m.size + 2] - plain[:m.size + 2]).max() <= 1e-9 * max(1.0, np.abs(plain).max())


def test_the_first_update_takes_the_rules_disc_and_later_ones_halve():
    """``newton._bisect`` on made-up sets: a disc of 33 nodes too large (the last node's force negative) with
    the disc of 32 as the rules' set: the first update takes it, a later one halves the bracket instead."""
    from pocket.solid.newton import _bisect, _Bracket

    disc, rules, none = np.arange(33), np.arange(32), np.array([], dtype=int)
    first = _Bracket(low=20)
    np.testing.assert_array_equal(_bisect(disc, rules, none, False, first), rules)
    assert (first.low, first.high) == (20, 33)
    later = _Bracket(low=20, updates=1)
    np.testing.assert_array_equal(_bisect(disc, rules, none, False, later), np.arange(26))  # edge (20 + 33) // 2


def test_the_sheet_keeps_its_volume(pressed):
    """int (J - 1) 2 pi r dr dz = 0 to the Newton tolerance: the constant is in the bilinear pressure space."""
    m, y, _, _ = pressed
    u = split(m, y)[0]
    uq = m.basis_u.interpolate(u)
    x = m.basis_u.global_coordinates()
    J = kinematics.jacobian(kinematics.gradient(uq.grad, uq[0], x[0]))
    change = np.sum((J - 1.0) * m.basis_u.dx * 2.0 * np.pi * x[0])
    volume = np.pi * T
    print(f"relative change of the sheet's volume: {change / volume:.3e}")
    assert abs(change) <= 1e-9 * volume  # the constraint's residual at the Newton tolerance, relative


def test_the_weak_incompressibility_is_at_the_solver_tolerance(pressed):
    """Taylor-Hood's constraint int q (J - 1) dV = 0 (q bilinear) is one block of the equations Newton solves:
    its residual, relative to int q dV, is below the tolerance read as a strain (tol / R = 1e-10; the last
    step of 1e-10 R leaves a residual quadratically smaller, so round-off, ~1e-14, is what remains), while
    the pointwise |J - 1| at the clamp's corners is a discretisation error of order one."""
    m, y, _, _ = pressed
    f = post.fields(m, y)
    print(f"weak {f.det_f_constraint_residual:.3e}, largest pointwise {f.mesh_det_f_error_peak:.3e}")
    assert f.det_f_constraint_residual <= TOL, f.det_f_constraint_residual
    assert f.mesh_det_f_error_peak > 1e3 * TOL  # another quantity: the test tells them apart


def test_pointwise_incompressibility_converges_away_from_the_clamp():
    """|det F - 1| at the quadrature points is not the solver's tolerance (Taylor-Hood holds J = 1 in the mean
    against bilinear pressures) but a discretisation error: measured at the inflated headline pocket on
    r < 0.9 (the clamp's corner is singular), it falls under refinement along the radius at a fitted order
    printed here; at least 1.5 is asserted (the biquadratic displacement's gradient is O(h^2))."""
    peaks = []
    sizes = (16, 32, 64)
    for n in sizes:
        m = model.discretize(T, mesh.section(T, n, 2, DEFAULT_CORNER),
                             laws.derivatives(mooney_rivlin(47 / 160).scaled()))
        y, _ = inflation.to_pressure(m, 3.0 * T * PHAT, TOL)
        uq = m.basis_u.interpolate(split(m, y)[0])
        x = m.basis_u.global_coordinates()
        J = kinematics.jacobian(kinematics.gradient(uq.grad, uq[0], x[0]))
        peaks.append(np.abs(J - 1.0)[x[0] < 0.9].max())
    order = -np.polyfit(np.log(sizes), np.log(peaks), 1)[0]
    print(f"max |J - 1| on r < 0.9: {peaks}, order {order:.2f}")
    assert order > 1.5
    assert peaks[-1] < 1e-3


def test_the_membrane_and_the_solid_agree_to_order_t():
    """At T/R = 0.0125 the inflated headline pocket's heights and volume lie within 2 T/R (relative) of the
    membrane's (the measured difference is about 1.0 T/R in the volume, ``test_solid_thin``)."""
    s = solid.inflate(47 / 160, PHAT, thickness_ratio=T, elements=ELEMENTS)
    ref = shooting.inflate(47 / 160, PHAT)
    for key, value in (("height_mid", s.extra["height_mid"]), ("volume", s.volume)):
        target = ref.height if key == "height_mid" else ref.volume
        assert abs(value / target - 1.0) < 2.0 * T, (key, value, target)


@pytest.mark.parametrize(("flags", "text"), [
    (["--thickness-ratio", "0"], "--thickness-ratio = 0"),
    (["--thickness-ratio", "0.5"], "--thickness-ratio = 0.5"),
    (["--thickness-ratio", "-0.01"], "--thickness-ratio = -0.01"),
    (["--layers", "1"], "--layers = 1"),
    (["--elements", "2"], "--elements = 2"),
])
def test_bad_input_is_one_line_and_exit_2(flags, text, capsys):
    """A thickness ratio outside (0, 0.5), too few layers or elements: exit 2 and one line naming the flag."""
    status = main(["compress", "--alpha", "0.3", "--pressure", "0.31", "--force", "0.2", "--solver", "solid", *flags])
    err = capsys.readouterr().err
    assert status == 2, err
    assert text in err, err
    assert err.count("\n") == 1, err


def test_bad_input_in_python_before_any_work():
    """The same checks from Python: InputError, one line, naming the keyword."""
    for kwargs in ({"thickness_ratio": 0.0}, {"thickness_ratio": 0.7}, {"layers": 1}):
        with pytest.raises(InputError) as err:
            solid.inflate(0.3, 0.31, **kwargs)
        assert "\n" not in str(err.value)
        assert next(iter(kwargs)) in str(err.value)


def test_a_coarse_mesh_pressed_to_where_the_bisection_tries_the_pole_alone_solves(monkeypatch):
    """On 8 x 2 elements, pressing a pocket to 0.9 H0 made the bisection of the contact disc's edge try the disc of
    one node, which it built empty (a raw ValueError: argmax of an empty sequence). The disc of one node is the
    pole's: the state solves, and it is the state the plain update rules reach (to the Newton tolerance)."""
    from pocket.solid import newton

    options = {"thickness_ratio": 0.02, "elements": 8, "layers": 2}
    height = 0.9 * solid.inflate(47 / 160, 0.3, **options).height
    pressed = solid.compress_height(47 / 160, 0.3, height, **options)
    monkeypatch.setattr(newton, "_bisect", lambda active, new, *rest: new)
    plain = solid.compress_height(47 / 160, 0.3, height, **options)
    assert pressed.height == pytest.approx(height, rel=1e-12)
    for key in ("force", "pressure_ratio", "contact_radius", "volume"):
        assert getattr(pressed, key) == pytest.approx(getattr(plain, key), rel=1e-8), key
