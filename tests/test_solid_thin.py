"""The solid tends to the membrane as T/R -> 0, at first order; and its own mesh convergence.

Exact answers: the membrane (``pocket.shooting``, an independent solver) is the solid's limit as T/R ->
0, and a membrane of finite thickness differs from the continuum by O(T/R): the clamp's boundary layer,
a few T wide, where the solid bends and the membrane's slope jumps, shifts the whole profile by O(T/R)
(where the fluid's surface lies is a second-order matter: ``pocket.core.offset``). The fitted slope of
log|solid / membrane - 1| against log(T/R) over T/R = 0.04, 0.02, 0.01 is printed and must be near 1.
Mesh convergence: successive differences of the inflated state's scalars under halving fall at a fitted
order (printed).
"""

import numpy as np
import pytest

from pocket import shooting, solid
from pocket.core.fluids import gas
from pocket.core.materials import LAWS, Material, mooney_rivlin

pytestmark = pytest.mark.slow

RATIOS = np.array([0.04, 0.02, 0.01])
#: the mesh: the differences at T/R = 0.01 are ~1e-3 in P/P_I, ~1e-2 in V; the mesh's own error (two layers)
#: is ~6e-4 in V (measured against four and eight layers) and ~2e-4 in P/P_I at 32 elements (against 64): the
#: compression of the liquid, whose P/P_I is asserted, takes 64 elements
ELEMENTS, LAYERS = 32, 2
FORCE = 0.5


def _rate(differences) -> float:
    return float(np.polyfit(np.log(RATIOS), np.log(np.abs(differences)), 1)[0])


def _inflated(state, reference):
    return {"H0 (mid-surface)": state.extra["height_mid"] / reference.height - 1.0,
            "H0 (upper surface)": state.height / reference.height - 1.0,
            "V": state.volume / reference.volume - 1.0}


@pytest.mark.slow
@pytest.mark.parametrize(("name", "material", "pressure", "fluid", "elements", "printed"), [
    ("Mooney-Rivlin, liquid", mooney_rivlin(47 / 160), 0.31, None, 64, ()),
    # a gas at Phat_atm = 1 takes up most of the change: its P/P_I differs from the membrane's by ~1e-4,
    # below the mesh's error there (printed, not asserted)
    ("Mooney-Rivlin, gas", mooney_rivlin(47 / 160), 0.31, gas(1.0), ELEMENTS, ("P/P_I",)),
    # the registry's three-term Ogden rubber (principal stretches, ``pocket.solid.stretches``); its upper
    # surface's H0 is printed only
    ("Ogden, liquid", Material("ogden", dict(LAWS["ogden"].example)), 0.31, None, 64, ("H0 (upper surface)",)),
])
def test_compression_tends_to_the_membrane_at_first_order(name, material, pressure, fluid, elements, printed):
    """P/P_I and H/H0 at Fhat = 0.5 (and the inflated H0, V) differ from the membrane's by O(T/R), each with one
    sign: fitted rates within [0.8, 1.3] (measured 1.0 to 1.1 for the liquid at 64 elements; the bound above
    1.2 leaves room for the mesh's ~2e-4 in a P/P_I difference of ~8e-4 at T/R = 0.01)."""
    reference = shooting.compress(material, pressure, FORCE, fluid=fluid)
    rows = []
    for t in RATIOS:
        state = solid.compress(material, pressure, FORCE, fluid=fluid, thickness_ratio=t, elements=elements,
                               layers=LAYERS)
        rows.append({**_inflated(state.inflated, reference.inflated),
                     "P/P_I": state.pressure_ratio / reference.pressure_ratio - 1.0,
                     "H/H0": state.height_ratio / reference.height_ratio - 1.0})
    for key in rows[0]:
        values = [row[key] for row in rows]
        rate = _rate(values)
        print(f"{name}: {key} solid/membrane - 1 = {', '.join(f'{v:+.3e}' for v in values)}; rate {rate:.3f}")
        if key not in printed:
            assert len({np.sign(v) for v in values}) == 1, (key, values, rate)
            assert 0.8 <= rate <= 1.3, (key, values, rate)


def test_inflation_of_a_second_law_tends_to_the_membrane_at_first_order():
    """The neo-Hookean rubber at Phat = 0.2 (below its pressure maximum): H0 and V at first order."""
    material = Material("neo-hookean", {"mu": 1.0})
    reference = shooting.inflate(material, 0.2)
    rows = [_inflated(solid.inflate(material, 0.2, thickness_ratio=t, elements=ELEMENTS, layers=LAYERS), reference)
            for t in RATIOS]
    for key in rows[0]:
        values = [row[key] for row in rows]
        rate = _rate(values)
        print(f"neo-Hookean: {key} solid/membrane - 1 = {', '.join(f'{v:+.3e}' for v in values)}; rate {rate:.3f}")
        assert len({np.sign(v) for v in values}) == 1, (key, values, rate)
        assert 0.8 <= rate <= 1.3, (key, values, rate)


def _order(values, sizes) -> float:
    steps = np.abs(np.diff(values))
    return float(-np.polyfit(np.log(np.asarray(sizes[1:], float)), np.log(steps), 1)[0])


@pytest.mark.slow
def test_mesh_convergence_along_the_radius_and_through_the_thickness():
    """The inflated headline pocket (T/R = 0.0125): successive differences of H0 and V when the elements along
    the radius double (16 .. 64, four layers) and when the layers double (2 .. 8, 32 elements). The clamp's
    corners, where the clamped face meets the free surfaces and the strain is singular, are meshed at T/2
    whatever the elements and the layers (``pocket.solid.mesh``: finer, the upper surface folds there), so
    both refinements converge the same regularised problem. Along the radius V has converged to ~2e-7
    (relative) at 32 elements: asserted below 1e-5. Through the thickness the measured order in V and H0 is
    ~3 (printed); asserted: the differences fall, the last below 2e-4."""
    material = mooney_rivlin(47 / 160)
    sizes = [16, 32, 64]
    states = [solid.inflate(material, 0.31, elements=n, layers=4) for n in sizes]
    for key in ("height", "volume"):
        values = [getattr(s, key) for s in states]
        order = _order(values, sizes)
        print(f"radius: {key} {values}, successive differences {np.abs(np.diff(values))}, order {order:.2f}")
        assert np.abs(np.diff(values)).max() < 1e-5 * abs(values[-1])
    layers = [2, 4, 8]
    states = [solid.inflate(material, 0.31, elements=32, layers=n) for n in layers]
    for key in ("height", "volume"):
        values = [getattr(s, key) for s in states]
        steps = np.abs(np.diff(values))
        print(f"thickness: {key} {values}, successive differences {steps}, order {_order(values, layers):.2f}")
        assert steps[1] < steps[0]
        assert steps[1] < 2e-4 * abs(values[-1])
