"""The clamp's corners (``pocket.solid.mesh``): meshed at a fraction of a thickness, whatever the radial elements.

Without the clamp's upper jaw, the upper surface beside the clamp lies on the inside of the sheet's bend there;
with corner elements much shorter than the thickness its node beside the corner sank below the corner (the
discrete surface folded), det F in the corner element spread over 0.2 to 2.9, and Newton cycled there. The
inflation below stalled with the former corner mesh (elements 0.15 T long and high: four layers) at Phat = 0.84
(64 elements) and, after 30 s of halving, below Phat = 1 (16 elements); at T/2 it converges unfolded. What the
corner's mesh costs is measured against corner elements half as long: a fraction of the membrane's own O(T/R)
difference, without the jaw (a regularisation of the singular corner) and with it (a mesh of its rounded edge).
"""

import numpy as np
import pytest
from pocket.solid import DEFAULT_CLAMP_RADIUS, DEFAULT_CORNER, inflation, laws, mesh, model
from pocket.solid.post import fields

from pocket import shooting
from pocket.core.materials import mooney_rivlin

T = 0.0125


@pytest.mark.parametrize("thickness", [0.001, 0.0125, 0.04, 0.08, 0.2])
def test_the_corner_elements_do_not_depend_on_the_radial_elements(thickness):
    """The elements at the clamp are DEFAULT_CORNER T long over mesh.WRAP thicknesses, then x 1.5, x 1.5^2, for
    every radial count and layer count; neighbours differ by at most 2.45 in length: the bulk's last node keeps
    between 0.5 and 1.5 of its element, beside a cluster element within sqrt(1.5) of that element (2.45 =
    sqrt(1.5) / 0.5)."""
    wrap = int(np.ceil(mesh.WRAP / DEFAULT_CORNER))
    expected = DEFAULT_CORNER * thickness * np.array([1.0] * wrap + [1.5, 2.25])
    for n in (8, 16, 32, 64, 256, 2000):
        for layers in (2, 4, 16):
            r = np.unique(mesh.section(thickness, n, layers, DEFAULT_CORNER).p[0])
            d = np.diff(r)
            assert r[0] == 0.0
            assert r[-1] == 1.0
            assert np.all(d > 0.0)
            np.testing.assert_allclose(d[-expected.size:][::-1], expected, rtol=1e-12)
            assert max((d[1:] / d[:-1]).max(), (d[:-1] / d[1:]).max()) <= 2.45, (n, layers)


def test_inflation_passes_the_pressure_where_a_finer_corner_folded():
    """Without the clamp's upper jaw, corner elements T/2 long (the default without a jaw): Phat = 1 on four layers
    and 16 radial elements (the former corner mesh stalled before it): converged,
    and the upper surface rises from the clamp's corner over the corner element's nodes (the former mesh's
    last converged state had the node beside the corner 0.05 T below the corner: a fold)."""
    m = model.discretize(T, mesh.section(T, 16, 4, 0.5), laws.derivatives(mooney_rivlin(0.3).scaled()))
    y, _ = inflation.to_pressure(m, 3.0 * T * 1.0, 1e-10)
    eta = fields(m, y).top_eta[-3:]
    print(f"upper surface's heights over the corner element at Phat = 1 (units T): {eta / T}")
    assert eta[0] > eta[1] > eta[2]


@pytest.mark.parametrize(("clamp_radius", "coarse", "fine"),
                         [(0.0, 1.0, 0.5), (DEFAULT_CLAMP_RADIUS, DEFAULT_CORNER, 0.5 * DEFAULT_CORNER)])
def test_the_corner_regularisation_costs_a_fraction_of_the_membrane_difference(clamp_radius, coarse, fine):
    """The inflated headline pocket (alpha = 47/160, Phat = 0.31; 32 elements, two layers) with corner elements
    ``coarse`` and ``fine`` thicknesses long: the relative change of V, H0 and the mid-surface's H0 is printed
    beside the solid's difference from the membrane (``pocket.shooting``), and must be below a tenth of it for V
    and H0. Without the clamp's upper jaw the corner is singular and the change is the regularisation's (T vs T/2,
    measured ~3.8e-4 against 1.3e-2 in V); with the default jaw, whose edge (T/2) the corner elements resolve
    from T/2 down, it is the mesh's (the default, T/4, against T/8). The mid-surface's H0 is itself within
    ~1e-3 of the membrane's, so it is bounded absolutely: below 1e-3, the solid's stated accuracy."""
    from pocket import solid

    material = mooney_rivlin(47 / 160)
    membrane = shooting.inflate(material, 0.31)
    states = {}
    for size in (fine, coarse):
        states[size] = solid.inflate(material, 0.31, elements=32, layers=2, corner=size, clamp_radius=clamp_radius)
    keys = {"V": lambda s: s.volume, "H0": lambda s: s.height, "H0 (mid-surface)": lambda s: s.extra["height_mid"]}
    for key, value in keys.items():
        corner = value(states[coarse]) / value(states[fine]) - 1.0
        difference = value(states[fine]) / (membrane.volume if key == "V" else membrane.height) - 1.0
        print(f"{key}: corner {coarse} T vs {fine} T {corner:+.2e}, solid vs membrane {difference:+.2e}")
        assert abs(corner) < (1e-3 if key == "H0 (mid-surface)" else 0.1 * abs(difference))


def test_the_grid_groups_nodes_placed_a_rounding_apart():
    """``post._levels`` puts coordinates within 1e-10 of each other on one level, whichever side of a fixed decimal
    rounding boundary they fall (rounding to 12 decimals split such a pair, and the grid of 20 elements with
    corner elements T/4 failed to reshape); every mesh's grid of nodes is then a full rectangle: the heights by
    the radii, each node once."""
    from pocket.solid import post

    x = np.array([0.3, 0.1234567890125 - 1e-16, 0.1234567890125 + 1e-16, 0.7, 0.3 + 5e-11, 0.30000001])
    np.testing.assert_array_equal(post._levels(x), [1, 0, 0, 3, 1, 2])
    for elements in (16, 20, 24, 37):
        for corner in (0.0625, 0.25, 0.5):
            t = 0.0125
            m = model.discretize(t, mesh.section(t, elements, 4, corner), laws.derivatives(mooney_rivlin(0.3).scaled()))
            scalar, grid = post._grid(m)
            assert grid.shape[0] == 2 * 4 + 1
            assert np.array_equal(np.sort(grid.ravel()), np.arange(scalar.N))
