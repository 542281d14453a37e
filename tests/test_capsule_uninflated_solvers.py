"""The uninflated capsule (P_I = 0) by the two solvers, independently: the shooting solver's descent
(``pocket.shooting.descent``) against the finite elements' (``pocket.fem.descent``).

Each reaches the deep branch by its own route and equations; they must agree on every key of the capsule's
contract within the finite elements' error, estimated as the shift of the key from the mesh of half as many
elements (the keys converge at least at first order, so the finer mesh's error is at most that shift), and on
where the branch starts (the contact edge's tension vanishing) within the same estimate of the finite elements'
start. The shooting solver's own error (rtol 1e-10) is far below: its keys move by less than 1e-9 at rtol 1e-12
(``tests/test_shooting_capsule_descent.py``).
"""

from __future__ import annotations

import math
import re

import pytest

from pocket import fem, shooting
from pocket.core.errors import OutOfRangeError

RUBBER = 0.0  # neo-Hookean
KEYS = ("pressure", "height", "volume", "contact_area", "contact_radius", "contact_radius_deformed")
EXTRA = ("stretch_pole", "radius_equator", "force_ETR")


def _values(state) -> dict[str, float]:
    return {**{k: float(getattr(state, k)) for k in KEYS}, **{k: float(state.extra[k]) for k in EXTRA}}


@pytest.mark.parametrize("height", [0.7, 0.6, 0.3])
def test_the_solvers_agree_on_the_uninflated_capsule(height):
    """Every key, at a plate height where the pole's patch is compressive (0.7, 0.6) and where it is taut (0.3)."""
    shot = _values(shooting.compress_height(RUBBER, 0.0, height, geometry="capsule"))
    state = fem.compress_height(RUBBER, 0.0, height, geometry="capsule")
    elements = state.extra["elements"]
    fine = _values(state)
    coarse = _values(fem.compress_height(RUBBER, 0.0, height, geometry="capsule", elements=elements // 2))
    for key in fine:
        mesh = abs(fine[key] - coarse[key])
        print(f"H = {height}, {key}: shooting {shot[key]!r}, finite elements {fine[key]!r} ({elements} elements), "
              f"differ by {abs(fine[key] - shot[key]):.2e}; mesh shift {mesh:.2e}")
        assert abs(fine[key] - shot[key]) <= mesh + 1e-12, key


def _fem_start(**options) -> tuple[float, float]:
    """The bracket (reached, beyond) of heights the finite elements quote for the start of the uninflated capsule's
    range, refusing a height above it."""
    with pytest.raises(OutOfRangeError) as refused:
        fem.compress_height(RUBBER, 0.0, 0.9, geometry="capsule", **options)
    found = re.search(r"start deeper, at plate height h/R = (\S+) to (\S+) \(", str(refused.value))
    assert found, str(refused.value)
    reached, beyond = (float(v) for v in found.groups())
    return reached, beyond


def test_the_solvers_agree_on_where_the_uninflated_range_starts():
    """The shooting solver's H* (bisected to 2e-6) lies in the finite elements' bracket widened by their mesh's
    error there, estimated as the shift of the bracket's middle from the mesh of half as many elements plus that
    bracket's half-width."""
    with pytest.raises(OutOfRangeError) as refused:
        shooting.compress_height(RUBBER, 0.0, 0.9, geometry="capsule")
    shot = float(re.search(r"start deeper, at height = (\S+):", str(refused.value)).group(1))
    reached, beyond = _fem_start()
    elements = fem.inflate(RUBBER, 0.0, geometry="capsule").extra["elements"]
    coarse = _fem_start(elements=elements // 2)
    mesh = abs(0.5 * (reached + beyond) - 0.5 * sum(coarse)) + 0.5 * (coarse[1] - coarse[0])
    print(f"H*: shooting {shot!r}; finite elements [{reached!r}, {beyond!r}] ({elements} elements), {coarse} "
          f"({elements // 2}); allowed {mesh + 2e-6:.2e} beyond the bracket")
    assert reached - mesh - 2e-6 <= shot <= beyond + mesh + 2e-6


@pytest.mark.slow  # the shooting solver's Brent's method on its heights, seconds a force
def test_the_solvers_agree_on_the_uninflated_capsule_under_force_control():
    """F / (E T R) given (``force_unit="ETR"``): each solver finds its own plate height for the force (the
    shooting solver by Brent's method on its heights, the finite elements by their continuation in the force),
    and the two agree on every key within the finite elements' mesh shift; each reports the force asked."""
    shot = shooting.compression_curve(RUBBER, 0.0, [0.5, 2.0], geometry="capsule", force_unit="ETR")
    fine = fem.compression_curve(RUBBER, 0.0, [0.5, 2.0], geometry="capsule", force_unit="ETR")
    elements = fine[0].extra["elements"]
    coarse = fem.compression_curve(RUBBER, 0.0, [0.5, 2.0], geometry="capsule", force_unit="ETR",
                                   elements=elements // 2)
    for force, s, f, c in zip((0.5, 2.0), shot, fine, coarse, strict=True):
        assert abs(s.extra["force_ETR"] / force - 1.0) < 1e-12
        assert f.extra["force_ETR"] == force
        a, b, rough = _values(s), _values(f), _values(c)
        for key in a:
            print(f"F/(ETR) = {force}, {key}: shooting {a[key]!r}, finite elements {b[key]!r}, mesh shift "
                  f"{abs(b[key] - rough[key]):.2e}")
            assert abs(a[key] - b[key]) <= abs(b[key] - rough[key]) + 1e-12 * max(1.0, abs(b[key])), key


@pytest.mark.parametrize("solver", [shooting, fem])
def test_an_uninflated_capsule_at_no_force_is_the_unstressed_sphere_the_plates_touch(solver):
    """Exact answer: at P_I = 0 the plates touch the unstressed sphere at F = 0 (force control) and at its own
    height H = R (height control), the one state of the branch pressed from the touch: height 1, volume 4 pi / 3,
    no contact, F / (E T R) = 0, its Fhat and P / P_I undefined (NaN, and not reported); the same state both ways.
    A height above it does not touch the capsule."""
    by_force = solver.compress(RUBBER, 0.0, 0.0, geometry="capsule", force_unit="ETR")
    by_height = solver.compress_height(RUBBER, 0.0, 1.0, geometry="capsule")
    for state in (by_force, by_height):
        assert (state.height, state.contact_area, state.contact_radius, state.pressure) == (1.0, 0.0, 0.0, 0.0)
        assert state.extra["force_ETR"] == 0.0
        assert math.isnan(state.force)
        assert math.isnan(state.pressure_ratio)
        assert "force" not in state.scalars()
        assert "pressure_ratio" not in state.scalars()
        assert abs(state.volume / (4.0 * math.pi / 3.0) - 1.0) < 1e-9  # the FE's sphere is its mesh's
    assert by_force.scalars() == by_height.scalars()
    with pytest.raises(OutOfRangeError, match=r"^height = 1\.01 is above the inflated pocket"):
        solver.compress_height(RUBBER, 0.0, 1.01, geometry="capsule")
