"""Mesh convergence of the finite-element solver against the shooting reference.

Theory (smooth solution, Lagrange elements of order p): the error in the energy
norm is O(h^p) and, the problem being variational, the error in smooth
functionals (volume, pressure at given volume, the pole height, a nodal value of
a 1-D problem) is O(h^(2p)): order 2 for P1, 4 for P2.

With contact the meridian curvature jumps at the contact edge (0 inside, P/T1
outside), so eta is only in H^(5/2 - eps): on uniform meshes the P2 rate for
contact quantities drops below 4 (measured about 2.3 for the contact radius),
while P1, limited to 2 by its own order, keeps 2. Refining the mesh 8x around
the edge (``meshes.refined``) restores the accuracy the smooth part allows.

Observed orders are fitted with np.polyfit on log(error) vs log(h) and printed
on failure; the finest errors are capped as well.
"""

import numpy as np
import pytest

from pocket import fem, meshes, shooting

ALPHA, PRESSURE = 47 / 160, 0.31
INFLATION_MESHES = {1: (20, 40, 80, 160), 2: (10, 20, 40, 80)}


def _order(sizes, errors):
    return np.polyfit(np.log(sizes), np.log(errors), 1)[0]


@pytest.fixture(scope="module")
def inflation_errors():
    ref = shooting.inflate(ALPHA, PRESSURE)
    out = {}
    for order, ns in INFLATION_MESHES.items():
        rows = []
        for n in ns:
            mesh = meshes.uniform(n)
            by_p = fem.inflate(ALPHA, PRESSURE, mesh=mesh, order=order)
            by_v = fem.inflate_volume(ALPHA, ref.volume, mesh=mesh, order=order)
            rows.append([abs(by_p.height / ref.height - 1), abs(by_p.volume / ref.volume - 1),
                         abs(by_v.pressure / ref.pressure - 1)])
        out[order] = 1.0 / np.array(ns), np.array(rows)
    return out


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("column, name", [(0, "height"), (1, "volume"), (2, "pressure")])
def test_inflation_converges_at_order_2p(inflation_errors, order, column, name):
    """Height, volume (pressure control) and pressure (volume control): order 2p
    within 0.3 (pre-asymptotic curvature of the fit on the coarse meshes)."""
    h, errors = inflation_errors[order]
    observed = _order(h, errors[:, column])
    assert abs(observed - 2 * order) < 0.3, (
        f"P{order} {name}: observed order {observed:.3f}, expected {2 * order}, errors {errors[:, column]}")
    assert errors[-1, column] < (1e-4 if order == 1 else 1e-8), f"finest error {errors[-1, column]:.3e}"


@pytest.fixture(scope="module")
def contact_reference():
    return shooting.compress(ALPHA, PRESSURE, 0.19)


def _contact_errors(ref, order, ns, refine):
    sizes, errors = [], []
    for n in ns:
        mesh = meshes.refined(n, at=ref.contact_radius) if refine else meshes.uniform(n)
        state = fem.compress(ALPHA, PRESSURE, 0.19, mesh=mesh, order=order)
        sizes.append(np.diff(mesh).max())
        errors.append(abs(state.contact_radius / ref.contact_radius - 1))
    return np.array(sizes), np.array(errors)


def test_contact_radius_p1(contact_reference):
    """P1: order 2 with or without refinement at the edge (P1's own limit), within
    0.4 (the edge moves inside its element from mesh to mesh, scattering the errors)."""
    for refine in (False, True):
        h, errors = _contact_errors(contact_reference, 1, (40, 80, 160), refine)
        observed = _order(h, errors)
        assert abs(observed - 2) < 0.4, f"refine={refine}: observed order {observed:.3f}, errors {errors}"


def test_contact_radius_p2(contact_reference):
    """P2: on uniform meshes the edge reduces the order below 4 (observed in [1.8, 3.2]);
    refined 8x at the edge, every error is at least 5x smaller than on the uniform mesh
    with the same base n, and the finest is below 1e-6 (the issue's refined-mesh bar)."""
    ns = (20, 40, 80)
    h, uniform = _contact_errors(contact_reference, 2, ns, refine=False)
    observed = _order(h, uniform)
    assert 1.8 < observed < 3.2, f"uniform P2: observed order {observed:.3f}, errors {uniform}"
    _, refined = _contact_errors(contact_reference, 2, ns, refine=True)
    assert np.all(refined < 0.2 * uniform), f"refined {refined} vs uniform {uniform}"
    assert refined[-1] < 1e-6, f"finest refined error {refined[-1]:.3e}"
