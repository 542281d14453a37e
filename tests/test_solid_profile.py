"""The solid pressed by a user's profile (``pocket.solid.contact``: the vertical gap g = h + f(rho) - z).

Exact answers: the bordered Jacobian with a profile's contact rows is the derivative of the residual
(central differences); a profile table sampled from a sphere presses the sheet as that sphere does (an
independent formulation: the sphere's gap is the distance to its centre, the profile's a vertical
difference through a spline), to the table's interpolation error; the contact area is the curved area.
"""

import numpy as np
import pytest
from pocket.solid import DEFAULT_CORNER, contact, laws, mesh, model
from pocket.solid.equations import Control
from solidstates import bent, check_jacobian

from pocket import solid
from pocket.core.indenters import Profile, Sphere
from pocket.core.materials import mooney_rivlin
from pocket.core.profiles import table

K, T, PHAT, FORCE = 0.4, 0.02, 0.31, 0.3


def _sphere_table(rows: int):
    """The sphere of radius K as a profile table of ``rows`` rows to 0.9 K."""
    rho = np.linspace(0.0, 0.9 * K, rows)
    return table(rho, K - np.sqrt(K * K - rho * rho))


@pytest.mark.parametrize("held", ["force", "height"])
def test_the_profile_jacobian_is_the_derivative_of_the_residual(held):
    """Central differences of the residual along a random direction equal the Jacobian's product with it
    (a wrong or missing curvature term is off by O(1))."""
    t, h = 0.05, 0.33
    m = model.discretize(t, mesh.section(t, 8, 2, DEFAULT_CORNER), laws.derivatives(mooney_rivlin(47 / 160).scaled()))
    rng = np.random.default_rng(7)
    u = bent(m, rng)
    active = np.array([0, 1, 2, 3])
    y = np.concatenate([u, 0.1 * rng.standard_normal(m.basis_p.N), [0.02, h], 0.5 + rng.random(active.size)])
    gas = lambda pf: (0.4 / (1 + pf), -0.4 / (1 + pf) ** 2)  # noqa: E731  (any smooth V(p_f))
    surface = contact.Surface(Profile(_sphere_table(30)))
    control = Control(volume=gas, active=active, surface=surface, **{held: 0.5})
    direction, atol = check_jacobian(m, y, control, rng)
    rows = contact.rows(m, surface, y, active)
    assert np.abs(rows.k_uu @ direction[:m.basis_u.N]).max() > 1e3 * atol  # the curvature term matters here


@pytest.mark.slow
def test_a_table_of_a_sphere_presses_as_the_sphere(monkeypatch):
    """The profile sampled from the sphere K = 0.4 (40 rows) against the sphere itself: the same pressure ratio,
    lowest point to the spline's error, the contact area to the edge estimate's. On 64 elements as asked (the mesh
    that follows the edge, ``pocket.solid.edgemesh``, left out): the same nodes touch both surfaces, where a
    cluster about each one's edge estimate would mesh them ~1e-4 R apart."""
    from pocket.solid import edgemesh

    monkeypatch.setattr(edgemesh, "follow", lambda model, y, control, tol: (model, y, control, 0))
    mesh = {"thickness_ratio": T, "elements": 64}  # the premise measured below (the edge's spread scales with h)
    exact = solid.compress(mooney_rivlin(47 / 160), PHAT, FORCE, indenter=Sphere(K), **mesh)
    differences = []
    for rows in (20, 40):
        state = solid.compress(mooney_rivlin(47 / 160), PHAT, FORCE, indenter=Profile(_sphere_table(rows)), **mesh)
        differences.append([abs(state.pressure_ratio / exact.pressure_ratio - 1.0),
                            abs(state.height / exact.height - 1.0), abs(state.contact_area / exact.contact_area - 1.0)])
    print(f"|profile / sphere - 1| (P/P_I, h, A_c) at 20 and 40 rows: {differences}")
    # P/P_I and h: the same nodes touch the same surface (the spline's error ~1e-6 in z at 20 rows, measured
    # 5e-8 and 2e-9 in the states); A_c: the contact edge is extrapolated from the gaps beyond it (results),
    # vertical here, the distance to the centre there, which place it ~1e-4 R apart (1.2e-3 in A_c, measured),
    # inside the estimate's own spread over meshes (+-1.4e-3 R, 1.2 % in A_c)
    assert max(differences[1][:2]) < 1e-7
    assert differences[1][2] < 5e-3
    assert state.force == pytest.approx(FORCE, rel=1e-12)


@pytest.mark.slow
def test_a_contact_past_the_profile_is_out_of_range():
    """A profile shorter than the contact zone it would need: an OutOfRangeError naming the profile's end."""
    from pocket.core.errors import OutOfRangeError

    rho = np.linspace(0.0, 0.1, 11)
    short = table(rho, K - np.sqrt(K * K - rho * rho))
    with pytest.raises(OutOfRangeError, match="profile"):
        solid.compress(mooney_rivlin(47 / 160), PHAT, 1.0, indenter=Profile(short), thickness_ratio=T)
