"""A shallow dome (Phat_I from 1e-4 to 3e-3) under a large sphere (K = R_s/R above 1): shooting against finite
elements on every state inside the range, and on the range's end.

A pocket inflated this little has a pole strain s_0 of 1e-3 or less, and the contact zone's end state enters the
shooting residuals divided by s_0 (``pocket.shooting.surface``, "Tolerance of the sphere's contact zone");
integrated to the free sheet's rtol the zone left noise in the residuals a thousand times the Newton tolerance,
and the solver stalled inside its range (a compression exited 1, "meridian folded"; the range end was a
ConvergenceError, and so was a force past it). The exact answers here are the FE solver's, an independent
discretisation of the same membrane model, at its default mesh (256 P2 elements):

- inside the range both solve, and agree on every scalar they report to ``AGREE``;
- the range end under such a sphere is the sphere's lowest point reaching the clamp plane (h = 0): the FE's is the
  zero of its own h(F), found from its states just short of the shooting's end;
- past the end both refuse, with an OutOfRangeError (exit status 2), in one line.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pocket import fem, shooting
from pocket.cli import main
from pocket.core.errors import OutOfRangeError, exit_status
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import LAWS, check
from pocket.core.states import CHECKS

#: how closely the two solvers must agree on a state (relative; the height relative to the inflated height H0,
#: since it falls to 0 at the end). The FE's discretisation error at its default mesh is the larger part: P2
#: elements converge as h^4, measured at 256 elements below 1e-7 on these shallow states
AGREE = 1e-6
#: the tension minima: the FE samples an interior minimum at its nodes and quadrature points, to O(h^2)
#: (``tests/test_sphere_agree.py``)
AGREE_MINIMA = 3e-5
#: how closely the FE's range end must agree with the shooting's (relative)
AGREE_END = 1e-3

#: ``pocket compress --law neo-hookean --mu 1.0 --pressure P --force F --indenter sphere --indenter-radius K``
PRESSURE, FORCE, RADIUS = 0.00022631090533322825, 0.47243114058787555, 1.3790245400508674
NEO = check("neo-hookean", {"mu": 1.0})


def _differences(left, right) -> dict[str, float]:
    """{key: relative difference} over the float scalars both states report (the height, and its ratio to H0,
    relative to H0)."""
    a, b = left.scalars(), right.scalars()
    out = {key: abs(b[key] / value - 1.0) for key, value in a.items() if isinstance(value, float)}
    out["height"] = abs(right.height - left.height) / left.inflated.height
    out["height_ratio"] = abs(right.height_ratio - left.height_ratio)
    return out


def _assert_agree(left, right) -> None:
    """The two states agree to ``AGREE`` on every scalar, to ``AGREE_MINIMA`` on the tension minima."""
    worst = _differences(left, right)
    minima = {key: worst.pop(key) for key in CHECKS[:2]}
    print({key: f"{value:.1e}" for key, value in {**worst, **minima}.items()})
    assert max(worst.values()) < AGREE, worst
    assert max(minima.values()) < AGREE_MINIMA, minima


def test_shallow_dome_under_a_large_sphere_compresses_as_the_fem_does(capsys):
    """The reported state (neo-Hookean, Phat_I = 2.3e-4, K = 1.38, Fhat = 0.47, which the FE solves): shooting's
    ``pocket compress`` exits 0 (it exited 1, "meridian folded"), and its state agrees with the FE's on every scalar
    to ``AGREE``."""
    command = ["compress", "--law", "neo-hookean", "--mu", "1.0", "--pressure", repr(PRESSURE), "--force", repr(FORCE),
               "--indenter", "sphere", "--indenter-radius", repr(RADIUS)]
    assert main(command) == 0, capsys.readouterr().err
    kwargs = dict(indenter=Sphere(RADIUS))
    _assert_agree(shooting.compress(NEO, PRESSURE, FORCE, **kwargs), fem.compress(NEO, PRESSURE, FORCE, **kwargs))


@pytest.mark.slow
@pytest.mark.parametrize("solver", ["shooting", "fem"])
def test_force_past_a_shallow_domes_end_is_refused_in_one_line(capsys, solver):
    """A neo-Hookean pocket at Phat_I = 2.26e-4 under a sphere of K = 2.85 pressed 1 % past the shooting's range
    end: exit 2 and one line saying the force is beyond the model's range, for either solver; the shooting's names
    its end (it exited 1: the compression stalled, and so did the search for the end)."""
    pressure, radius = 0.00022572397623834572, 2.851781076972845
    end = shooting.range_end(NEO, pressure, indenter=Sphere(radius))
    command = ["compress", "--law", "neo-hookean", "--mu", "1.0", "--pressure", repr(pressure), "--indenter",
               "sphere", "--indenter-radius", repr(radius), "--force", repr(1.01 * end), "--solver", solver]
    assert main(command) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert "is beyond the model's range, which ends at" in err, err
    if solver == "shooting":
        assert f"force = {end:.10g}" in err, err


def _fem_end(material, pressure, radius, fluid, near) -> float:
    """The FE's range end under the sphere: the force at which its indenter's lowest point reaches the clamp plane,
    the zero nearest ``near`` of the parabola through its states' heights h(F) at 0.97, 0.98 and 0.99 of ``near``
    (the extrapolation's error is O(0.03^3) of the end)."""
    forces = [share * near for share in (0.97, 0.98, 0.99)]
    states = fem.compression_curve(material, pressure, forces, fluid=fluid, indenter=Sphere(radius))
    roots = np.roots(np.polyfit(forces, [s.height for s in states], 2))
    real = roots[np.isreal(roots)].real
    return float(real[np.argmin(np.abs(real - near))])


@pytest.mark.slow
@pytest.mark.parametrize(("law", "fluid", "pressure", "radius"), [
    ("ogden", gas(1.0, 1.4), 0.00011495367582735362, 1.819833162634235),
    ("mooney-rivlin", None, 0.000903602415868002, 2.5384621337775046),
    ("gent", gas(1.0, 1.4), 0.0003788512717319674, 2.868329222405751),
    ("yeoh", None, 0.0003461879841253163, 1.9265943354842754),
], ids=["ogden-gas", "mooney-rivlin-liquid", "gent-gas", "yeoh-liquid"])
def test_shallow_dome_range_end_under_a_large_sphere_is_the_fems(law, fluid, pressure, radius):
    """Four shallow pockets (each a ConvergenceError before: the continuation in the force stalled): the shooting's
    range end is the FE's, the force at which its sphere's lowest point reaches the clamp plane, to ``AGREE_END``."""
    material = check(law, dict(LAWS[law].example))
    end = shooting.range_end(material, pressure, fluid=fluid, indenter=Sphere(radius))
    fe = _fem_end(material, pressure, radius, fluid, end)
    print(f"shooting {end!r}, FE {fe!r}, relative difference {fe / end - 1.0:.1e}")
    assert fe == pytest.approx(end, rel=AGREE_END)


fluids = st.one_of(st.none(), st.builds(gas, st.floats(-1.0, 2.0).map(lambda e: 10.0**e), st.floats(1.0, 1.4)))


@pytest.mark.slow
@settings(max_examples=10, deadline=None)
@given(law=st.sampled_from(list(LAWS)), fluid=fluids,
       pressure=st.floats(math.log10(1e-4), math.log10(3e-3)).map(lambda e: 10.0**e), radius=st.floats(1.8, 3.0),
       inside=st.floats(0.05, 1.0), past=st.floats(1e-3, 0.5))
def test_shallow_domes_under_large_spheres_solve_inside_the_range_and_refuse_past_it(law, fluid, pressure, radius,
                                                                                       inside, past):
    """Any law (its registry example), a liquid or a gas, Phat_I in [1e-4, 3e-3], K in [1.8, 3]: at a force inside
    the shooting's range end both solvers solve and agree to ``AGREE``; past it by 0.1 % to 50 % both refuse with an
    OutOfRangeError (exit status 2), one line, the shooting's naming its end."""
    material = check(law, dict(LAWS[law].example))
    kwargs = dict(fluid=fluid, indenter=Sphere(radius))
    end = shooting.range_end(material, pressure, **kwargs)
    force = inside * end
    _assert_agree(shooting.compress(material, pressure, force, **kwargs),
                  fem.compress(material, pressure, force, **kwargs))
    for solver in (shooting, fem):
        with pytest.raises(OutOfRangeError) as refusal:
            solver.compress(material, pressure, (1.0 + past) * end, **kwargs)
        assert exit_status(refusal.value) == 2
        assert "\n" not in str(refusal.value)
        if solver is shooting:
            assert f"force = {end:.10g}" in str(refusal.value)
